!> Progressive damage of one ply at one point, plane stress, in the ply's
!> material axes: Hashin initiation (fibre tension and compression, matrix
!> tension and compression), linear softening per mode regularised by the
!> mode's fracture energy and the element's characteristic length (crack
!> band: Bazant & Oh 1983; Lapczyk & Hurtado 2007, Abaqus' damage evolution
!> for shells), damage that never heals, the viscous regularisation of
!> Lapczyk & Hurtado, the snap-back guard of Maimi et al. (2007) and the
!> damaged stiffness of Matzenmiller, Lubliner & Taylor (1995). The paper
!> stops at the undamaged lamina law, eq. (3); this replaces its Q of each
!> ply by Q(d). Formulas above ply_damage_step. More: docs/STRENGTH.md.
module ply_damage
   use kinds, only: dp
   use materials, only: lamina_t
   use failure_criteria, only: strength_t
   implicit none
   private
   public :: damage_card_t, ply_damage_step, damaged_q, ndmode, dmode_ft, dmode_fc, dmode_mt, dmode_mc, dmode_names

   !> The four damage modes, in the order of d(:): fibre tension and
   !> compression, matrix tension and compression.
   integer, parameter :: dmode_ft = 1, dmode_fc = 2, dmode_mt = 3, dmode_mc = 4, ndmode = 4
   character(len=18), parameter :: dmode_names(ndmode) = [character(len=18) :: 'fibre_tension', &
      'fibre_compression', 'matrix_tension', 'matrix_compression']

   !> What the kernel needs of a ply's material.
   type :: damage_card_t
      type(lamina_t) :: lam            !< elastic constants (E1, E2, G12, nu12 used)
      type(strength_t) :: str          !< strengths Xt, Xc, Yt, Yc, S12 (= S_L), S23 (= S_T) (Pa)
      real(dp) :: g(ndmode) = 0.0_dp   !< fracture energies gft, gfc, gmt, gmc (J/m^2)
      real(dp) :: alpha = 0.0_dp       !< share of tau_12 in fibre tension initiation (Abaqus' default 0)
      real(dp) :: eta = 0.0_dp         !< viscosity of the regularisation (s); 0: none
   end type damage_card_t

contains

   !> One increment of a ply point. Effective stress sig = M C(d) eps, M =
   !> diag(1/(1-d_f), 1/(1-d_m), 1/(1-d_s)) (Abaqus: the undamaged stress
   !> the damaged ply carries), with the damage at the start of the
   !> increment. Initiation indices (Hashin 1980 in plane stress, Abaqus'
   !> form; S_L = S12, S_T = S23):
   !>   ft (sig11 >= 0): (sig11/Xt)^2 + alpha (sig12/S_L)^2
   !>   fc (sig11 <  0): (sig11/Xc)^2
   !>   mt (sig22 >= 0): (sig22/Yt)^2 + (sig12/S_L)^2
   !>   mc (sig22 <  0): (sig22/(2 S_T))^2 + ((Yc/(2 S_T))^2 - 1) sig22/Yc + (sig12/S_L)^2
   !> Each is F(lambda sig) = a lambda^2 + b lambda along the current strain
   !> direction; the loading factor r = (b + sqrt(b^2 + 4a))/2 is the ratio
   !> delta_eq/delta_0 of the equivalent displacements of Lapczyk & Hurtado
   !> (r = 1 at onset). With sig_eq delta_eq = L w, w the mode's work density
   !> (ft: <sig11><eps11> + alpha sig12 gam12; fc: <-sig11><-eps11>;
   !> mt: <sig22><eps22> + sig12 gam12; mc: <-sig22><-eps22> + sig12 gam12),
   !> the ratio of final to onset displacement is r_f = delta_f/delta_0 =
   !> 2 G r^2/(L w), and linear softening gives
   !>   d = delta_f (delta_eq - delta_0)/(delta_eq (delta_f - delta_0)) = r_f (r - 1)/(r (r_f - 1)),
   !> so that L times the area under the stress-strain curve is G. Snap-back
   !> guard: r_f <= 1 (an element longer than 2 E G/X^2) would need the
   !> stress to fall faster than the strain unloads; the mode's strengths are
   !> then reduced by sqrt(r_f) (Maimi et al. 2007), which makes r_f = 1: the
   !> stress drops to zero at the reduced onset and L times the energy is
   !> still G; snapback(m) says so. d(m) = max(d(m), new): never heals. The
   !> stiffness uses dv, d's viscous shadow (Lapczyk & Hurtado):
   !> dv = (dt d + eta dv_old)/(eta + dt), dv = d when eta = 0.
   !> diss: the energy per unit volume this increment dissipated,
   !> eps.(C(dv_old) - C(dv)).eps/2 (J/m^3).
   pure subroutine ply_damage_step(card, eps, lc, dt, d, dv, snapback, diss)
      type(damage_card_t), intent(in) :: card   !< the ply's material
      real(dp), intent(in) :: eps(3)            !< (eps11, eps22, gamma12), material axes
      real(dp), intent(in) :: lc                !< characteristic length of the point (m)
      real(dp), intent(in) :: dt                !< the increment's time (s)
      real(dp), intent(inout) :: d(ndmode)      !< damage, the largest reached (-)
      real(dp), intent(inout) :: dv(ndmode)     !< its viscous shadow, in the stiffness (-)
      logical, intent(out) :: snapback(ndmode)  !< the mode's strengths were reduced
      real(dp), intent(out) :: diss             !< energy dissipated per unit volume (J/m^3)
      real(dp) :: sig(3), a(ndmode), b(ndmode), w(ndmode), r, rf, dnew, q_old(3,3)
      integer :: m
      q_old = damaged_q(card%lam, dv, eps)
      sig = effective_stress(card%lam, dv, eps)
      call mode_terms(card, sig, eps, a, b, w)
      snapback = .false.
      modes: do m = 1, ndmode
         if (a(m) <= 0.0_dp .and. b(m) <= 0.0_dp) cycle modes
         if (w(m) <= 0.0_dp) cycle modes
         r = 0.5_dp*(b(m) + sqrt(b(m)**2 + 4.0_dp*a(m)))
         rf = 2.0_dp*card%g(m)*r*r/(lc*w(m))       ! independent of the strain's size
         if (rf <= 1.0_dp) then           ! strengths reduced by sqrt(rf): loading factor r/sqrt(rf), r_f = 1
            if (r*r <= rf) cycle modes
            snapback(m) = d(m) < 1.0_dp      ! reported at the increment it acts
            dnew = 1.0_dp
         else
            if (r <= 1.0_dp) cycle modes
            dnew = min(1.0_dp, rf*(r - 1.0_dp)/(r*(rf - 1.0_dp)))
         end if
         d(m) = max(d(m), dnew)
      end do modes
      if (card%eta > 0.0_dp) then
         dv = (dt*d + card%eta*dv)/(card%eta + dt)
      else
         dv = d
      end if
      diss = 0.5_dp*dot_product(eps, matmul(q_old - damaged_q(card%lam, dv, eps), eps))
   end subroutine ply_damage_step

   !> The quadratic and linear coefficients a, b of each mode's index along
   !> the stress sig, and its work density w (above ply_damage_step); a = b
   !> = 0 for the mode the signs leave out.
   pure subroutine mode_terms(card, sig, eps, a, b, w)
      type(damage_card_t), intent(in) :: card
      real(dp), intent(in) :: sig(3), eps(3)
      real(dp), intent(out) :: a(ndmode), b(ndmode), w(ndmode)
      real(dp) :: shear
      associate (s => card%str)
         shear = (sig(3)/s%s12)**2
         a = 0.0_dp;  b = 0.0_dp;  w = 0.0_dp
         if (sig(1) >= 0.0_dp) then
            a(dmode_ft) = (sig(1)/s%xt)**2 + card%alpha*shear
            w(dmode_ft) = sig(1)*max(eps(1), 0.0_dp) + card%alpha*sig(3)*eps(3)
         else
            a(dmode_fc) = (sig(1)/s%xc)**2
            w(dmode_fc) = -sig(1)*max(-eps(1), 0.0_dp)
         end if
         if (sig(2) >= 0.0_dp) then
            a(dmode_mt) = (sig(2)/s%yt)**2 + shear
            w(dmode_mt) = sig(2)*max(eps(2), 0.0_dp) + sig(3)*eps(3)
         else
            a(dmode_mc) = (0.5_dp*sig(2)/s%s23)**2 + shear
            b(dmode_mc) = ((0.5_dp*s%yc/s%s23)**2 - 1.0_dp)*sig(2)/s%yc
            w(dmode_mc) = -sig(2)*max(-eps(2), 0.0_dp) + sig(3)*eps(3)
         end if
      end associate
   end subroutine mode_terms

   !> The active fibre and matrix damage and the shear damage of d
   !> (Abaqus): d_f by the sign of eps11's stress, d_m by eps22's,
   !> d_s = 1 - (1 - d_ft)(1 - d_fc)(1 - d_mt)(1 - d_mc).
   pure subroutine active_damage(lam, d, eps, df, dm, ds)
      type(lamina_t), intent(in) :: lam
      real(dp), intent(in) :: d(ndmode), eps(3)
      real(dp), intent(out) :: df, dm, ds
      real(dp) :: nu21, s1, s2
      nu21 = lam%nu12*lam%e2/lam%e1
      s1 = eps(1) + nu21*eps(2)          ! the signs of the undamaged sigma11, sigma22
      s2 = eps(2) + lam%nu12*eps(1)
      df = merge(d(dmode_ft), d(dmode_fc), s1 >= 0.0_dp)
      dm = merge(d(dmode_mt), d(dmode_mc), s2 >= 0.0_dp)
      ds = 1.0_dp - product(1.0_dp - d)
   end subroutine active_damage

   !> The damaged plane-stress stiffness (Matzenmiller, Lubliner & Taylor
   !> 1995, as in Abaqus), material axes, (11, 22, 12) with engineering
   !> gamma12, for damage d and the fibre and matrix damage the signs of the
   !> stress select (all the tension modes when eps is absent):
   !>   Q(d) = 1/D [ (1-d_f) E1, (1-d_f)(1-d_m) nu21 E1, 0; ., (1-d_m) E2, 0; 0, 0, D (1-d_s) G12 ],
   !>   D = 1 - (1-d_f)(1-d_m) nu12 nu21.   Q(0) is the lamina's Q of eq. (3).
   pure function damaged_q(lam, d, eps) result(q)
      type(lamina_t), intent(in) :: lam        !< the lamina
      real(dp), intent(in) :: d(ndmode)        !< damage (-)
      real(dp), intent(in), optional :: eps(3) !< the strain, for the signs
      real(dp) :: q(3,3)
      real(dp) :: df, dm, ds, nu21, den
      if (present(eps)) then
         call active_damage(lam, d, eps, df, dm, ds)
      else
         df = d(dmode_ft);  dm = d(dmode_mt);  ds = 1.0_dp - product(1.0_dp - d)
      end if
      nu21 = lam%nu12*lam%e2/lam%e1
      den = 1.0_dp - (1.0_dp - df)*(1.0_dp - dm)*lam%nu12*nu21
      q = 0.0_dp
      q(1,1) = (1.0_dp - df)*lam%e1/den
      q(2,2) = (1.0_dp - dm)*lam%e2/den
      q(1,2) = (1.0_dp - df)*(1.0_dp - dm)*nu21*lam%e1/den
      q(2,1) = q(1,2)
      q(3,3) = (1.0_dp - ds)*lam%g12
   end function damaged_q

   !> The effective stress M Q(d) eps (above ply_damage_step): no division
   !> by 1 - d, finite when a mode is fully damaged.
   pure function effective_stress(lam, d, eps) result(sig)
      type(lamina_t), intent(in) :: lam
      real(dp), intent(in) :: d(ndmode), eps(3)
      real(dp) :: sig(3)
      real(dp) :: df, dm, ds, nu21, den
      call active_damage(lam, d, eps, df, dm, ds)
      nu21 = lam%nu12*lam%e2/lam%e1
      den = 1.0_dp - (1.0_dp - df)*(1.0_dp - dm)*lam%nu12*nu21
      sig(1) = lam%e1*(eps(1) + (1.0_dp - dm)*nu21*eps(2))/den
      sig(2) = lam%e2*((1.0_dp - df)*lam%nu12*eps(1) + eps(2))/den
      sig(3) = lam%g12*eps(3)
   end function effective_stress

end module ply_damage
