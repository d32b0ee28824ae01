!> The impactor and the contact law alone: a rigid mass striking a rigid
!> target (validation check 6, docs/VALIDATION.md). The plate of the impact
!> analysis is replaced by a target that does not move, w_plate = 0, and
!> everything else is the impact analysis's own code: the impactor's
!> average-acceleration update (eq. 16, 21; newmark), the indentation law
!> with its history (eq. 11-13; contact_law), and the contact-force
!> iteration of a time step, eq. (17), with the same first guess and the
!> same bracketed update (src/scheme/contact_iteration.f90). Its closed form is Hertz's
!> (reference_solutions, hertz_impact).
!>
!> The run starts at first touch (alpha = 0, speed v0 towards the target)
!> and ends at separation: the step in which alpha falls to alpha_0 (the
!> permanent indentation), the crossing time interpolated linearly
!> within that step (alpha is smooth there, so the error is O(dt^2)).
module rigid_target
   use kinds, only: dp
   use contact_law, only: contact_law_t, contact_history_t, contact_force, contact_commit
   use newmark, only: impactor_advance
   use contact_iteration, only: force_bracket_t, bracket_update, contact_converged
   implicit none
   private
   public :: rigid_target_result_t, rigid_target_impact

   !> What a rigid-target impact gives.
   type :: rigid_target_result_t
      real(dp) :: alpha_m = 0.0_dp      !< largest indentation (m)
      real(dp) :: f_m = 0.0_dp          !< largest force (N)
      real(dp) :: duration = 0.0_dp     !< contact duration (s)
      real(dp) :: restitution = 0.0_dp  !< rebound speed / impact speed (-)
      real(dp) :: alpha_0 = 0.0_dp      !< permanent indentation at the end (m)
      integer :: steps = 0              !< time steps taken
      integer :: max_iterations = 0     !< most contact iterations in a step
      logical :: separated = .false.    !< the impactor left the target within max_steps
   end type rigid_target_result_t

contains

   !> Integrates the impact with steps dt until separation (at most
   !> max_steps steps), iterating the contact force of each step to
   !> |F_assumed - F_law| < cr1 F_assumed (eq. 17, at most max_iter times).
   pure function rigid_target_impact(mass, v0, law, dt, cr1, max_iter, max_steps) result(r)
      real(dp), intent(in) :: mass                 !< impactor mass (kg)
      real(dp), intent(in) :: v0                   !< impact speed (m/s)
      type(contact_law_t), intent(in) :: law       !< contact law (eq. 11-12)
      real(dp), intent(in) :: dt                   !< time step (s)
      real(dp), intent(in) :: cr1                  !< contact-force tolerance C_r1 (-)
      integer, intent(in) :: max_iter              !< contact iterations per step, at most
      integer, intent(in) :: max_steps             !< time steps, at most
      type(rigid_target_result_t) :: r
      type(contact_history_t) :: hist
      type(force_bracket_t) :: br
      real(dp) :: w, v, f, w_new, v_new, fa, fc, fnext
      integer :: step, it

      w = 0.0_dp;  v = v0;  f = 0.0_dp
      time_steps: do step = 1, max_steps
         ! -- the first guess: the impactor moves on under the force at t alone
         call impactor_advance(mass, dt, w, v, f, 0.0_dp, w_new, v_new)
         fa = contact_force(law, hist, w_new)
         br = force_bracket_t()
         contact_iterations: do it = 1, max_iter
            call impactor_advance(mass, dt, w, v, f, fa, w_new, v_new)   ! eq. (21)
            fc = contact_force(law, hist, w_new)                         ! eq. (11)-(13), w_plate = 0
            if (contact_converged(fa, fc, cr1, hist%f_m)) exit contact_iterations  ! eq. (17)
            call bracket_update(br, fa, fc, fnext)
            fa = fnext
         end do contact_iterations
         r%max_iterations = max(r%max_iterations, min(it, max_iter))
         r%steps = step
         r%f_m = max(r%f_m, fa)
         r%alpha_m = max(r%alpha_m, w_new)
         call contact_commit(law, hist, w_new)
         if (w_new <= hist%alpha_0 .and. step > 1) then
            ! -- separation within this step: interpolate alpha = alpha_0
            r%duration = real(step, dp)*dt - dt*(hist%alpha_0 - w_new)/(w - w_new)
            r%restitution = -v_new/v0
            r%separated = .true.
            exit time_steps
         end if
         w = w_new;  v = v_new;  f = fa
      end do time_steps
      r%alpha_0 = hist%alpha_0
   end function rigid_target_impact

end module rigid_target
