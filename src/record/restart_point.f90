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
   use file_system, only: remove_file, rename_file, truncate_file, file_size, open_probe, parent_directory
   use mesh, only: ndof_node
   use plate_model, only: model_t
   use plate_solver, only: solver_t, contact_response
   use contact_law, only: contact_history_t
   use contact_load, only: load_pattern_t
   use contact_iteration, only: step_state_t
   use newmark, only: newmark_t
   use result_files, only: reserve_summary, results_claim_t, result_suffixes, claim_results, claim_left_empty
   use process_stop, only: remove_on_stop
   use results_hdf5, only: results_reopen, results_point_t, results_point
   use run_recorder, only: record_t, record_settings, nwarn
   use progress_line, only: progress_start
   use step_peak, only: peak_state, peak_restore, peak_state_size
   use restart_io, only: put_tag, take_tag, put_text, take_text, put_value, take_value, put_array, take_reals, &
      take_ints, put_impactor, take_impactor, put_pattern, take_pattern, put_seal, seal_holds
   implicit none
   private
   public :: restart_save, restart_check, restart_resume, claim_run_files

   !> The layout of the file; a restart point of another is refused.
   integer, parameter :: layout = 3
   !> The deck's variables a restart may change.
   character(len=*), parameter :: free_vars(2) = [character(len=24) :: 'analysis.t_end', 'output.overwrite']
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
      if (restart_asked .and. .not. restarting) write (output_unit, '(a)') &
         'restart: no restart point ' // restart_file(deck) // ': the run starts at step 0'
      claimed = deck
      claimed%overwrite = deck%overwrite .or. restarting
      if (restart_asked .and. .not. claimed%overwrite) &
         claimed%overwrite = claim_left_empty(deck%prefix, result_suffixes(deck%analysis_kind))
      call claim_results(claimed, result_suffixes(deck%analysis_kind), claim, stat, errmsg)
      if (stat /= 0) return
      call remove_on_stop(claim%first)
      if (.not. restarting) call restart_discard(deck)
   end subroutine claim_run_files

   !> Removes an earlier run's restart point, which the files no longer match.
   subroutine restart_discard(deck)
      type(deck_t), intent(in) :: deck              !< the effective deck
      integer :: ios
      call remove_file(restart_file(deck), ios)
      call remove_file(restart_file(deck) // '.tmp', ios)
   end subroutine restart_discard

   !> <prefix>.restart, written when the files are flushed (results_tick), at
   !> step 0 and at the end: what the time loop carries from step to step
   !> (the deck as text: only &analysis t_end may change; the state, the
   !> solver, the record, what <prefix>.h5 holds), in tagged parts sealed by
   !> their CRC-32 (restart_io). Written whole to <prefix>.restart.tmp, forced
   !> to the disk and renamed over the old one: the old point or the new one.
   subroutine restart_save(deck, cpu_s, st, solver, rec, stat, errmsg)
      type(deck_t), intent(in) :: deck              !< the effective deck
      real(dp), intent(in) :: cpu_s                 !< cpu time of the run so far (s)
      type(step_state_t), intent(in) :: st          !< the state after the last step recorded, committed
      type(solver_t), intent(in) :: solver          !< the plate solver
      type(record_t), intent(in) :: rec             !< the run's record (its steps: the last step made)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure, naming the file
      character(len=:), allocatable :: path
      character(len=msg_len) :: iomsg
      integer :: u, ios
      path = restart_file(deck)
      call remove_file(path // '.tmp', ios)          ! a link itself, never what it points to
      open (newunit=u, file=path // '.tmp', access='stream', form='unformatted', status='new', &
            action='readwrite', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = path // '.tmp: ' // trim(iomsg)
         return
      end if
      call put_tag(u, 'impactRS', stat)
      call put_value(u, layout, stat)
      call put_deck(u, deck, stat)
      call put_tag(u, 'state', stat)
      call put_value(u, rec%steps, stat)
      call put_value(u, cpu_s, stat)
      call put_array(u, st%plate%d, stat)
      call put_array(u, st%plate%v, stat)
      call put_array(u, st%plate%a, stat)
      call put_impactor(u, st%imp, stat)
      call put_array(u, [st%hist%f_m, st%hist%alpha_m, st%hist%alpha_0], stat)
      call put_value(u, st%hist%separated, stat)
      call put_pattern(u, st%cit%pattern, stat)
      call put_solver(u, solver, stat)
      call put_record(u, rec, stat)
      call put_results(u, rec, stat)
      call put_tag(u, 'end', stat)
      call put_seal(u, stat)
      close (u, iostat=ios)
      if (stat == 0) stat = ios
      if (stat == 0) call force_to_disk(path // '.tmp', stat)
      if (stat == 0) call rename_file(path // '.tmp', path, stat, iomsg)
      if (stat == 0) call force_to_disk(directory_of(path), stat)
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
      integer :: u
      stat = 0
      step = 0
      path = restart_file(deck)
      inquire (file=path, exist=found)
      if (.not. found) return
      call open_point(path, u, stat, errmsg)
      if (stat /= 0) return
      call compare_deck(u, deck, changed, stat)
      call take_tag(u, 'state', stat)
      call take_value(u, step, stat)
      close (u)
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
      real(dp), allocatable :: x(:)
      integer, allocatable :: columns(:)
      integer :: u
      type(results_point_t) :: pt
      logical :: h5
      integer :: step
      real(dp) :: cpu_s
      if (solver%damage%on) then
         stat = 1;  errmsg = '--restart: a restart point does not keep the ply damage (&damage): run the deck again'
         return
      end if
      path = restart_file(deck)
      step = 0;  cpu_s = 0.0_dp
      call open_point(path, u, stat, errmsg)
      if (stat /= 0) return
      call compare_deck(u, deck, changed, stat)
      call take_tag(u, 'state', stat)
      call take_value(u, step, stat)
      call take_value(u, cpu_s, stat)
      call take_reals(u, st%plate%d, stat, model%msh%neq)
      call take_reals(u, st%plate%v, stat, model%msh%neq)
      call take_reals(u, st%plate%a, stat, model%msh%neq)
      call take_impactor(u, st%imp, stat)
      call take_reals(u, x, stat, 3)
      if (stat == 0) st%hist = contact_history_t(f_m=x(1), alpha_m=x(2), alpha_0=x(3))
      call take_value(u, st%hist%separated, stat)
      call take_pattern(u, st%cit%pattern, stat)
      call take_solver(u, solver, columns, stat)
      call take_record(u, deck, model, nm, rec, stat)
      rec%cpu_before = cpu_s
      h5 = .false.
      call take_results(u, model%msh%nnode, h5, pt, stat)
      call take_tag(u, 'end', stat)
      close (u)
      if (stat /= 0 .or. step /= rec%steps) then
         stat = 1
         errmsg = path // ': not a restart point of this run (or damaged)'
         return
      end if
      if (step > rec%nstep) then
         stat = 1
         errmsg = deck%source // ': &analysis t_end = ' // real_str(deck%t_end) // ' s ends at step ' &
            // int_str(rec%nstep) // ', before the restart point''s step ' // int_str(step)
         return
      end if
      if (h5 .neqv. deck%hdf5) then
         stat = 1
         errmsg = path // ': its run had &output hdf5 = ' // trim(merge('.true. ', '.false.', h5))
         return
      end if
      call response_columns(solver, columns, stat, errmsg)
      if (stat == 0) call reopen_history(deck, rec, stat, errmsg)
      if (stat == 0 .and. h5) call results_reopen(deck, model%msh, pt, rec%h5, stat, errmsg)
      if (stat == 0) call reserve_summary(deck, stat, errmsg)
      if (stat == 0) write (output_unit, '(a)') 'restart: the run continues after step ' // int_str(step) // ' (' &
         // path // ')'
   end subroutine restart_resume

   !> Opens a restart point for reading; checks its checksum, tag and layout.
   subroutine open_point(path, u, stat, errmsg)
      character(len=*), intent(in) :: path          !< <prefix>.restart
      integer, intent(out) :: u                     !< the open stream, at the deck's part
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: iomsg
      integer :: version
      open (newunit=u, file=path, access='stream', form='unformatted', status='old', action='read', &
            iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = path // ': ' // trim(iomsg)
         return
      end if
      if (.not. seal_holds(u)) then
         close (u)
         stat = 1
         errmsg = path // ': damaged (its checksum does not match its contents): no run continues from it'
         return
      end if
      version = -1
      call take_tag(u, 'impactRS', stat)
      call take_value(u, version, stat)
      if (stat == 0 .and. version /= layout) stat = 1
      if (stat /= 0) then
         close (u)
         errmsg = path // ': not a restart point of this build of impact'
      end if
   end subroutine open_point

   !> The deck's variables as 'group.name' and the text of their value.
   subroutine put_deck(u, deck, stat)
      integer, intent(in) :: u                      !< the restart file
      type(deck_t), intent(in) :: deck              !< the effective deck
      integer, intent(inout) :: stat                !< 0, or the first failure
      integer :: iv
      call put_tag(u, 'deck', stat)
      call put_value(u, size(deck_vars), stat)
      do iv = 1, size(deck_vars)
         call put_text(u, var_key(iv), stat)
         call put_text(u, deck_value_text(deck, iv), stat)
      end do
   end subroutine put_deck

   !> Reads the deck's part and names what differs from `deck` but free_vars.
   subroutine compare_deck(u, deck, changed, stat)
      integer, intent(in) :: u                      !< the restart file, at the deck's part
      type(deck_t), intent(in) :: deck              !< the effective deck
      character(len=:), allocatable, intent(out) :: changed   !< '&group name = value (was value), ...'
      integer, intent(inout) :: stat                !< 0, or the first failure
      character(len=:), allocatable :: key, then, now
      integer :: n, k, iv, dot
      changed = ''
      now = ''            ! (else gfortran 12 at -O2 takes its length for unset in the loop)
      n = -1
      call take_tag(u, 'deck', stat)
      call take_value(u, n, stat)
      if (stat == 0 .and. n /= size(deck_vars)) stat = 1
      variables: do k = 1, max(n, 0)
         call take_text(u, key, stat)
         call take_text(u, then, stat)
         if (stat /= 0) exit variables
         iv = k
         if (var_key(iv) /= key) stat = 1               ! another schema: another build
         if (stat /= 0) exit variables
         if (any(free_vars == key)) cycle variables
         now = deck_value_text(deck, iv)
         if (now == then) cycle variables
         dot = index(key, '.')
         if (len(changed) > 0) changed = changed // ', '
         changed = changed // '&' // key(:dot - 1) // ' ' // key(dot + 1:) // ' = ' // now // ' (was ' // then // ')'
      end do variables
   end subroutine compare_deck

   !> The solver's state that carries from step to step (above restart_save).
   subroutine put_solver(u, solver, stat)
      integer, intent(in) :: u                      !< the restart file
      type(solver_t), intent(in) :: solver          !< the plate solver
      integer, intent(inout) :: stat                !< 0, or the first failure
      call put_tag(u, 'solver', stat)
      call put_array(u, solver%contraction, stat)
      call put_array(u, [solver%since_measured, solver%solves, solver%response_solves, solver%factorizations, &
         solver%mixed_solves], stat)
      if (allocated(solver%mixing_note)) then
         call put_text(u, solver%mixing_note, stat)
      else
         call put_text(u, '', stat)
      end if
      call put_array(u, solver%resp_eq(:solver%nresp), stat)
   end subroutine put_solver

   !> Reads the solver's state and the equations of its response columns.
   subroutine take_solver(u, solver, columns, stat)
      integer, intent(in) :: u                      !< the restart file, at the solver's part
      type(solver_t), intent(inout) :: solver       !< the plate solver, factored
      integer, allocatable, intent(out) :: columns(:)   !< the equations of its columns
      integer, intent(inout) :: stat                !< 0, or the first failure
      real(dp), allocatable :: x(:)
      integer, allocatable :: i(:)
      character(len=:), allocatable :: note
      allocate (columns(0))
      call take_tag(u, 'solver', stat)
      call take_reals(u, x, stat, 2)
      call take_ints(u, i, stat, 5)
      call take_text(u, note, stat)
      call take_ints(u, columns, stat)
      if (stat /= 0) return
      solver%contraction = x
      solver%since_measured = i(1);  solver%solves = i(2);  solver%response_solves = i(3)
      solver%factorizations = i(4);  solver%mixed_solves = i(5)
      if (len(note) > 0) solver%mixing_note = note
   end subroutine take_solver

   !> The solver's response columns on the equations `columns`, computed again
   !> in their order (the same values); its count of back substitutions kept.
   subroutine response_columns(solver, columns, stat, errmsg)
      type(solver_t), intent(inout) :: solver       !< the plate solver, factored
      integer, intent(in) :: columns(:)             !< the equations
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(load_pattern_t) :: all
      integer :: counted
      counted = solver%response_solves
      all%n = size(columns)
      all%eq = columns
      allocate (all%c(all%n), source=1.0_dp)
      call contact_response(solver, all, stat, errmsg)
      solver%response_solves = counted
   end subroutine response_columns

   !> What the record carries from step to step: energies, previous step,
   !> running figures, warnings, the history's length, &strength's damage maps.
   subroutine put_record(u, rec, stat)
      type(record_t), intent(in) :: rec             !< the record
      integer, intent(in) :: u                      !< the restart file, an open stream
      integer, intent(inout) :: stat                !< 0, or the first failure
      call put_tag(u, 'record', stat)
      call put_array(u, [rec%e0, rec%contact_work, rec%contact_energy, rec%alpha_prev, &
         rec%first_contact_start, rec%first_contact_end, rec%max_energy_error, rec%energy_created, &
         rec%energy_lost, rec%max_w_over_h, rec%w_bend_max, &
         rec%diverged_at, rec%c_plate, rec%c_impactor, rec%max_slope], stat)
      call put_array(u, [peak_state(rec%force_peak), peak_state(rec%deflection_peak), peak_state(rec%strain_peak)], &
         stat)
      call put_array(u, [rec%steps, rec%contacts, rec%contact_iterations, rec%max_contact_iter, rec%max_solves, &
         rec%unconverged_steps, rec%first_unconverged, rec%nonlinear_fallback_steps, rec%contact_fallback_steps, &
         rec%warnings, rec%mixed_seen, rec%solves_before, merge(1, 0, rec%in_contact), rec%substepped_steps, &
         merge(1, 0, rec%warned)], stat)
      call put_value(u, real(rec%hist_bytes, dp), stat)
      call put_impactor(u, rec%imp_prev, stat)
      call put_pattern(u, rec%pattern_prev, stat)
      call put_array(u, rec%d_prev, stat)
      call put_value(u, rec%damage%active, stat)
      call put_value(u, rec%damage%delam%onset, stat)
      if (.not. rec%damage%active) return
      call put_array(u, [rec%damage%smax, rec%damage%step_fi, rec%damage%max_fi, rec%damage%max_time, &
         rec%damage%onset, rec%damage%onset_fi, rec%damage%peak_force, rec%damage%peak_time], stat)
      call put_array(u, [rec%damage%step_mode, rec%damage%max_mode, rec%damage%max_ply, rec%damage%max_point, &
         rec%damage%onset_mode, rec%damage%onset_ply, rec%damage%onset_point, rec%damage%peak_step], stat)
      call put_array(u, reshape(rec%damage%fi_max, [size(rec%damage%fi_max)]), stat)
      call put_array(u, reshape(rec%damage%mode_max, [size(rec%damage%mode_max)]), stat)
      call put_array(u, reshape(rec%damage%onset_time, [size(rec%damage%onset_time)]), stat)
      call put_array(u, rec%damage%d_peak, stat)
      call put_array(u, [rec%damage%delam%max_index], stat)
      call put_array(u, [rec%damage%delam%max_interface, rec%damage%delam%max_point], stat)
      call put_array(u, reshape(rec%damage%delam%map, [size(rec%damage%delam%map)]), stat)
   end subroutine put_record

   !> The record of the deck with the figures put_record wrote (its files closed).
   subroutine take_record(u, deck, model, nm, rec, stat)
      type(record_t), intent(out) :: rec            !< the record
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(model_t), intent(in) :: model            !< the model
      type(newmark_t), intent(in) :: nm             !< Newmark's constants (the time step)
      integer, intent(in) :: u                      !< the restart file, an open stream at the record's part
      integer, intent(inout) :: stat                !< 0, or the first failure
      real(dp), allocatable :: r(:)
      integer, allocatable :: i(:)
      real(dp) :: bytes
      logical :: active
      call record_settings(rec, deck, model, nm)
      call take_tag(u, 'record', stat)
      call take_reals(u, r, stat, 15)
      if (stat /= 0) return
      rec%e0 = r(1);  rec%contact_work = r(2);  rec%contact_energy = r(3);  rec%alpha_prev = r(4)
      rec%first_contact_start = r(5);  rec%first_contact_end = r(6);  rec%max_energy_error = r(7)
      rec%energy_created = r(8);  rec%energy_lost = r(9);  rec%max_w_over_h = r(10);  rec%w_bend_max = r(11)
      rec%diverged_at = r(12);  rec%c_plate = r(13);  rec%c_impactor = r(14);  rec%max_slope = r(15)
      call take_reals(u, r, stat, 3*peak_state_size)
      if (stat /= 0) return
      rec%force_peak = peak_restore(r(1:peak_state_size))
      rec%deflection_peak = peak_restore(r(peak_state_size + 1:2*peak_state_size))
      rec%strain_peak = peak_restore(r(2*peak_state_size + 1:))
      call take_ints(u, i, stat, 14 + nwarn)
      if (stat /= 0) return
      rec%steps = i(1);  rec%contacts = i(2);  rec%contact_iterations = i(3);  rec%max_contact_iter = i(4)
      rec%max_solves = i(5);  rec%unconverged_steps = i(6);  rec%first_unconverged = i(7)
      rec%nonlinear_fallback_steps = i(8);  rec%contact_fallback_steps = i(9);  rec%warnings = i(10)
      rec%mixed_seen = i(11);  rec%solves_before = i(12);  rec%in_contact = i(13) /= 0
      rec%substepped_steps = i(14)
      rec%warned = i(15:) /= 0
      call progress_start(rec%progress, rec%nstep, deck%t_end)   ! the progress line goes on
      bytes = 0.0_dp
      call take_value(u, bytes, stat)
      rec%hist_bytes = nint(bytes, int64)
      call take_impactor(u, rec%imp_prev, stat)
      call take_pattern(u, rec%pattern_prev, stat)
      call take_reals(u, rec%d_prev, stat, model%msh%neq)
      active = .false.
      call take_value(u, active, stat)
      if (stat == 0 .and. active .neqv. rec%damage%active) stat = 1
      call take_value(u, rec%damage%delam%onset, stat)
      if (stat /= 0 .or. .not. active) return
      call take_reals(u, r, stat, 12)
      call take_ints(u, i, stat, 8)
      if (stat /= 0) return
      rec%damage%smax = r(1:5);  rec%damage%step_fi = r(6);  rec%damage%max_fi = r(7)
      rec%damage%max_time = r(8);  rec%damage%onset = r(9);  rec%damage%onset_fi = r(10)
      rec%damage%peak_force = r(11);  rec%damage%peak_time = r(12)
      rec%damage%step_mode = i(1);  rec%damage%max_mode = i(2);  rec%damage%max_ply = i(3)
      rec%damage%max_point = i(4);  rec%damage%onset_mode = i(5);  rec%damage%onset_ply = i(6)
      rec%damage%onset_point = i(7);  rec%damage%peak_step = i(8)
      call take_reals(u, r, stat, size(rec%damage%fi_max))
      if (stat == 0) rec%damage%fi_max = reshape(r, shape(rec%damage%fi_max))
      call take_ints(u, i, stat, size(rec%damage%mode_max))
      if (stat == 0) rec%damage%mode_max = reshape(i, shape(rec%damage%mode_max))
      call take_reals(u, r, stat, size(rec%damage%onset_time))
      if (stat == 0) rec%damage%onset_time = reshape(r, shape(rec%damage%onset_time))
      call take_reals(u, rec%damage%d_peak, stat, model%msh%neq)
      call take_reals(u, r, stat, 1)
      call take_ints(u, i, stat, 2)
      if (stat /= 0) return
      rec%damage%delam%max_index = r(1);  rec%damage%delam%max_interface = i(1);  rec%damage%delam%max_point = i(2)
      call take_reals(u, r, stat, size(rec%damage%delam%map))
      if (stat == 0) rec%damage%delam%map = reshape(r, shape(rec%damage%delam%map))
   end subroutine take_record

   !> What <prefix>.h5 holds at the restart point: its rows, snapshots and peak.
   subroutine put_results(u, rec, stat)
      integer, intent(in) :: u                      !< the restart file
      type(record_t), intent(in) :: rec             !< the run's record
      integer, intent(inout) :: stat                !< 0, or the first failure
      type(results_point_t) :: pt
      call put_tag(u, 'results', stat)
      call put_value(u, allocated(rec%h5%path), stat)
      if (.not. allocated(rec%h5%path)) return
      pt = results_point(rec%h5)
      call put_array(u, [pt%rows, pt%snaps, pt%peak_step], stat)
      call put_array(u, [pt%peak_time, pt%peak_force], stat)
      call put_array(u, reshape(pt%peak_fields, [size(pt%peak_fields)]), stat)
   end subroutine put_results

   !> Reads what put_results wrote (nnode: the mesh's nodes).
   subroutine take_results(u, nnode, h5, pt, stat)
      integer, intent(in) :: u                      !< the restart file, at the results' part
      integer, intent(in) :: nnode                  !< the mesh's nodes
      logical, intent(out) :: h5                    !< the run wrote <prefix>.h5
      type(results_point_t), intent(out) :: pt      !< what it holds
      integer, intent(inout) :: stat                !< 0, or the first failure
      real(dp), allocatable :: x(:), f(:)
      integer, allocatable :: i(:)
      h5 = .false.
      call take_tag(u, 'results', stat)
      call take_value(u, h5, stat)
      if (stat /= 0 .or. .not. h5) return
      call take_ints(u, i, stat, 3)
      call take_reals(u, x, stat, 2)
      call take_reals(u, f, stat, ndof_node*nnode)
      if (stat /= 0) return
      pt = results_point_t(i(1), i(2), i(3), x(1), x(2), reshape(f, [ndof_node, nnode]))
   end subroutine take_results

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

   !> The directory of `path` ('.' or '/' when it has none).
   pure function directory_of(path) result(dir)
      character(len=*), intent(in) :: path          !< a file
      character(len=:), allocatable :: dir
      dir = parent_directory(path)
      if (len(dir) == 0) dir = merge('/', '.', path(1:min(1, len(path))) == '/')
   end function directory_of

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
