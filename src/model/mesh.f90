!> Mesh, freedoms and boundary conditions (paper Fig. 4, section 2.4).
!> Coordinates from the plate centre; the modelled domain is a 'quarter',
!> 'half', 'full' plate or a 'strip' (cylindrical bending), the impact point
!> always a corner node, element sizes graded away from it (above
!> build_mesh). Freedoms per node, in this order everywhere (eq. 1):
!>    1 u,  2 v,  3 w,  4 psi_x,  5 psi_y;   w and z point the way the impactor moves.
!> Nodes are numbered first along the direction with fewer nodes (half-
!> bandwidth about 5 (2 min(nx,ny) + 2) + 4); eq(k, node) is the equation
!> of freedom k, 0 where held. The edges (clamped, simply supported, free)
!> and the symmetry lines: above apply_boundary. More: docs/MODEL.md.
module mesh
   use kinds, only: dp, msg_len
   use shape_functions, only: nen, node_xi
   implicit none
   private
   public :: mesh_t, mesh_layout_t, ndof_node, nfe, build_mesh, apply_boundary, freedom_name, describe_equation, &
             locate_point

   !> Freedoms per node (u, v, w, psi_x, psi_y).
   integer, parameter :: ndof_node = 5
   !> Freedoms per element.
   integer, parameter :: nfe = ndof_node*nen
   character(len=5), parameter :: dof_names(ndof_node) = &
      [character(len=5) :: 'u', 'v', 'w', 'psi_x', 'psi_y']

   !> The modelled domain and where its elements are finer (build_mesh).
   type :: mesh_layout_t
      character(len=:), allocatable :: domain !< 'quarter', 'half', 'full' or 'strip'
      real(dp) :: x0 = 0, y0 = 0              !< impact point from the plate centre (m)
      real(dp) :: grading = 1.0_dp            !< ratio of successive element sizes away from it (-): 1, uniform
      !> nx, ny are the quarter plate's counts, doubled where the domain spans
      !> both sides of a centre line (above build_mesh)
      logical :: quarter_counts = .false.
   end type mesh_layout_t

   !> The mesh of the modelled domain and its freedom map.
   type :: mesh_t
      integer :: nx = 0, ny = 0               !< elements along x and y
      integer :: nnode = 0, nelem = 0         !< nodes, elements
      integer :: neq = 0                      !< free freedoms (equations)
      character(len=16) :: domain = ''        !< 'quarter', 'half', 'full' or 'strip'
      real(dp) :: x0 = 0, x1 = 0, y0 = 0, y1 = 0   !< domain extent (m), from the plate centre
      logical :: sym_x = .false.              !< x = 0 is a symmetry line (x >= 0 modelled)
      logical :: sym_y = .false.              !< y = 0 is a symmetry line (y >= 0 modelled)
      real(dp) :: x_impact = 0, y_impact = 0  !< impact point from the plate centre (m)
      real(dp) :: grading = 1.0_dp            !< ratio of successive element sizes away from the impact point
      real(dp), allocatable :: coords(:,:)    !< (2, nnode) node coordinates (m)
      integer, allocatable :: conn(:,:)       !< (nen, nelem) element nodes
      integer, allocatable :: grid(:,:)       !< (0:2nx, 0:2ny) node number of grid point
      real(dp), allocatable :: xline(:)       !< (0:nx) x of the element corner lines (m), increasing
      real(dp), allocatable :: yline(:)       !< (0:ny) y of the element corner lines (m), increasing
      integer, allocatable :: eq(:,:)         !< (ndof_node, nnode) equation numbers
      integer, allocatable :: elem_eq(:,:)    !< (nfe, nelem) equation numbers of element freedoms
      integer :: impact_node = 0              !< node at the impact point
      integer :: impact_elem = 0              !< element nearest the impact point (for the strain gauge)
      real(dp) :: sym_factor = 1.0_dp         !< plate represented / plate modelled (4 quarter, 2 half)
   end type mesh_t

