!> Restart points: `impact --restart deck.nml` continues the run at the
!> deck's prefix from its last restart point, appending to its files, and
!> ends as the run would have ended had it never stopped (the same history
!> rows, bit for bit). What a restart point holds: above restart_save. Not
!> from the paper. More: docs/ROBUSTNESS.md.
module restart_point
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use, intrinsic :: iso_c_binding, only: c_int, c_null_char
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_str
   use deck_schema, only: deck_t, deck_vars, var_key
   use deck_echo, only: deck_value_text
   use c_library, only: c_open, c_close, c_fsync
   use file_system, only: remove_file, rename_file, truncate_file, file_size, open_probe, nearest_directory
   use mesh, only: ndof_node
   use plate_model, only: model_t
   use plate_solver, only: solver_t, contact_response
   use contact_load, only: load_pattern_t
   use contact_iteration, only: step_state_t
   use newmark, only: newmark_t
   use result_files, only: reserve_summary, results_claim_t, result_suffixes, claim_results, claim_left_empty
   use process_stop, only: remove_on_stop
   use results_hdf5, only: results_open, results_point_t, results_point
   use run_recorder, only: record_t, record_settings, nwarn
   use progress_line, only: progress_start
   use step_peak, only: peak_track_t
   use damage_record, only: damage_t
   use restart_io, only: restart_stream_t, io_tag, io_text, io_value, io_values, io_count, io_block, &
      io_array, io_ints, io_impactor, io_pattern, put_seal, seal_holds
   implicit none
   private
   public :: restart_save, restart_check, restart_resume, claim_run_files

   !> The layout of the file; a restart point of another is refused.
   integer, parameter :: layout = 3
   !> The deck's variables a restart may change.
   character(len=*), parameter :: free_vars(2) = [character(len=24) :: 'analysis.t_end', 'output.overwrite']
   !> Reals of a peak's samples (io_peak).
   integer, parameter :: peak_size = 11
   !> open(2)'s O_RDONLY.
   integer(c_int), parameter :: o_rdonly = 0

