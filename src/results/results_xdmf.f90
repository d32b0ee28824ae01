!> <prefix>.xdmf beside <prefix>.h5: an XDMF 3 description of the results
!> file's mesh and nodal fields, so that ParaView, VisIt and meshio open a
!> run (README, "Looking at the fields"). The XML holds no numbers of its
!> own: every array is a dataset of <prefix>.h5, named by its path.
!>
!>   mesh        9-node quadrilaterals (XDMF Quadrilateral_9, VTK's
!>               biquadratic quad: the node order of src/model/shape_functions.f90,
!>               corners counter-clockwise, mid-sides, centre), points x, y (m)
!>   time steps  one per snapshot of /fields (Temporal collection, time in
!>               s): the nodal fields u, v, w (m), psi_x, psi_y (rad), and
!>               peak_u ... peak_psi_y, the state of the step of the largest
!>               contact force so far (/peak)
!>   plies       with &strength, at the end of the run: the damage map and
!>               the ply stresses at the peak force on a grid of the
!>               laminate, a temporal collection before the fields' one
!>               (src/results/xdmf_plies.f90, written into /xdmf/plies)
!>
!> What XDMF readers need that <prefix>.h5 did not have, in its group /xdmf:
!>
!>   /xdmf/cells          (nelem, 9)   element nodes numbered from 0 (XDMF
!>                                     counts from 0, /mesh/connectivity from 1)
!>   /xdmf/fields/<b>/<f>/<k> (nnode)  field f of snapshot k: a virtual dataset
!>                                     (HDF5 1.10) showing row k of /fields/<f>,
!>                                     no copy; readers see a plain dataset. b
!>                                     numbers the batch of snapshots the
!>                                     results file wrote in one flush
!>                                     (src/results/results_hdf5.f90): a group that is
!>                                     complete before the XML names it and
!>                                     never changed after
!>
!> Debian 12's ParaView (5.11) does not apply the XDMF hyperslabs and
!> functions of an Attribute, and meshio reads only whole datasets; a plain
!> dataset per snapshot is what every reader takes, hence the views.
!>
!> &output xdmf = 'whole' mirrors a quarter or half into the whole
!> plate (about x = 0 and y = 0, src/model/mesh.f90): u, psi_x change sign across
!> x = 0 and v, psi_y across y = 0, which no view can do, so the whole
!> plate's fields are written as data: /xdmf/coordinates (nnode_whole, 2),
!> /xdmf/cells, /xdmf/fields/<b>/<f>/<k> and /xdmf/peak/<f>, about 4 (quarter)
!> or 2 (half) times the modelled fields. Nodes on the symmetry lines are
!> shared, elements keep the counter-clockwise order. &output xdmf = 'none'
!> writes neither the XML nor /xdmf.
!>
!> Cost: a view is an HDF5 object, made when its batch is flushed (once a
!> second, src/results/results_hdf5.f90); the views are nothing at the default
!> fields_every and the largest part of the output of a small run with a
!> snapshot every step (README, "Looking at the fields").
!>
!> As the run goes: after a batch of snapshots the HDF5 file is flushed and
!> the XML is written to <prefix>.xdmf.tmp and renamed over <prefix>.xdmf
!> (one step: a reader sees the old file or the new one), after the first
!> batch and then at most once per xdmf_rewrite_interval of wall-clock time
!> (the XML grows with every snapshot; rewriting it each time would cost the
!> square of their number), and at the end. A killed run's XDMF opens, with
!> the snapshots up to its last rewrite and status 'running': the views it
!> names sit in batch groups that later writes leave alone. (A kill while
!> HDF5 flushes can still leave the file's newest structures half written:
!> one link of /xdmf/fields per batch, the growing datasets' chunk indices;
!> before the batches, every view was a link of one shared group per field,
!> rewritten 500 times a second by a fast run, and 1 killed run in 10 left
!> an XDMF that ParaView could not open.) (A run still
!> going: HDF5 1.10 does not let another process read the file it writes,
!> outside SWMR mode, which allows no new object once started.)
!>
!> Usage (src/results/results_hdf5.f90): xdmf_open after /mesh is written; for each
!> batch of snapshots appended to /fields, xdmf_snapshots, then
!> xdmf_batch_close; xdmf_peak after /peak is rewritten;
!> xdmf_close before the file is closed.
module results_xdmf
   use, intrinsic :: iso_fortran_env, only: int64
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_str
   use deck_schema, only: deck_t
   use mesh, only: mesh_t, ndof_node, freedom_name
   use shape_functions, only: nen
   use hdf5_io, only: h5io_group, h5io_write, h5io_rewrite, h5io_view_column, h5io_flush, h5io_set_attr
   use file_system, only: rename_file
   use xdmf_plies, only: xdmf_plies_t, plies_collection
   implicit none
   private
   public :: xdmf_t, xdmf_open, xdmf_snapshots, xdmf_batch_close, xdmf_peak, xdmf_close

   !> Longest number as text (src/system/number_text.f90, real_str).
   integer, parameter :: text_len = 32
   !> Least wall-clock time between two rewrites of the XML during a run (s).
   real(dp), parameter :: xdmf_rewrite_interval = 1.0_dp
   !> Fields odd across x = 0 (u, psi_x) and across y = 0 (v, psi_y), by freedom.
   logical, parameter :: odd_in_x(ndof_node) = [.true., .false., .false., .true., .false.]
   logical, parameter :: odd_in_y(ndof_node) = [.false., .true., .false., .false., .true.]
   !> Nodes of a 9-node element as (i, j) offsets on the grid from its
   !> corner (i, j) of lowest indices: corners counter-clockwise, mid-sides,
   !> centre (src/model/shape_functions.f90).
   integer, parameter :: element_di(nen) = [0, 2, 2, 0, 1, 2, 1, 0, 1]
   integer, parameter :: element_dj(nen) = [0, 0, 2, 2, 0, 1, 2, 1, 1]

   !> The XDMF file of a results file.
   type :: xdmf_t
      logical :: active = .false.                   !< <prefix>.xdmf is being written
      logical :: whole = .false.                    !< the mirrored whole plate (else the modelled domain)
      character(len=:), allocatable :: path         !< <prefix>.xdmf
      character(len=:), allocatable :: h5_name      !< <prefix>.h5 as the XML names it: its file name
      character(len=:), allocatable :: status       !< 'running', then the run's status
      integer :: nnode = 0, nelem = 0               !< nodes and elements shown
      integer :: nsnap = 0                          !< snapshots so far
      character(len=text_len), allocatable :: time(:), force(:)  !< of each snapshot (s, N), as the XML gives them
      integer, allocatable :: step(:)               !< of each snapshot
      integer, allocatable :: batch(:)              !< of each snapshot: its group /xdmf/fields/<batch>
      integer :: nbatch = 0                         !< batches so far
      integer, allocatable :: source(:)             !< whole: the modelled node of each node shown
      real(dp), allocatable :: parity(:,:)          !< whole: (ndof_node, nnode) sign of each field there
      integer(int64) :: written_at = 0              !< system_clock count of the last rewrite
      type(xdmf_plies_t) :: plies                   !< with &strength, the laminate's ply fields (src/results/xdmf_plies.f90)
   end type xdmf_t

