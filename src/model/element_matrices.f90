!> Element matrices of the 9-node Mindlin / von Karman plate element
!> (paper eq. 2, 4, 10, 14, 15 and Appendix B): [M], [K_L], the nonlinear
!> force K_N(d) d, the internal force and the strain energy.
!>
!> Freedoms of an element: 45, node by node (u, v, w, psi_x, psi_y). At a point:
!>   membrane   eps0  = Bm d + eps_nl,  eps_nl = (w,x^2/2, w,y^2/2, w,x w,y)  eq. (2)
!>   bending    kappa = Bb d = (psi_x,x, psi_y,y, psi_x,y + psi_y,x)
!>   shear      gamma = Bs d = (psi_y + w,y, psi_x + w,x)  = (eps4, eps5)
!>   resultants N = A eps0 + B kappa,  M = B eps0 + D kappa,  Q = Abar gamma   eq. (4)
!> 3x3 Gauss points for membrane, bending and inertia; transverse shear by
!> the element's shear rule (src/model/shear_strain.f90). The matrices of
!> eq. (15): above element_nonlinear_force. More: docs/MODEL.md.
module element_matrices
   use kinds, only: dp
   use materials, only: laminate_t
   use shape_functions, only: nen, shape9, shape9_derivs
   use gauss_rules, only: gauss_2d
   use shear_strain, only: shear_rule_t, shear_operator_t, shear_operator
   implicit none
   private
   public :: element_geometry_t, element_geometry, element_mass, element_stiffness, von_karman, &
             element_nonlinear_force, element_internal_force, element_strain_energy, &
             element_inplane_strain, element_gauss_point, point_derivs, element_tangent_stiffness, &
             element_pressure_load, element_mass_integrals, ngp_full, nfe_elem, point_strains, &
             shear_strains

   !> Gauss points of the full (3x3) rule.
   integer, parameter :: ngp_full = 9
   !> Freedoms per element.
   integer, parameter :: nfe_elem = 5*nen

   !> Shape functions and their x, y derivatives at the Gauss points of one
   !> element, with the weights times det J, and its transverse shear
   !> operator: computed once per element.
   type :: element_geometry_t
      real(dp) :: phi3(nen, ngp_full)      !< phi_i at the 3x3 points
      real(dp) :: dx3(2, nen, ngp_full)    !< (d/dx, d/dy) phi_i at the 3x3 points
      real(dp) :: wj3(ngp_full)            !< weight * det J (m^2) at the 3x3 points
      real(dp) :: xy3(2, ngp_full)         !< (x, y) of the 3x3 points (m)
      type(shear_operator_t) :: shear      !< gamma = Bs d at the shear points (module shear_strain)
   end type element_geometry_t