contains

   !> <prefix>.restart, the run's restart point.
   pure function restart_file(deck) result(path)
      type(deck_t), intent(in) :: deck              !< the effective deck
      character(len=:), allocatable :: path
      path = deck%prefix // '.restart'
   end function restart_file

   !> Claims the run's result files (claim_results): a restart continues its own
   !> files; a run that starts afresh discards an earlier restart point.
   subroutine claim_run_files(deck, restart_asked, restarting, claim, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      logical, intent(in) :: restart_asked          !< --restart was given
      logical, intent(in) :: restarting             !< the run continues from a restart point
      type(results_claim_t), intent(out) :: claim   !< the claim, held until release_results
      integer, intent(out) :: stat                  !< 0 when the run may write its results
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(deck_t) :: claimed
      integer :: ios
      if (restart_asked .and. .not. restarting) write (output_unit, '(a)') &
         'restart: no restart point ' // restart_file(deck) // ': the run starts at step 0'
      claimed = deck
      claimed%overwrite = deck%overwrite .or. restarting
      if (restart_asked .and. .not. claimed%overwrite) &
         claimed%overwrite = claim_left_empty(deck%prefix, result_suffixes(deck%analysis_kind))
      call claim_results(claimed, result_suffixes(deck%analysis_kind), claim, stat, errmsg)
      if (stat /= 0) return
      call remove_on_stop(claim%first)
      if (restarting) return
      call remove_file(restart_file(deck), ios)       ! an earlier run's: the files no longer match it
      call remove_file(restart_file(deck) // '.tmp', ios)
   end subroutine claim_run_files

   !> <prefix>.restart, written when the files are flushed (results_tick), at
   !> step 0 and at the end: what the time loop carries from step to step
   !> (the deck as text: only &analysis t_end may change; the state, the
   !> solver, the record, what <prefix>.h5 holds), in tagged parts sealed by
   !> their CRC-32 (restart_io), read back by the same routines (io_state ...).
   !> Written whole to <prefix>.restart.tmp, forced to the disk and renamed
   !> over the old one: the old point or the new one.
   subroutine restart_save(deck, cpu_s, st, solver, rec, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      real(dp), intent(in) :: cpu_s                 !< cpu time of the run so far (s)
      type(step_state_t), intent(inout) :: st       !< the state after the last step recorded
      type(solver_t), intent(inout) :: solver       !< the plate solver
      type(record_t), intent(inout) :: rec          !< the run's record (its steps: the last step)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure, naming the file
      character(len=:), allocatable :: path, changed
      character(len=msg_len) :: iomsg
      type(restart_stream_t) :: s
      type(results_point_t) :: pt
      integer, allocatable :: columns(:)
      integer :: ios, step
      real(dp) :: cpu
      logical :: h5
      path = restart_file(deck)
      call remove_file(path // '.tmp', ios)          ! a link itself, never what it points to
      open (newunit=s%u, file=path // '.tmp', access='stream', form='unformatted', status='new', &
            action='readwrite', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = path // '.tmp: ' // trim(iomsg)
         return
      end if
      step = rec%steps
      cpu = cpu_s
      h5 = allocated(rec%h5%path)
      if (h5) pt = results_point(rec%h5)
      call io_layout(s)
      call io_deck(s, deck, changed)
      call io_state(s, step, cpu, st)
      call io_solver(s, solver, columns)
      call io_record(s, rec, size(st%plate%d))
      call io_results(s, h5, pt)
      call io_tag(s, 'end')
      call put_seal(s%u, s%stat)
      close (s%u, iostat=ios)
      stat = s%stat
      if (stat == 0) stat = ios
      if (stat == 0) call force_to_disk(path // '.tmp', stat)
      if (stat == 0) call rename_file(path // '.tmp', path, stat, iomsg)
      if (stat == 0) call force_to_disk(nearest_directory(path), stat)   ! the directory, for the rename
      if (stat /= 0) errmsg = path // ': cannot write the restart point'
   end subroutine restart_save

   !> A restart's first look: there is a restart point, of this deck and layout, and its step.
   subroutine restart_check(deck, nstep, found, step, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      integer, intent(in) :: nstep                  !< the run's last step (t_end/dt)
      logical, intent(out) :: found                 !< there is a restart point
      integer, intent(out) :: step                  !< the step it was written after (0 if none)
      integer, intent(out) :: stat                  !< 0 when the run may continue from it
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=:), allocatable :: path, changed
      type(restart_stream_t) :: s
      stat = 0
      step = 0
      path = restart_file(deck)
      inquire (file=path, exist=found)
      if (.not. found) return
      call open_point(path, s, stat, errmsg)
      if (stat /= 0) return
      call io_deck(s, deck, changed)
      call io_tag(s, 'state')
      call io_value(s, step)
      close (s%u)
      stat = s%stat
      if (stat /= 0) then
         errmsg = path // ': not a restart point of this build of impact (or damaged)'
      else if (len(changed) > 0) then
         stat = 1
         errmsg = deck%source // ': --restart: the deck differs from the one of the run at its restart point (' &
            // path // '): ' // changed // '; only &analysis t_end may change'
      else if (step == nstep) then
         write (output_unit, '(a)') 'restart: the run is complete: its restart point ' // path // ' is at its ' &
            // 'last step, ' // int_str(step) // '; nothing is done (give a later &analysis t_end to continue it)'
      end if
   end subroutine restart_check

   !> Continues the run from its restart point: the state, the solver, the
   !> record and the files as they were there (above restart_save).
   subroutine restart_resume(deck, model, nm, solver, st, rec, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      type(newmark_t), intent(in) :: nm             !< Newmark's constants (the time step)
      type(solver_t), intent(inout) :: solver       !< the plate solver, factored
      type(step_state_t), intent(inout) :: st       !< plate, impactor, contact history and pattern
      type(record_t), intent(out) :: rec            !< the run's record, its files open again
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=:), allocatable :: path, changed
      integer, allocatable :: columns(:)
      type(restart_stream_t) :: s
      type(results_point_t) :: pt
      type(load_pattern_t) :: all
      logical :: h5
      integer :: step, counted
      real(dp) :: cpu_s
      if (solver%damage%on) then
         stat = 1;  errmsg = '--restart: a restart point does not keep the ply damage (&damage): run the deck again'
         return
      end if
      path = restart_file(deck)
      step = 0;  cpu_s = 0.0_dp
      call open_point(path, s, stat, errmsg)
      if (stat /= 0) return
      call record_settings(rec, deck, model, nm)
      h5 = .false.
      allocate (pt%peak_fields(ndof_node, model%msh%nnode))
      call io_deck(s, deck, changed)
      call io_state(s, step, cpu_s, st)
      call io_solver(s, solver, columns)
      call io_record(s, rec, model%msh%neq)
      call progress_start(rec%progress, rec%nstep, deck%t_end)   ! the progress line goes on
      rec%cpu_before = cpu_s
      call io_results(s, h5, pt)
      call io_tag(s, 'end')
      close (s%u)
      stat = 1
      if (s%stat /= 0 .or. step /= rec%steps) then
         errmsg = path // ': not a restart point of this run (or damaged)'
      else if (step > rec%nstep) then
         errmsg = deck%source // ': &analysis t_end = ' // real_str(deck%t_end) // ' s ends at step ' &
            // int_str(rec%nstep) // ', before the restart point''s step ' // int_str(step)
      else if (h5 .neqv. deck%hdf5) then
         errmsg = path // ': its run had &output hdf5 = ' // trim(merge('.true. ', '.false.', h5))
      else        ! the response columns again, in their order (the same values), not counted
         counted = solver%response_solves
         all%n = size(columns)
         all%eq = columns
         allocate (all%c(all%n), source=1.0_dp)
         call contact_response(solver, all, stat, errmsg)
         solver%response_solves = counted
      end if
      if (stat == 0) call reopen_history(deck, rec, stat, errmsg)
      if (stat == 0 .and. h5) call results_open(deck, model%msh, rec%h5, stat, errmsg, pt)
      if (stat == 0) call reserve_summary(deck, stat, errmsg)
      if (stat == 0) write (output_unit, '(a)') 'restart: the run continues after step ' // int_str(step) // ' (' &
         // path // ')'
   end subroutine restart_resume

   !> Opens a restart point for reading; checks its checksum, tag and layout.
   subroutine open_point(path, s, stat, errmsg)
      character(len=*), intent(in) :: path          !< <prefix>.restart
      type(restart_stream_t), intent(out) :: s      !< the open stream, at the deck's part
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: iomsg
      s%reading = .true.
      open (newunit=s%u, file=path, access='stream', form='unformatted', status='old', action='read', &
            iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = path // ': ' // trim(iomsg)
         return
      end if
      if (.not. seal_holds(s%u)) then
         close (s%u)
         stat = 1
         errmsg = path // ': damaged (its checksum does not match its contents): no run continues from it'
         return
      end if
      call io_layout(s)
      stat = s%stat
      if (stat /= 0) then
         close (s%u)
         errmsg = path // ': not a restart point of this build of impact'
      end if
   end subroutine open_point

   !> The file's tag and layout; read, stat /= 0 for another layout.
   subroutine io_layout(s)
      type(restart_stream_t), intent(inout) :: s    !< the restart file, at its start
      integer :: version
      version = layout
      call io_tag(s, 'impactRS')
      call io_value(s, version)
      if (s%stat == 0 .and. version /= layout) s%stat = 1
   end subroutine io_layout

   !> The deck's variables as 'group.name' and the text of their value; read,
   !> `changed` names what differs from `deck` but free_vars.
   subroutine io_deck(s, deck, changed)
      type(restart_stream_t), intent(inout) :: s    !< the restart file, at the deck's part
      type(deck_t), intent(in) :: deck              !< the effective deck
      character(len=:), allocatable, intent(out) :: changed   !< '&group name = value (was value), ...'
      character(len=:), allocatable :: key, then, now
      integer :: iv, dot
      changed = ''
      call io_tag(s, 'deck')
      call io_count(s, size(deck_vars))
      variables: do iv = 1, size(deck_vars)
         key = var_key(iv)
         now = deck_value_text(deck, iv)
         then = now
         call io_text(s, key)
         call io_text(s, then)
         if (s%stat /= 0) exit variables
         if (var_key(iv) /= key) s%stat = 1               ! another schema: another build
         if (s%stat /= 0) exit variables
         if (any(free_vars == key) .or. now == then) cycle variables
         dot = index(key, '.')
         if (len(changed) > 0) changed = changed // ', '
         changed = changed // '&' // key(:dot - 1) // ' ' // key(dot + 1:) // ' = ' // now // ' (was ' // then // ')'
      end do variables
   end subroutine io_deck

   !> The state after a step: its step, the cpu time so far, the plate's
   !> displacements, velocities and accelerations, the impactor, the contact
   !> history and load pattern.
   subroutine io_state(s, step, cpu_s, st)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      integer, intent(inout) :: step                !< the step
      real(dp), intent(inout) :: cpu_s              !< cpu time of the run so far (s)
      type(step_state_t), intent(inout) :: st       !< the state (its plate's vectors allocated)
      call io_tag(s, 'state')
      call io_values(s, step, cpu_s)
      call io_array(s, st%plate%d)
      call io_array(s, st%plate%v)
      call io_array(s, st%plate%a)
      call io_impactor(s, st%imp)
      call io_count(s, 3)
      call io_values(s, st%hist%f_m, st%hist%alpha_m, st%hist%alpha_0, st%hist%separated)
      call io_pattern(s, st%cit%pattern)
   end subroutine io_state

   !> The solver's state that carries from step to step and the equations of
   !> its response columns (above restart_save).
   subroutine io_solver(s, solver, columns)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(solver_t), intent(inout) :: solver       !< the plate solver, factored
      integer, allocatable, intent(out) :: columns(:)   !< the equations of its columns
      character(len=:), allocatable :: note
      call io_tag(s, 'solver')
      call io_array(s, solver%contraction)
      call io_count(s, 5)
      call io_values(s, solver%since_measured, solver%solves, solver%response_solves, &
         solver%factorizations, solver%mixed_solves)
      note = ''
      if (allocated(solver%mixing_note)) note = solver%mixing_note
      call io_text(s, note)
      if (s%reading .and. len(note) > 0) solver%mixing_note = note
      allocate (columns(0))
      if (.not. s%reading) columns = solver%resp_eq(:solver%nresp)
      call io_ints(s, columns)
   end subroutine io_solver

   !> What the record carries from step to step: energies, previous step,
   !> running figures, warnings, the history's length, &strength's damage maps.
   subroutine io_record(s, rec, neq)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(record_t), intent(inout) :: rec          !< the record (read: as record_settings made it)
      integer, intent(in) :: neq                    !< the plate's equations
      real(dp) :: bytes
      logical :: active
      call io_tag(s, 'record')
      call io_count(s, 15)
      call io_values(s, rec%e0, rec%contact_work, rec%contact_energy, rec%alpha_prev, &
         rec%first_contact_start, rec%first_contact_end, rec%max_energy_error)
      call io_values(s, rec%energy_created, rec%energy_lost, rec%max_w_over_h, rec%w_bend_max, &
         rec%diverged_at, rec%c_plate, rec%c_impactor)
      call io_value(s, rec%max_slope)
      call io_count(s, 3*peak_size)
      call io_peak(s, rec%force_peak)
      call io_peak(s, rec%deflection_peak)
      call io_peak(s, rec%strain_peak)
      call io_count(s, 14 + nwarn)
      call io_values(s, rec%steps, rec%contacts, rec%contact_iterations, rec%max_contact_iter, &
         rec%max_solves, rec%unconverged_steps, rec%first_unconverged)
      call io_values(s, rec%nonlinear_fallback_steps, rec%contact_fallback_steps, rec%warnings, &
         rec%mixed_seen, rec%solves_before, rec%in_contact, rec%substepped_steps)
      call io_block(s, rec%warned)
      bytes = real(rec%hist_bytes, dp)
      call io_value(s, bytes)
      rec%hist_bytes = nint(bytes, int64)
      call io_impactor(s, rec%imp_prev)
      call io_pattern(s, rec%pattern_prev)
      if (.not. allocated(rec%d_prev)) allocate (rec%d_prev(neq))
      call io_array(s, rec%d_prev)
      active = rec%damage%active
      call io_value(s, active)
      if (s%stat == 0 .and. active .neqv. rec%damage%active) s%stat = 1
      call io_value(s, rec%damage%delam%onset)
      if (active) call io_damage(s, rec%damage)
   end subroutine io_record

   !> A peak's samples (src/record/step_peak.f90): samples, last, times,
   !> values, before, after, as peak_size reals.
   subroutine io_peak(s, p)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(peak_track_t), intent(inout) :: p        !< the samples kept
      real(dp) :: x(3)
      x = [real(p%samples, dp), merge(1.0_dp, 0.0_dp, p%before), merge(1.0_dp, 0.0_dp, p%after)]
      call io_values(s, x(1), p%t_last, p%v_last)
      call io_block(s, p%t)
      call io_block(s, p%v)
      call io_values(s, x(2), x(3))
      if (.not. s%reading .or. s%stat /= 0) return
      p%samples = nint(x(1))
      p%before = x(2) /= 0.0_dp
      p%after = x(3) /= 0.0_dp
   end subroutine io_peak

   !> &strength's figures and maps (src/results/damage_record.f90).
   subroutine io_damage(s, dmg)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      type(damage_t), intent(inout) :: dmg          !< the damage record, active
      call io_count(s, 12)
      call io_block(s, dmg%smax)
      call io_values(s, dmg%step_fi, dmg%max_fi, dmg%max_time, dmg%onset, dmg%onset_fi, &
         dmg%peak_force, dmg%peak_time)
      call io_count(s, 8)
      call io_values(s, dmg%step_mode, dmg%max_mode, dmg%max_ply, dmg%max_point, dmg%onset_mode, &
         dmg%onset_ply, dmg%onset_point)
      call io_value(s, dmg%peak_step)
      call io_array(s, dmg%fi_max)
      call io_array(s, dmg%mode_max)
      call io_array(s, dmg%onset_time)
      call io_array(s, dmg%d_peak)
      call io_count(s, 1)
      call io_value(s, dmg%delam%max_index)
      call io_count(s, 2)
      call io_values(s, dmg%delam%max_interface, dmg%delam%max_point)
      call io_array(s, dmg%delam%map)
   end subroutine io_damage

   !> What <prefix>.h5 holds at the restart point (h5: the run writes it):
   !> its rows, snapshots and peak.
   subroutine io_results(s, h5, pt)
      type(restart_stream_t), intent(inout) :: s    !< the restart file
      logical, intent(inout) :: h5                  !< the run writes <prefix>.h5
      type(results_point_t), intent(inout) :: pt    !< what it holds (read: peak_fields allocated)
      call io_tag(s, 'results')
      call io_value(s, h5)
      if (s%stat /= 0 .or. .not. h5) return
      call io_count(s, 3)
      call io_values(s, pt%rows, pt%snaps, pt%peak_step)
      call io_count(s, 2)
      call io_values(s, pt%peak_time, pt%peak_force)
      call io_array(s, pt%peak_fields)
   end subroutine io_results

   !> The history file cut back to its length at the restart point, opened for appending.
   subroutine reopen_history(deck, rec, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(record_t), intent(inout) :: rec          !< the record: its history file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: iomsg
      integer(int64) :: bytes
      rec%hist_path = deck%prefix // '_history.dat'
      bytes = file_size(rec%hist_path)
      if (bytes < rec%hist_bytes) then
         stat = 1
         errmsg = rec%hist_path // ': holds ' // int_str(int(max(bytes, -1_int64))) // ' bytes, fewer than at ' &
            // 'the restart point (' // int_str(int(rec%hist_bytes)) // '): it is not this run''s history'
         return
      end if
      call truncate_file(rec%hist_path, rec%hist_bytes, stat)
      if (stat == 0) open (newunit=rec%hist_unit, file=rec%hist_path, status='old', action='write', &
                           position='append', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = rec%hist_path // ': cannot open it again: ' // trim(iomsg)
         return
      end if
      call open_probe(rec%hist_path, rec%hist_probe, stat)
      if (stat /= 0) errmsg = rec%hist_path // ': cannot open it to read its length'
   end subroutine reopen_history

   !> fsync(2) of the file or directory `path`.
   subroutine force_to_disk(path, stat)
      character(len=*), intent(in) :: path          !< the file or directory
      integer, intent(out) :: stat                  !< 0 on success
      integer(c_int) :: fd, r
      stat = 1
      fd = c_open(path // c_null_char, o_rdonly)
      if (fd < 0) return
      r = c_fsync(fd)
      stat = merge(0, 1, r == 0)
      r = c_close(fd)
   end subroutine force_to_disk

end module restart_point
