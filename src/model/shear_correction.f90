!> Shear correction factors of a laminate by Whitney's method (J. M.
!> Whitney, "Shear correction factors for orthotropic laminates under static
!> load", J. Appl. Mech. 40 (1973) 302-304): the k4, k5 of the paper's
!> Table 1 and eq. (6), computed from the layup when the deck does not give
!> them. The method (cylindrical bending, equilibrium, complementary
!> energy) is written out above whitney_factor_squared.
!>
!> The paper tabulates k, the square root of Whitney's energy factor k^2:
!> its eq. (6) multiplies by k_i k_j, so Abar44 = k4^2 int Qbar44 dz is
!> Whitney's corrected stiffness. Against Table 1: docs/MODEL.md.
module shear_correction
   use kinds, only: dp
   use materials, only: lamina_t, lamina_qbar, lamina_qbar_shear
   use gauss_rules, only: gauss_1d
   implicit none
   private
   public :: whitney_shear_factors, whitney_factor_squared

   !> Gauss points per ply: exact for the quartic F(z)^2.
   integer, parameter :: n_gauss = 3

contains

   !> Shear correction factors k4 (yz) and k5 (xz) of a layup by Whitney's
   !> method (above whitney_factor_squared): the factors whose products enter
   !> Abar_ij = int k_i k_j Qbar_ij dz of eq. (6).
   pure subroutine whitney_shear_factors(lam, angles, h, k4, k5)
      type(lamina_t), intent(in) :: lam    !< the lamina, the same in every ply
      real(dp), intent(in) :: angles(:)    !< ply angles from x, bottom (z = -h/2) to top (deg)
      real(dp), intent(in) :: h            !< laminate thickness, plies equally thick (m)
      real(dp), intent(out) :: k4          !< shear correction factor of the yz direction (-)
      real(dp), intent(out) :: k5          !< shear correction factor of the xz direction (-)
      real(dp) :: qb(3,3), qs(2,2), det
      real(dp), dimension(size(angles)) :: q11, q22, g44, g55, s44, s55
      integer :: ply

      plies: do ply = 1, size(angles)
         qb = lamina_qbar(lam, angles(ply))
         qs = lamina_qbar_shear(lam, angles(ply))
         det = qs(1,1)*qs(2,2) - qs(1,2)*qs(2,1)
         q11(ply) = qb(1,1);  q22(ply) = qb(2,2)
         g44(ply) = qs(1,1);  g55(ply) = qs(2,2)
         s44(ply) = qs(2,2)/det          ! gamma_yz per tau_yz with tau_xz = 0
         s55(ply) = qs(1,1)/det          ! gamma_xz per tau_xz with tau_yz = 0
      end do plies
      k4 = sqrt(whitney_factor_squared(q22, g44, s44, h))
      k5 = sqrt(whitney_factor_squared(q11, g55, s55, h))
   end subroutine whitney_shear_factors

   !> The method, per direction (written for xz, the factor k5; yz and k4 swap
   !> 1 <-> 2 and 4 <-> 5):
   !>
   !>  1. Cylindrical bending about y (epsilon_y = gamma_xy = 0, N_x = 0): the
   !>     bending stress of ply k is
   !>        sigma_x(z) = Qbar11_k (z - z_n) M_x / Dt11,
   !>     with the neutral surface z_n = B11/A11 and Dt11 = D11 - B11^2/A11
   !>     (z_n = 0 and Dt11 = D11 for a symmetric laminate).
   !>  2. Equilibrium, d sigma_x/dx + d tau_xz/dz = 0 with dM_x/dx = Q_x, gives
   !>     the shear stress that vanishes on both faces:
   !>        tau_xz(z) = (Q_x/Dt11) F(z),   F(z) = -int_{-h/2}^{z} Qbar11 (zeta - z_n) dzeta,
   !>     F(+h/2) = -(B11 - z_n A11) = 0.
   !>  3. Energy: the complementary energy of that stress per unit area,
   !>        1/2 int tau_xz^2 S55 dz = 1/2 (Q_x/Dt11)^2 int F^2 S55 dz,
   !>     where S55 = Qbar44/(Qbar44 Qbar55 - Qbar45^2) is the ply's transverse
   !>     shear compliance under tau_xz alone (tau_yz = 0), equals that of the
   !>     first-order theory, 1/2 Q_x^2/(k5^2 int Qbar55 dz). Hence
   !>        k5^2 = Dt11^2 / ( int Qbar55 dz * int F^2 S55 dz ).
   !>     For a homogeneous plate F = Q11 (z^2 - h^2/4)/2 and k^2 = 5/6.
   !>
   !> The integrals are exact: F is a quadratic in z within a ply, so F^2 is a
   !> quartic and the 3-point Gauss rule (exact to degree 5) integrates it ply
   !> by ply.
   !>
   !> Whitney's k^2 of one direction (steps 1-3 above) for plies of
   !> equal thickness h/n, listed bottom to top:
   !>    k^2 = Dt^2 / ( int G dz * int F(z)^2 S dz ).
   pure function whitney_factor_squared(q_bend, g_shear, s_shear, h) result(k2)
      real(dp), intent(in) :: q_bend(:)    !< bending modulus of each ply, Qbar11 or Qbar22 (Pa)
      real(dp), intent(in) :: g_shear(:)   !< transverse shear modulus of each ply, Qbar55 or Qbar44 (Pa)
      real(dp), intent(in) :: s_shear(:)   !< transverse shear compliance of each ply, S55 or S44 (1/Pa)
      real(dp), intent(in) :: h            !< laminate thickness (m)
      real(dp) :: k2
      real(dp) :: t, z0, z1, a1, b1, d1, zn, dt, f0, gbar, energy, xi(n_gauss), w(n_gauss), z
      integer :: ply, g, n

      n = size(q_bend)
      t = h/real(n, dp)
      a1 = 0.0_dp;  b1 = 0.0_dp;  d1 = 0.0_dp
      stiffness: do ply = 1, n
         z0 = -0.5_dp*h + real(ply - 1, dp)*t
         z1 = z0 + t
         a1 = a1 + q_bend(ply)*(z1 - z0)
         b1 = b1 + q_bend(ply)*(z1**2 - z0**2)/2.0_dp
         d1 = d1 + q_bend(ply)*(z1**3 - z0**3)/3.0_dp
      end do stiffness
      zn = b1/a1                 ! neutral surface of cylindrical bending
      dt = d1 - b1**2/a1         ! bending stiffness about it
      gbar = sum(g_shear)*t      ! int G dz

      call gauss_1d(n_gauss, xi, w)
      f0 = 0.0_dp                ! F at the bottom of the current ply
      energy = 0.0_dp            ! int F^2 S dz
      shear_energy: do ply = 1, n
         z0 = -0.5_dp*h + real(ply - 1, dp)*t
         do g = 1, n_gauss
            z = z0 + 0.5_dp*t*(1.0_dp + xi(g))
            energy = energy + 0.5_dp*t*w(g)*s_shear(ply)*f_at(z)**2
         end do
         f0 = f_at(z0 + t)
      end do shear_energy
      k2 = dt**2/(gbar*energy)

   contains

      !> F(z) within the current ply (bottom z0, F = f0 there).
      pure function f_at(zz) result(f)
         real(dp), intent(in) :: zz   !< height in the ply (m)
         real(dp) :: f
         f = f0 - 0.5_dp*q_bend(ply)*((zz - zn)**2 - (z0 - zn)**2)
      end function f_at

   end function whitney_factor_squared

end module shear_correction
