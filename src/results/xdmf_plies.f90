!> The ply fields of a run with &strength as a grid of <prefix>.xdmf: the damage map and the ply
!> stresses at the peak force (/strength, damage_record.f90) beside the nodal fields in ParaView,
!> VisIt, meshio. The grid is the laminate, one hexahedron per Gauss point, ply and ply face (above
!> laminate_grid), in /xdmf/plies of <prefix>.h5 with a dataset per cell attribute, and a temporal
!> collection "plies" (above plies_collection); the modelled domain only. Not from the paper. More:
!> docs/OUTPUT.md, "The ply fields".
module xdmf_plies
   use hdf5, only: hid_t
   use kinds, only: dp
   use number_text, only: int_str
   use mesh, only: mesh_t
   use shape_functions, only: nen, shape9
   use hdf5_io, only: h5io_group, h5io_write, h5io_delete
   implicit none
   private
   public :: xdmf_plies_t, ply_maps_t, plies_write, plies_add, plies_collection, data_item, xml_attribute

   !> Where the cells of the 3 x 3 Gauss points are cut, along xi and eta.
   real(dp), parameter :: plies_cut(4) = [-1.0_dp, -4.0_dp/9.0_dp, 4.0_dp/9.0_dp, 1.0_dp]
   !> The group of the grid's datasets in <prefix>.h5.
   character(len=*), parameter :: group = 'xdmf/plies'
   !> Points of the lattice of an element's cut lines (4 x 4).
   integer, parameter :: nen_lattice = 16
   !> Number of real and integer cell attributes, their names in the XML and datasets.
   integer, parameter :: nreals = 10, nints = 3, name_len = 24
   character(len=name_len), parameter :: real_names(nreals) = [character(len=name_len) :: &
      'ply_angle (deg)', 'damage_map (-)', 'onset_time (s)', 'peak_sigma_11 (Pa)', 'peak_sigma_22 (Pa)', &
      'peak_tau_12 (Pa)', 'peak_tau_23 (Pa)', 'peak_tau_13 (Pa)', 'peak_failure_index (-)', &
      'delamination_index (-)']
   character(len=name_len), parameter :: real_sets(nreals) = [character(len=name_len) :: &
      'ply_angle', 'damage_map', 'onset_time', 'peak_sigma_11', 'peak_sigma_22', &
      'peak_tau_12', 'peak_tau_23', 'peak_tau_13', 'peak_failure_index', 'delamination_index']
   character(len=name_len), parameter :: int_names(nints) = [character(len=name_len) :: 'ply', 'face', 'damage_mode']

   !> The laminate grid of a results file.
   type :: xdmf_plies_t
      logical :: active = .false.                   !< /xdmf/plies written: the XML shows it
      integer :: nply = 0, npoint = 0               !< plies, Gauss points
      integer :: ncell = 0, npts = 0                !< hexahedra, their points
      character(len=:), allocatable :: modes        !< the mode codes' words ('0 none, 1 fibre_tension, ...')
      character(len=2*name_len), allocatable :: added(:)   !< the maps plies_add wrote (ply damage)
   end type xdmf_plies_t

   !> The laminate and its damage maps, per ply and Gauss point: what plies_write shows.
   type :: ply_maps_t
      real(dp), allocatable :: z(:)                 !< (0:nply) ply interfaces (m)
      real(dp), allocatable :: angle(:)             !< (nply) ply angles (deg)
      real(dp), allocatable :: fi_max(:,:)          !< (nply, npoint) largest failure index over the run (-)
      integer, allocatable :: mode_max(:,:)         !< (nply, npoint) its mode
      real(dp), allocatable :: onset(:,:)           !< (nply, npoint) first time it reached 1 (s, -1 never)
      real(dp), allocatable :: sigma(:,:,:,:)       !< (5, 2, nply, npoint) stresses at the peak force (Pa)
      real(dp), allocatable :: fi(:,:,:)            !< (2, nply, npoint) failure indices there (-)
      real(dp), allocatable :: delam(:,:)           !< (nply - 1, npoint) interfaces' largest index (-)
      character(len=:), allocatable :: modes        !< the mode codes' words
   end type ply_maps_t

