!> impact: nonlinear analysis of a composite laminate struck by a rigid
!> impactor at low velocity, after I. H. Choi, C. S. Hong and I. Lee,
!> "Nonlinear Analysis of Composite Laminates Subjected to Low-Velocity
!> Impact", KSME Transactions (1991). Equation numbers are the paper's.
!>
!> The program is the paper's flowchart (Fig. 3): read the data; form the
!> laminate, the mesh and the matrices; factor the left-hand matrix once
!> (Akay); then in every time step assume a contact force, solve the plate
!> nonlinearly under it (eq. 19, 18), move the impactor (eq. 21), compute
!> the indentation and the law's force (eq. 13, 11, 12), and repeat until
!> the assumed and computed forces agree (eq. 17). Each box is one call;
!> the file of each is named after it (README, "From the paper to the code").
!>
!> Usage: impact [options] [deck.nml]     (no deck: standard input; --help)
program impact
   use, intrinsic :: iso_fortran_env, only: input_unit, output_unit, error_unit
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t
   use deck_echo, only: write_schema, write_deck_table
   use command_line, only: options_t, parse_command_line, read_input_deck
   use plate_model, only: model_t, build_model, mass_times
   use plate_solver, only: solver_t, solver_init, plate_solve
   use contact_iteration, only: contact_iteration_t, contact_area, contact_start, contact_next, contact_cut, &
      contact_converged, contact_report
   use contact_law, only: contact_history_t, contact_force, contact_commit
   use contact_load, only: pattern_load, pattern_mean
   use fast_scheme, only: fast_step, predicted_displacements
   use newmark, only: newmark_t, plate_state_t, impactor_state_t, newmark_init, newmark_predictor, &
      newmark_update, impactor_moved
   use run_recorder, only: record_t, record_open, record_step, record_close
   use step_trace, only: trace_t, trace_parse, trace_step, trace_iteration
   use run_report, only: echo_model, usage, usage_line
   use build_info, only: code_version
   use result_files, only: results_claim_t, result_suffixes, claim_results, release_results
   use fixed_point, only: fp_report
   use other_analyses, only: run_other_analysis
   use program_exit, only: exit_program
   use signal_stop, only: catch_stop_signals, keep_file_size_errors
   implicit none

   type(deck_t) :: deck
   type(model_t) :: model
   type(solver_t) :: solver
   type(newmark_t) :: nm
   type(plate_state_t) :: plate
   type(impactor_state_t) :: imp, imp_new
   type(contact_history_t) :: hist
   type(contact_iteration_t) :: cit
   type(record_t) :: rec
   type(trace_t) :: tr
   type(results_claim_t) :: claim
   real(dp), allocatable :: mb(:), d_new(:)
   real(dp) :: t, cpu0, cpu1
   integer :: stat, step, nstep, ic
   logical :: ok, solved, check_only
   character(len=msg_len) :: errmsg

   ! =====================================================================
   ! Input data: the deck (a file, or standard input), the command line's
   ! settings over it; checked against the schema and echoed
   ! =====================================================================
   call keep_file_size_errors()       ! past ulimit -f a write fails and the run says so
   call read_input()
   call cpu_time(cpu0)

   ! =====================================================================
   ! Laminate stiffness (eq. 6) and inertia (eq. 9); mesh and boundary
   ! conditions (Fig. 4); [M] and [K_L] assembled (eq. 15, Appendix B)
   ! =====================================================================
   call build_model(deck, model, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call echo_model(deck, model, output_unit)

   ! -- the other analyses of the same model (&analysis kind) end here
   if (deck%analysis_kind /= 'impact') then
      if (.not. check_only) call run_other_analysis(deck, model, output_unit, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call release_results(claim, discard=.false.)
      stop
   end if

   ! =====================================================================
   ! Newmark constants; the left-hand matrix of eq. (19), K_L + 4/dt^2 M,
   ! factored once (Akay's constant-coefficient scheme)
   ! =====================================================================
   nm = newmark_init(deck%dt)
   call solver_init(model, nm, solver, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call cpu_time(cpu1)
   write (output_unit, '(a,f10.3,a)') 'set-up (model, matrices, factorization): cpu ', cpu1 - cpu0, ' s'
   if (check_only) then
      write (output_unit, '(a)') 'data check: the deck is valid and K_L + 4/dt^2 M is positive definite; no time steps run'
      stop
   end if

   ! =====================================================================
   ! Initial conditions: the plate at rest, the impactor touching it at its
   ! impact velocity
   ! =====================================================================
   allocate (plate%d(model%msh%neq), plate%v(model%msh%neq), plate%a(model%msh%neq), source=0.0_dp)
   allocate (mb(model%msh%neq), d_new(model%msh%neq))
   imp = impactor_state_t(w=0.0_dp, v=deck%velocity, f=0.0_dp)
   call contact_area(model, hist, imp%f, cit%pattern)
   nstep = nint(deck%t_end/deck%dt)
   call record_open(rec, deck, model, solver, imp, stat, errmsg)
   if (stat /= 0) call fail_in_run(errmsg, 'failed while opening the results')

   ! =====================================================================
   ! Time integration (SIGTERM, SIGINT: stop after the step, src/system/signal_stop.f90)
   ! =====================================================================
   call catch_stop_signals()
   time_steps: do step = 1, nstep
      t = real(step, dp)*deck%dt
      call trace_step(tr, step, t, imp, .false.)
      ! -- {b} of eq. (20) and M{b}, fixed for the whole step
      call mass_times(model, newmark_predictor(nm, plate%d, plate%v, plate%a), mb)

      if (deck%scheme == 'fast') then
         ! -- the one-call alternative: the contact equation solved inside each eq. (19) iteration
         d_new = predicted_displacements(deck%dt, plate%d, plate%v)
         cit%f_assum = imp%f
         call fast_step(solver, model, mb, plate%d, imp, deck%dt, hist, d_new, cit, ok, stat, errmsg)
         call check_solver('the nonlinear iteration (eq. 19) with the contact equation')
         imp_new = impactor_moved(deck%mass, deck%dt, imp, cit%f_assum)
         ic = 1
         call trace_iteration(tr, step, ic, cit, solver, imp_new, d_new, hist, deck%scheme)
      else
         ! -- Fig. 3: assume the contact force, the plate not reacting at first (section 2.3)
         call contact_start(cit, model, hist, imp, pattern_mean(cit%pattern, plate%d), deck%dt, deck%force_update)
         d_new = plate%d;  solved = .false.
         contact_iterations: do ic = 1, deck%max_contact_iter
            ! -- the plate under the assumed force over its contact area: eq. (19) until eq. (18)
            call plate_solve(solver, model, mb + pattern_load(cit%pattern, cit%f_assum, model%msh%neq), &
                             plate%d, d_new, ok, stat, errmsg)
            if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
            solved = ok
            if (.not. ok) then                           ! eq. (19) failed: the force was too high
               call contact_cut(cit, model, hist)
               d_new = plate%d
               cycle contact_iterations
            end if
            ! -- the impactor under the same force, eq. (21)
            imp_new = impactor_moved(deck%mass, deck%dt, imp, cit%f_assum)
            ! -- the indentation, eq. (13), and the law's force, eq. (11)-(12)
            cit%alpha = imp_new%w - pattern_mean(cit%pattern, d_new)
            cit%f_cont = contact_force(model%law, hist, cit%alpha)
            call trace_iteration(tr, step, ic, cit, solver, imp_new, d_new, hist, deck%scheme)
            ! -- eq. (17): the forces agree, or a new assumed force
            if (contact_converged(cit%f_assum, cit%f_cont, deck%cr1, hist%f_m)) exit contact_iterations
            if (ic < deck%max_contact_iter) call contact_next(cit, model, hist)
         end do contact_iterations
         ok = ic <= deck%max_contact_iter
         ic = min(ic, deck%max_contact_iter)
         if (.not. ok .and. (deck%force_update /= 'plain' .or. .not. solved)) call fail_in_run('time step did not converge: ' &
            // 'the contact iteration (eq. 17): ' // contact_report(cit, deck%cr1, ic))
         if (.not. ok) imp_new%f = cit%f_cont     ! 'plain', the plate solved: F_assum <- F_cont, on to the next step
      end if

      ! -- accept the step: Newmark update (eq. 20), the impactor, the contact history
      call newmark_update(nm, plate%d, d_new, plate%v, plate%a)
      plate%d = d_new
      imp = imp_new
      call record_step(rec, step, model, solver, plate, imp, hist, cit, ic, ok, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
      call contact_commit(model%law, hist, cit%alpha)
      call trace_step(tr, step, t, imp, .true.)
      if (rec%stop) call finish(rec%stop_status, rec%exit_status)
   end do time_steps

   ! =====================================================================
   ! Summary
   ! =====================================================================
   call finish('completed', 0)

contains

   !> The command line, the deck and its settings (src/deck/command_line.f90);
   !> an impact run claims its result files before any work.
   subroutine read_input()
      type(options_t) :: opts
      call parse_command_line(opts, stat, errmsg)
      if (stat /= 0) call bad_usage(errmsg)
      select case (opts%action)
      case ('help');       call usage(output_unit)
      case ('version');    write (output_unit, '(a)') code_version
      case ('schema');     call write_schema(output_unit)
      case ('deck-table'); call write_deck_table(output_unit)
      end select
      if (opts%action /= 'run') stop
      check_only = opts%check
      call trace_parse(opts%trace, tr, stat)
      if (stat /= 0) call bad_usage('--trace ' // opts%trace // ': give time steps, e.g. --trace 120,121')
      call read_input_deck(opts, input_unit, deck, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      tr%unit = output_unit;  tr%cr1 = deck%cr1;  tr%cr2 = deck%cr2
      if (.not. check_only) then
         call claim_results(deck, result_suffixes(deck%analysis_kind), claim, stat, errmsg)
         if (stat /= 0) call fail(errmsg)
      end if
   end subroutine read_input

   !> A solver failure or an unconverged step of scheme 'fast' stops the run.
   subroutine check_solver(what)
      character(len=*), intent(in) :: what
      if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
      if (.not. ok) call fail_in_run('time step did not converge: ' // what // ': ' // fp_report(solver%guard))
   end subroutine check_solver

   !> The end of a run: the summary with its status, the last words.
   subroutine finish(status, exit_code)
      character(len=*), intent(in) :: status
      integer, intent(in) :: exit_code
      call cpu_time(cpu1)
      call record_close(rec, deck, model, solver, status, hist, imp, cpu1 - cpu0, output_unit, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'impact: error: ' // trim(errmsg)
      call release_results(claim, discard=.false.)
      if (exit_code /= 0 .or. stat /= 0) call exit_program(merge(exit_code, 1, exit_code > 128))  ! a signal: 128 + N
      stop
   end subroutine finish

   !> Stops during the run, keeping what was computed: the history is on
   !> disk, the summary says how far the run got.
   subroutine fail_in_run(message, status)
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: status
      character(len=80) :: where
      write (where, '(a,i0,a,es11.4,a)') 'failed at step ', step, ' (t = ', t, ' s)'
      if (present(status)) where = status
      write (error_unit, '(a/a)') 'impact: error: ' // trim(message), 'impact: ' // trim(where) &
         // '; results up to the last step are in ' // deck%prefix // '_history.dat'
      call finish(trim(where), 1)
   end subroutine fail_in_run

   !> Stops before any result exists: one line, exit status 1; a result
   !> file the claim created, still empty, is removed.
   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'impact: error: ' // trim(message)
      call release_results(claim, discard=.true.)
      call exit_program(1)
   end subroutine fail

   !> A wrong command line: the message and the usage's line, exit status 1.
   subroutine bad_usage(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a/a)') 'impact: error: ' // trim(message), usage_line // '      (impact --help: the options)'
      call exit_program(1)
   end subroutine bad_usage

end program impact
