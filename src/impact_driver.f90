!> The impact analysis of Fig. 3: the model set-up, the plate solution of a
!> time step with Akay's constant-coefficient iteration (eq. 18, 19), the
!> contact-force iteration (eq. 13, 17, 21) and the quantities written out.
!>
!> The main program (src/impact.f90) reads like the flowchart and calls the
!> procedures below, one per box.
!>
!> Units: SI throughout; the plate model may be a quarter or a half of the
!> plate (src/scene_model.f90 chooses), in which case it carries that share of
!> the contact force and its energies are multiplied by 4 or 2 to stand for
!> the whole plate (mesh%sym_factor).
module impact_driver
   use kinds, only: dp, msg_len
   use materials, only: laminate_t, laminate_drop_bend_twist
   use scene_model, only: scene_t, model_laminate, choose_domain, point_stiffness, energy_balance, &
      choose_theory, impact_element_size
   use mesh, only: mesh_t, build_mesh, apply_boundary, describe_equation, nfe, ndof_node
   use shear_strain, only: shear_rule_t, shear_rule_code, shear_mitc9, shear_stabilized
   use contact_load, only: contact_load_t, load_pattern_t, contact_load_init, load_pattern, pattern_mean, &
      pattern_add, load_point, load_hertz
   use element_matrices, only: element_geometry_t, element_geometry, element_mass, &
      element_stiffness, element_nonlinear_force, element_strain_energy, &
      element_inplane_strain, element_gauss_point, element_mass_integrals, element_mass_product
   use global_matrix, only: global_matrix_t, global_init, global_zero, global_assemble, &
      global_axpy_matrix, global_copy, global_matvec, global_factor, global_solve
   use contact_law, only: contact_law_t, contact_history_t, contact_force, solve_contact_equation, &
      law_indentation
   use newmark, only: newmark_t, impactor_advance
   use input_deck, only: deck_t
   use fixed_point, only: fp_guard_t, fp_start, fp_check, fp_next, fp_converged, fp_iterating
   implicit none
   private
   public :: model_t, plate_state_t, impactor_state_t, force_bracket_t, &
             build_model, factor_effective_matrix, plate_solve, fast_step, &
             predicted_displacements, contact_area, contact_work_increment, &
             nonlinear_force, mass_times, bracket_start, bracket_update, contact_converged, &
             first_force_guess, plate_kinetic_energy, plate_strain_energy, &
             back_face_strain, impact_deflection, gather_element, scatter_add_element, &
             bracket_cut, fixed_point_force, contact_report, max_deflection, von_karman_limit

   !> Everything about the plate that does not change during a run.
   type :: model_t
      type(mesh_t) :: msh                      !< mesh and freedoms
      type(laminate_t) :: lmt                  !< laminate used (D16 = D26 = 0 when averaged, scene%averaged)
      type(scene_t) :: scene                   !< the scene's choices and report (src/scene_model.f90)
      type(element_geometry_t), allocatable :: geo(:)  !< per-element geometry
      !> S_ij = int phi_i phi_j dA of each element (m^2), (nen, nen, nelem):
      !> M x element by element (mass_times)
      real(dp), allocatable :: mass_s(:,:,:)
      type(global_matrix_t) :: mass            !< [M]
      type(global_matrix_t) :: stiff           !< [K_L]
      type(global_matrix_t) :: keff            !< K_L + 4/dt^2 M, factored (eq. 19)
      type(contact_law_t) :: law               !< eq. (11)-(12) constants
      logical :: nonlinear = .true.            !< von Karman terms on
      real(dp) :: impactor_mass = 0.0_dp       !< m (kg)
      integer :: eq_impact = 0                 !< equation of w at the impact point
      real(dp) :: force_share = 1.0_dp         !< share of the contact force carried by the model
      type(contact_load_t) :: cload            !< how the contact force enters the plate (module contact_load)
      type(load_pattern_t) :: pattern          !< the contact load of the current force (contact_area)
      integer :: gauge_gp = 0                  !< 3x3 Gauss point of the strain gauge in msh%impact_elem
      real(dp) :: z_back = 0.0_dp              !< z of the back face, +h/2 (m)
      integer :: max_nonlinear_iter = 200      !< limit of the eq. (18) iteration
      real(dp) :: cr2 = 1.0e-7_dp              !< tolerance of eq. (18)
      character(len=32) :: shear_rule = ''     !< transverse shear rule used (module shear_strain)
      type(shear_rule_t) :: shear              !< the same, as the elements take it
      !> scheme = 'fast': (K_L + 4/dt^2 M)^-1 e_j for the equations j a contact
      !> load has touched so far (m/N), computed when first needed (contact_response)
      integer :: nresp = 0                     !< columns held
      integer, allocatable :: resp_eq(:)       !< their equations j
      real(dp), allocatable :: resp(:,:)       !< (neq, columns) the columns
      integer :: solves = 0                    !< back substitutions so far
      type(fp_guard_t) :: nl_guard             !< guard of the last eq. (19) iteration (module fixed_point)
      integer :: factorizations = 0            !< factorizations so far
   end type model_t

   !> Plate displacements, velocities and accelerations {D}, {V}, {A}.
   type :: plate_state_t
      real(dp), allocatable :: d(:), v(:), a(:)
   end type plate_state_t

   !> The rigid impactor: position, velocity (positive towards the plate)
   !> and the contact force at the same time.
   type :: impactor_state_t
      real(dp) :: w = 0.0_dp, v = 0.0_dp, f = 0.0_dp
   end type impactor_state_t

   !> The contact-force iteration's knowledge of the root of
   !> r(F) = F - F_cont(F), which increases with F: a harder push stops the
   !> impactor sooner and deflects the plate more, so the indentation and
   !> the law's force fall.
   type :: force_bracket_t
      real(dp) :: lo = 0.0_dp, hi = huge(1.0_dp)  !< bracket (N)
      real(dp) :: r_lo = 0.0_dp, r_hi = 0.0_dp    !< residuals at the ends
      logical :: has_lo = .false., has_hi = .false.  !< residual known at that end
      integer :: last_side = 0                    !< end moved last (-1 lo, +1 hi), for Illinois
      logical :: blind_hi = .false.      !< hi is a force whose plate solution failed: no residual there
      real(dp) :: r_prev = huge(1.0_dp)  !< |r| of the previous iteration (N), force_update = 'fixed_point'
      logical :: fell_back = .false.     !< 'fixed_point' stopped contracting: bracketed from then on
   end type force_bracket_t

   !> Deflection over thickness beyond which von Karman's theory of moderately
   !> large deflections is no longer trusted (a warning, not an error).
   real(dp), parameter :: von_karman_limit = 5.0_dp
   !> Largest factor by which force_update = 'fixed_point' may shrink the
   !> contact residual per iteration before it falls back (0.5: C_r1 = 0.2 %
   !> from a residual of the order of the force within about 9 iterations).
   real(dp), parameter :: max_contraction = 0.5_dp

