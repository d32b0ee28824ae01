!> Lamina and laminate stiffness: the constitutive part of the model
!> (paper section 2.1).
!>  - eq. (3)  the lamina law {sigma}_k = [Qbar_ij]_k {eps}_k, Qbar the
!>             plane-stress stiffness rotated by the ply angle (Jones, ch. 2);
!>  - eq. (4)  {N; M} = [A B; B D]{eps0; kappa},  {Q2; Q1} = [Abar]{eps4; eps5};
!>  - eq. (6)  (A, B, D) = int (1, z, z^2) Qbar dz, Abar_ij = int k_i k_j
!>             Qbar_ij dz (i, j = 4, 5: Table 1's factors enter squared);
!>  - eq. (9)  (P, R, I) = int rho (1, z, z^2) dz.
!> Strains ordered (1, 2, 6) in-plane, (4, 5) transverse shear, eps4 =
!> gamma_yz, eps5 = gamma_xz. Ply angles from the x axis, plies listed from
!> z = -h/2 (the impacted face; z points the way the impactor moves) to
!> z = +h/2, all of thickness h/nply. More: docs/MODEL.md.
module materials
   use kinds, only: dp, pi
   implicit none
   private
   public :: lamina_t, laminate_t, lamina_qbar, lamina_qbar_shear, &
             laminate_from_layup, laminate_drop_bend_twist

   !> Orthotropic lamina (paper Table 3), SI units.
   type :: lamina_t
      real(dp) :: e1   !< modulus along the fibres (Pa)
      real(dp) :: e2   !< modulus across the fibres (Pa)
      real(dp) :: g12  !< in-plane shear modulus (Pa)
      real(dp) :: g13  !< transverse shear modulus, 1-3 plane (Pa)
      real(dp) :: g23  !< transverse shear modulus, 2-3 plane (Pa)
      real(dp) :: nu12 !< major Poisson ratio (-)
      real(dp) :: rho  !< density (kg/m^3)
   end type lamina_t

   !> Laminate stiffness and inertia per unit area, eq. (4), (6), (9).
   type :: laminate_t
      real(dp) :: a(3,3) = 0.0_dp   !< extensional stiffness A_ij, i,j = 1,2,6 (N/m)
      real(dp) :: b(3,3) = 0.0_dp   !< coupling stiffness B_ij (N)
      real(dp) :: d(3,3) = 0.0_dp   !< bending stiffness D_ij (N m)
      real(dp) :: as(2,2) = 0.0_dp  !< transverse shear stiffness Abar_ij, i,j = 4,5 (N/m)
      real(dp) :: p = 0.0_dp        !< translational inertia P = int rho dz (kg/m^2)
      real(dp) :: r = 0.0_dp        !< coupling inertia R = int rho z dz (kg/m)
      real(dp) :: i = 0.0_dp        !< rotary inertia I = int rho z^2 dz (kg)
      real(dp) :: h = 0.0_dp        !< thickness (m)
   end type laminate_t

contains

   !> Transformed reduced stiffness [Qbar] (i, j = 1, 2, 6) of a lamina whose
   !> fibres make the angle theta with the x axis; eq. (3), Jones eq. (2.85).
   pure function lamina_qbar(lam, theta_deg) result(qbar)
      type(lamina_t), intent(in) :: lam       !< the lamina
      real(dp), intent(in) :: theta_deg       !< ply angle from x (degrees)
      real(dp) :: qbar(3,3)
      real(dp) :: nu21, den, q11, q12, q22, q66, c, s, c2, s2, c4, s4, c2s2

      nu21 = lam%nu12*lam%e2/lam%e1
      den  = 1.0_dp - lam%nu12*nu21
      q11 = lam%e1/den
      q22 = lam%e2/den
      q12 = lam%nu12*lam%e2/den
      q66 = lam%g12
      c = cos(theta_deg*pi/180.0_dp)
      s = sin(theta_deg*pi/180.0_dp)
      c2 = c*c;  s2 = s*s;  c4 = c2*c2;  s4 = s2*s2;  c2s2 = c2*s2

      qbar(1,1) = q11*c4 + 2.0_dp*(q12 + 2.0_dp*q66)*c2s2 + q22*s4
      qbar(2,2) = q11*s4 + 2.0_dp*(q12 + 2.0_dp*q66)*c2s2 + q22*c4
      qbar(1,2) = (q11 + q22 - 4.0_dp*q66)*c2s2 + q12*(c4 + s4)
      qbar(3,3) = (q11 + q22 - 2.0_dp*q12 - 2.0_dp*q66)*c2s2 + q66*(c4 + s4)
      qbar(1,3) = (q11 - q12 - 2.0_dp*q66)*c2*c*s + (q12 - q22 + 2.0_dp*q66)*s2*s*c
      qbar(2,3) = (q11 - q12 - 2.0_dp*q66)*s2*s*c + (q12 - q22 + 2.0_dp*q66)*c2*c*s
      qbar(2,1) = qbar(1,2)
      qbar(3,1) = qbar(1,3)
      qbar(3,2) = qbar(2,3)
   end function lamina_qbar

   !> Transformed transverse shear stiffness (i, j = 4, 5) of a lamina,
   !> eq. (3): Qbar44 = G23 c^2 + G13 s^2, Qbar55 = G13 c^2 + G23 s^2,
   !> Qbar45 = (G13 - G23) c s.
   pure function lamina_qbar_shear(lam, theta_deg) result(qs)
      type(lamina_t), intent(in) :: lam       !< the lamina
      real(dp), intent(in) :: theta_deg       !< ply angle from x (degrees)
      real(dp) :: qs(2,2)
      real(dp) :: c, s

      c = cos(theta_deg*pi/180.0_dp)
      s = sin(theta_deg*pi/180.0_dp)
      qs(1,1) = lam%g23*c*c + lam%g13*s*s
      qs(2,2) = lam%g13*c*c + lam%g23*s*s
      qs(1,2) = (lam%g13 - lam%g23)*c*s
      qs(2,1) = qs(1,2)
   end function lamina_qbar_shear

   !> Laminate stiffness and inertias from the layup: eq. (6) and (9), the
   !> through-thickness integrals done exactly ply by ply.
   pure function laminate_from_layup(lam, angles, h, k4, k5) result(lmt)
      type(lamina_t), intent(in) :: lam        !< the lamina, same in every ply
      real(dp), intent(in) :: angles(:)        !< ply angles, bottom to top (degrees)
      real(dp), intent(in) :: h                !< laminate thickness (m)
      real(dp), intent(in) :: k4               !< shear correction factor k4 (yz), Table 1
      real(dp), intent(in) :: k5               !< shear correction factor k5 (xz), Table 1
      type(laminate_t) :: lmt
      real(dp) :: t, z0, z1, qb(3,3), qs(2,2), kk(2)
      integer :: ply

      t = h/real(size(angles), dp)
      kk = [k4, k5]
      lmt%h = h
      plies: do ply = 1, size(angles)
         z0 = -0.5_dp*h + real(ply - 1, dp)*t
         z1 = z0 + t
         qb = lamina_qbar(lam, angles(ply))
         qs = lamina_qbar_shear(lam, angles(ply))
         lmt%a = lmt%a + qb*(z1 - z0)
         lmt%b = lmt%b + qb*(z1**2 - z0**2)/2.0_dp
         lmt%d = lmt%d + qb*(z1**3 - z0**3)/3.0_dp
         ! eq. (6): Abar_ij = int k_i k_j Qbar_ij dz
         lmt%as = lmt%as + spread(kk, 2, 2)*spread(kk, 1, 2)*qs*(z1 - z0)
      end do plies
      ! eq. (9): inertias of a laminate of one material
      lmt%p = lam%rho*h
      lmt%r = 0.0_dp
      lmt%i = lam%rho*h**3/12.0_dp
   end function laminate_from_layup

   !> The quarter-plate model of section 3.1: D16 = D26 = 0, the average of
   !> the [0/45/0/-45/0]2s and [0/-45/0/45/0]2s laminates.
   pure function laminate_drop_bend_twist(lmt) result(q)
      type(laminate_t), intent(in) :: lmt      !< the laminate as laid up
      type(laminate_t) :: q
      q = lmt
      q%d(1,3) = 0.0_dp;  q%d(3,1) = 0.0_dp
      q%d(2,3) = 0.0_dp;  q%d(3,2) = 0.0_dp
   end function laminate_drop_bend_twist

end module materials
