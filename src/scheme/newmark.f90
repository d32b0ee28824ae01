!> Newmark's constant average acceleration rule (beta = 1/4, gamma = 1/2)
!> for the plate, eq. (19)-(20), and the average-acceleration update of the
!> rigid impactor, eq. (16), (21).
!>
!> Plate, with a0 = 4/dt^2 and a1 = 4/dt:
!>   {b} = a0 {D}_t + a1 {V}_t + {A}_t                                  eq. (20)
!>   (K_L + a0 M) {D}_{t+dt} = {F}_{t+dt} + M {b} - K_N {D}              eq. (19)
!>   {A}_{t+dt} = a0 ({D}_{t+dt} - {D}_t) - a1 {V}_t - {A}_t
!>   {V}_{t+dt} = {V}_t + dt/2 ({A}_t + {A}_{t+dt})
!> The rule is unconditionally stable and has no amplitude decay for a
!> linear system; its period elongation is (omega dt)^2/12 to leading order.
!> Impactor (w positive the way it moves, m w'' + F = 0, eq. 16):
!>   w''_{t,t+dt} = -(F_t + F_{t+dt})/(2 m)                               eq. (21)
!>   w_{t+dt} = w_t + w'_t dt + w''_{t,t+dt} dt^2/2
!>   w'_{t+dt} = w'_t + w''_{t,t+dt} dt
module newmark
   use kinds, only: dp
   implicit none
   private
   public :: newmark_t, plate_state_t, impactor_t, newmark_init, newmark_predictor, newmark_update, &
             impactor_advance, impactor_moved, impactor_compliance

   !> The integration constants of a time step dt: the one place the run's
   !> time step lives once the deck is read.
   type :: newmark_t
      real(dp) :: dt = 0.0_dp   !< time step (s)
      real(dp) :: a0 = 0.0_dp   !< 4/dt^2 (1/s^2)
      real(dp) :: a1 = 0.0_dp   !< 4/dt (1/s)
   end type newmark_t

   !> The plate's displacements, velocities and accelerations {D}, {V}, {A}.
   type :: plate_state_t
      real(dp), allocatable :: d(:), v(:), a(:)
   end type plate_state_t

   !> The rigid impactor (eq. 16, 21): its mass, and its position, velocity
   !> and contact force at one time.
   type :: impactor_t
      real(dp) :: mass = 0.0_dp   !< m (kg)
      real(dp) :: w = 0.0_dp      !< position from first touch (m), positive towards the plate
      real(dp) :: v = 0.0_dp      !< velocity (m/s), positive towards the plate
      real(dp) :: f = 0.0_dp      !< contact force at the same time (N)
   end type impactor_t

contains

   !> Constants of the average acceleration rule for the step dt.
   pure function newmark_init(dt) result(nm)
      real(dp), intent(in) :: dt   !< time step (s)
      type(newmark_t) :: nm
      nm%dt = dt
      nm%a0 = 4.0_dp/dt**2
      nm%a1 = 4.0_dp/dt
   end function newmark_init

   !> {b} of eq. (20).
   pure function newmark_predictor(nm, d, v, a) result(b)
      type(newmark_t), intent(in) :: nm   !< constants
      real(dp), intent(in) :: d(:)        !< displacements at t
      real(dp), intent(in) :: v(:)        !< velocities at t
      real(dp), intent(in) :: a(:)        !< accelerations at t
      real(dp) :: b(size(d))
      b = nm%a0*d + nm%a1*v + a
   end function newmark_predictor

   !> Velocities and accelerations at t+dt from the new displacements.
   pure subroutine newmark_update(nm, d_old, d_new, v, a)
      type(newmark_t), intent(in) :: nm       !< constants
      real(dp), intent(in) :: d_old(:)        !< displacements at t
      real(dp), intent(in) :: d_new(:)        !< displacements at t+dt
      real(dp), intent(inout) :: v(:)         !< velocities, t -> t+dt
      real(dp), intent(inout) :: a(:)         !< accelerations, t -> t+dt
      real(dp) :: a_new(size(a))
      a_new = nm%a0*(d_new - d_old) - nm%a1*v - a
      v = v + 0.5_dp*nm%dt*(a + a_new)
      a = a_new
   end subroutine newmark_update

   !> Position and velocity of the rigid impactor at t+dt, eq. (21).
   pure subroutine impactor_advance(mass, dt, w, v, f_old, f_new, w_new, v_new)
      real(dp), intent(in) :: mass     !< impactor mass (kg)
      real(dp), intent(in) :: dt       !< time step (s)
      real(dp), intent(in) :: w, v     !< position (m) and velocity (m/s) at t
      real(dp), intent(in) :: f_old    !< contact force at t (N)
      real(dp), intent(in) :: f_new    !< contact force at t+dt (N)
      real(dp), intent(out) :: w_new   !< position at t+dt (m)
      real(dp), intent(out) :: v_new   !< velocity at t+dt (m/s)
      real(dp) :: acc
      acc = -(f_old + f_new)/(2.0_dp*mass)
      w_new = w + v*dt + 0.5_dp*acc*dt**2
      v_new = v + acc*dt
   end subroutine impactor_advance

   !> The impactor at t+dt under the force f_new at t+dt, eq. (21); its force
   !> is f_new.
   pure function impactor_moved(nm, imp, f_new) result(imp_new)
      type(newmark_t), intent(in) :: nm      !< constants (the step dt)
      type(impactor_t), intent(in) :: imp    !< the impactor at t
      real(dp), intent(in) :: f_new          !< contact force at t+dt (N)
      type(impactor_t) :: imp_new
      imp_new%mass = imp%mass
      call impactor_advance(imp%mass, nm%dt, imp%w, imp%v, imp%f, f_new, imp_new%w, imp_new%v)
      imp_new%f = f_new
   end function impactor_moved

   !> The impactor's compliance over a step, dt^2/(4 m) (m/N): by eq. (21) its
   !> position at t+dt moves back by this much per newton of the force at t+dt.
   pure function impactor_compliance(nm, imp) result(c)
      type(newmark_t), intent(in) :: nm      !< constants (the step dt)
      type(impactor_t), intent(in) :: imp    !< the impactor (its mass)
      real(dp) :: c
      c = nm%dt**2/(4.0_dp*imp%mass)
   end function impactor_compliance

end module newmark
