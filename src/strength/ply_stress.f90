!> Ply stresses through the thickness of the laminate, at a point of the
!> plate, in every ply's material axes, on both faces of every ply.
!> In-plane (eq. 2, 3): {sigma_x, sigma_y, tau_xy} = [Qbar]_k (eps0 + z kappa)
!> in ply k, rotated into the ply's axes (Jones 1975, ch. 2). Transverse
!> shear from equilibrium, the first two equations of eq. (7) integrated
!> from the impacted face, so that both faces are free of shear (above
!> ply_stack_init). Plies from z = -h/2 (the impacted face) to +h/2, each
!> h/n thick; face 1 of ply k is its bottom, face 2 its top. Stresses come
!> as (s11, s22, t12, t23, t13), the order of failure_criteria.
!> The strain state at a point is 18 numbers, (eps0, kappa, eps0_,x,
!> kappa_,x, eps0_,y, kappa_,y), and every stress is linear in it:
!> ply_stack_init tabulates the coefficients once per laminate,
!> ply_stresses applies them. More: docs/STRENGTH.md.
module ply_stress
   use kinds, only: dp, pi
   use materials, only: lamina_t, lamina_qbar
   use shape_functions, only: nen, shape9_derivs, shape9_second_derivs
   use gauss_rules, only: gauss_2d
   use element_matrices, only: von_karman
   implicit none
   private
   public :: ply_stack_t, ply_stack_init, ply_stresses, point_strain_state, element_second_derivatives
   public :: inplane_to_material, shear_to_material, nstate, ngp

   !> Numbers in a strain state (module header).
   integer, parameter :: nstate = 18
   !> Gauss points of an element (3 x 3, those of the membrane and bending terms).
   integer, parameter :: ngp = 9

   !> The laminate's through-thickness tables (above ply_stack_init). Plies of the
   !> same angle share their stiffness: the products with the strain state
   !> are formed once per angle.
   type :: ply_stack_t
      integer :: nply = 0, nangle = 0
      real(dp) :: h = 0.0_dp
      real(dp), allocatable :: z(:)           !< (0:nply) ply interfaces (m)
      real(dp), allocatable :: angle(:)       !< (nply) ply angles (deg)
      integer, allocatable :: kind(:)         !< (nply) which of the distinct angles
      real(dp), allocatable :: qbar(:,:,:)    !< (3, 3, nangle) Qbar of each distinct angle (Pa)
      real(dp), allocatable :: tqbar(:,:,:)   !< (3, 3, nangle) T Qbar: (s11, s22, t12) per (eps_x, eps_y, gamma_xy)
      real(dp), allocatable :: dz(:), dz2(:)  !< (nply) z_k - z_k-1 and (z_k^2 - z_k-1^2)/2 (m, m^2)
      real(dp), allocatable :: c(:), s(:)     !< (nply) cos, sin of the ply angles
   end type ply_stack_t

