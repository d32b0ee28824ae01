!> <prefix>.xdmf beside <prefix>.h5: an XDMF 3 description of the mesh (9-node quadrilaterals) and
!> nodal fields, one time step per snapshot, for ParaView, VisIt and meshio; with &strength the
!> plies (xdmf_plies.f90). Every array is a dataset of <prefix>.h5 or a view in <prefix>.xdmf.h5
!> (above xdmf_t). Called by src/results/results_hdf5.f90: xdmf_open, xdmf_start; per batch of
!> snapshots xdmf_grow, xdmf_snapshots, xdmf_batch_close; xdmf_peak; xdmf_close; a restart:
!> xdmf_cut, xdmf_resume. Not from the paper. More: docs/OUTPUT.md.
module results_xdmf
   use, intrinsic :: iso_fortran_env, only: int64
   use hdf5, only: hid_t
   use kinds, only: dp, msg_len
   use number_text, only: int_str, real_str
   use deck_schema, only: deck_t
   use mesh, only: mesh_t, ndof_node, freedom_name
   use shape_functions, only: nen
   use hdf5_io, only: h5io_open, h5io_close, h5io_group, h5io_write, h5io_rewrite, h5io_flush, h5io_set_attr
   use hdf5_series, only: h5io_view_column, h5io_create_series, h5io_real, h5io_open_dataset, h5io_append_block, &
      h5io_cut_series, h5io_close_dataset
   use file_system, only: rename_file
   use result_files, only: keep_failure
   use xdmf_plies, only: xdmf_plies_t, plies_collection, data_item, xml_attribute
   implicit none
   private
   public :: xdmf_t, xdmf_open, xdmf_start, xdmf_cut, xdmf_resume, xdmf_grow, xdmf_snapshots, xdmf_batch_close, &
             xdmf_peak, xdmf_close

   !> Longest number as text (src/system/number_text.f90, real_str).
   integer, parameter :: text_len = 32
   !> Values per chunk of the whole plate's growing fields.
   integer, parameter :: chunk_values = 512
   !> Least wall-clock time between two rewrites of the XML during a run (s).
   real(dp), parameter :: xdmf_rewrite_interval = 1.0_dp
   !> Fields odd across x = 0 (u, psi_x) and across y = 0 (v, psi_y), by freedom.
   logical, parameter :: odd_in_x(ndof_node) = [.true., .false., .false., .true., .false.]
   logical, parameter :: odd_in_y(ndof_node) = [.false., .true., .false., .false., .true.]
   !> Nodes of a 9-node element as (i, j) offsets on the grid from its lowest
   !> corner (src/model/shape_functions.f90's order).
   integer, parameter :: element_di(nen) = [0, 2, 2, 0, 1, 2, 1, 0, 1]
   integer, parameter :: element_dj(nen) = [0, 0, 2, 2, 0, 1, 2, 1, 1]

   !> A view per snapshot (a plain dataset, what every reader takes: ParaView 5.11 ignores
   !> hyperslabs, meshio reads whole datasets) in a file of its own, as <prefix>.h5 is written in
   !> SWMR mode, which makes no object. &output xdmf = 'whole' mirrors a quarter or half into the
   !> whole plate (u, psi_x odd across x = 0, v, psi_y across y = 0, which no view can do): its
   !> fields are data in /xdmf of <prefix>.h5, growing with /fields; 'none' writes neither XML, nor
   !> /xdmf, nor views.
   type :: xdmf_t
      logical :: active = .false.                   !< <prefix>.xdmf is being written
      logical :: whole = .false.                    !< the mirrored whole plate (else the modelled domain)
      character(len=:), allocatable :: path         !< <prefix>.xdmf
      character(len=:), allocatable :: h5_name      !< <prefix>.h5 as the XML names it: its file name
      character(len=:), allocatable :: views_path   !< <prefix>.xdmf.h5, the views
      character(len=:), allocatable :: views_name   !< its file name
      character(len=:), allocatable :: status       !< 'running', then the run's status
      integer(hid_t) :: vid = -1                    !< <prefix>.xdmf.h5, open
      integer :: nnode = 0, nelem = 0               !< nodes and elements shown
      integer :: nsnap = 0                          !< snapshots so far
      character(len=text_len), allocatable :: time(:), force(:)  !< of each snapshot (s, N), as the XML gives them
      integer, allocatable :: step(:)               !< of each snapshot
      integer, allocatable :: batch(:)              !< of each snapshot: its group /fields/<batch>
      integer :: nbatch = 0                         !< batches so far
      integer, allocatable :: source(:)             !< whole: the modelled node of each node shown
      real(dp), allocatable :: parity(:,:)          !< whole: (ndof_node, nnode) sign of each field there
      integer(int64) :: written_at = 0              !< system_clock count of the last rewrite
      type(xdmf_plies_t) :: plies                   !< with &strength, the laminate's ply fields (src/results/xdmf_plies.f90)
   end type xdmf_t

contains

   !> The XDMF of a run (nothing for 'none'): its names; for the whole plate
   !> its points, cells (from 1), the modelled node and each field's sign.
   subroutine setup(x, deck, msh, xy, cells)
      type(xdmf_t), intent(out) :: x                !< the XDMF file, not yet active
      type(deck_t), intent(in) :: deck              !< the effective deck (prefix, xdmf)
      type(mesh_t), intent(in) :: msh               !< the modelled mesh
      real(dp), allocatable, intent(out) :: xy(:,:) !< (2, nnode) the points shown (m)
      integer, allocatable, intent(out) :: cells(:,:)   !< (nen, nelem) the cells shown, from 1
      integer :: slash
      x%path = deck%prefix // '.xdmf'
      x%views_path = deck%prefix // '.xdmf.h5'
      slash = index(deck%prefix, '/', back=.true.)
      x%h5_name = deck%prefix(slash + 1:) // '.h5'
      x%views_name = deck%prefix(slash + 1:) // '.xdmf.h5'
      x%status = 'running'
      x%whole = deck%xdmf == 'whole' .and. (msh%sym_x .or. msh%sym_y)
      allocate (x%time(0), x%force(0), x%step(0), x%batch(0))
      if (x%whole) then
         call whole_plate(msh, xy, cells, x%source, x%parity)
      else
         xy = msh%coords
         cells = msh%conn
      end if
      x%nnode = size(xy, 2)
      x%nelem = size(cells, 2)
   end subroutine setup

   !> Writes /xdmf into <prefix>.h5 while it is made: cells from 0; for the
   !> whole plate its points, /peak and the empty growing fields.
   subroutine xdmf_open(x, deck, msh, fid, stat, errmsg)
      type(xdmf_t), intent(out) :: x                !< the XDMF file, ready for xdmf_start on return
      type(deck_t), intent(in) :: deck              !< the effective deck (prefix, xdmf)
      type(mesh_t), intent(in) :: msh               !< the modelled mesh
      integer(hid_t), intent(in) :: fid             !< <prefix>.h5, being made
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: xy(:,:)
      integer, allocatable :: cells(:,:)
      integer(hid_t) :: did
      integer :: k, n
      stat = 0
      if (deck%xdmf == 'none') return
      call setup(x, deck, msh, xy, cells)
      call h5io_group(fid, 'xdmf', stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'xdmf', 'domain', trim(merge('whole   ', 'modelled', x%whole)), &
         stat, errmsg)
      if (stat == 0) call h5io_set_attr(fid, 'xdmf', 'description', 'what ' // x%h5_name(:len(x%h5_name) - 3) &
         // '.xdmf shows (src/results/results_xdmf.f90): cells numbered from 0; the views of the snapshots are in ' &
         // x%views_name, stat, errmsg)
      if (stat == 0) call h5io_write(fid, 'xdmf/cells', cells - 1, stat, errmsg)
      if (stat /= 0 .or. .not. x%whole) return
      call h5io_write(fid, 'xdmf/coordinates', xy, stat, errmsg)
      if (stat == 0) call h5io_group(fid, 'xdmf/peak', stat, errmsg)
      if (stat == 0) call h5io_group(fid, 'xdmf/fields', stat, errmsg)
      fields: do k = 1, ndof_node
         if (stat /= 0) exit fields
         call h5io_write(fid, 'xdmf/peak/' // trim(freedom_name(k)), [(0.0_dp, n = 1, x%nnode)], stat, errmsg)
         if (stat == 0) call h5io_create_series(fid, 'xdmf/fields/' // trim(freedom_name(k)), h5io_real, &
            x%nnode, chunk_values, did, stat, errmsg)
         if (stat == 0) call h5io_close_dataset(did, stat, errmsg)
      end do fields
   end subroutine xdmf_open

   !> Starts <prefix>.xdmf.h5 and the XML without a snapshot; x active on return.
   subroutine xdmf_start(x, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file (xdmf_open, or xdmf_cut)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 0
      if (.not. allocated(x%path)) return           ! xdmf = 'none'
      call system_clock(x%written_at)
      call h5io_open(x%views_path, .true., .false., x%vid, stat, errmsg)
      if (stat == 0) call h5io_group(x%vid, 'fields', stat, errmsg)
      if (stat /= 0) then
         errmsg = x%views_path // ': ' // trim(errmsg)
         return
      end if
      x%active = .true.
      call write_xml(x, stat, errmsg)
   end subroutine xdmf_start

   !> A restart, while <prefix>.h5 is cut back to `snaps`: the whole plate's fields cut alike.
   subroutine xdmf_cut(x, deck, msh, fid, snaps, stat, errmsg)
      type(xdmf_t), intent(out) :: x                !< the XDMF file, ready for xdmf_resume on return
      type(deck_t), intent(in) :: deck              !< the effective deck (prefix, xdmf)
      type(mesh_t), intent(in) :: msh               !< the modelled mesh
      integer(hid_t), intent(in) :: fid             !< <prefix>.h5, open
      integer, intent(in) :: snaps                  !< snapshots kept
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: xy(:,:)
      integer, allocatable :: cells(:,:)
      integer(hid_t) :: did
      integer :: k, ios
      stat = 0
      if (deck%xdmf == 'none') return
      call setup(x, deck, msh, xy, cells)
      fields: do k = 1, ndof_node
         if (stat /= 0 .or. .not. x%whole) exit fields
         call h5io_open_dataset(fid, 'xdmf/fields/' // trim(freedom_name(k)), did, stat, errmsg)
         if (stat /= 0) exit fields
         call h5io_cut_series(did, snaps, stat, errmsg)
         call h5io_close_dataset(did, ios, errmsg)
      end do fields
   end subroutine xdmf_cut

   !> A restart: the XDMF of the snapshots kept, <prefix>.xdmf.h5 made anew
   !> with their views in one batch, and the XML.
   subroutine xdmf_resume(x, time, step, force, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file (xdmf_cut), active on return
      real(dp), intent(in) :: time(:), force(:)     !< the snapshots' times (s) and contact forces (N)
      integer, intent(in) :: step(:)                !< their steps
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      stat = 0
      if (.not. allocated(x%path)) return           ! xdmf = 'none'
      call xdmf_start(x, stat, errmsg)
      if (stat == 0 .and. size(step) > 0) call xdmf_snapshots(x, 0, step, time, force, stat, errmsg)
      if (stat == 0) call h5io_flush(x%vid, stat, errmsg)
      if (stat == 0) call write_xml(x, stat, errmsg)
   end subroutine xdmf_resume

   !> The whole plate: the mirror of the snapshots f just appended to /fields.
   subroutine xdmf_grow(x, fid, f, stat, errmsg)
      type(xdmf_t), intent(in) :: x                 !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< <prefix>.h5, open
      real(dp), intent(in) :: f(:,:,:)              !< (ndof_node, nnode, snapshot) their nodal values, modelled domain
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: mirrored(:,:)
      integer(hid_t) :: did
      integer :: k, j, ios
      stat = 0
      if (.not. (x%active .and. x%whole)) return
      allocate (mirrored(x%nnode, size(f, 3)))
      fields: do k = 1, ndof_node
         do j = 1, size(f, 3)
            mirrored(:, j) = x%parity(k, :)*f(k, x%source, j)
         end do
         call h5io_open_dataset(fid, 'xdmf/fields/' // trim(freedom_name(k)), did, stat, errmsg)
         if (stat /= 0) exit fields
         call h5io_append_block(did, mirrored, stat, errmsg)
         call h5io_close_dataset(did, ios, errmsg)
         if (stat /= 0) exit fields
      end do fields
   end subroutine xdmf_grow

   !> As the run goes: after a batch of snapshots <prefix>.xdmf.h5 is flushed and the XML rewritten
   !> by rename (a reader sees the old or the new file), after the first batch, then at most once
   !> per xdmf_rewrite_interval (the XML grows with every snapshot), and at the end; a killed run's
   !> XDMF opens, status 'running' (a restart makes <prefix>.xdmf.h5 anew). Here: a batch of
   !> snapshots after the first `before`, their views in the group /fields/<b> of <prefix>.xdmf.h5.
   subroutine xdmf_snapshots(x, before, step, time, force, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer, intent(in) :: before                 !< snapshots in <prefix>.h5 before the batch
      integer, intent(in) :: step(:)                !< each snapshot's time step
      real(dp), intent(in) :: time(:), force(:)     !< their times (s) and contact forces (N)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      character(len=:), allocatable :: source
      integer :: k, j
      stat = 0
      if (.not. x%active) return
      x%nsnap = before
      x%time = x%time(:before);  x%force = x%force(:before)
      x%step = x%step(:before);  x%batch = x%batch(:before)
      x%nbatch = x%nbatch + 1
      call h5io_group(x%vid, 'fields/' // int_str(x%nbatch), stat, errmsg)
      do k = 1, ndof_node
         if (stat == 0) call h5io_group(x%vid, 'fields/' // int_str(x%nbatch) // '/' // trim(freedom_name(k)), &
            stat, errmsg)
      end do
      snapshots: do j = 1, size(step)
         if (stat /= 0) exit snapshots
         x%nsnap = x%nsnap + 1
         x%time = [x%time, real_str(time(j))]
         x%force = [x%force, real_str(force(j))]
         x%step = [x%step, step(j)]
         x%batch = [x%batch, x%nbatch]
         fields: do k = 1, ndof_node
            source = merge('xdmf/fields/', 'fields/     ', x%whole)
            call h5io_view_column(x%vid, view_path(x, k, x%nsnap), x%h5_name, trim(source) // trim(freedom_name(k)), &
               x%nnode, x%nsnap, stat, errmsg)
            if (stat /= 0) exit snapshots
         end do fields
      end do snapshots
   end subroutine xdmf_snapshots

   !> Ends a batch: <prefix>.xdmf.h5 flushed, the XML rewritten when due.
   subroutine xdmf_batch_close(x, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer(int64) :: now, rate
      stat = 0
      if (.not. x%active) return
      call h5io_flush(x%vid, stat, errmsg)
      if (stat /= 0) return
      call system_clock(now, rate)
      if (x%nbatch == 1 .or. real(now - x%written_at, dp) >= xdmf_rewrite_interval*real(rate, dp)) &
         call write_xml(x, stat, errmsg)
   end subroutine xdmf_batch_close

   !> Where field k of snapshot s is in <prefix>.xdmf.h5: /fields/<b>/<f>/<s>.
   pure function view_path(x, k, s) result(path)
      type(xdmf_t), intent(in) :: x                 !< the XDMF file
      integer, intent(in) :: k, s                   !< freedom, snapshot
      character(len=:), allocatable :: path
      path = 'fields/' // int_str(x%batch(s)) // '/' // trim(freedom_name(k)) // '/' // int_str(s)
   end function view_path

   !> The peak state just rewritten: for the whole plate, mirrored into /xdmf/peak.
   subroutine xdmf_peak(x, fid, f, stat, errmsg)
      type(xdmf_t), intent(in) :: x                 !< the XDMF file
      integer(hid_t), intent(in) :: fid             !< <prefix>.h5, open
      real(dp), intent(in) :: f(:,:)                !< (ndof_node, nnode) the peak's nodal values, modelled domain
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer :: k
      stat = 0
      if (.not. (allocated(x%path) .and. x%whole)) return
      do k = 1, ndof_node
         if (stat == 0) call h5io_rewrite(fid, 'xdmf/peak/' // trim(freedom_name(k)), &
            x%parity(k, :)*f(k, x%source), stat, errmsg)
      end do
   end subroutine xdmf_peak

   !> The last XML, with every snapshot and the status; <prefix>.xdmf.h5 closed.
   subroutine xdmf_close(x, status, stat, errmsg)
      type(xdmf_t), intent(inout) :: x              !< the XDMF file
      character(len=*), intent(in) :: status        !< the run's status ('completed', 'failed at step N', ...)
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      integer :: ios
      character(len=msg_len) :: why
      stat = 0
      if (.not. x%active) return
      x%status = status
      call write_xml(x, stat, errmsg)
      call h5io_close(x%vid, ios, why)
      x%vid = -1
      call keep_failure(stat, errmsg, ios, x%views_path // ': ' // trim(why))
      x%active = .false.
   end subroutine xdmf_close

   !> Writes the XML to <prefix>.xdmf.tmp and renames it over <prefix>.xdmf.
   subroutine write_xml(x, stat, errmsg)
      type(xdmf_t), intent(inout) :: x
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=msg_len) :: iomsg
      character(len=:), allocatable :: tmp, h5, views, mesh_points, peak, nodes
      integer :: u, k, s
      h5 = xml_escaped(x%h5_name) // ':/'
      views = xml_escaped(x%views_name) // ':/'
      mesh_points = trim(merge('xdmf/coordinates', 'mesh/coordinates', x%whole))
      peak = trim(merge('xdmf/peak/', 'peak/     ', x%whole))
      nodes = int_str(x%nnode)
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
      write (u, '(a)') '        ' // data_item('Int', int_str(x%nelem) // ' ' // int_str(nen), h5 // 'xdmf/cells')
      write (u, '(a)') '      </Topology>'
      write (u, '(a)') '      <Geometry GeometryType="XY">'
      write (u, '(a)') '        ' // data_item('Float', int_str(x%nnode) // ' 2', h5 // mesh_points)
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
            call xml_attribute(u, trim(freedom_name(k)), 'Node', 'Float', nodes, &
               views // view_path(x, k, s))
         end do
         do k = 1, ndof_node
            call xml_attribute(u, 'peak_' // trim(freedom_name(k)), 'Node', 'Float', nodes, &
               h5 // peak // trim(freedom_name(k)))
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
   end subroutine write_xml

   !> The whole plate, mirrored about x = 0 (sym_x) and y = 0 (sym_y): points xy(2, n), cells from
   !> 1, counter-clockwise, each point's modelled node and each field's sign there.
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
