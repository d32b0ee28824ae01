!> Navier modal solution of the impact on a simply supported plate: the
!> validation reference for the dynamic point response of ./impact
!> (validation/navier_impact.f90 is the program; tests/test_navier_impact.pf
!> its tests). A validation oracle, not part of the library: it uses the
!> library's laminate, Navier modes, contact law and impactor update, so
!> that the only difference from the finite-element run is the spatial
!> discretisation.
!>
!> Plate. Simply supported a x b ("hard" support: w = 0 and the tangential
!> rotation 0 on the edges), linear Mindlin (FSDT) theory with rotary
!> inertia, laminate with B = 0, A16 = A26 = 0, Abar45 = 0 and D16 = D26 = 0
!> (the paper's averaged quarter model, section 3.1). With x, y from the
!> plate centre and the impact at the centre only odd m, n take part:
!>     w = sum_mn W_mn cos(alpha x) cos(beta y),  alpha = m pi/a, beta = n pi/b,
!> and each (m, n) is the 3 x 3 (W, psi_x, psi_y) system of
!> reference_solutions (navier_fsdt, module header item 1) with its three
!> modes k: S phi_k = omega_k^2 M phi_k, phi_k^T M phi_k = 1. Writing
!> u_j = phi_k(1) eta_k for the part of W_mn carried by mode j = (m, n, k),
!>     u_j'' + omega_j^2 u_j = c_j F(t) H_mn(t),    c_j = phi_k(1)^2 4/(a b),
!>     w(0, 0) = sum_j u_j,
!> where F is the contact force and H_mn the load's projection factor.
!> c_j and omega_j come from navier_fsdt with a unit central force, whose
!> terms are c = phi_k(1)^2 (4/(a b))/omega^2.
!>
!> Load. load_hertz: F spread over the contact disc with Hertz's pressure
!> p(r) = (3F/(2 pi a_c^2)) sqrt(1 - r^2/a_c^2), contact radius
!> a_c = sqrt(R alpha) (R the nose radius, alpha the current indentation,
!> a_c = 0 for alpha <= 0). The angular mean of cos(kx x) cos(ky y) on a
!> circle of radius r is J0(k r), k^2 = kx^2 + ky^2, and
!> int_0^a_c sqrt(1 - r^2/a_c^2) J0(k r) r dr = a_c^2 (sin s - s cos s)/s^3,
!> s = k a_c, so
!>     (4/(a b)) int p cos(alpha x) cos(beta y) dA = (4/(a b)) F H(k_mn a_c),
!>     H(s) = 3 (sin s - s cos s)/s^3 = (3/4) int_-1^1 (1 - u^2) cos(s u) du,
!> H(0) = 1, |H^(n)| <= 3/((n+1)(n+3)). The plate deflection in the contact
!> law (eq. 13) is the pressure-weighted mean
!>     w_plate = (1/F) int p w dA = sum_j H_mn(a_c) u_j.
!> load_point: the paper's point force, H = 1 (a_c -> 0); its Mindlin series
!> diverges like log(mmax) (the shear deflection under a point force is
!> infinite), which the program shows.
!>
!> Time integration. Newmark's constant average acceleration rule with the
!> deck's dt, mode by mode (it commutes with the modal decomposition, so the
!> solution converged in modes is the limit of the finite-element solution
!> with the same dt as the mesh is refined), a0 = 4/dt^2, a1 = 4/dt:
!>     b_j = a0 u_j + a1 u_j' + u_j'',   u_j(t+dt) = (b_j + c_j F H_mn)/(omega_j^2 + a0),
!> and the rigid impactor of eq. (21) (newmark, impactor_advance). For a
!> given a_c the step's modal displacements are linear in F, so
!>     w_plate(F, a_c) = P(a_c) + F Q(a_c),
!>     P(a_c) = sum_mn H_mn p_mn,  p_mn = sum_k b_j/(omega_j^2 + a0)      (per step)
!>     Q(a_c) = sum_mn H_mn^2 q_mn, q_mn = sum_k c_j/(omega_j^2 + a0)      (constant)
!> and the contact equation of the step is the scalar equation in alpha
!>     g(alpha) = alpha - w_r(F) + P(a_c) + F Q(a_c) = 0,
!>     F = F_law(alpha) (eq. 11-12, the committed history), a_c = sqrt(R alpha),
!>     w_r(F) = w_r + w_r' dt - (F_t + F) dt^2/(4 m)                      (eq. 21)
!> with a_c taken from the step's own alpha. g increases with alpha (F, F Q
!> and the impactor term all grow; the change of the weighting with a_c is
!> a few per cent of that), F = 0 for alpha <= alpha_0, so: if
!> g(alpha_0) >= 0 there is no contact in the step (F = 0, and the reported
!> alpha and w_plate are those weighted over the radius sqrt(R alpha_0) at
!> which contact would resume: the centre deflection before the first
!> contact); otherwise the root in (alpha_0, inf) is found by a safeguarded
!> Newton iteration that keeps a bracket [lo, hi] (bisection when Newton
!> leaves it), to rounding. The history is committed once per step
!> (contact_commit), as ./impact does.
!>
!> Cost. Each evaluation of g needs P and Q at a new a_c: a sum over the
!> (m, n) pairs of H(k a_c), whose sine and cosine would dominate the run.
!> H is entire and smooth, so it is tabulated once (hertz_table_t):
!> piecewise cubic Hermite on a uniform grid of step h_tab in s, from the
!> closed forms of H and H'; the interpolation error is at most
!> h^4/384 max|H''''| = h^4/384 * 3/35 (about 2e-16 for h = 1/1024), below
!> rounding. Pairs are sorted by k so that the table is read in order. The
!> Newton iteration starts from the indentation extrapolated from the last
!> three steps, so a step in contact costs 3 or 4 sums over the pairs (3.3
!> on average in the paper's scene) plus one pass that updates the modes and
!> forms the next step's p_mn. Steps without contact cost one sum (none
!> before the first contact) and the update. The paper's simply supported
!> scene with mmax = 1023 (786432 modes, 1200 steps) takes about 10 s.
!>
!> Summary figures are gathered as ./impact's run recorder gathers them, so that
!> peak force, contacts, first contact start and end and the largest centre
!> deflection mean what they mean in ./impact's summary.
!>
!> Units: SI throughout.
module navier_impact_solution
   use kinds, only: dp, pi, msg_len
   use materials, only: laminate_t, laminate_drop_bend_twist
   use deck_schema, only: deck_t
   use scene_model, only: scene_t, model_laminate, ncouplings, coupling_names, coupling_tol
   use contact_law, only: contact_law_t, contact_history_t, contact_force, contact_branch, law_tangent, &
      contact_commit, branch_none
   use newmark, only: impactor_advance
   use reference_solutions, only: navier_series_t, navier_fsdt, load_central_force, &
      hertz_impact_t, hertz_impact
   implicit none
   private
   public :: navier_problem_t, navier_result_t, hertz_table_t, &
             navier_problem_from_deck, navier_impact_run, navier_changes, &
             hertz_projection, hertz_projection_slope, hertz_table_build, hertz_table_lookup, &
             load_hertz, load_point, load_name, nchange, change_names

   !> Load models: Hertz pressure on the contact disc, or a point force.
   integer, parameter :: load_hertz = 1, load_point = 2
   !> Figures whose relative change between mode counts decides convergence
   !> (navier_changes): first-contact peak force, its time, the end of the
   !> first contact (times interpolated within the step), largest centre
   !> deflection (reported, not part of the criterion).
   integer, parameter :: nchange = 4
   character(len=*), parameter :: change_names(nchange) = [character(len=22) :: &
      'first_peak_force', 'first_peak_time', 'first_contact_end', 'max_deflection']

   !> Step of the table of H (in s = k a_c).
   real(dp), parameter :: h_tab = 1.0_dp/1024.0_dp
   !> Below this s, H and H' come from their Taylor series (the closed form cancels).
   real(dp), parameter :: s_series = 1.0_dp
   !> Terms of the Taylor series of H kept (s^(2k), k = 0..n_series-1; the
   !> first one left out is below 3e-21 for s <= 1).
   integer, parameter :: n_series = 10
   !> Most table intervals (about 130 MB of coefficients); beyond, the closed form.
   integer, parameter :: max_table = 4000000
   !> The table covers contact radii up to this multiple of the radius of a
   !> Hertz impact on a rigid target (the largest indentation the impactor's
   !> energy allows), beyond which H is computed in closed form.
   real(dp), parameter :: table_radius_margin = 1.5_dp
   !> Most evaluations of g in one time step.
   integer, parameter :: max_root_iter = 200
   !> Newton steps below this many units of rounding of alpha end the iteration.
   real(dp), parameter :: root_ulps = 16.0_dp

   !> The run's figures, as ./impact's summary names them (src/record/run_recorder.f90).
   type :: run_summary_t
      real(dp) :: peak_force = 0.0_dp          !< N
      real(dp) :: time_of_peak = 0.0_dp        !< s
      real(dp) :: first_contact_start = -1.0_dp, first_contact_end = -1.0_dp  !< s
      integer :: contacts = 0                  !< separate contact intervals
      logical :: in_contact = .false.
      real(dp) :: max_deflection = 0.0_dp      !< m
      real(dp) :: max_energy_error = 0.0_dp    !< J
      real(dp) :: permanent_indentation = 0.0_dp !< m
      real(dp) :: final_velocity = 0.0_dp      !< m/s
      real(dp) :: initial_energy = 0.0_dp      !< J
      integer :: steps = 0
      real(dp) :: cpu_s = 0.0_dp
   end type run_summary_t

   !> The impact problem: plate, laminate, impactor, law, time stepping.
   type :: navier_problem_t
      real(dp) :: a = 0.0_dp, b = 0.0_dp       !< plate size along x, y (m)
      type(laminate_t) :: lmt                  !< laminate (D16 = D26 = 0)
      real(dp) :: mass = 0.0_dp                !< impactor mass (kg)
      real(dp) :: velocity = 0.0_dp            !< impact velocity (m/s)
      real(dp) :: radius = 0.0_dp              !< nose radius R (m)
      type(contact_law_t) :: law               !< indentation law (eq. 11-12)
      real(dp) :: dt = 0.0_dp                  !< time step (s)
      real(dp) :: t_end = 0.0_dp               !< end time (s)
      integer :: load = load_hertz             !< load_hertz or load_point
   end type navier_problem_t

   !> Cubic Hermite table of H on [0, n h): interval j holds the
   !> coefficients of H(s) = c0 + c1 t + c2 t^2 + c3 t^3, s = (j + t) h.
   type :: hertz_table_t
      integer :: n = 0                         !< intervals
      real(dp) :: h = h_tab                    !< step in s (-)
      real(dp), allocatable :: c(:,:)          !< c(0:3, 0:n-1)
   end type hertz_table_t

   !> What a run gives: the figures of ./impact's summary and the history.
   type :: navier_result_t
      integer :: mmax = 0                      !< largest half-wave number (odd)
      integer :: pairs = 0                     !< (m, n) pairs
      integer :: modes = 0                     !< modes, 3 per pair
      integer :: load = load_hertz             !< load model
      type(run_summary_t) :: s                 !< ./impact's figures (peak, contacts, max deflection, ...)
      real(dp) :: first_peak_force = 0.0_dp    !< largest force of the first contact (N)
      real(dp) :: first_peak_time = 0.0_dp     !< its step time (s)
      real(dp) :: first_peak_time_interp = 0.0_dp !< the parabola's vertex through the 3 steps about it (s)
      real(dp) :: first_end_interp = -1.0_dp   !< end of the first contact, alpha = alpha_0 interpolated (s)
      real(dp) :: max_w_plate = 0.0_dp         !< largest weighted deflection w_plate (m)
      real(dp) :: max_contact_radius = 0.0_dp  !< largest contact radius (m)
      integer :: evaluations = 0               !< evaluations of g (sums over the pairs), all steps
      integer :: max_evaluations = 0           !< most in one step
      integer :: beyond_table = 0              !< evaluations that needed H beyond the table
      real(dp) :: table_radius = 0.0_dp        !< contact radius the table covers (m)
      real(dp) :: cpu_s = 0.0_dp               !< cpu time of the run (s)
      ! history, index 0 = t = 0, one entry per step
      integer :: nstep = 0                     !< steps
      real(dp), allocatable :: time(:)         !< s
      real(dp), allocatable :: force(:)        !< contact force F (N)
      real(dp), allocatable :: alpha(:)        !< indentation, eq. (13) (m)
      real(dp), allocatable :: w_plate(:)      !< pressure-weighted plate deflection (m)
      real(dp), allocatable :: w_centre(:)     !< centre deflection (m)
      real(dp), allocatable :: w_impactor(:)   !< impactor displacement since first touch (m)
      real(dp), allocatable :: v_impactor(:)   !< impactor velocity, + towards the plate (m/s)
      real(dp), allocatable :: contact_radius(:) !< a_c of the step, 0 without contact (m)
      real(dp), allocatable :: energy_error(:) !< E0 - (impactor + plate + int F d alpha) (J)
      integer, allocatable :: branch(:)        !< law branch (contact_law), 0 without contact
      integer, allocatable :: iterations(:)    !< evaluations of g in the step
   end type navier_result_t

   !> The modes and their state, pairs sorted by k (private to the run).
   type :: modal_state_t
      integer :: npair = 0
      real(dp), allocatable :: k(:)            ! sqrt(alpha^2 + beta^2) of each pair (1/m)
      real(dp), allocatable :: q(:)            ! q_mn = sum_k c_j/(omega_j^2 + a0) (m/N)
      real(dp), allocatable :: p(:)            ! p_mn of the step = sum_k b_j/(omega_j^2 + a0) (m)
      real(dp), allocatable :: hv(:)           ! H_mn at the last evaluated contact radius (-)
      real(dp), allocatable :: rinv(:,:)       ! 1/(omega_j^2 + a0) (s^2)
      real(dp), allocatable :: cr(:,:)         ! c_j/(omega_j^2 + a0) (m/N)
      real(dp), allocatable :: omega2(:,:)     ! omega_j^2 (1/s^2)
      real(dp), allocatable :: e_weight(:,:)   ! 1/(2 c_j): mode energy (u'^2 + omega^2 u^2)/(2 c_j) (N/m)
      real(dp), allocatable :: u(:,:), v(:,:), acc(:,:)   ! u_j (m), u_j' (m/s), u_j'' (m/s^2)
      real(dp) :: q_total = 0.0_dp             ! sum q_mn (point load) (m/N)
      real(dp) :: p_total = 0.0_dp             ! sum p_mn (point load) (m)
      real(dp) :: a0 = 0.0_dp, a1 = 0.0_dp     ! 4/dt^2, 4/dt
      integer :: beyond = 0                    ! evaluations beyond the table
   end type modal_state_t

   !> g and what comes with it at one trial indentation.
   type :: trial_t
      real(dp) :: alpha = 0.0_dp               ! trial indentation (m)
      real(dp) :: g = 0.0_dp                   ! residual of the contact equation (m)
      real(dp) :: dg = 1.0_dp                  ! d g / d alpha (-)
      real(dp) :: f = 0.0_dp                   ! law force (N)
      real(dp) :: radius = 0.0_dp              ! contact radius (m)
      real(dp) :: w_plate = 0.0_dp             ! weighted plate deflection (m)
      real(dp) :: g_noise = 0.0_dp             ! rounding level of g: 4 eps (sum of its terms' sizes) (m)
   end type trial_t


contains

   ! ============================================================ the load

   !> Name of a load model.
   pure function load_name(load) result(name)
      integer, intent(in) :: load              !< load_hertz or load_point
      character(len=:), allocatable :: name
      if (load == load_point) then
         name = 'point'
      else
         name = 'hertz'
      end if
   end function load_name

   !> H(s) = 3 (sin s - s cos s)/s^3: the projection of Hertz's pressure of
   !> total force 1 and radius a_c on cos(kx x) cos(ky y), s = k a_c.
   !> Taylor series below s_series, H = sum_k (-1)^k 3 s^(2k)/((2k)! (2k+1) (2k+3)).
   elemental function hertz_projection(s) result(h)
      real(dp), intent(in) :: s                !< k a_c (-)
      real(dp) :: h
      real(dp) :: x
      integer :: i
      if (abs(s) < s_series) then
         x = s*s
         h = series_coefficient(n_series - 1)
         do i = n_series - 2, 0, -1
            h = h*x + series_coefficient(i)
         end do
      else
         h = 3.0_dp*(sin(s) - s*cos(s))/s**3
      end if
   end function hertz_projection

   !> H'(s) = 3 sin(s)/s^2 - 3 H(s)/s (Taylor series below s_series).
   elemental function hertz_projection_slope(s) result(dh)
      real(dp), intent(in) :: s                !< k a_c (-)
      real(dp) :: dh
      real(dp) :: x
      integer :: i
      if (abs(s) < s_series) then
         x = s*s
         dh = 2.0_dp*real(n_series - 1, dp)*series_coefficient(n_series - 1)
         do i = n_series - 2, 1, -1
            dh = dh*x + 2.0_dp*real(i, dp)*series_coefficient(i)
         end do
         dh = dh*s
      else
         dh = 3.0_dp*(sin(s)/s - hertz_projection(s))/s
      end if
   end function hertz_projection_slope

   !> Coefficient of s^(2i) in the Taylor series of H.
   pure function series_coefficient(i) result(c)
      integer, intent(in) :: i                 !< power s^(2i)
      real(dp) :: c
      real(dp) :: fact
      integer :: j
      fact = 1.0_dp
      do j = 2, 2*i
         fact = fact*real(j, dp)
      end do
      c = 3.0_dp*real((-1)**i, dp)/(fact*real(2*i + 1, dp)*real(2*i + 3, dp))
   end function series_coefficient

   !> The table of H on [0, smax] (at least), step h_tab, at most max_table intervals.
   pure subroutine hertz_table_build(smax, table)
      real(dp), intent(in) :: smax             !< largest s to cover (-)
      type(hertz_table_t), intent(out) :: table   !< the table
      real(dp) :: h0, h1, d0, d1, s
      integer :: j
      table%h = h_tab
      table%n = max(1, min(max_table, ceiling(smax/h_tab) + 1))
      allocate (table%c(0:3, 0:table%n - 1))
      h1 = hertz_projection(0.0_dp)
      d1 = hertz_projection_slope(0.0_dp)*h_tab
      intervals: do j = 0, table%n - 1
         h0 = h1;  d0 = d1
         s = real(j + 1, dp)*h_tab
         h1 = hertz_projection(s)
         d1 = hertz_projection_slope(s)*h_tab
         table%c(0, j) = h0
         table%c(1, j) = d0
         table%c(2, j) = 3.0_dp*(h1 - h0) - 2.0_dp*d0 - d1
         table%c(3, j) = 2.0_dp*(h0 - h1) + d0 + d1
      end do intervals
   end subroutine hertz_table_build

   !> H(s) and H'(s) from the table, or in closed form beyond it (inside = .false.).
   pure subroutine hertz_table_lookup(table, s, h, dh, inside)
      type(hertz_table_t), intent(in) :: table !< the table
      real(dp), intent(in) :: s                !< k a_c >= 0 (-)
      real(dp), intent(out) :: h               !< H(s)
      real(dp), intent(out) :: dh              !< H'(s)
      logical, intent(out) :: inside           !< s was inside the table
      real(dp) :: x, t
      integer :: j
      x = s/table%h
      inside = x < real(table%n, dp)
      if (inside) then
         j = int(x)
         t = x - real(j, dp)
         h = table%c(0, j) + t*(table%c(1, j) + t*(table%c(2, j) + t*table%c(3, j)))
         dh = (table%c(1, j) + t*(2.0_dp*table%c(2, j) + 3.0_dp*t*table%c(3, j)))/table%h
      else
         h = hertz_projection(s)
         dh = hertz_projection_slope(s)
      end if
   end subroutine hertz_table_lookup

   ! ============================================================ the problem

   !> The problem of a deck: its plate, laminate (Whitney's k4, k5 when the
   !> deck gives none, as ./impact; then D16 = D26 = 0), impactor, law and
   !> time stepping. Refused (stat = 1, one line) unless the edges are
   !> simply supported, the impact is at the centre, and A16, A26, B, Abar45
   !> vanish (the Navier solution needs them to).
   subroutine navier_problem_from_deck(deck, load, problem, stat, errmsg)
      type(deck_t), intent(in) :: deck            !< the validated deck
      integer, intent(in) :: load                 !< load_hertz or load_point
      type(navier_problem_t), intent(out) :: problem   !< the problem
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      type(scene_t) :: scene
      type(laminate_t) :: lmt
      integer :: worst
      character(len=16) :: value

      stat = 0
      if (deck%edges /= 'simply_supported') then
         stat = 1
         errmsg = trim(deck%source)//": &boundary: edges = '"//trim(deck%edges)// &
            "': the Navier solution is for simply supported edges only"
         return
      end if
      if (deck%x0 /= 0.0_dp .or. deck%y0 /= 0.0_dp) then
         stat = 1
         errmsg = trim(deck%source)//': &impactor: x0, y0: the Navier solution is for an impact '// &
            'at the plate centre only (x0 = y0 = 0)'
         return
      end if
      call model_laminate(deck, lmt, scene)
      worst = 2 + maxloc(scene%couplings(3:), dim=1)
      if (scene%couplings(worst) > coupling_tol) then
         stat = 1
         write (value, '(es10.3)') scene%couplings(worst)
         errmsg = trim(deck%source)//': &laminate: '//trim(coupling_names(worst))//' = '// &
            trim(adjustl(value))//': the Navier solution needs A16 = A26 = B = Abar45 = 0'
         return
      end if
      problem%a = deck%a
      problem%b = deck%b
      problem%lmt = laminate_drop_bend_twist(lmt)
      problem%mass = deck%mass
      problem%velocity = deck%velocity
      problem%radius = 0.5_dp*deck%diameter
      problem%law = contact_law_t(k=deck%k, q=deck%q, alpha_p=deck%alpha_p, beta=deck%beta)
      problem%dt = deck%dt
      problem%t_end = deck%t_end
      problem%load = load
   end subroutine navier_problem_from_deck

   ! ============================================================ the run

   !> The impact with every odd m, n <= mmax (three modes each), from first
   !> touch to t_end (module header).
   subroutine navier_impact_run(problem, mmax, res, stat, errmsg)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      integer, intent(in) :: mmax                 !< largest half-wave number (odd; an even one means mmax - 1)
      type(navier_result_t), intent(out) :: res   !< figures and history
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      type(modal_state_t) :: st
      type(hertz_table_t) :: table
      type(contact_history_t) :: hist
      type(trial_t) :: tr
      real(dp) :: cpu0, cpu1, t, w_r, v_r, f_old, w_new, v_new, guess, w_centre, plate_energy, &
                  indentation_energy
      integer :: step, nstep, nev

      call cpu_time(cpu0)
      stat = 0
      if (mmax < 1) then
         stat = 1
         errmsg = 'navier_impact_run: mmax must be at least 1'
         return
      end if
      call modal_setup(problem, mmax, st, stat, errmsg)
      if (stat /= 0) return
      res%mmax = mmax - 1 + mod(mmax, 2)
      res%pairs = st%npair
      res%modes = 3*st%npair
      res%load = problem%load
      if (problem%load == load_hertz) then
         res%table_radius = table_radius(problem)
         call hertz_table_build(st%k(st%npair)*res%table_radius, table)
      end if

      nstep = nint(problem%t_end/problem%dt)
      res%nstep = nstep
      allocate (res%time(0:nstep), res%force(0:nstep), res%alpha(0:nstep), res%w_plate(0:nstep), &
                res%w_centre(0:nstep), res%w_impactor(0:nstep), res%v_impactor(0:nstep), &
                res%contact_radius(0:nstep), res%energy_error(0:nstep), res%branch(0:nstep), &
                res%iterations(0:nstep))
      res%time = 0.0_dp;  res%force = 0.0_dp;  res%alpha = 0.0_dp;  res%w_plate = 0.0_dp
      res%w_centre = 0.0_dp;  res%w_impactor = 0.0_dp;  res%contact_radius = 0.0_dp
      res%branch = branch_none;  res%iterations = 0;  res%energy_error = 0.0_dp
      indentation_energy = 0.0_dp
      res%v_impactor = problem%velocity
      res%s%initial_energy = 0.5_dp*problem%mass*problem%velocity**2

      ! the plate at rest, the impactor touching it at its impact velocity
      w_r = 0.0_dp;  v_r = problem%velocity;  f_old = 0.0_dp

      time_steps: do step = 1, nstep
         t = real(step, dp)*problem%dt
         ! -- the indentation the last three steps point to, when in contact
         guess = -1.0_dp
         if (step >= 3) then
            if (res%force(step - 1) > 0.0_dp) guess = 3.0_dp*(res%alpha(step - 1) - res%alpha(step - 2)) &
               + res%alpha(step - 3)
         end if
         call contact_step(problem, st, table, hist, w_r, v_r, f_old, guess, tr, nev, stat, errmsg)
         if (stat /= 0) then
            write (errmsg, '(a,i0,a,es11.4,a)') 'step ', step, ' (t = ', t, ' s): '//trim(errmsg)
            return
         end if
         ! -- accept the step: the modes, the impactor (eq. 21), the contact history
         call modal_update(problem, st, tr%f, w_centre, plate_energy)
         call impactor_advance(problem%mass, problem%dt, w_r, v_r, f_old, tr%f, w_new, v_new)
         call contact_commit(problem%law, hist, tr%alpha)
         ! -- energy: E0 = impactor + plate + int F d(alpha), as ./impact's balance
         indentation_energy = indentation_energy + 0.5_dp*(f_old + tr%f)*(tr%alpha - res%alpha(step - 1))
         res%energy_error(step) = res%s%initial_energy - (0.5_dp*problem%mass*v_new**2 + plate_energy &
            + indentation_energy)
         res%s%max_energy_error = max(res%s%max_energy_error, abs(res%energy_error(step)))
         w_r = w_new;  v_r = v_new;  f_old = tr%f

         res%time(step) = t
         res%force(step) = tr%f
         res%alpha(step) = tr%alpha
         res%w_plate(step) = tr%w_plate
         res%w_centre(step) = w_centre
         res%w_impactor(step) = w_r
         res%v_impactor(step) = v_r
         res%iterations(step) = nev
         if (tr%f > 0.0_dp) then
            res%contact_radius(step) = tr%radius
            res%branch(step) = contact_branch(hist, tr%alpha)
         end if
         res%evaluations = res%evaluations + nev
         res%max_evaluations = max(res%max_evaluations, nev)
         res%max_w_plate = max(res%max_w_plate, abs(tr%w_plate))
         res%max_contact_radius = max(res%max_contact_radius, res%contact_radius(step))
         call summary_record(res%s, t, tr%f, w_centre)
         res%s%steps = step
         if (res%s%contacts == 1 .and. res%s%in_contact .and. tr%f > res%first_peak_force) then
            res%first_peak_force = tr%f
            res%first_peak_time = t
         end if
         if (res%s%contacts == 1 .and. .not. res%s%in_contact .and. res%first_end_interp < 0.0_dp) then
            ! -- the first contact ended in this step: alpha fell to alpha_0
            !    within it, interpolated linearly (as rigid_target does)
            res%first_end_interp = t - problem%dt + problem%dt*(res%alpha(step - 1) - hist%alpha_0) &
               /(res%alpha(step - 1) - tr%alpha)
         end if
      end do time_steps

      res%s%permanent_indentation = hist%alpha_0
      res%s%final_velocity = v_r
      res%beyond_table = st%beyond
      call interpolate_first_peak(res)
      call cpu_time(cpu1)
      res%cpu_s = cpu1 - cpu0
      res%s%cpu_s = res%cpu_s
   end subroutine navier_impact_run

   !> Contact radius up to which H is tabulated: table_radius_margin times
   !> sqrt(R alpha_m) of the same impact on a rigid target.
   pure function table_radius(problem) result(r)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      real(dp) :: r
      type(hertz_impact_t) :: rigid
      rigid = hertz_impact(problem%mass, problem%velocity, problem%law%k, problem%law%q, &
                           problem%law%alpha_p, problem%law%beta)
      r = table_radius_margin*sqrt(problem%radius*rigid%alpha_m)
   end function table_radius

   !> The modes of every odd m, n <= mmax, sorted by k, at rest.
   subroutine modal_setup(problem, mmax, st, stat, errmsg)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      integer, intent(in) :: mmax                 !< largest half-wave number
      type(modal_state_t), intent(out) :: st      !< modes at rest
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      type(navier_series_t) :: series
      real(dp), allocatable :: kk(:), c(:,:), omega2(:,:)
      integer, allocatable :: order(:)
      integer :: i, j, t

      ! unit central force: terms c = phi(1)^2 (4/(a b))/omega^2, m outer, n inner
      call navier_fsdt(problem%lmt, problem%a, problem%b, load_central_force, 1.0_dp, mmax, &
                       series, stat, errmsg)
      if (stat /= 0) return
      st%npair = series%nterm/3
      allocate (kk(st%npair), c(3, st%npair), omega2(3, st%npair))
      pairs: do i = 1, st%npair
         t = 3*(i - 1)
         kk(i) = sqrt((series%m(t + 1)*pi/problem%a)**2 + (series%n(t + 1)*pi/problem%b)**2)
         omega2(:, i) = series%omega(t + 1:t + 3)**2
         c(:, i) = series%c(t + 1:t + 3)*omega2(:, i)
      end do pairs
      call sort_index(kk, order)

      st%a0 = 4.0_dp/problem%dt**2
      st%a1 = 4.0_dp/problem%dt
      allocate (st%k(st%npair), st%q(st%npair), st%p(st%npair), st%hv(st%npair), &
                st%rinv(3, st%npair), st%cr(3, st%npair), st%omega2(3, st%npair), st%e_weight(3, st%npair), &
                st%u(3, st%npair), st%v(3, st%npair), st%acc(3, st%npair))
      sorted: do i = 1, st%npair
         j = order(i)
         st%k(i) = kk(j)
         st%rinv(:, i) = 1.0_dp/(omega2(:, j) + st%a0)
         st%cr(:, i) = c(:, j)*st%rinv(:, i)
         st%omega2(:, i) = omega2(:, j)
         where (c(:, j) > 0.0_dp)
            st%e_weight(:, i) = 0.5_dp/c(:, j)
         elsewhere   ! a mode the load does not reach stays at rest
            st%e_weight(:, i) = 0.0_dp
         end where
         st%q(i) = sum(st%cr(:, i))
      end do sorted
      st%q_total = sum(st%q)
      st%p = 0.0_dp;  st%p_total = 0.0_dp
      st%hv = 1.0_dp
      st%u = 0.0_dp;  st%v = 0.0_dp;  st%acc = 0.0_dp
   end subroutine modal_setup

   !> The contact equation of one step (module header): F, alpha, a_c and
   !> w_plate of the step in tr; st%hv holds H at tr%radius. nev counts the
   !> evaluations of g.
   !>
   !> Safeguarded Newton in alpha with a bracket lo < root < hi (bisection
   !> when Newton leaves it). lo starts at alpha_0, where F = 0; whether
   !> g(alpha_0) < 0 (contact) is tested first when there is no guess, else
   !> only when needed: a trial with g < 0 proves contact (g increases), and
   !> the test is made when Newton heads below alpha_0. Converged when |g| is
   !> at the rounding level of its terms, or Newton's step is a few units of
   !> rounding of alpha, or the bracket is.
   subroutine contact_step(problem, st, table, hist, w_r, v_r, f_old, guess, tr, nev, stat, errmsg)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      type(modal_state_t), intent(inout) :: st    !< modes (p of the step in; hv out)
      type(hertz_table_t), intent(in) :: table    !< table of H
      type(contact_history_t), intent(in) :: hist !< committed contact history
      real(dp), intent(in) :: w_r, v_r            !< impactor position (m), velocity (m/s) at t
      real(dp), intent(in) :: f_old               !< contact force at t (N)
      real(dp), intent(in) :: guess               !< indentation expected (m); <= alpha_0: none
      type(trial_t), intent(out) :: tr            !< the step's solution
      integer, intent(out) :: nev                 !< evaluations of g
      integer, intent(out) :: stat                !< 0 on success
      character(len=*), intent(inout) :: errmsg   !< reason on failure
      real(dp) :: lo, hi, x, xn
      logical :: have_hi, contact_proved

      stat = 0
      nev = 0
      lo = hist%alpha_0
      have_hi = .false.
      hi = huge(1.0_dp)
      contact_proved = .false.
      if (guess > lo) then
         x = guess
      else
         call contact_test(contact_proved)
         if (.not. contact_proved) return
         x = newton_from(tr, lo, hi, have_hi)
      end if

      newton: do
         call residual(problem, st, table, hist, w_r, v_r, f_old, x, tr)
         nev = nev + 1
         if (abs(tr%g) <= tr%g_noise .and. (contact_proved .or. tr%g <= 0.0_dp .or. tr%f > 0.0_dp)) exit newton
         if (tr%g < 0.0_dp) then
            lo = x
            contact_proved = .true.
         else
            hi = x;  have_hi = .true.
         end if
         if (have_hi .and. contact_proved .and. hi - lo <= 4.0_dp*spacing(hi)) exit newton
         if (tr%dg > 0.0_dp .and. contact_proved) then
            if (abs(tr%g/tr%dg) <= root_ulps*spacing(x)) exit newton
         end if
         xn = newton_from(tr, lo, hi, have_hi)
         if (.not. contact_proved .and. (xn <= lo .or. tr%alpha - tr%g/tr%dg <= lo)) then
            ! -- Newton heads below alpha_0: is there contact at all?
            call contact_test(contact_proved)
            if (.not. contact_proved) return
            xn = 0.5_dp*(lo + hi)
         end if
         if (nev >= max_root_iter) then
            stat = 1
            write (errmsg, '(a,i0,a,es12.5,a,es12.5,a,es12.5,a)') 'the contact equation did not converge in ', &
               nev, ' evaluations: alpha in [', lo, ', ', hi, '] m, g = ', tr%g, ' m'
            return
         end if
         x = xn
      end do newton

   contains

      !> g(alpha_0), F = 0 there: contact when < 0; else the step's
      !> no-contact solution, alpha = w_r(0) - P(a_c(alpha_0)), in tr.
      subroutine contact_test(contact)
         logical, intent(out) :: contact           !< g(alpha_0) < 0
         call residual(problem, st, table, hist, w_r, v_r, f_old, hist%alpha_0, tr)
         nev = nev + 1
         contact = tr%g < 0.0_dp
         if (.not. contact) then
            tr%alpha = hist%alpha_0 - tr%g
            tr%f = 0.0_dp
         end if
      end subroutine contact_test
   end subroutine contact_step

   !> Next trial point: Newton's from tr, kept inside (lo, hi) (bisection
   !> when it leaves); without an upper end yet, at least doubling the
   !> distance from lo when Newton does not move to the right.
   pure function newton_from(tr, lo, hi, have_hi) result(xn)
      type(trial_t), intent(in) :: tr             !< the last trial
      real(dp), intent(in) :: lo, hi              !< bracket (g(lo) < 0 <= g(hi))
      logical, intent(in) :: have_hi              !< hi is known
      real(dp) :: xn
      if (tr%dg > 0.0_dp) then
         xn = tr%alpha - tr%g/tr%dg
      else
         xn = -huge(1.0_dp)
      end if
      if (have_hi) then
         if (.not. (xn > lo .and. xn < hi)) xn = 0.5_dp*(lo + hi)
      else if (.not. (xn > lo)) then
         xn = lo + max(2.0_dp*abs(tr%alpha - lo), abs(tr%g), spacing(lo))
      end if
   end function newton_from

   !> g(alpha) of the contact equation and its slope (module header).
   subroutine residual(problem, st, table, hist, w_r, v_r, f_old, alpha, tr)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      type(modal_state_t), intent(inout) :: st    !< modes (hv set here)
      type(hertz_table_t), intent(in) :: table    !< table of H
      type(contact_history_t), intent(in) :: hist !< committed contact history
      real(dp), intent(in) :: w_r, v_r            !< impactor position, velocity at t
      real(dp), intent(in) :: f_old               !< contact force at t (N)
      real(dp), intent(in) :: alpha               !< trial indentation (m)
      type(trial_t), intent(out) :: tr            !< g, its slope, F, a_c, w_plate
      real(dp) :: psum, qsum, dpsum, dqsum, w_new, v_new, df, dradius

      tr%alpha = alpha
      tr%f = contact_force(problem%law, hist, alpha)
      df = law_tangent(problem%law, hist, alpha)
      tr%radius = 0.0_dp
      if (problem%load == load_hertz) tr%radius = sqrt(problem%radius*max(alpha, 0.0_dp))
      if (tr%radius > 0.0_dp) then
         call load_sums(st, table, tr%radius, psum, qsum, dpsum, dqsum)
         dradius = 0.0_dp
         if (tr%radius > 0.0_dp) dradius = 0.5_dp*problem%radius/tr%radius
      else
         ! a point force (st%hv = 1 throughout), or no contact radius yet
         ! (then F = 0 and H does not enter the update): H = 1
         psum = st%p_total;  qsum = st%q_total
         dpsum = 0.0_dp;  dqsum = 0.0_dp;  dradius = 0.0_dp
      end if
      tr%w_plate = psum + tr%f*qsum
      call impactor_advance(problem%mass, problem%dt, w_r, v_r, f_old, tr%f, w_new, v_new)
      tr%g = alpha - w_new + tr%w_plate
      tr%g_noise = 4.0_dp*epsilon(1.0_dp)*(abs(alpha) + abs(w_new) + abs(psum) + abs(tr%f*qsum))
      tr%dg = 1.0_dp + df*(0.25_dp*problem%dt**2/problem%mass + qsum) + (dpsum + tr%f*dqsum)*dradius
   end subroutine residual

   !> P, Q and their derivatives in a_c: sums over the pairs of H_mn p_mn and
   !> H_mn^2 q_mn; H_mn left in st%hv. The table lookup of hertz_table_lookup,
   !> written out in the loop (the loop is most of the run's time); the
   !> pairs are sorted by k, so those beyond the table are the last ones.
   subroutine load_sums(st, table, radius, psum, qsum, dpsum, dqsum)
      type(modal_state_t), intent(inout) :: st    !< modes (hv set here)
      type(hertz_table_t), intent(in) :: table    !< table of H
      real(dp), intent(in) :: radius              !< contact radius a_c (m)
      real(dp), intent(out) :: psum, qsum         !< P (m), Q (m/N)
      real(dp), intent(out) :: dpsum, dqsum       !< dP/da_c (-), dQ/da_c (1/N)
      real(dp) :: h, dh, x, t, scale, x_end
      integer :: i, j, last
      psum = 0.0_dp;  qsum = 0.0_dp;  dpsum = 0.0_dp;  dqsum = 0.0_dp
      scale = radius/table%h
      x_end = real(table%n, dp)
      ! -- the pairs inside the table: k a_c/h < n
      last = st%npair
      do while (last > 0)
         if (st%k(last)*scale < x_end) exit
         last = last - 1
      end do
      inside: do i = 1, last
         x = st%k(i)*scale
         j = int(x)
         t = x - real(j, dp)
         h = table%c(0, j) + t*(table%c(1, j) + t*(table%c(2, j) + t*table%c(3, j)))
         dh = (table%c(1, j) + t*(2.0_dp*table%c(2, j) + 3.0_dp*t*table%c(3, j)))*(st%k(i)/table%h)
         st%hv(i) = h
         psum = psum + st%p(i)*h
         qsum = qsum + st%q(i)*h*h
         dpsum = dpsum + st%p(i)*dh
         dqsum = dqsum + st%q(i)*h*dh
      end do inside
      ! -- beyond it: the closed form
      beyond: do i = last + 1, st%npair
         h = hertz_projection(st%k(i)*radius)
         dh = hertz_projection_slope(st%k(i)*radius)*st%k(i)
         st%hv(i) = h
         psum = psum + st%p(i)*h
         qsum = qsum + st%q(i)*h*h
         dpsum = dpsum + st%p(i)*dh
         dqsum = dqsum + st%q(i)*h*dh
      end do beyond
      dqsum = 2.0_dp*dqsum
      if (last < st%npair) st%beyond = st%beyond + 1
   end subroutine load_sums

   !> Newmark update of every mode under the step's force F (and st%hv),
   !> the centre deflection, and the next step's p_mn.
   pure subroutine modal_update(problem, st, f, w_centre, energy)
      type(navier_problem_t), intent(in) :: problem   !< the problem
      type(modal_state_t), intent(inout) :: st    !< modes, t -> t+dt
      real(dp), intent(in) :: f                   !< contact force at t+dt (N)
      real(dp), intent(out) :: w_centre           !< centre deflection at t+dt (m)
      real(dp), intent(out) :: energy             !< plate energy, kinetic + strain, at t+dt (J)
      real(dp) :: fh, b, u_new, acc_new, half_dt
      integer :: i, j
      half_dt = 0.5_dp*problem%dt
      w_centre = 0.0_dp
      energy = 0.0_dp
      st%p_total = 0.0_dp
      pairs: do i = 1, st%npair
         fh = f*st%hv(i)
         st%p(i) = 0.0_dp
         modes: do j = 1, 3
            b = st%a0*st%u(j, i) + st%a1*st%v(j, i) + st%acc(j, i)
            u_new = b*st%rinv(j, i) + fh*st%cr(j, i)
            acc_new = st%a0*(u_new - st%u(j, i)) - st%a1*st%v(j, i) - st%acc(j, i)
            st%v(j, i) = st%v(j, i) + half_dt*(st%acc(j, i) + acc_new)
            st%acc(j, i) = acc_new
            st%u(j, i) = u_new
            w_centre = w_centre + u_new
            energy = energy + st%e_weight(j, i)*(st%v(j, i)**2 + st%omega2(j, i)*u_new**2)
            ! the next step's predictor, b/(omega^2 + a0)
            st%p(i) = st%p(i) + (st%a0*u_new + st%a1*st%v(j, i) + acc_new)*st%rinv(j, i)
         end do modes
         st%p_total = st%p_total + st%p(i)
      end do pairs
   end subroutine modal_update

   !> The first contact's peak time: the vertex of the parabola through the
   !> peak step and its neighbours.
   pure subroutine interpolate_first_peak(res)
      type(navier_result_t), intent(inout) :: res   !< history in, first_peak_time_interp out
      real(dp) :: fm, f0, fp, den
      integer :: n
      res%first_peak_time_interp = res%first_peak_time
      if (res%first_peak_force <= 0.0_dp) return
      n = nint(res%first_peak_time/(res%time(1) - res%time(0)))
      if (n < 1 .or. n >= res%nstep) return
      fm = res%force(n - 1);  f0 = res%force(n);  fp = res%force(n + 1)
      den = fm - 2.0_dp*f0 + fp
      if (den < 0.0_dp) res%first_peak_time_interp = res%time(n) + &
         0.5_dp*(res%time(n) - res%time(n - 1))*(fm - fp)/den
   end subroutine interpolate_first_peak

   ! ============================================================ convergence

   !> Relative changes of the convergence figures (change_names) from run
   !> coarse to run fine; the end of a first contact that has not ended is
   !> taken as the end time of the run.
   pure function navier_changes(coarse, fine) result(change)
      type(navier_result_t), intent(in) :: coarse, fine   !< two runs of the same problem
      real(dp) :: change(nchange)
      change(1) = rel(coarse%first_peak_force, fine%first_peak_force)
      change(2) = rel(coarse%first_peak_time_interp, fine%first_peak_time_interp)
      change(3) = rel(contact_end(coarse), contact_end(fine))
      change(4) = rel(coarse%s%max_deflection, fine%s%max_deflection)
   contains
      pure function rel(x0, x1) result(r)
         real(dp), intent(in) :: x0, x1
         real(dp) :: r
         if (x1 /= 0.0_dp) then
            r = abs(x1 - x0)/abs(x1)
         else
            r = abs(x1 - x0)
         end if
      end function rel
      pure function contact_end(r) result(te)
         type(navier_result_t), intent(in) :: r
         real(dp) :: te
         te = r%first_end_interp
         if (te < 0.0_dp) te = r%time(r%nstep)
      end function contact_end
   end function navier_changes

   ! ============================================================ helpers

   !> Indices that sort x ascending (heap sort).
   pure subroutine sort_index(x, order)
      real(dp), intent(in) :: x(:)                 !< keys
      integer, allocatable, intent(out) :: order(:)  !< x(order) ascending
      integer :: n, i, tmp, last
      n = size(x)
      allocate (order(n))
      order = [(i, i = 1, n)]
      heapify: do i = n/2, 1, -1
         call sift_down(x, order, i, n)
      end do heapify
      extract: do last = n, 2, -1
         tmp = order(1);  order(1) = order(last);  order(last) = tmp
         call sift_down(x, order, 1, last - 1)
      end do extract
   end subroutine sort_index

   !> Restores the max-heap of x(order(start:finish)) below start.
   pure subroutine sift_down(x, order, start, finish)
      real(dp), intent(in) :: x(:)                 !< keys
      integer, intent(inout) :: order(:)           !< heap of indices into x
      integer, intent(in) :: start, finish         !< root and last entry of the heap
      integer :: root, child, t
      root = start
      do while (2*root <= finish)
         child = 2*root
         if (child < finish) then
            if (x(order(child + 1)) > x(order(child))) child = child + 1
         end if
         if (x(order(root)) >= x(order(child))) return
         t = order(root);  order(root) = order(child);  order(child) = t
         root = child
      end do
   end subroutine sift_down

   !> The summary's figures after a step, by the rules of ./impact's
   !> recorder: the peak force and its time, the contacts (intervals of
   !> F > 0) and the first one's start and end, the largest deflection.
   pure subroutine summary_record(s, time, force, w_plate)
      type(run_summary_t), intent(inout) :: s   !< summary
      real(dp), intent(in) :: time              !< s
      real(dp), intent(in) :: force             !< N
      real(dp), intent(in) :: w_plate           !< m
      if (force > s%peak_force) then
         s%peak_force = force
         s%time_of_peak = time
      end if
      if (force > 0.0_dp .and. .not. s%in_contact) then
         s%in_contact = .true.
         s%contacts = s%contacts + 1
         if (s%contacts == 1) s%first_contact_start = time
      else if (force <= 0.0_dp .and. s%in_contact) then
         s%in_contact = .false.
         if (s%contacts == 1) s%first_contact_end = time
      end if
      s%max_deflection = max(s%max_deflection, abs(w_plate))
   end subroutine summary_record

end module navier_impact_solution
