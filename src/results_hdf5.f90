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
!>                           appended and flushed row by row (see hist_name below)
!>   /fields/time, step, force  (nsnap)    snapshot times (s), steps, contact force (N)
!>   /fields/u, v, w, psi_x, psi_y  (nsnap, nnode)  nodal values (m, m, m, rad, rad),
!>                           every fields_every steps and at the last step
!>   /peak                   step, time, force: the step of the largest contact force;
!>   /peak/u, v, w, psi_x, psi_y  (nnode)  the nodal values at that step, rewritten
!>                           whenever the force passes its previous largest value
!>   /summary                status ('running' until the run ends), then the figures
!>                           of <prefix>_summary.dat in SI units
!>
!> The fields are those of the modelled domain (a quarter of the plate when
!> &mesh domain = 'quarter'); held freedoms are 0.
!>
!> A run that is killed leaves a file that opens: the datasets are chunked and
!> extendible, the file is flushed (H5Fflush) after every history row and
!> every snapshot, and /summary status stays 'running'.
!>
!> Usage (src/impact.f90): results_open after the history file is open,
!> results_append_history after every history row, results_peak after every
!> step, results_snapshot every fields_every steps, results_finish at the end
!> (also after a failure). With hdf5 = .false. they all do nothing.
module results_hdf5
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use input_deck, only: deck_t, echo_deck, path_len
   use mesh, only: mesh_t, ndof_node, freedom_name
   use output_files, only: history_row_t, run_summary_t
   use hdf5_io, only: h5io_start, h5io_create, h5io_close, h5io_flush, h5io_group, h5io_set_attr, &
      h5io_write, h5io_rewrite, h5io_create_series, h5io_create_columns, h5io_append, &
      h5io_close_dataset, h5io_real, h5io_integer
   implicit none
   private
   public :: results_file_t, results_open, results_append_history, results_snapshot, results_peak, &
             results_finish, nodal_values, code_version, nhist_real, nhist_int, hist_name, hist_units, &
             field_units

   !> code_version: 'impact <git describe>' at build time (build/code_version.inc,
   !> written by mk/hdf5.mk).
   include 'code_version.inc'

   !> History columns: the reals, then the integers, in the order of the
   !> history file's columns (src/output_files.f90), in SI units.
   integer, parameter :: nhist_real = 13, nhist_int = 3
   integer, parameter :: name_len = 20, units_len = 8, text_len = 72
   character(len=name_len), parameter :: hist_name(nhist_real + nhist_int) = [character(len=name_len) :: &
      'time', 'force', 'indentation', 'w_plate', 'w_impactor', 'v_impactor', 'strain_y_back', &
      'ke_impactor', 'ke_plate', 'strain_energy', 'contact_work', 'indentation_energy', 'energy_error', &
      'branch', 'contact_iter', 'nonlinear_iter']
   character(len=units_len), parameter :: hist_units(nhist_real + nhist_int) = [character(len=units_len) :: &
      's', 'N', 'm', 'm', 'm', 'm/s', '-', 'J', 'J', 'J', 'J', 'J', 'J', '-', '-', '-']
   character(len=text_len), parameter :: hist_text(nhist_real + nhist_int) = [character(len=text_len) :: &
      'time', 'contact force on the whole plate F', 'indentation alpha = w_impactor - w_plate, eq. (13)', &
      'plate deflection at the impact point', 'impactor displacement since first touch', &
      'impactor velocity, positive towards the plate', &
      'in-plane y strain on the back face at the gauge (Fig. 9b, 10b)', 'impactor kinetic energy', &
      'plate kinetic energy, whole plate', 'plate strain energy, whole plate', &
      'work of the contact force on the plate, int F dw_plate', &
      'int F d alpha: stored in and dissipated by the contact', &
      'E0 - (ke_impactor + ke_plate + strain_energy + indentation_energy)', &
      'contact law branch: 0 none, 1 loading, 2 unloading, 3 reloading', &
      'contact-force iterations of the step, eq. (17)', 'plate solutions of the step, eq. (19)']
   !> Units of the nodal fields u, v, w, psi_x, psi_y.
   character(len=units_len), parameter :: field_units(ndof_node) = [character(len=units_len) :: &
      'm', 'm', 'm', 'rad', 'rad']
   !> History entries per chunk: one chunk of 1 KiB per column is rewritten at each flush.
   integer, parameter :: hist_chunk = 128
   !> An open results file and the ids of its growing datasets.
   type :: results_file_t
      logical :: active = .false.                       !< a file is open (&output hdf5)
      character(len=path_len + 3) :: path = ''          !< <prefix>.h5
      integer(hid_t) :: fid = -1                        !< the file
      integer(hid_t) :: hist(nhist_real + nhist_int) = -1   !< /history/<column>
      integer(hid_t) :: snap_time = -1, snap_step = -1, snap_force = -1   !< /fields/time, step, force
      integer(hid_t) :: snap_field(ndof_node) = -1      !< /fields/u, v, w, psi_x, psi_y
      integer, allocatable :: eq(:,:)                   !< (ndof_node, nnode) equation numbers, 0 held
      real(dp) :: peak_force = 0.0_dp                   !< largest contact force so far (N)
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
      character(len=8) :: date
      character(len=10) :: clock
      integer :: c, k, ecode

      stat = 0
      if (.not. deck%hdf5) return
      rf%path = trim(deck%prefix)//'.h5'
      rf%eq = msh%eq
      why = ''
      call h5io_start(stat, why)
      if (stat == 0) call h5io_create(trim(rf%path), rf%fid, stat, why)
      if (stat /= 0) then
         errmsg = '&output: prefix = "'//trim(deck%prefix)//'": '//trim(why)
         return
      end if
      rf%active = .true.

      ! -- root: what wrote the file
      call date_and_time(date=date, time=clock)
      call put_string('.', 'title', 'impact: low-velocity impact of a composite laminate (Choi, Hong & Lee 1991)')
      call put_string('.', 'code_version', code_version)
      call put_string('.', 'created', date(1:4)//'-'//date(5:6)//'-'//date(7:8)//'T'//clock(1:2)//':'// &
         clock(3:4)//':'//clock(5:6))

      call write_deck(rf%fid, deck, stat, why)
      if (stat == 0) call write_mesh(rf%fid, msh, stat, why)

      ! -- histories: one extendible dataset per column
      if (stat == 0) call h5io_group(rf%fid, 'history', stat, why)
      if (stat == 0) call put_int('history', 'every', deck%every, 'steps')
      history_columns: do c = 1, nhist_real + nhist_int
         if (stat /= 0) exit history_columns
         call h5io_create_series(rf%fid, 'history/'//trim(hist_name(c)), &
            merge(h5io_real, h5io_integer, c <= nhist_real), hist_chunk, rf%hist(c), stat, why)
         call put_string('history/'//trim(hist_name(c)), 'units', hist_units(c))
         call put_string('history/'//trim(hist_name(c)), 'description', hist_text(c))
      end do history_columns

      ! -- field snapshots: extendible, one column of nnode values per snapshot
      if (stat == 0) call h5io_group(rf%fid, 'fields', stat, why)
      call put_int('fields', 'fields_every', deck%fields_every, 'steps')
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/time', h5io_real, 1, rf%snap_time, stat, why)
      call put_string('fields/time', 'units', 's')
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/step', h5io_integer, 1, rf%snap_step, stat, why)
      call put_string('fields/step', 'units', '-')
      if (stat == 0) call h5io_create_series(rf%fid, 'fields/force', h5io_real, 1, rf%snap_force, stat, why)
      call put_string('fields/force', 'units', 'N')
      snapshot_fields: do k = 1, ndof_node
         if (stat /= 0) exit snapshot_fields
         call h5io_create_columns(rf%fid, 'fields/'//trim(freedom_name(k)), msh%nnode, rf%snap_field(k), &
            stat, why)
         call put_string('fields/'//trim(freedom_name(k)), 'units', field_units(k))
      end do snapshot_fields

      ! -- the peak: the state of the step of the largest force so far
      if (stat == 0) call h5io_group(rf%fid, 'peak', stat, why)
      call put_int('peak', 'step', 0, '-')
      call put_real('peak', 'time', 0.0_dp, 's')
      call put_real('peak', 'force', 0.0_dp, 'N')
      peak_fields: do k = 1, ndof_node
         if (stat /= 0) exit peak_fields
         call h5io_write(rf%fid, 'peak/'//trim(freedom_name(k)), [(0.0_dp, c = 1, msh%nnode)], stat, why)
         call put_string('peak/'//trim(freedom_name(k)), 'units', field_units(k))
      end do peak_fields

      if (stat == 0) call h5io_group(rf%fid, 'summary', stat, why)
      call put_string('summary', 'status', 'running')
      if (stat == 0) call h5io_flush(rf%fid, stat, why)
      if (stat /= 0) then
         errmsg = trim(rf%path)//': '//trim(why)
         call results_finish(rf, run_summary_t(status='failed while opening'), ecode, why)
      end if

   contains

      subroutine put_string(obj, name, value)
         character(len=*), intent(in) :: obj, name, value
         if (stat == 0) call h5io_set_attr(rf%fid, obj, name, trim(value), stat, why)
      end subroutine put_string

      subroutine put_int(obj, name, value, units)
         character(len=*), intent(in) :: obj, name
         integer, intent(in) :: value
         character(len=*), intent(in) :: units
         if (stat == 0) call h5io_set_attr(rf%fid, obj, name, value, stat, why)
         if (stat == 0) call h5io_set_attr(rf%fid, obj, name//'_units', units, stat, why)
      end subroutine put_int

      subroutine put_real(obj, name, value, units)
         character(len=*), intent(in) :: obj, name
         real(dp), intent(in) :: value
         character(len=*), intent(in) :: units
         if (stat == 0) call h5io_set_attr(rf%fid, obj, name, value, stat, why)
         if (stat == 0) call h5io_set_attr(rf%fid, obj, name//'_units', units, stat, why)
      end subroutine put_real

   end subroutine results_open

   !> Appends one history row (SI units) to /history and flushes the file.
   subroutine results_append_history(rf, row, stat, errmsg)
      !> The results file.
      type(results_file_t), intent(inout) :: rf
      !> The row just written to the history file.
      type(history_row_t), intent(in) :: row
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      real(dp) :: r(nhist_real)
      integer :: i(nhist_int), c
      character(len=msg_len) :: why

      stat = 0
      if (.not. rf%active) return
      r = [row%time, row%force, row%alpha, row%w_plate, row%w_impactor, row%v_impactor, row%strain_y, &
         row%ke_impactor, row%ke_plate, row%strain_energy, row%contact_work, row%indentation_energy, &
         row%energy_error]
      i = [row%branch, row%contact_iter, row%nonlinear_iter]
      why = ''
      reals: do c = 1, nhist_real
         call h5io_append(rf%hist(c), r(c), stat, why)
         if (stat /= 0) exit reals
      end do reals
      integers: do c = 1, nhist_int
         if (stat /= 0) exit integers
         call h5io_append(rf%hist(nhist_real + c), i(c), stat, why)
      end do integers
      if (stat == 0) call h5io_flush(rf%fid, stat, why)
      if (stat /= 0) errmsg = trim(rf%path)//': /history: '//trim(why)
   end subroutine results_append_history

   !> Appends a snapshot of the nodal fields u, v, w, psi_x, psi_y to /fields
   !> and flushes the file.
   subroutine results_snapshot(rf, step, time, force, d, stat, errmsg)
      !> The results file.
      type(results_file_t), intent(inout) :: rf
      !> Time step of the state.
      integer, intent(in) :: step
      !> Time (s) and contact force (N) of the state.
      real(dp), intent(in) :: time, force
      !> Plate displacements {D} by equation.
      real(dp), intent(in) :: d(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      real(dp) :: f(ndof_node, size(rf%eq, 2))
      character(len=msg_len) :: why
      integer :: k

      stat = 0
      if (.not. rf%active) return
      why = ''
      f = nodal_values(rf%eq, d)
      call h5io_append(rf%snap_time, time, stat, why)
      if (stat == 0) call h5io_append(rf%snap_step, step, stat, why)
      if (stat == 0) call h5io_append(rf%snap_force, force, stat, why)
      fields: do k = 1, ndof_node
         if (stat /= 0) exit fields
         call h5io_append(rf%snap_field(k), f(k, :), stat, why)
      end do fields
      if (stat == 0) call h5io_flush(rf%fid, stat, why)
      if (stat /= 0) errmsg = trim(rf%path)//': /fields: '//trim(why)
   end subroutine results_snapshot

   !> Keeps in /peak the state of the step with the largest contact force:
   !> rewrites it when `force` exceeds the largest so far.
   subroutine results_peak(rf, step, time, force, d, stat, errmsg)
      !> The results file.
      type(results_file_t), intent(inout) :: rf
      !> Time step of the state.
      integer, intent(in) :: step
      !> Time (s) and contact force (N) of the state.
      real(dp), intent(in) :: time, force
      !> Plate displacements {D} by equation.
      real(dp), intent(in) :: d(:)
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      real(dp) :: f(ndof_node, size(rf%eq, 2))
      character(len=msg_len) :: why
      integer :: k

      stat = 0
      if (.not. rf%active) return
      if (.not. force > rf%peak_force) return
      rf%peak_force = force
      why = ''
      f = nodal_values(rf%eq, d)
      fields: do k = 1, ndof_node
         call h5io_rewrite(rf%fid, 'peak/'//trim(freedom_name(k)), f(k, :), stat, why)
         if (stat /= 0) exit fields
      end do fields
      if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'step', step, stat, why)
      if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'time', time, stat, why)
      if (stat == 0) call h5io_set_attr(rf%fid, 'peak', 'force', force, stat, why)
      if (stat /= 0) errmsg = trim(rf%path)//': /peak: '//trim(why)
   end subroutine results_peak

   !> Writes /summary (the figures of <prefix>_summary.dat, SI units) and
   !> closes the file. Closes what it can even after a failure.
   subroutine results_finish(rf, s, stat, errmsg)
      !> The results file; inactive on return.
      type(results_file_t), intent(inout) :: rf
      !> The run's summary.
      type(run_summary_t), intent(in) :: s
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure (the first).
      character(len=*), intent(inout) :: errmsg
      character(len=msg_len) :: why
      real(dp) :: duration
      integer :: c, k, ios

      stat = 0
      if (.not. rf%active) return
      why = ''
      duration = -1.0_dp
      if (s%first_contact_end >= 0.0_dp) duration = s%first_contact_end - s%first_contact_start
      call put_string('status', s%status)
      call put_real('peak_force', s%peak_force, 'N')
      call put_real('time_of_peak', s%time_of_peak, 's')
      call put_real('contact_duration', duration, 's')
      call put_string('contact_duration_note', 'first contact; -1 if it had not ended')
      call put_int('contacts', s%contacts, '-')
      call put_real('max_deflection', s%max_deflection, 'm')
      call put_real('max_strain_y_back', s%max_strain_y, '-')
      call put_real('permanent_indentation', s%permanent_indentation, 'm')
      call put_real('rebound_velocity', -s%final_velocity, 'm/s')
      call put_real('initial_energy', s%initial_energy, 'J')
      call put_real('max_energy_error', s%max_energy_error, 'J')
      call put_int('steps', s%steps, '-')
      call put_int('plate_solves', s%plate_solves, '-')
      call put_int('factorizations', s%factorizations, '-')
      call put_int('contact_iterations', s%contact_iterations, '-')
      call put_int('max_contact_iter', s%max_contact_iter, '-')
      call put_int('max_nonlinear_iter', s%max_nonlinear_iter, '-')
      call put_int('unconverged_steps', s%unconverged_steps, '-')
      call put_real('cpu', s%cpu_s, 's')
      if (stat /= 0) errmsg = trim(rf%path)//': /summary: '//trim(why)

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
         errmsg = trim(rf%path)//': '//trim(why)
      end if
      rf%active = .false.

   contains

      subroutine close_one(did)
         integer(hid_t), intent(inout) :: did
         if (did < 0) return
         call h5io_close_dataset(did, ios, why)
         if (ios /= 0 .and. stat == 0) then
            stat = ios
            errmsg = trim(rf%path)//': '//trim(why)
         end if
         did = -1
      end subroutine close_one

      subroutine put_string(name, value)
         character(len=*), intent(in) :: name, value
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name, trim(value), stat, why)
      end subroutine put_string

      subroutine put_int(name, value, units)
         character(len=*), intent(in) :: name
         integer, intent(in) :: value
         character(len=*), intent(in) :: units
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name, value, stat, why)
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name//'_units', units, stat, why)
      end subroutine put_int

      subroutine put_real(name, value, units)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: value
         character(len=*), intent(in) :: units
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name, value, stat, why)
         if (stat == 0) call h5io_set_attr(rf%fid, 'summary', name//'_units', units, stat, why)
      end subroutine put_real

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

   !> /deck: the echo, and one attribute per namelist variable with its unit.
   subroutine write_deck(fid, deck, stat, errmsg)
      !> The open results file.
      integer(hid_t), intent(in) :: fid
      !> The effective deck.
      type(deck_t), intent(in) :: deck
      !> 0 on success.
      integer, intent(out) :: stat
      !> Reason on failure.
      character(len=*), intent(inout) :: errmsg
      character(len=:), allocatable :: echo
      character(len=path_len) :: line
      integer :: u, ios

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
      call put_text('deck', 'echo', echo)

      call add_group('plate')
      call put_real('plate', 'a', deck%a, 'm')
      call put_real('plate', 'b', deck%b, 'm')
      call put_real('plate', 'h', deck%h, 'm')
      call add_group('lamina')
      call put_real('lamina', 'e1', deck%e1, 'Pa')
      call put_real('lamina', 'e2', deck%e2, 'Pa')
      call put_real('lamina', 'g12', deck%g12, 'Pa')
      call put_real('lamina', 'g13', deck%g13, 'Pa')
      call put_real('lamina', 'g23', deck%g23, 'Pa')
      call put_real('lamina', 'nu12', deck%nu12, '-')
      call put_real('lamina', 'rho', deck%rho, 'kg/m^3')
      call add_group('laminate')
      if (stat == 0) call h5io_set_attr(fid, 'deck/laminate', 'angles', deck%angles, stat, errmsg)
      call put_text('deck/laminate', 'angles_units', 'deg')
      call put_real('laminate', 'k4', deck%k4, '-')
      call put_real('laminate', 'k5', deck%k5, '-')
      call add_group('impactor')
      call put_real('impactor', 'mass', deck%mass, 'kg')
      call put_real('impactor', 'velocity', deck%velocity, 'm/s')
      call put_real('impactor', 'diameter', deck%diameter, 'm')
      call add_group('contact')
      call put_real('contact', 'k', deck%k, 'N/m^1.5')
      call put_real('contact', 'q', deck%q, '-')
      call put_real('contact', 'alpha_p', deck%alpha_p, 'm')
      call put_real('contact', 'beta', deck%beta, '-')
      call add_group('mesh')
      call put_int('mesh', 'nx', deck%nx)
      call put_int('mesh', 'ny', deck%ny)
      call put_word('mesh', 'domain', deck%domain)
      call put_word('mesh', 'shear_rule', deck%shear_rule)
      call put_real('mesh', 'stabilization', deck%stabilization, '-')
      call add_group('boundary')
      call put_word('boundary', 'edges', deck%edges)
      call put_word('boundary', 'inplane', deck%inplane)
      call add_group('analysis')
      call put_word('analysis', 'kind', deck%analysis_kind)
      call put_word('analysis', 'theory', deck%theory)
      call put_real('analysis', 'dt', deck%dt, 's')
      call put_real('analysis', 't_end', deck%t_end, 's')
      call put_real('analysis', 'cr1', deck%cr1, '-')
      call put_real('analysis', 'cr2', deck%cr2, '-')
      call put_word('analysis', 'scheme', deck%scheme)
      call put_word('analysis', 'storage', deck%storage)
      call put_int('analysis', 'max_contact_iter', deck%max_contact_iter)
      call put_int('analysis', 'max_nonlinear_iter', deck%max_nonlinear_iter)
      call add_group('load')
      call put_word('load', 'kind', deck%load_kind)
      call put_real('load', 'magnitude', deck%load_magnitude, &
         trim(merge('N ', 'Pa', deck%load_kind == 'central_force')))
      call put_int('load', 'increments', deck%load_increments)
      call add_group('modes')
      call put_int('modes', 'count', deck%mode_count)
      call add_group('output')
      call put_word('output', 'prefix', deck%prefix)
      call put_int('output', 'every', deck%every)
      call put_word('output', 'hdf5', trim(merge('.true. ', '.false.', deck%hdf5)))
      call put_int('output', 'fields_every', deck%fields_every)

   contains

      subroutine add_group(name)
         character(len=*), intent(in) :: name
         if (stat == 0) call h5io_group(fid, 'deck/'//name, stat, errmsg)
      end subroutine add_group

      subroutine put_text(obj, name, value)
         character(len=*), intent(in) :: obj, name, value
         if (stat == 0) call h5io_set_attr(fid, obj, name, value, stat, errmsg)
      end subroutine put_text

      !> A keyword or a path: its value, unit '-'.
      subroutine put_word(grp, name, value)
         character(len=*), intent(in) :: grp, name, value
         call put_text('deck/'//grp, name, trim(value))
         call put_text('deck/'//grp, name//'_units', '-')
      end subroutine put_word

      subroutine put_real(grp, name, value, units)
         character(len=*), intent(in) :: grp, name
         real(dp), intent(in) :: value
         character(len=*), intent(in) :: units
         if (stat == 0) call h5io_set_attr(fid, 'deck/'//grp, name, value, stat, errmsg)
         call put_text('deck/'//grp, name//'_units', units)
      end subroutine put_real

      subroutine put_int(grp, name, value)
         character(len=*), intent(in) :: grp, name
         integer, intent(in) :: value
         if (stat == 0) call h5io_set_attr(fid, 'deck/'//grp, name, value, stat, errmsg)
         call put_text('deck/'//grp, name//'_units', '-')
      end subroutine put_int

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
         'then mid-sides from (0,-1), then the centre (src/shape_functions.f90)')
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
