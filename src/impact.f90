!> impact: nonlinear analysis of a composite laminate struck by a rigid
!> impactor at low velocity, after I. H. Choi, C. S. Hong and I. Lee,
!> "Nonlinear Analysis of Composite Laminates Subjected to Low-Velocity
!> Impact", KSME Transactions (1991). Equation numbers are the paper's.
!>
!> Usage:  ./impact < deck.nml      or      ./impact deck.nml
!>         ./impact --check deck.nml   (or --check < deck.nml): read, echo,
!>         build and factor, then stop before the time loop (a data check).
!>         ./impact --overwrite deck.nml: replace the results of an earlier
!>         run with the same prefix (as &output overwrite = .true.).
!>
!> A time step whose iterations do not converge, even after their
!> fall-backs (fixed_point, bracket_cut, force_update), stops the run with
!> the step, the time and the residuals named; the history keeps every
!> step before it (docs/STABILITY.md).
!>
!> The program follows the flowchart of the paper's Fig. 3: read the data,
!> form the laminate, the mesh and the matrices, factor the left-hand matrix
!> once (Akay), then in every time step assume a contact force, solve the
!> plate nonlinearly under it (eq. 19, 18), move the impactor (eq. 21),
!> compute the indentation and the law's force (eq. 13, 11, 12), and repeat
!> until the assumed and computed forces agree (eq. 17).
program impact
   use, intrinsic :: iso_fortran_env, only: input_unit, output_unit, error_unit
   use, intrinsic :: ieee_exceptions, only: ieee_set_flag, ieee_all
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, read_deck, read_deck_file, echo_deck
   use contact_law, only: contact_history_t, contact_force, contact_branch, contact_commit
   use newmark, only: newmark_t, newmark_init, newmark_predictor, newmark_update, impactor_advance
   use global_matrix, only: global_bandwidth, global_stored_entries
   use impact_driver, only: model_t, plate_state_t, impactor_state_t, force_bracket_t, &
      build_model, factor_effective_matrix, plate_solve, bracket_start, bracket_update, &
      fast_step, predicted_displacements, mass_times, contact_area, contact_work_increment, &
      contact_converged, first_force_guess, plate_kinetic_energy, plate_strain_energy, &
      back_face_strain, impact_deflection, &
      bracket_cut, fixed_point_force, contact_report, max_deflection, von_karman_limit
   use scene_model, only: write_scene_report, theory_warning, bending_deflection
   use output_files, only: history_row_t, run_summary_t, open_history, write_history_row, &
      summary_record, write_summary, check_output
   use fixed_point, only: fp_report
   use contact_load, only: load_pattern_t
   use static_analysis, only: run_static
   use modal_analysis, only: run_modes
   use pressure_analysis, only: run_pressure
   use results_hdf5, only: results_file_t, results_open, results_append_history, results_snapshot, &
      results_peak, results_finish
   implicit none

   type(deck_t) :: deck
   type(model_t) :: model
   type(newmark_t) :: nm
   type(plate_state_t) :: plate
   type(impactor_state_t) :: imp, imp_new
   type(contact_history_t) :: hist
   type(force_bracket_t) :: br
   type(history_row_t) :: row
   type(run_summary_t) :: summary
   type(results_file_t) :: results
   real(dp), allocatable :: mb(:), d_new(:)
   type(load_pattern_t) :: pattern_old
   real(dp) :: t, f_assum, f_cont, f_next, alpha, alpha_old, w_plate, w_plate_old, e0, t_cpu0, t_cpu1
   real(dp) :: contact_work, indentation_energy, w_bend, w_bend_max, w_step
   integer :: stat, step, nstep, hist_unit, ic, nl_iter, step_solves
   logical :: nl_ok, contact_ok, check_only, theory_short
   character(len=msg_len) :: errmsg, path, arg
   character(len=4*msg_len) :: report
   integer :: iarg
   logical :: overwrite, step_mixing, step_cut, warned_mixing, warned_contact, warned_w
   character(len=:), allocatable :: mixing_note

   ! =====================================================================
   ! Input data: the namelist deck, from a file named on the command line
   ! or from standard input; validated and echoed.
   ! =====================================================================
   errmsg = ''
   check_only = .false.
   overwrite = .false.
   iarg = 1
   options: do while (iarg <= command_argument_count())
      call get_command_argument(iarg, arg)
      if (arg == '--check') then
         check_only = .true.
      else if (arg == '--overwrite') then
         overwrite = .true.
      else if (arg(1:1) == '-') then
         call fail('unknown option '//trim(arg)// &
            ' (usage: impact [--check] [--overwrite] [deck.nml], or the deck on standard input)')
      else
         exit options
      end if
      iarg = iarg + 1
   end do options
   if (command_argument_count() >= iarg) then
      call get_command_argument(iarg, arg)
      call read_deck_file(trim(arg), deck, stat, errmsg)
   else
      call read_deck(input_unit, '<stdin>', deck, stat, errmsg)
   end if
   if (stat /= 0) call fail('input: '//errmsg)
   if (overwrite) deck%overwrite = .true.
   ! -- the results can be written, and no other run's results are replaced
   if (deck%analysis_kind == 'impact') then
      call check_output(deck, stat, errmsg)
      if (stat /= 0) call fail('input: '//errmsg)
   end if
   call cpu_time(t_cpu0)

   ! =====================================================================
   ! Laminate stiffness (eq. 6) and inertia (eq. 9); mesh and boundary
   ! conditions (Fig. 4); [M] and [K_L] assembled (eq. 15, Appendix B).
   ! =====================================================================
   call build_model(deck, model, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call echo_run(output_unit)

   ! =====================================================================
   ! The other analyses of the same model (&analysis kind): static load,
   ! natural modes, transient pressure. Each writes its own result files;
   ! the run then ends here (--check: only the data check below).
   ! =====================================================================
   if (deck%analysis_kind /= 'impact' .and. .not. check_only) then
      select case (deck%analysis_kind)
      case ('static')
         call run_static(deck, model, report, stat, errmsg)
      case ('modes')
         call run_modes(deck, model, report, stat, errmsg)
      case ('pressure')
         call run_pressure(deck, model, report, stat, errmsg)
      end select
      if (len_trim(report) > 0) write (output_unit, '(a)') trim(report)
      if (stat /= 0) call fail(errmsg)
      stop
   end if

   ! =====================================================================
   ! Newmark constants and the left-hand matrix of eq. (19),
   ! K_L + 4/dt^2 M, factored once (Akay's constant-coefficient scheme).
   ! =====================================================================
   nm = newmark_init(deck%dt)
   call factor_effective_matrix(model, nm, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call cpu_time(t_cpu1)
   write (output_unit, '(a,f10.3,a)') 'set-up (model, matrices, factorization): cpu ', t_cpu1 - t_cpu0, ' s'
   if (check_only) then
      write (output_unit, '(a)') 'data check: the deck is valid and K_L + 4/dt^2 M is positive definite; no time steps run'
      stop
   end if

   ! =====================================================================
   ! Initial conditions: the plate at rest, the impactor just touching it
   ! at its impact velocity.
   ! =====================================================================
   allocate (plate%d(model%msh%neq), plate%v(model%msh%neq), plate%a(model%msh%neq))
   allocate (mb(model%msh%neq), d_new(model%msh%neq))
   plate%d = 0.0_dp;  plate%v = 0.0_dp;  plate%a = 0.0_dp
   imp = impactor_state_t(w=0.0_dp, v=deck%velocity, f=0.0_dp)
   e0 = 0.5_dp*deck%mass*deck%velocity**2
   summary%initial_energy = e0
   contact_work = 0.0_dp;  indentation_energy = 0.0_dp
   alpha_old = 0.0_dp;  w_plate_old = 0.0_dp
   pattern_old = model%pattern
   warned_mixing = .false.;  warned_contact = .false.;  warned_w = .false.
   w_bend_max = 0.0_dp
   nstep = nint(deck%t_end/deck%dt)

   call open_history(deck, hist_unit, path, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   row = history_row_t(v_impactor=imp%v, ke_impactor=e0)
   call write_history_row(hist_unit, row)
   ! -- <prefix>.h5 (&output hdf5): deck, mesh, and the history as it grows
   call results_open(deck, model%msh, results, stat, errmsg)
   if (stat /= 0) call fail(errmsg)
   call results_append_history(results, row, stat, errmsg)
   if (stat /= 0) call fail(errmsg)

   ! =====================================================================
   ! Time integration
   ! =====================================================================
   time_steps: do step = 1, nstep
      t = real(step, dp)*deck%dt

      ! -- {b} of eq. (20) and M{b}, fixed for the whole step
      call mass_times(model, newmark_predictor(nm, plate%d, plate%v, plate%a), mb)

      d_new = plate%d
      contact_ok = .false.
      step_solves = model%solves
      step_mixing = .false.;  step_cut = .false.

      if (deck%scheme == 'fast') then
         ! -- scheme 'fast': the contact force solved inside each iteration of
         !    eq. (19), from the scalar equation F = F_law(alpha(F)) (eq. 11-13, 21),
         !    the iteration starting where the plate's velocity would take it
         d_new = predicted_displacements(deck%dt, plate%d, plate%v)
         f_assum = imp%f
         call fast_step(model, mb, plate%d, imp, deck%dt, hist, d_new, f_assum, alpha, &
                        nl_iter, nl_ok, stat, errmsg)
         if (stat /= 0) call fail_in_run('plate solution: '//errmsg)
         if (model%nl_guard%mixing) call note_mixing()
         if (.not. nl_ok) call fail_to_converge('the nonlinear iteration (eq. 19) with the contact equation: ' &
            //fp_report(model%nl_guard))
         call impactor_advance(deck%mass, deck%dt, imp%w, imp%v, imp%f, f_assum, imp_new%w, imp_new%v)
         w_plate = impact_deflection(model, d_new)
         f_cont = f_assum
         ic = 1
         contact_ok = .true.
      else
      ! -- scheme 'paper' (Fig. 3): assume the contact force, the plate not
      !    reacting at first (section 2.3), then iterate on it
      f_assum = first_force_guess(model, imp, impact_deflection(model, plate%d), deck%dt, hist)
      br = bracket_start()

      contact_iterations: do ic = 1, deck%max_contact_iter
         ! -- the plate under the assumed force, over its contact area:
         !    eq. (19) iterated to eq. (18)
         call contact_area(model, hist, f_assum)
         call plate_solve(model, mb, f_assum, plate%d, d_new, nl_iter, nl_ok, stat, errmsg)
         if (stat /= 0) call fail_in_run('plate solution: '//errmsg)
         if (model%nl_guard%mixing) call note_mixing()
         if (.not. nl_ok) then
            ! -- eq. (19) failed under this force even with its fall-back:
            !    the force is taken as too high, and the bracket cut below it
            if (ic == deck%max_contact_iter) call fail_to_converge('the nonlinear iteration (eq. 19) under ' &
               //'the assumed force '//real_text(f_assum)//' N: '//fp_report(model%nl_guard))
            call bracket_cut(br, f_assum, f_next)
            step_cut = .true.
            d_new = plate%d
            f_assum = f_next
            cycle contact_iterations
         end if

         ! -- the impactor under the same force, eq. (21)
         call impactor_advance(deck%mass, deck%dt, imp%w, imp%v, imp%f, f_assum, imp_new%w, imp_new%v)

         ! -- indentation, eq. (13), and the law's force, eq. (11)-(12)
         w_plate = impact_deflection(model, d_new)
         alpha = imp_new%w - w_plate
         f_cont = contact_force(model%law, hist, alpha)

         ! -- assumed and computed forces agree? eq. (17)
         if (contact_converged(f_assum, f_cont, deck%cr1)) then
            contact_ok = .true.
            exit contact_iterations
         end if
         if (ic == deck%max_contact_iter) exit contact_iterations   ! the last pair, for the diagnostic
         call bracket_update(br, f_assum, f_cont, f_next)
         if (deck%force_update == 'fixed_point') call fixed_point_force(br, f_assum, f_cont, f_next)
         f_assum = f_next
      end do contact_iterations
      ic = min(ic, deck%max_contact_iter)
      end if
      if (.not. contact_ok) call fail_to_converge('the contact iteration (eq. 17): ' &
         //contact_report(br, f_assum, f_cont, deck%cr1, deck%max_contact_iter))

      ! -- accept the step: Newmark update, impactor, contact history; the
      !    work of the contact force on the plate, and what the impactor
      !    lost beyond it (the energy the contact took)
      call newmark_update(nm, plate%d, d_new, plate%v, plate%a)
      imp_new%f = f_assum
      w_step = contact_work_increment(pattern_old, imp%f, model%pattern, imp_new%f, d_new - plate%d)
      contact_work = contact_work + w_step
      indentation_energy = indentation_energy + 0.5_dp*(imp%f + imp_new%f)*(imp_new%w - imp%w) - w_step
      plate%d = d_new
      pattern_old = model%pattern
      imp = imp_new
      call contact_commit(model%law, hist, alpha)
      w_plate_old = w_plate;  alpha_old = alpha

      call summary_record(summary, t, imp%f, w_plate, back_face_strain(model, plate%d))
      summary%contact_iterations = summary%contact_iterations + ic
      summary%max_contact_iter = max(summary%max_contact_iter, ic)
      summary%max_nonlinear_iter = max(summary%max_nonlinear_iter, model%solves - step_solves)
      summary%steps = step
      call bending_deflection(model%msh, deck%edges, plate%d, w_bend, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
      w_bend_max = max(w_bend_max, abs(w_bend))

      ! -- output
      if (mod(step, deck%every) == 0 .or. step == nstep) then
         row%time = t;  row%force = imp%f;  row%alpha = alpha
         row%w_plate = w_plate;  row%w_impactor = imp%w;  row%v_impactor = imp%v
         row%strain_y = back_face_strain(model, plate%d)
         row%ke_impactor = 0.5_dp*deck%mass*imp%v**2
         row%ke_plate = plate_kinetic_energy(model, plate%v)
         row%strain_energy = plate_strain_energy(model, plate%d)
         row%contact_work = contact_work
         row%indentation_energy = indentation_energy
         row%energy_error = e0 - (row%ke_impactor + row%ke_plate + row%strain_energy + indentation_energy)
         row%branch = contact_branch(hist, alpha)
         if (imp%f <= 0.0_dp) row%branch = 0
         row%contact_iter = ic
         row%nonlinear_iter = model%solves - step_solves
         summary%max_energy_error = max(summary%max_energy_error, abs(row%energy_error))
         call write_history_row(hist_unit, row)
         call results_append_history(results, row, stat, errmsg)
         if (stat /= 0) call fail_in_run(errmsg)
      end if
      ! -- field snapshots in <prefix>.h5: the largest force so far, every fields_every steps, the last
      call results_peak(results, step, t, imp%f, plate%d, stat, errmsg)
      if (stat /= 0) call fail_in_run(errmsg)
      if (mod(step, deck%fields_every) == 0 .or. step == nstep) then
         call results_snapshot(results, step, t, imp%f, plate%d, stat, errmsg)
         if (stat /= 0) call fail_in_run(errmsg)
      end if
      ! -- warnings: the fall-backs the step needed, deflections beyond von
      !    Karman's theory (w/h > 5); &analysis stop_on_warning stops the run
      if (step_mixing) then
         summary%nonlinear_fallback_steps = summary%nonlinear_fallback_steps + 1
         if (.not. warned_mixing) call warn(warned_mixing, 'the nonlinear iteration (eq. 19) fell back to ' &
            //'Anderson mixing and converged (later such steps are counted in the summary, ' &
            //'nonlinear_fallback_steps): '//mixing_note)
      end if
      if (step_cut .or. br%fell_back) then
         summary%contact_fallback_steps = summary%contact_fallback_steps + 1
         if (.not. warned_contact) call warn(warned_contact, trim(merge( &
            'the fixed-point force update stopped contracting; the step went on with the bracketed update', &
            'a plate solution failed under an assumed force; the force was cut and the step converged    ', &
            br%fell_back))//' (later such steps are counted in the summary, contact_fallback_steps)')
      end if
      summary%max_w_over_h = max(summary%max_w_over_h, max_deflection(model, plate%d)/deck%h)
      if (summary%max_w_over_h > von_karman_limit .and. .not. warned_w) call warn(warned_w, &
         'the plate deflection is '//real_text(summary%max_w_over_h)//' times the thickness, beyond the ' &
         //'moderately large deflections of von Karman''s theory (w/h > '//real_text(von_karman_limit) &
         //'): the results are outside the model''s validity')
   end do time_steps

   ! =====================================================================
   ! Summary
   ! =====================================================================
   close (hist_unit)
   call finish_summary('completed')
   write (output_unit, '(a)') 'history: '//trim(path)
   write (output_unit, '(a)') 'summary: '//trim(deck%prefix)//'_summary.dat'
   if (deck%hdf5) write (output_unit, '(a)') 'results: '//trim(deck%prefix)//'.h5'
   write (output_unit, '(a,es12.5,a,f9.2,a,i0,a,es12.5,a,f8.3,a)') 'peak force ', summary%peak_force, &
      ' N at ', summary%time_of_peak*1.0e6_dp, ' us; contacts ', summary%contacts, &
      '; max deflection ', summary%max_deflection*1.0e3_dp, ' mm; cpu ', summary%cpu_s, ' s'
   if (summary%warnings > 0) write (error_unit, '(a,i0,a,i0,a,i0,a,f0.2)') 'impact: ', summary%warnings, &
      ' warning(s) above; steps with a fall-back: nonlinear ', summary%nonlinear_fallback_steps, &
      ', contact ', summary%contact_fallback_steps, '; largest w/h ', summary%max_w_over_h
   ! -- did a linear run need the nonlinear theory? (src/scene_model.f90)
   call theory_warning(model%scene, w_bend_max, theory_short, errmsg)
   if (theory_short) write (error_unit, '(a)') 'warning: '//trim(errmsg)

contains

   !> Stops before any result exists.
   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'impact: error: '//trim(message)
      flush (error_unit)
      error stop 1
   end subroutine fail

   !> Stops during the run, keeping what was computed: the history is
   !> already on disk; the summary says how far the run got.
   subroutine fail_in_run(message)
      character(len=*), intent(in) :: message
      character(len=64) :: where
      write (where, '(a,i0,a,es11.4,a)') 'failed at step ', step, ' (t = ', t, ' s)'
      write (error_unit, '(a)') 'impact: error: '//trim(message)
      write (error_unit, '(a)') 'impact: '//trim(where)//'; results up to the last step are in '// &
         trim(deck%prefix)//'_history.dat'
      close (hist_unit)
      call finish_summary(where)
      flush (error_unit)
      ! the diagnostic above says what went wrong: no run-time note on the IEEE flags
      call ieee_set_flag(ieee_all, .false.)
      error stop 1
   end subroutine fail_in_run

   !> A step whose iterations did not converge: the run stops here with the
   !> diagnostic (the step and time follow from fail_in_run).
   subroutine fail_to_converge(diagnostic)
      character(len=*), intent(in) :: diagnostic   !< which iteration, its residuals against its tolerance
      summary%unconverged_steps = summary%unconverged_steps + 1
      call fail_in_run('time step did not converge: '//diagnostic)
   end subroutine fail_to_converge

   !> The eq. (19) iteration of this step needed its fall-back: remembered
   !> for the step's warning.
   subroutine note_mixing()
      if (.not. step_mixing) mixing_note = fp_report(model%nl_guard)
      step_mixing = .true.
   end subroutine note_mixing

   !> A warning on standard error naming the step and time, given once per
   !> kind (seen); counted in the summary. With &analysis stop_on_warning
   !> the run stops here, keeping what it computed.
   subroutine warn(seen, message)
      logical, intent(inout) :: seen               !< this kind of warning was given (set here)
      character(len=*), intent(in) :: message      !< what happened
      write (error_unit, '(a,i0,a,es11.4,a)') 'impact: warning: step ', step, ' (t = ', t, ' s): '//message
      flush (error_unit)
      seen = .true.
      summary%warnings = summary%warnings + 1
      if (deck%stop_on_warning) call fail_in_run('stopped at the warning above (&analysis stop_on_warning = .true.)')
   end subroutine warn

   !> A real in a short form for messages.
   pure function real_text(x) result(text)
      real(dp), intent(in) :: x                    !< the number
      character(len=:), allocatable :: text
      character(len=24) :: buf
      write (buf, '(g0.4)') x
      text = trim(adjustl(buf))
   end function real_text

   subroutine finish_summary(status)
      character(len=*), intent(in) :: status
      call cpu_time(t_cpu1)
      summary%status = status
      summary%permanent_indentation = hist%alpha_0
      summary%final_velocity = imp%v
      summary%plate_solves = model%solves
      summary%factorizations = model%factorizations
      summary%cpu_s = t_cpu1 - t_cpu0
      call write_summary(deck, summary, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'impact: error: '//trim(errmsg)
      call results_finish(results, summary, stat, errmsg)
      if (stat /= 0) write (error_unit, '(a)') 'impact: error: '//trim(errmsg)
   end subroutine finish_summary

   !> Echo of the effective input and the derived sizes (after STAP).
   subroutine echo_run(u)
      integer, intent(in) :: u
      write (u, '(a)') 'impact: low-velocity impact of a composite laminate (Choi, Hong & Lee 1991)'
      call echo_deck(deck, u, '')
      write (u, '(a,i0,a,i0,a,i0,a,i0,a,i0)') 'model: nodes ', model%msh%nnode, ', elements ', &
         model%msh%nelem, ', equations ', model%msh%neq, ', half-bandwidth ', &
         global_bandwidth(model%mass), ', stored entries ', global_stored_entries(model%mass)
      write (u, '(a)') 'transverse shear: '//trim(model%shear_rule)//'; contact load: '//trim(deck%contact_load)
      write (u, '(a,3es12.4)') 'laminate: A11 A22 A66 (N/m)  ', model%lmt%a(1,1), model%lmt%a(2,2), model%lmt%a(3,3)
      write (u, '(a,4es12.4)') 'laminate: D11 D22 D66 D16 (N m) ', model%lmt%d(1,1), model%lmt%d(2,2), &
         model%lmt%d(3,3), model%lmt%d(1,3)
      write (u, '(a,2es12.4)') 'laminate: Abar44 Abar55 (N/m) ', model%lmt%as(1,1), model%lmt%as(2,2)
      write (u, '(a,3es12.4)') 'laminate: P (kg/m^2), R (kg/m), I (kg) ', model%lmt%p, model%lmt%r, model%lmt%i
      call write_scene_report(model%scene, u)
   end subroutine echo_run

end program impact
