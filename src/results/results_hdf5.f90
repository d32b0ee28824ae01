!> The full results of a run in one HDF5 file, <prefix>.h5 (&output hdf5): the deck, the mesh, the
!> history's columns, the nodal fields every fields_every steps, the state at the largest force
!> (/peak), the summary; SI units, every dataset checksummed, written in blocks once a second. The
!> layout: docs/OUTPUT.md. Not from the paper.
module results_hdf5
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: iso_c_binding, only: c_int, c_null_char
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, deck_vars, deck_groups, value_t, deck_bind, strength_given, kind_real, kind_integer, &
      kind_logical, kind_word, kind_path, kind_reals
   use deck_echo, only: echo_deck
   use build_info, only: code_version
   use c_library, only: c_unlink
   use file_system, only: rename_file
   use mesh, only: mesh_t, ndof_node, freedom_name
   use plate_damage, only: damage_wanted
   use result_files, only: keep_failure, column_t, history_columns, nhist_damage, history_width, summary_item_t
   use hdf5_io, only: h5io_start, h5io_open, h5io_close, h5io_flush, h5io_group, h5io_set_attr, &
      h5io_update_attr, h5io_write, h5io_rewrite, h5io_delete
   use hdf5_series, only: h5io_create_series, h5io_append_block, h5io_open_dataset, &
      h5io_cut_series, h5io_read_series, h5io_close_dataset, h5io_real, h5io_integer
   use results_xdmf, only: xdmf_t, xdmf_open, xdmf_start, xdmf_resume, xdmf_snapshots, xdmf_batch_close, &
      xdmf_grow, xdmf_cut, xdmf_peak, xdmf_close
   implicit none
   private
   public :: results_file_t, results_point_t, results_point, results_open, results_append_history, results_state, &
             results_tick, results_flush, results_leave, results_closing, results_finish, attr_text, &
             attr_unit

   integer, parameter :: units_len = 8
   !> Units of /fields' time, step, force and nodal fields u, v, w, psi_x, psi_y.
   character(len=units_len), parameter :: snap_units(3 + ndof_node) = [character(len=units_len) :: &
      's', '-', 'N', 'm', 'm', 'm', 'rad', 'rad']
   !> The snapshot series (rf%snaps): time, step, force, then the nodal fields (mesh's freedom_name).
   character(len=12), parameter :: snap_names(3 + ndof_node) = [character(len=12) :: 'fields/time', &
      'fields/step', 'fields/force', 'fields/u', 'fields/v', 'fields/w', 'fields/psi_x', 'fields/psi_y']
   !> Values per chunk of a series (4 KiB; the fields': whole snapshots, one at least).
   integer, parameter :: hist_chunk = 512
   !> Wall time between two flushes (s): a killed run loses at most this.
   real(dp), parameter :: flush_seconds = 1.0_dp
   !> Rows that may wait before a flush, and the memory the waiting snapshots may take.
   integer, parameter :: flush_rows = 65536, min_snapshots = 16
   integer(int64), parameter :: buffer_bytes = 8*1024*1024
   !> An open results file and the ids of its growing datasets.
   type :: results_file_t
      logical :: active = .false.                       !< a file is being written (&output hdf5)
      logical :: broken = .false.                       !< a write failed: the file is left as at its last flush
      character(len=:), allocatable :: path             !< <prefix>.h5
      integer(hid_t) :: fid = -1                        !< the file while it is open (a flush, the end)
      integer(hid_t) :: hist(nhist_damage) = -1       !< /history/<column> (result_files: history_columns)
      integer :: ncol = 0                               !< the run's columns (history_width)
      integer(hid_t) :: snaps(3 + ndof_node) = -1       !< /fields/time, step, force, u, v, w, psi_x, psi_y
      integer, allocatable :: eq(:,:)                   !< (ndof_node, nnode) equation numbers, 0 held
      real(dp) :: peak_force = 0.0_dp                   !< largest contact force so far (N)
      type(xdmf_t) :: xdmf                              !< <prefix>.xdmf, for ParaView (src/results/results_xdmf.f90)
      integer :: rows_written = 0                       !< history rows in the file
      integer :: snaps_written = 0                      !< snapshots in the file
      !> what waits for the next flush (above results_tick)
      integer :: nrow = 0                               !< history rows waiting
      real(dp), allocatable :: rows(:,:)                !< (ncol, flush_rows) the rows, SI
      integer :: nsnap = 0                              !< snapshots waiting
      real(dp), allocatable :: snap(:,:)                !< (3, snapshots held) time, step, force
      real(dp), allocatable :: snap_fields(:,:,:)       !< (ndof_node, nnode, snapshots held) their fields
      logical :: peak_waiting = .false.                 !< the peak below is newer than the file's
      integer :: peak_step = 0                          !< step of the largest force
      real(dp) :: peak_time = 0.0_dp                    !< its time (s)
      real(dp), allocatable :: peak_fields(:,:)         !< (ndof_node, nnode) its fields
      integer(int64) :: flushed_at = 0                  !< system_clock count of the last flush
      integer(int64) :: clock_rate = 1                  !< system_clock counts per second
   end type results_file_t

   !> What a restart point holds of <prefix>.h5 (src/record/restart_point.f90).
   type :: results_point_t
      integer :: rows = 0, snaps = 0                !< history rows and snapshots in the file
      integer :: peak_step = 0                      !< the peak: its step,
      real(dp) :: peak_time = 0, peak_force = 0     !< time (s), force (N)
      real(dp), allocatable :: peak_fields(:,:)     !< and nodal fields (ndof_node, nnode)
   end type results_point_t

contains

   !> What the file holds once flushed, for a restart point.
   pure function results_point(rf) result(pt)
      type(results_file_t), intent(in) :: rf        !< the results file
      type(results_point_t) :: pt
      pt = results_point_t(rf%rows_written + rf%nrow, rf%snaps_written + rf%nsnap, rf%peak_step, rf%peak_time, &
                           rf%peak_force, rf%peak_fields)
   end function results_point

   !> Writes all but what grows (deck, mesh, empty series, /peak, /summary status 'running') under
   !> <prefix>.h5.tmp and renames it into place; from then on the file is open only while it is
   !> written, in SWMR mode, which keeps it readable on disk at every instant (a kill inside a write
   !> leaves it marked open: h5clear -s, or impact --restart, clears the mark). With pt (a restart):
   !> <prefix>.h5 cut back to pt; /summary back to 'running', /strength gone, the XDMF views anew.
   subroutine results_open(deck, msh, rf, stat, errmsg, pt)
      type(deck_t), intent(in) :: deck              !< the effective deck
      type(mesh_t), intent(in) :: msh               !< the mesh with its equation numbers
      type(results_file_t), intent(out) :: rf       !< the results file, active on return when deck%hdf5
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      type(results_point_t), intent(in), optional :: pt   !< a restart's point
      character(len=msg_len) :: why
      real(dp), allocatable :: time(:), step(:), force(:)
      integer(c_int) :: gone
      integer :: c, k, held
      stat = 0
      call system_clock(rf%flushed_at, rf%clock_rate)   ! (results_tick: restarts without HDF5 too)
      if (.not. deck%hdf5) return
      rf%path = deck%prefix//'.h5';  rf%eq = msh%eq
      rf%ncol = history_width(strength_given(deck), damage_wanted(deck))
      held = int(max(int(min_snapshots, int64), buffer_bytes/(8_int64*ndof_node*msh%nnode)))
      allocate (rf%rows(rf%ncol, flush_rows), rf%snap(3, held), rf%snap_fields(ndof_node, msh%nnode, held), &
                rf%peak_fields(ndof_node, msh%nnode), source=0.0_dp)
      why = ''
      if (.not. present(pt)) gone = c_unlink(rf%path // c_null_char)   ! an earlier run's (claim allowed)
      call h5io_start(stat, why)
      if (present(pt)) then
         rf%peak_step = pt%peak_step;  rf%peak_time = pt%peak_time;  rf%peak_force = pt%peak_force
         rf%peak_fields = pt%peak_fields
         if (stat == 0) call h5io_open(rf%path, .false., .false., rf%fid, stat, why)
         do c = 1, rf%ncol
            call cut(rf%hist(c), 'history/' // trim(history_columns(c)%name), pt%rows)
         end do
         do k = 1, size(rf%snaps)
            call cut(rf%snaps(k), trim(snap_names(k)), pt%snaps)
         end do
         if (stat == 0) call xdmf_cut(rf%xdmf, deck, msh, rf%fid, pt%snaps, stat, why)
         if (stat == 0) call h5io_update_attr(rf%fid, 'history', 'rows', pt%rows, stat, why)
         if (stat == 0) call h5io_update_attr(rf%fid, 'fields', 'snapshots', pt%snaps, stat, why)
         if (stat == 0) call write_peak(rf, stat, why)
         if (stat == 0) call h5io_delete(rf%fid, 'strength', stat, why)
         if (stat == 0) call h5io_delete(rf%fid, 'summary', stat, why)
         if (stat == 0) call h5io_group(rf%fid, 'summary', stat, why)
         call attr_text(rf%fid, 'summary', 'status', 'running', stat, why)
         if (stat == 0) call h5io_read_series(rf%fid, 'fields/time', time, stat, why)
         if (stat == 0) call h5io_read_series(rf%fid, 'fields/step', step, stat, why)
         if (stat == 0) call h5io_read_series(rf%fid, 'fields/force', force, stat, why)
         call close_window(rf, stat, why)
         if (stat == 0) call xdmf_resume(rf%xdmf, time, nint(step), force, stat, why)
         rf%rows_written = pt%rows;  rf%snaps_written = pt%snaps
      else
         if (stat == 0) call h5io_open(rf%path // '.tmp', .true., .true., rf%fid, stat, why)
         if (stat /= 0) then
            errmsg = '&output: prefix = "'//trim(deck%prefix)//'": '//trim(why)
            return
         end if
         call write_root(rf%fid, stat, why)
         if (stat == 0) call write_deck(rf%fid, deck, stat, why)
         if (stat == 0) call write_mesh(rf%fid, msh, stat, why)
         call create_history(rf, deck%every, stat, why)
         call create_fields(rf, deck%fields_every, msh%nnode, stat, why)
         call create_peak(rf%fid, msh%nnode, stat, why)
         if (stat == 0) call h5io_group(rf%fid, 'summary', stat, why)
         call attr_text(rf%fid, 'summary', 'status', 'running', stat, why)
         if (stat == 0) call xdmf_open(rf%xdmf, deck, msh, rf%fid, stat, why)
         call close_window(rf, stat, why)
         if (stat == 0) call rename_file(rf%path // '.tmp', rf%path, stat, why)
         if (stat == 0) call xdmf_start(rf%xdmf, stat, why)
      end if
      if (stat /= 0) then
         errmsg = rf%path // ': ' // trim(why)
         if (.not. present(pt)) gone = c_unlink(rf%path // '.tmp' // c_null_char)
         return
      end if
      rf%active = .true.
   contains
      !> The series `name` opened (did) and cut to n entries.
      subroutine cut(did, name, n)
         integer(hid_t), intent(inout) :: did
         character(len=*), intent(in) :: name
         integer, intent(in) :: n
         if (stat == 0) call h5io_open_dataset(rf%fid, name, did, stat, why)
         if (stat == 0) call h5io_cut_series(did, n, stat, why)
         if (stat /= 0 .and. index(why, "'") == 0) why = trim(why) // " '" // name // "'"
      end subroutine cut
   end subroutine results_open

   !> One history row (SI, history_columns' order), kept for the next flush.
   subroutine results_append_history(rf, row, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      real(dp), intent(in) :: row(:)                !< the row just written to the history file, SI (rf%ncol)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 0
      if (.not. rf%active) return
      if (rf%nrow == size(rf%rows, 2)) call results_flush(rf, stat, errmsg)
      if (stat /= 0) return
      rf%nrow = rf%nrow + 1
      rf%rows(:, rf%nrow) = row
   end subroutine results_append_history

   !> The nodal fields at the end of a step, kept for the next flush: a snapshot
   !> when `snapshot`, /peak's state when the force is the largest so far.
   subroutine results_state(rf, step, time, force, d, snapshot, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      integer, intent(in) :: step                   !< time step of the state
      real(dp), intent(in) :: time, force           !< its time (s) and contact force (N)
      real(dp), intent(in) :: d(:)                  !< plate displacements {D} by equation
      logical, intent(in) :: snapshot               !< append it to /fields
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 0
      if (.not. rf%active) return
      if (snapshot) then
         if (rf%nsnap == size(rf%snap, 2)) call results_flush(rf, stat, errmsg)
         if (stat /= 0) return
         rf%nsnap = rf%nsnap + 1
         rf%snap(:, rf%nsnap) = [time, real(step, dp), force]
         rf%snap_fields(:, :, rf%nsnap) = nodal_values(rf%eq, d)
      end if
      if (.not. force > rf%peak_force) return
      rf%peak_force = force
      rf%peak_step = step
      rf%peak_time = time
      rf%peak_fields = nodal_values(rf%eq, d)
      rf%peak_waiting = .true.
   end subroutine results_state

   !> Rows, snapshots and the peak wait in memory for results_flush: once flush_seconds have passed
   !> (a restart point is then due), when the buffers are full, on a warning, at the end.
   subroutine results_tick(rf, due, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      logical, intent(out) :: due                   !< a flush was made: the files hold every step so far
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer(int64) :: now
      stat = 0
      call system_clock(now)
      due = real(now - rf%flushed_at, dp) >= flush_seconds*real(rf%clock_rate, dp)
      if (.not. due) return
      call results_flush(rf, stat, errmsg)
      rf%flushed_at = now
   end subroutine results_tick

   !> Writes what waits in one opening of the file in SWMR mode, then the XDMF views.
   subroutine results_flush(rf, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: why
      character(len=:), allocatable :: part
      integer :: batch
      stat = 0
      if (.not. rf%active .or. rf%broken) return
      call system_clock(rf%flushed_at)
      if (rf%nrow == 0 .and. rf%nsnap == 0 .and. .not. rf%peak_waiting) return
      why = ''
      batch = rf%nsnap
      part = ''
      call h5io_open(rf%path, .false., .true., rf%fid, stat, why)
      if (stat == 0) part = '/history: '
      if (stat == 0) call write_rows(rf, stat, why)
      if (stat == 0) part = '/fields: '
      if (stat == 0) call write_snapshots(rf, stat, why)
      if (stat == 0) part = '/peak: '
      if (stat == 0 .and. rf%peak_waiting) call write_peak(rf, stat, why)
      if (stat == 0) part = ''
      ! all of it on disk, then the counts that say so (a kill between leaves the old counts)
      if (stat == 0) call h5io_flush(rf%fid, stat, why)
      if (stat == 0) call h5io_update_attr(rf%fid, 'history', 'rows', rf%rows_written + rf%nrow, stat, why)
      if (stat == 0) call h5io_update_attr(rf%fid, 'fields', 'snapshots', rf%snaps_written + rf%nsnap, stat, why)
      call close_window(rf, stat, why)
      if (stat == 0) then
         rf%rows_written = rf%rows_written + rf%nrow
         rf%snaps_written = rf%snaps_written + rf%nsnap
         rf%nrow = 0;  rf%nsnap = 0;  rf%peak_waiting = .false.
      end if
      ! the XML last, naming only what this flush has written (src/results/results_xdmf.f90)
      if (stat == 0 .and. batch > 0) then
         part = rf%xdmf%views_path // ': '
         call xdmf_snapshots(rf%xdmf, rf%snaps_written - batch, nint(rf%snap(2, :batch)), rf%snap(1, :batch), &
                             rf%snap(3, :batch), stat, why)
         if (stat == 0) call xdmf_batch_close(rf%xdmf, stat, why)
      end if
      if (stat /= 0) errmsg = rf%path//': '//part//trim(why)
      rf%broken = stat /= 0
   end subroutine results_flush

   !> The waiting rows appended to /history, a block per column.
   subroutine write_rows(rf, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file, open
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: c
      stat = 0
      columns: do c = 1, rf%ncol
         if (rf%nrow == 0 .or. stat /= 0) exit columns
         call h5io_open_dataset(rf%fid, 'history/' // trim(history_columns(c)%name), rf%hist(c), stat, why)
         if (stat /= 0) exit columns
         if (history_columns(c)%whole) then
            call h5io_append_block(rf%hist(c), nint(rf%rows(c, :rf%nrow)), stat, why)
         else
            call h5io_append_block(rf%hist(c), rf%rows(c, :rf%nrow), stat, why)
         end if
      end do columns
   end subroutine write_rows

   !> The waiting snapshots appended to /fields (and the XDMF's mirror).
   subroutine write_snapshots(rf, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file, open
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k, n
      stat = 0
      n = rf%nsnap
      if (n == 0) return
      do k = 1, size(rf%snaps)
         if (stat == 0) call h5io_open_dataset(rf%fid, trim(snap_names(k)), rf%snaps(k), stat, why)
         if (stat /= 0) exit
         if (k == 2) then
            call h5io_append_block(rf%snaps(k), nint(rf%snap(k, :n)), stat, why)
         else if (k <= 3) then
            call h5io_append_block(rf%snaps(k), rf%snap(k, :n), stat, why)
         else
            call h5io_append_block(rf%snaps(k), rf%snap_fields(k - 3, :, :n), stat, why)
         end if
      end do
      if (stat == 0) call xdmf_grow(rf%xdmf, rf%fid, rf%snap_fields(:, :, :n), stat, why)
   end subroutine write_snapshots

   !> /peak rewritten in place, and the XDMF's mirror of it.
   subroutine write_peak(rf, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file, open
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k
      stat = 0
      peak_fields: do k = 1, ndof_node
         call h5io_rewrite(rf%fid, 'peak/'//trim(freedom_name(k)), rf%peak_fields(k, :), stat, why)
         if (stat /= 0) exit peak_fields
      end do peak_fields
      if (stat == 0) call h5io_update_attr(rf%fid, 'peak', 'step', rf%peak_step, stat, why)
      if (stat == 0) call h5io_update_attr(rf%fid, 'peak', 'time', rf%peak_time, stat, why)
      if (stat == 0) call h5io_update_attr(rf%fid, 'peak', 'force', rf%peak_force, stat, why)
      if (stat == 0) call xdmf_peak(rf%xdmf, rf%fid, rf%peak_fields, stat, why)
   end subroutine write_peak

   !> Closes the series open in the file and the file, keeping the first failure.
   subroutine close_window(rf, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file
      integer, intent(inout) :: stat                !< 0 on success; the first failure is kept
      character(len=*), intent(inout) :: why        !< reason on failure
      character(len=msg_len) :: text
      integer :: ios
      call close_all(rf%hist)
      call close_all(rf%snaps)
      if (rf%fid < 0) return
      call h5io_close(rf%fid, ios, text)
      rf%fid = -1
      call keep_failure(stat, why, ios, text)
   contains
      subroutine close_all(did)
         integer(hid_t), intent(inout) :: did(:)
         integer :: c
         do c = 1, size(did)
            if (did(c) < 0) cycle
            call h5io_close_dataset(did(c), ios, text)
            did(c) = -1
            call keep_failure(stat, why, ios, text)
         end do
      end subroutine close_all
   end subroutine close_window

   !> Another write failed (a full disk): the file is left as at its last flush.
   subroutine results_leave(rf)
      type(results_file_t), intent(inout) :: rf     !< the results file
      rf%broken = rf%active
   end subroutine results_leave

   !> The end of a run: what waits written, the file opened (not SWMR) until results_finish.
   subroutine results_closing(rf)
      type(results_file_t), intent(inout) :: rf     !< the results file
      character(len=msg_len) :: why
      integer :: stat
      if (.not. rf%active .or. rf%fid >= 0) return
      if (.not. rf%broken) call results_flush(rf, stat, why)
      if (.not. rf%broken) call h5io_open(rf%path, .false., .false., rf%fid, stat, why)
      if (.not. rf%broken) rf%broken = stat /= 0
      if (rf%broken) rf%active = .false.            ! (nothing more is written into it)
   end subroutine results_closing

   !> Writes /summary (SI), closes the file and writes the XDMF's last XML.
   subroutine results_finish(rf, status, items, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file; inactive on return
      character(len=*), intent(in) :: status        !< 'completed', 'failed at step N', ...
      type(summary_item_t), intent(in) :: items(:)  !< the summary (result_files)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure (the first)
      character(len=msg_len) :: why
      integer :: k, ios
      stat = 0
      call results_closing(rf)
      if (rf%broken) then
         ! a write failed: more would write the file's metadata for data not there
         stat = 1
         errmsg = rf%path//': a write failed; the file is left as it was at its last flush, unfinished'
         rf%active = .false.
         return
      end if
      if (.not. rf%active) return
      why = ''
      call attr_text(rf%fid, 'summary', 'status', status, stat, why)
      summary_items: do k = 1, size(items)
         if (items(k)%key == 'status') cycle summary_items
         select case (items(k)%kind)
         case (1)
            call attr_unit(rf%fid, 'summary', items(k)%name, items(k)%si, items(k)%unit, stat, why)
         case (2)
            call attr_unit(rf%fid, 'summary', items(k)%name, nint(items(k)%si), '-', stat, why)
         case default
            call attr_text(rf%fid, 'summary', items(k)%name, items(k)%text, stat, why)
         end select
      end do summary_items
      if (stat /= 0) errmsg = rf%path//': /summary: '//trim(why)
      ios = 0
      call close_window(rf, ios, why)
      call keep_failure(stat, errmsg, ios, rf%path//': '//trim(why))
      call xdmf_close(rf%xdmf, status, ios, why)
      call keep_failure(stat, errmsg, ios, rf%xdmf%path//': '//trim(why))
      rf%active = .false.
   end subroutine results_finish

   !> The root's attributes: what wrote the file, and when.
   subroutine write_root(fid, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      character(len=8) :: date
      character(len=10) :: clock
      call date_and_time(date=date, time=clock)
      call attr_text(fid, '.', 'title', 'impact: low-velocity impact of a composite laminate (Choi, Hong & Lee 1991)', &
         stat, why)
      call attr_text(fid, '.', 'code_version', code_version, stat, why)
      call attr_text(fid, '.', 'created', date(1:4)//'-'//date(5:6)//'-'//date(7:8)//'T'//clock(1:2)//':'// &
         clock(3:4)//':'//clock(5:6), stat, why)
   end subroutine write_root

   !> /history: an empty series per history column of the run, its units and meaning.
   subroutine create_history(rf, every, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file (its history datasets on return)
      integer, intent(in) :: every                  !< &output every (steps between rows)
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      type(column_t) :: col
      integer :: c
      if (stat /= 0) return
      call h5io_group(rf%fid, 'history', stat, why)
      call attr_unit(rf%fid, 'history', 'every', every, 'steps', stat, why)
      call attr_unit(rf%fid, 'history', 'rows', 0, '-', stat, why)
      columns: do c = 1, rf%ncol
         if (stat /= 0) exit columns
         col = history_columns(c)      ! (a copy, not an associate name: see src/deck/input_deck.f90)
         call h5io_create_series(rf%fid, 'history/'//trim(col%name), &
            merge(h5io_integer, h5io_real, col%whole), 0, hist_chunk, rf%hist(c), stat, why)
         call attr_text(rf%fid, 'history/'//trim(col%name), 'units', col%unit, stat, why)
         call attr_text(rf%fid, 'history/'//trim(col%name), 'description', col%meaning, stat, why)
      end do columns
   end subroutine create_history

   !> /fields: the empty series of the snapshots, their times, steps, forces and fields.
   subroutine create_fields(rf, fields_every, nnode, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file (its snapshot datasets on return)
      integer, intent(in) :: fields_every, nnode    !< &output fields_every (steps between snapshots); nodes
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k
      if (stat /= 0) return
      call h5io_group(rf%fid, 'fields', stat, why)
      call attr_unit(rf%fid, 'fields', 'fields_every', fields_every, 'steps', stat, why)
      call attr_unit(rf%fid, 'fields', 'snapshots', 0, '-', stat, why)
      snapshot_series: do k = 1, size(rf%snaps)
         if (stat /= 0) exit snapshot_series
         call h5io_create_series(rf%fid, trim(snap_names(k)), merge(h5io_integer, h5io_real, k == 2), &
            merge(0, nnode, k <= 3), hist_chunk, rf%snaps(k), stat, why)
         call attr_text(rf%fid, trim(snap_names(k)), 'units', snap_units(k), stat, why)
      end do snapshot_series
   end subroutine create_fields

   !> /peak: the state of the step of the largest force so far (none yet: 0).
   subroutine create_peak(fid, nnode, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(in) :: nnode                  !< nodes of the mesh
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k, n
      if (stat /= 0) return
      call h5io_group(fid, 'peak', stat, why)
      call attr_unit(fid, 'peak', 'step', 0, '-', stat, why)
      call attr_unit(fid, 'peak', 'time', 0.0_dp, 's', stat, why)
      call attr_unit(fid, 'peak', 'force', 0.0_dp, 'N', stat, why)
      peak_fields: do k = 1, ndof_node
         if (stat /= 0) exit peak_fields
         call h5io_write(fid, 'peak/'//trim(freedom_name(k)), [(0.0_dp, n = 1, nnode)], stat, why)
         call attr_text(fid, 'peak/'//trim(freedom_name(k)), 'units', snap_units(3 + k), stat, why)
      end do peak_fields
   end subroutine create_peak

   !> Text attribute `name` of obj, trailing blanks removed; nothing after a failure.
   subroutine attr_text(fid, obj, name, value, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: obj, name, value   !< the object ('.': the root), attribute, text
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      if (stat == 0) call h5io_set_attr(fid, obj, name, trim(value), stat, why)
   end subroutine attr_text

   !> Attribute `name` of obj, real(dp) or integer, and `<name>_units`; nothing after a failure.
   subroutine attr_unit(fid, obj, name, value, units, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: obj, name     !< the object, the attribute
      class(*), intent(in) :: value                 !< its value
      character(len=*), intent(in) :: units         !< its unit
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      if (stat == 0) call h5io_set_attr(fid, obj, name, value, stat, why)
      if (stat == 0) call h5io_set_attr(fid, obj, name//'_units', units, stat, why)
   end subroutine attr_unit

   !> The nodal values of the freedoms, 0 where held (eq = 0).
   pure function nodal_values(eq, d) result(f)
      integer, intent(in) :: eq(:,:)   !< (ndof_node, nnode) equation numbers, 0 for held freedoms.
      real(dp), intent(in) :: d(:)   !< Values by equation.
      real(dp) :: f(size(eq, 1), size(eq, 2))
      integer :: n, k
      do n = 1, size(eq, 2)
         do k = 1, size(eq, 1)
            f(k, n) = 0.0_dp
            if (eq(k, n) > 0) f(k, n) = d(eq(k, n))
         end do
      end do
   end function nodal_values

   !> /deck: the echo, and per variable of the schema an attribute of
   !> /deck/<group> with its unit ('not given': an optional variable not given).
   subroutine write_deck(fid, deck, stat, errmsg)
      integer(hid_t), intent(in) :: fid             !< the open results file
      type(deck_t), intent(in) :: deck              !< the effective deck
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=:), allocatable :: echo, grp, name
      character(len=4096) :: line
      type(deck_t) :: copy
      type(value_t) :: v
      integer :: u, ios, ig, iv
      stat = 0
      call h5io_group(fid, 'deck', stat, errmsg)
      ! -- the echo of the deck, as the terminal and the column files show it
      echo = ''
      open (newunit=u, status='scratch', action='readwrite', form='formatted', iostat=ios)
      if (ios == 0) then
         call echo_deck(deck, u, '')
         rewind (u)
         echo_lines: do
            read (u, '(a)', iostat=ios) line
            if (ios /= 0) exit echo_lines
            echo = echo//trim(line)//new_line('a')
         end do echo_lines
         close (u)
      end if
      call attr_text(fid, 'deck', 'source', deck%source, stat, errmsg)
      if (allocated(deck%settings)) call attr_text(fid, 'deck', 'settings', deck%settings, stat, errmsg)
      call attr_text(fid, 'deck', 'echo', echo, stat, errmsg)
      do ig = 1, size(deck_groups)
         if (stat == 0) call h5io_group(fid, 'deck/'//trim(deck_groups(ig)), stat, errmsg)
      end do
      copy = deck
      variables: do iv = 1, size(deck_vars)
         if (stat /= 0) exit variables
         grp = 'deck/'//trim(deck_vars(iv)%group)
         call deck_bind(copy, iv, v, .false.)
         name = trim(deck_vars(iv)%name)
         select case (deck_vars(iv)%kind)
         case (kind_real)
            if (v%given) then
               call h5io_set_attr(fid, grp, name, v%r, stat, errmsg)
            else
               call attr_text(fid, grp, name, 'not given', stat, errmsg)
            end if
         case (kind_integer)
            call h5io_set_attr(fid, grp, name, v%i, stat, errmsg)
         case (kind_logical)
            call attr_text(fid, grp, name, trim(merge('.true. ', '.false.', v%l)), stat, errmsg)
         case (kind_word, kind_path)
            call attr_text(fid, grp, name, v%s, stat, errmsg)
         case (kind_reals)
            call h5io_set_attr(fid, grp, name, v%list, stat, errmsg)
         end select
         call attr_text(fid, grp, name//'_units', trim(deck_vars(iv)%unit), stat, errmsg)
      end do variables
   end subroutine write_deck

   !> /mesh: coordinates, connectivity, freedom map, grid and sizes.
   subroutine write_mesh(fid, msh, stat, errmsg)
      integer(hid_t), intent(in) :: fid   !< The open results file.
      type(mesh_t), intent(in) :: msh   !< The mesh with its equation numbers.
      integer, intent(out) :: stat   !< 0 on success.
      character(len=*), intent(inout) :: errmsg   !< Reason on failure.
      stat = 0
      call h5io_group(fid, 'mesh', stat, errmsg)
      call attr_text(fid, 'mesh', 'domain', msh%domain, stat, errmsg)
      call attr_unit(fid, 'mesh', 'nx', msh%nx, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'ny', msh%ny, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'nnode', msh%nnode, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'nelem', msh%nelem, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'neq', msh%neq, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'impact_node', msh%impact_node, '-', stat, errmsg)
      call attr_unit(fid, 'mesh', 'x0', msh%x0, 'm', stat, errmsg)
      call attr_unit(fid, 'mesh', 'x1', msh%x1, 'm', stat, errmsg)
      call attr_unit(fid, 'mesh', 'y0', msh%y0, 'm', stat, errmsg)
      call attr_unit(fid, 'mesh', 'y1', msh%y1, 'm', stat, errmsg)
      call attr_unit(fid, 'mesh', 'sym_factor', msh%sym_factor, '-', stat, errmsg)
      call attr_text(fid, 'mesh', 'freedoms', 'u v w psi_x psi_y', stat, errmsg)
      call attr_text(fid, 'mesh', 'node_order', '9-node Lagrange element: corners counter-clockwise from ' &
         // '(-1,-1), then mid-sides from (0,-1), then the centre (src/model/shape_functions.f90)', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/coordinates', msh%coords, stat, errmsg)
      call attr_text(fid, 'mesh/coordinates', 'units', 'm', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/connectivity', msh%conn, stat, errmsg)
      call attr_text(fid, 'mesh/connectivity', 'units', '-', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/freedom_map', msh%eq, stat, errmsg)
      call attr_text(fid, 'mesh/freedom_map', 'units', '-', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/grid', msh%grid, stat, errmsg)
      call attr_text(fid, 'mesh/grid', 'units', '-', stat, errmsg)
   end subroutine write_mesh

end module results_hdf5
