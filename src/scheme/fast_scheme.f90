!> scheme = 'fast' (the default): one call for the whole step, the
!> alternative to the two nested loops of the paper's flowchart
!> (src/scheme/contact_iteration.f90, src/scheme/plate_solver.f90): the
!> contact force is solved inside each iteration of eq. (19), a scalar
!> equation, and gives the paper's answer to the tolerances with fewer
!> plate solutions. In iteration n,
!>   D_0 = (K_L + 4/dt^2 M)^-1 (M b - K_N(D^n) D^n)         eq. (19), F = 0
!>   D(F) = D_0 + F g,  g = (K_L + 4/dt^2 M)^-1 p(F)        p the contact load
!>   w_r(F) = w_r + v dt - (F_t + F) dt^2/(4m)              eq. (21)
!>   alpha(F) = w_r(F) - w_p(D(F)), linear in F             eq. (13)
!> and F = F_law(alpha(F)) (eq. 11-12) is solved to rounding
!> (solve_contact_equation), again with the pattern of its root until it
!> stops moving; eq. (17) then holds exactly. One solve per step, accepted
!> by eq. (18) with the contraction measured by probes: above
!> first_contraction. More: docs/PERFORMANCE.md.
module fast_scheme
   use kinds, only: dp
   use plate_model, only: model_t
   use plate_solver, only: solver_t, solve_once, iteration_end, contact_response, add_pattern_response, pattern_compliance
   use contact_iteration, only: step_state_t, contact_area
   use contact_law, only: solve_contact_equation
   use contact_load, only: pattern_mean, load_point
   use newmark, only: newmark_t, impactor_moved, impactor_compliance
   use fixed_point, only: fp_start
   implicit none
   private
   public :: fast_step

   !> Steps between two measurements of the contraction theta (module
   !> header): a measurement costs one more solution, so 1/measure_every
   !> solutions per step on average.
   integer, parameter :: measure_every = 8

