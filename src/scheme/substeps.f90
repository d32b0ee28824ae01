!> scheme = 'fast': a time step whose eq. (19) iteration does not meet
!> eq. (18), even with its fall-back, is taken again from the state at t in
!> 2^k sub-steps of dt/2^k, k = 1 .. max_halvings, before the run gives up
!> (above take_substeps); only the whole step is recorded (above
!> fast_step_or_substeps). The paper's scheme ('paper') has none: it is
!> kept as published. More: docs/STABILITY.md.
module substeps
   use kinds, only: dp
   use number_text, only: int_str
   use plate_model, only: model_t, mass_times
   use plate_solver, only: solver_t, solver_refactor
   use contact_iteration, only: step_state_t, step_accept
   use contact_law, only: contact_history_t
   use newmark, only: newmark_t, plate_state_t, impactor_t, newmark_init, newmark_predictor
   use fast_scheme, only: fast_step
   use fixed_point, only: fp_report
   implicit none
   private
   public :: fast_step_or_substeps

   !> The most halvings of a step that did not converge: sub-steps down to
   !> dt/2^max_halvings (2 + 4 + 8 + 16 = 30 sub-steps and 5 factorizations
   !> at most for the step) before the run gives up. Measured on 320 random
   !> extreme scenes (tools/stress/stress.py --random 160, seeds 1 and 2):
   !> with 4, five of the six that stopped run through; the sixth (a 68 g impactor at
   !> 31 m/s on a free 0.17 mm plate, dt = 13.5 us) needs 6, with 390 of its
   !> 400 steps sub-stepped, 244 s of cpu instead of 13 s to its stop, and
   !> w/h = 432, far beyond the model: a stop that names the step is better.
   !> The runs needing none are unchanged, bit for bit.
   integer, parameter :: max_halvings = 4