contains

   !> Transverse shear from equilibrium: eq. (3)'s own shear stresses
   !> Qbar_44,55 (eps4, eps5) are constant in each ply and do not vanish on the
   !> faces; the stresses that do are those of the first two equations of
   !> eq. (7) (in-plane inertia aside), integrated from the impacted face
   !> z = -h/2, where the contact is frictionless:
   !>     tau_xz(z) = -int_{-h/2}^{z} (sigma_x,x + tau_xy,y) dzeta
   !>               = -[G_1j(z) eps0_j,x + H_1j(z) kappa_j,x + G_3j(z) eps0_j,y + H_3j(z) kappa_j,y],
   !>     tau_yz(z) = -[G_3j(z) eps0_j,x + H_3j(z) kappa_j,x + G_2j(z) eps0_j,y + H_2j(z) kappa_j,y],
   !> with G(z) = int_{-h/2}^{z} Qbar dzeta and H(z) = int_{-h/2}^{z} Qbar zeta
   !> dzeta, the integrals of eq. (6) (G(h/2) = A, H(h/2) = B) taken up to z:
   !> the same integration of Qbar that Whitney's shear correction does
   !> (src/model/shear_correction.f90) in cylindrical bending, here with every
   !> gradient of the laminate strains. At z = +h/2 the integral leaves
   !> -(N_x,x + N_xy,y), the membrane force the in-plane inertia P u'' carries
   !> (and the rounding of the discrete equilibrium); the density is the same
   !> in every ply, so that force is spread through the thickness as
   !> (z + h/2)/h and subtracted: both faces are then free of shear. The
   !> gradients eps0_j,x, kappa_j,y, ... come from the second derivatives of
   !> the element's shape functions (element_second_derivatives); in the
   !> nonlinear theory eps0 holds the von Karman terms and so do its
   !> gradients ((w,x^2/2),x = w,x w,xx, ...). The shear stresses are then
   !> rotated: t13 = c t_xz + s t_yz, t23 = -s t_xz + c t_yz.
   !>
   !> The tables of a laminate of one lamina, plies h/n thick, angles bottom
   !> to top (above).
   pure subroutine ply_stack_init(lam, angles, h, stack)
      type(lamina_t), intent(in) :: lam          !< the lamina
      real(dp), intent(in) :: angles(:)          !< ply angles from x, z = -h/2 first (deg)
      real(dp), intent(in) :: h                  !< laminate thickness (m)
      type(ply_stack_t), intent(out) :: stack    !< the tables
      real(dp) :: distinct(size(angles))
      integer :: k, a, n

      n = size(angles)
      stack%nply = n
      stack%h = h
      allocate (stack%z(0:n), stack%angle(n), stack%kind(n), stack%dz(n), stack%dz2(n), stack%c(n), stack%s(n))
      stack%angle = angles
      stack%z = [(-0.5_dp*h + real(k, dp)*h/real(n, dp), k = 0, n)]
      stack%dz = stack%z(1:n) - stack%z(0:n-1)
      stack%dz2 = 0.5_dp*(stack%z(1:n)**2 - stack%z(0:n-1)**2)
      stack%c = cos(angles*pi/180.0_dp)
      stack%s = sin(angles*pi/180.0_dp)
      stack%nangle = 0
      plies: do k = 1, n
         do a = 1, stack%nangle
            if (distinct(a) == angles(k)) then     ! the same number in the deck: the same tables
               stack%kind(k) = a
               cycle plies
            end if
         end do
         stack%nangle = stack%nangle + 1
         distinct(stack%nangle) = angles(k)
         stack%kind(k) = stack%nangle
      end do plies
      allocate (stack%qbar(3, 3, stack%nangle), stack%tqbar(3, 3, stack%nangle))
      do a = 1, stack%nangle
         stack%qbar(:, :, a) = lamina_qbar(lam, distinct(a))
         stack%tqbar(:, :, a) = matmul(stress_rotation(cos(distinct(a)*pi/180.0_dp), &
                                       sin(distinct(a)*pi/180.0_dp)), stack%qbar(:, :, a))
      end do
   end subroutine ply_stack_init

   !> The stresses of every ply face at a point of strain state e:
   !> sigma(:, f, k) = (s11, s22, t12, t23, t13) (Pa) on face f (1 bottom,
   !> 2 top) of ply k, material axes (module header); with mean, also each
   !> ply's through-thickness average: exact, the in-plane stresses being
   !> linear in z within a ply and the shear quadratic (Simpson's rule on
   !> its faces and middle).
   pure subroutine ply_stresses(stack, e, sigma, mean)
      type(ply_stack_t), intent(in) :: stack        !< the laminate's tables
      real(dp), intent(in) :: e(nstate)             !< strain state (module header)
      real(dp), intent(out) :: sigma(5, 2, stack%nply)   !< stresses (Pa)
      real(dp), intent(out), optional :: mean(5, stack%nply)   !< ply averages (Pa)
      real(dp) :: p0(3, stack%nangle), p1(3, stack%nangle), ax(3, stack%nangle), bx(3, stack%nangle), &
                  ay(3, stack%nangle), by(3, stack%nangle), txz(0:stack%nply), tyz(0:stack%nply), z, r, &
                  mxz(stack%nply), myz(stack%nply), zm, hz, hz2
      integer :: a, i, j, k, f, n
      n = stack%nply
      ! -- per distinct angle: T Qbar eps0, T Qbar kappa, and Qbar times the gradients
      angles: do a = 1, stack%nangle
         p0(:, a) = 0.0_dp;  p1(:, a) = 0.0_dp
         ax(:, a) = 0.0_dp;  bx(:, a) = 0.0_dp;  ay(:, a) = 0.0_dp;  by(:, a) = 0.0_dp
         do j = 1, 3
            p0(:, a) = p0(:, a) + stack%tqbar(:, j, a)*e(j)
            p1(:, a) = p1(:, a) + stack%tqbar(:, j, a)*e(3 + j)
            ax(:, a) = ax(:, a) + stack%qbar(:, j, a)*e(6 + j)
            bx(:, a) = bx(:, a) + stack%qbar(:, j, a)*e(9 + j)
            ay(:, a) = ay(:, a) + stack%qbar(:, j, a)*e(12 + j)
            by(:, a) = by(:, a) + stack%qbar(:, j, a)*e(15 + j)
         end do
      end do angles
      ! -- transverse shear: equilibrium integrated from the impacted face,
      !    -(sigma_x,x + tau_xy,y) and -(tau_xy,x + sigma_y,y) ply by ply
      txz(0) = 0.0_dp;  tyz(0) = 0.0_dp
      through: do k = 1, n
         a = stack%kind(k)
         txz(k) = txz(k-1) - (stack%dz(k)*(ax(1, a) + ay(3, a)) + stack%dz2(k)*(bx(1, a) + by(3, a)))
         tyz(k) = tyz(k-1) - (stack%dz(k)*(ax(3, a) + ay(2, a)) + stack%dz2(k)*(bx(3, a) + by(2, a)))
      end do through
      ! -- the shear at each ply's middle, for the averages
      if (present(mean)) then
         do k = 1, n
            a = stack%kind(k)
            zm = 0.5_dp*(stack%z(k-1) + stack%z(k))
            hz = 0.5_dp*stack%dz(k)
            hz2 = 0.5_dp*(zm**2 - stack%z(k-1)**2)
            r = (zm + 0.5_dp*stack%h)/stack%h
            mxz(k) = txz(k-1) - (hz*(ax(1, a) + ay(3, a)) + hz2*(bx(1, a) + by(3, a))) - r*txz(n)
            myz(k) = tyz(k-1) - (hz*(ax(3, a) + ay(2, a)) + hz2*(bx(3, a) + by(2, a))) - r*tyz(n)
         end do
      end if
      ! -- faces free: the top's residual (in-plane inertia) spread as (z + h/2)/h
      do i = 1, n
         r = (stack%z(i) + 0.5_dp*stack%h)/stack%h
         txz(i) = txz(i) - r*txz(n)
         tyz(i) = tyz(i) - r*tyz(n)
      end do
      ! -- every ply face in its material axes
      plies: do k = 1, n
         a = stack%kind(k)
         do f = 1, 2
            i = k - 2 + f
            z = stack%z(i)
            sigma(1:3, f, k) = p0(:, a) + z*p1(:, a)
            sigma(4, f, k) = -stack%s(k)*txz(i) + stack%c(k)*tyz(i)    ! t23
            sigma(5, f, k) = stack%c(k)*txz(i) + stack%s(k)*tyz(i)     ! t13
         end do
      end do plies
      if (.not. present(mean)) return
      averages: do k = 1, n
         a = stack%kind(k)
         mean(1:3, k) = p0(:, a) + 0.5_dp*(stack%z(k-1) + stack%z(k))*p1(:, a)
         mxz(k) = (txz(k-1) + 4.0_dp*mxz(k) + txz(k))/6.0_dp
         myz(k) = (tyz(k-1) + 4.0_dp*myz(k) + tyz(k))/6.0_dp
         mean(4, k) = -stack%s(k)*mxz(k) + stack%c(k)*myz(k)
         mean(5, k) = stack%c(k)*mxz(k) + stack%s(k)*myz(k)
      end do averages
   end subroutine ply_stresses

   !> The in-plane stresses (sx, sy, txy) in the axes of a ply at theta_deg:
   !> (s11, s22, t12) (module header).
   pure function inplane_to_material(theta_deg, sxy) result(s12)
      real(dp), intent(in) :: theta_deg     !< fibre angle from x (deg)
      real(dp), intent(in) :: sxy(3)        !< (sigma_x, sigma_y, tau_xy) (Pa)
      real(dp) :: s12(3)                    !< (sigma_11, sigma_22, tau_12) (Pa)
      real(dp) :: t(3,3)
      t = stress_rotation(cos(theta_deg*pi/180.0_dp), sin(theta_deg*pi/180.0_dp))
      s12 = matmul(t, sxy)
   end function inplane_to_material

   !> The transverse shear stresses (t_xz, t_yz) in the axes of a ply at
   !> theta_deg: (t23, t13).
   pure function shear_to_material(theta_deg, txz_tyz) result(t)
      real(dp), intent(in) :: theta_deg     !< fibre angle from x (deg)
      real(dp), intent(in) :: txz_tyz(2)    !< (tau_xz, tau_yz) (Pa)
      real(dp) :: t(2)                      !< (tau_23, tau_13) (Pa)
      real(dp) :: c, s
      c = cos(theta_deg*pi/180.0_dp);  s = sin(theta_deg*pi/180.0_dp)
      t = [-s*txz_tyz(1) + c*txz_tyz(2), c*txz_tyz(1) + s*txz_tyz(2)]
   end function shear_to_material

   !> The stress rotation T: (s11, s22, t12) = T (sx, sy, txy).
   pure function stress_rotation(c, s) result(t)
      real(dp), intent(in) :: c             !< cos theta (-)
      real(dp), intent(in) :: s             !< sin theta (-)
      real(dp) :: t(3,3)                    !< the rotation (-)
      t(1, :) = [c*c, s*s, 2.0_dp*c*s]
      t(2, :) = [s*s, c*c, -2.0_dp*c*s]
      t(3, :) = [-c*s, c*s, c*c - s*s]
   end function stress_rotation

   !> Second derivatives (d2/dx2, d2/dy2, d2/dxdy) of the shape functions at
   !> the 3 x 3 Gauss points of the element with node coordinates xe (the
   !> points' order of src/linalg/gauss_rules.f90, as element_geometry's):
   !>     d2 phi/dx_a dx_b = sum_ij xi_i,a xi_j,b (phi_,ij - sum_k phi_,x_k x_k,ij).
   pure function element_second_derivatives(xe) result(d2)
      real(dp), intent(in) :: xe(2, nen)       !< node coordinates (m)
      real(dp) :: d2(3, nen, ngp)              !< (xx, yy, xy) per node and point (1/m^2)
      real(dp) :: pts(2, ngp), w(ngp), dref(2, nen), dd(3, nen), jac(2,2), jinv(2,2), det, &
                  dxy(2, nen), xh(2, 3), hess(2,2,nen), x2(2,2,2), c(2,2,nen)
      integer :: g, i
      call gauss_2d(3, pts, w)
      points: do g = 1, ngp
         dref = shape9_derivs(pts(1, g), pts(2, g))
         dd = shape9_second_derivs(pts(1, g), pts(2, g))
         jac = matmul(dref, transpose(xe))              ! J(i,j) = dx_j/dxi_i
         det = jac(1,1)*jac(2,2) - jac(1,2)*jac(2,1)
         jinv = reshape([jac(2,2), -jac(2,1), -jac(1,2), jac(1,1)], [2,2])/det   ! dxi_i/dx_j = jinv(i,j)
         dxy = matmul(jinv, dref)                        ! (d/dx, d/dy) phi
         xh = matmul(xe, transpose(dd))                  ! x_k,ij: (k, (xixi, etaeta, xieta))
         do i = 1, 2
            x2(i, :, 1) = [xh(i, 1), xh(i, 3)]
            x2(i, :, 2) = [xh(i, 3), xh(i, 2)]
         end do
         nodes: do i = 1, nen
            ! phi_,ij - sum_k phi_,k x_k,ij   (i, j along xi, eta)
            hess(1, 1, i) = dd(1, i) - dxy(1, i)*x2(1, 1, 1) - dxy(2, i)*x2(2, 1, 1)
            hess(2, 2, i) = dd(2, i) - dxy(1, i)*x2(1, 2, 2) - dxy(2, i)*x2(2, 2, 2)
            hess(1, 2, i) = dd(3, i) - dxy(1, i)*x2(1, 1, 2) - dxy(2, i)*x2(2, 1, 2)
            hess(2, 1, i) = hess(1, 2, i)
            c(:, :, i) = matmul(jinv, matmul(hess(:, :, i), transpose(jinv)))
            d2(:, i, g) = [c(1, 1, i), c(2, 2, i), c(1, 2, i)]
         end do nodes
      end do points
   end function element_second_derivatives

   !> The strain state (module header) at a point with shape-function
   !> derivatives dxy and second derivatives d2, element displacements de
   !> (u, v, w, psi_x, psi_y by node); von Karman terms when nonlinear.
   pure function point_strain_state(dxy, d2, de, nonlinear) result(e)
      real(dp), intent(in) :: dxy(2, nen)      !< (d/dx, d/dy) phi_i (1/m)
      real(dp), intent(in) :: d2(3, nen)       !< (xx, yy, xy) phi_i (1/m^2)
      real(dp), intent(in) :: de(5*nen)        !< element displacements
      logical, intent(in) :: nonlinear         !< von Karman strains
      real(dp) :: e(nstate)
      real(dp) :: g1(5), gx(5), gy(5), gxx(5), gyy(5), gxy(5)
      integer :: i
      ! first and second derivatives of the five fields (u, v, w, psi_x, psi_y)
      gx = 0.0_dp;  gy = 0.0_dp;  gxx = 0.0_dp;  gyy = 0.0_dp;  gxy = 0.0_dp
      nodes: do i = 1, nen
         g1 = de(5*i-4:5*i)
         gx = gx + dxy(1, i)*g1
         gy = gy + dxy(2, i)*g1
         gxx = gxx + d2(1, i)*g1
         gyy = gyy + d2(2, i)*g1
         gxy = gxy + d2(3, i)*g1
      end do nodes
      associate (ux => gx(1), uy => gy(1), vx => gx(2), vy => gy(2), wx => gx(3), wy => gy(3), &
                 uxx => gxx(1), uyy => gyy(1), uxy => gxy(1), vxx => gxx(2), vyy => gyy(2), vxy => gxy(2), &
                 wxx => gxx(3), wyy => gyy(3), wxy => gxy(3))
         e(1:3) = [ux, vy, uy + vx]
         e(7:9) = [uxx, vxy, uxy + vxx]
         e(13:15) = [uxy, vyy, uyy + vxy]
         if (nonlinear) then
            e(1:3) = e(1:3) + von_karman(wx, wy)
            e(7:9) = e(7:9) + [wx*wxx, wy*wxy, wxx*wy + wx*wxy]
            e(13:15) = e(13:15) + [wx*wxy, wy*wyy, wxy*wy + wx*wyy]
         end if
      end associate
      e(4:6) = [gx(4), gy(5), gy(4) + gx(5)]                   ! kappa
      e(10:12) = [gxx(4), gxy(5), gxy(4) + gxx(5)]             ! kappa_,x
      e(16:18) = [gxy(4), gyy(5), gyy(4) + gxy(5)]             ! kappa_,y
   end function point_strain_state

end module ply_stress
