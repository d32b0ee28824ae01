!> The plate solution of a time step (Fig. 3, "nonlinear plate solution"):
!> Akay's constant-coefficient iteration of eq. (19), stopped by eq. (18),
!> on the left-hand matrix K_L + 4/dt^2 M that is factored once per run (and
!> again only around a step taken in sub-steps, src/scheme/substeps.f90).
!>   (K_L + 4/dt^2 M) D^{n+1} = F + M b - K_N(D^n) D^n        eq. (19)
!>   sum (D^{n+1} - D^n)^2 / sum (D^{n+1} - D_t)^2 < C_r2      eq. (18)
!>
!> The solver holds what changes while the model does not: the factored
!> matrix, the guard of the iteration (module fixed_point: divergence or
!> stagnation switches to Anderson mixing), the counters of solves and
!> factorizations, the eq. (18) ratios of the last solution (the teaching
!> trace prints them), and, for scheme 'fast' (src/scheme/fast_scheme.f90), the
!> responses (K_L + 4/dt^2 M)^-1 e_j to unit loads on the equations a
!> contact load has touched.
module plate_solver
   use kinds, only: dp
   use plate_model, only: model_t, nonlinear_force, assemble_matrices
   use mesh, only: describe_equation
   use newmark, only: newmark_t
   use global_matrix, only: global_matrix_t, global_copy, global_axpy_matrix, global_factor, global_solve, &
      global_release
   use contact_load, only: load_pattern_t, pattern_mean
   use fixed_point, only: fp_guard_t, fp_start, fp_check, fp_next, fp_report, fp_converged, fp_iterating
   use plate_damage, only: plate_damage_t, damage_force
   implicit none
   private
   public :: solver_t, solver_init, solver_refactor, plate_solve, solve_once, iteration_end, contact_response, &
             add_pattern_response, pattern_compliance, plate_compliance

   !> The plate solver of a run.
   type :: solver_t
      type(global_matrix_t) :: keff            !< K_L + 4/dt^2 M, factored (eq. 19)
      type(fp_guard_t) :: guard                !< guard of the last eq. (19) iteration
      integer :: max_iter = 200                !< limit of the eq. (19) iterations (&analysis max_nonlinear_iter)
      real(dp) :: cr2 = 1.0e-7_dp              !< tolerance C_r2 of eq. (18)
      integer :: solves = 0                    !< back substitutions of eq. (19) so far
      integer :: response_solves = 0           !< back substitutions for contact_response so far
      integer :: factorizations = 0            !< factorizations so far
      integer :: mixed_solves = 0              !< plate solutions that needed the guard's fall-back so far
      character(len=:), allocatable :: mixing_note  !< the guard's report of the last of them
      integer :: iterations = 0                !< eq. (19) iterations of the last plate solution
      logical :: converged = .false.           !< its last iteration met eq. (18) (iteration_end)
      real(dp), allocatable :: ratios(:)       !< their eq. (18) ratios
      !> scheme 'fast': (K_L + 4/dt^2 M)^-1 e_j for the equations j a contact
      !> load has touched so far (m/N), computed when first needed
      integer :: nresp = 0                     !< columns held
      integer, allocatable :: resp_eq(:)       !< their equations j
      real(dp), allocatable :: resp(:,:)       !< (neq, columns) the columns
      !> scheme 'fast': the contraction of the eq. (19) iteration, theta^2 =
      !> ratio of iteration 2 / ratio of iteration 1, on the last two steps
      !> that measured it (huge: not measured yet), and the steps since the
      !> last (src/scheme/fast_scheme.f90, "one solve per step")
      real(dp) :: contraction(2) = huge(1.0_dp)
      integer :: since_measured = 0
      !> scheme 'fast': the sub-steps the last time step was taken in
      !> (0: the step itself; src/scheme/substeps.f90), set every step
      integer :: substeps = 0
      type(plate_damage_t) :: damage           !< ply damage: its force K_D D joins K_N D (src/strength/plate_damage.f90)
   end type solver_t

