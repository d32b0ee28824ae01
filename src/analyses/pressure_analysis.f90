!> Transient analysis (`&analysis kind = 'pressure'`): the plate at rest, loaded at t = 0 by
!> the load of `&load` (a uniform or sinusoidal pressure, or a central force) held constant to
!> t_end. The time integration is the impact analysis's without the impactor: Newmark's rule
!> with Akay's constant left-hand matrix, eq. (19)-(20),
!>     (K_L + 4/dt^2 M) D^{n+1}_{t+dt} = F + M {b} - K_N(D^n) D^n,
!> iterated to eq. (18); its start and energy: above pressure_solve.
!> More: docs/ANALYSES.md.
module pressure_analysis
   use number_text, only: int_str
   use kinds, only: dp
   use plate_model, only: model_t, centre_deflection, plate_kinetic_energy, &
      plate_strain_energy
   use newmark, only: newmark_t, newmark_init, newmark_predictor, newmark_update
   use global_matrix, only: global_matrix_t, global_copy, global_factor, global_solve, global_matvec, global_release
   use plate_solver, only: solver_t, solver_init, plate_solve
   use mesh, only: describe_equation
   implicit none
   private
   public :: pressure_result_t, pressure_solve

   !> Response history (index 0: t = 0).
   type :: pressure_result_t
      integer :: nstep = 0                       !< time steps done
      real(dp), allocatable :: t(:)              !< (0:nstep) time (s)
      real(dp), allocatable :: w_centre(:)       !< (0:nstep) centre deflection (m)
      real(dp), allocatable :: kinetic(:)        !< (0:nstep) plate kinetic energy (J)
      real(dp), allocatable :: strain(:)         !< (0:nstep) strain energy (J)
      real(dp), allocatable :: work(:)           !< (0:nstep) work of the load, F . D (J)
      integer, allocatable :: iterations(:)      !< (0:nstep) plate solutions of the step
      integer :: unconverged = 0                 !< steps whose eq. (18) iteration did not converge
   end type pressure_result_t

contains

   !> Integrates nstep steps of dt from rest under the load f applied at
   !> t = 0: the initial acceleration is M^-1 F (zero would cost the rule its
   !> second order). The energies (W = F . D, kinetic, strain; W - KE - U = 0
   !> to rounding in the linear theory) every `every` steps and at the last.
   subroutine pressure_solve(model, f, dt, nstep, every, res, stat, errmsg)
      type(model_t), intent(in) :: model           !< model
      real(dp), intent(in) :: f(:)                 !< load vector (N)
      real(dp), intent(in) :: dt                   !< time step (s)
      integer, intent(in) :: nstep                 !< number of steps
      integer, intent(in) :: every                 !< energies every this many steps
      type(pressure_result_t), intent(out) :: res  !< history
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< reason on failure
      type(newmark_t) :: nm
      type(global_matrix_t) :: mfac
      real(dp) :: d(size(f)), v(size(f)), a(size(f)), d_new(size(f)), rhs(size(f))
      type(solver_t) :: solver
      integer :: step, bad_eq, solves0
      logical :: converged
      allocate (res%t(0:nstep), res%w_centre(0:nstep), res%kinetic(0:nstep), res%strain(0:nstep), &
                res%work(0:nstep), source=0.0_dp)
      allocate (res%iterations(0:nstep), source=0)

      ! -- initial acceleration M a = F (the plate at rest)
      call global_copy(mfac, model%mass)
      call global_factor(mfac, stat, errmsg, bad_eq)
      if (stat /= 0 .and. bad_eq > 0) errmsg = 'pressure: M is not positive definite: pivot of ' // &
         trim(describe_equation(model%msh, bad_eq))
      if (stat /= 0) return
      d = 0.0_dp;  v = 0.0_dp;  a = f
      call global_solve(mfac, a, stat, errmsg)
      call global_release(mfac)       ! M's factor is not needed again (sparse: C memory)
      if (stat /= 0) return

      ! -- K_L + 4/dt^2 M, factored once (eq. 19)
      nm = newmark_init(dt)
      call solver_init(model, nm, solver, stat, errmsg)
      if (stat /= 0) return

      time_steps: do step = 1, nstep
         call global_matvec(model%mass, newmark_predictor(nm, d, v, a), rhs)
         rhs = rhs + f
         d_new = d
         solves0 = solver%solves
         call plate_solve(solver, model, rhs, d, d_new, converged, stat, errmsg)
         if (stat /= 0) then
            errmsg = 'pressure: step ' // int_str(step) // ': ' // trim(errmsg)
            return
         end if
         if (.not. converged) res%unconverged = res%unconverged + 1
         call newmark_update(nm, d, d_new, v, a)
         d = d_new
         res%nstep = step
         res%t(step) = real(step, dp)*dt
         res%w_centre(step) = centre_deflection(model, d)
         res%iterations(step) = solver%solves - solves0
         if (mod(step, every) == 0 .or. step == nstep) then
            res%kinetic(step) = plate_kinetic_energy(model, v)
            res%strain(step) = plate_strain_energy(model, d)
            res%work(step) = dot_product(f, d)*model%msh%sym_factor
         end if
      end do time_steps
   end subroutine pressure_solve

end module pressure_analysis
