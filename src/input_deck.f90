!> The input deck: one namelist file, read from standard input or a path.
!>
!> Usage: `./impact < input/clamped.nml`. Every value is in SI units. The deck
!> has one namelist group per concern; a group that is absent, and a variable
!> that is absent from its group, keep the default, and the defaults are the
!> values of the paper (Choi, Hong & Lee 1991; see /work/shared/paper/NOTES.md).
!> Group and variable names and the keyword values are case-insensitive; the
!> keywords are stored in lower case. Text outside the groups and everything
!> after `!` is a comment.
!>
!>     group      variable            unit       default          meaning
!>     &plate     a                   m          0.15             plate length along x
!>                b                   m          0.10             plate width along y
!>                h                   m          0.0027           plate thickness
!>     &lamina    e1, e2              Pa         120e9, 7.9e9     Young's moduli along, across the fibres
!>                g12, g13, g23       Pa         5.5e9, 5.5e9, 2.63e9   shear moduli
!>                nu12                -          0.30             major Poisson ratio
!>                rho                 kg/m^3     1580             density
!>     &laminate  angles(:)           deg        [0/45/0/-45/0]2s ply angles from x, bottom (z = -h/2)
!>                                                                to top; all plies equally thick, h/n
!>                k4, k5              -          (Whitney)        shear correction factors (Table 1); not
!>                                                                given: computed from the layup by
!>                                                                Whitney's method (src/shear_correction.f90)
!>                bend_twist          -          'auto'           D16, D26: 'auto' (dropped on a quarter, half
!>                                                                or strip, section 3.1; kept on the full
!>                                                                plate) | 'drop' (everywhere; lets domain
!>                                                                'auto' pick a quarter) | 'keep' (full plate
!>                                                                or domain 'auto' only)
!>     &impactor  mass                kg         0.243            impactor mass
!>                velocity            m/s        3.0              initial velocity, towards the plate
!>                diameter            m          0.0127           diameter of the hemispherical nose
!>                x0, y0              m          0, 0             impact point from the plate centre
!>     &contact   k                   N/m^1.5    1.413e9          contact stiffness, F = k alpha^1.5
!>                q                   -          2.5              unloading exponent
!>                alpha_p             m          1.667e-5         indentation beyond which it is permanent
!>                beta                -          0.094            alpha0 = beta (alpha_m - alpha_p)
!>                load                -          'hertz'          'hertz' (Hertz's pressure over the contact
!>                                                                area) | 'point' (the paper's point force)
!>     &mesh      nx, ny              -          9, 6             9-node elements from the impact point to
!>                                                                an edge along x, y for a centred impact
!>                                                                (the quarter's counts; src/mesh.f90)
!>                domain              -          'auto'           'auto' (the smallest the scene allows,
!>                                                                src/scene_model.f90) | 'quarter' | 'half'
!>                                                                | 'full' |
!>                                                                'strip' (quarter of a plate infinitely
!>                                                                long in y: y = b/2 a symmetry line too)
!>                shear_rule          -          'auto'           transverse shear of the element: 'mitc9'
!>                                                                (assumed strain) | 'selective' (2x2, the
!>                                                                paper's) | 'stabilized' | 'full' (3x3) |
!>                                                                'auto' (mitc9; src/shear_strain.f90)
!>                stabilization       -          0.01             fraction eps of 3x3 shear when stabilized
!>                average_bend_twist  -          .false.          .true.: the paper's averaging (section 3.1)
!>                                                                is accepted, D16 = D26 = 0 on a quarter or
!>                                                                half domain chosen by 'auto'
!>                grading             -          1                ratio of successive element sizes away
!>                                                                from the impact point (1 = uniform, <= 3)
!>     &boundary  edges               -          'clamped'        'free' | 'simply_supported' | 'clamped'
!>                inplane             -          'immovable'      in-plane condition of simply supported
!>                                                                edges: 'immovable' | 'movable'
!>     &analysis  kind                -          'impact'         'impact' | 'static' | 'modes' | 'pressure'
!>                                                                (transient, suddenly applied &load)
!>                theory              -          'nonlinear'      'linear' | 'nonlinear' (von Karman) | 'auto'
!>                                                                (from the scene's deflection estimate)
!>                dt                  s          2.5e-6           time step
!>                t_end               s          3.0e-3           end time
!>                cr1                 -          2.0e-3           contact force tolerance, eq. (17)
!>                cr2                 -          1.0e-7           nonlinear iteration tolerance, eq. (18)
!>                scheme              -          'paper'          contact/nonlinear iteration: 'paper' | 'fast'
!>                storage             -          'band'           'band' (LAPACK band Cholesky) | 'skyline'
!>                max_contact_iter    -          50               contact iterations per step, at most
!>                max_nonlinear_iter  -          200              nonlinear iterations per contact iteration
!>                force_update        -          'bracketed'      update of the assumed contact force (scheme
!>                                                                'paper'): 'bracketed' (regula falsi) |
!>                                                                'fixed_point' (F = F_cont; falls back to
!>                                                                'bracketed' when it stops contracting)
!>                stop_on_warning     -          .false.          stop the run at the first warning (w/h > 5,
!>                                                                a fall-back of an iteration)
!>     &load      kind                -          'uniform'        load of kind = 'static' | 'pressure':
!>                                                                'uniform' | 'sinusoidal' (q0 cos(pi x/a)
!>                                                                cos(pi y/b), x, y from the centre) |
!>                                                                'central_force' (at the plate centre)
!>                magnitude           Pa or N    1000             pressure q0 (Pa) or central force (N), > 0
!>                increments          -          10               equal load increments of a nonlinear
!>                                                                static analysis (Newton in each)
!>     &modes     count               -          6                natural modes computed (kind = 'modes')
!>                shapes              -          .true.           also the mode shapes (memory 8 n^2 bytes
!>                                                                for n equations); .false.: frequencies only
!>     &output    prefix              -          'out/impact'     output file prefix (path without suffix)
!>                every               -          1                write every N-th time step to the history
!>                overwrite           -          .false.          replace the results of an earlier run with
!>                                                                the same prefix (else the run is refused)
!>                hdf5                -          .true.           also write <prefix>.h5 (src/results_hdf5.f90)
!>                fields_every        -          40               field snapshots in <prefix>.h5 every N-th step
!>
!> The ply angles are given as a list, `angles = 0, 45, 0, -45, 0, ...`, at most
!> `max_plies` of them, without gaps. With domain = 'quarter' the layup must be
!> symmetric about the mid-plane (the quarter model assumes B = 0).
!>
!> Checked after reading (validate_deck), the first failure ends the read:
!> a, b, h, the moduli, rho, mass, velocity, diameter, k, q, dt, t_end > 0 and
!> finite; h < min(a, b); nu12 > 0 and nu12**2 < e1/e2; k4, k5 in (0, 1.2]
!> or not given; the nose on the plate, |x0| <= a/2 - diameter/2 and
!> |y0| <= b/2 - diameter/2; a 'quarter' or 'strip' domain needs
!> x0 = y0 = 0 and a 'half' x0 = 0 or y0 = 0; grading in [1, 3];
!> alpha_p >= 0; beta in [0, 1); cr1, cr2 in (0, 1), cr1 >= 100 eps; dt < t_end,
!> t_end/dt steps at most huge(1); nx, ny,
!> max_contact_iter, max_nonlinear_iter, every, fields_every >= 1; at least one ply, every
!> angle finite; the keywords in their sets; prefix not empty; magnitude > 0
!> and finite; increments, count >= 1; kind = 'modes' needs storage = 'band'
!> (LAPACK's banded eigensolver).
!>
!> A sample deck (the clamped plate of Fig. 10, nonlinear; it is
!> tests/data/decks/sample.nml):
!>
!>     ! clamped [0/45/0/-45/0]2s plate, 243 g at 3 m/s
!>     &plate    a = 0.15, b = 0.10, h = 0.0027 /
!>     &laminate angles = 0, 45, 0, -45, 0, 0, 45, 0, -45, 0,
!>                        0, -45, 0, 45, 0, 0, -45, 0, 45, 0 /
!>     &impactor mass = 0.243, velocity = 3.0 /
!>     &mesh     nx = 9, ny = 6, domain = 'quarter' /
!>     &boundary edges = 'clamped' /
!>     &analysis theory = 'nonlinear', dt = 2.5e-6, t_end = 3.0e-3 /
!>     &output   prefix = 'out/clamped' /
!>
!> A variable given without a value (`mass = ,` or `angles = /`), which the
!> namelist read would pass over silently, keeping the default, is an error.
!>
!> How it is read: the deck is copied line by line to a scratch file (standard
!> input cannot be rewound), its text is scanned for the group starts `&name`
!> (unknown, repeated or unclosed groups are rejected), then each group present
!> is read from the rewound scratch file into local variables that hold the
!> defaults. A failed read is diagnosed by reading the group's assignments one
!> at a time, so that the message names the offending variable. Last, every
!> value is range-checked (validate_deck).
module input_deck
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use kinds, only: dp, msg_len
   implicit none
   private
   public :: deck_t, max_plies, name_len, path_len, paper_angles, k_not_given
   public :: read_deck, read_deck_file, validate_deck, echo_deck, to_lower

   !> Size of the namelist buffer for the ply angles: the most plies a deck can give.
   integer, parameter :: max_plies = 1000
   !> Length of keyword values (domain, edges, ...) and of paths (source, prefix).
   integer, parameter :: name_len = 32, path_len = 256

   !> Value of &laminate k4, k5 that means "not given": the factors are then
   !> computed from the layup by Whitney's method (never 0, never a valid factor).
   real(dp), parameter :: k_not_given = -huge(1.0_dp)

   !> The layup of the paper, [0/45/0/-45/0]2s, bottom to top (deg): the default angles.
   real(dp), parameter :: paper_angles(20) = [ &
      0.0_dp, 45.0_dp, 0.0_dp, -45.0_dp, 0.0_dp, 0.0_dp, 45.0_dp, 0.0_dp, -45.0_dp, 0.0_dp, &
      0.0_dp, -45.0_dp, 0.0_dp, 45.0_dp, 0.0_dp, 0.0_dp, -45.0_dp, 0.0_dp, 45.0_dp, 0.0_dp]

   !> Everything the deck sets, with the paper's values as defaults (SI units).
   !> `angles` has no default initialisation (it is allocatable): read_deck sets it
   !> to paper_angles when the deck gives no plies.
   type :: deck_t
      character(len=path_len) :: source = '<stdin>'   ! file the deck came from
      ! &plate a, b, h /            plate length along x, width along y, thickness (m)
      real(dp) :: a = 0.15_dp, b = 0.10_dp, h = 0.0027_dp
      ! &lamina e1, e2, g12, g13, g23, nu12, rho /   (Pa, -, kg/m^3)  paper Table 3
      real(dp) :: e1 = 120.0e9_dp, e2 = 7.9e9_dp, g12 = 5.5e9_dp, g13 = 5.5e9_dp, g23 = 2.63e9_dp
      real(dp) :: nu12 = 0.30_dp, rho = 1580.0_dp
      ! &laminate angles, k4, k5 /  ply angles in degrees from x, bottom (z=-h/2) to top; shear correction (Table 1)
      real(dp), allocatable :: angles(:)          ! default: [0/45/0/-45/0]_2s, 20 plies
      real(dp) :: k4 = k_not_given, k5 = k_not_given   ! not given: Whitney's method (src/shear_correction.f90)
      character(len=name_len) :: bend_twist = 'auto'     ! D16, D26: 'auto' | 'drop' | 'keep'
      ! &impactor mass, velocity, diameter /  (kg, m/s, m)
      real(dp) :: mass = 0.243_dp, velocity = 3.0_dp, diameter = 0.0127_dp
      real(dp) :: x0 = 0.0_dp, y0 = 0.0_dp               ! impact point from the plate centre (m)
      ! &contact k, q, alpha_p, beta /  (N/m^1.5, -, m, -)  paper Table 2 in SI
      real(dp) :: k = 1.413e9_dp, q = 2.5_dp, alpha_p = 1.667e-5_dp, beta = 0.094_dp
      ! &contact load /  how the contact force enters the plate: 'hertz' (Hertz's pressure over the
      !    contact area, the default) | 'point' (the paper's point force, eq. 10)
      character(len=name_len) :: contact_load = 'hertz'
      ! &mesh nx, ny, domain, shear_rule, stabilization, average_bend_twist, grading /
      !    elements along x and y of the domain (the quarter's with 'auto'); domain and how the code
      !    chooses it; D16 = D26 = 0 accepted; ratio of successive element sizes
      integer :: nx = 9, ny = 6
      character(len=name_len) :: domain = 'auto'         ! 'auto' | 'quarter' | 'half' | 'full' | 'strip'
      logical :: average_bend_twist = .false.            ! accept D16 = D26 = 0 (section 3.1) for 'auto'
      real(dp) :: grading = 1.0_dp                       ! ratio of successive element sizes (1: uniform)
      character(len=name_len) :: shear_rule = 'auto'     ! 'auto' (mitc9) | 'mitc9' | 'selective' | 'stabilized' | 'full'
      real(dp) :: stabilization = 0.01_dp                ! fraction of 3x3 shear when stabilized
      ! &boundary edges, inplane /  'free' | 'simply_supported' | 'clamped';
      !    in-plane condition of simply supported edges: 'immovable' | 'movable'
      character(len=name_len) :: edges = 'clamped', inplane = 'immovable'
      ! &analysis kind, theory, dt, t_end, cr1, cr2, scheme, storage, max_contact_iter, max_nonlinear_iter /
      character(len=name_len) :: analysis_kind = 'impact'  ! 'impact' | 'static' | 'modes' | 'pressure'
      character(len=name_len) :: theory = 'nonlinear'   ! 'linear' | 'nonlinear' | 'auto'
      real(dp) :: dt = 2.5e-6_dp, t_end = 3.0e-3_dp     ! s
      real(dp) :: cr1 = 2.0e-3_dp, cr2 = 1.0e-7_dp      ! eq. (17), (18) tolerances (0.2 %, 1e-7)
      character(len=name_len) :: scheme = 'paper'        ! contact/nonlinear iteration scheme: 'paper' | 'fast'
      character(len=name_len) :: storage = 'band'        ! 'band' (LAPACK band Cholesky) | 'skyline' (own LDL^T)
      integer :: max_contact_iter = 50, max_nonlinear_iter = 200
      ! &analysis force_update, stop_on_warning /  'bracketed' | 'fixed_point' (the paper's plain
      !    update, guarded); stop at the first warning (w/h > 5, a fall-back) instead of going on
      character(len=name_len) :: force_update = 'bracketed'
      logical :: stop_on_warning = .false.
      ! &load kind, magnitude, increments /  load of the static and pressure analyses:
      !    'uniform' | 'sinusoidal' | 'central_force'; q0 (Pa) or force (N); Newton load increments
      character(len=name_len) :: load_kind = 'uniform'
      real(dp) :: load_magnitude = 1000.0_dp
      integer :: load_increments = 10
      ! &modes count, shapes /  natural modes computed by the modal analysis; with their shapes
      integer :: mode_count = 6
      logical :: mode_shapes = .true.
      ! &output prefix, every /  output file prefix (path without suffix); write every N-th step
      character(len=path_len) :: prefix = 'out/impact'
      integer :: every = 1
      ! &output overwrite /  replace an earlier run's <prefix>_history.dat, _summary.dat (else refused)
      logical :: overwrite = .false.
      ! &output hdf5, fields_every /  write <prefix>.h5; nodal field snapshots in it every N-th step
      logical :: hdf5 = .true.
      integer :: fields_every = 40
   end type deck_t

   !> The namelist groups a deck may hold, in the order of the echo.
   integer, parameter :: group_name_len = 8
   character(len=group_name_len), parameter :: known_groups(11) = [character(len=group_name_len) :: &
      'plate', 'lamina', 'laminate', 'impactor', 'contact', 'mesh', 'boundary', 'analysis', 'load', &
      'modes', 'output']

   !> Marks the entries of the angles buffer that the deck did not set.
   real(dp), parameter :: no_ply = -huge(1.0_dp)
   !> Upper bound of the ratio of successive element sizes, &mesh grading.
   real(dp), parameter :: max_grading = 3.0_dp
   !> Upper bound of the shear correction factors k4, k5.
   real(dp), parameter :: max_shear_correction = 1.2_dp
   !> Characters read per chunk when a deck line is copied.
   integer, parameter :: chunk_len = 256
   !> Longest value text quoted in a message before it is cut short.
   integer, parameter :: max_quoted = 60
   !> Ply angles per echo line.
   integer, parameter :: angles_per_line = 10
   !> Width of the group column of the echo ('&laminate  ').
   integer, parameter :: group_column = 11
   !> Smallest contact-force tolerance C_r1: 100 eps, the rounding of the force.
   real(dp), parameter :: min_cr1 = 100.0_dp * epsilon(1.0_dp)
   !> Status returned on any failure.
   integer, parameter :: failed = 1

   !> One line of text, of any length.
   type :: text_t
      character(len=:), allocatable :: s
   end type text_t

   !> A namelist group found in the deck text.
   type :: group_t
      character(len=:), allocatable :: name   ! lower case, without '&'
      character(len=:), allocatable :: body   ! text up to the closing '/', comments removed
      logical :: closed = .false.             ! the closing '/' (or &end) was found
   end type group_t

contains

   !> Reads a deck from `unit`, an open formatted sequential unit (standard input
   !> is fine: the unit is read once, to its end, and never rewound), then checks
   !> every value with validate_deck. On failure `stat` /= 0 and `errmsg` names the
   !> file, the group and the variable; `deck` is then incomplete.
   subroutine read_deck(unit, source, deck, stat, errmsg)
      !> Unit to read the deck from.
      integer, intent(in) :: unit
      !> Name of the deck for messages and the echo (a path or '<stdin>').
      character(len=*), intent(in) :: source
      !> The deck: defaults overridden by what the file gives.
      type(deck_t), intent(out) :: deck
      !> 0 when the deck was read and is valid.
      integer, intent(out) :: stat
      !> Set on failure.
      character(len=*), intent(inout) :: errmsg

      type(text_t), allocatable :: lines(:)
      type(group_t), allocatable :: groups(:)
      integer :: scratch, ios, ig, jg
      character(len=msg_len) :: msg

      deck%source = source
      deck%angles = paper_angles

      call read_lines(unit, lines, ios, msg)
      if (ios /= 0) then
         stat = failed
         errmsg = trim(deck%source) // ': cannot read the deck: ' // trim(msg)
         return
      end if

      ! Groups: known names only, each at most once, each closed.
      call scan_groups(lines, groups)
      stat = 0
      groups_1: do ig = 1, size(groups)
         if (.not. any(known_groups == groups(ig)%name)) then
            stat = failed
            errmsg = trim(deck%source) // ': unknown namelist group &' // groups(ig)%name &
               // ' (the groups are ' // group_list() // ')'
         else if (.not. groups(ig)%closed) then
            stat = failed
            errmsg = trim(deck%source) // ': namelist &' // groups(ig)%name &
               // ": no closing '/' (the group runs into the next group or the end of the file)"
         else
            call missing_value(deck%source, groups(ig)%name, groups(ig)%body, stat, errmsg)
            do jg = 1, ig - 1
               if (groups(jg)%name == groups(ig)%name) then
                  stat = failed
                  errmsg = trim(deck%source) // ': namelist group &' // groups(ig)%name &
                     // ' is given twice; give each group once'
                  exit
               end if
            end do
         end if
         if (stat /= 0) return
      end do groups_1

      ! Copy the text to a scratch file that every group read rewinds.
      open (newunit=scratch, status='scratch', form='formatted', action='readwrite', &
         iostat=ios, iomsg=msg)
      if (ios /= 0) then
         stat = failed
         errmsg = trim(deck%source) // ': cannot open a scratch file: ' // trim(msg)
         return
      end if
      copy_1: do ig = 1, size(lines)
         write (scratch, '(a)', iostat=ios, iomsg=msg) lines(ig)%s
         if (ios /= 0) then
            stat = failed
            errmsg = trim(deck%source) // ': cannot write the scratch copy: ' // trim(msg)
            close (scratch, iostat=ios)
            return
         end if
      end do copy_1

      ! Read the groups present, in the order the deck gives them.
      read_groups: do ig = 1, size(groups)
         select case (groups(ig)%name)
         case ('plate')
            call read_plate(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('lamina')
            call read_lamina(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('laminate')
            call read_laminate(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('impactor')
            call read_impactor(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('contact')
            call read_contact(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('mesh')
            call read_mesh(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('boundary')
            call read_boundary(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('analysis')
            call read_analysis(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('load')
            call read_load(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('modes')
            call read_modes(scratch, groups(ig)%body, deck, stat, errmsg)
         case ('output')
            call read_output(scratch, groups(ig)%body, deck, stat, errmsg)
         end select
         if (stat /= 0) exit
      end do read_groups
      close (scratch, iostat=ios)
      if (stat /= 0) return

      call validate_deck(deck, stat, errmsg)
   end subroutine read_deck

   !> Opens the deck file `path`, reads it with read_deck and closes it.
   subroutine read_deck_file(path, deck, stat, errmsg)
      !> Path of the deck file.
      character(len=*), intent(in) :: path
      !> The deck read.
      type(deck_t), intent(out) :: deck
      !> 0 when the deck was read and is valid.
      integer, intent(out) :: stat
      !> Set on failure.
      character(len=*), intent(inout) :: errmsg

      integer :: unit, ios
      character(len=msg_len) :: msg

      open (newunit=unit, file=path, status='old', action='read', form='formatted', &
         access='sequential', iostat=ios, iomsg=msg)
      if (ios /= 0) then
         stat = failed
         errmsg = "cannot open the deck file '" // trim(path) // "': " // trim(msg)
         return
      end if
      call read_deck(unit, path, deck, stat, errmsg)
      close (unit, iostat=ios, iomsg=msg)
      if (ios /= 0 .and. stat == 0) then
         stat = failed
         errmsg = "cannot close the deck file '" // trim(path) // "': " // trim(msg)
      end if
   end subroutine read_deck_file

   !> Checks every value of `deck`; stops at the first bad one, with a message
   !> "<file>: &group: variable = value: what is wrong". The keyword values
   !> (domain, edges, inplane, theory, scheme, storage) are normalised to lower
   !> case without leading blanks, so the deck is intent(inout).
   subroutine validate_deck(deck, stat, errmsg)
      !> The deck to check; its keywords come back in lower case.
      type(deck_t), intent(inout) :: deck
      !> 0 when every value is acceptable.
      integer, intent(out) :: stat
      !> Set on failure.
      character(len=*), intent(inout) :: errmsg

      integer :: n, i

      stat = 0

      call positive('plate', 'a', deck%a, 'm')
      call positive('plate', 'b', deck%b, 'm')
      call positive('plate', 'h', deck%h, 'm')
      if (stat == 0) call need(deck%h < min(deck%a, deck%b), 'plate', 'h', real_str(deck%h), &
         'the thickness must be smaller than a and b')

      call positive('lamina', 'e1', deck%e1, 'Pa')
      call positive('lamina', 'e2', deck%e2, 'Pa')
      call positive('lamina', 'g12', deck%g12, 'Pa')
      call positive('lamina', 'g13', deck%g13, 'Pa')
      call positive('lamina', 'g23', deck%g23, 'Pa')
      call positive('lamina', 'nu12', deck%nu12, '')
      if (stat == 0) call need(deck%nu12**2 < deck%e1 / deck%e2, 'lamina', 'nu12', real_str(deck%nu12), &
         'nu12**2 must be less than e1/e2 = ' // real_str(deck%e1 / deck%e2) &
         // ' (else the lamina stiffness is not positive definite)')
      call positive('lamina', 'rho', deck%rho, 'kg/m^3')

      if (stat == 0) call need(allocated(deck%angles), 'laminate', 'angles', '(none)', 'give at least one ply')
      if (stat == 0) call need(size(deck%angles) >= 1, 'laminate', 'angles', '(none)', 'give at least one ply')
      if (stat == 0) then
         n = size(deck%angles)
         do i = 1, n
            call need(ieee_is_finite(deck%angles(i)), 'laminate', 'angles(' // int_str(i) // ')', &
               real_str(deck%angles(i)), 'must be finite')
         end do
      end if
      if (deck%k4 /= k_not_given) call in_range('laminate', 'k4', deck%k4, 0.0_dp, max_shear_correction, &
         '(0, 1.2], or not given (Whitney)')
      if (deck%k5 /= k_not_given) call in_range('laminate', 'k5', deck%k5, 0.0_dp, max_shear_correction, &
         '(0, 1.2], or not given (Whitney)')
      call keyword('laminate', 'bend_twist', deck%bend_twist, [character(len=name_len) :: 'auto', 'drop', 'keep'])

      call positive('impactor', 'mass', deck%mass, 'kg')
      call positive('impactor', 'velocity', deck%velocity, 'm/s')
      call positive('impactor', 'diameter', deck%diameter, 'm')
      if (stat == 0) call need(ieee_is_finite(deck%x0) .and. abs(deck%x0) <= 0.5_dp*(deck%a - deck%diameter), &
         'impactor', 'x0', real_str(deck%x0), 'the nose must lie on the plate: |x0| <= (a - diameter)/2 = ' &
         // real_str(0.5_dp*(deck%a - deck%diameter)) // ' m (x0 is measured from the plate centre)')
      if (stat == 0) call need(ieee_is_finite(deck%y0) .and. abs(deck%y0) <= 0.5_dp*(deck%b - deck%diameter), &
         'impactor', 'y0', real_str(deck%y0), 'the nose must lie on the plate: |y0| <= (b - diameter)/2 = ' &
         // real_str(0.5_dp*(deck%b - deck%diameter)) // ' m (y0 is measured from the plate centre)')

      call positive('contact', 'k', deck%k, 'N/m^1.5')
      call positive('contact', 'q', deck%q, '')
      call need(ieee_is_finite(deck%alpha_p) .and. deck%alpha_p >= 0.0_dp, 'contact', 'alpha_p', &
         real_str(deck%alpha_p), 'must be zero or positive (m)')
      call need(deck%beta >= 0.0_dp .and. deck%beta < 1.0_dp, 'contact', 'beta', real_str(deck%beta), &
         'must be in [0, 1)')
      call keyword('contact', 'load', deck%contact_load, [character(len=name_len) :: 'hertz', 'point'])

      call need(deck%nx >= 1, 'mesh', 'nx', int_str(deck%nx), 'must be at least 1')
      call need(deck%ny >= 1, 'mesh', 'ny', int_str(deck%ny), 'must be at least 1')
      call keyword('mesh', 'domain', deck%domain, &
         [character(len=name_len) :: 'auto', 'quarter', 'half', 'full', 'strip'])
      if (stat == 0 .and. deck%domain /= 'full' .and. deck%domain /= 'auto') &
         call need(deck%bend_twist /= 'keep', 'laminate', 'bend_twist', &
         "'keep'", "the symmetry lines of &mesh domain = '" // trim(deck%domain) // "' need D16 = D26 = 0 " &
         // "(section 3.1): use domain = 'full'")
      if (stat == 0 .and. deck%average_bend_twist) call need(deck%bend_twist /= 'keep', 'laminate', 'bend_twist', &
         "'keep'", "contradicts &mesh average_bend_twist = .true., which accepts D16 = D26 = 0")
      if (stat == 0 .and. (deck%domain == 'quarter' .or. deck%domain == 'strip')) &
         call need(deck%x0 == 0.0_dp .and. deck%y0 == 0.0_dp, 'mesh', 'domain', "'" // trim(deck%domain) // "'", &
         'needs the impact point at the centre, but &impactor x0 = ' // real_str(deck%x0) // ' m, y0 = ' &
         // real_str(deck%y0) // " m: use domain = 'auto', 'half' or 'full'")
      if (stat == 0 .and. deck%domain == 'half') &
         call need(deck%x0 == 0.0_dp .or. deck%y0 == 0.0_dp, 'mesh', 'domain', "'half'", &
         'needs the impact point on a centre line (x0 = 0 or y0 = 0), but &impactor x0 = ' &
         // real_str(deck%x0) // ' m, y0 = ' // real_str(deck%y0) // " m: use domain = 'auto' or 'full'")
      call need(deck%grading >= 1.0_dp .and. deck%grading <= max_grading, 'mesh', 'grading', &
         real_str(deck%grading), 'must be in [1, ' // real_str(max_grading) // '] (1: uniform)')
      call keyword('mesh', 'shear_rule', deck%shear_rule, &
         [character(len=name_len) :: 'auto', 'mitc9', 'selective', 'stabilized', 'full'])
      call need(deck%stabilization > 0.0_dp .and. deck%stabilization <= 1.0_dp, 'mesh', 'stabilization', &
         real_str(deck%stabilization), 'must be in (0, 1]')
      if (stat == 0 .and. (deck%domain == 'quarter' .or. deck%domain == 'strip')) then
         n = size(deck%angles)
         symmetry_1: do i = 1, n / 2
            if (deck%angles(i) == deck%angles(n + 1 - i)) cycle symmetry_1
            call need(.false., 'laminate', 'angles', list_str(deck%angles), &
               'not symmetric about the mid-plane (ply ' // int_str(i) // ' at ' // real_str(deck%angles(i)) &
               // ' deg, ply ' // int_str(n + 1 - i) // ' at ' // real_str(deck%angles(n + 1 - i)) &
               // " deg), but &mesh domain = '" // trim(deck%domain) // "' assumes B = 0: use domain = 'full'")
            exit symmetry_1
         end do symmetry_1
      end if

      call keyword('boundary', 'edges', deck%edges, &
         [character(len=name_len) :: 'free', 'simply_supported', 'clamped'])
      call keyword('boundary', 'inplane', deck%inplane, [character(len=name_len) :: 'immovable', 'movable'])

      call keyword('analysis', 'kind', deck%analysis_kind, &
         [character(len=name_len) :: 'impact', 'static', 'modes', 'pressure'])
      call keyword('analysis', 'theory', deck%theory, [character(len=name_len) :: 'linear', 'nonlinear', 'auto'])
      if (stat == 0 .and. deck%theory == 'auto') call need(deck%analysis_kind == 'impact', 'analysis', 'theory', &
         "'auto'", "chooses from the impact's deflection estimate: give 'linear' or 'nonlinear' for kind = '" &
         // trim(deck%analysis_kind) // "'")
      call positive('analysis', 'dt', deck%dt, 's')
      call positive('analysis', 't_end', deck%t_end, 's')
      if (stat == 0) call need(deck%dt < deck%t_end, 'analysis', 'dt', real_str(deck%dt), &
         'must be less than t_end = ' // real_str(deck%t_end))
      call need(deck%cr1 > 0.0_dp .and. deck%cr1 < 1.0_dp, 'analysis', 'cr1', real_str(deck%cr1), &
         'must be in (0, 1): a relative tolerance')
      call need(deck%cr1 >= min_cr1, 'analysis', 'cr1', real_str(deck%cr1), &
         'must be at least ' // real_str(min_cr1) // ' (100 eps): eq. (17) cannot be met below the rounding of the force')
      if (stat == 0) call need(deck%t_end / deck%dt < real(huge(1), dp), 'analysis', 'dt', real_str(deck%dt), &
         'gives t_end/dt = ' // real_str(deck%t_end / deck%dt) // ' time steps, more than ' // int_str(huge(1)))
      call need(deck%cr2 > 0.0_dp .and. deck%cr2 < 1.0_dp, 'analysis', 'cr2', real_str(deck%cr2), &
         'must be in (0, 1): a relative tolerance')
      call keyword('analysis', 'scheme', deck%scheme, [character(len=name_len) :: 'paper', 'fast'])
      call keyword('analysis', 'storage', deck%storage, [character(len=name_len) :: 'band', 'skyline'])
      call keyword('analysis', 'force_update', deck%force_update, &
         [character(len=name_len) :: 'bracketed', 'fixed_point'])
      call need(deck%max_contact_iter >= 1, 'analysis', 'max_contact_iter', int_str(deck%max_contact_iter), &
         'must be at least 1')
      call need(deck%max_nonlinear_iter >= 1, 'analysis', 'max_nonlinear_iter', &
         int_str(deck%max_nonlinear_iter), 'must be at least 1')
      if (stat == 0 .and. deck%analysis_kind == 'modes') call need(deck%storage == 'band', 'analysis', &
         'storage', "'" // trim(deck%storage) // "'", "kind = 'modes' needs storage = 'band' " &
         // "(LAPACK's banded eigensolver dsbgvx)")

      call keyword('load', 'kind', deck%load_kind, [character(len=name_len) :: 'uniform', 'sinusoidal', &
         'central_force'])
      call positive('load', 'magnitude', deck%load_magnitude, 'Pa, or N for a central force')
      call need(deck%load_increments >= 1, 'load', 'increments', int_str(deck%load_increments), &
         'must be at least 1')
      call need(deck%mode_count >= 1, 'modes', 'count', int_str(deck%mode_count), 'must be at least 1')

      call need(len_trim(deck%prefix) > 0, 'output', 'prefix', "''", 'must not be empty')
      call need(deck%every >= 1, 'output', 'every', int_str(deck%every), 'must be at least 1')
      call need(deck%fields_every >= 1, 'output', 'fields_every', int_str(deck%fields_every), &
         'must be at least 1 (time steps between field snapshots in <prefix>.h5)')

   contains

      !> Fails with "<file>: &group: name = value: what" unless `ok` (first failure wins).
      subroutine need(ok, group, name, value, what)
         logical, intent(in) :: ok
         character(len=*), intent(in) :: group, name, value, what
         if (stat /= 0 .or. ok) return
         stat = failed
         errmsg = trim(deck%source) // ': &' // group // ': ' // name // ' = ' // value // ': ' // what
      end subroutine need

      !> Requires a finite x > 0.
      subroutine positive(group, name, x, unit)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: x
         character(len=*), intent(in) :: unit
         if (len(unit) > 0) then
            call need(ieee_is_finite(x) .and. x > 0.0_dp, group, name, real_str(x), &
               'must be positive (' // unit // ')')
         else
            call need(ieee_is_finite(x) .and. x > 0.0_dp, group, name, real_str(x), 'must be positive')
         end if
      end subroutine positive

      !> Requires lower < x <= upper.
      subroutine in_range(group, name, x, lower, upper, range)
         character(len=*), intent(in) :: group, name
         real(dp), intent(in) :: x, lower, upper
         character(len=*), intent(in) :: range
         call need(x > lower .and. x <= upper, group, name, real_str(x), 'must be in ' // range)
      end subroutine in_range

      !> Lower-cases `value` and requires it to be one of `allowed`.
      subroutine keyword(group, name, value, allowed)
         character(len=*), intent(in) :: group, name
         character(len=*), intent(inout) :: value
         character(len=*), intent(in) :: allowed(:)
         character(len=:), allocatable :: choices
         integer :: j
         value = to_lower(adjustl(value))
         choices = "'" // trim(allowed(1)) // "'"
         do j = 2, size(allowed)
            choices = choices // ", '" // trim(allowed(j)) // "'"
         end do
         call need(any(allowed == value), group, name, "'" // trim(value) // "'", 'must be one of ' // choices)
      end subroutine keyword

   end subroutine validate_deck

   !> Writes the effective values of `deck`, a few lines per group, each line
   !> starting with `lead` ('# ' in the output files, '' on the terminal), in a
   !> namelist-like form with the unit of each value. The reals are written with
   !> the fewest digits that read back to the same double.
   subroutine echo_deck(deck, unit, lead)
      !> The deck to echo.
      type(deck_t), intent(in) :: deck
      !> Open formatted unit to write to.
      integer, intent(in) :: unit
      !> Text that starts every line.
      character(len=*), intent(in) :: lead

      character(len=:), allocatable :: list
      character(len=group_column) :: blank
      integer :: n, i

      blank = ''
      list = ''
      call put('deck', 'source = ' // "'" // trim(deck%source) // "'")
      call put('&plate', 'a = ' // real_str(deck%a) // ' m, b = ' // real_str(deck%b) // ' m, h = ' &
         // real_str(deck%h) // ' m')
      call put('&lamina', 'e1 = ' // real_str(deck%e1) // ' Pa, e2 = ' // real_str(deck%e2) &
         // ' Pa, g12 = ' // real_str(deck%g12) // ' Pa, g13 = ' // real_str(deck%g13) &
         // ' Pa, g23 = ' // real_str(deck%g23) // ' Pa')
      call put(blank, 'nu12 = ' // real_str(deck%nu12) // ', rho = ' // real_str(deck%rho) // ' kg/m^3')
      n = 0
      if (allocated(deck%angles)) n = size(deck%angles)
      if (n > 0) then
         call put('&laminate', k_str('k4', deck%k4) // ', ' // k_str('k5', deck%k5) // ", bend_twist = '" &
            // trim(deck%bend_twist) // "', " // int_str(n) // ' plies of ' // real_str(deck%h / n) &
            // ' m, angles (deg, bottom to top) =')
      else
         call put('&laminate', k_str('k4', deck%k4) // ', ' // k_str('k5', deck%k5) &
            // ", bend_twist = '" // trim(deck%bend_twist) // "', no plies")
      end if
      angles_1: do i = 1, n
         if (mod(i - 1, angles_per_line) == 0) then
            list = '  ' // real_str(deck%angles(i))
         else
            list = list // ', ' // real_str(deck%angles(i))
         end if
         if (mod(i, angles_per_line) == 0 .or. i == n) then
            if (i < n) list = list // ','
            call put(blank, list)
         end if
      end do angles_1
      call put('&impactor', 'mass = ' // real_str(deck%mass) // ' kg, velocity = ' // real_str(deck%velocity) &
         // ' m/s, diameter = ' // real_str(deck%diameter) // ' m, x0 = ' // real_str(deck%x0) // ' m, y0 = ' &
         // real_str(deck%y0) // ' m')
      call put('&contact', 'k = ' // real_str(deck%k) // ' N/m^1.5, q = ' // real_str(deck%q) &
         // ', alpha_p = ' // real_str(deck%alpha_p) // ' m, beta = ' // real_str(deck%beta) &
         // ", load = '" // trim(deck%contact_load) // "'")
      call put('&mesh', 'nx = ' // int_str(deck%nx) // ', ny = ' // int_str(deck%ny) // ", domain = '" &
         // trim(deck%domain) // "', shear_rule = '" // trim(deck%shear_rule) // "', stabilization = " &
         // real_str(deck%stabilization))
      call put(blank, 'average_bend_twist = ' // trim(merge('.true. ', '.false.', deck%average_bend_twist)) &
         // ', grading = ' // real_str(deck%grading))
      call put('&boundary', "edges = '" // trim(deck%edges) // "', inplane = '" // trim(deck%inplane) // "'")
      call put('&analysis', "kind = '" // trim(deck%analysis_kind) // "', theory = '" // trim(deck%theory) &
         // "', dt = " // real_str(deck%dt) // ' s, t_end = ' // real_str(deck%t_end) // ' s, cr1 = ' &
         // real_str(deck%cr1) // ', cr2 = ' // real_str(deck%cr2))
      call put(blank, "scheme = '" // trim(deck%scheme) // "', storage = '" // trim(deck%storage) &
         // "', max_contact_iter = " // int_str(deck%max_contact_iter) // ', max_nonlinear_iter = ' &
         // int_str(deck%max_nonlinear_iter))
      call put(blank, "force_update = '" // trim(deck%force_update) // "', stop_on_warning = " &
         // trim(merge('.true. ', '.false.', deck%stop_on_warning)))
      call put('&load', "kind = '" // trim(deck%load_kind) // "', magnitude = " // real_str(deck%load_magnitude) &
         // ' ' // trim(merge('N ', 'Pa', deck%load_kind == 'central_force')) // ', increments = ' &
         // int_str(deck%load_increments))
      call put('&modes', 'count = ' // int_str(deck%mode_count) // ', shapes = ' &
         // trim(merge('.true. ', '.false.', deck%mode_shapes)))
      call put('&output', "prefix = '" // trim(deck%prefix) // "', every = " // int_str(deck%every) &
         // ', hdf5 = ' // trim(merge('.true. ', '.false.', deck%hdf5)) // ', fields_every = ' &
         // int_str(deck%fields_every) // ', overwrite = ' // trim(merge('.true. ', '.false.', deck%overwrite)))

   contains

      !> 'name = value', or 'name = (not given: Whitney)' for a shear correction factor.
      function k_str(name, k) result(text)
         character(len=*), intent(in) :: name
         real(dp), intent(in) :: k
         character(len=:), allocatable :: text
         if (k == k_not_given) then
            text = name // ' = (not given: Whitney)'
         else
            text = name // ' = ' // real_str(k)
         end if
      end function k_str

      !> Writes lead, the group name padded to the group column, and the text.
      subroutine put(group, text)
         character(len=*), intent(in) :: group, text
         character(len=group_column) :: column
         column = group
         write (unit, '(a)') lead // column // text
      end subroutine put

   end subroutine echo_deck

   !> `s` with the letters A-Z turned to a-z.
   pure function to_lower(s) result(lower)
      !> Text to convert.
      character(len=*), intent(in) :: s
      character(len=len(s)) :: lower
      integer, parameter :: shift = iachar('a') - iachar('A')
      integer :: i
      lower = s
      do i = 1, len(s)
         if (lge(s(i:i), 'A') .and. lle(s(i:i), 'Z')) lower(i:i) = achar(iachar(s(i:i)) + shift)
      end do
   end function to_lower

   ! ---------------------------------------------------------------------------
   ! One reader per group: locals start from the deck's values (the defaults),
   ! the group is read from the rewound scratch copy, and only a good read is
   ! copied back. After a failed read, the group's assignments are read again one
   ! at a time from strings, and the first that fails names the bad variable.
   ! ---------------------------------------------------------------------------

   !> &plate a, b, h /
   subroutine read_plate(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: a, b, h
      namelist /plate/ a, b, h
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      a = deck%a
      b = deck%b
      h = deck%h
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=plate, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('plate', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=plate, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'plate', 'a, b, h', ios, msg, pieces, bad, stat, errmsg)
         return
      end if
      deck%a = a
      deck%b = b
      deck%h = h
      stat = 0
   end subroutine read_plate

   !> &lamina e1, e2, g12, g13, g23, nu12, rho /
   subroutine read_lamina(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: e1, e2, g12, g13, g23, nu12, rho
      namelist /lamina/ e1, e2, g12, g13, g23, nu12, rho
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      e1 = deck%e1
      e2 = deck%e2
      g12 = deck%g12
      g13 = deck%g13
      g23 = deck%g23
      nu12 = deck%nu12
      rho = deck%rho
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=lamina, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('lamina', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=lamina, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'lamina', 'e1, e2, g12, g13, g23, nu12, rho', ios, msg, pieces, bad, &
            stat, errmsg)
         return
      end if
      deck%e1 = e1
      deck%e2 = e2
      deck%g12 = g12
      deck%g13 = g13
      deck%g23 = g23
      deck%nu12 = nu12
      deck%rho = rho
      stat = 0
   end subroutine read_lamina

   !> &laminate angles, k4, k5 /  The angles buffer starts filled with no_ply;
   !> the plies are its leading set entries, and a gap is an error.
   subroutine read_laminate(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: angles(max_plies), k4, k5
      character(len=name_len) :: bend_twist
      namelist /laminate/ angles, k4, k5, bend_twist
      integer :: ios, n, next, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      angles = no_ply
      k4 = deck%k4
      k5 = deck%k5
      bend_twist = deck%bend_twist
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=laminate, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('laminate', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=laminate, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'laminate', 'angles, k4, k5, bend_twist', ios, msg, pieces, bad, stat, &
            errmsg)
         return
      end if
      n = 0
      do while (n < max_plies)
         if (angles(n + 1) == no_ply) exit
         n = n + 1
      end do
      do next = n + 2, max_plies
         if (angles(next) /= no_ply) then
            stat = failed
            errmsg = trim(deck%source) // ': &laminate: angles(' // int_str(n + 1) // ') is not given but angles(' &
               // int_str(next) // ') is: give every ply from the bottom one up, without gaps'
            return
         end if
      end do
      if (n > 0) deck%angles = angles(:n)
      deck%k4 = k4
      deck%k5 = k5
      deck%bend_twist = bend_twist
      stat = 0
   end subroutine read_laminate

   !> &impactor mass, velocity, diameter, x0, y0 /
   subroutine read_impactor(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: mass, velocity, diameter, x0, y0
      namelist /impactor/ mass, velocity, diameter, x0, y0
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      mass = deck%mass
      velocity = deck%velocity
      diameter = deck%diameter
      x0 = deck%x0
      y0 = deck%y0
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=impactor, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('impactor', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=impactor, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'impactor', 'mass, velocity, diameter, x0, y0', ios, msg, pieces, bad, &
            stat, errmsg)
         return
      end if
      deck%mass = mass
      deck%velocity = velocity
      deck%diameter = diameter
      deck%x0 = x0
      deck%y0 = y0
      stat = 0
   end subroutine read_impactor

   !> &contact k, q, alpha_p, beta, load /
   subroutine read_contact(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      real(dp) :: k, q, alpha_p, beta
      character(len=name_len) :: load
      namelist /contact/ k, q, alpha_p, beta, load
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      load = deck%contact_load
      k = deck%k
      q = deck%q
      alpha_p = deck%alpha_p
      beta = deck%beta
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=contact, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('contact', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=contact, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'contact', 'k, q, alpha_p, beta, load', ios, msg, pieces, bad, stat, errmsg)
         return
      end if
      deck%contact_load = load
      deck%k = k
      deck%q = q
      deck%alpha_p = alpha_p
      deck%beta = beta
      stat = 0
   end subroutine read_contact

   !> &mesh nx, ny, domain, shear_rule, stabilization, average_bend_twist, grading /
   subroutine read_mesh(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: nx, ny
      character(len=name_len) :: domain, shear_rule
      real(dp) :: stabilization, grading
      logical :: average_bend_twist
      namelist /mesh/ nx, ny, domain, shear_rule, stabilization, average_bend_twist, grading
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      nx = deck%nx
      ny = deck%ny
      domain = deck%domain
      shear_rule = deck%shear_rule
      stabilization = deck%stabilization
      average_bend_twist = deck%average_bend_twist
      grading = deck%grading
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=mesh, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('mesh', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=mesh, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'mesh', &
            'nx, ny, domain, shear_rule, stabilization, average_bend_twist, grading', ios, msg, pieces, bad, &
            stat, errmsg)
         return
      end if
      deck%nx = nx
      deck%ny = ny
      deck%domain = domain
      deck%shear_rule = shear_rule
      deck%stabilization = stabilization
      deck%average_bend_twist = average_bend_twist
      deck%grading = grading
      stat = 0
   end subroutine read_mesh

   !> &boundary edges, inplane /
   subroutine read_boundary(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=name_len) :: edges, inplane
      namelist /boundary/ edges, inplane
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      edges = deck%edges
      inplane = deck%inplane
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=boundary, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('boundary', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=boundary, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'boundary', 'edges, inplane', ios, msg, pieces, bad, stat, errmsg)
         return
      end if
      deck%edges = edges
      deck%inplane = inplane
      stat = 0
   end subroutine read_boundary

   !> &analysis kind, theory, dt, t_end, cr1, cr2, scheme, storage, max_contact_iter, max_nonlinear_iter /
   subroutine read_analysis(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=name_len) :: kind, theory, scheme, storage
      real(dp) :: dt, t_end, cr1, cr2
      integer :: max_contact_iter, max_nonlinear_iter
      character(len=name_len) :: force_update
      logical :: stop_on_warning
      namelist /analysis/ kind, theory, dt, t_end, cr1, cr2, scheme, storage, max_contact_iter, &
         max_nonlinear_iter, force_update, stop_on_warning
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      kind = deck%analysis_kind
      theory = deck%theory
      dt = deck%dt
      t_end = deck%t_end
      cr1 = deck%cr1
      cr2 = deck%cr2
      scheme = deck%scheme
      storage = deck%storage
      max_contact_iter = deck%max_contact_iter
      max_nonlinear_iter = deck%max_nonlinear_iter
      force_update = deck%force_update
      stop_on_warning = deck%stop_on_warning
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=analysis, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('analysis', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=analysis, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'analysis', &
            'kind, theory, dt, t_end, cr1, cr2, scheme, storage, max_contact_iter, max_nonlinear_iter, ' &
            // 'force_update, stop_on_warning', ios, msg, pieces, bad, stat, errmsg)
         return
      end if
      deck%analysis_kind = kind
      deck%theory = theory
      deck%dt = dt
      deck%t_end = t_end
      deck%cr1 = cr1
      deck%cr2 = cr2
      deck%scheme = scheme
      deck%storage = storage
      deck%max_contact_iter = max_contact_iter
      deck%max_nonlinear_iter = max_nonlinear_iter
      deck%force_update = force_update
      deck%stop_on_warning = stop_on_warning
      stat = 0
   end subroutine read_analysis

   !> &load kind, magnitude, increments /
   subroutine read_load(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=name_len) :: kind
      real(dp) :: magnitude
      integer :: increments
      namelist /load/ kind, magnitude, increments
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      kind = deck%load_kind
      magnitude = deck%load_magnitude
      increments = deck%load_increments
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=load, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('load', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=load, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'load', 'kind, magnitude, increments', ios, msg, pieces, bad, &
            stat, errmsg)
         return
      end if
      deck%load_kind = kind
      deck%load_magnitude = magnitude
      deck%load_increments = increments
      stat = 0
   end subroutine read_load

   !> &modes count, shapes /
   subroutine read_modes(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      integer :: count
      logical :: shapes
      namelist /modes/ count, shapes
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      count = deck%mode_count
      shapes = deck%mode_shapes
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=modes, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('modes', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=modes, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'modes', 'count, shapes', ios, msg, pieces, bad, stat, errmsg)
         return
      end if
      deck%mode_count = count
      deck%mode_shapes = shapes
      stat = 0
   end subroutine read_modes

   !> &output prefix, every, hdf5, fields_every /
   subroutine read_output(scratch, body, deck, stat, errmsg)
      integer, intent(in) :: scratch
      character(len=*), intent(in) :: body
      type(deck_t), intent(inout) :: deck
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: errmsg
      character(len=path_len) :: prefix
      integer :: every, fields_every
      logical :: hdf5
      logical :: overwrite
      namelist /output/ prefix, every, hdf5, fields_every, overwrite
      integer :: ios, trial, bad
      character(len=msg_len) :: msg
      type(text_t), allocatable :: pieces(:)

      prefix = deck%prefix
      every = deck%every
      hdf5 = deck%hdf5
      fields_every = deck%fields_every
      overwrite = deck%overwrite
      msg = ''
      rewind (scratch, iostat=ios, iomsg=msg)
      if (ios == 0) read (scratch, nml=output, iostat=ios, iomsg=msg)
      if (ios /= 0) then
         call split_assignments('output', body, pieces)
         do bad = 1, size(pieces)
            read (pieces(bad)%s, nml=output, iostat=trial)
            if (trial /= 0) exit
         end do
         call read_failure(deck%source, 'output', 'prefix, every, hdf5, fields_every, overwrite', ios, msg, &
            pieces, bad, stat, errmsg)
         return
      end if
      deck%prefix = prefix
      deck%every = every
      deck%hdf5 = hdf5
      deck%fields_every = fields_every
      deck%overwrite = overwrite
      stat = 0
   end subroutine read_output

   ! ---------------------------------------------------------------------------
   ! Text helpers
   ! ---------------------------------------------------------------------------

   !> Builds the message of a failed group read. The runtime's message names the
   !> item it could not match, which for a value of the wrong type is the value,
   !> not the variable; so the caller has read the group's assignments one at a
   !> time, and `pieces(bad)` is the first that failed (none if bad > size(pieces)).
   subroutine read_failure(source, group, variables, ios, msg, pieces, bad, stat, errmsg)
      !> Name of the deck.
      character(len=*), intent(in) :: source
      !> Group name, without '&'.
      character(len=*), intent(in) :: group
      !> The group's variables, comma separated.
      character(len=*), intent(in) :: variables
      !> iostat and iomsg of the failed read.
      integer, intent(in) :: ios
      character(len=*), intent(in) :: msg
      !> The assignments, each wrapped as a group (see split_assignments).
      type(text_t), intent(in) :: pieces(:)
      !> Index of the first assignment that failed on its own.
      integer, intent(in) :: bad
      !> Set to failed.
      integer, intent(out) :: stat
      !> The message.
      character(len=*), intent(inout) :: errmsg

      character(len=:), allocatable :: head, name, piece
      integer :: cut

      stat = failed
      head = trim(source) // ': namelist &' // group // ': '
      if (ios == iostat_end) then
         errmsg = head // "end of file before the closing '/'"
         return
      end if
      if (bad < 1 .or. bad > size(pieces)) then
         errmsg = head // trim(msg)
         return
      end if
      ! Unwrap '&group assignment /' and drop a trailing comma.
      piece = pieces(bad)%s
      piece = trim(adjustl(piece(len(group) + 2:len(piece) - 1)))
      if (piece(len(piece):) == ',') piece = trim(piece(:len(piece) - 1))
      cut = scan(piece, '(= ')
      if (cut == 0) cut = len(piece) + 1
      name = to_lower(piece(:cut - 1))
      if (index(', ' // variables // ',', ', ' // name // ',') == 0) then
         errmsg = head // trim(msg) // ' (the variables of &' // group // ' are ' // variables // ')'
      else
         if (len(piece) > max_quoted) piece = piece(:max_quoted) // ' ...'
         errmsg = head // 'bad value for ' // name // ': ' // piece // ': ' // trim(msg) &
            // ' (a value of the wrong type, or too many values? text values need quotes)'
      end if
   end subroutine read_failure

   !> Fails when an assignment of the group has no value (`mass = ,`, `angles = /`):
   !> the namelist read takes it as a null value and keeps the default, silently.
   subroutine missing_value(source, group, body, stat, errmsg)
      !> Name of the deck.
      character(len=*), intent(in) :: source
      !> Group name, without '&'.
      character(len=*), intent(in) :: group
      !> The group's text (see scan_groups).
      character(len=*), intent(in) :: body
      !> Set to failed when a value is missing, else unchanged.
      integer, intent(inout) :: stat
      !> The message.
      character(len=*), intent(inout) :: errmsg
      type(text_t), allocatable :: pieces(:)
      character(len=:), allocatable :: piece
      integer :: i, eq

      call split_assignments(group, body, pieces)
      do i = 1, size(pieces)
         ! '&group name = values /': the values are between the '=' and the closing ' /'
         piece = pieces(i)%s
         eq = index(piece, '=')
         if (eq == 0) cycle
         if (verify(piece(eq + 1:len(piece) - 1), ' ,') == 0) then
            stat = failed
            errmsg = trim(source) // ': &' // group // ': ' // trim(adjustl(piece(len(group) + 2:eq - 1))) &
               // ' = (nothing): the value is missing (a variable without a value would keep its default)'
            return
         end if
      end do
   end subroutine missing_value

   !> Reads every line of `unit` up to its end.
   subroutine read_lines(unit, lines, ios, msg)
      integer, intent(in) :: unit
      type(text_t), allocatable, intent(out) :: lines(:)
      !> 0, or the iostat of a read error (the end of the file is not an error).
      integer, intent(out) :: ios
      character(len=*), intent(inout) :: msg
      character(len=chunk_len) :: chunk
      character(len=:), allocatable :: line
      integer :: nread

      allocate (lines(0))
      line = ''
      lines_1: do
         read (unit, '(a)', advance='no', iostat=ios, iomsg=msg, size=nread) chunk
         if (ios == 0) then
            line = line // chunk
         else if (is_iostat_eor(ios)) then
            lines = [lines, text_t(line // chunk(:nread))]
            line = ''
         else if (is_iostat_end(ios)) then
            if (len(line) > 0) lines = [lines, text_t(line)]
            ios = 0
            exit lines_1
         else
            exit lines_1
         end if
      end do lines_1
   end subroutine read_lines

   !> Finds the namelist groups in the deck text the way the runtime does: a
   !> group starts at '&name' (or '$name') and ends at the first '/' (or '&end')
   !> outside a quoted string; '!' outside a string starts a comment. The body of a
   !> group is its text after the name, comments removed, lines joined by blanks.
   !> A group start met inside a group leaves that group unclosed.
   subroutine scan_groups(lines, groups)
      type(text_t), intent(in) :: lines(:)
      type(group_t), allocatable, intent(out) :: groups(:)
      character(len=*), parameter :: blank_quote = ' '
      character :: quote, c
      logical :: inside
      integer :: il, i, from, last, ng

      allocate (groups(0))
      inside = .false.
      quote = blank_quote
      ng = 0
      lines_1: do il = 1, size(lines)
         associate (s => lines(il)%s)
            from = 1
            i = 1
            chars_1: do while (i <= len(s))
               c = s(i:i)
               if (inside .and. quote /= blank_quote) then
                  if (c == quote) quote = blank_quote
               else if (c == '!') then
                  exit chars_1
               else if (inside .and. (c == '''' .or. c == '"')) then
                  quote = c
               else if (inside .and. c == '/') then
                  groups(ng)%body = groups(ng)%body // s(from:i - 1)
                  groups(ng)%closed = .true.
                  inside = .false.
               else if ((c == '&' .or. c == '$') .and. i < len(s)) then
                  last = name_end(s, i + 1)
                  if (last > i) then
                     if (inside) groups(ng)%body = groups(ng)%body // s(from:i - 1)
                     if (inside .and. to_lower(s(i + 1:last)) == 'end') then
                        groups(ng)%closed = .true.
                        inside = .false.
                     else
                        call add_group(groups, to_lower(s(i + 1:last)))
                        ng = ng + 1
                        inside = .true.
                        from = last + 1
                     end if
                     i = last
                  end if
               end if
               i = i + 1
            end do chars_1
            if (inside) groups(ng)%body = groups(ng)%body // s(from:min(i - 1, len(s))) // ' '
         end associate
      end do lines_1
   end subroutine scan_groups

   !> Appends an open group called `name`, with an empty body, to `groups`.
   subroutine add_group(groups, name)
      type(group_t), allocatable, intent(inout) :: groups(:)
      character(len=*), intent(in) :: name
      type(group_t), allocatable :: grown(:)
      integer :: i
      allocate (grown(size(groups) + 1))
      do i = 1, size(groups)
         call move_alloc(groups(i)%name, grown(i)%name)
         call move_alloc(groups(i)%body, grown(i)%body)
         grown(i)%closed = groups(i)%closed
      end do
      grown(size(grown))%name = name
      grown(size(grown))%body = ''
      grown(size(grown))%closed = .false.
      call move_alloc(grown, groups)
   end subroutine add_group

   !> Index of the last character of the name starting at s(first:), or first - 1
   !> if no name starts there (a name is a letter followed by letters, digits, '_').
   pure function name_end(s, first) result(last)
      character(len=*), intent(in) :: s
      integer, intent(in) :: first
      integer :: last
      last = first - 1
      if (first > len(s)) return
      if (.not. is_letter(s(first:first))) return
      last = first
      do while (last < len(s))
         if (.not. (is_letter(s(last + 1:last + 1)) .or. is_digit(s(last + 1:last + 1)) &
            .or. s(last + 1:last + 1) == '_')) exit
         last = last + 1
      end do
   end function name_end

   !> Splits a group body into its assignments 'name = values', each running up to
   !> the name of the next, and wraps each as a group of its own, '&group name =
   !> values /', ready for a namelist read from a string. A name is the identifier
   !> (with an optional subscript) just before an '=' outside quoted strings.
   subroutine split_assignments(group, body, pieces)
      character(len=*), intent(in) :: group
      character(len=*), intent(in) :: body
      type(text_t), allocatable, intent(out) :: pieces(:)
      integer, allocatable :: starts(:)
      character :: quote
      integer :: i, j, n

      allocate (starts(0))
      quote = ' '
      do i = 1, len(body)
         if (quote /= ' ') then
            if (body(i:i) == quote) quote = ' '
         else if (body(i:i) == '''' .or. body(i:i) == '"') then
            quote = body(i:i)
         else if (body(i:i) == '=') then
            j = i - 1
            do while (j >= 1)
               if (body(j:j) /= ' ') exit
               j = j - 1
            end do
            if (j >= 1) then
               if (body(j:j) == ')') j = index(body(:j), '(', back=.true.) - 1
            end if
            do while (j >= 1)
               if (.not. (is_letter(body(j:j)) .or. is_digit(body(j:j)) .or. body(j:j) == '_' &
                  .or. body(j:j) == '%')) exit
               j = j - 1
            end do
            if (j + 1 < i) starts = [starts, j + 1]
         end if
      end do
      n = size(starts)
      allocate (pieces(n))
      do i = 1, n
         if (i < n) then
            pieces(i)%s = '&' // group // ' ' // body(starts(i):starts(i + 1) - 1) // ' /'
         else
            pieces(i)%s = '&' // group // ' ' // body(starts(i):) // ' /'
         end if
      end do
   end subroutine split_assignments

   !> The known groups as '&plate, &lamina, ...'.
   function group_list() result(list)
      character(len=:), allocatable :: list
      integer :: i
      list = '&' // trim(known_groups(1))
      do i = 2, size(known_groups)
         list = list // ', &' // trim(known_groups(i))
      end do
   end function group_list

   pure logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (lge(c, 'a') .and. lle(c, 'z')) .or. (lge(c, 'A') .and. lle(c, 'Z'))
   end function is_letter

   pure logical function is_digit(c)
      character, intent(in) :: c
      is_digit = lge(c, '0') .and. lle(c, '9')
   end function is_digit

   !> The reals of `x` as 'x1, x2, ...', cut short after max_quoted characters.
   function list_str(x) result(s)
      real(dp), intent(in) :: x(:)
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(x)
         if (i > 1) s = s // ', '
         s = s // real_str(x(i))
         if (len(s) > max_quoted .and. i < size(x)) then
            s = s // ', ...'
            exit
         end if
      end do
   end function list_str

   !> An integer without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_str

   !> A real in the fewest significant digits that read back to the same double:
   !> fixed notation for 1e-3 <= |x| < 1e7 ('0.15', '1580.0', '-45.0'), else a
   !> compact exponent ('1.2e11', '2.5e-6').
   function real_str(x) result(s)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      integer, parameter :: max_decimals = 16, min_fixed_exp = -3, max_fixed_exp = 6
      character(len=40) :: buf, fmt
      character(len=:), allocatable :: sign, digits
      real(dp) :: back
      integer :: p, epos, e, ios

      if (ieee_is_nan(x)) then
         s = 'NaN'
         return
      else if (.not. ieee_is_finite(x)) then
         s = 'Infinity'
         if (x < 0.0_dp) s = '-Infinity'
         return
      else if (x == 0.0_dp) then
         s = '0.0'
         return
      end if
      do p = 1, max_decimals
         write (fmt, '(a, i0, a)') '(es40.', p, 'e4)'
         write (buf, fmt) x
         read (buf, *, iostat=ios) back
         if (ios == 0 .and. back == x) exit
      end do
      buf = adjustl(buf)
      sign = ''
      if (buf(1:1) == '-') then
         sign = '-'
         buf = buf(2:)
      end if
      epos = index(buf, 'E')
      read (buf(epos + 1:), *) e
      digits = buf(1:1) // buf(3:epos - 1)          ! mantissa d.ddd without the point
      do while (len(digits) > 1)
         if (digits(len(digits):) /= '0') exit
         digits = digits(:len(digits) - 1)
      end do
      if (e >= 0 .and. e <= max_fixed_exp) then
         if (len(digits) <= e + 1) then
            s = sign // digits // repeat('0', e + 1 - len(digits)) // '.0'
         else
            s = sign // digits(:e + 1) // '.' // digits(e + 2:)
         end if
      else if (e < 0 .and. e >= min_fixed_exp) then
         s = sign // '0.' // repeat('0', -e - 1) // digits
      else if (len(digits) == 1) then
         s = sign // digits // '.0e' // int_str(e)
      else
         s = sign // digits(1:1) // '.' // digits(2:) // 'e' // int_str(e)
      end if
   end function real_str

end module input_deck