contains

   ! ================================================================ set-up

   !> Material (eq. 6, 9), mesh and boundary conditions (Fig. 4), element
   !> matrices and their assembly into [M] and [K_L] (eq. 15, Appendix B).
   subroutine build_model(deck, model, stat, errmsg)
      type(deck_t), intent(in) :: deck          !< the input deck
      type(model_t), intent(out) :: model       !< the model
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp) :: ke(nfe, nfe), me(nfe, nfe)
      integer :: e
      logical :: ok

      ! -- material: lamina (Table 3), laminate (eq. 6, 9) with the deck's or
      !    Whitney's shear correction; the domain the scene allows; D16 = D26
      !    = 0 on a reduced domain (the paper's averaging, section 3.1) or when
      !    the deck drops them (&laminate bend_twist = 'drop')
      call model_laminate(deck, model%lmt, model%scene)
      call choose_domain(deck, model%scene, stat, errmsg)
      if (stat /= 0) return
      if (model%scene%averaged) model%lmt = laminate_drop_bend_twist(model%lmt)
      model%law = contact_law_t(deck%k, deck%q, deck%alpha_p, deck%beta)
      model%impactor_mass = deck%mass
      model%z_back = 0.5_dp*deck%h
      model%cr2 = deck%cr2
      model%max_nonlinear_iter = deck%max_nonlinear_iter

      ! -- transverse shear of the element (module shear_strain): 'auto' is
      !    MITC9, which neither locks nor leaves a mechanism (the paper's 2x2
      !    rule, 'selective', leaves near-mechanisms that a point force
      !    excites: docs/VALIDATION.md)
      model%shear_rule = deck%shear_rule
      if (deck%shear_rule == 'auto') model%shear_rule = 'mitc9'
      model%shear = shear_rule_t(code=shear_rule_code(model%shear_rule))
      if (model%shear%code == shear_stabilized) model%shear%eps = deck%stabilization

      ! -- mesh, boundary conditions, equation numbers (Fig. 4)
      call build_mesh(deck%a, deck%b, deck%nx, deck%ny, model%scene%domain, model%msh, stat, errmsg, &
                      x0=deck%x0, y0=deck%y0, grading=deck%grading, quarter_counts=deck%domain == 'auto')
      if (stat /= 0) return
      call apply_boundary(model%msh, deck%edges, deck%inplane, stat, errmsg)
      if (stat /= 0) return
      model%eq_impact = model%msh%eq(3, model%msh%impact_node)
      model%force_share = 1.0_dp/model%msh%sym_factor

      ! -- the contact load: the paper's point force (eq. 10) or Hertz's
      !    pressure over the contact area (module contact_load)
      call contact_load_init(model%msh, merge(load_point, load_hertz, deck%contact_load == 'point'), &
                             0.5_dp*deck%diameter, model%cload, stat)
      if (stat /= 0) then
         write (errmsg, '(a,i0)') 'contact load: the Gauss rule of the contact disc failed, LAPACK info = ', stat
         return
      end if
      call load_pattern(model%cload, model%msh, 0.0_dp, model%pattern)

      ! -- element geometry, once per element
      allocate (model%geo(model%msh%nelem))
      geometry: do e = 1, model%msh%nelem
         call element_geometry(model%msh%coords(:, model%msh%conn(:, e)), model%shear, model%geo(e), ok)
         if (.not. ok) then
            stat = 1
            write (errmsg, '(a,i0,a)') 'mesh: element ', e, ' has a non-positive Jacobian'
            return
         end if
      end do geometry
      model%gauge_gp = element_gauss_point(model%geo(model%msh%impact_elem), &
                                           model%msh%coords(:, model%msh%impact_node))

      ! -- [M] and [K_L], assembled once (eq. 15)
      call global_init(model%mass, deck%storage, model%msh%neq, model%msh%elem_eq, stat, errmsg)
      if (stat /= 0) return
      call global_init(model%stiff, deck%storage, model%msh%neq, model%msh%elem_eq, stat, errmsg)
      if (stat /= 0) return
      call global_zero(model%mass)
      call global_zero(model%stiff)
      allocate (model%mass_s(nfe/ndof_node, nfe/ndof_node, model%msh%nelem))   ! nodes per element
      elements: do e = 1, model%msh%nelem
         model%mass_s(:, :, e) = element_mass_integrals(model%geo(e))
         call element_mass(model%lmt, model%geo(e), me)
         call element_stiffness(model%lmt, model%geo(e), ke)
         call global_assemble(model%mass, me, model%msh%elem_eq(:, e))
         call global_assemble(model%stiff, ke, model%msh%elem_eq(:, e))
      end do elements

      ! -- the scene's static estimate, and the theory it calls for
      !    (src/scene_model.f90)
      call point_stiffness(model%msh, model%lmt, model%geo, model%force_share, deck%edges, &
                           deck%storage, model%scene, stat, errmsg)
      if (stat /= 0) return
      call energy_balance(model%scene%energy, model%scene%stiffness, deck%k, model%scene%force, &
                          model%scene%deflection, model%scene%indentation)
      model%scene%contact_radius = sqrt(0.5_dp*deck%diameter*model%scene%indentation)   ! Hertz
      model%scene%element_size = impact_element_size(model%msh)
      model%scene%point_load = deck%contact_load == 'point'
      call choose_theory(deck%theory, model%scene%deflection/deck%h, model%scene%theory, &
                         model%scene%theory_reason)
      model%nonlinear = model%scene%theory == 'nonlinear'
   end subroutine build_model

   !> The left-hand matrix of eq. (19), K_L + 4/dt^2 M, formed and factored
   !> once: Akay's constant-coefficient scheme never changes it.
   subroutine factor_effective_matrix(model, nm, stat, errmsg)
      type(model_t), intent(inout) :: model     !< model; keff is set
      type(newmark_t), intent(in) :: nm         !< Newmark constants
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< names equation, node and freedom on failure
      integer :: bad_eq
      call global_copy(model%keff, model%stiff)
      call global_axpy_matrix(model%keff, nm%a0, model%mass)
      bad_eq = 0
      call global_factor(model%keff, stat, errmsg, bad_eq)
      model%factorizations = model%factorizations + 1
      if (stat /= 0 .and. bad_eq > 0) &
         errmsg = 'K_L + 4/dt^2 M is not positive definite: pivot of ' // &
                  trim(describe_equation(model%msh, bad_eq))
   end subroutine factor_effective_matrix

   !> scheme = 'fast': the plate's response to a unit load on each equation
   !> of the current contact pattern, (K_L + 4/dt^2 M)^-1 e_j, one back
   !> substitution per equation the first time a pattern touches it (kept
   !> for the rest of the run). With the left-hand matrix of eq. (19)
   !> constant, the solution of a step is linear in the contact force F:
   !> D = D_0 + F sum_j c_j (K_L + 4/dt^2 M)^-1 e_j.
   subroutine contact_response(model, stat, errmsg)
      type(model_t), intent(inout) :: model     !< model; resp grows
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp), allocatable :: grown(:,:)
      integer, allocatable :: grown_eq(:)
      integer :: j, eq
      stat = 0
      if (.not. allocated(model%resp)) then
         allocate (model%resp(model%msh%neq, 16), model%resp_eq(16))
         model%nresp = 0
      end if
      equations: do j = 1, model%pattern%n
         eq = model%pattern%eq(j)
         if (any(model%resp_eq(:model%nresp) == eq)) cycle equations
         if (model%nresp == size(model%resp_eq)) then
            allocate (grown(model%msh%neq, 2*model%nresp), grown_eq(2*model%nresp))
            grown(:, :model%nresp) = model%resp(:, :model%nresp)
            grown_eq(:model%nresp) = model%resp_eq(:model%nresp)
            call move_alloc(grown, model%resp);  call move_alloc(grown_eq, model%resp_eq)
         end if
         model%nresp = model%nresp + 1
         model%resp_eq(model%nresp) = eq
         model%resp(:, model%nresp) = 0.0_dp
         model%resp(eq, model%nresp) = 1.0_dp
         call global_solve(model%keff, model%resp(:, model%nresp), stat, errmsg)
         model%solves = model%solves + 1
         if (stat /= 0) return
      end do equations
   end subroutine contact_response

   !> The contact area of the contact force f (N): the pattern of its load
   !> (module contact_load), with the contact radius a = sqrt(R alpha(f)),
   !> alpha(f) the law's indentation at f after the committed history.
   subroutine contact_area(model, hist, f)
      type(model_t), intent(inout) :: model        !< model; its pattern is set
      type(contact_history_t), intent(in) :: hist  !< committed contact history
      real(dp), intent(in) :: f                    !< contact force on the whole plate (N)
      real(dp) :: a
      a = 0.0_dp
      if (model%cload%kind == load_hertz .and. f > 0.0_dp) &
         a = sqrt(model%cload%nose_radius*law_indentation(model%law, hist, f))
      call load_pattern(model%cload, model%msh, a, model%pattern)
   end subroutine contact_area

   !> The work of the contact force on the (whole) plate over a step (J):
   !> the trapezoidal rule of the load vectors at both ends,
   !> 1/2 (F_t p_t + F_{t+dt} p_{t+dt})^T (D_{t+dt} - D_t) times sym_factor,
   !> which is the work Newmark's rule balances against the plate's energy.
   pure function contact_work_increment(pat_old, f_old, pat_new, f_new, dd) result(w)
      type(load_pattern_t), intent(in) :: pat_old, pat_new  !< the load patterns at t and t+dt
      real(dp), intent(in) :: f_old, f_new                  !< the forces at t and t+dt (N)
      real(dp), intent(in) :: dd(:)                         !< D_{t+dt} - D_t
      real(dp) :: w
      w = 0.5_dp*(f_old*pattern_mean(pat_old, dd) + f_new*pattern_mean(pat_new, dd))
   end function contact_work_increment

   ! ================================================================ plate

   !> The nonlinear term K_N(D) D of eq. (19), assembled element by element
   !> (zero for the linear theory).
   subroutine nonlinear_force(model, d, fn)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: d(:)              !< global displacements
      real(dp), intent(out) :: fn(:)            !< K_N(D) D
      real(dp) :: de(nfe), fe(nfe)
      integer :: e
      fn = 0.0_dp
      if (.not. model%nonlinear) return
      elements: do e = 1, model%msh%nelem
         call gather_element(model%msh%elem_eq(:, e), d, de)
         call element_nonlinear_force(model%lmt, model%geo(e), de, fe)
         call scatter_add_element(model%msh%elem_eq(:, e), fe, fn)
      end do elements
   end subroutine nonlinear_force

   !> y = M x, element by element (eq. 15: M is the sum of the element
   !> mass matrices): the product the assembled [M] gives, up to rounding,
   !> at a cost proportional to the number of elements instead of N kd
   !> (profiled: dsbmv with [M] cost about half a plate solve).
   subroutine mass_times(model, x, y)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: x(:)              !< global vector
      real(dp), intent(out) :: y(:)             !< M x
      real(dp) :: xe(nfe), ye(nfe)
      integer :: e
      y = 0.0_dp
      elements: do e = 1, model%msh%nelem
         call gather_element(model%msh%elem_eq(:, e), x, xe)
         call element_mass_product(model%lmt, model%mass_s(:, :, e), xe, ye)
         call scatter_add_element(model%msh%elem_eq(:, e), ye, y)
      end do elements
   end subroutine mass_times

   !> The plate at t+dt under the contact force f (the share the model
   !> carries, spread as model%pattern says: contact_area): Akay's
   !> iteration of eq. (19),
   !>   (K_L + 4/dt^2 M) D^{n+1} = F + M b - K_N(D^n) D^n,
   !> until eq. (18): sum (D^{n+1} - D^n)^2 / sum (D^{n+1} - D_t)^2 < C_r2.
   !> d holds the first iterate on entry and the solution on exit. The
   !> iteration is guarded (module fixed_point): divergence or stagnation
   !> switches to Anderson mixing; model%nl_guard tells how it ended.
   subroutine plate_solve(model, mb, f, d_t, d, iterations, converged, stat, errmsg)
      type(model_t), intent(inout) :: model     !< model (counts solves)
      real(dp), intent(in) :: mb(:)             !< M {b} of eq. (19)-(20)
      real(dp), intent(in) :: f                 !< contact force on the whole plate (N)
      real(dp), intent(in) :: d_t(:)            !< converged displacements at t
      real(dp), intent(inout) :: d(:)           !< iterate in, solution out
      integer, intent(out) :: iterations        !< iterations used
      logical, intent(out) :: converged         !< eq. (18) met
      integer, intent(out) :: stat              !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp) :: rhs(size(d)), fn(size(d))
      logical :: done

      converged = .false.
      iterations = 0
      call fp_start(model%nl_guard, size(d), model%max_nonlinear_iter, model%cr2)
      nonlinear_iterations: do
         iterations = iterations + 1
         call nonlinear_force(model, d, fn)
         rhs = mb - fn
         call pattern_add(model%pattern, f, rhs)
         call global_solve(model%keff, rhs, stat, errmsg)
         model%solves = model%solves + 1
         if (stat /= 0) return
         call iteration_end(model, d_t, rhs, d, converged, done, stat, errmsg)
         if (done .or. stat /= 0) exit nonlinear_iterations
      end do nonlinear_iterations
   end subroutine plate_solve

   !> First iterate of a step of scheme = 'fast': the displacements at t+dt
   !> if the plate kept its velocity, D_t + dt V_t. Starting nearer the
   !> solution than D_t, the iteration's stopping test (eq. 18) leaves a
   !> smaller error, with fewer solves (docs/PERFORMANCE.md: 6x9 clamped
   !> scene, first 1 ms: peak force within 0.005 % of the cr2 -> 0 answer
   !> with 816 solves, against 0.14 % and 1043 solves from D_t). The
   !> acceleration term of Newmark's predictor, dt^2/2 A_t, is left out: it
   !> extrapolates the accelerations of the modes the step does not resolve
   !> (omega dt >> 1 on fine meshes) and needs more iterations (12x18: 2171
   !> solves against 813).
   pure function predicted_displacements(dt, d, v) result(d_pred)
      real(dp), intent(in) :: dt       !< time step (s)
      real(dp), intent(in) :: d(:)     !< displacements at t (m, rad)
      real(dp), intent(in) :: v(:)     !< velocities at t (m/s, rad/s)
      real(dp) :: d_pred(size(d))
      d_pred = d + dt*v
   end function predicted_displacements

   !> One time step of scheme = 'fast': the contact force is solved inside
   !> each iteration of eq. (19) instead of around the whole nonlinear
   !> solution. In iteration n,
   !>   D_0 = (K_L + 4/dt^2 M)^-1 (M b - K_N(D^n) D^n)         eq. (19), F = 0
   !>   D(F) = D_0 + F g,  g = (K_L + 4/dt^2 M)^-1 p(F)        p the contact load
   !>   w_r(F) = w_r + v dt - (F_t + F) dt^2/(4m)              eq. (21)
   !>   alpha(F) = w_r(F) - w_p(D(F)), linear in F             eq. (13)
   !> and F = F_law(alpha(F)) (eq. 11-12) is a scalar equation solved to
   !> rounding (solve_contact_equation). With Hertz's load the pattern p
   !> depends on F through the contact radius; the scalar equation is then
   !> solved again with the pattern of its root until the root stops moving
   !> (the pattern changes with F^(1/3): two or three passes). g comes from
   !> the columns of contact_response, without a solve once the contact's
   !> equations are known. The iteration stops by eq. (18); at that point
   !> eq. (17) holds exactly. One back substitution per iteration, one
   !> iteration in all for the linear theory.
   subroutine fast_step(model, mb, d_t, imp, dt, hist, d, f, alpha, iterations, converged, stat, errmsg)
      type(model_t), intent(inout) :: model        !< model (counts solves; its contact pattern is set)
      real(dp), intent(in) :: mb(:)                !< M {b} of eq. (19)-(20)
      real(dp), intent(in) :: d_t(:)               !< converged displacements at t
      type(impactor_state_t), intent(in) :: imp    !< impactor at t
      real(dp), intent(in) :: dt                   !< time step (s)
      type(contact_history_t), intent(in) :: hist  !< committed contact history
      real(dp), intent(inout) :: d(:)              !< first iterate in, solution out
      real(dp), intent(inout) :: f                 !< a guess of the contact force in (N), the force at t+dt out
      real(dp), intent(out) :: alpha               !< indentation at t+dt (m)
      integer, intent(out) :: iterations           !< iterations (= back substitutions)
      logical, intent(out) :: converged            !< eq. (18) met
      integer, intent(out) :: stat                 !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      integer, parameter :: max_passes = 50
      real(dp), parameter :: pass_tol = 1.0e-12_dp
      real(dp) :: rhs(size(d)), fn(size(d)), w_r0, compliance, f_new
      integer :: pass, j
      logical :: done

      ! impactor position at t+dt if the new force were zero
      w_r0 = imp%w + imp%v*dt - imp%f*dt**2/(4.0_dp*model%impactor_mass)
      converged = .false.
      iterations = 0
      alpha = 0.0_dp
      f = max(f, 0.0_dp)
      call fp_start(model%nl_guard, size(d), model%max_nonlinear_iter, model%cr2)
      nonlinear_iterations: do
         iterations = iterations + 1
         call nonlinear_force(model, d, fn)
         rhs = mb - fn
         call global_solve(model%keff, rhs, stat, errmsg)
         model%solves = model%solves + 1
         if (stat /= 0) return
         ! -- the contact equation, with the contact area of its root
         contact_passes: do pass = 1, max_passes
            call contact_area(model, hist, f)
            call contact_response(model, stat, errmsg)
            if (stat /= 0) return
            compliance = dt**2/(4.0_dp*model%impactor_mass) + pattern_compliance(model)
            call solve_contact_equation(model%law, hist, w_r0 - pattern_mean(model%pattern, rhs), compliance, &
                                        f_new, alpha)
            done = abs(f_new - f) <= pass_tol*max(f_new, f) .or. model%cload%kind == load_point
            f = f_new
            if (done) exit contact_passes
         end do contact_passes
         call contact_area(model, hist, f)
         do j = 1, model%pattern%n
            rhs = rhs + f*model%pattern%c(j)*model%resp(:, findloc(model%resp_eq(:model%nresp), &
                                                                 model%pattern%eq(j), dim=1))
         end do
         call iteration_end(model, d_t, rhs, d, converged, done, stat, errmsg)
         if (done .or. stat /= 0) exit nonlinear_iterations
      end do nonlinear_iterations
   end subroutine fast_step

   !> The plate's compliance under the impactor for the current contact
   !> pattern p: the pressure-weighted deflection per newton of contact
   !> force, p^T (K_L + 4/dt^2 M)^-1 p / total (m/N), from the columns of
   !> contact_response.
   pure function pattern_compliance(model) result(c)
      type(model_t), intent(in) :: model           !< model with the pattern's columns
      real(dp) :: c
      integer :: j, k
      c = 0.0_dp
      do k = 1, model%pattern%n
         j = findloc(model%resp_eq(:model%nresp), model%pattern%eq(k), dim=1)
         c = c + model%pattern%c(k)*pattern_mean(model%pattern, model%resp(:, j))
      end do
   end function pattern_compliance

   !> The end of one iteration of eq. (19), for both schemes: the linear
   !> theory is exact after one solve; otherwise eq. (18) and the guard
   !> against divergence and stagnation decide, and the next iterate is
   !> formed (plain substitution, or the guard's Anderson mixing fall-back).
   subroutine iteration_end(model, d_t, rhs, d, converged, done, stat, errmsg)
      type(model_t), intent(inout) :: model     !< model (its guard)
      real(dp), intent(in) :: d_t(:)            !< converged displacements at t
      real(dp), intent(in) :: rhs(:)            !< the solution of eq. (19) from iterate d
      real(dp), intent(inout) :: d(:)           !< iterate in; next iterate, or the result, out
      logical, intent(out) :: converged         !< eq. (18) met
      logical, intent(out) :: done              !< the iteration is over (converged or given up)
      integer, intent(out) :: stat              !< 0 unless the mixing failed
      character(len=*), intent(inout) :: errmsg !< reason on failure
      stat = 0
      done = .true.
      converged = .true.
      if (.not. model%nonlinear) then
         d = rhs
         return
      end if
      call fp_check(model%nl_guard, d, rhs, d_t)
      converged = model%nl_guard%state == fp_converged
      if (converged) then
         d = rhs
      else if (model%nl_guard%state /= fp_iterating) then
         d = model%nl_guard%d_best   ! the least wrong iterate, finite
      else
         done = .false.
         call fp_next(model%nl_guard, d, rhs, stat, errmsg)
      end if
   end subroutine iteration_end

   ! ======================================================= contact force

   !> First assumed force of a step (section 2.3): the impactor indents as
   !> if the plate did not react, so w_plate stays at its value at t and the
   !> impactor moves on under the force of t alone.
   function first_force_guess(model, imp, w_plate, dt, hist) result(f)
      type(model_t), intent(in) :: model           !< model
      type(impactor_state_t), intent(in) :: imp    !< impactor at t
      real(dp), intent(in) :: w_plate              !< plate deflection at t (m)
      real(dp), intent(in) :: dt                   !< time step (s)
      type(contact_history_t), intent(in) :: hist  !< committed contact history
      real(dp) :: f
      real(dp) :: w_new, v_new
      call impactor_advance(model%impactor_mass, dt, imp%w, imp%v, imp%f, 0.0_dp, w_new, v_new)
      f = contact_force(model%law, hist, w_new - w_plate)
   end function first_force_guess

   !> A fresh bracket: F = 0 is a lower bound of the root.
   pure function bracket_start() result(br)
      type(force_bracket_t) :: br
      br = force_bracket_t()
   end function bracket_start

   !> Records the residual r = f_assumed - f_contact and returns the next
   !> assumed force: the law's force while only one side of the root is
   !> known, regula falsi with the Illinois modification once it is
   !> bracketed. This is the update the paper leaves open (NOTES.md §4);
   !> it always converges because r increases with the force.
   pure subroutine bracket_update(br, f_assumed, f_contact, f_next)
      type(force_bracket_t), intent(inout) :: br  !< bracket, updated
      real(dp), intent(in) :: f_assumed           !< force the plate was solved with (N)
      real(dp), intent(in) :: f_contact           !< force of the law at the resulting indentation (N)
      real(dp), intent(out) :: f_next             !< next assumed force (N)
      real(dp) :: r
      logical :: inside

      r = f_assumed - f_contact
      if (r > 0.0_dp) then
         if (br%last_side == 1 .and. br%has_lo) br%r_lo = 0.5_dp*br%r_lo   ! Illinois
         br%hi = f_assumed;  br%r_hi = r;  br%has_hi = .true.;  br%last_side = 1
      else
         if (br%last_side == -1 .and. br%has_hi) br%r_hi = 0.5_dp*br%r_hi
         br%lo = f_assumed;  br%r_lo = r;  br%has_lo = .true.;  br%last_side = -1
      end if

      if (r > 0.0_dp) br%blind_hi = .false.
      if (br%has_lo .and. br%has_hi .and. .not. br%blind_hi) then
         f_next = br%lo - br%r_lo*(br%hi - br%lo)/(br%r_hi - br%r_lo)
      else
         f_next = f_contact
      end if
      ! stay inside the bracket; F = 0 may be tried while its residual is unknown
      inside = f_next < br%hi .and. (f_next > br%lo .or. (.not. br%has_lo .and. f_next >= br%lo))
      if (.not. inside) then
         if (br%has_hi) then
            f_next = 0.5_dp*(br%lo + br%hi)
         else
            f_next = max(f_contact, br%lo)
         end if
      end if
   end subroutine bracket_update

   !> The plate solution under f_assumed failed (eq. 19 did not converge,
   !> even with its fall-back): the force is taken as too high (a harder
   !> push deflects the plate more, and large deflections are what break
   !> eq. 19); it becomes the upper end of the bracket, without a residual,
   !> and the next assumed force is the middle of the bracket.
   pure subroutine bracket_cut(br, f_assumed, f_next)
      type(force_bracket_t), intent(inout) :: br  !< bracket, updated
      real(dp), intent(in) :: f_assumed           !< force whose plate solution failed (N)
      real(dp), intent(out) :: f_next             !< next assumed force (N)
      br%hi = f_assumed;  br%has_hi = .true.;  br%blind_hi = .true.;  br%last_side = 1
      f_next = 0.5_dp*(br%lo + br%hi)
   end subroutine bracket_cut

   !> force_update = 'fixed_point': the plain update F_next = F_cont, which
   !> the paper may have used (it does not say). Its residual
   !> r = F_assum - F_cont is multiplied in each iteration by about
   !> -dF_cont/dF = k_c (dt^2/4m + g), k_c the law's tangent stiffness and g
   !> the plate's compliance over a step at the impact point: it diverges
   !> when that exceeds 1 (long steps, stiff contact, heavy impactor) and
   !> crawls near 1. The first time |r| falls by less than max_contraction,
   !> the step falls back to the bracketed update (bracket_update runs
   !> before this in every iteration, so its bracket is ready) and
   !> br%fell_back says so.
   pure subroutine fixed_point_force(br, f_assumed, f_contact, f_next)
      type(force_bracket_t), intent(inout) :: br  !< bracket; fell_back set when the update stops contracting
      real(dp), intent(in) :: f_assumed           !< force the plate was solved with (N)
      real(dp), intent(in) :: f_contact           !< force of the law at the resulting indentation (N)
      real(dp), intent(inout) :: f_next           !< the bracketed update in, the plain one out (N)
      real(dp) :: r
      r = abs(f_assumed - f_contact)
      if (.not. br%fell_back) then
         if (r > max_contraction*br%r_prev) then
            br%fell_back = .true.
         else
            f_next = f_contact
         end if
      end if
      br%r_prev = r
   end subroutine fixed_point_force

   !> The diagnostic of a contact iteration that did not converge: the last
   !> forces, their eq. (17) residual against C_r1, and the bracket.
   function contact_report(br, f_assumed, f_contact, cr1, iterations) result(text)
      type(force_bracket_t), intent(in) :: br     !< bracket at the end
      real(dp), intent(in) :: f_assumed           !< last assumed force (N)
      real(dp), intent(in) :: f_contact           !< the law's force at its indentation (N)
      real(dp), intent(in) :: cr1                 !< tolerance C_r1 of eq. (17)
      integer, intent(in) :: iterations           !< iterations made
      character(len=:), allocatable :: text
      character(len=320) :: buf
      real(dp), parameter :: collapsed = 1.0e-9_dp   ! relative width of a bracket that has collapsed
      write (buf, '(a,i0,a,es12.5,a,es12.5,a,es10.3,a,es10.3,a,es16.9,a,es16.9,a)') 'no convergence in ', &
         iterations, ' iterations (max_contact_iter); F_assum = ', f_assumed, ' N, F_cont = ', f_contact, &
         ' N, |F_assum - F_cont| / F_assum = ', abs(f_assumed - f_contact)/max(abs(f_assumed), tiny(1.0_dp)), &
         ' against C_r1 = ', cr1, '; the root lies in [', br%lo, ', ', min(br%hi, huge(1.0_dp)), '] N'
      text = trim(buf)
      if (br%blind_hi) then
         text = text // '; the plate solution (eq. 19) failed under the upper end of the bracket, and the ' // &
            'root lies beyond the forces it can be solved for with this time step: a shorter dt may help'
      else if (br%has_lo .and. br%has_hi .and. br%hi - br%lo <= collapsed*br%hi) then
         text = text // '; the bracket has shrunk to a point where F_cont jumps (the plate''s response ' // &
            'changes abruptly there)'
      end if
   end function contact_report

   !> Convergence of the contact iteration, eq. (17):
   !> |F_assum - F_cont| / F_assum < C_r1 (both zero: no contact, converged).
   pure function contact_converged(f_assumed, f_contact, cr1) result(done)
      real(dp), intent(in) :: f_assumed, f_contact  !< forces (N)
      real(dp), intent(in) :: cr1                   !< tolerance C_r1
      logical :: done
      if (f_assumed <= 0.0_dp) then
         done = f_contact <= 0.0_dp
      else
         done = abs(f_assumed - f_contact) < cr1*f_assumed
      end if
   end function contact_converged

   ! ============================================================ outputs

   !> Plate deflection under the impactor (m), eq. (13): the deflection of
   !> the impact point for the point force, the pressure-weighted mean over
   !> the contact area for Hertz's load (module contact_load), with the
   !> current contact pattern (contact_area).
   pure function impact_deflection(model, d) result(w)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: w
      w = pattern_mean(model%pattern, d)
   end function impact_deflection

   !> Plate deflection for the von Karman check (m): the largest |w| when
   !> the edges hold w somewhere; for a free plate the spread max w - min w,
   !> which leaves out the rigid-body translation that strains nothing.
   pure function max_deflection(model, d) result(w_max)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: w_max
      real(dp) :: w, w_hi, w_lo
      logical :: held
      integer :: n
      w_max = 0.0_dp
      w_hi = -huge(1.0_dp);  w_lo = huge(1.0_dp)
      held = .false.
      nodes: do n = 1, model%msh%nnode
         if (model%msh%eq(3, n) > 0) then
            w = d(model%msh%eq(3, n))
            w_max = max(w_max, abs(w))
            w_hi = max(w_hi, w);  w_lo = min(w_lo, w)
         else
            held = .true.
         end if
      end do nodes
      if (.not. held .and. w_hi >= w_lo) w_max = w_hi - w_lo
   end function max_deflection

   !> Kinetic energy of the whole plate, 1/2 V^T M V (J).
   function plate_kinetic_energy(model, v) result(ek)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: v(:)         !< global velocities
      real(dp) :: ek
      real(dp) :: mv(size(v))
      call mass_times(model, v, mv)
      ek = 0.5_dp*dot_product(v, mv)*model%msh%sym_factor
   end function plate_kinetic_energy

   !> Strain energy of the whole plate (J), von Karman strains for the
   !> nonlinear theory.
   function plate_strain_energy(model, d) result(u)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: u
      real(dp) :: de(nfe)
      integer :: e
      u = 0.0_dp
      elements: do e = 1, model%msh%nelem
         call gather_element(model%msh%elem_eq(:, e), d, de)
         u = u + element_strain_energy(model%lmt, model%geo(e), de, model%nonlinear)
      end do elements
      u = u*model%msh%sym_factor
   end function plate_strain_energy

   !> The paper's strain gauge (Fig. 9b): in-plane y strain on the face
   !> opposite the impact, at the Gauss point nearest the impact point, in
   !> the element nearest it.
   function back_face_strain(model, d) result(eps_y)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: eps_y
      real(dp) :: de(nfe), eps(3)
      integer :: e
      e = model%msh%impact_elem
      call gather_element(model%msh%elem_eq(:, e), d, de)
      eps = element_inplane_strain(model%geo(e), de, model%gauge_gp, model%z_back, model%nonlinear)
      eps_y = eps(2)
   end function back_face_strain

   ! ============================================================ helpers

   !> Element displacements from the global vector (0 for held freedoms).
   pure subroutine gather_element(eqs, d, de)
      integer, intent(in) :: eqs(:)
      real(dp), intent(in) :: d(:)
      real(dp), intent(out) :: de(:)
      where (eqs > 0)
         de = d(max(eqs, 1))
      elsewhere
         de = 0.0_dp
      end where
   end subroutine gather_element

   !> Adds element forces into the global vector.
   pure subroutine scatter_add_element(eqs, fe, f)
      integer, intent(in) :: eqs(:)
      real(dp), intent(in) :: fe(:)
      real(dp), intent(inout) :: f(:)
      integer :: k
      do k = 1, size(eqs)
         if (eqs(k) > 0) f(eqs(k)) = f(eqs(k)) + fe(k)
      end do
   end subroutine scatter_add_element

end module impact_driver
