!> Where delamination may start, from what the undamaged run computes:
!> threshold load, impact regime, Choi & Chang's index per interface.
!>  - Davies & Zhang, Int. J. Impact Eng. 16 (1995) 149-170: P_c = pi sqrt(32 D* G_IIc / 3);
!>    D* of R. Olsson, Compos. Part A 32 (2001) 1207-1215: D* = sqrt(D11 D22 (A + 1)/2),
!>    A = (D12 + 2 D66)/sqrt(D11 D22); small-mass impact 1.213 P_c (Olsson, Donadon &
!>    Falzon, Int. J. Solids Struct. 43 (2006) 3124-3141).
!>  - Regime: R. Olsson, Compos. Part A 31 (2000) 879-887, impactor/plate mass (the
!>    whole plate) below 0.23 small mass, above 2 large mass, between otherwise.
!>  - H. Y. Choi & F.-K. Chang, J. Compos. Mater. 26 (1992) 2134-2169: interface n
!>    between ply n (impacted side) and ply n+1,
!>      e_D^2 = D_a [(s23^n/S_i)^2 + (s13^(n+1)/S_i)^2 + (s22^(n+1)/Y^(n+1))^2],
!>    ply averages in each ply's material axes (ply_stress, mean), Y = Yt for
!>    s22 >= 0 else Yc, S_i = S12 (the code's strength of tau_13), D_a = 1.8 (their
!>    fit for T300/976). The index is e_D^2 (quadratic like Hashin's), 1 at onset.
module delamination
   use kinds, only: dp, pi
   use failure_criteria, only: strength_t
   implicit none
   private
   public :: effective_stiffness, threshold_load, impact_regime, choi_chang_index, interface_indices
   public :: dynamic_factor
   public :: delamination_t, delamination_open, delamination_force, delamination_point, write_delamination_scene

   !> Small-mass dynamic threshold over the static one (-).
   real(dp), parameter :: dynamic_factor = 1.213_dp
   !> Olsson's mass-ratio bounds of the small- and large-mass regimes (-).
   real(dp), parameter :: small_mass_ratio = 0.23_dp, large_mass_ratio = 2.0_dp
   !> Choi & Chang's empirical constant D_a (-).
   real(dp), parameter :: choi_chang_da = 1.8_dp

   !> What a run finds of delamination (the thresholds with G_IIc, the
   !> interfaces with the ply strengths).
   type :: delamination_t
      real(dp) :: ratio = 0.0_dp                  !< impactor/plate mass (-)
      logical :: threshold = .false.              !< G_IIc given: p_c, p_dyn, onset
      real(dp) :: p_c = 0.0_dp, p_dyn = 0.0_dp    !< static and small-mass thresholds (N)
      real(dp) :: onset = -1.0_dp                 !< first time the force passed p_c (s), -1 never
      logical :: interfaces = .false.             !< strengths given: map, max_*
      type(strength_t) :: strength                !< ply strengths (Pa)
      real(dp), allocatable :: map(:,:)           !< (nply - 1, npoint) largest e_D^2 over the run
      real(dp) :: max_index = 0.0_dp              !< the run's largest e_D^2
      integer :: max_interface = 0, max_point = 0 !< where (interface k: plies k, k+1)
   end type delamination_t

contains

   !> The record of a run: its regime; its thresholds when G_IIc is given;
   !> its interfaces' map when the strengths are (none with one ply).
   pure subroutine delamination_open(rec, d, with_g2c, g2c, with_str, str, nply, npoint)
      type(delamination_t), intent(out) :: rec    !< the record (its ratio set by the caller)
      real(dp), intent(in) :: d(3,3)              !< bending stiffness D_ij (N m)
      logical, intent(in) :: with_g2c             !< G_IIc given
      real(dp), intent(in) :: g2c                 !< G_IIc (J/m^2), when given
      logical, intent(in) :: with_str             !< the strengths given
      type(strength_t), intent(in) :: str         !< ply strengths (Pa), when given
      integer, intent(in) :: nply, npoint         !< plies; Gauss points
      if (with_g2c) then
         rec%threshold = .true.
         rec%p_c = threshold_load(d, g2c)
         rec%p_dyn = dynamic_factor*rec%p_c
      end if
      if (with_str) then
         rec%interfaces = nply > 1
         rec%strength = str
         allocate (rec%map(nply - 1, npoint))
         rec%map = 0.0_dp
      end if
   end subroutine delamination_open

   !> The contact force f at time t: the first time it passes P_c.
   pure subroutine delamination_force(rec, t, f)
      type(delamination_t), intent(inout) :: rec  !< the record
      real(dp), intent(in) :: t, f                !< time (s), contact force (N)
      if (rec%threshold .and. rec%onset < 0.0_dp .and. f > rec%p_c) rec%onset = t
   end subroutine delamination_force

   !> The ply averages mean(5, nply) at point p: its interfaces' e_D^2 into
   !> the map and the run's largest.
   pure subroutine delamination_point(rec, p, mean)
      type(delamination_t), intent(inout) :: rec  !< the record
      integer, intent(in) :: p                    !< the point
      real(dp), intent(in) :: mean(:,:)           !< (5, nply) ply averages (Pa)
      real(dp) :: ed2(size(mean, 2) - 1)
      integer :: k
      if (.not. rec%interfaces) return
      call interface_indices(rec%strength, mean, ed2)
      rec%map(:, p) = max(rec%map(:, p), ed2)
      k = maxloc(ed2, dim=1)
      if (ed2(k) > rec%max_index) then
         rec%max_index = ed2(k)
         rec%max_interface = k
         rec%max_point = p
      end if
   end subroutine delamination_point

   !> Olsson's effective bending stiffness D* (N m) of D (1, 2, 6 order).
   pure real(dp) function effective_stiffness(d)
      real(dp), intent(in) :: d(3,3)          !< bending stiffness D_ij (N m)
      real(dp) :: a
      a = (d(1,2) + 2.0_dp*d(3,3))/sqrt(d(1,1)*d(2,2))
      effective_stiffness = sqrt(d(1,1)*d(2,2)*(a + 1.0_dp)/2.0_dp)
   end function effective_stiffness

   !> Davies & Zhang's static delamination threshold load P_c (N).
   pure real(dp) function threshold_load(d, g2c)
      real(dp), intent(in) :: d(3,3)          !< bending stiffness D_ij (N m)
      real(dp), intent(in) :: g2c             !< mode II interlaminar fracture toughness (J/m^2)
      threshold_load = pi*sqrt(32.0_dp*effective_stiffness(d)*g2c/3.0_dp)
   end function threshold_load

   !> The impact regime of an impactor/plate mass ratio: 'small mass',
   !> 'large mass' or 'between'.
   pure function impact_regime(ratio) result(word)
      real(dp), intent(in) :: ratio           !< impactor mass / plate mass (-)
      character(len=:), allocatable :: word
      if (ratio < small_mass_ratio) then
         word = 'small mass'
      else if (ratio > large_mass_ratio) then
         word = 'large mass'
      else
         word = 'between'
      end if
   end function impact_regime

   !> Choi & Chang's e_D^2 of one interface (module header).
   pure real(dp) function choi_chang_index(str, upper, lower)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      real(dp), intent(in) :: upper(5)        !< ply n's averages (s11, s22, t12, t23, t13) (Pa)
      real(dp), intent(in) :: lower(5)        !< ply n+1's averages (Pa)
      real(dp) :: y
      y = merge(str%yt, str%yc, lower(2) >= 0.0_dp)
      choi_chang_index = choi_chang_da*((upper(4)/str%s12)**2 + (lower(5)/str%s12)**2 + (lower(2)/y)**2)
   end function choi_chang_index

   !> e_D^2 of every interface of a point from its ply averages:
   !> ed2(k) between plies k and k+1.
   pure subroutine interface_indices(str, mean, ed2)
      type(strength_t), intent(in) :: str     !< ply strengths (Pa)
      real(dp), intent(in) :: mean(:,:)       !< (5, nply) ply averages, impacted face first (Pa)
      real(dp), intent(out) :: ed2(:)         !< (nply - 1) indices (-)
      integer :: k
      do k = 1, size(ed2)
         ed2(k) = choi_chang_index(str, mean(:, k), mean(:, k + 1))
      end do
   end subroutine interface_indices

   !> The scene check's lines: the regime, the thresholds, and, when the
   !> deck asks for strength, what the code does not model.
   subroutine write_delamination_scene(unit, d, impactor_mass, plate_mass, with_g2c, g2c, asked)
      integer, intent(in) :: unit                 !< open formatted unit
      real(dp), intent(in) :: d(3,3)              !< bending stiffness D_ij (N m)
      real(dp), intent(in) :: impactor_mass, plate_mass   !< (kg), the whole plate's
      logical, intent(in) :: with_g2c             !< G_IIc given
      real(dp), intent(in) :: g2c                 !< G_IIc (J/m^2), when given
      logical, intent(in) :: asked                !< &strength gives strengths or toughnesses
      character(len=*), parameter :: lead = 'scene: '
      write (unit, '(a)') lead // 'impact regime     ' // impact_regime(impactor_mass/plate_mass) &
         // ' (Olsson 2000, of the mass ratio: below 0.23 small mass, wave-controlled; above 2 large mass, ' &
         // 'quasi-static; between otherwise)'
      if (with_g2c) then
         write (unit, '(a,es10.3,a,es10.3,a,es10.3,a)') lead // 'delamination      threshold P_c = ', &
            threshold_load(d, g2c), ' N, small mass 1.213 P_c = ', dynamic_factor*threshold_load(d, g2c), &
            ' N (Davies & Zhang 1995, D* = ', effective_stiffness(d), ' N m)'
      else
         write (unit, '(a)') lead // 'delamination      threshold not computed (&strength g2c not given)'
      end if
      if (asked) write (unit, '(a)') lead // 'out of scope      delamination growth and shape, fibre kinking, ' &
         // 'through-thickness crushing under the impactor, compression after impact (they need stacked ' &
         // 'plates with cohesive interfaces, or solids): the interface indices say where delamination ' &
         // 'starts, not what it becomes; ply damage (&damage) softens the plies in their plane only'
   end subroutine write_delamination_scene

end module delamination