contains

   !> Starts <prefix>.xdmf for the results file fid (open, /mesh written):
   !> /xdmf (the cells numbered from 0; the whole plate's mesh and peak when
   !> &output xdmf = 'whole') and the XML without a snapshot; nothing for
   !> xdmf = 'none'.
   subroutine xdmf_open(x, deck, msh, fid, stat, errmsg)
      type(xdmf_t), intent(out) :: x                !< the XDMF file, active on return
      type(deck_t), intent(in) :: deck              !< the effective deck (prefix, xdmf)
      type(mesh_t), intent(in) :: msh               !< the modelled mesh
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: xy(:,:)
      integer, allocatable :: cells(:,:)
      integer :: slash, k, n

      stat = 0
      if (deck%xdmf == 'none') return
      x%path = deck%prefix // '.xdmf'
      slash = index(deck%prefix, '/', back=.true.)
      x%h5_name = deck%prefix(slash + 1:) // '.h5'
      x%status = 'running'
      x%whole = deck%xdmf == 'whole' .and. (msh%sym_x .or. msh%sym_y)
      allocate (x%time(0), x%force(0), x%step(0), x%batch(0))
      call system_clock(x%written_at)

      call h5io_group(fid, 'xdmf', stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'xdmf', 'domain', trim(merge('whole   ', 'modelled', x%whole)), &
         stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'xdmf', 'description', 'what ' // x%h5_name(:len(x%h5_name) - 3) &
         // '.xdmf shows (src/results/results_xdmf.f90): cells numbered from 0, fields/<b>/<f>/<k>: field f of ' &
         // 'snapshot k, written in batch b', stat, errmsg)
      if (stat == 0) call h5io_group(fid, 'xdmf/fields', stat, errmsg)
      if (stat /= 0) return
      if (x%whole) then
         call whole_plate(msh, xy, cells, x%source, x%parity)
         x%nnode = size(xy, 2)
         x%nelem = size(cells, 2)
         call h5io_write(fid, 'xdmf/coordinates', xy, stat, errmsg)
         if (stat == 0) call h5io_group(fid, 'xdmf/peak', stat, errmsg)
         do k = 1, ndof_node
            if (stat == 0) call h5io_write(fid, 'xdmf/peak/' // trim(freedom_name(k)), &
               [(0.0_dp, n = 1, x%nnode)], stat, errmsg)
         end do
      else
         x%nnode = msh%nnode
         x%nelem = msh%nelem
         cells = msh%conn
      end if
      if (stat == 0) call h5io_write(fid, 'xdmf/cells', cells - 1, stat, errmsg)
      if (stat /= 0) return
      x%active = .true.
      call write_xml(x, fid, stat, errmsg)
   end subroutine xdmf_open

   !> A batch of snapshots, just appended to /fields: the group
   !> /xdmf/fields/<b>, its groups of the fields, and each snapshot's views
   !> (or, for the whole plate, its mirrored fields).
   subroutine xdmf_snapshots(x, fid, step, time, force, f, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(in) :: step(:)                !< each snapshot's time step
      real(dp), intent(in) :: time(:), force(:)     !< their times (s) and contact forces (N)
      real(dp), intent(in) :: f(:,:,:)              !< (ndof_node, nnode, snapshot) their nodal values, modelled domain
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer :: k, j
      stat = 0
      if (.not. x%active) return
      x%nbatch = x%nbatch + 1
      call h5io_group(fid, batch_group(x%nbatch), stat, errmsg)
      do k = 1, ndof_node
         if (stat == 0) call h5io_group(fid, batch_group(x%nbatch) // '/' // trim(freedom_name(k)), stat, errmsg)
      end do
      snapshots: do j = 1, size(step)
         if (stat /= 0) exit snapshots
         call add_snapshot(x, fid, step(j), time(j), force(j), f(:, :, j), stat, errmsg)
      end do snapshots
   end subroutine xdmf_snapshots

   !> Ends a batch: the XML rewritten when due (module header).
   subroutine xdmf_batch_close(x, fid, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer(int64) :: now, rate
      stat = 0
      if (.not. x%active) return
      call system_clock(now, rate)
      if (x%nbatch == 1 .or. real(now - x%written_at, dp) >= xdmf_rewrite_interval*real(rate, dp)) &
         call write_xml(x, fid, stat, errmsg)
   end subroutine xdmf_batch_close

   !> Snapshot number x%nsnap + 1, just appended to /fields, in the open
   !> batch b: its views (or, for the whole plate, its mirrored fields)
   !> /xdmf/fields/<b>/<f>/<k>.
   subroutine add_snapshot(x, fid, step, time, force, f, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< the open results file
      integer, intent(in) :: step                   !< the snapshot's time step
      real(dp), intent(in) :: time, force           !< its time (s) and contact force (N)
      real(dp), intent(in) :: f(:,:)                !< (ndof_node, nnode) its nodal values, modelled domain
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer :: k

      stat = 0
      x%nsnap = x%nsnap + 1
      x%time = [x%time, real_str(time)]
      x%force = [x%force, real_str(force)]
      x%step = [x%step, step]
      x%batch = [x%batch, x%nbatch]
      fields: do k = 1, ndof_node
         if (stat /= 0) exit fields
         if (x%whole) then
            call h5io_write(fid, view_path(x, k, x%nsnap), x%parity(k, :)*f(k, x%source), stat, errmsg)
         else
            call h5io_view_column(fid, view_path(x, k, x%nsnap), 'fields/' // trim(freedom_name(k)), size(f, 2), &
               x%nsnap, stat, errmsg)
         end if
      end do fields
   end subroutine add_snapshot

   !> The group of batch b.
   pure function batch_group(b) result(path)
      integer, intent(in) :: b                      !< batch number
      character(len=:), allocatable :: path
      path = 'xdmf/fields/' // int_str(b)
   end function batch_group

   !> Where field k of snapshot s is: /xdmf/fields/<b>/<f>/<s>.
   pure function view_path(x, k, s) result(path)
      type(xdmf_t), intent(in) :: x                 !< the XDMF file
      integer, intent(in) :: k, s                   !< freedom, snapshot
      character(len=:), allocatable :: path
      path = batch_group(x%batch(s)) // '/' // trim(freedom_name(k)) // '/' // int_str(s)
   end function view_path

   !> The peak state just rewritten in /peak: for the whole plate, mirrored
   !> into /xdmf/peak (the modelled domain's XML shows /peak itself).
   subroutine xdmf_peak(x, fid, f, stat, errmsg)
      type(xdmf_t), intent(in) :: x                 !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< the open results file
      real(dp), intent(in) :: f(:,:)                !< (ndof_node, nnode) the peak's nodal values, modelled domain
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer :: k
      stat = 0
      if (.not. (x%active .and. x%whole)) return
      do k = 1, ndof_node
         if (stat == 0) call h5io_rewrite(fid, 'xdmf/peak/' // trim(freedom_name(k)), &
            x%parity(k, :)*f(k, x%source), stat, errmsg)
      end do
   end subroutine xdmf_peak

   !> The last XML, with every snapshot and the run's status; x inactive after.
   subroutine xdmf_close(x, fid, status, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: status        !< the run's status ('completed', 'failed at step N', ...)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 0
      if (.not. x%active) return
      x%status = status
      call write_xml(x, fid, stat, errmsg)
      x%active = .false.
   end subroutine xdmf_close

   ! ============================================================== the XML

   !> Flushes the results file, writes the XML to <prefix>.xdmf.tmp and
   !> renames it over <prefix>.xdmf.
   subroutine write_xml(x, fid, stat, errmsg)
      type(xdmf_t), intent(inout) :: x
      integer(hid_t), intent(in) :: fid
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: tmp, h5, mesh_points, peak
      integer :: u, k, s

      call h5io_flush(fid, stat, errmsg)
      if (stat /= 0) return
      h5 = xml_escaped(x%h5_name) // ':/'
      mesh_points = 'mesh/coordinates'
      peak = 'peak/'
      if (x%whole) then
         mesh_points = 'xdmf/coordinates'
         peak = 'xdmf/peak/'
      end if
      tmp = x%path // '.tmp'
      open (newunit=u, file=tmp, status='replace', action='write', form='formatted', iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = 'cannot write ' // tmp // ': ' // trim(iomsg)
         return
      end if
      write (u, '(a)') '<?xml version="1.0" encoding="UTF-8"?>'
      write (u, '(a)') '<!-- impact: the mesh and nodal fields of ' // xml_escaped(x%h5_name) // ' (XDMF 3, for ' &
         // 'ParaView, VisIt, meshio; src/results/results_xdmf.f90). SI units: x, y, u, v, w in m, psi_x, psi_y in rad, ' &
         // 'time in s; peak_*: the state of the step of the largest contact force so far. -->'
      write (u, '(a)') '<Xdmf Version="3.0" xmlns:xi="http://www.w3.org/2001/XInclude">'
      write (u, '(a)') '  <Domain>'
      write (u, '(a)') '    <Information Name="status" Value="' // xml_escaped(x%status) // '"/>'
      write (u, '(a)') '    <Grid Name="mesh" GridType="Uniform">'
      write (u, '(a)') '      <Topology TopologyType="Quadrilateral_9" NumberOfElements="' // int_str(x%nelem) // '">'
      write (u, '(a)') '        ' // data_item('Int', 4, int_str(x%nelem) // ' ' // int_str(nen), h5 // 'xdmf/cells')
      write (u, '(a)') '      </Topology>'
      write (u, '(a)') '      <Geometry GeometryType="XY">'
      write (u, '(a)') '        ' // data_item('Float', 8, int_str(x%nnode) // ' 2', h5 // mesh_points)
      write (u, '(a)') '      </Geometry>'
      write (u, '(a)') '    </Grid>'
      call plies_collection(x%plies, u, h5, x%time(:x%nsnap))
      write (u, '(a)') '    <Grid Name="fields" GridType="Collection" CollectionType="Temporal">'
      snapshots: do s = 1, x%nsnap
         write (u, '(a)') '      <Grid Name="step ' // int_str(x%step(s)) // '" GridType="Uniform">'
         write (u, '(a)') '        <xi:include xpointer="xpointer(//Grid[@Name=''mesh'']/*[self::Topology ' &
            // 'or self::Geometry])"/>'
         write (u, '(a)') '        <Time Value="' // trim(x%time(s)) // '"/>'
         write (u, '(a)') '        <Information Name="step" Value="' // int_str(x%step(s)) // '"/>'
         write (u, '(a)') '        <Information Name="force_N" Value="' // trim(x%force(s)) // '"/>'
         do k = 1, ndof_node
            call attribute(trim(freedom_name(k)), view_path(x, k, s))
         end do
         do k = 1, ndof_node
            call attribute('peak_' // trim(freedom_name(k)), peak // trim(freedom_name(k)))
         end do
         write (u, '(a)') '      </Grid>'
      end do snapshots
      write (u, '(a)') '    </Grid>'
      write (u, '(a)') '  </Domain>'
      write (u, '(a)') '</Xdmf>'
      close (u, iostat=stat, iomsg=iomsg)
      if (stat /= 0) then
         errmsg = 'cannot write ' // tmp // ': ' // trim(iomsg)
         return
      end if
      call rename_file(tmp, x%path, stat, errmsg)
      if (stat /= 0) return
      call system_clock(x%written_at)

   contains

      subroutine attribute(name, path)
         character(len=*), intent(in) :: name, path
         write (u, '(a)') '        <Attribute Name="' // name // '" AttributeType="Scalar" Center="Node">'
         write (u, '(a)') '          ' // data_item('Float', 8, int_str(x%nnode), h5 // path)
         write (u, '(a)') '        </Attribute>'
      end subroutine attribute

   end subroutine write_xml

   !> An HDF DataItem: type 'Int' or 'Float', bytes per value, dimensions
   !> (C order, as the HDF5 file has them) and 'file:/path'.
   pure function data_item(number_type, precision, dims, where) result(text)
      character(len=*), intent(in) :: number_type, dims, where
      integer, intent(in) :: precision
      character(len=:), allocatable :: text
      text = '<DataItem Format="HDF" DataType="' // number_type // '" Precision="' // int_str(precision) &
         // '" Dimensions="' // dims // '">' // where // '</DataItem>'
   end function data_item

   ! ============================================================ the mirror

   !> The whole plate from the modelled domain, mirrored about x = 0 when
   !> msh%sym_x and about y = 0 when msh%sym_y: points xy(2, n), cells
   !> (nen, e) numbered from 1, counter-clockwise, the modelled node of
   !> each point and the sign of each field there.
   subroutine whole_plate(msh, xy, cells, source, parity)
      type(mesh_t), intent(in) :: msh
      real(dp), allocatable, intent(out) :: xy(:,:)
      integer, allocatable, intent(out) :: cells(:,:)
      integer, allocatable, intent(out) :: source(:)
      real(dp), allocatable, intent(out) :: parity(:,:)
      integer :: ilo, jlo, ihi, jhi, ni, i, j, n, e, k, ib, jb
      real(dp) :: sx, sy

      ihi = 2*msh%nx;  jhi = 2*msh%ny
      ilo = merge(-ihi, 0, msh%sym_x)
      jlo = merge(-jhi, 0, msh%sym_y)
      ni = ihi - ilo + 1
      allocate (xy(2, ni*(jhi - jlo + 1)), source(ni*(jhi - jlo + 1)), parity(ndof_node, ni*(jhi - jlo + 1)))
      points_j: do j = jlo, jhi
         points_i: do i = ilo, ihi
            n = point(i, j)
            source(n) = msh%grid(abs(i), abs(j))
            sx = merge(-1.0_dp, 1.0_dp, i < 0)
            sy = merge(-1.0_dp, 1.0_dp, j < 0)
            xy(:, n) = [sx, sy]*msh%coords(:, source(n))
            do k = 1, ndof_node
               parity(k, n) = merge(sx, 1.0_dp, odd_in_x(k))*merge(sy, 1.0_dp, odd_in_y(k))
            end do
         end do points_i
      end do points_j
      allocate (cells(nen, ((ihi - ilo)/2)*((jhi - jlo)/2)))
      e = 0
      elements_j: do jb = jlo, jhi - 2, 2
         elements_i: do ib = ilo, ihi - 2, 2
            e = e + 1
            do k = 1, nen
               cells(k, e) = point(ib + element_di(k), jb + element_dj(k))
            end do
         end do elements_i
      end do elements_j

   contains

      !> The number of grid point (i, j) of the whole plate, i fastest.
      pure integer function point(i, j)
         integer, intent(in) :: i, j
         point = (j - jlo)*ni + (i - ilo) + 1
      end function point

   end subroutine whole_plate

   ! ============================================================== helpers

   !> text with the XML special characters & < > " replaced by entities.
   pure function xml_escaped(text) result(out)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: out
      integer :: k
      out = ''
      do k = 1, len(text)
         select case (text(k:k))
         case ('&');  out = out // '&amp;'
         case ('<');  out = out // '&lt;'
         case ('>');  out = out // '&gt;'
         case ('"');  out = out // '&quot;'
         case default; out = out // text(k:k)
         end select
      end do
   end function xml_escaped

end module results_xdmf
