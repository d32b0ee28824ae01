!> The plate model: the boxes "laminate stiffness", "mesh and boundary
!> conditions" and "[M], [K_L]" of the paper's flowchart (Fig. 3), built
!> once from the deck and then only read (intent(in) everywhere after
!> build_model), and what is computed from it element by element: the
!> nonlinear term K_N(D) D of eq. (19), M x, and the probes the results
!> need (the strain gauge, the energies, the largest deflection).
!>
!> Units: SI throughout. The model may be a quarter or a half of the plate
!> (src/model/scene_model.f90 chooses), in which case it carries that share of the
!> contact force (force_share) and its energies are multiplied by
!> mesh%sym_factor (4 or 2) to stand for the whole plate.
module plate_model
   use kinds, only: dp, msg_len
   use materials, only: laminate_t, laminate_drop_bend_twist
   use scene_model, only: scene_t, model_laminate, choose_domain, point_stiffness, energy_balance, &
      choose_theory, impact_element_size, choose_storage
   use mesh, only: mesh_t, mesh_layout_t, build_mesh, apply_boundary, nfe, ndof_node, locate_point
   use shape_functions, only: nen
   use shear_strain, only: shear_rule_t, shear_rule_code, shear_stabilized
   use contact_load, only: contact_load_t, contact_load_init, load_point, load_hertz
   use element_matrices, only: element_geometry_t, element_geometry, element_mass, element_stiffness, &
      element_inplane_strain, element_gauss_point, point_derivs
   use element_work, only: element_work_t, work_build, work_nonlinear_force, work_mass_times, work_strain_energy, &
      work_mass_quadratic
   use global_matrix, only: global_matrix_t, global_init, global_zero, global_assemble, global_release
   use contact_law, only: contact_law_t
   use deck_schema, only: deck_t, is_given
   use scene_settings, only: choose_settings
   implicit none
   private
   public :: model_t, build_model, assemble_matrices, release_assembled, nonlinear_force, mass_times, gather_element, &
             scatter_add_element, centre_deflection, back_face_strain, max_deflection, plate_kinetic_energy, &
             plate_strain_energy

   !> Everything about the plate that does not change during a run.
   type :: model_t
      type(mesh_t) :: msh                      !< mesh and freedoms
      type(laminate_t) :: lmt                  !< laminate used (D16 = D26 = 0 when averaged, scene%averaged)
      type(scene_t) :: scene                   !< the scene's choices and report (src/model/scene_model.f90)
      type(element_geometry_t), allocatable :: geo(:)  !< per-element geometry and shear operator
      type(element_work_t) :: work             !< the same, laid out for the element work of a step
      type(global_matrix_t) :: mass            !< [M]
      type(global_matrix_t) :: stiff           !< [K_L]
      type(contact_law_t) :: law               !< eq. (11)-(12) constants
      type(contact_load_t) :: cload            !< how the contact force enters the plate (module contact_load)
      logical :: nonlinear = .true.            !< von Karman terms on
      integer :: eq_impact = 0                 !< equation of w at the impact point
      real(dp) :: force_share = 1.0_dp         !< share of a force at the impact point the model carries
      integer :: gauge_elem = 0                !< element of the strain gauge (place_gauge)
      real(dp) :: gauge_xy(2) = 0.0_dp         !< the gauge's point (m), from the plate centre
      real(dp) :: gauge_dxy(2, nen) = 0.0_dp   !< shape-function derivatives there (1/m)
      real(dp) :: z_back = 0.0_dp              !< z of the back face, +h/2 (m)
      character(len=16) :: shear_rule = ''     !< transverse shear rule used (module shear_strain)
      integer :: max_nonlinear_iter = 200      !< limit of the eq. (19) and Newton iterations
      real(dp) :: cr2 = 1.0e-7_dp              !< tolerance C_r2 of eq. (18)
   end type model_t

