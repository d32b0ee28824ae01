!> impact: nonlinear analysis of a composite laminate struck by a rigid
!> impactor at low velocity, after I. H. Choi, C. S. Hong and I. Lee,
!> "Nonlinear Analysis of Composite Laminates Subjected to Low-Velocity
!> Impact", KSME Transactions (1991). Equation numbers are the paper's.
!> The program is the paper's flowchart (Fig. 3), one call per box; the
!> file of each is named after it (docs/ALGORITHM.md).
!> Usage: impact [options] [deck.nml]     (no deck: standard input; --help)
program impact
   use, intrinsic :: iso_fortran_env, only: input_unit, output_unit, error_unit
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, accuracy_wanted
   use command_line, only: options_t, parse_command_line, read_input_deck
   use input_deck, only: validate_deck
   use scene_settings, only: choose_settings
   use plate_model, only: model_t, build_model, release_assembled, mass_times
   use plate_solver, only: solver_t, solver_init, plate_solve, plate_compliance
   use contact_iteration, only: step_state_t, contact_iteration_t, step_start, step_accept, contact_start, &
      contact_next, contact_cut, contact_indentation, contact_outcome, contact_report
   use contact_law, only: contact_commit
   use plate_damage, only: damage_init, damage_update
   use contact_load, only: pattern_load, pattern_mean
   use substeps, only: fast_step_or_substeps
   use newmark, only: newmark_t, impactor_t, newmark_init, newmark_predictor, impactor_moved
   use run_recorder, only: record_t, record_open, record_step, record_close
   use step_trace, only: trace_t, trace_parse, trace_step, trace_iteration
   use run_report, only: echo_model, write_answer, usage_line, say_large_chosen_mesh
   use result_files, only: results_claim_t, release_results
   use other_analyses, only: run_other_analysis
   use process_stop, only: catch_stop_signals, stop_after_step, stop_signal_caught, &
      keep_file_size_errors, exit_program
   use restart_point, only: restart_save, restart_check, restart_resume, claim_run_files
   use number_text, only: int_str
   use c_library, only: c_isatty
   use accuracy_driver, only: run_accuracy
   use child_process, only: die_with_parent
   implicit none

   type(deck_t) :: deck                    ! the input deck, as read and checked
   type(model_t) :: model                  ! laminate, mesh, [M], [K_L], contact law and load
   type(solver_t) :: solver                ! K_L + 4/dt^2 M factored, and the eq. (19) iteration's state
   type(newmark_t) :: nm, step_nm          ! Newmark's constants (dt, 4/dt^2, 4/dt); the step's: nm or a sub-step's
   type(step_state_t) :: st                ! the step: plate, impactor, contact history and iteration
   type(record_t) :: rec                   ! the run's record: history rows, HDF5, summary maxima, warnings
   type(trace_t) :: tr                     ! --trace: the steps whose iterations are printed
   type(results_claim_t) :: claim          ! the result files this run owns (claimed before any work)
   real(dp) :: cpu0, cpu1, c_plate         ! cpu time (s); the plate's compliance over a step (m/N)
   integer :: step, nstep, first_step, ic  ! the step, their number, the first's predecessor, contact iteration
   integer :: stat                         ! 0, or a failure of the call just made
   logical :: ok, check_only, restarting   ! the step converged; --check; --restart from a restart point
   character(len=msg_len) :: errmsg        ! the failure's message

   ! == Input data: the deck (a file, or standard input), the command line's settings over it
   call catch_stop_signals()          ! from the first instruction: a stop signal ends the set-up at once
   call die_with_parent()             ! a run of an accuracy ladder ends with its parent (src/accuracy/)
   call keep_file_size_errors()       ! past ulimit -f a write fails and the run says so
   call read_input()
   call cpu_time(cpu0)

   ! == Laminate stiffness (eq. 6), inertia (eq. 9); mesh, boundary conditions (Fig. 4); [M], [K_L] (eq. 15)
   call build_model(deck, model, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call echo_model(deck, model, output_unit)
   if (deck%analysis_kind /= 'impact') then      ! the other analyses of the same model end here
      if (.not. check_only) call run_other_analysis(deck, model, output_unit, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      call release_results(claim, discard=.false.)
      stop
   end if

   ! == The left-hand matrix of eq. (19), K_L + 4/dt^2 M, factored once (Akay's constant coefficients)
   call solver_init(model, nm, solver, stat, errmsg)
   if (stat == 0) call damage_init(deck, model, deck%damage_model, deck%damage_viscosity, solver%damage, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call release_assembled(model)      ! the steps need the factor; M x and K_N D are element by element
   call cpu_time(cpu1)
   write (output_unit, '(a,f10.3,a)') 'set-up (model, matrices, factorization): cpu ', cpu1 - cpu0, ' s'
   if (check_only) then
      write (output_unit, '(a)') 'data check: the deck is valid and K_L + 4/dt^2 M is positive definite; no time steps run'
      stop
   end if

   ! == Initial conditions: the plate at rest, the impactor touching it at v0; or, --restart, where it stopped
   call step_start(st, model, impactor_t(mass=deck%mass, w=0.0_dp, v=deck%velocity, f=0.0_dp), &
                   contact_iteration_t(update=deck%force_update, cr1=deck%cr1))
   call stop_after_step()             ! from here a stop signal ends the run after its step, results written
   if (restarting) then               ! (the state, the solver's counters and the record as they were)
      call restart_resume(deck, model, nm, solver, st, rec, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      first_step = rec%steps;  cpu0 = cpu0 - rec%cpu_before    ! the cpu time of the run before it stopped counts
   else
      step = 0;  first_step = 0;  c_plate = -1.0_dp
      ! -- scheme 'paper': the plate's compliance over a step, for the summary's fixed-point slope
      if (deck%scheme == 'paper') call plate_compliance(solver, st%cit%pattern, c_plate, stat, errmsg)
      if (stat == 0) call record_open(rec, deck, model, nm, st%imp, c_plate, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg, 'failed while opening the results')
      call save_restart_point()
   end if

   ! == Time integration (Fig. 3): scheme 'fast' in one call (src/scheme/fast_scheme.f90), or the paper's boxes
   time_steps: do step = first_step + 1, nstep
      call trace_step(tr, step, step*nm%dt, st%imp, .false.)
      ! -- {b} of eq. (20) and M{b}, fixed for the whole step
      call mass_times(model, newmark_predictor(nm, st%plate%d, st%plate%v, st%plate%a), st%mb)
      if (deck%scheme == 'fast') then
         ! -- scheme 'fast': the contact equation inside each eq. (19) iteration (sub-steps if it fails)
         call fast_step_or_substeps(solver, model, nm, st, step_nm, ok, stat, errmsg)
         if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
         if (.not. ok) call fail_in_run('time step did not converge: ' // trim(errmsg))
         call trace_iteration(tr, step, st, solver, deck%scheme)
      else
         ! -- assume the contact force, the plate not reacting at first (section 2.3)
         call contact_start(st%cit, model, st%hist, nm, st%imp, pattern_mean(st%cit%pattern, st%plate%d))
         st%d_new = st%plate%d;  step_nm = nm
         contact_iterations: do ic = 1, deck%max_contact_iter
            st%cit%iterations = ic
            ! -- the plate under the assumed force over its contact area: eq. (19) until eq. (18)
            call plate_solve(solver, model, st%mb + pattern_load(st%cit%pattern, st%cit%f_assum, model%msh%neq), &
                             st%plate%d, st%d_new, st%cit%solved, stat, errmsg)
            if (stat /= 0) call fail_in_run('plate solution: ' // errmsg)
            if (.not. st%cit%solved) then                ! eq. (19) failed: the force was too high
               call contact_cut(st%cit, model, st%hist);  st%d_new = st%plate%d
               cycle contact_iterations
            end if
            ! -- the impactor under the same force, eq. (21)
            st%imp_new = impactor_moved(nm, st%imp, st%cit%f_assum)
            ! -- the indentation, eq. (13), the law's force, eq. (11)-(12), and eq. (17)
            call contact_indentation(st%cit, model, st%hist, st%imp_new, st%d_new)
            call trace_iteration(tr, step, st, solver, deck%scheme)
            if (st%cit%converged) exit contact_iterations
            if (ic < deck%max_contact_iter) call contact_next(st%cit, model, st%hist)   ! a new assumed force
         end do contact_iterations
         ! -- eq. (17) met, or 'plain' goes on with F_cont; else the run stops
         call contact_outcome(st%cit, st%imp_new, ok)
         if (.not. ok) call fail_in_run('time step did not converge: the contact iteration (eq. 17): ' &
                                        // contact_report(st%cit))
      end if
      ! -- accept the step: Newmark update (eq. 20; after sub-steps, the last one's), impactor; record; contact
      call step_accept(st, step_nm, model, commit=.false.)
      call damage_update(solver%damage, model, st%plate%d, nm%dt)     ! ply damage of the step (src/strength/)
      call record_step(rec, step, model, solver, st, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
      call contact_commit(model%law, st%hist, st%cit%alpha)
      call trace_step(tr, step, step*nm%dt, st%imp, .true.)
      ! -- a divergence, or a warning with stop_on_warning; a stop signal; a restart point once a second
      if (rec%stop) call finish((rec%stop_status), rec%exit_status)   ! (a copy: finish sets it)
      if (stop_signal_caught() > 0) call finish('stopped by signal ' // int_str(stop_signal_caught()) // ' at step ' &
                                                // int_str(step), 128 + stop_signal_caught())
      if (rec%restart_due) call save_restart_point()
   end do time_steps

   ! == Summary
   call finish('completed', 0)

contains

   !> The command line, the deck and its settings (src/deck/command_line.f90),
   !> dt and the mesh chosen from the scene where the deck gives none; an
   !> accuracy run hands over to its driver; an impact run claims its files.
   subroutine read_input()
      type(options_t) :: opts
      integer :: accuracy_exit            ! the exit status of an accuracy run
      call parse_command_line(opts, stat, errmsg)
      if (stat /= 0) call bad_usage(errmsg)
      call write_answer(opts%action, output_unit)     ! --help, --version, --schema, --deck-table
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
      nm = newmark_init(deck%dt)            ! from here on dt lives in nm
      nstep = nint(deck%t_end/nm%dt)
      if (accuracy_wanted(deck) .and. .not. check_only) then     ! a ladder of runs (src/accuracy/)
         call run_accuracy(opts, deck, output_unit, accuracy_exit, stat, errmsg)
         if (stat /= 0) call fail(errmsg)
         call exit_program(accuracy_exit)
      end if
      tr%unit = output_unit;  tr%cr1 = deck%cr1;  tr%cr2 = deck%cr2
      if (restarting) call restart_check(deck, nstep, restarting, first_step, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
      if (restarting .and. first_step == nstep) stop    ! complete (restart_check said so): nothing rewritten
      if (check_only) return
      call claim_run_files(deck, opts%restart, restarting, claim, stat, errmsg)
      if (stat /= 0) call fail(errmsg)
   end subroutine read_input

   !> The end of a run: the summary, the last words; a run that completed or
   !> was stopped by a signal leaves its restart point.
   subroutine finish(status, exit_code)
      character(len=*), intent(in) :: status
      integer, intent(in) :: exit_code
      call cpu_time(cpu1)
      rec%stop_status = status
      call record_close(rec, deck, model, solver, st, cpu1 - cpu0, stat, errmsg)
      if (stat == 0 .and. (exit_code == 0 .or. exit_code > 128)) &
         call restart_save(deck, cpu1 - cpu0, st, solver, rec, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'impact: error: ' // trim(errmsg)
      call release_results(claim, discard=.false.)
      if (exit_code /= 0 .or. stat /= 0) call exit_program(merge(exit_code, 1, exit_code > 128))  ! a signal: 128 + N
      stop
   end subroutine finish

   !> A restart point after the step just recorded (the files were just flushed).
   subroutine save_restart_point()
      call cpu_time(cpu1)
      call restart_save(deck, cpu1 - cpu0, st, solver, rec, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
   end subroutine save_restart_point

   !> Stops during the run: the history is on disk, the summary says how far.
   subroutine fail_in_run(message, status)
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: status
      character(len=80) :: where
      character(len=:), allocatable :: note
      write (where, '(a,i0,a,es11.4,a)') 'failed at step ', step, ' (t = ', step*nm%dt, ' s)'
      note = '; results up to the last step are in ' // deck%prefix // '_history.dat'
      if (present(status)) where = status            ! before the first step: no results
      if (present(status)) note = ': no step ran'
      write (error_unit, '(a/a)') 'impact: error: ' // trim(message), 'impact: ' // trim(where) // note
      call finish(trim(where), 1)
   end subroutine fail_in_run

   !> Stops before any result exists (exit status 1): a result file the
   !> claim created, still empty, is removed.
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
