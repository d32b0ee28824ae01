!> The deck's variables, declared once: one entry of `deck_vars` per variable
!> (group, name, kind, unit, default, range, meaning), from which the reader,
!> the checks, the echo, /deck of <prefix>.h5, `impact --schema` and the
!> table of docs/DECK.md derive. The values live in `deck_t`, connected by
!> `deck_bind`. Adding a variable: its entry, its component, its line in
!> deck_bind, any check across variables in validate_deck (input_deck.f90).
!> A default '' makes it optional: "not given" is a value no reader produces
!> (NaN, not_given_integer); ask is_given, never compare with the sentinel.
!> Not from the paper. More: docs/DECK.md.
module deck_schema
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
   use kinds, only: dp
   implicit none
   private
   public :: deck_var_t, deck_t, value_t, deck_vars, deck_groups, deck_bind, find_var, var_key, strength_given
   public :: toughness_given, strength_names, toughness_names
   public :: is_given, not_given_real, not_given_integer, accuracy_wanted
   public :: kind_real, kind_integer, kind_logical, kind_word, kind_path, kind_reals, kind_names
   public :: max_word_len, max_path_len, max_list_len, words_of, words_quoted

   !> Kinds of variable.
   integer, parameter :: kind_real = 1, kind_integer = 2, kind_logical = 3, kind_word = 4, &
                         kind_path = 5, kind_reals = 6
   character(len=8), parameter :: kind_names(6) = [character(len=8) :: 'real', 'integer', 'logical', &
      'word', 'text', 'reals']
   !> Longest word (a keyword), longest text (a path), longest list (plies).
   integer, parameter :: max_word_len = 32, max_path_len = 4096, max_list_len = 1000
   !> The ply strengths of &strength, and its fracture toughnesses.
   character(len=3), parameter :: strength_names(6) = [character(len=3) :: 'xt', 'xc', 'yt', 'yc', 's12', 's23']
   character(len=3), parameter :: toughness_names(6) = [character(len=3) :: 'g1c', 'g2c', 'gft', 'gfc', 'gmt', 'gmc']
   !> "Not given" of an optional integer: a value no reader produces (module header).
   integer, parameter :: not_given_integer = -huge(0) - 1

   !> One variable of the deck.
   type :: deck_var_t
      character(len=8) :: group        !< namelist group, without '&'
      character(len=18) :: name        !< variable
      integer :: kind                  !< kind_real, ...
      character(len=10) :: unit        !< SI unit, '-' for none
      character(len=72) :: default     !< as written in a deck; '' = not given (optional)
      character(len=56) :: range       !< admissible values (module header)
      character(len=240) :: meaning    !< what it is, one sentence
   end type deck_var_t

   !> The namelist groups, in the order of the echo and the table of docs/DECK.md.
   character(len=8), parameter :: deck_groups(14) = [character(len=8) :: 'plate', 'lamina', 'laminate', &
      'strength', 'damage', 'impactor', 'contact', 'mesh', 'boundary', 'analysis', 'load', 'modes', 'output', 'accuracy']

   !> THE LIST. The paper's values as defaults (section 2.4, Tables 1-3).
   type(deck_var_t), parameter :: deck_vars(*) = [ &
      deck_var_t('plate', 'a', kind_real, 'm', '0.15', '[1e-3, 100]', 'plate length along x'), &
      deck_var_t('plate', 'b', kind_real, 'm', '0.10', '[1e-3, 100]', 'plate width along y'), &
      deck_var_t('plate', 'h', kind_real, 'm', '0.0027', '[1e-6, 1]', 'plate thickness'), &
      deck_var_t('lamina', 'e1', kind_real, 'Pa', '120e9', '[1e5, 1e18]', &
         'Young''s modulus along the fibres (Table 3)'), &
      deck_var_t('lamina', 'e2', kind_real, 'Pa', '7.9e9', '[1e5, 1e18]', 'Young''s modulus across the fibres'), &
      deck_var_t('lamina', 'g12', kind_real, 'Pa', '5.5e9', '[1e5, 1e18]', 'in-plane shear modulus'), &
      deck_var_t('lamina', 'g13', kind_real, 'Pa', '5.5e9', '[1e5, 1e18]', 'transverse shear modulus, 1-3 plane'), &
      deck_var_t('lamina', 'g23', kind_real, 'Pa', '2.63e9', '[1e5, 1e18]', 'transverse shear modulus, 2-3 plane'), &
      deck_var_t('lamina', 'nu12', kind_real, '-', '0.30', '(0, 10]', 'major Poisson ratio'), &
      deck_var_t('lamina', 'rho', kind_real, 'kg/m^3', '1580', '[1, 1e5]', 'density'), &
      deck_var_t('laminate', 'angles', kind_reals, 'deg', &
         '0, 45, 0, -45, 0, 0, 45, 0, -45, 0, 0, -45, 0, 45, 0, 0, -45, 0, 45, 0', '[-360, 360]', &
         'ply angles from x, listed from z = -h/2 (the impacted face) to +h/2, all plies h/n thick ' &
         // '(the default: the paper''s [0/45/0/-45/0]2s); each in [-360, 360]'), &
      deck_var_t('laminate', 'k4', kind_real, '-', '', '(0, 1.2]', 'shear correction factor of Abar44 = k4^2 ' &
         // 'int Qbar44 dz (eq. 6, Table 1); not given: Whitney''s method from the layup'), &
      deck_var_t('laminate', 'k5', kind_real, '-', '', '(0, 1.2]', 'shear correction factor of Abar55 = k5^2 ' &
         // 'int Qbar55 dz; not given: Whitney''s method'), &
      deck_var_t('laminate', 'bend_twist', kind_word, '-', 'auto', 'auto | drop | keep', 'D16, D26: ''auto'' ' &
         // '(dropped on a quarter, half or strip, section 3.1), ''drop'' (everywhere), ''keep'' (full plate only)'), &
      deck_var_t('strength', 'xt', kind_real, 'Pa', '', '[1e3, 1e11]', 'ply tensile strength along the fibres; ' &
         // 'the paper gives no strengths: with all six given, ply stresses and failure indices are computed'), &
      deck_var_t('strength', 'xc', kind_real, 'Pa', '', '[1e3, 1e11]', &
         'ply compressive strength along the fibres (a magnitude)'), &
      deck_var_t('strength', 'yt', kind_real, 'Pa', '', '[1e3, 1e11]', 'ply tensile strength across the fibres'), &
      deck_var_t('strength', 'yc', kind_real, 'Pa', '', '[1e3, 1e11]', &
         'ply compressive strength across the fibres (a magnitude)'), &
      deck_var_t('strength', 's12', kind_real, 'Pa', '', '[1e3, 1e11]', &
         'ply in-plane shear strength (also of tau_13)'), &
      deck_var_t('strength', 's23', kind_real, 'Pa', '', '[1e3, 1e11]', 'ply transverse shear strength'), &
      deck_var_t('strength', 'criterion', kind_word, '-', 'hashin', 'hashin | max_stress | tsai_wu', &
         'failure criterion of the plies: ''hashin'' (Hashin 1980), ''max_stress'' or ''tsai_wu'' ' &
         // '(Tsai & Wu 1971)'), &
      deck_var_t('strength', 'g1c', kind_real, 'J/m^2', '', '[1, 1e6]', 'mode I interlaminar fracture ' &
         // 'toughness (DCB test, ASTM D5528); read and checked, not used yet'), &
      deck_var_t('strength', 'g2c', kind_real, 'J/m^2', '', '[1, 1e6]', 'mode II interlaminar fracture ' &
         // 'toughness (ENF test, ASTM D7905); gives the delamination threshold load (Davies & Zhang 1995); ' &
         // 'not given: not computed'), &
      deck_var_t('strength', 'gft', kind_real, 'J/m^2', '', '[1, 1e6]', 'ply fracture energy, fibre tension ' &
         // '(compact tension); needs the six strengths; used by &damage'), &
      deck_var_t('strength', 'gfc', kind_real, 'J/m^2', '', '[1, 1e6]', 'ply fracture energy, fibre ' &
         // 'compression (compact compression); needs the six strengths; used by &damage'), &
      deck_var_t('strength', 'gmt', kind_real, 'J/m^2', '', '[1, 1e6]', 'ply fracture energy, matrix tension ' &
         // '(about G_Ic); needs the six strengths; used by &damage'), &
      deck_var_t('strength', 'gmc', kind_real, 'J/m^2', '', '[1, 1e6]', 'ply fracture energy, matrix ' &
         // 'compression (about G_IIc); needs the six strengths; used by &damage'), &
      deck_var_t('damage', 'model', kind_word, '-', 'auto', 'auto | hashin | none', 'progressive ply damage: ' &
         // '''hashin'' (Hashin onset, crack-band softening), ''none'', or ''auto'' (hashin when &strength gives ' &
         // 'the six strengths and gft, gfc, gmt, gmc)'), &
      deck_var_t('damage', 'viscosity', kind_real, 's', '0', '[0, 1]', 'viscous regularisation of the damage ' &
         // '(Lapczyk & Hurtado 2007); 0: none'), &
      deck_var_t('impactor', 'mass', kind_real, 'kg', '0.243', '[1e-6, 1e4]', 'impactor mass'), &
      deck_var_t('impactor', 'velocity', kind_real, 'm/s', '3.0', '(0, 1e3]', 'impact velocity, towards the plate'), &
      deck_var_t('impactor', 'diameter', kind_real, 'm', '0.0127', '[1e-5, 10]', &
         'diameter of the hemispherical nose (the law''s k belongs to it)'), &
      deck_var_t('impactor', 'x0', kind_real, 'm', '0', '(-inf, inf)', 'impact point along x, from the plate centre'), &
      deck_var_t('impactor', 'y0', kind_real, 'm', '0', '(-inf, inf)', 'impact point along y, from the plate centre'), &
      deck_var_t('contact', 'k', kind_real, 'N/m^1.5', '1.413e9', '[1e3, 1e15]', &
         'contact stiffness, F = k alpha^1.5 (eq. 11, Table 2)'), &
      deck_var_t('contact', 'q', kind_real, '-', '2.5', '(0, 10]', 'unloading exponent'), &
      deck_var_t('contact', 'alpha_p', kind_real, 'm', '1.667e-5', '[0, 1e-2]', &
         'critical indentation, beyond which it is permanent'), &
      deck_var_t('contact', 'beta', kind_real, '-', '0.094', '[0, 1)', &
         'permanent indentation alpha0 = beta (alpha_m - alpha_p) (eq. 12)'), &
      deck_var_t('contact', 'load', kind_word, '-', 'hertz', 'hertz | point', 'how the force enters the plate: ' &
         // '''hertz'' (Hertz''s pressure over the contact disc a = sqrt(R alpha)) or ''point'' (eq. 10)'), &
      deck_var_t('mesh', 'nx', kind_integer, '-', '', '[1, 10000]', 'elements along x of the domain (with domain ' &
         // '''auto'': of the quarter, doubled across each centre line the domain spans); not given: chosen ' &
         // 'from the scene (src/model/scene_settings.f90)'), &
      deck_var_t('mesh', 'ny', kind_integer, '-', '', '[1, 10000]', 'elements along y, likewise'), &
      deck_var_t('mesh', 'domain', kind_word, '-', 'auto', 'auto | quarter | half | full | strip', &
         '''auto'' (the smallest domain the scene allows), ''quarter'', ''half'', ''full'' or ''strip'''), &
      deck_var_t('mesh', 'average_bend_twist', kind_logical, '-', '.false.', '', &
         '.true.: the paper''s averaging (section 3.1) is accepted, D16 = D26 = 0 on a quarter or half'), &
      deck_var_t('mesh', 'grading', kind_real, '-', '1', '[1, 3]', &
         'ratio of successive element sizes away from the impact point (1: uniform)'), &
      deck_var_t('mesh', 'shear_rule', kind_word, '-', 'auto', 'auto | mitc9 | selective | stabilized | full', &
         'transverse shear of the element: ''mitc9'', ''selective'' (the paper''s 2x2 rule), ''stabilized'', ' &
         // '''full'' (3x3) or ''auto'' (mitc9)'), &
      deck_var_t('mesh', 'stabilization', kind_real, '-', '0.01', '(0, 1]', &
         'fraction of 3x3 shear in ''stabilized'''), &
      deck_var_t('boundary', 'edges', kind_word, '-', 'clamped', 'free | simply_supported | clamped', &
         'edge condition of all four edges'), &
      deck_var_t('boundary', 'inplane', kind_word, '-', 'immovable', 'immovable | movable', &
         'in-plane condition of simply supported edges'), &
      deck_var_t('analysis', 'kind', kind_word, '-', 'impact', 'impact | static | modes | pressure', &
         'the analysis: ''impact'' (the paper''s), ''static'', ''modes'' or ''pressure'' (&load held from t = 0)'), &
      deck_var_t('analysis', 'theory', kind_word, '-', 'nonlinear', 'linear | nonlinear | auto', &
         '''linear'', ''nonlinear'' (von Karman) or ''auto'' (from the scene''s deflection estimate)'), &
      deck_var_t('analysis', 'dt', kind_real, 's', '', '[1e-10, 1e-2]', 'time step; not given: chosen from ' &
         // 'the scene, the Hertz contact time or the plate''s period / 160 (src/model/scene_settings.f90)'), &
      deck_var_t('analysis', 't_end', kind_real, 's', '3.0e-3', '(0, 10]', 'end time'), &
      deck_var_t('analysis', 'cr1', kind_real, '-', '2.0e-3', '(0, 1)', &
         'contact-force tolerance C_r1, eq. (17)'), &
      deck_var_t('analysis', 'cr2', kind_real, '-', '1.0e-7', '(0, 1)', &
         'nonlinear-iteration tolerance C_r2, eq. (18)'), &
      deck_var_t('analysis', 'scheme', kind_word, '-', 'fast', 'fast | paper', &
         '''fast'': the contact force solved inside each eq. (19) iteration, about one solve per step; ' &
         // '''paper'': the flowchart''s nested iterations (Fig. 3)'), &
      deck_var_t('analysis', 'storage', kind_word, '-', 'auto', 'auto | band | skyline | sparse', &
         '''band'' (LAPACK dpbtrf/dpbtrs), ''skyline'' (the code''s own LDL^T), ''sparse'' (CHOLMOD) or ' &
         // '''auto'' (band below 3000 equations, sparse from there; modes: band)'), &
      deck_var_t('analysis', 'max_contact_iter', kind_integer, '-', '50', '[1, 10000]', &
         'contact iterations per step, at most'), &
      deck_var_t('analysis', 'max_nonlinear_iter', kind_integer, '-', '200', '[1, 100000]', &
         'eq. (19) iterations per plate solution, at most'), &
      deck_var_t('analysis', 'force_update', kind_word, '-', 'bracketed', 'bracketed | fixed_point | plain', &
         'update of the assumed contact force (scheme ''paper''): ''bracketed'' (regula falsi), ''fixed_point''' &
         // ' (F <- F_cont, falls back to bracketed) or ''plain'' (F <- F_cont, no fall-back)'), &
      deck_var_t('analysis', 'stop_on_warning', kind_logical, '-', '.false.', '', &
         'stop the run at the first warning instead of going on'), &
      deck_var_t('load', 'kind', kind_word, '-', 'uniform', 'uniform | sinusoidal | central_force', &
         'load of the static and pressure analyses: ''uniform'', ''sinusoidal'' (the single Navier term) or ' &
         // '''central_force'''), &
      deck_var_t('load', 'magnitude', kind_real, 'Pa or N', '1000', '(0, 1e12]', &
         'q0, or the central force'), &
      deck_var_t('load', 'increments', kind_integer, '-', '10', '[1, 100000]', &
         'load increments of a von Karman static analysis'), &
      deck_var_t('modes', 'count', kind_integer, '-', '6', '[1, 1000]', 'natural modes computed'), &
      deck_var_t('modes', 'shapes', kind_logical, '-', '.true.', '', 'also the mode shapes'), &
      deck_var_t('output', 'prefix', kind_path, '-', 'out/impact', '', &
         'path prefix of the result files; its directory is created'), &
      deck_var_t('output', 'every', kind_integer, '-', '1', '[1, inf)', 'write every N-th step to the history'), &
      deck_var_t('output', 'overwrite', kind_logical, '-', '.false.', '', &
         'replace the results of an earlier run with the same prefix (else the run is refused)'), &
      deck_var_t('output', 'hdf5', kind_logical, '-', '.true.', '', 'also write the full results to <prefix>.h5'), &
      deck_var_t('output', 'xdmf', kind_word, '-', 'modelled', 'modelled | whole | none', '<prefix>.xdmf beside ' &
         // '<prefix>.h5, for ParaView: ''modelled'' (the domain of &mesh), ''whole'' (a quarter or half mirrored ' &
         // 'into the whole plate; its fields then also stored in <prefix>.h5) or ''none'' (no XDMF file)'), &
      deck_var_t('output', 'fields_every', kind_integer, '-', '40', '[1, inf)', &
         'field snapshots in <prefix>.h5 every N-th step'), &
      deck_var_t('output', 'gauge', kind_word, '-', 'point', 'point | paper', 'the back-face strain gauge: ''point'' ' &
         // '(at gauge_x, gauge_y, from the element''s strain field: converges as the mesh is refined) or ' &
         // '''paper'' (Fig. 9b: the Gauss point nearest the impact point, moves with the mesh)'), &
      deck_var_t('output', 'gauge_x', kind_real, 'm', '', '(-inf, inf)', 'the strain gauge along x from the ' &
         // 'plate centre; not given: the impact point''s (with gauge = ''paper'': the paper''s Gauss point''s)'), &
      deck_var_t('output', 'gauge_y', kind_real, 'm', '', '(-inf, inf)', 'the strain gauge along y, likewise'), &
      deck_var_t('accuracy', 'target', kind_real, '-', '', '(0, 0.5]', 'relative error every result must ' &
         // 'reach: the run refines dt and the mesh on a ladder of runs until it estimates so (impact ' &
         // '--accuracy TOL; src/accuracy/); not given: one plain run, no estimate'), &
      deck_var_t('accuracy', 'max_cpu_s', kind_real, 's', '', '(0, inf)', &
         'cpu time all the runs of an accuracy run may take together; not given: 100 times its first run''s'), &
      deck_var_t('accuracy', 'mesh_factor', kind_real, '-', '1.5', '[1.2, 2]', &
         'ratio of the element counts of successive meshes of the accuracy ladder'), &
      deck_var_t('accuracy', 'results', kind_path, '-', 'default', '', 'the results that must meet the target, ' &
         // 'summary keys joined by + (peak_force_N, max_deflection_mm, contact_duration_us, time_of_peak_us, ' &
         // 'max_strain_y_back, max_failure_index), ''default'' (the first three, max_failure_index) or ''all''') ]

   !> Everything the deck sets (SI units); defaults: default_deck (input_deck).
   type :: deck_t
      character(len=:), allocatable :: source       !< file the deck came from, or '<stdin>'
      character(len=:), allocatable :: settings     !< the command line's --set settings over it, '' for none
      ! &plate
      real(dp) :: a = 0, b = 0, h = 0
      ! &lamina
      real(dp) :: e1 = 0, e2 = 0, g12 = 0, g13 = 0, g23 = 0, nu12 = 0, rho = 0
      ! &laminate
      real(dp), allocatable :: angles(:)
      real(dp) :: k4 = 0, k5 = 0                    !< NaN: not given (Whitney's method; is_given)
      character(len=:), allocatable :: bend_twist
      ! &strength (NaN: not given, as k4, k5: strength_given)
      real(dp) :: xt = 0, xc = 0, yt = 0, yc = 0, s12 = 0, s23 = 0
      real(dp) :: g1c = 0, g2c = 0, gft = 0, gfc = 0, gmt = 0, gmc = 0   !< NaN: not given (is_given)
      character(len=:), allocatable :: criterion
      ! &damage
      character(len=:), allocatable :: damage_model
      real(dp) :: damage_viscosity = 0
      ! &impactor
      real(dp) :: mass = 0, velocity = 0, diameter = 0, x0 = 0, y0 = 0
      ! &contact
      real(dp) :: k = 0, q = 0, alpha_p = 0, beta = 0
      character(len=:), allocatable :: contact_load
      ! &mesh
      integer :: nx = 0, ny = 0                     !< not_given_integer: not given (chosen, src/model/scene_settings.f90)
      character(len=:), allocatable :: domain, shear_rule
      logical :: average_bend_twist = .false.
      real(dp) :: grading = 0, stabilization = 0
      ! &boundary
      character(len=:), allocatable :: edges, inplane
      ! &analysis
      character(len=:), allocatable :: analysis_kind, theory, scheme, storage, force_update
      real(dp) :: dt = 0, t_end = 0, cr1 = 0, cr2 = 0   !< dt NaN: not given (chosen, as nx, ny)
      integer :: max_contact_iter = 0, max_nonlinear_iter = 0
      logical :: stop_on_warning = .false.
      ! &load
      character(len=:), allocatable :: load_kind
      real(dp) :: load_magnitude = 0
      integer :: load_increments = 0
      ! &modes
      integer :: mode_count = 0
      logical :: mode_shapes = .false.
      ! &output
      character(len=:), allocatable :: prefix
      integer :: every = 0, fields_every = 0
      logical :: overwrite = .false., hdf5 = .false.
      character(len=:), allocatable :: xdmf, gauge
      real(dp) :: gauge_x = 0, gauge_y = 0          !< NaN: not given (the impact point; is_given)
      ! &accuracy
      real(dp) :: accuracy_target = 0              !< NaN: not given (one plain run; accuracy_wanted)
      real(dp) :: accuracy_max_cpu_s = 0, accuracy_mesh_factor = 0
      character(len=:), allocatable :: accuracy_results
      !> dt, nx, ny chosen from the scene: what and why ('' for a given value)
      character(len=240) :: dt_chosen = '', mesh_chosen = ''
      !> which variables the deck (or --set) gave, by entry of deck_vars
      logical :: given(size(deck_vars)) = .false.
   end type deck_t

   !> One value on its way in or out of a deck_t (deck_bind).
   type :: value_t
      real(dp) :: r = 0                              !< kind_real
      integer :: i = 0                               !< kind_integer
      logical :: l = .false.                         !< kind_logical
      character(len=:), allocatable :: s            !< kind_word, kind_path
      real(dp), allocatable :: list(:)               !< kind_reals
      logical :: given = .true.                      !< an optional variable has a value
   end type value_t

contains

   !> 'group.name' of entry iv.
   pure function var_key(iv) result(key)
      integer, intent(in) :: iv
      character(len=:), allocatable :: key
      key = trim(deck_vars(iv)%group) // '.' // trim(deck_vars(iv)%name)
   end function var_key

   !> The entry of group.name, 0 when there is none.
   pure function find_var(group, name) result(iv)
      character(len=*), intent(in) :: group, name   !< lower case
      integer :: iv
      iv = findloc(deck_vars%group == group .and. deck_vars%name == name, .true., dim=1)
   end function find_var

   !> True when the deck gives the six strengths of &strength: the ply
   !> stresses and the failure criterion are then computed.
   pure logical function strength_given(deck)
      type(deck_t), intent(in) :: deck   !< the deck
      integer :: k
      strength_given = all([(is_given(deck, 'strength', trim(strength_names(k))), k = 1, size(strength_names))])
   end function strength_given

   !> True when the deck gives any toughness of &strength (g1c, ... gmc).
   pure logical function toughness_given(deck)
      type(deck_t), intent(in) :: deck              !< the deck
      integer :: k
      toughness_given = any([(is_given(deck, 'strength', trim(toughness_names(k))), k = 1, size(toughness_names))])
   end function toughness_given

   !> True when the deck asks for an accuracy run (&accuracy target, --accuracy).
   pure logical function accuracy_wanted(deck)
      type(deck_t), intent(in) :: deck   !< the deck
      accuracy_wanted = is_given(deck, 'accuracy', 'target')
   end function accuracy_wanted

   !> True when group.name has a value: always with a default, for an optional
   !> one when given one (module header); false for an unknown name.
   pure logical function is_given(deck, group, name)
      type(deck_t), intent(in) :: deck              !< the deck
      character(len=*), intent(in) :: group, name   !< the variable, lower case
      type(deck_t) :: copy
      type(value_t) :: v
      integer :: iv
      iv = find_var(group, name)
      is_given = iv > 0
      if (iv == 0) return
      if (len_trim(deck_vars(iv)%default) > 0) return
      copy = deck                        ! (deck_bind moves values both ways: a copy keeps deck intent(in))
      call deck_bind(copy, iv, v, .false.)
      is_given = v%given
   end function is_given

   !> "Not given" of an optional real: NaN (module header).
   pure function not_given_real() result(x)
      real(dp) :: x
      x = ieee_value(x, ieee_quiet_nan)
   end function not_given_real

   !> Moves entry iv's value between v and the deck: in when set, else out.
   !> An optional value without a value (v%given false) goes in as its
   !> sentinel and comes out with v%given false (module header).
   pure subroutine deck_bind(deck, iv, v, set)
      type(deck_t), intent(inout) :: deck   !< the deck
      integer, intent(in) :: iv             !< entry of deck_vars
      type(value_t), intent(inout) :: v     !< the value
      logical, intent(in) :: set            !< direction: v -> deck
      if (.not. set) v = value_t()
      if (set .and. .not. v%given) then     ! an optional variable without a value: its sentinel
         v%r = not_given_real()
         v%i = not_given_integer
      end if
      select case (var_key(iv))
      case ('plate.a');                    call bind_value(deck%a, v, set)
      case ('plate.b');                    call bind_value(deck%b, v, set)
      case ('plate.h');                    call bind_value(deck%h, v, set)
      case ('lamina.e1');                  call bind_value(deck%e1, v, set)
      case ('lamina.e2');                  call bind_value(deck%e2, v, set)
      case ('lamina.g12');                 call bind_value(deck%g12, v, set)
      case ('lamina.g13');                 call bind_value(deck%g13, v, set)
      case ('lamina.g23');                 call bind_value(deck%g23, v, set)
      case ('lamina.nu12');                call bind_value(deck%nu12, v, set)
      case ('lamina.rho');                 call bind_value(deck%rho, v, set)
      case ('laminate.angles');            call bind_list(deck%angles, v, set)
      case ('laminate.k4');                call bind_value(deck%k4, v, set)
      case ('laminate.k5');                call bind_value(deck%k5, v, set)
      case ('laminate.bend_twist');        call bind_text(deck%bend_twist, v, set)
      case ('strength.xt');                call bind_value(deck%xt, v, set)
      case ('strength.xc');                call bind_value(deck%xc, v, set)
      case ('strength.yt');                call bind_value(deck%yt, v, set)
      case ('strength.yc');                call bind_value(deck%yc, v, set)
      case ('strength.s12');               call bind_value(deck%s12, v, set)
      case ('strength.s23');               call bind_value(deck%s23, v, set)
      case ('strength.criterion');         call bind_text(deck%criterion, v, set)
      case ('strength.g1c');               call bind_value(deck%g1c, v, set)
      case ('strength.g2c');               call bind_value(deck%g2c, v, set)
      case ('strength.gft');               call bind_value(deck%gft, v, set)
      case ('strength.gfc');               call bind_value(deck%gfc, v, set)
      case ('strength.gmt');               call bind_value(deck%gmt, v, set)
      case ('strength.gmc');               call bind_value(deck%gmc, v, set)
      case ('damage.model');               call bind_text(deck%damage_model, v, set)
      case ('damage.viscosity');           call bind_value(deck%damage_viscosity, v, set)
      case ('impactor.mass');              call bind_value(deck%mass, v, set)
      case ('impactor.velocity');          call bind_value(deck%velocity, v, set)
      case ('impactor.diameter');          call bind_value(deck%diameter, v, set)
      case ('impactor.x0');                call bind_value(deck%x0, v, set)
      case ('impactor.y0');                call bind_value(deck%y0, v, set)
      case ('contact.k');                  call bind_value(deck%k, v, set)
      case ('contact.q');                  call bind_value(deck%q, v, set)
      case ('contact.alpha_p');            call bind_value(deck%alpha_p, v, set)
      case ('contact.beta');               call bind_value(deck%beta, v, set)
      case ('contact.load');               call bind_text(deck%contact_load, v, set)
      case ('mesh.nx');                    call bind_value(deck%nx, v, set)
      case ('mesh.ny');                    call bind_value(deck%ny, v, set)
      case ('mesh.domain');                call bind_text(deck%domain, v, set)
      case ('mesh.average_bend_twist');    call bind_value(deck%average_bend_twist, v, set)
      case ('mesh.grading');               call bind_value(deck%grading, v, set)
      case ('mesh.shear_rule');            call bind_text(deck%shear_rule, v, set)
      case ('mesh.stabilization');         call bind_value(deck%stabilization, v, set)
      case ('boundary.edges');             call bind_text(deck%edges, v, set)
      case ('boundary.inplane');           call bind_text(deck%inplane, v, set)
      case ('analysis.kind');              call bind_text(deck%analysis_kind, v, set)
      case ('analysis.theory');            call bind_text(deck%theory, v, set)
      case ('analysis.dt');                call bind_value(deck%dt, v, set)
      case ('analysis.t_end');             call bind_value(deck%t_end, v, set)
      case ('analysis.cr1');               call bind_value(deck%cr1, v, set)
      case ('analysis.cr2');               call bind_value(deck%cr2, v, set)
      case ('analysis.scheme');            call bind_text(deck%scheme, v, set)
      case ('analysis.storage');           call bind_text(deck%storage, v, set)
      case ('analysis.max_contact_iter');  call bind_value(deck%max_contact_iter, v, set)
      case ('analysis.max_nonlinear_iter'); call bind_value(deck%max_nonlinear_iter, v, set)
      case ('analysis.force_update');      call bind_text(deck%force_update, v, set)
      case ('analysis.stop_on_warning');   call bind_value(deck%stop_on_warning, v, set)
      case ('load.kind');                  call bind_text(deck%load_kind, v, set)
      case ('load.magnitude');             call bind_value(deck%load_magnitude, v, set)
      case ('load.increments');            call bind_value(deck%load_increments, v, set)
      case ('modes.count');                call bind_value(deck%mode_count, v, set)
      case ('modes.shapes');               call bind_value(deck%mode_shapes, v, set)
      case ('output.prefix');              call bind_text(deck%prefix, v, set)
      case ('output.every');               call bind_value(deck%every, v, set)
      case ('output.overwrite');           call bind_value(deck%overwrite, v, set)
      case ('output.hdf5');                call bind_value(deck%hdf5, v, set)
      case ('output.xdmf');                call bind_text(deck%xdmf, v, set)
      case ('output.fields_every');        call bind_value(deck%fields_every, v, set)
      case ('output.gauge');               call bind_text(deck%gauge, v, set)
      case ('output.gauge_x');             call bind_value(deck%gauge_x, v, set)
      case ('output.gauge_y');             call bind_value(deck%gauge_y, v, set)
      case ('accuracy.target');            call bind_value(deck%accuracy_target, v, set)
      case ('accuracy.max_cpu_s');         call bind_value(deck%accuracy_max_cpu_s, v, set)
      case ('accuracy.mesh_factor');       call bind_value(deck%accuracy_mesh_factor, v, set)
      case ('accuracy.results');           call bind_text(deck%accuracy_results, v, set)
      end select
      if (.not. set .and. len_trim(deck_vars(iv)%default) == 0) then
         select case (deck_vars(iv)%kind)
         case (kind_real);    v%given = .not. ieee_is_nan(v%r)
         case (kind_integer); v%given = v%i /= not_given_integer
         end select
      end if
   end subroutine deck_bind

   !> A real, integer or logical between v and the deck (deck_bind).
   pure subroutine bind_value(x, v, set)
      class(*), intent(inout) :: x              !< the deck's component
      type(value_t), intent(inout) :: v         !< the value
      logical, intent(in) :: set                !< direction: v -> x
      select type (x)
      type is (real(dp))
         if (set) x = v%r
         if (.not. set) v%r = x
      type is (integer)
         if (set) x = v%i
         if (.not. set) v%i = x
      type is (logical)
         if (set) x = v%l
         if (.not. set) v%l = x
      end select
   end subroutine bind_value

   !> A word or a text between v%s and the deck ('' for an unset one) (deck_bind).
   pure subroutine bind_text(x, v, set)
      character(len=:), allocatable, intent(inout) :: x   !< the deck's component
      type(value_t), intent(inout) :: v                   !< the value
      logical, intent(in) :: set                          !< direction: v -> x
      if (set) then
         x = v%s
      else
         v%s = ''
         if (allocated(x)) v%s = x
      end if
   end subroutine bind_text

   !> A list of reals between v%list and the deck (none for an unset one) (deck_bind).
   pure subroutine bind_list(x, v, set)
      real(dp), allocatable, intent(inout) :: x(:)   !< the deck's component
      type(value_t), intent(inout) :: v              !< the value
      logical, intent(in) :: set                     !< direction: v -> x
      if (set) then
         x = v%list
      else
         allocate (v%list(0))
         if (allocated(x)) v%list = x
      end if
   end subroutine bind_list

   !> The words of a range 'a | b | c' as 'a b c'.
   pure function words_of(range) result(words)
      character(len=*), intent(in) :: range
      character(len=:), allocatable :: words
      integer :: i
      words = trim(range)
      do i = 1, len(words)
         if (words(i:i) == '|') words(i:i) = ' '
      end do
   end function words_of

   !> The words of a range as "'a', 'b', 'c'".
   pure function words_quoted(range) result(text)
      character(len=*), intent(in) :: range
      character(len=:), allocatable :: text
      integer :: bar
      text = "'" // trim(range) // "'"
      bar = index(text, ' | ')
      do while (bar > 0)
         text = text(:bar - 1) // "', '" // text(bar + 3:)
         bar = index(text, ' | ')
      end do
   end function words_quoted

end module deck_schema
