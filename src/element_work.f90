!> The element work of a time step, all elements at once: the nonlinear
!> term K_N(D) D of eq. (19), the mass product M x (eq. 15, for M {b} of
!> eq. 20 and the kinetic energy) and the strain energy of the output steps.
!> The same sums as the element routines of module element_matrices (whose
!> formulas they follow, and against which test_element_work checks them),
!> arranged so that the compiler vectorises them: the elements are the
!> inner, contiguous index of every array, and each loop runs over a block
!> of elements with the Gauss points and nodes outside. One pass gathers
!> the element values, computes the strains at all Gauss points of the
!> block, and scatters the forces back (docs/PERFORMANCE.md, "The element
!> work of a step").
!>
!> M x uses the assembled scalar mass S_ij = int phi_i phi_j dA over the
!> nodes (compressed rows): the consistent mass matrix is P S, R S and I S
!> on the freedoms (Appendix B), so M x is one product of S with the five
!> fields at once, without the zeros inside the band of [M].
!>
!> Built once with the model (work_build); then only read.
module element_work
   use kinds, only: dp
   use materials, only: laminate_t
   use mesh, only: mesh_t, ndof_node
   use shape_functions, only: nen
   use element_matrices, only: element_geometry_t, element_mass_integrals, ngp_full
   implicit none
   private
   public :: element_work_t, work_build, work_nonlinear_force, work_mass_times, work_strain_energy

   !> Elements per block of the vectorised loops (a block's arrays stay in
   !> the first-level cache).
   integer, parameter :: block = 64
   !> Shear rows per shear point (eps4, eps5) and element shear freedoms
   !> (w, psi_x, psi_y of the nine nodes).
   integer, parameter :: nrow_shear = 2, nfs = 3*nen

   !> What the element work needs, in the vectorised layout.
   type :: element_work_t
      integer :: nelem = 0, nnode = 0, neq = 0
      type(laminate_t) :: lmt                     !< the laminate (A, B, D, Abar, P, R, I)
      logical :: coupled = .false.                !< B /= 0 (an unsymmetric laminate)
      integer, allocatable :: feq(:,:,:)          !< (nelem, nen, ndof_node) equations of the freedoms, 0 held
      real(dp), allocatable :: dx(:,:,:)          !< (nelem, ngp_full, nen) d phi / dx at the 3x3 points (1/m)
      real(dp), allocatable :: dy(:,:,:)          !< (nelem, ngp_full, nen) d phi / dy
      real(dp), allocatable :: wj(:,:)            !< (nelem, ngp_full) weight * det J (m^2)
      integer :: npt = 0                          !< shear points per element
      real(dp), allocatable :: bs(:,:,:,:)        !< (nelem, npt, nrow_shear, nfs) shear operator
      real(dp), allocatable :: swj(:,:)           !< (nelem, npt) its weights (m^2)
      integer, allocatable :: s_start(:)          !< (nnode + 1) first entry of each row of S
      integer, allocatable :: s_col(:)            !< node of each entry
      real(dp), allocatable :: s_val(:)           !< S_ij (m^2)
   end type element_work_t

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
      call assemble_scalar_mass(m, geo, w)
   end subroutine work_build

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

   !> y = M x (the consistent mass of eq. 15), by the scalar mass S.
   subroutine work_mass_times(w, m, x, y)
      type(element_work_t), intent(in) :: w   !< the layout
      type(mesh_t), intent(in) :: m           !< mesh with equation numbers
      real(dp), intent(in) :: x(:)            !< global vector
      real(dp), intent(out) :: y(:)           !< M x
      real(dp) :: xn(ndof_node, w%nnode), sx(ndof_node)
      integer :: n, k, q

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

   !> fn = K_N(d) d, the nonlinear term of eq. (19) (module element_matrices,
   !> element_nonlinear_force, for the formulas).
   subroutine work_nonlinear_force(w, d, fn)
      type(element_work_t), intent(in) :: w   !< the layout
      real(dp), intent(in) :: d(:)            !< global displacements
      real(dp), intent(out) :: fn(:)          !< K_N(d) d
      real(dp) :: dp0(0:w%neq), fp0(0:w%neq)
      real(dp), dimension(block, nen, ndof_node) :: de, fe
      real(dp), dimension(block, ngp_full) :: ux, uy, vx, vy, wx, wy, px_x, px_y, py_x, py_y, &
         e1, e2, e3, k1, k2, k3, n1, n2, n3, a1, a2, a3, b1, b2, b3, qx, qy
      real(dp) :: a(3,3), b(3,3)
      integer :: e0, nb

      a = w%lmt%a;  b = w%lmt%b
      dp0(0) = 0.0_dp;  dp0(1:) = d
      fp0 = 0.0_dp
      blocks: do e0 = 1, w%nelem, block
         nb = min(block, w%nelem - e0 + 1)
         call gather(w, dp0, e0, nb, de)
         ! -- slopes and membrane strains at the Gauss points
         call gradient(w, e0, nb, de(:, :, 1), ux, uy)
         call gradient(w, e0, nb, de(:, :, 2), vx, vy)
         call gradient(w, e0, nb, de(:, :, 3), wx, wy)
         e1(:nb, :) = ux(:nb, :) + 0.5_dp*wx(:nb, :)**2
         e2(:nb, :) = vy(:nb, :) + 0.5_dp*wy(:nb, :)**2
         e3(:nb, :) = uy(:nb, :) + vx(:nb, :) + wx(:nb, :)*wy(:nb, :)
         ! -- the membrane force of eps_nl, A eps_nl, and the whole N = A eps0 + B kappa, times w j
         k1(:nb, :) = 0.5_dp*wx(:nb, :)**2;  k2(:nb, :) = 0.5_dp*wy(:nb, :)**2;  k3(:nb, :) = wx(:nb, :)*wy(:nb, :)
         a1(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(1,1)*k1(:nb, :) + a(1,2)*k2(:nb, :) + a(1,3)*k3(:nb, :))
         a2(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(2,1)*k1(:nb, :) + a(2,2)*k2(:nb, :) + a(2,3)*k3(:nb, :))
         a3(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(3,1)*k1(:nb, :) + a(3,2)*k2(:nb, :) + a(3,3)*k3(:nb, :))
         n1(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(1,1)*e1(:nb, :) + a(1,2)*e2(:nb, :) + a(1,3)*e3(:nb, :))
         n2(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(2,1)*e1(:nb, :) + a(2,2)*e2(:nb, :) + a(2,3)*e3(:nb, :))
         n3(:nb, :) = w%wj(e0:e0+nb-1, :)*(a(3,1)*e1(:nb, :) + a(3,2)*e2(:nb, :) + a(3,3)*e3(:nb, :))
         if (w%coupled) then
            call gradient(w, e0, nb, de(:, :, 4), px_x, px_y)
            call gradient(w, e0, nb, de(:, :, 5), py_x, py_y)
            n1(:nb, :) = n1(:nb, :) + w%wj(e0:e0+nb-1, :)*(b(1,1)*px_x(:nb, :) + b(1,2)*py_y(:nb, :) &
                                                          + b(1,3)*(px_y(:nb, :) + py_x(:nb, :)))
            n2(:nb, :) = n2(:nb, :) + w%wj(e0:e0+nb-1, :)*(b(2,1)*px_x(:nb, :) + b(2,2)*py_y(:nb, :) &
                                                          + b(2,3)*(px_y(:nb, :) + py_x(:nb, :)))
            n3(:nb, :) = n3(:nb, :) + w%wj(e0:e0+nb-1, :)*(b(3,1)*px_x(:nb, :) + b(3,2)*py_y(:nb, :) &
                                                          + b(3,3)*(px_y(:nb, :) + py_x(:nb, :)))
            b1(:nb, :) = w%wj(e0:e0+nb-1, :)*(b(1,1)*k1(:nb, :) + b(1,2)*k2(:nb, :) + b(1,3)*k3(:nb, :))
            b2(:nb, :) = w%wj(e0:e0+nb-1, :)*(b(2,1)*k1(:nb, :) + b(2,2)*k2(:nb, :) + b(2,3)*k3(:nb, :))
            b3(:nb, :) = w%wj(e0:e0+nb-1, :)*(b(3,1)*k1(:nb, :) + b(3,2)*k2(:nb, :) + b(3,3)*k3(:nb, :))
         end if
         ! -- the forces: Bm^T (A eps_nl) on u, v; Bnl^T N on w; Bb^T (B eps_nl) on psi
         qx(:nb, :) = wx(:nb, :)*n1(:nb, :) + wy(:nb, :)*n3(:nb, :)
         qy(:nb, :) = wy(:nb, :)*n2(:nb, :) + wx(:nb, :)*n3(:nb, :)
         call divergence(w, e0, nb, a1, a3, fe(:, :, 1))
         call divergence(w, e0, nb, a3, a2, fe(:, :, 2))
         call divergence(w, e0, nb, qx, qy, fe(:, :, 3))
         if (w%coupled) then
            call divergence(w, e0, nb, b1, b3, fe(:, :, 4))
            call divergence(w, e0, nb, b3, b2, fe(:, :, 5))
         else
            fe(:nb, :, 4:5) = 0.0_dp
         end if
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
      real(dp), dimension(block, nen, ndof_node) :: de
      real(dp), dimension(block, ngp_full) :: ux, uy, vx, vy, wx, wy, px_x, px_y, py_x, py_y, &
         e1, e2, e3, k1, k2, k3, dens
      real(dp), dimension(block) :: g4, g5, sdens
      real(dp) :: a(3,3), b(3,3), dd(3,3), as(2,2)
      integer :: e0, nb, p, j

      a = w%lmt%a;  b = w%lmt%b;  dd = w%lmt%d;  as = w%lmt%as
      dp0(0) = 0.0_dp;  dp0(1:) = d
      u = 0.0_dp
      blocks: do e0 = 1, w%nelem, block
         nb = min(block, w%nelem - e0 + 1)
         call gather(w, dp0, e0, nb, de)
         call gradient(w, e0, nb, de(:, :, 1), ux, uy)
         call gradient(w, e0, nb, de(:, :, 2), vx, vy)
         call gradient(w, e0, nb, de(:, :, 3), wx, wy)
         call gradient(w, e0, nb, de(:, :, 4), px_x, px_y)
         call gradient(w, e0, nb, de(:, :, 5), py_x, py_y)
         e1(:nb, :) = ux(:nb, :);  e2(:nb, :) = vy(:nb, :);  e3(:nb, :) = uy(:nb, :) + vx(:nb, :)
         if (nonlinear) then
            e1(:nb, :) = e1(:nb, :) + 0.5_dp*wx(:nb, :)**2
            e2(:nb, :) = e2(:nb, :) + 0.5_dp*wy(:nb, :)**2
            e3(:nb, :) = e3(:nb, :) + wx(:nb, :)*wy(:nb, :)
         end if
         k1(:nb, :) = px_x(:nb, :);  k2(:nb, :) = py_y(:nb, :);  k3(:nb, :) = px_y(:nb, :) + py_x(:nb, :)
         ! eps0 A eps0 + 2 eps0 B kappa + kappa D kappa, at every Gauss point
         dens(:nb, :) = quad(a, e1, e2, e3, e1, e2, e3) + 2.0_dp*quad(b, e1, e2, e3, k1, k2, k3) &
                        + quad(dd, k1, k2, k3, k1, k2, k3)
         u = u + 0.5_dp*sum(w%wj(e0:e0+nb-1, :)*dens(:nb, :))
         ! -- transverse shear, by the element's rule
         shear_points: do p = 1, w%npt
            g4(:nb) = 0.0_dp;  g5(:nb) = 0.0_dp
            do j = 1, nen
               g4(:nb) = g4(:nb) + w%bs(e0:e0+nb-1, p, 1, j)*de(:nb, j, 3) &
                         + w%bs(e0:e0+nb-1, p, 1, nen + j)*de(:nb, j, 4) &
                         + w%bs(e0:e0+nb-1, p, 1, 2*nen + j)*de(:nb, j, 5)
               g5(:nb) = g5(:nb) + w%bs(e0:e0+nb-1, p, 2, j)*de(:nb, j, 3) &
                         + w%bs(e0:e0+nb-1, p, 2, nen + j)*de(:nb, j, 4) &
                         + w%bs(e0:e0+nb-1, p, 2, 2*nen + j)*de(:nb, j, 5)
            end do
            sdens(:nb) = as(1,1)*g4(:nb)**2 + (as(1,2) + as(2,1))*g4(:nb)*g5(:nb) + as(2,2)*g5(:nb)**2
            u = u + 0.5_dp*sum(w%swj(e0:e0+nb-1, p)*sdens(:nb))
         end do shear_points
      end do blocks

   contains

      !> x^T c y at every Gauss point of the block, x = (x1, x2, x3), y likewise.
      pure function quad(c, x1, x2, x3, y1, y2, y3) result(v)
         real(dp), intent(in) :: c(3,3)
         real(dp), intent(in), dimension(block, ngp_full) :: x1, x2, x3, y1, y2, y3
         real(dp) :: v(nb, ngp_full)
         v = x1(:nb, :)*(c(1,1)*y1(:nb, :) + c(1,2)*y2(:nb, :) + c(1,3)*y3(:nb, :)) &
           + x2(:nb, :)*(c(2,1)*y1(:nb, :) + c(2,2)*y2(:nb, :) + c(2,3)*y3(:nb, :)) &
           + x3(:nb, :)*(c(3,1)*y1(:nb, :) + c(3,2)*y2(:nb, :) + c(3,3)*y3(:nb, :))
      end function quad

   end function work_strain_energy

   ! ============================================================== kernels

   !> The element values of the block's elements e0 .. e0+nb-1 from the
   !> global vector d0 (index 0 holds the 0 of the held freedoms).
   subroutine gather(w, d0, e0, nb, de)
      type(element_work_t), intent(in) :: w
      real(dp), intent(in) :: d0(0:)
      integer, intent(in) :: e0, nb
      real(dp), intent(out) :: de(block, nen, ndof_node)
      integer :: i, k
      do k = 1, ndof_node
         do i = 1, nen
            de(:nb, i, k) = d0(w%feq(e0:e0+nb-1, i, k))
         end do
      end do
   end subroutine gather

   !> Adds the element forces fe of the block into the global vector f0
   !> (index 0 collects the held freedoms' share, dropped).
   subroutine scatter_add(w, e0, nb, fe, f0)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb
      real(dp), intent(in) :: fe(block, nen, ndof_node)
      real(dp), intent(inout) :: f0(0:)
      integer :: i, k, e
      do k = 1, ndof_node
         do i = 1, nen
            do e = 1, nb
               f0(w%feq(e0 + e - 1, i, k)) = f0(w%feq(e0 + e - 1, i, k)) + fe(e, i, k)
            end do
         end do
      end do
   end subroutine scatter_add

   !> The x and y derivatives of one field (nodal values v) at the Gauss points.
   subroutine gradient(w, e0, nb, v, gx, gy)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb
      real(dp), intent(in) :: v(block, nen)
      real(dp), intent(out) :: gx(block, ngp_full), gy(block, ngp_full)
      integer :: g, i
      do g = 1, ngp_full
         gx(:nb, g) = 0.0_dp;  gy(:nb, g) = 0.0_dp
         do i = 1, nen
            gx(:nb, g) = gx(:nb, g) + w%dx(e0:e0+nb-1, g, i)*v(:nb, i)
            gy(:nb, g) = gy(:nb, g) + w%dy(e0:e0+nb-1, g, i)*v(:nb, i)
         end do
      end do
   end subroutine gradient

   !> The nodal forces sum_g (d phi_i/dx sx + d phi_i/dy sy) of the fluxes
   !> (sx, sy) at the Gauss points (weights already in them).
   subroutine divergence(w, e0, nb, sx, sy, f)
      type(element_work_t), intent(in) :: w
      integer, intent(in) :: e0, nb
      real(dp), intent(in) :: sx(block, ngp_full), sy(block, ngp_full)
      real(dp), intent(out) :: f(block, nen)
      integer :: g, i
      do i = 1, nen
         f(:nb, i) = 0.0_dp
         do g = 1, ngp_full
            f(:nb, i) = f(:nb, i) + w%dx(e0:e0+nb-1, g, i)*sx(:nb, g) + w%dy(e0:e0+nb-1, g, i)*sy(:nb, g)
         end do
      end do
   end subroutine divergence

end module element_work
