!> The teaching trace: `impact --trace STEP[,STEP...] deck.nml` prints, for
!> those steps, every box of the paper's flowchart (Fig. 3) with its
!> equation: the assumed force, eq. (19) with its eq. (18) ratio, eq. (21),
!> (13), (11-12) and the test of eq. (17). docs/ALGORITHM.md walks one step.
module step_trace
   use kinds, only: dp
   use plate_solver, only: solver_t
   use contact_iteration, only: step_state_t, contact_converged
   use contact_law, only: contact_branch
   use contact_load, only: pattern_mean
   use newmark, only: impactor_t
   implicit none
   private
   public :: trace_t, trace_parse, trace_step, trace_iteration

   !> Which steps to trace, and where to.
   type :: trace_t
      integer, allocatable :: steps(:)     !< the steps traced (none: no trace)
      integer :: unit = 6                  !< where the trace goes (standard output)
      real(dp) :: cr1 = 0.0_dp, cr2 = 0.0_dp   !< the tolerances, for the tests printed
   end type trace_t

   character(len=*), parameter :: branch_names(0:3) = [character(len=9) :: 'none', 'loading', 'unloading', &
      'reloading']

contains

   !> The steps of a list '120,121,400'; stat /= 0 when it is not one.
   subroutine trace_parse(list, tr, stat)
      character(len=*), intent(in) :: list     !< the steps, comma-separated
      type(trace_t), intent(inout) :: tr       !< the trace
      integer, intent(out) :: stat             !< 0, or 1 when list is not a list of steps
      integer :: from, comma, step
      from = 1
      if (.not. allocated(tr%steps)) allocate (tr%steps(0))
      stat = 0
      if (len(list) == 0) return
      stat = 1
      do
         comma = index(list(from:), ',')
         if (comma == 0) comma = len(list) - from + 2
         if (verify(list(from:from + comma - 2), '0123456789') /= 0 .or. comma < 2) return
         read (list(from:from + comma - 2), *) step
         if (step < 1) return
         tr%steps = [tr%steps, step]
         from = from + comma
         if (from > len(list)) exit
      end do
      stat = 0
   end subroutine trace_parse

   !> The start (done false) or end (done true) of a traced step.
   subroutine trace_step(tr, step, t, imp, done)
      type(trace_t), intent(in) :: tr
      integer, intent(in) :: step              !< the step
      real(dp), intent(in) :: t                !< its time t + dt (s)
      type(impactor_t), intent(in) :: imp    !< the impactor at t (done false) or t + dt (true)
      logical, intent(in) :: done
      if (.not. traced(tr, step)) return
      if (.not. done) then
         write (tr%unit, '(a,i0,a,es12.5,a)') 'trace: step ', step, ' to t = ', t, ' s (Fig. 3, one pass of the time loop)'
         write (tr%unit, '(a,es13.6,a,es13.6,a,es13.6,a)') 'trace:   the impactor at t: w_r = ', imp%w, ' m, v = ', &
            imp%v, ' m/s, F = ', imp%f, ' N'
      else
         write (tr%unit, '(a,es13.6,a,es13.6,a)') 'trace:   step accepted: F = ', imp%f, ' N, w_r = ', imp%w, &
            ' m; Newmark update of V, A (eq. 20), contact history committed'
      end if
   end subroutine trace_step

   !> One contact iteration ic of a traced step, box by box.
   subroutine trace_iteration(tr, step, st, solver, scheme)
      type(trace_t), intent(in) :: tr
      integer, intent(in) :: step              !< the step
      type(step_state_t), intent(in) :: st     !< its contact iteration, plate solution and impactor moved
      type(solver_t), intent(in) :: solver     !< the eq. (19) iterations of the plate solution
      character(len=*), intent(in) :: scheme   !< 'paper' or 'fast'
      integer :: n
      if (.not. traced(tr, step)) return
      associate (cit => st%cit, ic => st%cit%iterations, imp_new => st%imp_new, d => st%d_new, hist => st%hist)
      if (scheme == 'fast') then
         write (tr%unit, '(a)') "trace:   scheme 'fast': the contact equation F = F_law(alpha(F)) solved inside " &
            // 'each eq. (19) iteration (src/scheme/fast_scheme.f90)'
      else if (cit%pattern%radius > 0.0_dp) then
         write (tr%unit, '(a,i0,a,es13.6,a,es11.4,a,i0,a)') 'trace:   contact iteration ', ic, &
            ': assumed force F_assum = ', cit%f_assum, ' N over a contact disc of radius ', cit%pattern%radius, &
            ' m (Hertz''s pressure on ', cit%pattern%n, ' equations)'
      else
         write (tr%unit, '(a,i0,a,es13.6,a)') 'trace:   contact iteration ', ic, &
            ': assumed force F_assum = ', cit%f_assum, ' N at the impact node (the point force, eq. 10)'
      end if
      do n = 1, solver%iterations
         write (tr%unit, '(a,i0,a,es10.3,a,es10.3)') 'trace:     eq. (19) iteration ', n, &
            ': eq. (18) ratio sum (D^n+1 - D^n)^2 / sum (D^n+1 - D_t)^2 = ', solver%ratios(n), '  C_r2 = ', tr%cr2
      end do
      n = solver%iterations
      if (scheme == 'fast' .and. n == 1 .and. solver%ratios(1) > tr%cr2) then
         write (tr%unit, '(a,es10.3,a,es10.3,a)') 'trace:     the first solution is the answer: eq. (18) on the ' &
            // 'next change, theta^2 x ratio = ', solver%guard%theta2_first*solver%ratios(1), ' < C_r2 (theta^2 = ', &
            solver%guard%theta2_first, ' measured on earlier steps)'
      else if (scheme == 'fast' .and. n == 2 .and. solver%ratios(2) <= tr%cr2) then
         write (tr%unit, '(a)') 'trace:     a probe: the second solution measured the first (theta^2 = ratio 2 / ' &
            // 'ratio 1), which meets eq. (18) and stays the answer'
      end if
      write (tr%unit, '(a,es13.6,a)') 'trace:     eq. (21) impactor: w_r(t+dt) = ', imp_new%w, ' m'
      write (tr%unit, '(a,es13.6,a,es13.6,a)') 'trace:     eq. (13) indentation: alpha = w_r - w_p = ', cit%alpha, &
         ' m (w_p = ', pattern_mean(cit%pattern, d), ' m, under the impactor)'
      write (tr%unit, '(a,es13.6,a)') 'trace:     eq. (11)-(12) the law: F_cont = ', cit%f_cont, ' N on the ' &
         // trim(branch_names(contact_branch(hist, cit%alpha))) // ' branch'
      write (tr%unit, '(a,es10.3,a,es10.3,a)') 'trace:     eq. (17) |F_assum - F_cont| / F_assum = ', &
         abs(cit%f_assum - cit%f_cont)/max(cit%f_assum, tiny(1.0_dp)), ' against C_r1 = ', tr%cr1, ': ' &
         // trim(merge('converged    ', 'not converged', &
            contact_converged(cit%f_assum, cit%f_cont, tr%cr1, hist%f_m)))
      end associate
   end subroutine trace_iteration

   pure logical function traced(tr, step)
      type(trace_t), intent(in) :: tr
      integer, intent(in) :: step
      traced = .false.
      if (allocated(tr%steps)) traced = any(tr%steps == step)
   end function traced

end module step_trace
