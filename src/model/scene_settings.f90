!> Settings from the scene: the time step &analysis dt and the mesh &mesh nx,
!> ny of a deck that does not give them, chosen before any model exists
!> from closed-form estimates (the Hertz contact time with the law of
!> eq. 11, the plate's fundamental period, the bending wavelength: above
!> hertz_contact_time), aiming at 1 % on the peak force and the largest
!> deflection; the rules: above scene_settings_of. A deck that gives them
!> runs them. Not from the paper. More: docs/MODEL.md, "Settings from the
!> scene".
module scene_settings
   use kinds, only: dp, pi
   use deck_schema, only: deck_t, is_given
   use materials, only: lamina_t, laminate_t, laminate_from_layup
   use number_text, only: real_short, int_str
   implicit none
   private
   public :: settings_t, scene_settings_of, choose_settings, hertz_contact_time, plate_period

   !> Time steps in the shorter of the Hertz contact time and the plate's period (above scene_settings_of).
   real(dp), parameter :: steps_per_time = 160.0_dp
   !> Elements per bending wavelength at the contact's frequency (above scene_settings_of).
   real(dp), parameter :: elements_per_wavelength = 10.0_dp
   !> Elements along the shorter side of the quarter plate, at least (above scene_settings_of).
   real(dp), parameter :: min_elements_side = 6.0_dp
   !> Johnson's factor of the Hertz contact time, eq. 11.24 (-).
   real(dp), parameter :: hertz_time_factor = 2.9432_dp
   !> Warburton's factors of the first mode of a clamped plate (-).
   real(dp), parameter :: g_clamped = 1.506_dp, h_clamped = 1.248_dp
   !> Shear correction used for the bending stiffness only (D does not depend on it) (-).
   real(dp), parameter :: k_any = 5.0_dp/6.0_dp
   !> Bounds of the chosen step (the schema's range of &analysis dt) (s).
   real(dp), parameter :: dt_min = 1.0e-10_dp, dt_max = 1.0e-2_dp
   !> Most elements along a side the choice gives (-).
   integer, parameter :: max_count = 200

   !> The settings chosen from the scene, and the estimates behind them.
   type :: settings_t
      real(dp) :: contact_time = 0.0_dp     !< Hertz contact time T_H against a rigid plate (s)
      real(dp) :: period = 0.0_dp           !< plate's fundamental period T_1 (s)
      real(dp) :: wavelength = 0.0_dp       !< bending wavelength at the contact's frequency (m)
      real(dp) :: contact_radius = 0.0_dp   !< Hertz radius sqrt(R alpha_m) (m)
      real(dp) :: mass_ratio = 0.0_dp       !< impactor mass / plate mass (-)
      real(dp) :: element = 0.0_dp          !< element size aimed at (m)
      real(dp) :: dt = 0.0_dp               !< the step (s)
      integer :: nx = 0, ny = 0             !< the counts of the deck's domain
      character(len=240) :: dt_reason = ''  !< 'dt chosen = ...', one line
      character(len=240) :: mesh_reason = '' !< 'nx, ny chosen = ...', one line
   end type settings_t

contains

   !> The chicken-and-egg: the static estimate of src/model/scene_model.f90
   !> (point_stiffness) needs a mesh; the choice here needs none. It uses:
   !>  - the Hertz contact time of the impactor against a rigid plate
   !>    (Johnson, Contact Mechanics, 1985, section 11.4, eq. 11.24 with the
   !>    law F = k alpha^1.5 of eq. 11):
   !>       alpha_m = (5 m v^2 / (4 k))^(2/5),   T_H = 2.9432 alpha_m / v;
   !>    the plate's compliance only lengthens the contact, so T_H is the
   !>    shortest time scale of the contact;
   !>  - the plate's fundamental period T_1 = 2 pi / omega_1 from Warburton's
   !>    formula for a specially orthotropic plate (Warburton 1954; Leissa,
   !>    Vibration of Plates, 1969, section 4.3; Dickinson 1978):
   !>       omega_1^2 = pi^4 / (rho h) [D11 G^4/a^4 + 2 (D12 + 2 D66) H^2/(a^2 b^2) + D22 G^4/b^4]
   !>    with G = H = 1 for simply supported edges (exact, Navier) and G =
   !>    1.506, H = 1.248 for clamped ones; free edges take the simply
   !>    supported value (D16, D26 are left out: an estimate);
   !>  - the bending wavelength at the contact's frequency, the wave that the
   !>    mesh must carry during the contact (Kirchhoff plate, D = sqrt(D11 D22)):
   !>       lambda = 2 pi (D / (rho h omega^2))^(1/4),   omega = 2 pi / T;
   !>  - the Hertz contact radius a = sqrt(R alpha_m) and the impactor's mass
   !>    against the plate's, reported with the choice.
   !>
   !> Hertz contact time of an impactor of mass m at speed v against a rigid
   !> plate, F = k alpha^1.5 (above; Johnson 1985, eq. 11.24) (s).
   pure real(dp) function hertz_contact_time(mass, velocity, k) result(t)
      real(dp), intent(in) :: mass       !< impactor mass (kg)
      real(dp), intent(in) :: velocity   !< impact velocity (m/s)
      real(dp), intent(in) :: k          !< contact stiffness (N/m^1.5)
      t = hertz_time_factor*hertz_indentation(mass, velocity, k)/velocity
   end function hertz_contact_time

   !> Largest Hertz indentation against a rigid plate, (5 m v^2/(4 k))^(2/5) (m).
   pure real(dp) function hertz_indentation(mass, velocity, k) result(alpha)
      real(dp), intent(in) :: mass, velocity, k   !< as hertz_contact_time
      alpha = (1.25_dp*mass*velocity**2/k)**0.4_dp
   end function hertz_indentation

   !> Fundamental period of the plate, Warburton's formula (above hertz_contact_time) (s).
   pure real(dp) function plate_period(lmt, a, b, edges) result(t)
      type(laminate_t), intent(in) :: lmt       !< the laminate (D, inertia P)
      real(dp), intent(in) :: a, b              !< plate sides (m)
      character(len=*), intent(in) :: edges     !< &boundary edges
      real(dp) :: g, h, omega2
      g = 1.0_dp;  h = 1.0_dp
      if (edges == 'clamped') then
         g = g_clamped;  h = h_clamped
      end if
      omega2 = pi**4/lmt%p*(lmt%d(1,1)*g**4/a**4 + 2.0_dp*(lmt%d(1,2) + 2.0_dp*lmt%d(3,3))*h**2/(a*b)**2 &
                            + lmt%d(2,2)*g**4/b**4)
      t = 2.0_dp*pi/sqrt(omega2)
   end function plate_period

   !> Bending wavelength of the plate at the period t (above hertz_contact_time) (m).
   pure real(dp) function bending_wavelength(lmt, t) result(lambda)
      type(laminate_t), intent(in) :: lmt       !< the laminate (D, inertia P)
      real(dp), intent(in) :: t                 !< period (s)
      real(dp) :: omega
      omega = 2.0_dp*pi/t
      lambda = 2.0_dp*pi*(sqrt(lmt%d(1,1)*lmt%d(2,2))/(lmt%p*omega**2))**0.25_dp
   end function bending_wavelength

   !> The step (of the impact and the pressure analyses; the static and modal
   !> ones have none, their dt stays not given): dt = min(T_H, T_1) /
   !> steps_per_time (T_1 alone for the pressure analysis), rounded down to two
   !> significant digits (the average-acceleration rule's period error grows as
   !> (omega dt)^2 / 12; what the step costs in the peak force:
   !> docs/MODEL.md, "Settings from the scene").
   !>
   !> The mesh: elements no larger than lambda / elements_per_wavelength
   !> (nine-node elements: two node spacings each) and no larger than the
   !> shorter side of the quarter plate / min_elements_side, the paper's
   !> 9 x 6 quarter on its plate (docs/VALIDATION.md). The Hertz disc is not a
   !> criterion (its load is spread over the element, &contact load =
   !> 'hertz'). The counts are those of the domain the deck's nx, ny count:
   !> the quarter with domain 'auto', 'quarter' or 'strip'; the half with
   !> 'half'; the whole plate with 'full' (src/model/mesh.f90).
   !>
   !> The settings the scene of `deck` calls for (as above), whether or
   !> not the deck gives them; the reasons say which estimate decided.
   pure function scene_settings_of(deck) result(s)
      type(deck_t), intent(in) :: deck          !< the validated deck
      type(settings_t) :: s
      type(laminate_t) :: lmt
      real(dp) :: t_scale, span(2)
      character(len=:), allocatable :: which

      lmt = laminate_from_layup(lamina_t(deck%e1, deck%e2, deck%g12, deck%g13, deck%g23, deck%nu12, deck%rho), &
                                deck%angles, deck%h, k_any, k_any)
      s%period = plate_period(lmt, deck%a, deck%b, deck%edges)
      s%mass_ratio = deck%mass/(deck%rho*deck%h*deck%a*deck%b)
      t_scale = s%period
      which = 'plate period T_1 = ' // real_short(s%period*1.0e6_dp) // ' us'
      if (deck%analysis_kind == 'impact') then
         s%contact_time = hertz_contact_time(deck%mass, deck%velocity, deck%k)
         s%contact_radius = sqrt(0.5_dp*deck%diameter*hertz_indentation(deck%mass, deck%velocity, deck%k))
         if (s%contact_time < s%period) then
            t_scale = s%contact_time
            which = 'Hertz contact time T_H = ' // real_short(s%contact_time*1.0e6_dp) // ' us (< ' // which // ')'
         else
            which = which // ' (<= Hertz contact time T_H = ' // real_short(s%contact_time*1.0e6_dp) // ' us)'
         end if
      end if
      s%dt = min(max(two_digits_down(t_scale/steps_per_time), dt_min), dt_max)
      s%dt_reason = 'dt chosen = ' // real_short(s%dt*1.0e6_dp) // ' us: ' // which // ' / ' &
         // int_str(nint(steps_per_time)) // ', 2 digits'

      s%wavelength = bending_wavelength(lmt, t_scale)
      s%element = min(s%wavelength/elements_per_wavelength, 0.5_dp*min(deck%a, deck%b)/min_elements_side)
      span = domain_span(deck)
      s%nx = min(max(ceiling(span(1)/s%element - 1.0e-9_dp), 1), max_count)
      s%ny = min(max(ceiling(span(2)/s%element - 1.0e-9_dp), 1), max_count)
      s%mesh_reason = 'nx, ny chosen = ' // int_str(s%nx) // ' x ' // int_str(s%ny) // ': elements <= ' &
         // real_short(s%element*1.0e3_dp) // ' mm = min(bending wavelength ' // real_short(s%wavelength*1.0e3_dp) &
         // ' mm/' // int_str(nint(elements_per_wavelength)) // ', min(a, b)/' // int_str(nint(2*min_elements_side)) &
         // '); Hertz radius ' // real_short(s%contact_radius*1.0e3_dp) // ' mm; impactor/plate mass ' &
         // real_short(s%mass_ratio)
   end function scene_settings_of

   !> The deck with dt and nx, ny chosen from the scene where it does not
   !> give them (deck%dt_chosen, deck%mesh_chosen then say what and why);
   !> a given value is kept. nx and ny are chosen together unless both are given.
   pure subroutine choose_settings(deck)
      type(deck_t), intent(inout) :: deck       !< the validated deck
      type(settings_t) :: s
      logical :: dt_given, mesh_given, nx_given, ny_given
      dt_given = is_given(deck, 'analysis', 'dt') .or. deck%analysis_kind == 'static' &
                 .or. deck%analysis_kind == 'modes'      ! (no time steps: dt stays not given)
      nx_given = is_given(deck, 'mesh', 'nx')
      ny_given = is_given(deck, 'mesh', 'ny')
      mesh_given = nx_given .and. ny_given
      if (dt_given .and. mesh_given) return
      s = scene_settings_of(deck)
      if (.not. dt_given) then
         deck%dt = s%dt
         deck%dt_chosen = s%dt_reason
      end if
      if (.not. mesh_given) then
         if (.not. nx_given) deck%nx = s%nx
         if (.not. ny_given) deck%ny = s%ny
         deck%mesh_chosen = s%mesh_reason
         if (nx_given .or. ny_given) deck%mesh_chosen = &
            'nx, ny = ' // int_str(deck%nx) // ' x ' // int_str(deck%ny) // ' (one given, the other chosen); ' &
            // s%mesh_reason(len('nx, ny chosen = ') + 1:)
      end if
   end subroutine choose_settings

   !> Lengths along x and y of the domain that &mesh nx, ny count (above scene_settings_of) (m).
   pure function domain_span(deck) result(span)
      type(deck_t), intent(in) :: deck          !< the deck
      real(dp) :: span(2)
      span = 0.5_dp*[deck%a, deck%b]
      select case (deck%domain)
      case ('full')
         span = [deck%a, deck%b]
      case ('half')
         if (deck%y0 == 0.0_dp) then     ! symmetric about y = 0: y >= 0, the whole length along x
            span(1) = deck%a
         else
            span(2) = deck%b
         end if
      end select
   end function domain_span

   !> x > 0 rounded down to two significant digits (2.006e-6 -> 2.0e-6).
   pure real(dp) function two_digits_down(x) result(y)
      real(dp), intent(in) :: x                 !< a positive number
      real(dp) :: scale
      scale = 10.0_dp**(floor(log10(x)) - 1)
      y = real(floor(x/scale*(1.0_dp + 1.0e-12_dp)), dp)*scale
   end function two_digits_down

end module scene_settings