contains

   !> Only the whole step is recorded: the caller accepts the last sub-step
   !> as it accepts a step, with the Newmark constants of that sub-step
   !> (step_nm), so the step's history row is at t + dt and the plate's
   !> velocities and accelerations are the sub-steps' own. The scheme's
   !> contraction estimate is measured afresh in the sub-steps, and again on
   !> the run's step after them (the steps that follow probe until they have
   !> two measurements: the estimate of the steps before a step that did not
   !> converge is no longer the iteration's). The solver's response columns
   !> of the run's matrix are kept aside during the sub-steps and put back
   !> after (the sub-steps' own are dropped), so the steps that follow use the
   !> same columns as before. solver%substeps tells the recorder how many
   !> sub-steps the step took (src/record/run_recorder.f90, substepped_steps).
   !>
   !> One time step of scheme 'fast' (module fast_scheme), taken again in
   !> sub-steps when its iteration does not converge (module header). On
   !> exit, when the step was sub-stepped, plate, imp and hist are the state
   !> at the start of the last sub-step and step_nm its constants; d and
   !> imp_new are the state at t + dt either way, for the caller to accept
   !> with step_nm (newmark_update) as it accepts a step. When no sub-step
   !> division converged either, plate, imp and hist are those at t and
   !> errmsg says which iteration failed and what was tried.
   subroutine fast_step_or_substeps(solver, model, nm, st, step_nm, converged, stat, errmsg)
      type(solver_t), intent(inout) :: solver          !< solver (its factor is the run's step's on exit)
      type(model_t), intent(in) :: model               !< model
      type(newmark_t), intent(in) :: nm                !< Newmark constants of the run's step dt
      type(step_state_t), intent(inout) :: st          !< the step (its state at t, M {b}; above)
      type(newmark_t), intent(out) :: step_nm          !< the constants to accept d with: nm, or the last sub-step's
      logical, intent(out) :: converged                !< eq. (18) met (in every sub-step)
      integer, intent(out) :: stat                     !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg        !< reason on failure, and when not converged
      type(plate_state_t) :: plate_t                   ! the plate at t
      type(impactor_t) :: imp_t                        ! the impactor at t
      type(contact_history_t) :: hist_t                ! the contact history at t
      real(dp), allocatable :: resp(:,:)               ! the run's response columns, kept aside
      integer, allocatable :: resp_eq(:)               ! their equations
      integer :: nresp                                 ! their number
      integer :: k                                     ! halvings
      character(len=:), allocatable :: why             ! the last sub-step's report when none converged

      step_nm = nm
      solver%substeps = 0
      call fast_step(solver, model, nm, st, converged, stat, errmsg)
      if (stat /= 0) return
      if (converged) return
      why = fp_report(solver%guard)
      plate_t = st%plate;  imp_t = st%imp;  hist_t = st%hist
      nresp = solver%nresp
      call move_alloc(solver%resp, resp);  call move_alloc(solver%resp_eq, resp_eq)
      allocate (solver%resp(size(st%d_new), 0), solver%resp_eq(0))
      halvings: do k = 1, max_halvings
         step_nm = newmark_init(nm%dt/2**k)
         call solver_refactor(solver, model, step_nm, stat, errmsg)
         if (stat /= 0) exit halvings
         st%plate = plate_t;  st%imp = imp_t;  st%hist = hist_t
         call take_substeps(solver, model, step_nm, 2**k, st, converged, stat, errmsg)
         if (stat /= 0) exit halvings
         if (converged) then
            solver%substeps = 2**k
            exit halvings
         end if
         why = fp_report(solver%guard)
      end do halvings
      if (stat == 0) call solver_refactor(solver, model, nm, stat, errmsg)
      call move_alloc(resp, solver%resp);  call move_alloc(resp_eq, solver%resp_eq)
      solver%nresp = nresp
      solver%contraction = huge(1.0_dp);  solver%since_measured = 0
      if (stat /= 0 .or. converged) return
      st%plate = plate_t;  st%imp = imp_t;  st%hist = hist_t;  step_nm = nm
      errmsg = 'the nonlinear iteration (eq. 19) with the contact equation: ' // why // '; taken again in ' &
         // int_str(2**max_halvings) // ' sub-steps of dt/' // int_str(2**max_halvings) // ' (' &
         // int_str(max_halvings) // ' halvings), it did not converge either: ' &
         // 'the time step (&analysis dt) is far too long for the scene, or the scene beyond the model'
   end subroutine fast_step_or_substeps

   !> A step of the run's dt whose eq. (19) iteration (with the contact
   !> equation, src/scheme/fast_scheme.f90) ends without meeting eq. (18),
   !> even with its fall-back, is taken again from the state at t in 2^k
   !> sub-steps of dt/2^k, k = 1, 2, ..., max_halvings, until every sub-step
   !> converges. A shorter step makes the iteration contract faster: its map
   !> D -> (K_L + 4/dt^2 M)^-1 (F + M b - K_N(D) D) has the nonlinear term
   !> against a left-hand matrix whose mass part grows as 1/dt^2, and the
   !> step's change, the iteration's start, shrinks. For each k the left-hand
   !> matrix K_L + 4/dt_sub^2 M is factored anew (module plate_solver,
   !> solver_refactor: the old factor released first, never two at once), and
   !> after the sub-steps the run's K_L + 4/dt^2 M is factored again, with the
   !> same bits as at the set-up. Each sub-step is a fast_step with its own
   !> M {b}; between sub-steps the plate is updated by Newmark's rule of the
   !> sub-step (eq. 20) and the contact history committed, as the time loop
   !> does between steps (src/impact.f90).
   !>
   !> n sub-steps of scheme 'fast' with the constants sub_nm, from plate,
   !> imp and hist: each sub-step but the last accepted as the time loop
   !> accepts a step (Newmark's update, eq. 20; the impactor; the contact
   !> history committed). Stops at the first sub-step that does not
   !> converge.
   subroutine take_substeps(solver, model, sub_nm, n, st, converged, stat, errmsg)
      type(solver_t), intent(inout) :: solver          !< solver, factored for sub_nm
      type(model_t), intent(in) :: model               !< model
      type(newmark_t), intent(in) :: sub_nm            !< Newmark constants of a sub-step
      integer, intent(in) :: n                         !< sub-steps
      type(step_state_t), intent(inout) :: st          !< at t in; at the last sub-step's start and end out
      logical, intent(out) :: converged                !< every sub-step met eq. (18)
      integer, intent(out) :: stat                     !< 0 unless the solver failed
      character(len=*), intent(inout) :: errmsg        !< reason on failure
      integer :: j                                     ! sub-step

      solver%contraction = huge(1.0_dp);  solver%since_measured = 0
      converged = .false.
      stat = 0
      sub_steps: do j = 1, n
         call mass_times(model, newmark_predictor(sub_nm, st%plate%d, st%plate%v, st%plate%a), st%mb)
         call fast_step(solver, model, sub_nm, st, converged, stat, errmsg)
         if (stat /= 0 .or. .not. converged .or. j == n) exit sub_steps
         call step_accept(st, sub_nm, model, commit=.true.)
      end do sub_steps
   end subroutine take_substeps

end module substeps