contains

   !> Material (eq. 6, 9), mesh and boundary conditions (Fig. 4), element
   !> matrices and their assembly into [M] and [K_L] (eq. 15, Appendix B).
   subroutine build_model(deck, model, stat, errmsg)
      type(deck_t), intent(in) :: deck          !< the input deck
      type(model_t), intent(out) :: model       !< the model
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< reason on failure
      type(shear_rule_t) :: rule
      type(deck_t) :: settled                   ! the deck with its dt, nx, ny (scene_settings)
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
      model%z_back = 0.5_dp*deck%h
      model%max_nonlinear_iter = deck%max_nonlinear_iter
      model%cr2 = deck%cr2

      ! -- transverse shear of the element (module shear_strain): 'auto' is
      !    MITC9, which neither locks nor leaves a mechanism (the paper's 2x2
      !    rule, 'selective', leaves near-mechanisms that a point force
      !    excites: docs/VALIDATION.md)
      model%shear_rule = deck%shear_rule
      if (deck%shear_rule == 'auto') model%shear_rule = 'mitc9'
      rule = shear_rule_t(code=shear_rule_code(model%shear_rule))
      if (rule%code == shear_stabilized) rule%eps = deck%stabilization

      ! -- mesh, boundary conditions, equation numbers (Fig. 4)
      settled = deck                   ! nx, ny of a deck made in code that gives none: from the scene
      call choose_settings(settled)
      call build_mesh(deck%a, deck%b, settled%nx, settled%ny, mesh_layout_t(trim(model%scene%domain), deck%x0, &
                      deck%y0, deck%grading, deck%domain == 'auto'), model%msh, stat, errmsg)
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

      ! -- element geometry and shear operator, once per element
      allocate (model%geo(model%msh%nelem))
      geometry: do e = 1, model%msh%nelem
         call element_geometry(model%msh%coords(:, model%msh%conn(:, e)), rule, model%geo(e), ok)
         if (.not. ok) then
            stat = 1
            write (errmsg, '(a,i0,a)') 'mesh: element ', e, ' has a non-positive Jacobian'
            return
         end if
      end do geometry
      call place_gauge(deck, model, stat, errmsg)
      if (stat /= 0) return

      ! -- [M] and [K_L], assembled once (eq. 15), in the deck's storage or
      !    the one 'auto' picks for this many equations (src/model/scene_model.f90)
      call choose_storage(deck%storage, model%msh%neq, deck%analysis_kind == 'modes', model%scene)
      call assemble_matrices(model%msh, model%lmt, model%geo, model%scene%storage, model%mass, model%stiff, &
                             stat, errmsg)
      if (stat /= 0) return
      call work_build(model%msh, model%lmt, model%geo, model%work)

      ! -- the scene's static estimate, and the theory it calls for
      !    (src/model/scene_model.f90)
      call point_stiffness(model%msh, model%lmt, model%geo, model%stiff, deck%edges, model%scene, stat, errmsg)
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

   !> [M] and [K_L] assembled from the element matrices (eq. 15, Appendix B)
   !> in the storage `storage`: by build_model, and again by a refactoring
   !> of the left-hand matrix for another time step once the model's own
   !> were released (src/scheme/plate_solver.f90, solver_refactor), with
   !> the same operations in the same order: the same bits.
   subroutine assemble_matrices(msh, lmt, geo, storage, mass, stiff, stat, errmsg)
      type(mesh_t), intent(in) :: msh                   !< mesh and freedoms
      type(laminate_t), intent(in) :: lmt               !< laminate
      type(element_geometry_t), intent(in) :: geo(:)    !< per-element geometry and shear operator
      character(len=*), intent(in) :: storage           !< the storage of the matrices (the scene's)
      type(global_matrix_t), intent(inout) :: mass      !< [M], released and assembled
      type(global_matrix_t), intent(inout) :: stiff     !< [K_L], released and assembled
      integer, intent(out) :: stat                      !< 0 on success
      character(len=*), intent(inout) :: errmsg         !< reason on failure
      real(dp) :: ke(nfe, nfe), me(nfe, nfe)            ! element stiffness and mass matrices
      integer :: e                                      ! element
      call global_init(mass, storage, msh%neq, msh%elem_eq, stat, errmsg)
      if (stat /= 0) return
      call global_init(stiff, storage, msh%neq, msh%elem_eq, stat, errmsg)
      if (stat /= 0) return
      call global_zero(mass)
      call global_zero(stiff)
      elements: do e = 1, msh%nelem
         call element_mass(lmt, geo(e), me)
         call element_stiffness(lmt, geo(e), ke)
         call global_assemble(mass, me, msh%elem_eq(:, e))
         call global_assemble(stiff, ke, msh%elem_eq(:, e))
      end do elements
   end subroutine assemble_matrices

   !> Release the assembled [M] and [K_L] once the impact's left-hand matrix
   !> K_L + 4/dt^2 M is factored: its time steps form M x and K_N(D) D
   !> element by element (mass_times, nonlinear_force), so what stays is the
   !> factor and the element work (the other analyses keep them: static and
   !> pressure multiply with them).
   subroutine release_assembled(model)
      type(model_t), intent(inout) :: model     !< the model; mass and stiff released
      call global_release(model%mass)
      call global_release(model%stiff)
   end subroutine release_assembled

   ! ========================================================= element work

   !> The nonlinear term K_N(D) D of eq. (19), assembled element by element
   !> (zero for the linear theory; module element_work).
   subroutine nonlinear_force(model, d, fn)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: d(:)              !< global displacements
      real(dp), intent(out) :: fn(:)            !< K_N(D) D
      if (.not. model%nonlinear) then
         fn = 0.0_dp
         return
      end if
      call work_nonlinear_force(model%work, d, fn)
   end subroutine nonlinear_force

   !> y = M x, element by element (eq. 15: M is the sum of the element mass
   !> matrices): the product the assembled [M] gives, up to rounding, at a
   !> cost proportional to the number of nodes instead of N kd (module
   !> element_work).
   subroutine mass_times(model, x, y)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: x(:)              !< global vector
      real(dp), intent(out) :: y(:)             !< M x
      call work_mass_times(model%work, model%msh, x, y)
   end subroutine mass_times

   ! =============================================================== probes

   !> Deflection of the impact point, the node (m): the static and pressure
   !> analyses' centre deflection.
   pure function centre_deflection(model, d) result(w)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: w
      w = d(model%eq_impact)
   end function centre_deflection

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
      ek = 0.5_dp*work_mass_quadratic(model%work, model%msh, v)*model%msh%sym_factor
   end function plate_kinetic_energy

   !> Strain energy of the whole plate (J), von Karman strains for the
   !> nonlinear theory.
   function plate_strain_energy(model, d) result(u)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: u
      u = work_strain_energy(model%work, d, model%nonlinear)*model%msh%sym_factor
   end function plate_strain_energy

   !> The strain gauge: in-plane y strain on the face opposite the impact,
   !> at the gauge's point (place_gauge).
   function back_face_strain(model, d) result(eps_y)
      type(model_t), intent(in) :: model   !< model
      real(dp), intent(in) :: d(:)         !< global displacements
      real(dp) :: eps_y
      real(dp) :: de(nfe), eps(3)
      call gather_element(model%msh%elem_eq(:, model%gauge_elem), d, de)
      eps = element_inplane_strain(model%gauge_dxy, de, model%z_back, model%nonlinear)
      eps_y = eps(2)
   end function back_face_strain

   !> The strain gauge's point: the deck's &output gauge_x, gauge_y, the
   !> impact point where it gives none, mirrored into the modelled domain
   !> across its symmetry lines (eps_y is even in x and y); the strain is the
   !> element's field there, which converges as the mesh is refined. With
   !> gauge = 'paper' and no point given, the paper's (Fig. 9b): the Gauss
   !> point nearest the impact point in the element at it (moves with the mesh).
   subroutine place_gauge(deck, model, stat, errmsg)
      type(deck_t), intent(in) :: deck          !< the deck
      type(model_t), intent(inout) :: model     !< the model, its geometry built
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp) :: p(2), xi(2), phi(nen), wj, det
      integer :: e, g
      logical :: given

      stat = 0
      given = is_given(deck, 'output', 'gauge_x') .or. is_given(deck, 'output', 'gauge_y')
      model%gauge_xy = [model%msh%x_impact, model%msh%y_impact]
      if (deck%gauge == 'paper') then
         e = model%msh%impact_elem
         g = element_gauss_point(model%geo(e), model%msh%coords(:, model%msh%impact_node))
         model%gauge_elem = e
         model%gauge_xy = model%geo(e)%xy3(:, g)
         model%gauge_dxy = model%geo(e)%dx3(:, :, g)
         if (.not. given) return
      end if
      if (is_given(deck, 'output', 'gauge_x')) model%gauge_xy(1) = deck%gauge_x
      if (is_given(deck, 'output', 'gauge_y')) model%gauge_xy(2) = deck%gauge_y
      p = model%gauge_xy
      if (model%msh%sym_x) p(1) = abs(p(1))
      if (model%msh%sym_y) p(2) = abs(p(2))
      call locate_point(model%msh, p, e, xi)
      if (e == 0) then
         stat = 1
         write (errmsg, '(a,es11.4,a,es11.4,a)') 'output: the gauge at (', p(1), ', ', p(2), &
            ') m is outside the modelled domain'
         return
      end if
      model%gauge_elem = e
      call point_derivs(model%msh%coords(:, model%msh%conn(:, e)), xi, 1.0_dp, phi, model%gauge_dxy, wj, det)
   end subroutine place_gauge

   ! ============================================================== helpers

   !> Element displacements from the global vector (0 for held freedoms).
   pure subroutine gather_element(eqs, d, de)
      integer, intent(in) :: eqs(:)       !< equation of each element freedom, 0 held
      real(dp), intent(in) :: d(:)        !< global vector
      real(dp), intent(out) :: de(:)      !< element vector
      where (eqs > 0)
         de = d(max(eqs, 1))
      elsewhere
         de = 0.0_dp
      end where
   end subroutine gather_element

   !> Adds element forces into the global vector.
   pure subroutine scatter_add_element(eqs, fe, f)
      integer, intent(in) :: eqs(:)       !< equation of each element freedom, 0 held
      real(dp), intent(in) :: fe(:)       !< element vector
      real(dp), intent(inout) :: f(:)     !< global vector
      integer :: k
      do k = 1, size(eqs)
         if (eqs(k) > 0) f(eqs(k)) = f(eqs(k)) + fe(k)
      end do
   end subroutine scatter_add_element

end module plate_model
