!> What an accuracy run writes (docs/ACCURACY.md): <prefix>_summary.dat, the run chosen's
!> summary then the accuracy's keys (target, status, the run chosen, each result's `_error`,
!> `_error_dt`, `_error_mesh`, the models' `_change_theory`, `_change_bend_twist`, the cost);
!> <prefix>_accuracy.dat, one row per run and the axes' estimates as '#' lines
!> (postproc/accuracy.gp); and the same in a few lines on standard output.
module accuracy_report
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t
   use deck_echo, only: echo_deck
   use number_text, only: int_str, real_short
   use result_files, only: summary_item_t, summary_real, summary_integer, summary_text, write_summary_file, &
      write_column_block
   use result_reader, only: summary_t, read_summary
   use accuracy_runs, only: run_t, launcher_t, nq, iq_peak_time, result_keys, result_units, state_done, &
      error_scale, state_skipped, state_stopped, is_ladder
   use accuracy_ladder, only: axis_t, judged_t, judge_run
   implicit none
   private
   public :: comparison_t, accuracy_outcome_t, write_accuracy_table, write_accuracy_summary, report_terminal, &
             model_changes, model_required, model_needed

   !> A model compared at the chosen settings: the theory, or D16, D26.
   type :: comparison_t
      character(len=12) :: what = ''               !< 'theory' or 'bend_twist'
      character(len=160) :: compared = ''          !< what the other run changes
      integer :: run = 0                           !< its run, 0 when none was made
      integer :: base = 0                          !< the run it is compared with (the chosen, or another: at)
      character(len=400) :: at = ''                !< why base is not the run chosen
      character(len=160) :: note = ''              !< why none was made
      character(len=16) :: richer = ''             !< the fuller model: 'nonlinear', or 'keep' (D16, D26)
      character(len=16) :: simpler = ''            !< the other: 'linear', or 'drop' (D16 = D26 = 0)
      logical :: chosen_richer = .true.            !< the run chosen has the fuller model
   end type comparison_t

   !> The outcome of the ladder.
   type :: accuracy_outcome_t
      real(dp) :: target = 0.0_dp                  !< the relative error asked for
      logical :: met = .false.                     !< every error within it
      character(len=240) :: status = ''            !< 'met', 'cap reached: ...', 'not met: ...', 'stopped ...'
      integer :: stop_signal = 0                   !< the stop signal that ended it, 0: none
      integer :: chosen = 0                        !< the run whose results are given
      type(judged_t) :: jd                         !< its results and errors
      logical :: estimated(nq) = .false.           !< the results estimated
      logical :: targeted(nq) = .false.            !< of which those that must meet the target
      real(dp) :: wall_s = 0.0_dp                  !< wall time of the accuracy run (s)
      type(comparison_t) :: cmp(2)                 !< the models compared
   end type accuracy_outcome_t

   !> Columns of <prefix>_accuracy.dat before the results.
   integer, parameter :: nfixed = 12
   !> Whose the time error is of a run chosen without it measured on its mesh, and why.
   character(len=*), parameter :: unmeasured_time = &
      'mesh 0''s (the cap left no neighbouring time level on the chosen mesh)'
   !> A run's state as a word (state_planned, ... of accuracy_runs).
   character(len=7), parameter :: state_words(0:5) = [character(len=7) :: 'planned', 'planned', 'done', 'failed', &
      'skipped', 'stopped']