contains

   !> First iterate of a step of scheme = 'fast': the displacements at t+dt
   !> if the plate kept its velocity, D_t + dt V_t. Starting nearer the
   !> solution than D_t, the stopping test (eq. 18) leaves a smaller error
   !> with fewer solves; the acceleration term of Newmark's predictor,
   !> dt^2/2 A_t, is left out: it extrapolates the accelerations of the modes
   !> the step does not resolve (omega dt >> 1 on fine meshes) and needs more
   !> iterations (docs/PERFORMANCE.md).
   pure function predicted_displacements(nm, d, v) result(d_pred)
      type(newmark_t), intent(in) :: nm  !< Newmark constants (the step dt)
      real(dp), intent(in) :: d(:)       !< displacements at t (m, rad)
      real(dp), intent(in) :: v(:)       !< velocities at t (m/s, rad/s)
      real(dp) :: d_pred(size(d))
      d_pred = d + nm%dt*v
   end function predicted_displacements

   !> One time step of scheme = 'fast' (module header), from the first
   !> iterate predicted_displacements and the impactor's force at t as the
   !> first guess. On exit imp_new is the impactor at t+dt with its force,
   !> and cit the step's contact as the paper's iteration would leave it
   !> after one iteration that met eq. (17): F_assum = F_cont, the
   !> indentation alpha and the contact area. The solver's contraction
   !> estimate is updated when the step measures it.
   subroutine fast_step(solver, model, nm, st, converged, stat, errmsg)
      type(solver_t), intent(inout) :: solver          !< solver (counts solves, its columns grow)
      type(model_t), intent(in) :: model               !< model
      type(newmark_t), intent(in) :: nm                !< Newmark constants (the step dt)
      type(step_state_t), intent(inout) :: st          !< the step: at t and its M {b} (in), at t+dt (out)
      logical, intent(out) :: converged                !< eq. (18) met
      integer, intent(out) :: stat                     !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg        !< reason on failure
      integer, parameter :: max_passes = 50             ! contact passes (Hertz's area) of one iteration
      real(dp), parameter :: pass_tol = 1.0e-12_dp      ! relative change of the root that ends them
      real(dp) :: rhs(size(st%d_new)), w_r0, compliance, f, f_new, alpha, d_first(size(st%d_new)), f_first, alpha_first
      integer :: pass
      logical :: done, probing

      associate (plate => st%plate, imp => st%imp, hist => st%hist, mb => st%mb, d => st%d_new, &
                 imp_new => st%imp_new, cit => st%cit)
      d = predicted_displacements(nm, plate%d, plate%v)
      ! impactor position at t+dt (m) if the new force were zero, eq. (21)
      imp_new = impactor_moved(nm, imp, 0.0_dp)
      w_r0 = imp_new%w
      converged = .false.
      solver%iterations = 0
      f = max(imp%f, 0.0_dp)
      alpha = 0.0_dp
      f_first = f;  alpha_first = alpha
      call fp_start(solver%guard, size(d), solver%max_iter, solver%cr2)
      solver%guard%rate_test = .true.
      solver%guard%accelerate = .true.
      solver%guard%theta2_first = first_contraction(solver)
      probing = solver%guard%theta2_first >= 1.0_dp
      nonlinear_iterations: do
         call solve_once(solver, model, mb, d, rhs, stat, errmsg)
         if (stat /= 0) return
         ! -- the contact equation, with the contact area of its root
         contact_passes: do pass = 1, max_passes
            call contact_area(model, hist, f, cit%pattern)
            call contact_response(solver, cit%pattern, stat, errmsg)
            if (stat /= 0) return
            ! the compliance of the contact equation (m/N): impactor, eq. (21), and plate under the pattern
            compliance = impactor_compliance(nm, imp) + pattern_compliance(solver, cit%pattern)
            call solve_contact_equation(model%law, hist, w_r0 - pattern_mean(cit%pattern, rhs), compliance, &
                                        f_new, alpha)
            done = abs(f_new - f) <= pass_tol*max(f_new, f) .or. model%cload%kind == load_point
            f = f_new
            if (done) exit contact_passes
         end do contact_passes
         call contact_area(model, hist, f, cit%pattern)
         call add_pattern_response(solver, cit%pattern, f, rhs)
         ! -- eq. (18), also on the estimated next change (above first_contraction)
         call iteration_end(solver, model, plate%d, rhs, d, done, stat, errmsg)
         converged = solver%converged
         if (solver%iterations == 1) then
            d_first = rhs;  f_first = f;  alpha_first = alpha
         end if
         ! -- a probe: the second solution only measured the first, which eq. (18) accepts
         if (probing .and. solver%iterations == 2 .and. converged) then
            d = d_first;  f = f_first;  alpha = alpha_first
            call contact_area(model, hist, f, cit%pattern)
         end if
         if (done .or. stat /= 0) exit nonlinear_iterations
      end do nonlinear_iterations
      call measure_contraction(solver)
      imp_new = impactor_moved(nm, imp, f)
      cit%f_assum = f;  cit%f_cont = f;  cit%alpha = alpha
      cit%iterations = 1;  cit%solved = converged;  cit%converged = converged
      end associate
   end subroutine fast_step

   !> One solve per step (the nonlinear theory). The first iterate is
   !> extrapolated, D^0 = D_t + dt V_t (predicted_displacements), and the
   !> first solution D^1 is the step's answer when the iteration's error is
   !> below the tolerance. Eq. (18) compares two successive iterates, so taken
   !> literally it needs a second solution to accept the first; but the change
   !> the next iteration would make is the contraction theta of the iteration
   !> times this one's, |D^2 - D^1| ~ theta |D^1 - D^0|, and theta changes
   !> slowly from step to step (it grows with the deflection). So D^1 is
   !> accepted when eq. (18) holds for that estimate,
   !>
   !>   theta^2 sum (D^1 - D^0)^2 < C_r2 sum (D^1 - D_t)^2,
   !>
   !> theta^2 = ratio(2)/ratio(1), the larger of the last two measured (the
   !> stopping test of the simplified Newton iteration of implicit Runge-Kutta
   !> codes, with the rate of earlier steps: Hairer and Wanner, Solving ODEs
   !> II, section IV.8). theta is measured by a probe, in the first steps and
   !> every measure_every steps: the second solution is made, and when it
   !> meets eq. (18) (|D^2 - D^1| small) it has only measured the first, which
   !> stays the step's answer. A step whose estimate fails, or whose probe
   !> does not meet eq. (18), iterates on with the paper's test and takes the
   !> converged iterate; from the fifth iterate on the iterates are combined
   !> by Anderson mixing (module fixed_point), which the plain iteration of
   !> eq. (19) needs where the deflection is large (docs/PERFORMANCE.md,
   !> "Large deflections").
   !>
   !> Why the probe keeps D^1: the average acceleration rule turns any change
   !> of the step's error from one step to the next into a velocity error
   !> that it never damps (V_t+dt = 2/dt (D_t+dt - D_t) - V_t), which the next
   !> predictor carries. A run that takes one solution in most steps and two
   !> in some has such jumps; one that always takes the first has an error
   !> that changes smoothly, and takes fewer solutions.
   !>
   !> theta^2 for the rate test of a step's first solution (as above):
   !> the larger of the last two measured, or 1 (the paper's eq. 18: go on
   !> and measure theta) in the first steps, every measure_every steps, or
   !> when a measurement is missing.
   pure function first_contraction(solver) result(theta2)
      type(solver_t), intent(in) :: solver   !< solver: its contraction estimate
      real(dp) :: theta2
      if (solver%since_measured >= measure_every .or. any(solver%contraction >= huge(1.0_dp))) then
         theta2 = 1.0_dp
      else
         theta2 = min(1.0_dp, maxval(solver%contraction))
      end if
   end function first_contraction

   !> After a step: theta^2 = ratio(2)/ratio(1) when the step went on to a
   !> second iteration of eq. (19) (and was not mixed: the guard's fall-back
   !> changes the map), else one more step since the last measurement.
   pure subroutine measure_contraction(solver)
      type(solver_t), intent(inout) :: solver   !< solver: its contraction estimate
      if (solver%iterations >= 2 .and. solver%ratios(1) > 0.0_dp .and. .not. solver%guard%mixing) then
         solver%contraction = [solver%contraction(2), solver%ratios(2)/solver%ratios(1)]
         solver%since_measured = 0
      else
         solver%since_measured = solver%since_measured + 1
      end if
   end subroutine measure_contraction

end module fast_scheme
