!> What an accuracy run writes (docs/ACCURACY.md, what it reports): <prefix>_summary.dat, the
!> run chosen's summary then the accuracy's keys; <prefix>_accuracy.dat, one row per run and
!> the axes' estimates as '#' lines (postproc/accuracy.gp); the same in a few lines on
!> standard output.
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
      error_scale, is_ladder
   use accuracy_ladder, only: ladder_t, axis_t, judged_t, judge_run
   use model_comparison, only: comparison_t, comparison_items, comparison_lines, relative
   implicit none
   private
   public :: accuracy_outcome_t, write_accuracy_table, write_accuracy_summary, report_terminal

   !> The outcome of the ladder.
   type :: accuracy_outcome_t
      logical :: met = .false.                     !< every error within it
      character(len=240) :: status = ''            !< 'met', 'cap reached: ...', 'not met: ...', 'stopped ...'
      integer :: stop_signal = 0                   !< the stop signal that ended it, 0: none
      integer :: chosen = 0                        !< the run whose results are given
      type(judged_t) :: jd                         !< its results and errors
      real(dp) :: wall_s = 0.0_dp                  !< wall time of the accuracy run (s)
      type(comparison_t) :: cmp(2)                 !< the models compared
   end type accuracy_outcome_t

   !> Columns of <prefix>_accuracy.dat before the results.
   integer, parameter :: nfixed = 12
   !> Whose the time error is of a run chosen without it measured on its mesh, and why.
   character(len=*), parameter :: unmeasured_time = &
      'mesh 0''s (the cap left no neighbouring time level on the chosen mesh)'
   !> The mesh error from two levels.
   character(len=*), parameter :: two_meshes = 'two levels: 3 times their difference (Roache''s factor of safety 3)'
   !> A run's state as a word (state_planned, ... of accuracy_runs).
   character(len=7), parameter :: state_words(0:5) = [character(len=7) :: 'planned', 'planned', 'done', 'failed', &
      'skipped', 'stopped']

