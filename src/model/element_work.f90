!> The element work of a time step, all elements at once: the nonlinear
!> term K_N(D) D of eq. (19), the mass product M x (eq. 15, for M {b} of
!> eq. 20 and the kinetic energy) and the strain energy of the output steps.
!> The same sums as the element routines of src/model/element_matrices.f90
!> (tests/test_element_work.pf checks them), arranged so that the compiler
!> vectorises them: the elements are the inner, contiguous index of every
!> array, each loop runs over a block of elements. Rectangles share one
!> derivative table (above find_rectangles); M x uses the scalar mass S_ij
!> (above assemble_scalar_mass). Built once with the model (work_build);
!> then only read. More: docs/PERFORMANCE.md, "The element work of a step".
module element_work
   use kinds, only: dp
   use materials, only: laminate_t
   use mesh, only: mesh_t, ndof_node
   use shape_functions, only: nen
   use element_matrices, only: element_geometry_t, element_mass_integrals, ngp_full
   implicit none
   private
   public :: element_work_t, work_build, work_nonlinear_force, work_mass_times, work_mass_quadratic, &
             work_strain_energy

   !> Largest number of elements per block of the vectorised loops (a block's
   !> arrays stay in the cache); a mesh with fewer has one block of its own
   !> size (element_work_t%nblk).
   integer, parameter :: block = 64
   !> Shear rows per shear point (eps4, eps5) and element shear freedoms
   !> (w, psi_x, psi_y of the nine nodes).
   integer, parameter :: nrow_shear = 2, nfs = 3*nen

   !> What the element work needs, in the vectorised layout.
   type :: element_work_t
      integer :: nelem = 0, nnode = 0, neq = 0
      integer :: nblk = 1                         !< elements per block: min(block, nelem)
      type(laminate_t) :: lmt                     !< the laminate (A, B, D, Abar, P, R, I)
      logical :: coupled = .false.                !< B /= 0 (an unsymmetric laminate)
      integer, allocatable :: feq(:,:,:)          !< (nelem, nen, ndof_node) equations of the freedoms, 0 held
      real(dp), allocatable :: dx(:,:,:)          !< (nelem, ngp_full, nen) d phi / dx at the 3x3 points (1/m)
      real(dp), allocatable :: dy(:,:,:)          !< (nelem, ngp_full, nen) d phi / dy
      logical :: rectangles = .false.             !< every element a rectangle: dx = sx rdx, dy = sy rdy
      real(dp) :: rdx(ngp_full, nen) = 0.0_dp     !< d phi / d xi at the 3x3 points (the first element's, scaled)
      real(dp) :: rdy(ngp_full, nen) = 0.0_dp     !< d phi / d eta
      real(dp), allocatable :: sx(:), sy(:)       !< (nelem) 2/h_x, 2/h_y of each rectangle (1/m)
      real(dp) :: r(nen, 2*ngp_full) = 0.0_dp     !< [rdx^T | rdy^T]: gradients and forces are products with it
      real(dp) :: sref(nen, nen) = 0.0_dp         !< rectangles: the first element's S_ij; the others' are c(e) sref
      real(dp), allocatable :: c(:)               !< (nelem) their factors (the area ratio)
      real(dp), allocatable :: wj(:,:)            !< (nelem, ngp_full) weight * det J (m^2)
      integer :: npt = 0                          !< shear points per element
      real(dp), allocatable :: bs(:,:,:,:)        !< (nelem, npt, nrow_shear, nfs) shear operator
      real(dp), allocatable :: swj(:,:)           !< (nelem, npt) its weights (m^2)
      integer, allocatable :: s_start(:)          !< (nnode + 1) first entry of each row of S
      integer, allocatable :: s_col(:)            !< node of each entry
      real(dp), allocatable :: s_val(:)           !< S_ij (m^2)
   end type element_work_t

   interface
      !> BLAS: C = alpha op(A) op(B) + beta C.
      subroutine dgemm(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc)
         import :: dp
         character(len=1), intent(in) :: transa, transb
         integer, intent(in) :: m, n, k, lda, ldb, ldc
         real(dp), intent(in) :: alpha, beta, a(lda, *), b(ldb, *)
         real(dp), intent(inout) :: c(ldc, *)
      end subroutine dgemm
   end interface

contains

   !> The vectorised layout of the elements of mesh m with geometry geo, and
   !> the assembled scalar mass S.
   subroutine work_build(m, lmt, geo, w)
      type(mesh_t), intent(in) :: m                       !< mesh with equation numbers
      type(laminate_t), intent(in) :: lmt                 !< laminate
      type(element_geometry_t), intent(in) :: geo(:)      !< per-element geometry (module element_matrices)
      type(element_work_t), intent(out) :: w              !< the layout
      integer :: e, g, i, k, p

      w%nelem = m%nelem;  w%nnode = m%nnode;  w%neq = m%neq
      w%nblk = min(block, m%nelem)
      w%lmt = lmt
      w%coupled = any(lmt%b /= 0.0_dp)
      w%npt = geo(1)%shear%npoint
      allocate (w%feq(w%nelem, nen, ndof_node), w%dx(w%nelem, ngp_full, nen), w%dy(w%nelem, ngp_full, nen), &
                w%wj(w%nelem, ngp_full), w%bs(w%nelem, w%npt, nrow_shear, nfs), w%swj(w%nelem, w%npt))
      elements: do e = 1, w%nelem
         do k = 1, ndof_node
            do i = 1, nen
               w%feq(e, i, k) = m%eq(k, m%conn(i, e))
            end do
         end do
         do i = 1, nen
            do g = 1, ngp_full
               w%dx(e, g, i) = geo(e)%dx3(1, i, g)
               w%dy(e, g, i) = geo(e)%dx3(2, i, g)
            end do
         end do
         w%wj(e, :) = geo(e)%wj3
         do p = 1, w%npt
            do i = 1, nen
               do k = 1, 3          ! w, psi_x, psi_y
                  w%bs(e, p, :, (k - 1)*nen + i) = geo(e)%shear%b(:, k, i, p)
               end do
            end do
            w%swj(e, p) = geo(e)%shear%wj(p)
         end do
      end do elements
      call find_rectangles(w)
      allocate (w%c(w%nelem))
      w%sref = element_mass_integrals(geo(1))
      do e = 1, w%nelem
         w%c(e) = sum(w%wj(e, :))/sum(w%wj(1, :))
         if (w%rectangles) w%rectangles = all(abs(element_mass_integrals(geo(e)) - w%c(e)*w%sref) &
                                              <= 1.0e-12_dp*w%c(e)*maxval(abs(w%sref)))
      end do
      call assemble_scalar_mass(m, geo, w)
   end subroutine work_build

   !> The mesh's elements are rectangles (src/model/mesh.f90: straight grid lines,
   !> mid-side nodes halfway): then d phi/dx = 2/h_x d phi/d xi at every Gauss
   !> point, the same 9 x 9 table for every element times its own factor, and
   !> the gradients and the nodal forces of a block of elements are each one
   !> matrix product with that table (BLAS dgemm: the five fields of all the
   !> block's elements at once). work_build checks it, element by element,
   !> and otherwise keeps each element's own derivatives.
   !>
   !> Whether every element's derivatives are one table scaled by its own
   !> factors, dx(e, :, :) = sx(e) rdx, dy(e, :, :) = sy(e) rdy, to rounding
   !> (as above). The table is the first element's with
   !> its factor taken out: the largest |dx| of an element is sx times the
   !> largest |d phi/d xi| at the 3x3 points, the same for all.
   subroutine find_rectangles(w)
      type(element_work_t), intent(inout) :: w
      real(dp), parameter :: same = 1.0e-12_dp     ! relative rounding of two equal derivative tables
      integer :: e
      allocate (w%sx(w%nelem), w%sy(w%nelem))
      do e = 1, w%nelem
         w%sx(e) = maxval(abs(w%dx(e, :, :)))/maxval(abs(w%dx(1, :, :)))
         w%sy(e) = maxval(abs(w%dy(e, :, :)))/maxval(abs(w%dy(1, :, :)))
      end do
      w%rdx = w%dx(1, :, :);  w%rdy = w%dy(1, :, :)
      w%r(:, :ngp_full) = transpose(w%rdx);  w%r(:, ngp_full+1:) = transpose(w%rdy)
      w%rectangles = .true.
      do e = 1, w%nelem
         w%rectangles = w%rectangles .and. all(abs(w%dx(e, :, :) - w%sx(e)*w%rdx) <= same*w%sx(e)*maxval(abs(w%rdx))) &
                                     .and. all(abs(w%dy(e, :, :) - w%sy(e)*w%rdy) <= same*w%sy(e)*maxval(abs(w%rdy)))
      end do
   end subroutine find_rectangles

   !> M x uses the assembled scalar mass S_ij = int phi_i phi_j dA over the
   !> nodes (compressed rows): the consistent mass matrix is P S, R S and I S
   !> on the freedoms (Appendix B), so M x is one product of S with the five
   !> fields at once, without the zeros inside the band of [M].
   !>
   !> S_ij = sum over elements of int phi_i phi_j dA, in compressed rows:
   !> for each node the nodes of its elements (marked once each).
   subroutine assemble_scalar_mass(m, geo, w)
      type(mesh_t), intent(in) :: m
      type(element_geometry_t), intent(in) :: geo(:)
      type(element_work_t), intent(inout) :: w
      integer, allocatable :: elem_start(:), elem_list(:), slot(:)
      real(dp) :: s(nen, nen)
      integer :: e, i, j, n, pass, nnz, k, ke, row

      ! -- the elements of each node
      allocate (elem_start(m%nnode + 1), elem_list(nen*m%nelem), slot(m%nnode))
      elem_start = 0
      do e = 1, m%nelem
         do i = 1, nen
            elem_start(m%conn(i, e) + 1) = elem_start(m%conn(i, e) + 1) + 1
         end do
      end do
      elem_start(1) = 1
      do n = 1, m%nnode
         elem_start(n + 1) = elem_start(n + 1) + elem_start(n)
      end do
      slot = elem_start(:m%nnode)
      do e = 1, m%nelem
         do i = 1, nen
            elem_list(slot(m%conn(i, e))) = e
            slot(m%conn(i, e)) = slot(m%conn(i, e)) + 1
         end do
      end do
      ! -- two passes: count the entries of each row, then fill them
      allocate (w%s_start(m%nnode + 1))
      slot = 0                        ! slot(j): position of node j in the current row, 0 none
      passes: do pass = 1, 2
         nnz = 0
         rows: do row = 1, m%nnode
            if (pass == 2) w%s_start(row) = nnz + 1
            k = nnz
            do ke = elem_start(row), elem_start(row + 1) - 1
               e = elem_list(ke)
               if (pass == 2) s = element_mass_integrals(geo(e))
               i = findloc(m%conn(:, e), row, dim=1)
               do j = 1, nen
                  n = m%conn(j, e)
                  if (slot(n) == 0) then
                     k = k + 1
                     slot(n) = k
                     if (pass == 2) then
                        w%s_col(k) = n;  w%s_val(k) = 0.0_dp
                     end if
                  end if
                  if (pass == 2) w%s_val(slot(n)) = w%s_val(slot(n)) + s(i, j)
               end do
            end do
            ! clear the marks of this row
            if (pass == 1) then
               do ke = elem_start(row), elem_start(row + 1) - 1
                  slot(m%conn(:, elem_list(ke))) = 0
               end do
            else
               slot(w%s_col(nnz + 1:k)) = 0
            end if
            nnz = k
         end do rows
         if (pass == 1) allocate (w%s_col(nnz), w%s_val(nnz))
      end do passes
      w%s_start(m%nnode + 1) = nnz + 1
   end subroutine assemble_scalar_mass

   !> y = M x (the consistent mass of eq. 15), by the scalar mass S: for
   !> rectangles element by element, S_e = c(e) sref (one product for a
   !> block of elements); otherwise with the assembled S.
   subroutine work_mass_times(w, m, x, y)
      type(element_work_t), intent(in) :: w   !< the layout
      type(mesh_t), intent(in) :: m           !< mesh with equation numbers
      real(dp), intent(in) :: x(:)            !< global vector
      real(dp), intent(out) :: y(:)           !< M x
      real(dp) :: xn(ndof_node, w%nnode), sx(ndof_node)
      real(dp) :: x0(0:w%neq), y0(0:w%neq)
      real(dp), dimension(w%nblk, ndof_node, nen) :: xe, ye
      integer :: n, k, q, e0, nb

      if (w%rectangles) then
         x0(0) = 0.0_dp;  x0(1:) = x
         y0 = 0.0_dp
         xe = 0.0_dp
         blocks: do e0 = 1, w%nelem, w%nblk
            nb = min(w%nblk, w%nelem - e0 + 1)
            call gather(w, x0, e0, nb, xe)
            call block_mass_times(w, e0, nb, xe, ye)
            call scatter_add(w, e0, nb, ye, y0)
         end do blocks
         y = y0(1:)
         return
      end if

      do n = 1, w%nnode
         do k = 1, ndof_node
            xn(k, n) = 0.0_dp
            if (m%eq(k, n) > 0) xn(k, n) = x(m%eq(k, n))
         end do
      end do
      nodes: do n = 1, w%nnode
         sx = 0.0_dp
         do q = w%s_start(n), w%s_start(n + 1) - 1
            sx = sx + w%s_val(q)*xn(:, w%s_col(q))
         end do
         if (m%eq(1, n) > 0) y(m%eq(1, n)) = w%lmt%p*sx(1) + w%lmt%r*sx(4)
         if (m%eq(2, n) > 0) y(m%eq(2, n)) = w%lmt%p*sx(2) + w%lmt%r*sx(5)
         if (m%eq(3, n) > 0) y(m%eq(3, n)) = w%lmt%p*sx(3)
         if (m%eq(4, n) > 0) y(m%eq(4, n)) = w%lmt%i*sx(4) + w%lmt%r*sx(1)
         if (m%eq(5, n) > 0) y(m%eq(5, n)) = w%lmt%i*sx(5) + w%lmt%r*sx(2)
      end do nodes
   end subroutine work_mass_times

   !> x^T M x (for x the velocities, twice the kinetic energy, not yet
   !> times the symmetry factor): on rectangles the sum of x_e^T M_e x_e
   !> over the elements, without assembling M x; otherwise from M x.
   function work_mass_quadratic(w, m, x) result(q)
      type(element_work_t), intent(in) :: w   !< the layout
      type(mesh_t), intent(in) :: m           !< mesh with equation numbers
      real(dp), intent(in) :: x(:)            !< global vector
      real(dp) :: q
      real(dp) :: x0(0:w%neq), y(size(x))
      real(dp), dimension(w%nblk, ndof_node, nen) :: xe, ye
      integer :: e0, nb

      if (.not. w%rectangles) then
         call work_mass_times(w, m, x, y)
         q = dot_product(x, y)
         return
      end if
      x0(0) = 0.0_dp;  x0(1:) = x
      xe = 0.0_dp
      q = 0.0_dp
      blocks: do e0 = 1, w%nelem, w%nblk
         nb = min(w%nblk, w%nelem - e0 + 1)
         call gather(w, x0, e0, nb, xe)
         call block_mass_times(w, e0, nb, xe, ye)
         q = q + sum(xe(:nb, :, :)*ye(:nb, :, :))
      end do blocks
   end function work_mass_quadratic

   !> fn = K_N(d) d, the nonlinear term of eq. (19) (module element_matrices,
   !> element_nonlinear_force, for the formulas).
   subroutine work_nonlinear_force(w, d, fn)
      type(element_work_t), intent(in) :: w   !< the layout
      real(dp), intent(in) :: d(:)            !< global displacements
      real(dp), intent(out) :: fn(:)          !< K_N(d) d
      real(dp) :: dp0(0:w%neq), fp0(0:w%neq)
      real(dp), dimension(w%nblk, ndof_node, nen) :: de, fe
      real(dp) :: gr(w%nblk, ndof_node, 2*ngp_full), fl(w%nblk, ndof_node, 2*ngp_full)
      real(dp), dimension(w%nblk, ngp_full) :: ux, uy, vx, vy, wx, wy, px_x, px_y, py_x, py_y, &
         e1, e2, e3, k1, k2, k3, n1, n2, n3, a1, a2, a3, b1, b2, b3, wj
      real(dp) :: a(3,3), b(3,3)
      integer :: e0, nb, nf, x1, x2, y1, y2

      a = w%lmt%a;  b = w%lmt%b
      nf = merge(ndof_node, 3, w%coupled)
      x1 = 1;  x2 = ngp_full;  y1 = ngp_full + 1;  y2 = 2*ngp_full
      dp0(0) = 0.0_dp;  dp0(1:) = d
      fp0 = 0.0_dp
      de = 0.0_dp;  fl = 0.0_dp
      blocks: do e0 = 1, w%nelem, w%nblk
         nb = min(w%nblk, w%nelem - e0 + 1)
         call gather(w, dp0, e0, nb, de)
         ! -- slopes and membrane strains at the Gauss points (u, v, w; psi too when B /= 0)
         call gradients(w, e0, nb, nf, de, gr)
         ux(:nb, :) = gr(:nb, 1, x1:x2);  uy(:nb, :) = gr(:nb, 1, y1:y2)
         vx(:nb, :) = gr(:nb, 2, x1:x2);  vy(:nb, :) = gr(:nb, 2, y1:y2)
         wx(:nb, :) = gr(:nb, 3, x1:x2);  wy(:nb, :) = gr(:nb, 3, y1:y2)
         wj(:nb, :) = w%wj(e0:e0+nb-1, :)
         e1(:nb, :) = ux(:nb, :) + 0.5_dp*wx(:nb, :)**2
         e2(:nb, :) = vy(:nb, :) + 0.5_dp*wy(:nb, :)**2
         e3(:nb, :) = uy(:nb, :) + vx(:nb, :) + wx(:nb, :)*wy(:nb, :)
         ! -- the membrane force of eps_nl, A eps_nl, and the whole N = A eps0 + B kappa (eq. 2, 4), times w j
         k1(:nb, :) = 0.5_dp*wx(:nb, :)**2;  k2(:nb, :) = 0.5_dp*wy(:nb, :)**2;  k3(:nb, :) = wx(:nb, :)*wy(:nb, :)
         a1(:nb, :) = wj(:nb, :)*(a(1,1)*k1(:nb, :) + a(1,2)*k2(:nb, :) + a(1,3)*k3(:nb, :))
         a2(:nb, :) = wj(:nb, :)*(a(2,1)*k1(:nb, :) + a(2,2)*k2(:nb, :) + a(2,3)*k3(:nb, :))
         a3(:nb, :) = wj(:nb, :)*(a(3,1)*k1(:nb, :) + a(3,2)*k2(:nb, :) + a(3,3)*k3(:nb, :))
         n1(:nb, :) = wj(:nb, :)*(a(1,1)*e1(:nb, :) + a(1,2)*e2(:nb, :) + a(1,3)*e3(:nb, :))
         n2(:nb, :) = wj(:nb, :)*(a(2,1)*e1(:nb, :) + a(2,2)*e2(:nb, :) + a(2,3)*e3(:nb, :))
         n3(:nb, :) = wj(:nb, :)*(a(3,1)*e1(:nb, :) + a(3,2)*e2(:nb, :) + a(3,3)*e3(:nb, :))
         if (w%coupled) then
            px_x(:nb, :) = gr(:nb, 4, x1:x2);  px_y(:nb, :) = gr(:nb, 4, y1:y2)
            py_x(:nb, :) = gr(:nb, 5, x1:x2);  py_y(:nb, :) = gr(:nb, 5, y1:y2)
            n1(:nb, :) = n1(:nb, :) + wj(:nb, :)*(b(1,1)*px_x(:nb, :) + b(1,2)*py_y(:nb, :) &
                                                  + b(1,3)*(px_y(:nb, :) + py_x(:nb, :)))
            n2(:nb, :) = n2(:nb, :) + wj(:nb, :)*(b(2,1)*px_x(:nb, :) + b(2,2)*py_y(:nb, :) &
                                                  + b(2,3)*(px_y(:nb, :) + py_x(:nb, :)))
            n3(:nb, :) = n3(:nb, :) + wj(:nb, :)*(b(3,1)*px_x(:nb, :) + b(3,2)*py_y(:nb, :) &
                                                  + b(3,3)*(px_y(:nb, :) + py_x(:nb, :)))
            b1(:nb, :) = wj(:nb, :)*(b(1,1)*k1(:nb, :) + b(1,2)*k2(:nb, :) + b(1,3)*k3(:nb, :))
            b2(:nb, :) = wj(:nb, :)*(b(2,1)*k1(:nb, :) + b(2,2)*k2(:nb, :) + b(2,3)*k3(:nb, :))
            b3(:nb, :) = wj(:nb, :)*(b(3,1)*k1(:nb, :) + b(3,2)*k2(:nb, :) + b(3,3)*k3(:nb, :))
            fl(:nb, 4, x1:x2) = b1(:nb, :);  fl(:nb, 4, y1:y2) = b3(:nb, :)
            fl(:nb, 5, x1:x2) = b3(:nb, :);  fl(:nb, 5, y1:y2) = b2(:nb, :)
         end if
         ! -- the forces: Bm^T (A eps_nl) on u, v; Bnl^T N on w; Bb^T (B eps_nl) on psi
         fl(:nb, 1, x1:x2) = a1(:nb, :);  fl(:nb, 1, y1:y2) = a3(:nb, :)
         fl(:nb, 2, x1:x2) = a3(:nb, :);  fl(:nb, 2, y1:y2) = a2(:nb, :)
         fl(:nb, 3, x1:x2) = wx(:nb, :)*n1(:nb, :) + wy(:nb, :)*n3(:nb, :)
         fl(:nb, 3, y1:y2) = wy(:nb, :)*n2(:nb, :) + wx(:nb, :)*n3(:nb, :)
         call forces(w, e0, nb, nf, fl, fe)
         call scatter_add(w, e0, nb, fe, fp0)
      end do blocks
      fn = fp0(1:)
   end subroutine work_nonlinear_force

   !> Strain energy of the model (J, not yet times the symmetry factor), von
   !> Karman strains when nonlinear (module element_matrices,
   !> element_strain_energy, for the formulas).
   function work_strain_energy(w, d, nonlinear) result(u)
      type(element_work_t), intent(in) :: w   !< the layout
      real(dp), intent(in) :: d(:)            !< global displacements
      logical, intent(in) :: nonlinear        !< von Karman strains
      real(dp) :: u
      real(dp) :: dp0(0:w%neq)
      real(dp), dimension(w%nblk, ndof_node, nen) :: de
      real(dp) :: gr(w%nblk, ndof_node, 2*ngp_full)
      real(dp), dimension(w%nblk, ngp_full) :: ux, uy, vx, vy, wx, wy, px_x, px_y, py_x, py_y, &
         e1, e2, e3, k1, k2, k3, dens
      real(dp), dimension(w%nblk) :: g4, g5, sdens
      real(dp) :: a(3,3), b(3,3), dd(3,3), as(2,2)
      integer :: e0, nb, p, j, x1, x2, y1, y2

      a = w%lmt%a;  b = w%lmt%b;  dd = w%lmt%d;  as = w%lmt%as
      x1 = 1;  x2 = ngp_full;  y1 = ngp_full + 1;  y2 = 2*ngp_full
      dp0(0) = 0.0_dp;  dp0(1:) = d
      u = 0.0_dp
      de = 0.0_dp
      blocks: do e0 = 1, w%nelem, w%nblk
         nb = min(w%nblk, w%nelem - e0 + 1)
         call gather(w, dp0, e0, nb, de)
         call gradients(w, e0, nb, ndof_node, de, gr)
         ux(:nb, :) = gr(:nb, 1, x1:x2);  uy(:nb, :) = gr(:nb, 1, y1:y2)
         vx(:nb, :) = gr(:nb, 2, x1:x2);  vy(:nb, :) = gr(:nb, 2, y1:y2)
         wx(:nb, :) = gr(:nb, 3, x1:x2);  wy(:nb, :) = gr(:nb, 3, y1:y2)
         px_x(:nb, :) = gr(:nb, 4, x1:x2);  px_y(:nb, :) = gr(:nb, 4, y1:y2)
         py_x(:nb, :) = gr(:nb, 5, x1:x2);  py_y(:nb, :) = gr(:nb, 5, y1:y2)
         e1(:nb, :) = ux(:nb, :);  e2(:nb, :) = vy(:nb, :);  e3(:nb, :) = uy(:nb, :) + vx(:nb, :)
         if (nonlinear) then
            e1(:nb, :) = e1(:nb, :) + 0.5_dp*wx(:nb, :)**2
            e2(:nb, :) = e2(:nb, :) + 0.5_dp*wy(:nb, :)**2
            e3(:nb, :) = e3(:nb, :) + wx(:nb, :)*wy(:nb, :)
         end if
         k1(:nb, :) = px_x(:nb, :);  k2(:nb, :) = py_y(:nb, :);  k3(:nb, :) = px_y(:nb, :) + py_x(:nb, :)
         ! eps0 A eps0 + 2 eps0 B kappa + kappa D kappa (von Karman eps0, eq. 2; A, B, D of eq. 4), at every Gauss point
         dens(:nb, :) = quad(a, e1, e2, e3, e1, e2, e3) + 2.0_dp*quad(b, e1, e2, e3, k1, k2, k3) &
                        + quad(dd, k1, k2, k3, k1, k2, k3)
         u = u + 0.5_dp*sum(w%wj(e0:e0+nb-1, :)*dens(:nb, :))
         ! -- transverse shear, by the element's rule
         shear_points: do p = 1, w%npt
            g4(:nb) = 0.0_dp;  g5(:nb) = 0.0_dp
            do j = 1, nen
               g4(:nb) = g4(:nb) + w%bs(e0:e0+nb-1, p, 1, j)*de(:nb, 3, j) &
                         + w%bs(e0:e0+nb-1, p, 1, nen + j)*de(:nb, 4, j) &
                         + w%bs(e0:e0+nb-1, p, 1, 2*nen + j)*de(:nb, 5, j)
               g5(:nb) = g5(:nb) + w%bs(e0:e0+nb-1, p, 2, j)*de(:nb, 3, j) &
                         + w%bs(e0:e0+nb-1, p, 2, nen + j)*de(:nb, 4, j) &
                         + w%bs(e0:e0+nb-1, p, 2, 2*nen + j)*de(:nb, 5, j)
            end do
            sdens(:nb) = as(1,1)*g4(:nb)**2 + (as(1,2) + as(2,1))*g4(:nb)*g5(:nb) + as(2,2)*g5(:nb)**2
            u = u + 0.5_dp*sum(w%swj(e0:e0+nb-1, p)*sdens(:nb))
         end do shear_points
      end do blocks

   contains

      !> x^T c y at every Gauss point of the block, x = (x1, x2, x3), y likewise.
      pure function quad(c, x1, x2, x3, y1, y2, y3) result(v)
         real(dp), intent(in) :: c(3,3)
         real(dp), intent(in), dimension(w%nblk, ngp_full) :: x1, x2, x3, y1, y2, y3
         real(dp) :: v(nb, ngp_full)
         v = x1(:nb, :)*(c(1,1)*y1(:nb, :) + c(1,2)*y2(:nb, :) + c(1,3)*y3(:nb, :)) &
           + x2(:nb, :)*(c(2,1)*y1(:nb, :) + c(2,2)*y2(:nb, :) + c(2,3)*y3(:nb, :)) &
           + x3(:nb, :)*(c(3,1)*y1(:nb, :) + c(3,2)*y2(:nb, :) + c(3,3)*y3(:nb, :))
      end function quad

   end function work_strain_energy

   ! ============================================================== kernels

   !> ye = M_e xe for the block's elements e0 .. e0+nb-1 of a mesh of
   !> rectangles: c(e) sref on each field, mixed by P, R and I (Appendix B).
   subroutine block_mass_times(w, e0, nb, xe, ye)
      type(element_work_t), intent(in) :: w   !< the layout
      integer, intent(in) :: e0, nb           !< the block's first element and size
      real(dp), intent(in) :: xe(w%nblk, ndof_node, nen)    !< the element values
      real(dp), intent(out) :: ye(w%nblk, ndof_node, nen)   !< M_e xe (rows 1 .. nb)
      real(dp) :: se(w%nblk, ndof_node, nen)
      integer :: i, k
      call dgemm('N', 'N', w%nblk*ndof_node, nen, nen, 1.0_dp, xe, w%nblk*ndof_node, w%sref, nen, &
                 0.0_dp, se, w%nblk*ndof_node)
      do i = 1, nen
         do k = 1, ndof_node
            se(:nb, k, i) = w%c(e0:e0+nb-1)*se(:nb, k, i)
         end do
         ye(:nb, 1, i) = w%lmt%p*se(:nb, 1, i) + w%lmt%r*se(:nb, 4, i)
         ye(:nb, 2, i) = w%lmt%p*se(:nb, 2, i) + w%lmt%r*se(:nb, 5, i)
         ye(:nb, 3, i) = w%lmt%p*se(:nb, 3, i)
         ye(:nb, 4, i) = w%lmt%i*se(:nb, 4, i) + w%lmt%r*se(:nb, 1, i)
         ye(:nb, 5, i) = w%lmt%i*se(:nb, 5, i) + w%lmt%r*se(:nb, 2, i)
      end do
   end subroutine block_mass_times

   !> The element values of the block's elements e0 .. e0+nb-1 from the
   !> global vector d0 (index 0 holds the 0 of the held freedoms).
   subroutine gather(w, d0, e0, nb, de)
      type(element_work_t), intent(in) :: w
      real(dp), intent(in) :: d0(0:)
      integer, intent(in) :: e0, nb
      real(dp), intent(inout) :: de(w%nblk, ndof_node, nen)
      integer :: i, k
      do i = 1, nen
         do k = 1, ndof_node
            de(:nb, k, i) = d0(w%feq(e0:e0+nb-1, i, k))
         end do
      end do
   end subroutine gather

   !> Adds the element forces fe of the block into the global vector f0
   !> (index 0 collects the held freedoms' share, dropped).
   subroutine scatter_add(w, e0, nb, fe, f0)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb
      real(dp), intent(in) :: fe(w%nblk, ndof_node, nen)
      real(dp), intent(inout) :: f0(0:)
      integer :: i, k, e
      do i = 1, nen
         do k = 1, ndof_node
            do e = 1, nb
               f0(w%feq(e0 + e - 1, i, k)) = f0(w%feq(e0 + e - 1, i, k)) + fe(e, k, i)
            end do
         end do
      end do
   end subroutine scatter_add

   !> The x and y derivatives of the first nf fields at the Gauss points:
   !> gr(e, k, g) = d/dx of field k at point g, gr(e, k, ngp_full + g) =
   !> d/dy. Rectangles: one product of the block's values with the table r
   !> (the first nf fields are the first nf nblk rows), then each element's
   !> factors.
   subroutine gradients(w, e0, nb, nf, de, gr)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb, nf
      real(dp), intent(in) :: de(w%nblk, ndof_node, nen)
      real(dp), intent(out) :: gr(w%nblk, ndof_node, 2*ngp_full)
      integer :: g, i, k
      if (w%rectangles) then
         call dgemm('N', 'N', w%nblk*nf, 2*ngp_full, nen, 1.0_dp, de, w%nblk*ndof_node, w%r, nen, &
                    0.0_dp, gr, w%nblk*ndof_node)
         do g = 1, ngp_full
            do k = 1, nf
               gr(:nb, k, g) = w%sx(e0:e0+nb-1)*gr(:nb, k, g)
               gr(:nb, k, ngp_full + g) = w%sy(e0:e0+nb-1)*gr(:nb, k, ngp_full + g)
            end do
         end do
         return
      end if
      do g = 1, ngp_full
         do k = 1, nf
            gr(:nb, k, g) = 0.0_dp;  gr(:nb, k, ngp_full + g) = 0.0_dp
            do i = 1, nen
               gr(:nb, k, g) = gr(:nb, k, g) + w%dx(e0:e0+nb-1, g, i)*de(:nb, k, i)
               gr(:nb, k, ngp_full + g) = gr(:nb, k, ngp_full + g) + w%dy(e0:e0+nb-1, g, i)*de(:nb, k, i)
            end do
         end do
      end do
   end subroutine gradients

   !> The nodal forces fe(e, k, i) = sum_g (d phi_i/dx fl(e, k, g) + d phi_i/dy
   !> fl(e, k, ngp_full + g)) of the fluxes fl of the first nf fields at the
   !> Gauss points (weights already in them); the other fields' are 0.
   !> Rectangles: each element's factors, then one product with the table
   !> r. fl is scaled in place.
   subroutine forces(w, e0, nb, nf, fl, fe)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb, nf
      real(dp), intent(inout) :: fl(w%nblk, ndof_node, 2*ngp_full)
      real(dp), intent(out) :: fe(w%nblk, ndof_node, nen)
      integer :: g, i, k
      fe(:, nf+1:, :) = 0.0_dp
      if (w%rectangles) then
         do g = 1, ngp_full
            do k = 1, nf
               fl(:nb, k, g) = w%sx(e0:e0+nb-1)*fl(:nb, k, g)
               fl(:nb, k, ngp_full + g) = w%sy(e0:e0+nb-1)*fl(:nb, k, ngp_full + g)
            end do
         end do
         call dgemm('N', 'T', w%nblk*nf, nen, 2*ngp_full, 1.0_dp, fl, w%nblk*ndof_node, w%r, nen, &
                    0.0_dp, fe, w%nblk*ndof_node)
         return
      end if
      do i = 1, nen
         do k = 1, nf
            fe(:nb, k, i) = 0.0_dp
            do g = 1, ngp_full
               fe(:nb, k, i) = fe(:nb, k, i) + w%dx(e0:e0+nb-1, g, i)*fl(:nb, k, g) &
                               + w%dy(e0:e0+nb-1, g, i)*fl(:nb, k, ngp_full + g)
            end do
         end do
      end do
   end subroutine forces

end module element_work