contains

   !> Writes /xdmf/plies into the open results file fid and makes p active
   !> (the maps: ply_maps_t; z(0) = -h/2 the impacted face; stresses s11 s22
   !> t12 t23 t13 in material axes; points 9 per element, xi fastest).
   subroutine plies_write(p, fid, msh, maps, stat, errmsg)
      type(xdmf_plies_t), intent(out) :: p          !< the grid, active on success
      integer(hid_t), intent(in) :: fid             !< the open results file
      type(mesh_t), intent(in) :: msh               !< the modelled mesh
      type(ply_maps_t), intent(in) :: maps          !< the laminate and its maps
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      real(dp), allocatable :: xyz(:,:), face_values(:,:,:)
      integer, allocatable :: cells(:,:)
      integer :: nply, npoint, ncell, c, k
      nply = size(maps%angle)
      npoint = size(maps%fi_max, 2)
      ncell = 2*nply*npoint
      call laminate_grid(msh, maps%z, xyz, cells)
      stat = 0
      ! a restarted run (src/record/restart_point.f90) finds the group of the run it continues
      call h5io_delete(fid, group, stat, errmsg)
      if (stat == 0) call h5io_group(fid, group, stat, errmsg)
      if (stat == 0) call h5io_write(fid, group // '/points', xyz, stat, errmsg)
      if (stat == 0) call h5io_write(fid, group // '/cells', cells, stat, errmsg)
      deallocate (xyz, cells)
      ! -- where each cell is
      call put('ply', reshape(spread(spread([(k, k = 1, nply)], 1, 2), 3, npoint), [ncell]))
      call put('face', reshape(spread(spread([1, 2], 2, nply), 3, npoint), [ncell]))
      call put(real_sets(1), reshape(spread(spread(maps%angle, 1, 2), 3, npoint), [ncell]))
      ! -- the damage map, the same on both faces of a ply
      call put(real_sets(2), reshape(spread(maps%fi_max, 1, 2), [ncell]))
      call put(real_sets(3), reshape(spread(maps%onset, 1, 2), [ncell]))
      call put('damage_mode', reshape(spread(maps%mode_max, 1, 2), [ncell]))
      ! -- the peak force's stresses and indices, face by face
      do c = 1, 5
         call put(real_sets(3 + c), reshape(maps%sigma(c, :, :, :), [ncell]))
      end do
      call put(real_sets(9), reshape(maps%fi, [ncell]))
      ! -- each interface's index on the two half-plies beside it
      allocate (face_values(2, nply, npoint))
      face_values = 0.0_dp
      face_values(2, 1:nply-1, :) = maps%delam
      face_values(1, 2:nply, :) = maps%delam
      call put(real_sets(10), reshape(face_values, [ncell]))
      if (stat /= 0) return
      p%active = .true.
      p%nply = nply
      p%npoint = npoint
      p%ncell = ncell
      p%npts = nen_lattice*msh%nelem*(2*nply + 1)
      p%modes = maps%modes
      allocate (p%added(0))
   contains
      subroutine put(name, x)
         character(len=*), intent(in) :: name
         class(*), intent(in) :: x(:)
         if (stat == 0) call h5io_write(fid, group // '/' // trim(name), x, stat, errmsg)
      end subroutine put
   end subroutine plies_write

   !> One more map v (nply, npoint) of the active grid p, the same on both
   !> faces of a ply, as /xdmf/plies/<name> (the ply damage of a mode).
   subroutine plies_add(p, fid, name, v, stat, errmsg)
      type(xdmf_plies_t), intent(inout) :: p        !< the grid (active)
      integer(hid_t), intent(in) :: fid             !< the open results file
      character(len=*), intent(in) :: name          !< the map's name (-, no unit)
      real(dp), intent(in) :: v(:,:)                !< (nply, npoint) its values
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< reason on failure
      call h5io_write(fid, group // '/' // name, reshape(spread(v, 1, 2), [p%ncell]), stat, errmsg)
      if (stat == 0) p%added = [p%added, [character(len=2*name_len) :: name]]
   end subroutine plies_add

   !> The laminate grid: in the plane, the cell of a 3 x 3 Gauss point is the part of its element
   !> its weight stands for (xi, eta cut at -1, -4/9, 4/9, 1), mapped by the shape functions;
   !> through the thickness ply k is cut at its middle, the lower half its face towards the impacted
   !> face (2k-1), the upper the other (2k); z turned over (z_view = -z) so the impacted face is on
   !> top. Points xyz (3, npts) (m), hexahedra cells (8, ncell) numbered from 0, lower face first,
   !> counter-clockwise from above.
   subroutine laminate_grid(msh, z, xyz, cells)
      type(mesh_t), intent(in) :: msh
      real(dp), intent(in) :: z(0:)
      real(dp), allocatable, intent(out) :: xyz(:,:)
      integer, allocatable, intent(out) :: cells(:,:)
      real(dp) :: xe(2, nen), xy(2), zl(0:2*(size(z) - 1))
      integer :: nply, nl, e, a, b, l, i, j, k, f, c, lo, n0, quad(4)
      nply = size(z) - 1
      nl = 2*nply + 1
      ! -- the levels from the impacted face, z turned over (above laminate_grid)
      do k = 1, nply
         zl(2*k - 2) = -z(k - 1)
         zl(2*k - 1) = -0.5_dp*(z(k - 1) + z(k))
      end do
      zl(2*nply) = -z(nply)
      allocate (xyz(3, nen_lattice*nl*msh%nelem), cells(8, 18*nply*msh%nelem))
      c = 0
      elements: do e = 1, msh%nelem
         xe = msh%coords(:, msh%conn(:, e))
         n0 = nen_lattice*nl*(e - 1)
         lattice: do b = 0, 3
            do a = 0, 3
               xy = matmul(xe, shape9(plies_cut(a + 1), plies_cut(b + 1)))
               do l = 0, nl - 1
                  xyz(:, n0 + lattice_point(a, b, l) + 1) = [xy, zl(l)]
               end do
            end do
         end do lattice
         ! -- the Gauss points, xi fastest; plies from the impacted face
         points_j: do j = 1, 3
            points_i: do i = 1, 3
               quad = [lattice_point(i - 1, j - 1, 0), lattice_point(i, j - 1, 0), lattice_point(i, j, 0), &
                       lattice_point(i - 1, j, 0)]
               do k = 1, nply
                  do f = 1, 2
                     c = c + 1
                     lo = 2*(k - 1) + f                ! the deeper level (lower in z_view)
                     cells(:, c) = n0 + [quad + lo, quad + lo - 1]
                  end do
               end do
            end do points_i
         end do points_j
      end do elements
   contains
      !> Point (from 0, in the element) of lattice corner (a, b) at level l.
      pure integer function lattice_point(a, b, l)
         integer, intent(in) :: a, b, l
         lattice_point = (4*b + a)*nl + l
      end function lattice_point
   end subroutine laminate_grid

   !> The temporal collection "plies" of the XML on unit u, before the nodal fields' (ParaView reads
   !> top-level temporal collections only; meshio the last, "fields"): at each time, the laminate
   !> with its cell attributes; h5 is the results file as the XML names it, with ':/' appended.
   subroutine plies_collection(p, u, h5, times)
      type(xdmf_plies_t), intent(in) :: p           !< the grid (active)
      integer, intent(in) :: u                      !< the XML file
      character(len=*), intent(in) :: h5            !< '<file>.h5:/'
      character(len=*), intent(in) :: times(:)      !< the times (s), as text
      character(len=:), allocatable :: cells, at
      integer :: s, j
      if (.not. p%active) return
      cells = int_str(p%ncell)
      at = h5 // group // '/'
      write (u, '(a)') '    <Grid Name="plies" GridType="Collection" CollectionType="Temporal">'
      steps: do s = 1, size(times)
         write (u, '(a)') '      <Grid Name="plies ' // int_str(s) // '" GridType="Uniform">'
         write (u, '(a)') '        <Time Value="' // trim(times(s)) // '"/>'
         write (u, '(a)') '        <Information Name="damage_mode" Value="' // p%modes // '"/>'
         write (u, '(a)') '        <Topology TopologyType="Hexahedron" NumberOfElements="' // cells // '">'
         write (u, '(a)') '          ' // data_item('Int', cells // ' 8', h5 // group // '/cells')
         write (u, '(a)') '        </Topology>'
         write (u, '(a)') '        <Geometry GeometryType="XYZ">'
         write (u, '(a)') '          ' // data_item('Float', int_str(p%npts) // ' 3', h5 // group // '/points')
         write (u, '(a)') '        </Geometry>'
         do j = 1, nints
            call xml_attribute(u, trim(int_names(j)), 'Cell', 'Int', cells, at // trim(int_names(j)))
         end do
         do j = 1, nreals
            call xml_attribute(u, trim(real_names(j)), 'Cell', 'Float', cells, at // trim(real_sets(j)))
         end do
         do j = 1, size(p%added)
            call xml_attribute(u, trim(p%added(j)) // ' (-)', 'Cell', 'Float', cells, at // trim(p%added(j)))
         end do
         write (u, '(a)') '      </Grid>'
      end do steps
      write (u, '(a)') '    </Grid>'
   end subroutine plies_collection

   !> An XDMF scalar Attribute on unit u, centred on 'Node' or 'Cell', its data (data_item) at `where`.
   subroutine xml_attribute(u, name, center, number_type, dims, where)
      integer, intent(in) :: u
      character(len=*), intent(in) :: name, center, number_type, dims, where
      write (u, '(a)') '        <Attribute Name="' // name // '" AttributeType="Scalar" Center="' // center &
         // '">'
      write (u, '(a)') '          ' // data_item(number_type, dims, where)
      write (u, '(a)') '        </Attribute>'
   end subroutine xml_attribute

   !> An HDF DataItem of 4-byte integers ('Int') or 8-byte reals ('Float'):
   !> dimensions (C order), 'file:/path'.
   pure function data_item(number_type, dims, where) result(text)
      character(len=*), intent(in) :: number_type, dims, where
      character(len=:), allocatable :: text
      text = '<DataItem Format="HDF" DataType="' // number_type // '" Precision="' &
         // merge('4', '8', number_type == 'Int') // '" Dimensions="' // dims // '">' // where // '</DataItem>'
   end function data_item

end module xdmf_plies