contains

   !> <prefix>_accuracy.dat (module header).
   subroutine write_accuracy_table(deck, lad, out, stat, errmsg)
      type(deck_t), intent(in) :: deck             !< the accuracy run's deck
      type(ladder_t), intent(in) :: lad            !< the ladder
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< what failed
      character(len=32) :: names(nfixed + 4*nq)
      character(len=96) :: texts(nfixed + 4*nq)
      character(len=msg_len) :: iomsg
      character(len=16) :: order
      character(len=:), allocatable :: key, unit
      type(axis_t) :: axes(2)
      integer :: u, i, iq
      names(:nfixed) = [character(len=32) :: 'run', 'role', 'time_level', 'mesh_level', 'dt_us', 'nx', 'ny', &
         'grading', 'element_size_rel', 'cpu_s', 'chosen', 'state']
      texts(:nfixed) = [character(len=96) :: 'the run: <prefix>_acc/<run>_summary.dat', &
         'time, mesh or combined (the ladder), theory or bend_twist (a model compared)', &
         'k: dt = dt0/2^k', 'j: the mesh refined j times by &accuracy mesh_factor', 'time step (us)', &
         '&mesh nx', '&mesh ny', '&mesh grading', '1/sqrt(nx ny) relative to mesh level 0', &
         'cpu time of the run (s)', '1: the run whose results the summary gives', &
         'done, failed, or skipped (it would pass &accuracy max_cpu_s)']
      do iq = 1, nq                                 ! the result, its error, the time part, the mesh part
         key = trim(result_keys(iq));  unit = ' (' // trim(result_units(iq))
         names(nfixed + iq::nq) = [character(len=32) :: key, key // '_error', key // '_error_dt', &
                                   key // '_error_mesh']
         texts(nfixed + iq::nq) = [character(len=96) :: 'the run''s ' // key // unit // '; NaN: none)', &
            'its estimated error' // unit // '; NaN: not estimated)', 'of which the time part' // unit // ')', &
            'and the mesh part' // unit // ')']
      end do
      open (newunit=u, file=deck%prefix // '_accuracy.dat', status='replace', action='write', iostat=stat, &
            iomsg=iomsg)
      if (stat /= 0) then
         errmsg = 'cannot write ' // deck%prefix // '_accuracy.dat: ' // trim(iomsg)
         return
      end if
      write (u, '(a)') '# impact: accuracy ladder, one row per run (target ' // real_short(lad%target) // ')'
      call echo_deck(deck, u, '# ')
      call write_column_block(u, names, texts)
      do i = 1, size(lad%runs)
         call write_row(lad%runs(i), i == out%chosen)
      end do
      write (u, '(a)') '# estimates of the finest level of each axis (src/accuracy/error_estimate.f90):'
      write (u, '(a)') '# result axis levels observed_order asymptotic error(result''s unit) rule'
      axes = [lad%tx, lad%mx]
      do iq = 1, nq
         if (.not. lad%estimated(iq)) cycle
         do i = 1, 2
            associate (e => axes(i)%finest(iq))
            order = '-'
            if (e%order >= 0.0_dp) write (order, '(f6.2)') e%order
            write (u, '(a,1x,a,1x,i0,1x,a,1x,a,es12.4,1x,a)') '# ' // trim(result_keys(iq)), &
               merge('time', 'mesh', i == 1), axes(i)%levels, trim(adjustl(order)), &
               trim(merge('yes', 'no ', e%asymptotic)), e%error, trim(e%how)
            end associate
         end do
      end do
      close (u, iostat=stat, iomsg=iomsg)
      if (stat /= 0) errmsg = deck%prefix // '_accuracy.dat: ' // trim(iomsg)
   contains
      !> The row of run r: the errors of a ladder run on the axes, NaN for the rest.
      subroutine write_row(r, chosen)
         type(run_t), intent(in) :: r              !< the run
         logical, intent(in) :: chosen             !< it is the run chosen
         real(dp) :: err(nq, 3), q(nq), h_rel
         type(judged_t) :: jd
         err = ieee_value(err, ieee_quiet_nan)
         q = merge(r%q, err(:, 1), r%state == state_done)
         if (r%state == state_done .and. is_ladder(r) .and. r%k < lad%tx%levels .and. r%j < lad%mx%levels) then
            jd = judge_run(lad, r%k, r%j)
            err = merge(reshape([jd%err, jd%err_time, jd%err_mesh], [nq, 3]), err, spread(lad%estimated, 2, 3))
         end if
         h_rel = sqrt(real(lad%runs(1)%nx, dp)*real(lad%runs(1)%ny, dp)/(real(r%nx, dp)*real(r%ny, dp)))
         write (u, '(a,1x,a,2(1x,i3),es15.6e3,2(1x,i5),f9.5,f9.5,es12.4,1x,i1,1x,a,*(es16.7e3))') trim(r%name), &
            trim(r%role), r%k, r%j, r%dt*1.0e6_dp, r%nx, r%ny, r%grading, h_rel, r%cpu_s, merge(1, 0, chosen), &
            state_words(r%state), q, err
      end subroutine write_row
   end subroutine write_accuracy_table

   !> <prefix>_summary.dat (module header).
   subroutine write_accuracy_summary(deck, la, lad, out, stat, errmsg)
      type(deck_t), intent(in) :: deck             !< the accuracy run's deck
      type(launcher_t), intent(in) :: la           !< the launcher (its directory, its spending)
      type(ladder_t), intent(in) :: lad            !< the ladder
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      integer, intent(out) :: stat                 !< 0 on success
      character(len=*), intent(inout) :: errmsg    !< what failed
      type(summary_t) :: s
      type(summary_item_t), allocatable :: items(:)
      type(run_t) :: r
      character(len=:), allocatable :: key, unit
      integer :: i, iq
      real(dp) :: reference(nq)
      r = lad%runs(out%chosen)
      reference = error_scale(out%jd%value)
      call read_summary(la%dir // trim(r%name) // '_summary.dat', s, stat, errmsg)
      if (stat /= 0) return
      allocate (items(0))
      do i = 1, size(s%keys)
         call summary_text(items, trim(s%keys(i)), trim(s%texts(i)))
      end do
      call put('accuracy_target', '-', lad%target)
      call summary_text(items, 'accuracy_status', trim(out%status))
      if (out%stop_signal > 0) call summary_integer(items, 'accuracy_stop_signal', out%stop_signal)
      call summary_text(items, 'accuracy_values', 'of the run chosen, not extrapolated')
      key = 'true'
      if (.not. out%jd%time_measured) key = 'false: ' // unmeasured_time
      call summary_text(items, 'time_error_measured', key)
      if (out%jd%two_levels) call summary_text(items, 'time_error_estimate', &
                                               'two levels: Roache''s grid convergence index, Fs = 3')
      if (lad%mx%levels == 2) call summary_text(items, 'mesh_error_estimate', two_meshes)
      call summary_text(items, 'chosen_run', la%dir // trim(r%name))
      call summary_real(items, 'chosen_dt_us', 'chosen_dt', 's', r%dt, 1.0e6_dp)
      call summary_integer(items, 'chosen_nx', r%nx)
      call summary_integer(items, 'chosen_ny', r%ny)
      call put('chosen_grading', '-', r%grading)
      call summary_text(items, 'chosen_theory', trim(la%theory))
      do iq = 1, nq
         if (.not. lad%estimated(iq)) cycle
         key = trim(result_keys(iq));  unit = trim(result_units(iq))
         call put(key // '_error', unit, out%jd%err(iq))
         call put(key // '_error_dt', unit, out%jd%err_time(iq))
         call put(key // '_error_mesh', unit, out%jd%err_mesh(iq))
         if (iq == iq_peak_time) call put(key // '_error_maxima', unit, out%jd%err_maxima(iq))
         call put(key // '_relative_error', '-', relative(out%jd%err(iq), reference(iq)))
      end do
      do i = 1, size(out%cmp)
         call comparison_items(items, out%cmp(i), lad)
      end do
      call summary_integer(items, 'accuracy_runs', count(lad%runs%state == state_done))
      call summary_real(items, 'accuracy_cpu_s', 'accuracy_cpu', 's', la%spent, 1.0_dp)
      call put('accuracy_cpu_in_chosen_runs', '-', la%spent/max(r%cpu_s, tiny(1.0_dp)))   ! in runs of the chosen
      call summary_real(items, 'accuracy_wall_s', 'accuracy_wall', 's', out%wall_s, 1.0_dp)
      call write_summary_file(deck, items, stat, errmsg)
   contains
      !> A real item whose key is its name, in the result's unit.
      subroutine put(name, unit_name, value)
         character(len=*), intent(in) :: name, unit_name
         real(dp), intent(in) :: value
         call summary_real(items, name, name, unit_name, value, 1.0_dp)
      end subroutine put
   end subroutine write_accuracy_summary

   !> The accuracy run's words on standard output.
   subroutine report_terminal(unit, la, lad, out)
      integer, intent(in) :: unit                  !< standard output
      type(launcher_t), intent(in) :: la           !< the launcher
      type(ladder_t), intent(in) :: lad            !< the ladder
      type(accuracy_outcome_t), intent(in) :: out  !< the outcome
      type(run_t) :: r
      integer :: iq, i
      character(len=msg_len) :: line
      real(dp) :: reference(nq)
      r = lad%runs(out%chosen)
      reference = error_scale(out%jd%value)
      write (unit, '(a)') 'accuracy: ' // trim(out%status)
      if (out%jd%two_levels) write (unit, '(a)') 'accuracy: the time error on the chosen mesh is from two ' // &
         'time levels: Roache''s grid convergence index, factor of safety 3'
      if (lad%mx%levels == 2) write (unit, '(a)') 'accuracy: the mesh error is from ' // two_meshes
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
         if (.not. lad%estimated(iq)) cycle
         write (line, '(a,es14.6,a,es10.3,a,f7.3,a,es10.3,a,es10.3,a)') result_keys(iq), out%jd%value(iq), ' +- ', &
            out%jd%err(iq), ' (', 100.0_dp*relative(out%jd%err(iq), reference(iq)), ' %; dt ', &
            out%jd%err_time(iq), ', mesh ', out%jd%err_mesh(iq), ')'
         write (unit, '(a)') '  ' // trim(line)
      end do
      do i = 1, size(out%cmp)
         call comparison_lines(unit, out%cmp(i), lad, out%chosen)
      end do
      write (unit, '(a)') 'accuracy: ' // int_str(count(lad%runs%state == state_done)) // ' runs, cpu ' // &
         real_short(la%spent) // ' s (' // real_short(la%spent/max(r%cpu_s, tiny(1.0_dp))) // &
         ' times the run chosen), wall ' // real_short(out%wall_s) // ' s on ' // int_str(la%cpus) // &
         ' CPUs; every run: ' // la%dir // '; summary: ' // la%dir(:len(la%dir) - 5) // '_summary.dat'
   end subroutine report_terminal

end module accuracy_report
