!> The full results of a run in one HDF5 file, <prefix>.h5, beside the column
!> files (&output hdf5 = .true., the default).
!>
!> Layout (SI units; every number carries its unit: datasets in a `units`
!> attribute, attributes in a companion attribute `<name>_units`; '-' for
!> dimensionless). Arrays are shown in C order, as h5dump and h5py show them:
!>
!>   /                       code_version, created, title
!>   /deck                   source, echo (the deck echo, every value with its unit)
!>   /deck/<group>           one attribute per namelist variable, and <variable>_units
!>   /mesh                   domain, nx, ny, nnode, nelem, neq, impact_node, sym_factor,
!>                           x0, x1, y0, y1 (extent of the modelled domain, m),
!>                           freedoms ('u v w psi_x psi_y'), node_order
!>   /mesh/coordinates       (nnode, 2)    x, y of each node (m)
!>   /mesh/connectivity      (nelem, 9)    nodes of each element, numbered from 1
!>   /mesh/freedom_map       (nnode, 5)    equation of u, v, w, psi_x, psi_y; 0 = held
!>   /mesh/grid              (2ny+1, 2nx+1) node at grid point (j, i), i along x
!>   /history/<column>       (nrow)        one extendible dataset per history column,
!>                           appended block by block (see the flushes below)
!>   /fields/time, step, force  (nsnap)    snapshot times (s), steps, contact force (N)
!>   /fields/u, v, w, psi_x, psi_y  (nsnap, nnode)  nodal values (m, m, m, rad, rad),
!>                           every fields_every steps and at the last step
!>   /peak                   step, time, force: the step of the largest contact force;
!>   /peak/u, v, w, psi_x, psi_y  (nnode)  the nodal values at that step, rewritten
!>                           whenever the force passes its previous largest value
!>   /summary                status ('running' until the run ends), then the figures
!>                           of <prefix>_summary.dat in SI units
!>   /strength               only with &strength: the damage map and the ply stresses
!>                           at the peak force, written at the end by src/results/damage_record.f90
!>                           (layout there); the history then has the columns
!>                           failure_index and failure_mode too (history_width)
!>
!>   /xdmf                   what <prefix>.xdmf (ParaView, VisIt, meshio) needs
!>                           besides: src/results/results_xdmf.f90
!>
!> The fields are those of the modelled domain (a quarter of the plate when
!> &mesh domain = 'quarter'); held freedoms are 0.
!>
!> Output that costs little and loses nothing: the history rows, the
!> snapshots and the peak state wait in memory and are written in blocks,
!> and the file is flushed (H5Fflush), by results_flush: once flush_seconds
!> of wall time have passed since the last flush (checked at every row), when
!> flush_rows rows or flush_snapshots snapshots are waiting, on a warning
!> (src/results/run_recorder.f90), and at the end, whatever the end (results_finish:
!> completed, failed, stopped by a signal). Between two flushes the library
!> is not called, so a run that is killed (SIGKILL) leaves a file that
!> opens, holds every step up to its last flush (all but the last second)
!> and says /summary status = 'running'; the datasets are chunked and
!> extendible. Writing a row costs a copy into memory; a flush of a second's
!> rows costs one write per dataset (docs/PERFORMANCE.md, "What the output
!> costs").
!>
!> Usage (src/results/run_recorder.f90): results_open after the history file is
!> open, results_append_history after every history row, results_state after
!> every step (a snapshot every fields_every steps), results_flush when the
!> file must be up to date now, results_finish at the end (also after a
!> failure). With hdf5 = .false. they all do nothing.
module results_hdf5
   use, intrinsic :: iso_fortran_env, only: int64
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use deck_schema, only: deck_t, deck_vars, deck_groups, value_t, deck_bind, strength_given, kind_real, kind_integer, &
      kind_logical, kind_word, kind_path, kind_reals
   use deck_echo, only: echo_deck
   use build_info, only: code_version
   use mesh, only: mesh_t, ndof_node, freedom_name
   use result_files, only: column_t, history_columns, nhist_strength, history_width, summary_item_t
   use hdf5_io, only: h5io_start, h5io_create, h5io_close, h5io_flush, h5io_group, h5io_set_attr, &
      h5io_write, h5io_rewrite, h5io_create_series, h5io_create_columns, h5io_append_block, &
      h5io_close_dataset, h5io_real, h5io_integer
   use results_xdmf, only: xdmf_t, xdmf_open, xdmf_snapshots, xdmf_batch_close, xdmf_peak, xdmf_close
   implicit none
   private
   public :: results_file_t, results_open, results_append_history, results_state, results_flush, results_leave, &
             results_finish, nodal_values, field_units


   integer, parameter :: units_len = 8
   !> Units of the nodal fields u, v, w, psi_x, psi_y.
   character(len=units_len), parameter :: field_units(ndof_node) = [character(len=units_len) :: &
      'm', 'm', 'm', 'rad', 'rad']
   !> History entries per chunk (1 KiB per column).
   integer, parameter :: hist_chunk = 128
   !> Wall time between two flushes (s): a killed run loses at most this.
   real(dp), parameter :: flush_seconds = 1.0_dp
   !> Rows and snapshots that may wait in memory before a flush (bounds the
   !> memory: 4096 rows of 16 numbers are 0.5 MB).
   integer, parameter :: flush_rows = 4096, flush_snapshots = 16
   !> An open results file and the ids of its growing datasets.
   type :: results_file_t
      logical :: active = .false.                       !< a file is open (&output hdf5)
      logical :: broken = .false.                       !< a write failed: the file is left as at its last flush
      character(len=:), allocatable :: path             !< <prefix>.h5
      integer(hid_t) :: fid = -1                        !< the file
      integer(hid_t) :: hist(nhist_strength) = -1       !< /history/<column> (result_files: history_columns)
      integer :: ncol = 0                               !< the run's columns (history_width)
      integer(hid_t) :: snap_time = -1, snap_step = -1, snap_force = -1   !< /fields/time, step, force
      integer(hid_t) :: snap_field(ndof_node) = -1      !< /fields/u, v, w, psi_x, psi_y
      integer, allocatable :: eq(:,:)                   !< (ndof_node, nnode) equation numbers, 0 held
      real(dp) :: peak_force = 0.0_dp                   !< largest contact force so far (N)
      type(xdmf_t) :: xdmf                              !< <prefix>.xdmf, for ParaView (src/results/results_xdmf.f90)
      !> what waits for the next flush (module header)
      integer :: nrow = 0                               !< history rows waiting
      real(dp), allocatable :: rows(:,:)                !< (ncol, flush_rows) the rows, SI
      integer :: nsnap = 0                              !< snapshots waiting
      real(dp), allocatable :: snap(:,:)                !< (3, flush_snapshots) time, step, force
      real(dp), allocatable :: snap_fields(:,:,:)       !< (ndof_node, nnode, flush_snapshots) their fields
      logical :: peak_waiting = .false.                 !< the peak below is newer than the file's
      integer :: peak_step = 0                          !< step of the largest force
      real(dp) :: peak_time = 0.0_dp                    !< its time (s)
      real(dp), allocatable :: peak_fields(:,:)         !< (ndof_node, nnode) its fields
      integer(int64) :: flushed_at = 0                  !< system_clock count of the last flush
      integer(int64) :: clock_rate = 1                  !< system_clock counts per second
   end type results_file_t

contains

   !> Creates <prefix>.h5 (when deck%hdf5) and writes the deck, the mesh, the
   !> code version and the empty growing datasets; the summary says 'running'.
   subroutine results_open(deck, msh, rf, stat, errmsg)
      !> The effective deck.
      type(deck_t), intent(in) :: deck
      !> The mesh with its equation numbers.
      type(mesh_t), intent(in) :: msh
      !> The results file, open on return when deck%hdf5.
      type(results_file_t), intent(out) :: rf
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      character(len=msg_len) :: why
      integer :: ecode

      stat = 0
      if (.not. deck%hdf5) return
      rf%path = deck%prefix//'.h5'
      rf%eq = msh%eq
      rf%ncol = history_width(strength_given(deck))
      allocate (rf%rows(rf%ncol, flush_rows), rf%snap(3, flush_snapshots), &
                rf%snap_fields(ndof_node, msh%nnode, flush_snapshots), rf%peak_fields(ndof_node, msh%nnode))
      call system_clock(rf%flushed_at, rf%clock_rate)
      why = ''
      call h5io_start(stat, why)
      if (stat == 0) call h5io_create(trim(rf%path), rf%fid, stat, why)
      if (stat /= 0) then
         errmsg = '&output: prefix = "'//trim(deck%prefix)//'": '//trim(why)
         return
      end if
      rf%active = .true.

      call write_root(rf%fid, stat, why)
      if (stat == 0) call write_deck(rf%fid, deck, stat, why)
      if (stat == 0) call write_mesh(rf%fid, msh, stat, why)
      call create_history(rf, deck%every, stat, why)
      call create_fields(rf, deck%fields_every, msh%nnode, stat, why)
      call create_peak(rf%fid, msh%nnode, stat, why)
      if (stat == 0) call h5io_group(rf%fid, 'summary', stat, why)
      call attr_text(rf%fid, 'summary', 'status', 'running', stat, why)
      if (stat == 0) call xdmf_open(rf%xdmf, deck, msh, rf%fid, stat, why)
      if (stat == 0) call h5io_flush(rf%fid, stat, why)
      if (stat /= 0) then
         errmsg = rf%path//': '//trim(why)
         rf%broken = .true.
         call results_finish(rf, 'failed while opening', [summary_item_t ::], ecode, why)
      end if
   end subroutine results_open

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

   !> /history: one empty extendible dataset per history column of the run,
   !> with its units and meaning.
   subroutine create_history(rf, every, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file (its history datasets on return)
      integer, intent(in) :: every                  !< &output every (steps between rows)
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      type(column_t) :: col
      integer :: c

      if (stat /= 0) return
      call h5io_group(rf%fid, 'history', stat, why)
      call attr_int(rf%fid, 'history', 'every', every, 'steps', stat, why)
      columns: do c = 1, rf%ncol
         if (stat /= 0) exit columns
         col = history_columns(c)      ! (a copy, not an associate name: see src/deck/input_deck.f90)
         call h5io_create_series(rf%fid, 'history/'//trim(col%name), &
            merge(h5io_integer, h5io_real, col%whole), hist_chunk, rf%hist(c), stat, why)
         call attr_text(rf%fid, 'history/'//trim(col%name), 'units', col%unit, stat, why)
         call attr_text(rf%fid, 'history/'//trim(col%name), 'description', col%meaning, stat, why)
      end do columns
   end subroutine create_history

   !> /fields: the empty extendible datasets of the snapshots, their times,
   !> steps and forces, and one column of nnode values per snapshot of each
   !> nodal field.
   subroutine create_fields(rf, fields_every, nnode, stat, why)
      type(results_file_t), intent(inout) :: rf     !< the results file (its snapshot datasets on return)
      integer, intent(in) :: fields_every           !< &output fields_every (steps between snapshots)
      integer, intent(in) :: nnode                  !< nodes of the mesh
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k

      if (stat /= 0) return
      call h5io_group(rf%fid, 'fields', stat, why)
      call attr_int(rf%fid, 'fields', 'fields_every', fields_every, 'steps', stat, why)
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/time', h5io_real, 1, rf%snap_time, stat, why)
      call attr_text(rf%fid, 'fields/time', 'units', 's', stat, why)
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/step', h5io_integer, 1, rf%snap_step, stat, why)
      call attr_text(rf%fid, 'fields/step', 'units', '-', stat, why)
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/force', h5io_real, 1, rf%snap_force, stat, why)
      call attr_text(rf%fid, 'fields/force', 'units', 'N', stat, why)
      snapshot_fields: do k = 1, ndof_node
         if (stat /= 0) exit snapshot_fields
         call h5io_create_columns(rf%fid, 'fields/'//trim(freedom_name(k)), nnode, rf%snap_field(k), stat, why)
         call attr_text(rf%fid, 'fields/'//trim(freedom_name(k)), 'units', field_units(k), stat, why)
      end do snapshot_fields
   end subroutine create_fields

   !> /peak: the state of the step of the largest force so far, none yet
   !> (step 0, time 0, force 0, the nodal fields 0).
   subroutine create_peak(fid, nnode, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(in) :: nnode                  !< nodes of the mesh
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      integer :: k, n

      if (stat /= 0) return
      call h5io_group(fid, 'peak', stat, why)
      call attr_int(fid, 'peak', 'step', 0, '-', stat, why)
      call attr_real(fid, 'peak', 'time', 0.0_dp, 's', stat, why)
      call attr_real(fid, 'peak', 'force', 0.0_dp, 'N', stat, why)
      peak_fields: do k = 1, ndof_node
         if (stat /= 0) exit peak_fields
         call h5io_write(fid, 'peak/'//trim(freedom_name(k)), [(0.0_dp, n = 1, nnode)], stat, why)
         call attr_text(fid, 'peak/'//trim(freedom_name(k)), 'units', field_units(k), stat, why)
      end do peak_fields
   end subroutine create_peak

   !> Attribute `name` of obj, the text value without its trailing blanks;
   !> nothing after an earlier failure.
   subroutine attr_text(fid, obj, name, value, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: obj           !< the object ('.' for the root)
      character(len=*), intent(in) :: name          !< the attribute
      character(len=*), intent(in) :: value         !< its text
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      if (stat == 0) call h5io_set_attr(fid, obj, name, trim(value), stat, why)
   end subroutine attr_text

   !> Integer attribute `name` of obj and its unit in `<name>_units`;
   !> nothing after an earlier failure.
   subroutine attr_int(fid, obj, name, value, units, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: obj           !< the object
      character(len=*), intent(in) :: name          !< the attribute
      integer, intent(in) :: value                  !< its value
      character(len=*), intent(in) :: units         !< its unit
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      if (stat == 0) call h5io_set_attr(fid, obj, name, value, stat, why)
      if (stat == 0) call h5io_set_attr(fid, obj, name//'_units', units, stat, why)
   end subroutine attr_int

   !> Real attribute `name` of obj and its unit in `<name>_units`; nothing
   !> after an earlier failure.
   subroutine attr_real(fid, obj, name, value, units, stat, why)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: obj           !< the object
      character(len=*), intent(in) :: name          !< the attribute
      real(dp), intent(in) :: value                 !< its value
      character(len=*), intent(in) :: units         !< its unit
      integer, intent(inout) :: stat                !< 0 on success; nothing is written after a failure
      character(len=*), intent(inout) :: why        !< reason on failure
      if (stat == 0) call h5io_set_attr(fid, obj, name, value, stat, why)
      if (stat == 0) call h5io_set_attr(fid, obj, name//'_units', units, stat, why)
   end subroutine attr_real

   !> Appends one history row (SI units, in the order of history_columns)
   !> to /history: it waits in memory for the next flush (module header),
   !> which this call makes when it is due.
   subroutine results_append_history(rf, row, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      real(dp), intent(in) :: row(:)                !< the row just written to the history file, SI (rf%ncol)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer(int64) :: now
      stat = 0
      if (.not. rf%active) return
      rf%nrow = rf%nrow + 1
      rf%rows(:, rf%nrow) = row
      call system_clock(now)
      if (rf%nrow == flush_rows .or. real(now - rf%flushed_at, dp) >= flush_seconds*real(rf%clock_rate, dp)) &
         call results_flush(rf, stat, errmsg)
   end subroutine results_append_history

   !> The nodal fields u, v, w, psi_x, psi_y of the state at the end of a
   !> step: a snapshot for /fields when `snapshot` is true, and the state of
   !> /peak when the contact force exceeds the largest so far; both wait in
   !> memory for the next flush.
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
         if (rf%nsnap == flush_snapshots) call results_flush(rf, stat, errmsg)
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

   !> Writes what waits in memory (history rows, snapshots, the peak) and
   !> flushes the file (H5Fflush): on return the file on disk holds every
   !> row given so far.
   subroutine results_flush(rf, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=msg_len) :: why
      character(len=:), allocatable :: part
      integer :: c, k
      logical :: batch

      stat = 0
      if (.not. rf%active) return
      why = ''
      batch = rf%nsnap > 0
      ! a failure ends the flush; the message names the part being written
      parts: block
         part = '/history: '
         columns: do c = 1, rf%ncol
            if (rf%nrow == 0 .or. stat /= 0) exit columns
            if (history_columns(c)%whole) then
               call h5io_append_block(rf%hist(c), nint(rf%rows(c, :rf%nrow)), stat, why)
            else
               call h5io_append_block(rf%hist(c), rf%rows(c, :rf%nrow), stat, why)
            end if
         end do columns
         if (stat /= 0) exit parts
         rf%nrow = 0
         if (rf%nsnap > 0) then
            part = '/fields: '
            call h5io_append_block(rf%snap_time, rf%snap(1, :rf%nsnap), stat, why)
            if (stat == 0) call h5io_append_block(rf%snap_step, nint(rf%snap(2, :rf%nsnap)), stat, why)
            if (stat == 0) call h5io_append_block(rf%snap_force, rf%snap(3, :rf%nsnap), stat, why)
            fields: do k = 1, ndof_node
               if (stat /= 0) exit fields
               call h5io_append_block(rf%snap_field(k), rf%snap_fields(k, :, :rf%nsnap), stat, why)
            end do fields
            if (stat == 0) call xdmf_snapshots(rf%xdmf, rf%fid, nint(rf%snap(2, :rf%nsnap)), rf%snap(1, :rf%nsnap), &
               rf%snap(3, :rf%nsnap), rf%snap_fields(:, :, :rf%nsnap), stat, why)
            if (stat /= 0) exit parts
            rf%nsnap = 0
         end if
         if (rf%peak_waiting) then
            part = '/peak: '
            peak_fields: do k = 1, ndof_node
               call h5io_rewrite(rf%fid, 'peak/'//trim(freedom_name(k)), rf%peak_fields(k, :), stat, why)
               if (stat /= 0) exit peak_fields
            end do peak_fields
            if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'step', rf%peak_step, stat, why)
            if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'time', rf%peak_time, stat, why)
            if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'force', rf%peak_force, stat, why)
            if (stat == 0) call xdmf_peak(rf%xdmf, rf%fid, rf%peak_fields, stat, why)
            if (stat /= 0) exit parts
            rf%peak_waiting = .false.
         end if
         part = ''
         call h5io_flush(rf%fid, stat, why)
         ! the XML last, naming only what this flush has written (src/results/results_xdmf.f90)
         if (stat == 0 .and. batch) call xdmf_batch_close(rf%xdmf, rf%fid, stat, why)
         call system_clock(rf%flushed_at)
      end block parts
      if (stat /= 0) errmsg = rf%path//': '//part//trim(why)
      rf%broken = stat /= 0
   end subroutine results_flush

   !> Another of the run's writes failed (the history: a full disk, the
   !> file-size limit): the file is written no more and left as it was at its
   !> last flush, which opens; writing the summary into it now could leave
   !> its metadata half written.
   subroutine results_leave(rf)
      type(results_file_t), intent(inout) :: rf     !< the results file
      rf%broken = rf%active
   end subroutine results_leave

   !> Writes /summary (the items of <prefix>_summary.dat, SI units, and the
   !> status) and closes the file. Closes what it can even after a failure.
   subroutine results_finish(rf, status, items, stat, errmsg)
      type(results_file_t), intent(inout) :: rf     !< the results file; inactive on return
      character(len=*), intent(in) :: status        !< 'completed', 'failed at step N', ...
      type(summary_item_t), intent(in) :: items(:)  !< the summary (result_files)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure (the first)
      character(len=msg_len) :: why
      integer :: c, k, ios

      stat = 0
      if (.not. rf%active) return
      if (.not. rf%broken) call results_flush(rf, stat, errmsg)      ! what waits, whatever the end
      if (rf%broken) then
         ! a write failed (a full disk, the file-size limit): writing more, even
         ! closing, would rewrite the file's metadata for data that is not there;
         ! left alone it opens as it was at its last flush
         stat = 1
         errmsg = rf%path//': a write failed; the file is left as it was at its last flush, unfinished'
         rf%active = .false.
         return
      end if
      why = ''
      call put_string('status', status)
      summary_items: do k = 1, size(items)
         if (items(k)%key == 'status') cycle summary_items
         select case (items(k)%kind)
         case (1)
            if (stat == 0) call h5io_set_attr(rf%fid, 'summary', items(k)%name, items(k)%si, stat, why)
            if (stat == 0) call h5io_set_attr(rf%fid, 'summary', items(k)%name//'_units', items(k)%unit, stat, why)
         case (2)
            if (stat == 0) call h5io_set_attr(rf%fid, 'summary', items(k)%name, nint(items(k)%si), stat, why)
            if (stat == 0) call h5io_set_attr(rf%fid, 'summary', items(k)%name//'_units', '-', stat, why)
         case default
            call put_string(items(k)%name, items(k)%text)
         end select
      end do summary_items
      if (stat /= 0) errmsg = rf%path//': /summary: '//trim(why)
      call xdmf_close(rf%xdmf, rf%fid, status, ios, why)
      if (ios /= 0 .and. stat == 0) then
         stat = ios
         errmsg = rf%xdmf%path//': '//trim(why)
      end if

      ! -- close everything, keeping the first failure
      do c = 1, size(rf%hist)
         call close_one(rf%hist(c))
      end do
      call close_one(rf%snap_time)
      call close_one(rf%snap_step)
      call close_one(rf%snap_force)
      do k = 1, ndof_node
         call close_one(rf%snap_field(k))
      end do
      call h5io_close(rf%fid, ios, why)
      if (ios /= 0 .and. stat == 0) then
         stat = ios
         errmsg = rf%path//': '//trim(why)
      end if
      rf%active = .false.

   contains

      subroutine close_one(did)
         integer(hid_t), intent(inout) :: did
         if (did < 0) return
         call h5io_close_dataset(did, ios, why)
         if (ios /= 0 .and. stat == 0) then
            stat = ios
            errmsg = rf%path//': '//trim(why)
         end if
         did = -1
      end subroutine close_one

      subroutine put_string(name, value)
         character(len=*), intent(in) :: name, value
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name, trim(value), stat, why)
      end subroutine put_string

   end subroutine results_finish

   !> The nodal values of the freedoms: f(k, n) = d(eq(k, n)), 0 where the
   !> freedom is held (eq = 0).
   pure function nodal_values(eq, d) result(f)
      !> (ndof_node, nnode) equation numbers, 0 for held freedoms.
      integer, intent(in) :: eq(:,:)
      !> Values by equation.
      real(dp), intent(in) :: d(:)
      real(dp) :: f(size(eq, 1), size(eq, 2))
      integer :: n, k
      do n = 1, size(eq, 2)
         do k = 1, size(eq, 1)
            f(k, n) = 0.0_dp
            if (eq(k, n) > 0) f(k, n) = d(eq(k, n))
         end do
      end do
   end function nodal_values

   ! ------------------------------------------------------------ deck, mesh

   !> /deck: the echo, and one attribute per variable of the schema
   !> (src/deck/deck_schema.f90) in /deck/<group>, with its unit in <name>_units;
   !> an optional variable not given is the text 'not given'.
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
      call put_text('deck', 'source', deck%source)
      if (allocated(deck%settings)) call put_text('deck', 'settings', deck%settings)
      call put_text('deck', 'echo', echo)
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
               call put_text(grp, name, 'not given')
            end if
         case (kind_integer)
            call h5io_set_attr(fid, grp, name, v%i, stat, errmsg)
         case (kind_logical)
            call put_text(grp, name, trim(merge('.true. ', '.false.', v%l)))
         case (kind_word, kind_path)
            call put_text(grp, name, v%s)
         case (kind_reals)
            call h5io_set_attr(fid, grp, name, v%list, stat, errmsg)
         end select
         call put_text(grp, name//'_units', trim(deck_vars(iv)%unit))
      end do variables

   contains

      subroutine put_text(obj, name, value)
         character(len=*), intent(in) :: obj, name, value
         if (stat == 0) call h5io_set_attr(fid, obj, name, value, stat, errmsg)
      end subroutine put_text

   end subroutine write_deck

   !> /mesh: coordinates, connectivity, freedom map, grid and sizes.
   subroutine write_mesh(fid, msh, stat, errmsg)
      !> The open results file.
      integer(hid_t), intent(in) :: fid
      !> The mesh with its equation numbers.
      type(mesh_t), intent(in) :: msh
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg

      stat = 0
      call h5io_group(fid, 'mesh', stat, errmsg)
      call put_text('domain', msh%domain)
      call put_count('nx', msh%nx)
      call put_count('ny', msh%ny)
      call put_count('nnode', msh%nnode)
      call put_count('nelem', msh%nelem)
      call put_count('neq', msh%neq)
      call put_count('impact_node', msh%impact_node)
      call put_length('x0', msh%x0)
      call put_length('x1', msh%x1)
      call put_length('y0', msh%y0)
      call put_length('y1', msh%y1)
      if (stat == 0) call h5io_set_attr(fid, 'mesh', 'sym_factor', msh%sym_factor, stat, errmsg)
      call put_text('sym_factor_units', '-')
      call put_text('freedoms', 'u v w psi_x psi_y')
      call put_text('node_order', '9-node Lagrange element: corners counter-clockwise from (-1,-1), '// &
         'then mid-sides from (0,-1), then the centre (src/model/shape_functions.f90)')
      if (stat == 0) call h5io_write(fid, 'mesh/coordinates', msh%coords, stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'mesh/coordinates', 'units', 'm', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/connectivity', msh%conn, stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'mesh/connectivity', 'units', '-', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/freedom_map', msh%eq, stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'mesh/freedom_map', 'units', '-', stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'mesh/grid', msh%grid, stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'mesh/grid', 'units', '-', stat, errmsg)

   contains

      subroutine put_text(name, value)
         character(len=*), intent(in) :: name, value
         if (stat == 0) call h5io_set_attr(fid, 'mesh', name, trim(value), stat, errmsg)
      end subroutine put_text

      subroutine put_count(name, value)
         character(len=*), intent(in) :: name
         integer, intent(in) :: value
         if (stat == 0) call h5io_set_attr(fid, 'mesh', name, value, stat, errmsg)
         call put_text(name//'_units', '-')
      end subroutine put_count

      subroutine put_length(name, value)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         if (stat == 0) call h5io_set_attr(fid, 'mesh', name, value, stat, errmsg)
         call put_text(name//'_units', 'm')
      end subroutine put_length

   end subroutine write_mesh

end module results_hdf5