contains

   !> The solver of the model for the time step nm%dt: K_L + 4/dt^2 M formed
   !> and factored once (Akay's constant-coefficient scheme never changes
   !> it). A pivot that fails names its equation, node and freedom.
   subroutine solver_init(model, nm, solver, stat, errmsg)
      type(model_t), intent(in) :: model        !< the model (its matrices and iteration controls)
      type(newmark_t), intent(in) :: nm         !< Newmark constants
      type(solver_t), intent(out) :: solver     !< the solver
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< names equation, node and freedom on failure
      solver%max_iter = model%max_nonlinear_iter
      solver%cr2 = model%cr2
      allocate (solver%ratios(model%max_nonlinear_iter), solver%resp_eq(0), solver%resp(model%msh%neq, 0))
      call global_copy(solver%keff, model%stiff)
      call factor_left_matrix(solver, model, nm, model%mass, stat, errmsg)
   end subroutine solver_init

   !> The solver's left-hand matrix for another time step nm%dt (a step
   !> taken in sub-steps, src/scheme/substeps.f90, and back to the run's
   !> step after): the old factor is released first, [K_L] and [M]
   !> assembled again into its place (the model's were released after the
   !> set-up; module plate_model, assemble_matrices), K_L + 4/dt^2 M formed
   !> in place and factored. One factor at a time, and at most [K_L], [M]
   !> and the factor at once, less than the set-up's peak (which also held
   !> the copy). The same operations as solver_init: the run's step
   !> factored again gives the same bits. The response columns belong to
   !> the old matrix: the caller keeps or drops them (none are held after).
   subroutine solver_refactor(solver, model, nm, stat, errmsg)
      type(solver_t), intent(inout) :: solver   !< solver: its factor replaced, counted
      type(model_t), intent(in) :: model        !< the model (its mesh, laminate and elements)
      type(newmark_t), intent(in) :: nm         !< Newmark constants of the new step
      integer, intent(out) :: stat              !< 0 on success
      character(len=*), intent(inout) :: errmsg !< names equation, node and freedom on failure
      type(global_matrix_t) :: mass             ! [M], assembled for the factoring and released
      call global_release(solver%keff)
      solver%nresp = 0
      call assemble_matrices(model%msh, model%lmt, model%geo, model%scene%storage, mass, solver%keff, stat, errmsg)
      if (stat == 0) call factor_left_matrix(solver, model, nm, mass, stat, errmsg)
      call global_release(mass)
   end subroutine solver_refactor

   !> K_L + 4/dt^2 M from solver%keff = K_L, factored and counted. A pivot
   !> that fails names its equation, node and freedom.
   subroutine factor_left_matrix(solver, model, nm, mass, stat, errmsg)
      type(solver_t), intent(inout) :: solver      !< solver: keff holds K_L on entry, the factor on exit
      type(model_t), intent(in) :: model           !< the model (its mesh, to name a pivot)
      type(newmark_t), intent(in) :: nm            !< Newmark constants
      type(global_matrix_t), intent(in) :: mass    !< [M]
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< names equation, node and freedom on failure
      integer :: bad_eq                            ! the equation of a failed pivot (0: none)
      call global_axpy_matrix(solver%keff, nm%a0, mass)
      bad_eq = 0
      call global_factor(solver%keff, stat, errmsg, bad_eq)
      solver%factorizations = solver%factorizations + 1
      if (stat /= 0 .and. bad_eq > 0) &
         errmsg = 'K_L + 4/dt^2 M is not positive definite: pivot of ' // trim(describe_equation(model%msh, bad_eq))
   end subroutine factor_left_matrix

   !> The plate at t+dt under the load vector `load` = M b + F (the contact
   !> force over its area, or the pressure analysis's load): Akay's
   !> iteration of eq. (19) until eq. (18). d holds the first iterate on
   !> entry and the solution on exit; solver%guard tells how it ended.
   subroutine plate_solve(solver, model, load, d_t, d, converged, stat, errmsg)
      type(solver_t), intent(inout) :: solver   !< solver (counts solves)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: load(:)           !< M {b} + {F} of eq. (19)-(20)
      real(dp), intent(in) :: d_t(:)            !< converged displacements at t
      real(dp), intent(inout) :: d(:)           !< iterate in, solution out
      logical, intent(out) :: converged         !< eq. (18) met
      integer, intent(out) :: stat              !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp) :: rhs(size(d))
      logical :: done
      converged = .false.
      solver%iterations = 0
      call fp_start(solver%guard, size(d), solver%max_iter, solver%cr2)
      nonlinear_iterations: do
         call solve_once(solver, model, load, d, rhs, stat, errmsg)
         if (stat /= 0) return
         call iteration_end(solver, model, d_t, rhs, d, done, stat, errmsg)
         converged = solver%converged
         if (done .or. stat /= 0) exit nonlinear_iterations
      end do nonlinear_iterations
   end subroutine plate_solve

   !> One solution of eq. (19) from the iterate d: rhs = (K_L + 4/dt^2 M)^-1
   !> (load - K_N(d) d - K_D(d) d), one back substitution, counted.
   subroutine solve_once(solver, model, load, d, rhs, stat, errmsg)
      type(solver_t), intent(inout) :: solver   !< solver (counts solves)
      type(model_t), intent(in) :: model        !< model
      real(dp), intent(in) :: load(:)           !< M {b} + {F} of eq. (19)-(20)
      real(dp), intent(in) :: d(:)              !< the iterate D^n
      real(dp), intent(out) :: rhs(:)           !< D^n+1 from it
      integer, intent(out) :: stat              !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg !< reason on failure
      real(dp) :: fn(size(d))
      call nonlinear_force(model, d, fn)
      call damage_force(solver%damage, model, d, fn)
      rhs = load - fn
      call global_solve(solver%keff, rhs, stat, errmsg)
      solver%solves = solver%solves + 1
   end subroutine solve_once

   !> The end of one iteration of eq. (19), for both schemes: the linear
   !> theory is exact after one solve; otherwise eq. (18) and the guard
   !> against divergence and stagnation decide, and the next iterate is
   !> formed (plain substitution, or the guard's Anderson mixing fall-back);
   !> solver%converged says whether eq. (18) was met.
   subroutine iteration_end(solver, model, d_t, rhs, d, done, stat, errmsg)
      type(solver_t), intent(inout) :: solver   !< solver (its guard; converged)
      type(model_t), intent(in) :: model        !< model (the theory)
      real(dp), intent(in) :: d_t(:)            !< converged displacements at t
      real(dp), intent(in) :: rhs(:)            !< the solution of eq. (19) from iterate d
      real(dp), intent(inout) :: d(:)           !< iterate in; next iterate, or the result, out
      logical, intent(out) :: done              !< the iteration is over (converged or given up)
      integer, intent(out) :: stat              !< 0 unless the mixing failed
      character(len=*), intent(inout) :: errmsg !< reason on failure
      stat = 0
      done = .true.
      solver%converged = .true.
      solver%iterations = solver%iterations + 1
      if (.not. model%nonlinear) then
         d = rhs
         solver%ratios(solver%iterations) = 0.0_dp
         return
      end if
      call fp_check(solver%guard, d, rhs, d_t)
      solver%ratios(min(solver%iterations, solver%max_iter)) = solver%guard%ratio
      solver%converged = solver%guard%state == fp_converged
      if (solver%guard%state /= fp_iterating .and. solver%guard%mixing) then
         solver%mixed_solves = solver%mixed_solves + 1
         solver%mixing_note = fp_report(solver%guard)
      end if
      if (solver%converged) then
         d = rhs
      else if (solver%guard%state /= fp_iterating) then
         d = solver%guard%d_best   ! the least wrong iterate, finite
      else
         done = .false.
         call fp_next(solver%guard, d, rhs, stat, errmsg)
      end if
   end subroutine iteration_end

   !> scheme 'fast': the plate's response to a unit load on each equation of
   !> the contact pattern, (K_L + 4/dt^2 M)^-1 e_j, one back substitution per
   !> equation the first time a pattern touches it (kept for the run). With
   !> the left-hand matrix of eq. (19) constant, the solution of a step is
   !> linear in the contact force F: D = D_0 + F sum_j c_j (K_L + 4/dt^2 M)^-1 e_j.
   subroutine contact_response(solver, pattern, stat, errmsg)
      type(solver_t), intent(inout) :: solver       !< solver; its columns grow
      type(load_pattern_t), intent(in) :: pattern   !< the contact pattern
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: grown(:,:)
      integer, allocatable :: grown_eq(:)
      integer :: j, eq, n
      stat = 0
      equations: do j = 1, pattern%n
         eq = pattern%eq(j)
         n = solver%nresp
         if (any(solver%resp_eq(:n) == eq)) cycle equations
         if (n == size(solver%resp_eq)) then
            allocate (grown(size(solver%resp, 1), max(16, 2*n)), grown_eq(max(16, 2*n)))
            grown(:, :n) = solver%resp(:, :n)
            grown_eq(:n) = solver%resp_eq(:n)
            call move_alloc(grown, solver%resp);  call move_alloc(grown_eq, solver%resp_eq)
         end if
         solver%nresp = n + 1
         solver%resp_eq(n + 1) = eq
         solver%resp(:, n + 1) = 0.0_dp
         solver%resp(eq, n + 1) = 1.0_dp
         call global_solve(solver%keff, solver%resp(:, n + 1), stat, errmsg)
         solver%response_solves = solver%response_solves + 1
         if (stat /= 0) return
      end do equations
   end subroutine contact_response

   !> x = x + f g, g = (K_L + 4/dt^2 M)^-1 p the response to the contact
   !> pattern p, from the columns of contact_response (which must have seen
   !> the pattern), without forming g.
   pure subroutine add_pattern_response(solver, pattern, f, x)
      type(solver_t), intent(in) :: solver          !< solver with the pattern's columns
      type(load_pattern_t), intent(in) :: pattern   !< the contact pattern
      real(dp), intent(in) :: f                     !< contact force (N)
      real(dp), intent(inout) :: x(:)               !< vector added to
      integer :: j, col
      do j = 1, pattern%n
         col = findloc(solver%resp_eq(:solver%nresp), pattern%eq(j), dim=1)
         x = x + (f*pattern%c(j))*solver%resp(:, col)
      end do
   end subroutine add_pattern_response

   !> The plate's compliance under the impactor for the pattern p: the
   !> pressure-weighted deflection per newton of contact force,
   !> p^T (K_L + 4/dt^2 M)^-1 p / total (m/N).
   pure function pattern_compliance(solver, pattern) result(c)
      type(solver_t), intent(in) :: solver          !< solver with the pattern's columns
      type(load_pattern_t), intent(in) :: pattern   !< the contact pattern
      real(dp) :: c
      integer :: j, k
      c = 0.0_dp
      do k = 1, pattern%n
         j = findloc(solver%resp_eq(:solver%nresp), pattern%eq(k), dim=1)
         c = c + pattern%c(k)*pattern_mean(pattern, solver%resp(:, j))
      end do
   end function pattern_compliance

   !> The plate's compliance under the pattern over one step (m/N, -1 when
   !> its solve failed): pattern_compliance, its columns computed first.
   subroutine plate_compliance(solver, pattern, c, stat, errmsg)
      type(solver_t), intent(inout) :: solver       !< solver; its columns grow
      type(load_pattern_t), intent(in) :: pattern   !< the contact pattern
      real(dp), intent(out) :: c                    !< the compliance (m/N)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      call contact_response(solver, pattern, stat, errmsg)
      c = -1.0_dp
      if (stat == 0) c = pattern_compliance(solver, pattern)
   end subroutine plate_compliance

end module plate_solver