contains

   !> <prefix>_accuracy.dat (module header).
   subroutine write_accuracy_table(deck, runs, tx, mx, out, stat, errmsg)
      type(deck_t), intent(in) :: deck             !< the accuracy run's deck
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(axis_t), intent(in) :: tx, mx           !< the axes
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< what failed
      character(len=32) :: names(nfixed + 4*nq)
      character(len=96) :: texts(nfixed + 4*nq)
      character(len=msg_len) :: iomsg
      integer :: u, i, iq
      names(:nfixed) = [character(len=32) :: 'run', 'role', 'time_level', 'mesh_level', 'dt_us', 'nx', 'ny', &
         'grading', 'element_size_rel', 'cpu_s', 'chosen', 'state']
      texts(:nfixed) = [character(len=96) :: 'the run: <prefix>_acc/<run>_summary.dat', &
         'time, mesh or combined (the ladder), theory or bend_twist (a model compared)', &
         'k: dt = dt0/2^k', 'j: the mesh refined j times by &accuracy mesh_factor', 'time step (us)', &
         '&mesh nx', '&mesh ny', '&mesh grading', '1/sqrt(nx ny) relative to mesh level 0', &
         'cpu time of the run (s)', '1: the run whose results the summary gives', &
         'done, failed, or skipped (it would pass &accuracy max_cpu_s)']
      do iq = 1, nq
         names(nfixed + iq) = result_keys(iq)
         texts(nfixed + iq) = 'the run''s ' // trim(result_keys(iq)) // ' (' // trim(result_units(iq)) // &
                              '; NaN: none)'
         names(nfixed + nq + iq) = trim(result_keys(iq)) // '_error'
         texts(nfixed + nq + iq) = 'its estimated error (' // trim(result_units(iq)) // '; NaN: not estimated)'
         names(nfixed + 2*nq + iq) = trim(result_keys(iq)) // '_error_dt'
         texts(nfixed + 2*nq + iq) = 'of which the time part (' // trim(result_units(iq)) // ')'
         names(nfixed + 3*nq + iq) = trim(result_keys(iq)) // '_error_mesh'
         texts(nfixed + 3*nq + iq) = 'and the mesh part (' // trim(result_units(iq)) // ')'
      end do
      open (newunit=u, file=deck%prefix // '_accuracy.dat', status='replace', action='write', iostat=stat, &
            iomsg=iomsg)
      if (stat /= 0) then
         errmsg = 'cannot write ' // deck%prefix // '_accuracy.dat: ' // trim(iomsg)
         return
      end if
      write (u, '(a)') '# impact: accuracy ladder, one row per run (target ' // real_short(out%target) // ')'
      call echo_deck(deck, u, '# ')
      call write_column_block(u, names, texts)
      do i = 1, size(runs)
         call write_row(i)
      end do
      call write_estimates(u, tx, mx, out%estimated)
      close (u, iostat=stat, iomsg=iomsg)
      if (stat /= 0) errmsg = deck%prefix // '_accuracy.dat: ' // trim(iomsg)
   contains
      !> The row of run i.
      subroutine write_row(i)
         integer, intent(in) :: i                  !< the run
         real(dp) :: err(nq), err_time(nq), err_mesh(nq), q(nq), h_rel
         type(judged_t) :: jd
         err = ieee_value(err, ieee_quiet_nan)
         err_time = err;  err_mesh = err
         q = merge(runs(i)%q, err, runs(i)%state == state_done)
         if (runs(i)%state == state_done .and. is_ladder(runs(i)) .and. runs(i)%k < tx%levels .and. &
             runs(i)%j < mx%levels) then                  ! the results not estimated NaN
            jd = judge_run(runs, tx, mx, runs(i)%k, runs(i)%j, out%target, out%targeted)
            err = merge(jd%err, err, out%estimated);  err_time = merge(jd%err_time, err, out%estimated)
            err_mesh = merge(jd%err_mesh, err_time, out%estimated)
         end if
         h_rel = sqrt(real(runs(1)%nx, dp)*real(runs(1)%ny, dp)/(real(runs(i)%nx, dp)*real(runs(i)%ny, dp)))
         write (u, '(a,1x,a,2(1x,i3),es15.6e3,2(1x,i5),f9.5,f9.5,es12.4,1x,i1,1x,a,24es16.7e3)') &
            trim(runs(i)%name), trim(runs(i)%role), runs(i)%k, runs(i)%j, runs(i)%dt*1.0e6_dp, runs(i)%nx, &
            runs(i)%ny, runs(i)%grading, h_rel, runs(i)%cpu_s, merge(1, 0, i == out%chosen), &
            state_words(runs(i)%state), q, err, err_time, err_mesh
      end subroutine write_row
   end subroutine write_accuracy_table

   !> The estimates of the finest level of both axes as '#' lines.
   subroutine write_estimates(u, tx, mx, active)
      integer, intent(in) :: u                     !< the open file
      type(axis_t), intent(in) :: tx, mx           !< the axes
      logical, intent(in) :: active(nq)            !< the results estimated
      integer :: iq
      write (u, '(a)') '# estimates of the finest level of each axis (src/accuracy/error_estimate.f90):'
      write (u, '(a)') '# result axis levels observed_order asymptotic error(result''s unit) rule'
      do iq = 1, nq
         if (.not. active(iq)) cycle
         call one('time', tx, iq)
         call one('mesh', mx, iq)
      end do
   contains
      !> The line of one result on one axis.
      subroutine one(name, ax, iq)
         character(len=*), intent(in) :: name      !< the axis
         type(axis_t), intent(in) :: ax            !< the axis
         integer, intent(in) :: iq                 !< the result
         character(len=16) :: order
         order = '-'
         if (ax%finest(iq)%order >= 0.0_dp) write (order, '(f6.2)') ax%finest(iq)%order
         write (u, '(a,1x,a,1x,i0,1x,a,1x,a,es12.4,1x,a)') '# ' // trim(result_keys(iq)), name, ax%levels, &
            trim(adjustl(order)), trim(merge('yes', 'no ', ax%finest(iq)%asymptotic)), ax%finest(iq)%error, &
            trim(ax%finest(iq)%how)
      end subroutine one
   end subroutine write_estimates

   !> <prefix>_summary.dat (module header).
   subroutine write_accuracy_summary(deck, la, runs, out, stat, errmsg)
      type(deck_t), intent(in) :: deck             !< the accuracy run's deck
      type(launcher_t), intent(in) :: la           !< the launcher (its directory, its spending)
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< what failed
      type(summary_t) :: s
      type(summary_item_t), allocatable :: items(:)
      type(run_t) :: r
      integer :: i, iq
      real(dp) :: reference(nq)
      r = runs(out%chosen)
      reference = error_scale(out%jd%value)
      call read_summary(la%dir // trim(r%name) // '_summary.dat', s, stat, errmsg)
      if (stat /= 0) return
      allocate (items(0))
      do i = 1, size(s%keys)
         call summary_text(items, trim(s%keys(i)), trim(s%texts(i)))
      end do
      call put('accuracy_target', '-', out%target)
      call summary_text(items, 'accuracy_status', trim(out%status))
      if (out%stop_signal > 0) call summary_integer(items, 'accuracy_stop_signal', out%stop_signal)
      call summary_text(items, 'accuracy_values', 'of the run chosen, not extrapolated')
      if (out%jd%time_measured) then
         call summary_text(items, 'time_error_measured', 'true')
      else
         call summary_text(items, 'time_error_measured', 'false: ' // unmeasured_time)
      end if
      if (out%jd%two_levels) call summary_text(items, 'time_error_estimate', &
                                               'two levels: Roache''s grid convergence index, Fs = 3')
      call summary_text(items, 'chosen_run', la%dir // trim(r%name))
      call summary_real(items, 'chosen_dt_us', 'chosen_dt', 's', r%dt, 1.0e6_dp)
      call summary_integer(items, 'chosen_nx', r%nx)
      call summary_integer(items, 'chosen_ny', r%ny)
      call put('chosen_grading', '-', r%grading)
      call summary_text(items, 'chosen_theory', trim(la%theory))
      do iq = 1, nq
         if (.not. out%estimated(iq)) cycle
         call put(trim(result_keys(iq)) // '_error', trim(result_units(iq)), out%jd%err(iq))
         call put(trim(result_keys(iq)) // '_error_dt', trim(result_units(iq)), out%jd%err_time(iq))
         call put(trim(result_keys(iq)) // '_error_mesh', trim(result_units(iq)), out%jd%err_mesh(iq))
         if (iq == iq_peak_time) call put(trim(result_keys(iq)) // '_error_maxima', trim(result_units(iq)), &
                                          out%jd%err_maxima(iq))
         call put(trim(result_keys(iq)) // '_relative_error', '-', relative(out%jd%err(iq), reference(iq)))
      end do
      do i = 1, size(out%cmp)
         call comparison_items(items, out%cmp(i), runs, out)
      end do
      call summary_integer(items, 'accuracy_runs', count(runs%state == state_done))
      call summary_real(items, 'accuracy_cpu_s', 'accuracy_cpu', 's', la%spent, 1.0_dp)
      call put('accuracy_cpu_in_chosen_runs', '-', la%spent/max(r%cpu_s, tiny(1.0_dp)))   ! in runs of the chosen
      call summary_real(items, 'accuracy_wall_s', 'accuracy_wall', 's', out%wall_s, 1.0_dp)
      call write_summary_file(deck, items, stat, errmsg)
   contains
      !> A real item whose key is its name, in the result's unit.
      subroutine put(key, unit, value)
         character(len=*), intent(in) :: key, unit
         real(dp), intent(in) :: value
         call summary_real(items, key, key, unit, value, 1.0_dp)
      end subroutine put
   end subroutine write_accuracy_summary

   !> The summary's items of one model compared: what, and the relative change of each result.
   subroutine comparison_items(items, c, runs, out)
      type(summary_item_t), allocatable, intent(inout) :: items(:)   !< the summary
      type(comparison_t), intent(in) :: c          !< the comparison
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      real(dp) :: change(nq)
      integer :: iq
      if (c%run == 0 .or. len(not_compared(c, runs)) > 0) then
         call summary_text(items, trim(c%what) // '_compared', 'none: ' // not_compared(c, runs))
         return
      end if
      call summary_text(items, trim(c%what) // '_compared', trim(c%compared))
      call summary_text(items, trim(c%what) // '_compared_at', trim(runs(c%base)%name))
      change = model_changes(c, runs, out)
      call summary_text(items, trim(c%what) // '_needed', trim(model_needed(c, change, out)))
      do iq = 1, nq
         if (.not. out%estimated(iq)) cycle
         call summary_real(items, trim(result_keys(iq)) // '_change_' // trim(c%what), trim(result_keys(iq)) // &
                           '_change_' // trim(c%what), '-', change(iq), 1.0_dp)
      end do
   end subroutine comparison_items

   !> The accuracy run's words on standard output.
   subroutine report_terminal(unit, la, runs, out)
      integer, intent(in) :: unit                  !< standard output
      type(launcher_t), intent(in) :: la           !< the launcher
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      type(run_t) :: r
      integer :: iq, i
      character(len=msg_len) :: line
      real(dp) :: reference(nq)
      r = runs(out%chosen)
      reference = error_scale(out%jd%value)
      write (unit, '(a)') 'accuracy: ' // trim(out%status)
      if (out%jd%two_levels) write (unit, '(a)') 'accuracy: the time error on the chosen mesh is from two ' // &
         'time levels: Roache''s grid convergence index, factor of safety 3'
      if (.not. out%jd%time_measured) write (unit, '(a)') 'accuracy: the time error was not measured on ' // &
         'the chosen mesh: it is ' // unmeasured_time
      if (out%jd%err_maxima(iq_peak_time) > 0.0_dp) write (unit, '(a)') 'accuracy: ' // &
         trim(result_keys(iq_peak_time)) // ': the force has other maxima within the peak force''s error of it, ' // &
         'up to ' // real_short(out%jd%err_maxima(iq_peak_time)) // ' us from the peak: which is the highest ' // &
         'is not settled at these settings (its error counts them)'
      write (unit, '(a)') 'accuracy: results of run ' // trim(r%name) // ' (dt ' // real_short(r%dt*1.0e6_dp) // &
         ' us, mesh ' // int_str(r%nx) // ' x ' // int_str(r%ny) // ', grading ' // real_short(r%grading) // &
         ', ' // trim(la%theory) // '), not extrapolated; error = time part + mesh part + their interaction'
      do iq = 1, nq
         if (.not. out%estimated(iq)) cycle
         write (line, '(a,es14.6,a,es10.3,a,f7.3,a,es10.3,a,es10.3,a)') result_keys(iq), out%jd%value(iq), ' +- ', &
            out%jd%err(iq), ' (', 100.0_dp*relative(out%jd%err(iq), reference(iq)), ' %; dt ', &
            out%jd%err_time(iq), ', mesh ', out%jd%err_mesh(iq), ')'
         write (unit, '(a)') '  ' // trim(line)
      end do
      do i = 1, size(out%cmp)
         call comparison_lines(unit, out%cmp(i), runs, out)
      end do
      write (unit, '(a)') 'accuracy: ' // int_str(count(runs%state == state_done)) // ' runs, cpu ' // &
         real_short(la%spent) // ' s (' // real_short(la%spent/max(r%cpu_s, tiny(1.0_dp))) // &
         ' times the run chosen), wall ' // real_short(out%wall_s) // ' s on ' // int_str(la%cpus) // &
         ' CPUs; every run: ' // la%dir // '; summary: ' // la%dir(:len(la%dir) - 5) // '_summary.dat'
   end subroutine report_terminal

   !> The terminal's lines of one model compared, with its verdict (model_required).
   subroutine comparison_lines(unit, c, runs, out)
      integer, intent(in) :: unit                  !< standard output
      type(comparison_t), intent(in) :: c          !< the comparison
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      real(dp) :: change(nq)
      character(len=msg_len) :: line
      integer :: iq
      if (c%run == 0 .or. len(not_compared(c, runs)) > 0) then
         write (unit, '(a)') 'model: ' // trim(c%what) // ': not compared: ' // not_compared(c, runs)
         return
      end if
      change = model_changes(c, runs, out)
      line = ''
      do iq = 1, nq
         if (.not. out%estimated(iq)) cycle
         write (line, '(a,1x,a,f8.3,a)') trim(line), trim(result_keys(iq)), 100.0_dp*change(iq), ' %'
      end do
      write (unit, '(a)') 'model: ' // trim(c%what) // ': ' // trim(c%compared) // ' changes' // trim(line)
      if (c%base /= out%chosen) write (unit, '(a)') 'model: ' // trim(c%what) // ': compared at run ' // &
         trim(runs(c%base)%name) // ', not at the run chosen: ' // trim(c%at)
      line = 'model: ' // trim(c%what) // ': within the target ' // real_short(out%target) // ': '
      if (model_required(change, out)) line = 'model: ' // trim(c%what) // ': more than the target ' // &
         real_short(out%target) // ': the scene requires '
      if (model_required(change, out) .and. c%chosen_richer) line = trim(line) // ' the model of the run chosen (' // &
         trim(c%richer) // ')'
      if (model_required(change, out) .and. .not. c%chosen_richer) line = trim(line) // ' the other model (' // &
         trim(c%richer) // '): the results above are the simpler model''s (' // trim(c%simpler) // &
         '), and the fuller one moves them by more than the target'
      if (.not. model_required(change, out) .and. c%chosen_richer) line = trim(line) // ' the simpler model (' // &
         trim(c%simpler) // ') would do as well'
      if (.not. model_required(change, out) .and. .not. c%chosen_richer) line = trim(line) // &
         ' the model of the run chosen (' // trim(c%simpler) // ') does as well as the fuller one (' // trim(c%richer) // ')'
      write (unit, '(a)') trim(line)
   end subroutine comparison_lines

   !> The relative change of each result estimated that the other model of c makes (else 0).
   pure function model_changes(c, runs, out) result(change)
      type(comparison_t), intent(in) :: c          !< the comparison (its runs done)
      type(run_t), intent(in) :: runs(:)           !< the runs
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome (the results estimated)
      real(dp) :: change(nq), reference(nq)
      integer :: iq
      change = 0.0_dp
      reference = error_scale(runs(c%base)%q)
      do iq = 1, nq
         if (out%estimated(iq)) change(iq) = relative(runs(c%run)%q(iq) - runs(c%base)%q(iq), reference(iq))
      end do
   end function model_changes

   !> Whether a result that must meet the target changes by more than the target.
   pure logical function model_required(change, out)
      real(dp), intent(in) :: change(nq)           !< the relative changes (model_changes)
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome (the target, the results targeted)
      model_required = any(out%targeted .and. abs(change) > out%target)
   end function model_required

   !> The verdict of comparison c: the fuller model when model_required, else the simpler.
   pure function model_needed(c, change, out) result(name)
      type(comparison_t), intent(in) :: c          !< the comparison
      real(dp), intent(in) :: change(nq)           !< the relative changes (model_changes)
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome (the target, the results targeted)
      character(len=:), allocatable :: name
      if (model_required(change, out)) then
         name = trim(c%richer)
      else
         name = trim(c%simpler)
      end if
   end function model_needed

   !> Why comparison c has no results ('' when it has): none made, or its run skipped,
   !> stopped or failed.
   function not_compared(c, runs) result(text)
      type(comparison_t), intent(in) :: c          !< the comparison
      type(run_t), intent(in) :: runs(:)           !< the runs
      character(len=:), allocatable :: text
      text = ''
      if (c%run == 0) then
         text = trim(c%note)
      else if (runs(c%run)%state == state_skipped) then
         text = 'the run ' // trim(runs(c%run)%name) // ' would pass &accuracy max_cpu_s'
      else if (runs(c%run)%state == state_stopped) then
         text = 'the run ' // trim(runs(c%run)%name) // ' was stopped'
      else if (runs(c%run)%state /= state_done) then
         text = 'the run ' // trim(runs(c%run)%name) // ' failed (' // trim(runs(c%run)%status) // ')'
      end if
   end function not_compared

   !> err/|value|, 0 when both are 0, huge when only value is.
   pure real(dp) function relative(err, value)
      real(dp), intent(in) :: err                  !< the error or change
      real(dp), intent(in) :: value                !< the value
      if (value /= 0.0_dp) then
         relative = err/abs(value)
      else if (err == 0.0_dp) then
         relative = 0.0_dp
      else
         relative = huge(1.0_dp)
      end if
   end function relative

end module accuracy_report
