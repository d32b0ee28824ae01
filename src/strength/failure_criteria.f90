!> Failure criteria of a unidirectional ply: the failure index of one
!> stress state in the ply's material axes (1 at failure, below 1 safe),
!> and the mode it names. Not from the paper, which stops at the ply
!> stresses of eq. (3); the criteria: Hashin (1980), maximum stress (Jones
!> 1975, the paper's reference 17), Tsai-Wu (1971), written out above
!> failure_index; the stresses and strengths: above strength_t.
!> Modes: mode_none (no stress), mode_fibre_tension, mode_fibre_compression,
!> mode_matrix_tension, mode_matrix_compression, mode_shear_12 (tau_12 or
!> tau_13 against S12), mode_shear_23 (tau_23 against S23); mode_names
!> gives their words. More: docs/STRENGTH.md.
module failure_criteria
   use kinds, only: dp
   implicit none
   private
   public :: strength_t, criterion_hashin, criterion_max_stress, criterion_tsai_wu, criterion_code
   public :: mode_none, mode_fibre_tension, mode_fibre_compression, mode_matrix_tension, &
             mode_matrix_compression, mode_shear_12, mode_shear_23, nmode, mode_names
   public :: failure_index, failure_indices

   !> Stresses in the material axes (1 along the fibres, 2 across them in the
   !> ply's plane, 3 through the thickness), in the paper's order of eq. (3):
   !>     sigma = (sigma_11, sigma_22, tau_12, tau_23, tau_13)   (1, 2, 6, 4, 5)
   !> sigma_33 = 0, the plate theory's (eq. 3 has no normal stress through the
   !> thickness; under the impactor the contact pressure is not in it).
   !>
   !> Strengths (Pa, all positive): Xt, Xc along the fibres in tension and
   !> compression, Yt, Yc across them, S12 the in-plane (axial) shear strength,
   !> which also holds tau_13 (a transversely isotropic ply: S13 = S12), S23 the
   !> transverse shear strength.
   !>
   !> Ply strengths (Pa), all positive.
   type :: strength_t
      real(dp) :: xt = 0.0_dp    !< tensile strength along the fibres
      real(dp) :: xc = 0.0_dp    !< compressive strength along the fibres (a magnitude)
      real(dp) :: yt = 0.0_dp    !< tensile strength across the fibres
      real(dp) :: yc = 0.0_dp    !< compressive strength across the fibres (a magnitude)
      real(dp) :: s12 = 0.0_dp   !< in-plane shear strength (also of tau_13)
      real(dp) :: s23 = 0.0_dp   !< transverse shear strength
   end type strength_t

   !> The criteria.
   integer, parameter :: criterion_hashin = 1, criterion_max_stress = 2, criterion_tsai_wu = 3
   !> The modes (above).
   integer, parameter :: mode_none = 0, mode_fibre_tension = 1, mode_fibre_compression = 2, &
      mode_matrix_tension = 3, mode_matrix_compression = 4, mode_shear_12 = 5, mode_shear_23 = 6, nmode = 6
   character(len=18), parameter :: mode_names(0:nmode) = [character(len=18) :: 'none', 'fibre_tension', &
      'fibre_compression', 'matrix_tension', 'matrix_compression', 'shear_12', 'shear_23']

contains

   !> The criterion code of its deck word ('hashin', 'max_stress',
   !> 'tsai_wu'); 0 for any other word.
   pure integer function criterion_code(word)
      character(len=*), intent(in) :: word   !< &strength criterion
      select case (trim(word))
      case ('hashin');     criterion_code = criterion_hashin
      case ('max_stress'); criterion_code = criterion_max_stress
      case ('tsai_wu');    criterion_code = criterion_tsai_wu
      case default;        criterion_code = 0
      end select
   end function criterion_code

   !> The failure index is 1 at failure, below 1 safe:
   !>  - 'hashin', Z. Hashin, "Failure criteria for unidirectional fiber
   !>    composites", J. Appl. Mech. 47 (1980) 329-334, eq. (23)-(26) with
   !>    sigma_33 = 0 (S_A = S12, S_T = S23):
   !>      fibre tension (sigma_11 >= 0)  (s11/Xt)^2 + (t12^2 + t13^2)/S12^2
   !>      fibre compression (s11 < 0)    (s11/Xc)^2
   !>      matrix tension (s22 >= 0)      (s22/Yt)^2 + t23^2/S23^2 + (t12^2 + t13^2)/S12^2
   !>      matrix compression (s22 < 0)   (s22/(2 S23))^2 + ((Yc/(2 S23))^2 - 1) s22/Yc
   !>                                     + t23^2/S23^2 + (t12^2 + t13^2)/S12^2
   !>    the index is the larger of the fibre mode and the matrix mode the
   !>    signs select; it is quadratic in the stresses (its square root is
   !>    about the stress ratio).
   !>  - 'max_stress', the maximum stress criterion (R. M. Jones, Mechanics of
   !>    Composite Materials, 1975, ch. 2, the paper's reference 17): the largest of
   !>    s11/Xt or -s11/Xc, s22/Yt or -s22/Yc, |t12|/S12, |t13|/S12, |t23|/S23;
   !>    linear in the stresses.
   !>  - 'tsai_wu', S. W. Tsai and E. M. Wu, "A general theory of strength for
   !>    anisotropic materials", J. Compos. Mater. 5 (1971) 58-80: with
   !>      F1 = 1/Xt - 1/Xc, F11 = 1/(Xt Xc), F2 = 1/Yt - 1/Yc, F22 = 1/(Yt Yc),
   !>      F66 = F55 = 1/S12^2, F44 = 1/S23^2, F12 = -sqrt(F11 F22)/2
   !>    (the interaction term of Tsai & Hahn, Introduction to Composite
   !>    Materials, 1980), the quadratic part a = F11 s11^2 + F22 s22^2 +
   !>    2 F12 s11 s22 + F66 t12^2 + F44 t23^2 + F55 t13^2 and the linear part
   !>    b = F1 s11 + F2 s22 fail at a + b = 1. The index is the inverse of the
   !>    strength ratio R (the factor on the stresses that reaches failure,
   !>    a R^2 + b R = 1): 1/R = (b + sqrt(b^2 + 4 a))/2, linear in the
   !>    stresses and 1 exactly when a + b = 1. The criterion names no mode;
   !>    the mode given is the one of the largest stress ratio (max_stress).
   !>
   !> The failure index and mode of the stress state sigma under criterion.
   pure subroutine failure_index(str, criterion, sigma, fi, mode)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      integer, intent(in) :: criterion        !< criterion_hashin, ...
      real(dp), intent(in) :: sigma(5)        !< (s11, s22, t12, t23, t13) in the material axes (Pa)
      real(dp), intent(out) :: fi             !< failure index (-), 1 at failure
      integer, intent(out) :: mode            !< its mode
      select case (criterion)
      case (criterion_max_stress)
         call max_stress_index(str, sigma, fi, mode)
      case (criterion_tsai_wu)
         call tsai_wu_index(str, sigma, fi, mode)
      case default
         call hashin_index(str, sigma, fi, mode)
      end select
   end subroutine failure_index

   !> failure_index of many stress states, sigma(:, j) -> fi(j), mode(j)
   !> (one call per Gauss point in the time loop).
   pure subroutine failure_indices(str, criterion, sigma, fi, mode)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      integer, intent(in) :: criterion        !< criterion_hashin, ...
      real(dp), intent(in) :: sigma(:,:)      !< (5, n) stress states in the material axes (Pa)
      real(dp), intent(out) :: fi(:)          !< (n) failure indices (-)
      integer, intent(out) :: mode(:)         !< (n) their modes
      real(dp) :: r(6)
      integer :: j
      select case (criterion)
      case (criterion_max_stress)
         do j = 1, size(fi)
            call max_stress_index(str, sigma(:, j), fi(j), mode(j))
         end do
      case (criterion_tsai_wu)
         do j = 1, size(fi)
            call tsai_wu_index(str, sigma(:, j), fi(j), mode(j))
         end do
      case default
         r = hashin_factors(str)
         do j = 1, size(fi)
            call hashin_scaled(r, sigma(:, j), fi(j), mode(j))
         end do
      end select
   end subroutine failure_indices

   !> Hashin (1980), eq. (23)-(26) with sigma_33 = 0 (above failure_index).
   pure subroutine hashin_index(str, sigma, fi, mode)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      real(dp), intent(in) :: sigma(5)        !< (s11, s22, t12, t23, t13) (Pa)
      real(dp), intent(out) :: fi             !< failure index (-)
      integer, intent(out) :: mode            !< the mode of the larger of the two indices
      call hashin_scaled(hashin_factors(str), sigma, fi, mode)
   end subroutine hashin_index

   !> The reciprocal strengths Hashin's criterion multiplies by: 1/Xt, 1/Xc,
   !> 1/Yt, 1/S23, 1/S12, and the factor ((Yc/(2 S23))^2 - 1)/Yc of matrix
   !> compression (the time loop divides once, not at every point).
   pure function hashin_factors(str) result(r)
      type(strength_t), intent(in) :: str
      real(dp) :: r(6)
      r = [1.0_dp/str%xt, 1.0_dp/str%xc, 1.0_dp/str%yt, 1.0_dp/str%s23, 1.0_dp/str%s12, &
           ((str%yc/(2.0_dp*str%s23))**2 - 1.0_dp)/str%yc]
   end function hashin_factors

   !> hashin_index with the factors of hashin_factors.
   pure subroutine hashin_scaled(r, sigma, fi, mode)
      real(dp), intent(in) :: r(6), sigma(5)
      real(dp), intent(out) :: fi
      integer, intent(out) :: mode
      real(dp) :: axial_shear, f_fibre, f_matrix
      integer :: m_fibre, m_matrix
      axial_shear = (sigma(3)**2 + sigma(5)**2)*r(5)**2
      if (sigma(1) >= 0.0_dp) then
         f_fibre = (sigma(1)*r(1))**2 + axial_shear
         m_fibre = mode_fibre_tension
      else
         f_fibre = (sigma(1)*r(2))**2
         m_fibre = mode_fibre_compression
      end if
      if (sigma(2) >= 0.0_dp) then
         f_matrix = (sigma(2)*r(3))**2 + (sigma(4)*r(4))**2 + axial_shear
         m_matrix = mode_matrix_tension
      else
         f_matrix = (0.5_dp*sigma(2)*r(4))**2 + r(6)*sigma(2) + (sigma(4)*r(4))**2 + axial_shear
         m_matrix = mode_matrix_compression
      end if
      if (f_fibre >= f_matrix) then
         fi = f_fibre;  mode = m_fibre
      else
         fi = f_matrix;  mode = m_matrix
      end if
      if (all(sigma == 0.0_dp)) mode = mode_none
   end subroutine hashin_scaled

   !> The maximum stress criterion (above failure_index).
   pure subroutine max_stress_index(str, sigma, fi, mode)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      real(dp), intent(in) :: sigma(5)        !< (s11, s22, t12, t23, t13) (Pa)
      real(dp), intent(out) :: fi             !< largest stress ratio (-)
      integer, intent(out) :: mode            !< its mode
      real(dp) :: r(6)
      integer, parameter :: modes(6) = [mode_fibre_tension, mode_fibre_compression, mode_matrix_tension, &
         mode_matrix_compression, mode_shear_12, mode_shear_23]
      r = 0.0_dp
      if (sigma(1) >= 0.0_dp) then
         r(1) = sigma(1)/str%xt
      else
         r(2) = -sigma(1)/str%xc
      end if
      if (sigma(2) >= 0.0_dp) then
         r(3) = sigma(2)/str%yt
      else
         r(4) = -sigma(2)/str%yc
      end if
      r(5) = max(abs(sigma(3)), abs(sigma(5)))/str%s12
      r(6) = abs(sigma(4))/str%s23
      mode = modes(maxloc(r, dim=1))
      fi = maxval(r)
      if (fi == 0.0_dp) mode = mode_none
   end subroutine max_stress_index

   !> Tsai-Wu (1971) as the inverse strength ratio (above failure_index).
   pure subroutine tsai_wu_index(str, sigma, fi, mode)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      real(dp), intent(in) :: sigma(5)        !< (s11, s22, t12, t23, t13) (Pa)
      real(dp), intent(out) :: fi             !< 1/R (-)
      integer, intent(out) :: mode            !< the largest stress ratio's mode
      real(dp) :: f1, f2, f11, f22, f12, quad, lin, ratio
      f1 = 1.0_dp/str%xt - 1.0_dp/str%xc
      f2 = 1.0_dp/str%yt - 1.0_dp/str%yc
      f11 = 1.0_dp/(str%xt*str%xc)
      f22 = 1.0_dp/(str%yt*str%yc)
      f12 = -0.5_dp*sqrt(f11*f22)
      quad = f11*sigma(1)**2 + f22*sigma(2)**2 + 2.0_dp*f12*sigma(1)*sigma(2) &
             + (sigma(3)**2 + sigma(5)**2)/str%s12**2 + (sigma(4)/str%s23)**2
      lin = f1*sigma(1) + f2*sigma(2)
      fi = 0.5_dp*(lin + sqrt(lin**2 + 4.0_dp*quad))
      call max_stress_index(str, sigma, ratio, mode)
   end subroutine tsai_wu_index

end module failure_criteria
