!> scheme = 'fast': one call for the whole step, the alternative to the
!> two nested loops of the paper's flowchart (src/contact_iteration.f90 and
!> src/plate_solver.f90). The contact force is solved inside each iteration
!> of eq. (19) instead of around the whole nonlinear solution; it gives the
!> paper's answer to the tolerances (docs/PERFORMANCE.md) with fewer plate
!> solutions, because the contact equation is scalar. In iteration n,
!>
!>   D_0 = (K_L + 4/dt^2 M)^-1 (M b - K_N(D^n) D^n)         eq. (19), F = 0
!>   D(F) = D_0 + F g,  g = (K_L + 4/dt^2 M)^-1 p(F)        p the contact load
!>   w_r(F) = w_r + v dt - (F_t + F) dt^2/(4m)              eq. (21)
!>   alpha(F) = w_r(F) - w_p(D(F)), linear in F             eq. (13)
!>
!> and F = F_law(alpha(F)) (eq. 11-12) is solved to rounding
!> (solve_contact_equation). With Hertz's load the pattern p depends on F
!> through the contact radius; the scalar equation is then solved again
!> with the pattern of its root until the root stops moving (p changes with
!> F^(1/3): two or three passes). g comes from the columns of
!> contact_response, without a solve once the contact's equations are
!> known. The iteration stops by eq. (18); at that point eq. (17) holds
!> exactly. One back substitution per iteration, one iteration in all for
!> the linear theory.
module fast_scheme
   use kinds, only: dp
   use plate_model, only: model_t
   use plate_solver, only: solver_t, solve_once, iteration_end, contact_response, pattern_response, pattern_compliance
   use contact_iteration, only: contact_iteration_t, contact_area
   use contact_law, only: contact_history_t, solve_contact_equation
   use contact_load, only: pattern_mean, load_point
   use newmark, only: impactor_state_t
   use fixed_point, only: fp_start
   implicit none
   private
   public :: fast_step, predicted_displacements

contains

   !> First iterate of a step of scheme = 'fast': the displacements at t+dt
   !> if the plate kept its velocity, D_t + dt V_t. Starting nearer the
   !> solution than D_t, the stopping test (eq. 18) leaves a smaller error
   !> with fewer solves; the acceleration term of Newmark's predictor,
   !> dt^2/2 A_t, is left out: it extrapolates the accelerations of the modes
   !> the step does not resolve (omega dt >> 1 on fine meshes) and needs more
   !> iterations (docs/PERFORMANCE.md).
   pure function predicted_displacements(dt, d, v) result(d_pred)
      real(dp), intent(in) :: dt       !< time step (s)
      real(dp), intent(in) :: d(:)     !< displacements at t (m, rad)
      real(dp), intent(in) :: v(:)     !< velocities at t (m/s, rad/s)
      real(dp) :: d_pred(size(d))
      d_pred = d + dt*v
   end function predicted_displacements

   !> One time step of scheme = 'fast' (module header). cit%f_assum holds a
   !> guess of the force on entry (the force at t) and the force at t+dt on
   !> exit, equal to cit%f_cont; cit%alpha and cit%pattern are the step's.
   subroutine fast_step(solver, model, mb, d_t, imp, dt, hist, d, cit, converged, stat, errmsg)
      type(solver_t), intent(inout) :: solver          !< solver (counts solves, its columns grow)
      type(model_t), intent(in) :: model               !< model
      real(dp), intent(in) :: mb(:)                    !< M {b} of eq. (19)-(20)
      real(dp), intent(in) :: d_t(:)                   !< converged displacements at t
      type(impactor_state_t), intent(in) :: imp        !< impactor at t
      real(dp), intent(in) :: dt                       !< time step (s)
      type(contact_history_t), intent(in) :: hist      !< committed contact history
      real(dp), intent(inout) :: d(:)                  !< first iterate in, solution out
      type(contact_iteration_t), intent(inout) :: cit  !< the force in and out, its indentation and area
      logical, intent(out) :: converged                !< eq. (18) met
      integer, intent(out) :: stat                     !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg        !< reason on failure
      integer, parameter :: max_passes = 50
      real(dp), parameter :: pass_tol = 1.0e-12_dp
      real(dp) :: rhs(size(d)), w_r0, compliance, f, f_new, alpha
      integer :: pass
      logical :: done

      ! impactor position at t+dt if the new force were zero
      w_r0 = imp%w + imp%v*dt - imp%f*dt**2/(4.0_dp*model%impactor_mass)
      converged = .false.
      solver%iterations = 0
      f = max(cit%f_assum, 0.0_dp)
      alpha = 0.0_dp
      call fp_start(solver%guard, size(d), solver%max_iter, solver%cr2)
      nonlinear_iterations: do
         call solve_once(solver, model, mb, d, rhs, stat, errmsg)
         if (stat /= 0) return
         ! -- the contact equation, with the contact area of its root
         contact_passes: do pass = 1, max_passes
            call contact_area(model, hist, f, cit%pattern)
            call contact_response(solver, cit%pattern, stat, errmsg)
            if (stat /= 0) return
            compliance = dt**2/(4.0_dp*model%impactor_mass) + pattern_compliance(solver, cit%pattern)
            call solve_contact_equation(model%law, hist, w_r0 - pattern_mean(cit%pattern, rhs), compliance, &
                                        f_new, alpha)
            done = abs(f_new - f) <= pass_tol*max(f_new, f) .or. model%cload%kind == load_point
            f = f_new
            if (done) exit contact_passes
         end do contact_passes
         call contact_area(model, hist, f, cit%pattern)
         rhs = rhs + f*pattern_response(solver, cit%pattern)
         call iteration_end(solver, model, d_t, rhs, d, converged, done, stat, errmsg)
         if (done .or. stat /= 0) exit nonlinear_iterations
      end do nonlinear_iterations
      cit%f_assum = f;  cit%f_cont = f;  cit%alpha = alpha
   end subroutine fast_step

end module fast_scheme
