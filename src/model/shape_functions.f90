!> The 9-node Lagrange quadrilateral: shape functions of eq. (14).
!>
!> Local node numbering (corners counter-clockwise, then mid-sides, then
!> the centre), on the reference square (xi, eta) in [-1, 1]^2:
!>
!>       4 ---- 7 ---- 3        eta
!>       |             |         ^
!>       8      9      6         |
!>       |             |         +--> xi
!>       1 ---- 5 ---- 2
!>
!> phi_i(xi, eta) = L_a(xi) L_b(eta), with the quadratic Lagrange polynomials
!> L_1 = s(s-1)/2, L_2 = 1 - s^2, L_3 = s(s+1)/2 at s = -1, 0, +1.
module shape_functions
   use kinds, only: dp
   implicit none
   private
   public :: nen, shape9, shape9_derivs, shape9_second_derivs, node_xi, node_position

   !> Nodes per element.
   integer, parameter :: nen = 9
   !> Position index (1: -1, 2: 0, 3: +1) of each node along xi and eta.
   integer, parameter :: ia(nen) = [1, 3, 3, 1, 2, 3, 2, 1, 2]
   integer, parameter :: ib(nen) = [1, 1, 3, 3, 1, 2, 3, 2, 2]

contains

   !> Position index (1: -1, 2: 0, 3: +1) of local node i along xi (k = 1)
   !> or eta (k = 2): phi_i = L_a(xi) L_b(eta) with a = node_position(1, i),
   !> b = node_position(2, i).
   pure integer function node_position(k, i)
      integer, intent(in) :: k   !< 1: xi, 2: eta
      integer, intent(in) :: i   !< local node, 1..9
      node_position = merge(ia(i), ib(i), k == 1)
   end function node_position

   !> Reference coordinates (xi, eta) of local node i.
   pure function node_xi(i) result(x)
      integer, intent(in) :: i   !< local node, 1..9
      real(dp) :: x(2)
      real(dp), parameter :: s(3) = [-1.0_dp, 0.0_dp, 1.0_dp]
      x = [s(ia(i)), s(ib(i))]
   end function node_xi

   !> Values of the nine shape functions at (xi, eta).
   pure function shape9(xi, eta) result(phi)
      real(dp), intent(in) :: xi, eta   !< reference coordinates
      real(dp) :: phi(nen)
      real(dp) :: lx(3), ly(3), dl(3)
      call lagrange3(xi, lx, dl)
      call lagrange3(eta, ly, dl)
      phi = lx(ia)*ly(ib)
   end function shape9

   !> Derivatives of the nine shape functions with respect to xi and eta:
   !> dphi(1,i) = d phi_i / d xi, dphi(2,i) = d phi_i / d eta.
   pure function shape9_derivs(xi, eta) result(dphi)
      real(dp), intent(in) :: xi, eta   !< reference coordinates
      real(dp) :: dphi(2, nen)
      real(dp) :: lx(3), ly(3), dlx(3), dly(3)
      call lagrange3(xi, lx, dlx)
      call lagrange3(eta, ly, dly)
      dphi(1,:) = dlx(ia)*ly(ib)
      dphi(2,:) = lx(ia)*dly(ib)
   end function shape9_derivs

   !> Second derivatives of the nine shape functions with respect to xi and
   !> eta: d2phi(1,i) = d2 phi_i/d xi2, d2phi(2,i) = d2 phi_i/d eta2,
   !> d2phi(3,i) = d2 phi_i/d xi d eta (the ply stresses' equilibrium,
   !> src/strength/ply_stress.f90, needs the gradients of the strains).
   pure function shape9_second_derivs(xi, eta) result(d2phi)
      real(dp), intent(in) :: xi, eta   !< reference coordinates
      real(dp) :: d2phi(3, nen)
      real(dp) :: lx(3), ly(3), dlx(3), dly(3)
      real(dp), parameter :: d2l(3) = [1.0_dp, -2.0_dp, 1.0_dp]   ! L'' of the three polynomials
      call lagrange3(xi, lx, dlx)
      call lagrange3(eta, ly, dly)
      d2phi(1,:) = d2l(ia)*ly(ib)
      d2phi(2,:) = lx(ia)*d2l(ib)
      d2phi(3,:) = dlx(ia)*dly(ib)
   end function shape9_second_derivs

   !> Quadratic Lagrange polynomials through s = -1, 0, 1 and their slopes.
   pure subroutine lagrange3(s, l, dl)
      real(dp), intent(in) :: s        !< coordinate
      real(dp), intent(out) :: l(3)    !< values
      real(dp), intent(out) :: dl(3)   !< derivatives
      l  = [0.5_dp*s*(s - 1.0_dp), 1.0_dp - s*s, 0.5_dp*s*(s + 1.0_dp)]
      dl = [s - 0.5_dp, -2.0_dp*s, s + 0.5_dp]
   end subroutine lagrange3

end module shape_functions
