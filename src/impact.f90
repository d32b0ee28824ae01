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
!> the file of each is named after it (docs/ALGORITHM.md).
!> Usage: impact [options] [deck.nml]     (no deck: standard input; --help)
program impact
   use, intrinsic :: iso_fortran_env, only: input_unit, output_unit, error_unit
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, accuracy_wanted
   use command_line, only: options_t, parse_command_line, read_input_deck
   use input_deck, only: validate_deck
   use scene_settings, only: choose_settings
   use plate_model, only: model_t, build_model, release_assembled, mass_times
   use plate_solver, only: solver_t, solver_init, plate_solve
   use plate_damage, only: damage_init, damage_update
   use contact_iteration, only: contact_iteration_t, contact_area, contact_start, contact_next, contact_cut, &
      contact_indentation, contact_outcome, contact_report
   use contact_law, only: contact_history_t, contact_commit
   use contact_load, only: pattern_load, pattern_mean
   use substeps, only: fast_step_or_substeps
   use newmark, only: newmark_t, plate_state_t, impactor_t, newmark_init, newmark_predictor, &
      newmark_update, impactor_moved
   use run_recorder, only: record_t, record_open, record_step, record_close
   use step_trace, only: trace_t, trace_parse, trace_step, trace_iteration
   use run_report, only: echo_model, write_answer, usage_line, say_large_chosen_mesh
   use build_info, only: code_version
   use result_files, only: results_claim_t, release_results
   use other_analyses, only: run_other_analysis
   use process_stop, only: catch_stop_signals, stop_after_step, stop_signal_caught, &
      keep_file_size_errors, exit_program
   use restart_point, only: restart_file, restart_save, restart_check, restart_resume, claim_run_files
   use number_text, only: int_str
   use c_library, only: c_isatty
   use accuracy_driver, only: run_accuracy
   use child_process, only: die_with_parent
   implicit none

   type(deck_t) :: deck                    ! the input deck, as read and checked
   type(model_t) :: model                  ! laminate, mesh, [M], [K_L], contact law and load
   type(solver_t) :: solver                ! K_L + 4/dt^2 M factored, and the eq. (19) iteration's state
   type(newmark_t) :: nm                   ! Newmark's constants: the time step dt, 4/dt^2, 4/dt
   type(newmark_t) :: step_nm              ! those the step is accepted with: nm, or its last sub-step's
   type(plate_state_t) :: plate            ! {D}, {V}, {A} at t
   type(impactor_t) :: imp                 ! the impactor (mass; position, velocity, force) at t
   type(impactor_t) :: imp_new             ! the impactor at t+dt under the assumed force
   type(contact_history_t) :: hist         ! the contact's committed history (loading, unloading, alpha_m, F_m)
   type(contact_iteration_t) :: cit        ! the step's contact iteration (Fig. 3, the outer loop)
   type(record_t) :: rec                   ! the run's recorder: history rows, HDF5, summary maxima, warnings
   type(trace_t) :: tr                     ! --trace: the steps whose iterations are printed
   type(results_claim_t) :: claim          ! the result files this run owns (claimed before any work)
   real(dp), allocatable :: mb(:)          ! M {b} of eq. (19)-(20), fixed within a step
   real(dp), allocatable :: d_new(:)       ! {D} at t+dt, the iterate of eq. (19)
   real(dp) :: t                           ! the time at the end of the step (s)
   real(dp) :: cpu0, cpu1                  ! cpu time at the start and now (s)
   integer :: step, nstep                  ! the time step, and their number
   integer :: first_step                   ! the step the time loop starts after (0, or a restart point's)
   integer :: ic                           ! the contact iteration of the step
   integer :: stat                         ! 0, or a failure of the call just made
   logical :: ok                           ! the step's iterations converged (eq. 17, 18)
   logical :: check_only                   ! --check: the data check, no time steps
   logical :: restarting                   ! --restart with a restart point: the run continues from it
   character(len=msg_len) :: errmsg        ! the failure's message

   ! =====================================================================
   ! Input data: the deck (a file, or standard input), the command line's
   ! settings over it; checked against the schema and echoed
   ! =====================================================================
   call catch_stop_signals()          ! from the first instruction: a stop signal ends the set-up at once
   call die_with_parent()             ! a run of an accuracy ladder ends with its parent (src/accuracy/)
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
   nm = newmark_init(deck%dt)          ! from here on dt lives in nm
   call solver_init(model, nm, solver, stat, errmsg)
   if (stat == 0) call damage_init(deck, model, deck%damage_model, deck%damage_viscosity, solver%damage, stat, errmsg)
   if (stat == 0 .and. restarting .and. solver%damage%on) call fail('--restart: a restart point does not keep the ' &
      // 'ply damage (&damage): run the deck again from the start')
   if (stat /= 0) call fail(errmsg)
   call release_assembled(model)      ! the steps need the factor; M x and K_N D are element by element
   call cpu_time(cpu1)
   write (output_unit, '(a,f10.3,a)') 'set-up (model, matrices, factorization): cpu ', cpu1 - cpu0, ' s'
   if (check_only) then
      write (output_unit, '(a)') 'data check: the deck is valid and K_L + 4/dt^2 M is positive definite; no time steps run'
      stop
   end if

   ! =====================================================================
   ! Initial conditions: the plate at rest, the impactor touching it at its
   ! impact velocity; or, with --restart, the run where it stopped
   ! =====================================================================
   cit = contact_iteration_t(update=deck%force_update, cr1=deck%cr1)
   nstep = nint(deck%t_end/nm%dt)
   call stop_after_step()             ! from here a stop signal ends the run after its step, results written
   if (restarting) then
      call restart_resume(deck, model, nstep, solver, plate, imp, hist, cit, rec, first_step, cpu1, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      cpu0 = cpu0 - cpu1                 ! the cpu time of the run before it stopped counts
      write (output_unit, '(a)') 'restart: the run continues after step ' // int_str(first_step) // ' (' &
         // restart_file(deck) // ')'
   else
      allocate (plate%d(model%msh%neq), plate%v(model%msh%neq), plate%a(model%msh%neq), source=0.0_dp)
      imp = impactor_t(mass=deck%mass, w=0.0_dp, v=deck%velocity, f=0.0_dp)
      call contact_area(model, hist, imp%f, cit%pattern)
      step = 0;  t = 0.0_dp
      call record_open(rec, deck, model, solver, imp, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg, 'failed while opening the results')
      first_step = 0
      call save_restart_point(first_step)
   end if
   allocate (mb(model%msh%neq), d_new(model%msh%neq))

   ! =====================================================================
   ! Time integration (Fig. 3), the paper's scheme first; scheme 'fast' is
   ! its one-call alternative (src/scheme/fast_scheme.f90)
   ! =====================================================================
   time_steps: do step = first_step + 1, nstep
      t = real(step, dp)*nm%dt
      call trace_step(tr, step, t, imp, .false.)
      ! -- {b} of eq. (20) and M{b}, fixed for the whole step
      call mass_times(model, newmark_predictor(nm, plate%d, plate%v, plate%a), mb)
      step_nm = nm
      if (deck%scheme == 'paper') then
         ! -- assume the contact force, the plate not reacting at first (section 2.3)
         call contact_start(cit, model, hist, nm, imp, pattern_mean(cit%pattern, plate%d))
         d_new = plate%d
         contact_iterations: do ic = 1, deck%max_contact_iter
            cit%iterations = ic
            ! -- the plate under the assumed force over its contact area: eq. (19) until eq. (18)
            call plate_solve(solver, model, mb + pattern_load(cit%pattern, cit%f_assum, model%msh%neq), &
                             plate%d, d_new, cit%solved, stat, errmsg)
            if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
            if (.not. cit%solved) then                   ! eq. (19) failed: the force was too high
               call contact_cut(cit, model, hist);  d_new = plate%d
               cycle contact_iterations
            end if
            ! -- the impactor under the same force, eq. (21)
            imp_new = impactor_moved(nm, imp, cit%f_assum)
            ! -- the indentation, eq. (13), the law's force, eq. (11)-(12), and eq. (17)
            call contact_indentation(cit, model, hist, imp_new, d_new)
            call trace_iteration(tr, step, ic, cit, solver, imp_new, d_new, hist, deck%scheme)
            if (cit%converged) exit contact_iterations
            if (ic < deck%max_contact_iter) call contact_next(cit, model, hist)   ! a new assumed force
         end do contact_iterations
         ! -- eq. (17) met, or 'plain' goes on with F_cont; else the run stops
         call contact_outcome(cit, imp_new, ok)
         if (.not. ok) call fail_in_run('time step did not converge: the contact iteration (eq. 17): ' // contact_report(cit))
      else
         ! -- scheme 'fast': the contact equation inside each eq. (19) iteration (sub-steps if it fails)
         call fast_step_or_substeps(solver, model, nm, mb, plate, imp, hist, d_new, imp_new, cit, step_nm, ok, &
                                    stat, errmsg)
         call check_solver('the nonlinear iteration (eq. 19) with the contact equation')
         call trace_iteration(tr, step, 1, cit, solver, imp_new, d_new, hist, deck%scheme)
      end if
      ! -- accept the step: Newmark update (eq. 20; after sub-steps, the last one's), impactor, contact
      call newmark_update(step_nm, plate%d, d_new, plate%v, plate%a)
      plate%d = d_new;  imp = imp_new
      call damage_update(solver%damage, model, plate%d, nm%dt)     ! ply damage of the step (src/strength/)
      call record_step(rec, step, model, solver, plate, imp, hist, cit, cit%iterations, cit%converged, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
      call contact_commit(model%law, hist, cit%alpha)
      call trace_step(tr, step, t, imp, .true.)
      ! -- a divergence, or a warning with stop_on_warning; a stop signal; a restart point once a second
      if (rec%stop) call finish(rec%stop_status, rec%exit_status)
      if (stop_signal_caught() > 0) call stop_on_signal()
      if (rec%restart_due) call save_restart_point(step)
   end do time_steps

   ! =====================================================================
   ! Summary
   ! =====================================================================
   call finish('completed', 0)

contains

   !> The command line, the deck and its settings (src/deck/command_line.f90),
   !> dt and the mesh chosen from the scene where the deck gives none
   !> (src/model/scene_settings.f90); an accuracy run (&accuracy target
   !> given) hands over to its driver and
   !> ends there; an impact run claims its result files before any work.
   subroutine read_input()
      type(options_t) :: opts
      integer :: accuracy_exit            ! the exit status of an accuracy run
      call parse_command_line(opts, stat, errmsg)
      if (stat /= 0) call bad_usage(errmsg)
      call write_answer(opts%action, output_unit, code_version)     ! --help, --version, --schema, --deck-table
      if (opts%action /= 'run') stop
      check_only = opts%check
      restarting = opts%restart .and. .not. check_only
      call trace_parse(opts%trace, tr, stat)
      if (stat /= 0) call bad_usage('--trace ' // opts%trace // ': give time steps, e.g. --trace 120,121')
      if (len(opts%deck_path) == 0) then      ! on a terminal, what it waits for (else it waits without a word)
         if (c_isatty(0) == 1) write (error_unit, '(a)') 'impact: reading the deck from standard input, a ' &
            // 'terminal: type it and end with Ctrl-D, or give a deck file (' // usage_line(8:) &
            // '; impact --help: the options)'
      end if
      call read_input_deck(opts, input_unit, deck, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call choose_settings(deck)            ! dt, nx, ny the deck does not give: from the scene
      call validate_deck(deck, stat, errmsg)   ! (the chosen ones checked as given ones)
      if (stat /= 0) call fail(errmsg)
      call say_large_chosen_mesh(deck, output_unit)
      if (accuracy_wanted(deck) .and. .not. check_only) then     ! a ladder of runs (src/accuracy/)
         call run_accuracy(opts, deck, output_unit, accuracy_exit, stat, errmsg)
         if (stat /= 0) call fail(errmsg)
         call exit_program(accuracy_exit)
      end if
      tr%unit = output_unit;  tr%cr1 = deck%cr1;  tr%cr2 = deck%cr2
      if (restarting) call restart_check(deck, restarting, first_step, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      if (restarting .and. first_step == nint(deck%t_end/deck%dt)) then    ! nothing to do, nothing rewritten
         write (output_unit, '(a)') 'restart: the run is complete: its restart point ' // restart_file(deck) &
            // ' is at its last step, ' // int_str(first_step) // '; nothing is done (give a later &analysis ' &
            // 't_end to continue it)'
         stop
      end if
      if (opts%restart .and. .not. (restarting .or. check_only)) write (output_unit, '(a)') &
         'restart: no restart point ' // restart_file(deck) // ': the run starts at step 0'
      if (check_only) return
      call claim_run_files(deck, opts%restart, restarting, claim, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine read_input

   !> A solver failure or a step of scheme 'fast' that did not converge, even
   !> in sub-steps, stops the run (errmsg: the iteration's report).
   subroutine check_solver(what)
      character(len=*), intent(in) :: what
      if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
      if (.not. ok) call fail_in_run('time step did not converge: ' // what // ': ' // trim(errmsg))
   end subroutine check_solver

   !> The end of a run: the summary with its status, the last words; a run
   !> that completed or was stopped by a signal leaves its restart point.
   subroutine finish(status, exit_code)
      character(len=*), intent(in) :: status
      integer, intent(in) :: exit_code
      call cpu_time(cpu1)
      call record_close(rec, deck, model, solver, status, hist, imp, cpu1 - cpu0, output_unit, stat, errmsg)
      if (stat == 0 .and. (exit_code == 0 .or. exit_code > 128)) &
         call restart_save(deck, rec%steps, cpu1 - cpu0, plate, imp, hist, cit, solver, rec, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'impact: error: ' // trim(errmsg)
      call release_results(claim, discard=.false.)
      if (exit_code /= 0 .or. stat /= 0) call exit_program(merge(exit_code, 1, exit_code > 128))  ! a signal: 128 + N
      stop
   end subroutine finish

   !> A stop signal caught during the step: the run ends here, its results
   !> written (exit status 128 + the signal's number).
   subroutine stop_on_signal()
      call finish('stopped by signal ' // int_str(stop_signal_caught()) // ' at step ' // int_str(step), &
                  128 + stop_signal_caught())
   end subroutine stop_on_signal

   !> A restart point after step `at` (src/results/restart_point.f90): the
   !> files were just flushed.
   subroutine save_restart_point(at)
      integer, intent(in) :: at
      call cpu_time(cpu1)
      call restart_save(deck, at, cpu1 - cpu0, plate, imp, hist, cit, solver, rec, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
   end subroutine save_restart_point

   !> Stops during the run, keeping what was computed: the history is on
   !> disk, the summary says how far the run got.
   subroutine fail_in_run(message, status)
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: status
      character(len=80) :: where
      write (where, '(a,i0,a,es11.4,a)') 'failed at step ', step, ' (t = ', t, ' s)'
      if (present(status)) then          ! before the first step: no results
         where = status
         write (error_unit, '(a/a)') 'impact: error: ' // trim(message), 'impact: ' // trim(where) // ': no step ran'
      else
         write (error_unit, '(a/a)') 'impact: error: ' // trim(message), 'impact: ' // trim(where) &
            // '; results up to the last step are in ' // deck%prefix // '_history.dat'
      end if
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