contains

   !> Coordinates are measured from the plate centre: the plate is
   !> -a/2 <= x <= a/2, -b/2 <= y <= b/2, and the impact point is (x_i, y_i)
   !> (&impactor x0, y0; the centre by default). The modelled domain is:
   !>  - 'quarter': 0 <= x <= a/2, 0 <= y <= b/2, the impact point at the
   !>    centre, the corner (0, 0); the lines x = 0 and y = 0 are symmetry lines
   !>    (section 2.4, 3.1);
   !>  - 'half': symmetric about one centre line through the impact point: about
   !>    y = 0 (the x axis; 0 <= y <= b/2 modelled) when y_i = 0, else about
   !>    x = 0 (the y axis; 0 <= x <= a/2 modelled), which needs x_i = 0; a
   !>    'half' at the centre is therefore the half y >= 0;
   !>  - 'full': the whole plate;
   !>  - 'strip': the quarter's rectangle, but y = b/2 is a symmetry line
   !>    too, so the model is a plate infinitely long along y in cylindrical
   !>    bending, of span a between its x edges (TWK Arts. 2-3; the
   !>    validation's strip). y = 0 and y = b/2 hold v and psi_y.
   !>
   !> Element counts and sizes: nx x ny elements on the modelled domain. The
   !> impact point is always a corner node of the elements around it (a node
   !> line runs through x_i and one through y_i): where the domain extends on
   !> both sides of it along x, the stretch of length L_lo below it gets
   !> n_lo = nint(nx L_lo/a) elements, at least 1 and at most nx - 1, and the
   !> stretch above the other nx - n_lo (nx >= 2 is needed; likewise along y).
   !> So a centred quarter nx x ny, half 2nx x ny and full 2nx x 2ny are
   !> mirror images of each other. With quarter_counts (the scene's 'auto'
   !> domain), nx and ny are read as the quarter plate's counts and doubled
   !> along each direction in which the domain spans both sides of a centre
   !> line, so the chosen domain keeps the quarter's element size. Within a
   !> stretch of n elements the sizes grow geometrically away from the impact
   !> point, s_k = s_1 g^(k-1), k = 1..n, with g = grading (1: uniform) and
   !> s_1 = L (g - 1)/(g^n - 1); a symmetry line is such a stretch's start.
   !> Mid-side and centre nodes sit at the middle of their element
   !> (straight-sided, affine elements).
   !>
   !> Lays out nodes and elements of the modelled domain (Fig. 4; the
   !> domains, element counts and grading as above).
   subroutine build_mesh(a, b, nx, ny, layout, m, stat, errmsg)
      real(dp), intent(in) :: a, b            !< plate size along x and y (m)
      integer, intent(in) :: nx, ny           !< elements along x and y of the domain (as above)
      type(mesh_layout_t), intent(in) :: layout   !< the domain, the impact point, the grading
      type(mesh_t), intent(out) :: m          !< the mesh
      integer, intent(out) :: stat            !< 0 on success
      character(len=*), intent(inout) :: errmsg  !< reason on failure
      real(dp), allocatable :: xl(:), yl(:)
      integer :: i, j, ie, je, e, k, n, ngx, ngy, ix, jy, ncx, ncy
      logical :: doubled
      real(dp) :: xi(2)

      stat = 0
      if (nx < 1 .or. ny < 1) then
         stat = 1
         write (errmsg, '(a,i0,a,i0)') 'mesh: needs at least one element each way, got nx = ', nx, ', ny = ', ny
         return
      end if
      associate (domain => layout%domain)
      m%x_impact = layout%x0;  m%y_impact = layout%y0;  m%grading = layout%grading
      if (abs(m%x_impact) >= 0.5_dp*a .or. abs(m%y_impact) >= 0.5_dp*b) then
         stat = 1
         write (errmsg, '(a,es11.4,a,es11.4,a)') 'mesh: the impact point (', m%x_impact, ', ', m%y_impact, &
            ') m is not inside the plate'
         return
      end if
      if (.not. (m%grading >= 1.0_dp)) then
         stat = 1
         write (errmsg, '(a,es11.4,a)') 'mesh: grading = ', m%grading, ' must be at least 1'
         return
      end if
      m%domain = domain
      select case (domain)
      case ('quarter', 'strip')
         m%sym_x = .true.;  m%sym_y = .true.
      case ('half')
         m%sym_y = m%y_impact == 0.0_dp          ! about y = 0 when possible (as above)
         m%sym_x = .not. m%sym_y
      case ('full')
         m%sym_x = .false.;  m%sym_y = .false.
      case default
         stat = 1
         errmsg = 'mesh: unknown domain "'//trim(domain)//'" (quarter, half, full or strip)'
         return
      end select
      if ((m%sym_x .and. m%x_impact /= 0.0_dp) .or. (m%sym_y .and. m%y_impact /= 0.0_dp)) then
         stat = 1
         write (errmsg, '(a,a,a,es11.4,a,es11.4,a)') 'mesh: domain "', trim(domain), &
            '" needs the impact point on its symmetry lines, got (', m%x_impact, ', ', m%y_impact, ') m'
         return
      end if
      m%sym_factor = merge(2.0_dp, 1.0_dp, m%sym_x)*merge(2.0_dp, 1.0_dp, m%sym_y)

      ! element counts of the domain
      doubled = layout%quarter_counts
      ncx = nx;  ncy = ny
      if (doubled .and. .not. m%sym_x) ncx = 2*nx
      if (doubled .and. .not. m%sym_y) ncy = 2*ny
      if ((ncx < 2 .and. .not. m%sym_x) .or. (ncy < 2 .and. .not. m%sym_y)) then
         stat = 1
         write (errmsg, '(a,i0,a,i0,a)') 'mesh: nx = ', ncx, ', ny = ', ncy, ': a domain that extends on both ' &
            // 'sides of the impact point needs at least 2 elements that way (one each side)'
         return
      end if

      ! element corner lines along x and y, the impact point on one of each
      call node_lines(0.5_dp*a, ncx, m%x_impact, m%sym_x, m%grading, xl, ix)
      call node_lines(0.5_dp*b, ncy, m%y_impact, m%sym_y, m%grading, yl, jy)
      m%nx = size(xl) - 1;  m%ny = size(yl) - 1
      m%x0 = xl(0);  m%x1 = xl(m%nx);  m%y0 = yl(0);  m%y1 = yl(m%ny)
      m%xline = xl;  m%yline = yl

      ngx = 2*m%nx + 1;  ngy = 2*m%ny + 1
      m%nnode = ngx*ngy
      m%nelem = m%nx*m%ny
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
            m%coords(:, n) = [0.5_dp*(xl(i/2) + xl(i - i/2)), 0.5_dp*(yl(j/2) + yl(j - j/2))]
         end do
      end do grid_nodes

      elements: do je = 0, m%ny - 1
         do ie = 0, m%nx - 1
            e = 1 + ie + m%nx*je
            do k = 1, nen
               xi = node_xi(k)
               m%conn(k, e) = m%grid(2*ie + 1 + nint(xi(1)), 2*je + 1 + nint(xi(2)))
            end do
         end do
      end do elements

      ! the impact point, and the element that has it as its lower-left
      ! corner (the +x, +y side: the quarter's first element)
      m%impact_node = m%grid(2*ix, 2*jy)
      m%impact_elem = 1 + ix + m%nx*jy
      end associate
   end subroutine build_mesh

   !> Element corner lines of one direction (above build_mesh): from the lower
   !> edge (or the symmetry line) to the upper edge, graded away from the
   !> impact point, which is line `at`.
   pure subroutine node_lines(half, n, p, sym, grading, lines, at)
      real(dp), intent(in) :: half              !< half the plate's size in this direction (m)
      integer, intent(in) :: n                  !< elements of the domain in this direction (>= 2 unless sym)
      real(dp), intent(in) :: p                 !< impact point coordinate from the centre (m)
      logical, intent(in) :: sym                !< the centre line is a symmetry line (p = 0)
      real(dp), intent(in) :: grading           !< ratio of successive element sizes (-)
      real(dp), allocatable, intent(out) :: lines(:)  !< (0:n) line coordinates (m), increasing
      integer, intent(out) :: at                !< index of the line through the impact point
      integer :: n_lo, n_hi

      n_lo = 0
      if (.not. sym) n_lo = min(max(1, nint(real(n, dp)*(half + p)/(2.0_dp*half))), n - 1)
      n_hi = n - n_lo
      allocate (lines(0:n))
      at = n_lo
      lines(n_lo:) = p + graded_offsets(half - p, n_hi, grading)
      if (.not. sym) lines(n_lo:0:-1) = p - graded_offsets(half + p, n_lo, grading)
      lines(n) = half          ! the edges exactly
      if (.not. sym) lines(0) = -half
   end subroutine node_lines

   !> Offsets 0 = d_0 < d_1 < ... < d_n = len of n elements whose sizes grow
   !> by the factor g: d_k - d_{k-1} = s_1 g^(k-1), s_1 = len (g-1)/(g^n-1)
   !> (len/n for g = 1).
   pure function graded_offsets(len, n, g) result(d)
      real(dp), intent(in) :: len   !< stretch length (m)
      integer, intent(in) :: n      !< elements
      real(dp), intent(in) :: g     !< ratio of successive sizes, >= 1
      real(dp) :: d(0:n)
      real(dp) :: s
      integer :: k
      if (g == 1.0_dp) then
         s = len/real(n, dp)
      else
         s = len*(g - 1.0_dp)/(g**n - 1.0_dp)
      end if
      d(0) = 0.0_dp
      do k = 1, n
         d(k) = d(k-1) + s*g**(k - 1)
      end do
      d(n) = len
   end function graded_offsets

   !> Boundary conditions (section 2.4; the in-plane condition of "simply
   !> supported" and the tangential rotation the paper leaves open, docs/MODEL.md,
   !> "Choices the paper leaves open"):
   !>  - 'clamped':          u = v = w = psi_x = psi_y = 0;
   !>  - 'simply_supported': w = 0 and the rotation along the edge psi_s = 0
   !>    (psi_y on x = const edges, psi_x on y = const edges: the "hard" simple
   !>    support of Navier's solution); in-plane 'immovable' also holds u = v = 0,
   !>    'movable' leaves them free;
   !>  - 'free':             nothing held;
   !>  - symmetry lines (quarter, half, strip): a mirror image about x = 0 has
   !>    u, psi_x odd and v, w, psi_y even in x, so x = 0 holds u and psi_x;
   !>    likewise y = 0 holds v and psi_y. Which laminates allow it is the
   !>    business of src/model/scene_model.f90.
   !>
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
            ! outer edges: x = x1 always; x = x0 unless it is a symmetry line
            on_x_edge = i == ngx - 1 .or. (i == 0 .and. .not. m%sym_x)
            on_y_edge = (j == ngy - 1 .and. m%domain /= 'strip') .or. (j == 0 .and. .not. m%sym_y)
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
            if (m%sym_x .and. i == 0) held([1, 4], n) = .true.   ! symmetry about x = 0
            if (m%sym_y .and. j == 0) held([2, 5], n) = .true.   ! symmetry about y = 0
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

   !> The element that holds the point p of the modelled domain, and p's
   !> reference coordinates (xi, eta) in it (the elements are straight-sided
   !> rectangles on the grid lines: above build_mesh). e = 0 when p lies
   !> outside the domain.
   pure subroutine locate_point(m, p, e, xi)
      type(mesh_t), intent(in) :: m       !< mesh
      real(dp), intent(in) :: p(2)        !< point (m), from the plate centre
      integer, intent(out) :: e           !< element, 0 when outside
      real(dp), intent(out) :: xi(2)      !< reference coordinates in [-1, 1]
      integer :: ie, je
      real(dp) :: lo(2), hi(2)
      e = 0;  xi = 0.0_dp
      ie = stretch(p(1), m%xline)
      je = stretch(p(2), m%yline)
      if (ie < 0 .or. je < 0) return
      e = 1 + ie + m%nx*je
      lo = [m%xline(ie), m%yline(je)];  hi = [m%xline(ie + 1), m%yline(je + 1)]
      xi = (2.0_dp*p - (lo + hi))/(hi - lo)
   contains
      !> The stretch k - 1 (from 0) between the increasing lines(k) and
      !> lines(k+1) that holds x, by bisection; -1 outside.
      pure function stretch(x, lines) result(k)
         real(dp), intent(in) :: x, lines(:)
         integer :: k
         integer :: lo_i, hi_i, mid
         k = -1
         if (x < lines(1) .or. x > lines(size(lines))) return
         lo_i = 1;  hi_i = size(lines)
         do while (hi_i - lo_i > 1)
            mid = (lo_i + hi_i)/2
            if (x >= lines(mid)) then
               lo_i = mid
            else
               hi_i = mid
            end if
         end do
         k = lo_i - 1
      end function stretch
   end subroutine locate_point

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
