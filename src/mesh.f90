!> Mesh, freedoms and boundary conditions (paper Fig. 4).
!>
!> The modelled domain is a rectangle meshed with nx x ny 9-node elements:
!>  - domain 'quarter': 0 <= x <= a/2, 0 <= y <= b/2, the impact point (the
!>    plate centre) at the corner (0, 0); the lines x = 0 and y = 0 are
!>    symmetry lines (section 2.4, 3.1);
!>  - domain 'full': -a/2 <= x <= a/2, -b/2 <= y <= b/2, the impact point at
!>    the origin, which is always a node of the (2nx+1) x (2ny+1) node grid;
!>  - domain 'strip': the quarter's rectangle, but y = b/2 is a symmetry line
!>    too, so the model is a plate infinitely long along y in cylindrical
!>    bending, of span a between its x edges (TWK Arts. 2-3; the
!>    validation's strip). y = 0 and y = b/2 hold v and psi_y.
!>
!> Freedoms per node, in this order everywhere in the code (eq. 1):
!>    1 u,  2 v,  3 w,  4 psi_x,  5 psi_y.
!> w and z point the way the impactor moves.
!>
!> Node numbering: the grid node (i, j), i = 0..2nx along x and j = 0..2ny
!> along y, is numbered running first along the direction with fewer nodes,
!> which keeps the half-bandwidth at about 5 (2 min(nx,ny) + 2) + 4.
!> Equation numbers: eq(k, node) is the global equation of freedom k of node,
!> 0 where the freedom is held; equations follow the node numbering.
!>
!> Boundary conditions (section 2.4; NOTES.md "open points"):
!>  - 'clamped':          u = v = w = psi_x = psi_y = 0;
!>  - 'simply_supported': w = 0 and the rotation along the edge psi_s = 0
!>    (psi_y on x = const edges, psi_x on y = const edges: the "hard" simple
!>    support of Navier's solution); in-plane 'immovable' also holds u = v = 0,
!>    'movable' leaves them free;
!>  - 'free':             nothing held;
!>  - symmetry lines of the quarter model: x = 0 holds u and psi_x, y = 0
!>    holds v and psi_y.
module mesh
   use kinds, only: dp, msg_len
   use shape_functions, only: nen, node_xi
   implicit none
   private
   public :: mesh_t, ndof_node, nfe, build_mesh, apply_boundary, &
             freedom_name, describe_equation, element_freedoms

   !> Freedoms per node (u, v, w, psi_x, psi_y).
   integer, parameter :: ndof_node = 5
   !> Freedoms per element.
   integer, parameter :: nfe = ndof_node*nen
   character(len=5), parameter :: dof_names(ndof_node) = &
      [character(len=5) :: 'u', 'v', 'w', 'psi_x', 'psi_y']

   !> The mesh of the modelled domain and its freedom map.
   type :: mesh_t
      integer :: nx = 0, ny = 0               !< elements along x and y
      integer :: nnode = 0, nelem = 0         !< nodes, elements
      integer :: neq = 0                      !< free freedoms (equations)
      character(len=16) :: domain = ''        !< 'quarter', 'full' or 'strip'
      real(dp) :: x0 = 0, x1 = 0, y0 = 0, y1 = 0   !< domain extent (m)
      real(dp), allocatable :: coords(:,:)    !< (2, nnode) node coordinates (m)
      integer, allocatable :: conn(:,:)       !< (nen, nelem) element nodes
      integer, allocatable :: grid(:,:)       !< (0:2nx, 0:2ny) node number of grid point
      integer, allocatable :: eq(:,:)         !< (ndof_node, nnode) equation numbers
      integer, allocatable :: elem_eq(:,:)    !< (nfe, nelem) equation numbers of element freedoms
      integer :: impact_node = 0              !< node at the impact point
      integer :: impact_elem = 0              !< element nearest the impact point (for the strain gauge)
      real(dp) :: sym_factor = 1.0_dp         !< plate represented / plate modelled (4 for a quarter)
   end type mesh_t

contains

   !> Lays out nodes and elements of the modelled domain (Fig. 4).
   subroutine build_mesh(a, b, nx, ny, domain, m, stat, errmsg)
      real(dp), intent(in) :: a, b            !< plate size along x and y (m)
      integer, intent(in) :: nx, ny           !< elements along x and y of the domain
      character(len=*), intent(in) :: domain  !< 'quarter', 'full' or 'strip'
      type(mesh_t), intent(out) :: m          !< the mesh
      integer, intent(out) :: stat            !< 0 on success
      character(len=*), intent(inout) :: errmsg  !< reason on failure
      integer :: i, j, ie, je, e, k, n, ngx, ngy
      real(dp) :: xi(2)

      stat = 0
      if (nx < 1 .or. ny < 1) then
         stat = 1
         write (errmsg, '(a,i0,a,i0)') 'mesh: needs at least one element each way, got nx = ', nx, ', ny = ', ny
         return
      end if
      m%nx = nx;  m%ny = ny;  m%domain = domain
      select case (domain)
      case ('quarter', 'strip')
         m%x0 = 0.0_dp;  m%x1 = 0.5_dp*a;  m%y0 = 0.0_dp;  m%y1 = 0.5_dp*b
         m%sym_factor = 4.0_dp
      case ('full')
         m%x0 = -0.5_dp*a;  m%x1 = 0.5_dp*a;  m%y0 = -0.5_dp*b;  m%y1 = 0.5_dp*b
         m%sym_factor = 1.0_dp
      case default
         stat = 1
         errmsg = 'mesh: unknown domain "'//trim(domain)//'" (quarter, full or strip)'
         return
      end select

      ngx = 2*nx + 1;  ngy = 2*ny + 1
      m%nnode = ngx*ngy
      m%nelem = nx*ny
      allocate (m%coords(2, m%nnode), m%grid(0:ngx-1, 0:ngy-1), m%conn(nen, m%nelem))

      ! node numbers: run first along the direction with fewer nodes
      grid_nodes: do j = 0, ngy - 1
         do i = 0, ngx - 1
            if (ngy <= ngx) then
               n = 1 + j + ngy*i
            else
               n = 1 + i + ngx*j
            end if
            m%grid(i, j) = n
            m%coords(:, n) = [m%x0 + (m%x1 - m%x0)*real(i, dp)/real(ngx - 1, dp), &
                              m%y0 + (m%y1 - m%y0)*real(j, dp)/real(ngy - 1, dp)]
         end do
      end do grid_nodes

      elements: do je = 0, ny - 1
         do ie = 0, nx - 1
            e = 1 + ie + nx*je
            do k = 1, nen
               xi = node_xi(k)
               m%conn(k, e) = m%grid(2*ie + 1 + nint(xi(1)), 2*je + 1 + nint(xi(2)))
            end do
         end do
      end do elements

      ! the impact point: the plate centre
      if (domain /= 'full') then
         m%impact_node = m%grid(0, 0)
         m%impact_elem = 1
      else
         m%impact_node = m%grid(nx, ny)
         ! the element with the centre at (or nearest to) its lower-left corner
         m%impact_elem = 1 + nx/2 + nx*(ny/2)
      end if
   end subroutine build_mesh

   !> Holds the freedoms of the edges and symmetry lines and numbers the
   !> remaining equations.
   subroutine apply_boundary(m, edges, inplane, stat, errmsg)
      type(mesh_t), intent(inout) :: m        !< mesh; eq and elem_eq are set
      character(len=*), intent(in) :: edges   !< 'free', 'simply_supported' or 'clamped'
      character(len=*), intent(in) :: inplane !< 'immovable' or 'movable' (simply supported)
      integer, intent(out) :: stat            !< 0 on success
      character(len=*), intent(inout) :: errmsg  !< reason on failure
      logical :: held(ndof_node, m%nnode)
      integer :: i, j, n, k, e, ngx, ngy
      logical :: on_x_edge, on_y_edge

      stat = 0
      held = .false.
      ngx = 2*m%nx + 1;  ngy = 2*m%ny + 1
      if (all(edges /= [character(len=16) :: 'free', 'simply_supported', 'clamped'])) then
         stat = 1;  errmsg = 'boundary: unknown edges "'//trim(edges)//'"';  return
      end if
      if (all(inplane /= [character(len=16) :: 'immovable', 'movable'])) then
         stat = 1;  errmsg = 'boundary: unknown inplane "'//trim(inplane)//'"';  return
      end if

      grid_nodes: do j = 0, ngy - 1
         do i = 0, ngx - 1
            n = m%grid(i, j)
            ! outer edges: x = x1 always; x = x0 only on the full plate
            on_x_edge = i == ngx - 1 .or. (i == 0 .and. m%domain == 'full')
            on_y_edge = (j == ngy - 1 .and. m%domain /= 'strip') .or. (j == 0 .and. m%domain == 'full')
            if (on_x_edge .or. on_y_edge) then
               select case (edges)
               case ('clamped')
                  held(:, n) = .true.
               case ('simply_supported')
                  held(3, n) = .true.
                  if (on_x_edge) held(5, n) = .true.   ! psi_y along an x = const edge
                  if (on_y_edge) held(4, n) = .true.   ! psi_x along a y = const edge
                  if (inplane == 'immovable') held(1:2, n) = .true.
               end select
            end if
            if (m%domain /= 'full') then
               if (i == 0) held([1, 4], n) = .true.   ! symmetry about x = 0
               if (j == 0) held([2, 5], n) = .true.   ! symmetry about y = 0
            end if
            if (m%domain == 'strip' .and. j == ngy - 1) held([2, 5], n) = .true.   ! and about y = b/2
         end do
      end do grid_nodes

      if (allocated(m%eq)) deallocate (m%eq)
      if (allocated(m%elem_eq)) deallocate (m%elem_eq)
      allocate (m%eq(ndof_node, m%nnode), m%elem_eq(nfe, m%nelem))
      m%neq = 0
      number: do n = 1, m%nnode
         do k = 1, ndof_node
            if (held(k, n)) then
               m%eq(k, n) = 0
            else
               m%neq = m%neq + 1
               m%eq(k, n) = m%neq
            end if
         end do
      end do number
      elements: do e = 1, m%nelem
         m%elem_eq(:, e) = element_freedoms(m, e)
      end do elements
      if (m%eq(3, m%impact_node) == 0) then
         stat = 1
         errmsg = 'boundary: the impact point has its deflection w held'
      end if
   end subroutine apply_boundary

   !> Equation numbers of the 45 freedoms of element e, node by node
   !> (u, v, w, psi_x, psi_y of local node 1, then node 2, ...).
   pure function element_freedoms(m, e) result(eqs)
      type(mesh_t), intent(in) :: m   !< mesh with equation numbers
      integer, intent(in) :: e        !< element
      integer :: eqs(nfe)
      integer :: k
      do k = 1, nen
         eqs(ndof_node*(k-1)+1 : ndof_node*k) = m%eq(:, m%conn(k, e))
      end do
   end function element_freedoms

   !> Name of freedom k (1..5).
   pure function freedom_name(k) result(name)
      integer, intent(in) :: k   !< freedom index
      character(len=5) :: name
      name = dof_names(k)
   end function freedom_name

   !> A sentence naming equation ieq: its node, the node's position and the
   !> freedom (for a bad pivot, after Bathe's COLSOL).
   function describe_equation(m, ieq) result(text)
      type(mesh_t), intent(in) :: m   !< mesh with equation numbers
      integer, intent(in) :: ieq      !< equation number
      character(len=msg_len) :: text
      integer :: loc(2)
      text = ''
      if (ieq < 1 .or. ieq > m%neq) then
         write (text, '(a,i0,a)') 'equation ', ieq, ' (outside the system)'
         return
      end if
      loc = findloc(m%eq, ieq)
      write (text, '(a,i0,a,i0,a,es11.4,a,es11.4,a,a)') 'equation ', ieq, ': node ', loc(2), &
         ' at (x, y) = (', m%coords(1, loc(2)), ', ', m%coords(2, loc(2)), ') m, freedom ', &
         trim(dof_names(loc(1)))
   end function describe_equation

end module mesh