contains

   !> Shape function derivatives and integration weights of the element with
   !> node coordinates xe (isoparametric map, eq. 14), and its shear
   !> operator under rule. ok is false when the Jacobian is not positive
   !> somewhere (a distorted or inverted element).
   pure subroutine element_geometry(xe, rule, geo, ok)
      real(dp), intent(in) :: xe(2, nen)             !< node coordinates (m)
      type(shear_rule_t), intent(in) :: rule         !< transverse shear rule (module shear_strain)
      type(element_geometry_t), intent(out) :: geo   !< the element's geometry
      logical, intent(out) :: ok                     !< det J > 0 at every point
      real(dp) :: pts3(2, ngp_full), w3(ngp_full)
      real(dp) :: det3(ngp_full)
      logical :: shear_ok
      integer :: g

      call gauss_2d(3, pts3, w3)
      full_rule: do g = 1, ngp_full
         call point_derivs(xe, pts3(:, g), w3(g), geo%phi3(:, g), geo%dx3(:, :, g), geo%wj3(g), det3(g))
         geo%xy3(:, g) = matmul(xe, geo%phi3(:, g))
      end do full_rule
      call shear_operator(xe, rule, geo%shear, shear_ok)
      ok = all(det3 > 0.0_dp) .and. shear_ok
   end subroutine element_geometry

   !> Shape functions, their x, y derivatives, the weight w det J and det J
   !> at the reference point pt of the element with node coordinates xe
   !> (isoparametric map, eq. 14); dxy = 0 where det J <= 0.
   pure subroutine point_derivs(xe, pt, w, phi, dxy, wj, det)
      real(dp), intent(in) :: xe(2, nen)     !< node coordinates (m)
      real(dp), intent(in) :: pt(2)          !< reference point (xi, eta)
      real(dp), intent(in) :: w              !< its integration weight
      real(dp), intent(out) :: phi(nen)      !< shape functions
      real(dp), intent(out) :: dxy(2, nen)   !< their derivatives d/dx, d/dy (1/m)
      real(dp), intent(out) :: wj            !< w det J (m^2)
      real(dp), intent(out) :: det           !< det J (m^2)
      real(dp) :: dref(2, nen), jac(2,2), jinv(2,2)
      phi = shape9(pt(1), pt(2))
      dref = shape9_derivs(pt(1), pt(2))
      ! J(i,j) = d x_j / d xi_i
      jac = matmul(dref, transpose(xe))
      det = jac(1,1)*jac(2,2) - jac(1,2)*jac(2,1)
      if (det <= 0.0_dp) then
         dxy = 0.0_dp;  wj = 0.0_dp
         return
      end if
      jinv = reshape([jac(2,2), -jac(2,1), -jac(1,2), jac(1,1)], [2,2])/det
      dxy = matmul(jinv, dref)
      wj = w*det
   end subroutine point_derivs

   !> Consistent mass matrix, 3x3 Gauss (Appendix B: P[S], R[S], I[S] blocks
   !> with S_ij = int phi_i phi_j).
   pure subroutine element_mass(lmt, geo, me)
      type(laminate_t), intent(in) :: lmt           !< inertias P, R, I (eq. 9)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(out) :: me(nfe_elem, nfe_elem)  !< element mass matrix
      real(dp) :: s(nen, nen)
      integer :: i, j, k

      s = element_mass_integrals(geo)
      me = 0.0_dp
      do j = 1, nen
         do i = 1, nen
            do k = 1, 3
               me(5*(i-1)+k, 5*(j-1)+k) = lmt%p*s(i, j)
            end do
            do k = 4, 5
               me(5*(i-1)+k, 5*(j-1)+k) = lmt%i*s(i, j)
            end do
            me(5*(i-1)+1, 5*(j-1)+4) = lmt%r*s(i, j)
            me(5*(i-1)+4, 5*(j-1)+1) = lmt%r*s(i, j)
            me(5*(i-1)+2, 5*(j-1)+5) = lmt%r*s(i, j)
            me(5*(i-1)+5, 5*(j-1)+2) = lmt%r*s(i, j)
         end do
      end do
   end subroutine element_mass

   !> The one block of the consistent mass matrix, S_ij = int phi_i phi_j dA
   !> (m^2), 3x3 Gauss: element_mass places P S, R S and I S on the
   !> freedoms (Appendix B). Kept per element, it gives M x element by
   !> element without the zeros inside the band of the assembled matrix.
   pure function element_mass_integrals(geo) result(s)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp) :: s(nen, nen)                       !< S_ij (m^2)
      integer :: g, j
      s = 0.0_dp
      gauss_points: do g = 1, ngp_full
         do j = 1, nen
            s(:, j) = s(:, j) + geo%wj3(g)*geo%phi3(:, g)*geo%phi3(j, g)
         end do
      end do gauss_points
   end function element_mass_integrals

   !> Linear stiffness [K_L] (Appendix B): membrane and bending with 3x3
   !> Gauss points, transverse shear by the element's shear rule.
   pure subroutine element_stiffness(lmt, geo, ke)
      type(laminate_t), intent(in) :: lmt           !< A, B, D, Abar (eq. 6)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(out) :: ke(nfe_elem, nfe_elem)  !< element stiffness
      real(dp) :: bmb(6, nfe_elem), bs(2, nfe_elem), c(6,6)
      integer :: g

      c(1:3, 1:3) = lmt%a;  c(1:3, 4:6) = lmt%b
      c(4:6, 1:3) = lmt%b;  c(4:6, 4:6) = lmt%d
      ke = 0.0_dp
      membrane_bending: do g = 1, ngp_full
         bmb = b_membrane_bending(geo%dx3(:, :, g))
         ke = ke + geo%wj3(g)*matmul(transpose(bmb), matmul(c, bmb))
      end do membrane_bending
      transverse_shear: do g = 1, geo%shear%npoint
         bs = b_shear(geo%shear%b(:, :, :, g))
         ke = ke + geo%shear%wj(g)*matmul(transpose(bs), matmul(lmt%as, bs))
      end do transverse_shear
   end subroutine element_stiffness

   !> Matrices (eq. 15, Appendix B):
   !>   [M]   = int N^T diag(P, P, P, I, I) N  (+ R coupling u-psi_x, v-psi_y)
   !>   [K_L] = int [Bm; Bb]^T [A B; B D] [Bm; Bb] + int Bs^T Abar Bs
   !>   [K_N(d)] d = f_int(d) - K_L d, where f_int = dU/dd is the internal force
   !>          of the von Karman strains. With Bnl d' = d eps_nl / dd . d'
   !>          (rows: w,x phi_i,x ; w,y phi_i,y ; w,x phi_i,y + w,y phi_i,x on
   !>          the w freedoms):
   !>   K_N(d) d = int Bm^T (A eps_nl) + Bb^T (B eps_nl) + Bnl^T N
   !>   which is Appendix B's [K_N] blocks times d, evaluated without forming them.
   !>
   !> The nonlinear term K_N(d) d of eq. (15) and (19) for the element
   !> displacements de (as above).
   pure subroutine element_nonlinear_force(lmt, geo, de, fn)
      type(laminate_t), intent(in) :: lmt           !< A, B, D
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      real(dp), intent(out) :: fn(nfe_elem)         !< K_N(d) d
      real(dp) :: eps0(3), kap(3), enl(3), n(3), wx, wy, an(3), bn(3)
      integer :: g, i

      fn = 0.0_dp
      gauss_points: do g = 1, ngp_full
         call point_strains(geo%dx3(:, :, g), de, eps0, kap, wx, wy)
         enl = von_karman(wx, wy)
         eps0 = eps0 + enl
         n  = matmul(lmt%a, eps0) + matmul(lmt%b, kap)
         an = geo%wj3(g)*matmul(lmt%a, enl)      ! membrane force of eps_nl
         bn = geo%wj3(g)*matmul(lmt%b, enl)      ! moment of eps_nl
         n  = geo%wj3(g)*n
         nodes: do i = 1, nen
            associate (px => geo%dx3(1, i, g), py => geo%dx3(2, i, g))
               ! Bm^T (A eps_nl):  u, v rows
               fn(5*i-4) = fn(5*i-4) + px*an(1) + py*an(3)
               fn(5*i-3) = fn(5*i-3) + py*an(2) + px*an(3)
               ! Bnl^T N:  w row
               fn(5*i-2) = fn(5*i-2) + (wx*px)*n(1) + (wy*py)*n(2) + (wx*py + wy*px)*n(3)
               ! Bb^T (B eps_nl):  psi_x, psi_y rows
               fn(5*i-1) = fn(5*i-1) + px*bn(1) + py*bn(3)
               fn(5*i)   = fn(5*i)   + py*bn(2) + px*bn(3)
            end associate
         end do nodes
      end do gauss_points
   end subroutine element_nonlinear_force

   !> The whole internal force f_int(d) = dU/dd = K_L d + K_N(d) d; with
   !> nonlinear false only K_L d.
   pure subroutine element_internal_force(lmt, geo, de, nonlinear, f)
      type(laminate_t), intent(in) :: lmt           !< laminate
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      logical, intent(in) :: nonlinear              !< von Karman terms included
      real(dp), intent(out) :: f(nfe_elem)          !< internal force
      real(dp) :: ke(nfe_elem, nfe_elem), fn(nfe_elem)
      call element_stiffness(lmt, geo, ke)
      f = matmul(ke, de)
      if (nonlinear) then
         call element_nonlinear_force(lmt, geo, de, fn)
         f = f + fn
      end if
   end subroutine element_internal_force

   !> Strain energy of the element, U = 1/2 int (eps0 N + kappa M + gamma Q),
   !> von Karman strains when nonlinear is true; the shear part by the
   !> element's shear rule, so that the energy is the one of its stiffness.
   pure function element_strain_energy(lmt, geo, de, nonlinear) result(u)
      type(laminate_t), intent(in) :: lmt           !< laminate
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      logical, intent(in) :: nonlinear              !< von Karman strains
      real(dp) :: u
      real(dp) :: eps0(3), kap(3), gam(2), wx, wy
      integer :: g

      u = 0.0_dp
      membrane_bending: do g = 1, ngp_full
         call point_strains(geo%dx3(:, :, g), de, eps0, kap, wx, wy)
         if (nonlinear) eps0 = eps0 + von_karman(wx, wy)
         u = u + 0.5_dp*geo%wj3(g)*( dot_product(eps0, matmul(lmt%a, eps0)) &
               + 2.0_dp*dot_product(eps0, matmul(lmt%b, kap)) + dot_product(kap, matmul(lmt%d, kap)) )
      end do membrane_bending
      transverse_shear: do g = 1, geo%shear%npoint
         gam = shear_strains(geo%shear%b(:, :, :, g), de)
         u = u + 0.5_dp*geo%shear%wj(g)*dot_product(gam, matmul(lmt%as, gam))
      end do transverse_shear
   end function element_strain_energy

   !> The transverse shear strains (eps4, eps5) = Bs d at one shear point,
   !> without forming Bs.
   pure function shear_strains(b, de) result(gam)
      real(dp), intent(in) :: b(2, 3, nen)          !< the operator at the point (module shear_strain)
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      real(dp) :: gam(2)
      integer :: i
      gam = 0.0_dp
      do i = 1, nen
         gam = gam + b(:, 1, i)*de(5*i-2) + b(:, 2, i)*de(5*i-1) + b(:, 3, i)*de(5*i)
      end do
   end function shear_strains

   !> In-plane strains (eps_x, eps_y, gamma_xy) at depth z at a point of
   !> the element with shape-function derivatives dxy (a Gauss point's,
   !> geo%dx3(:, :, g), or point_derivs'), eq. (2): eps = eps0 + z kappa.
   pure function element_inplane_strain(dxy, de, z, nonlinear) result(eps)
      real(dp), intent(in) :: dxy(2, nen)           !< shape-function derivatives at the point (1/m)
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      real(dp), intent(in) :: z                     !< depth from the mid-plane (m)
      logical, intent(in) :: nonlinear              !< von Karman strains
      real(dp) :: eps(3)
      real(dp) :: eps0(3), kap(3), wx, wy
      call point_strains(dxy, de, eps0, kap, wx, wy)
      if (nonlinear) eps0 = eps0 + von_karman(wx, wy)
      eps = eps0 + z*kap
   end function element_inplane_strain

   !> The 3x3 Gauss point of the element nearest to the point p.
   pure function element_gauss_point(geo, p) result(g)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: p(2)                  !< point (m)
      integer :: g
      g = minloc(sum((geo%xy3 - spread(p, 2, ngp_full))**2, dim=1), dim=1)
   end function element_gauss_point

   !> Tangent stiffness K_T(d) = d f_int/d d of the von Karman element, for
   !> Newton's method in the static analysis (src/analyses/static_analysis.f90):
   !>   K_T = K_L + int [ Bnl^T A Bm + Bm^T A Bnl + Bnl^T A Bnl + Bnl^T B Bb
   !>                     + Bb^T B Bnl + G^T [Nx Nxy; Nxy Ny] G ]        (3x3 points)
   !> with Bnl(d) the rows of d eps_nl/d d (above element_nonlinear_force), G = (phi_i,x;
   !> phi_i,y) on the w freedoms and N = A (eps0 + eps_nl) + B kappa the
   !> membrane forces at d: the derivative of K_L d + K_N(d) d (eq. 15, 19).
   pure subroutine element_tangent_stiffness(lmt, geo, de, kt)
      type(laminate_t), intent(in) :: lmt           !< A, B, D, Abar (eq. 6)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: de(nfe_elem)          !< element displacements
      real(dp), intent(out) :: kt(nfe_elem, nfe_elem)  !< tangent stiffness
      real(dp) :: bmb(6, nfe_elem), bnl(6, nfe_elem), gw(2, nfe_elem), c(6,6), &
                  cb(6, nfe_elem), eps0(3), kap(3), n(3), nhat(2,2), wx, wy
      integer :: g, i

      call element_stiffness(lmt, geo, kt)
      c(1:3, 1:3) = lmt%a;  c(1:3, 4:6) = lmt%b
      c(4:6, 1:3) = lmt%b;  c(4:6, 4:6) = lmt%d
      gauss_points: do g = 1, ngp_full
         call point_strains(geo%dx3(:, :, g), de, eps0, kap, wx, wy)
         n = matmul(lmt%a, eps0 + von_karman(wx, wy)) + matmul(lmt%b, kap)
         nhat = reshape([n(1), n(3), n(3), n(2)], [2, 2])
         bmb = b_membrane_bending(geo%dx3(:, :, g))
         bnl = 0.0_dp
         gw = 0.0_dp
         nodes: do i = 1, nen
            associate (px => geo%dx3(1, i, g), py => geo%dx3(2, i, g))
               bnl(1, 5*i-2) = wx*px
               bnl(2, 5*i-2) = wy*py
               bnl(3, 5*i-2) = wx*py + wy*px
               gw(1, 5*i-2) = px
               gw(2, 5*i-2) = py
            end associate
         end do nodes
         cb = matmul(c, bnl)
         kt = kt + geo%wj3(g)*( matmul(transpose(bmb), cb) + matmul(transpose(cb), bmb) &
                 + matmul(transpose(bnl), cb) + matmul(transpose(gw), matmul(nhat, gw)) )
      end do gauss_points
   end subroutine element_tangent_stiffness

   !> Consistent load vector of a transverse pressure, f_i = int phi_i q dA
   !> on the w freedoms (3x3 Gauss points, the rule of the mass matrix: exact
   !> for a uniform pressure on a straight-sided element).
   pure subroutine element_pressure_load(geo, q, fe)
      type(element_geometry_t), intent(in) :: geo   !< element geometry
      real(dp), intent(in) :: q(ngp_full)           !< pressure at the 3x3 points (Pa), + along w
      real(dp), intent(out) :: fe(nfe_elem)         !< element load vector (N)
      integer :: g, i
      fe = 0.0_dp
      gauss_points: do g = 1, ngp_full
         do i = 1, nen
            fe(5*i-2) = fe(5*i-2) + geo%wj3(g)*geo%phi3(i, g)*q(g)
         end do
      end do gauss_points
   end subroutine element_pressure_load

   ! ---------------------------------------------------------------- kernels

   !> Linear membrane strains Bm d, curvatures Bb d and the slopes of w at a
   !> point with shape-function derivatives dxy.
   pure subroutine point_strains(dxy, de, eps0, kap, wx, wy)
      real(dp), intent(in) :: dxy(2, nen), de(nfe_elem)
      real(dp), intent(out) :: eps0(3), kap(3), wx, wy
      real(dp) :: px, py
      integer :: i
      ! one pass over the nodes, no reshaped copy of de (profiled: the
      ! reshape was a library call per Gauss point)
      eps0 = 0.0_dp;  kap = 0.0_dp;  wx = 0.0_dp;  wy = 0.0_dp
      nodes: do i = 1, nen
         px = dxy(1, i);  py = dxy(2, i)
         ! freedoms of node i: u, v, w, psi_x, psi_y = de(5i-4 .. 5i)
         eps0(1) = eps0(1) + px*de(5*i-4)
         eps0(2) = eps0(2) + py*de(5*i-3)
         eps0(3) = eps0(3) + py*de(5*i-4) + px*de(5*i-3)
         wx = wx + px*de(5*i-2)
         wy = wy + py*de(5*i-2)
         kap(1) = kap(1) + px*de(5*i-1)
         kap(2) = kap(2) + py*de(5*i)
         kap(3) = kap(3) + py*de(5*i-1) + px*de(5*i)
      end do nodes
   end subroutine point_strains

   !> The von Karman membrane strain of eq. (2), eps_nl = (w,x^2/2, w,y^2/2, w,x w,y).
   pure function von_karman(wx, wy) result(enl)
      real(dp), intent(in) :: wx, wy                !< slopes w,x and w,y (-)
      real(dp) :: enl(3)
      enl = [0.5_dp*wx*wx, 0.5_dp*wy*wy, wx*wy]
   end function von_karman

   !> [Bm; Bb] (6 x 45) at a point.
   pure function b_membrane_bending(dxy) result(bmat)
      real(dp), intent(in) :: dxy(2, nen)
      real(dp) :: bmat(6, nfe_elem)
      integer :: i
      bmat = 0.0_dp
      do i = 1, nen
         bmat(1, 5*i-4) = dxy(1, i)
         bmat(2, 5*i-3) = dxy(2, i)
         bmat(3, 5*i-4) = dxy(2, i);  bmat(3, 5*i-3) = dxy(1, i)
         bmat(4, 5*i-1) = dxy(1, i)
         bmat(5, 5*i)   = dxy(2, i)
         bmat(6, 5*i-1) = dxy(2, i);  bmat(6, 5*i) = dxy(1, i)
      end do
   end function b_membrane_bending

   !> Bs (2 x 45) at one shear point from the shear operator there:
   !> rows eps4 = psi_y + w,y, eps5 = psi_x + w,x (module shear_strain).
   pure function b_shear(b) result(bmat)
      real(dp), intent(in) :: b(2, 3, nen)
      real(dp) :: bmat(2, nfe_elem)
      integer :: i
      bmat = 0.0_dp
      do i = 1, nen
         bmat(:, 5*i-2) = b(:, 1, i)
         bmat(:, 5*i-1) = b(:, 2, i)
         bmat(:, 5*i)   = b(:, 3, i)
      end do
   end function b_shear

end module element_matrices
