!> The input deck: a namelist file checked against the schema (deck_schema.f90),
!> then as a whole (validate_deck). An absent variable keeps its default; each
!> fault stops the reading with "<deck>: &group: variable = value: what is
!> wrong". More: docs/DECK.md.
module input_deck
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use kinds, only: dp, msg_len
   use number_text, only: real_str, real_short, int_str, list_str
   use system_limits, only: memory_available, memory_room, free_disk_space, file_size_limit, read_only_file_system
   use storage_choice, only: resolve_storage, matrices_memory
   use file_system, only: path_problem, prefix_problem, nearest_directory
   use deck_text, only: item_t, group_text_t, read_deck_text, split_value_text, lower_case, shown_text
   use deck_echo, only: unknown_name, interval, interval_text, deck_value_text
   use deck_schema, only: deck_t, value_t, deck_var_t, deck_vars, deck_groups, deck_bind, find_var, &
      strength_given, is_given, words_of, words_quoted, strength_names, toughness_names, &
      kind_real, kind_integer, kind_logical, kind_word, kind_path, kind_reals, &
      max_word_len, max_path_len, max_list_len
   implicit none
   private
   public :: deck_t, default_deck, read_deck, read_deck_file, validate_deck, set_variable, model_size

   !> Status returned on any failure.
   integer, parameter :: failed = 1
   !> Longest value text quoted in a message before it is cut short.
   integer, parameter :: max_quoted = 60
   !> Smallest contact-force tolerance C_r1: 100 eps, the rounding of the force.
   real(dp), parameter :: min_cr1 = 100.0_dp*epsilon(1.0_dp)
   !> Bytes in a MiB, a GiB.
   real(dp), parameter :: mib = 1024.0_dp**2, gib = 1024.0_dp**3
   !> What a run takes beside its matrices, for the check against ulimit -v:
   !> a tenth more for the model, and the libraries' (OpenBLAS's) buffers.
   real(dp), parameter :: model_share = 1.1_dp, library_bytes = 160.0_dp*mib

   !> The checks of a deck so far: the first failure wins.
   type :: checks_t
      integer :: stat = 0                           !< 0, or failed after a failure
      character(len=:), allocatable :: message      !< the first failure's one-line message
   end type checks_t

contains

   !> The deck of the schema's defaults (the paper's values), source '<defaults>'.
   function default_deck() result(deck)
      type(deck_t) :: deck
      type(value_t) :: v
      type(item_t), allocatable :: items(:)
      character(len=:), allocatable :: what
      integer :: iv, stat
      deck%source = '<defaults>'
      deck%settings = ''
      do iv = 1, size(deck_vars)
         if (len_trim(deck_vars(iv)%default) == 0) then
            v = value_t(given=.false.)
         else
            call split_value_text(trim(deck_vars(iv)%default), items, stat, what)
            if (stat == 0) call convert(iv, items, v, stat, what)
            if (stat /= 0) cycle     ! never: a test reads every default (tests/test_input_deck.pf)
         end if
         call deck_bind(deck, iv, v, .true.)
      end do
   end function default_deck

   !> Reads a deck from `unit` (read once to its end) and checks it unless
   !> check = .false.; on failure stat /= 0 and errmsg the module header's message.
   subroutine read_deck(unit, source, deck, stat, errmsg, check)
      integer, intent(in) :: unit                   !< unit to read from
      character(len=*), intent(in) :: source        !< the deck's name in messages: its path, or '<stdin>'
      type(deck_t), intent(out) :: deck             !< defaults overridden by the deck
      integer, intent(out) :: stat                  !< 0 when the deck was read and is valid
      character(len=*), intent(inout) :: errmsg     !< the message on failure
      logical, intent(in), optional :: check        !< check the deck (default .true.)
      type(group_text_t), allocatable :: groups(:)
      character(len=:), allocatable :: what
      integer :: line, ig
      deck = default_deck()
      deck%source = source
      call read_deck_text(unit, groups, stat, line, what)
      if (stat /= 0 .and. line > 0) what = 'line ' // int_str(line) // ': ' // what
      if (stat == 0 .and. size(groups) == 0) what = 'the deck has no namelist group: an empty deck would run ' &
         // 'the default scene (give at least one group, e.g. &analysis kind = ''impact'' /)'
      do ig = 1, size(groups)
         if (len(what) == 0) call read_group(groups, ig, deck, what)
      end do
      stat = merge(failed, 0, len(what) > 0)
      if (stat /= 0) errmsg = source // ': ' // what
      if (stat /= 0) return
      if (present(check)) then
         if (.not. check) return
      end if
      call validate_deck(deck, stat, errmsg)
   end subroutine read_deck

   !> Group ig of the deck's text into the deck; what is '' or its first fault.
   subroutine read_group(groups, ig, deck, what)
      type(group_text_t), intent(in) :: groups(:)            !< the deck's groups
      integer, intent(in) :: ig                              !< the group to read
      type(deck_t), intent(inout) :: deck                    !< the deck
      character(len=:), allocatable, intent(inout) :: what   !< '' or what is wrong
      type(value_t) :: v
      integer :: jg, ia, ja, iv, stat
      associate (g => groups(ig))
         if (.not. any(deck_groups == g%name)) what = unknown_name(g%name, '')
         do jg = 1, ig - 1
            if (groups(jg)%name == g%name .and. len(what) == 0) what = '&' // g%name // ': the group is given ' &
               // 'twice (lines ' // int_str(groups(jg)%line) // ' and ' // int_str(g%line) // '); give each group once'
         end do
         do ia = 1, size(g%assignments)
            if (len(what) > 0) return
            associate (a => g%assignments(ia))
               iv = find_var(g%name, a%name)
               if (iv == 0) what = unknown_name(g%name, a%name)
               do ja = 1, ia - 1
                  if (g%assignments(ja)%name == a%name .and. len(what) == 0) what = '&' // g%name // ': ' &
                     // a%name // ' = ' // items_text(a%items) // ': given twice in the group (lines ' &
                     // int_str(g%assignments(ja)%line) // ' and ' // int_str(a%line) // '); give each variable once'
               end do
               if (len(what) > 0) return
               call convert(iv, a%items, v, stat, what)
               if (stat /= 0) what = '&' // g%name // ': ' // a%name // ' = ' // items_text(a%items) // ': ' // what
               if (stat /= 0) return
               call deck_bind(deck, iv, v, .true.)
               deck%given(iv) = .true.
            end associate
         end do
      end associate
   end subroutine read_group

   !> read_deck of the file `path`; a directory or an unreadable file is refused.
   subroutine read_deck_file(path, deck, stat, errmsg, check)
      character(len=*), intent(in) :: path          !< the deck's path
      type(deck_t), intent(out) :: deck             !< the deck read
      integer, intent(out) :: stat                  !< 0 when the deck was read and is valid
      character(len=*), intent(inout) :: errmsg     !< the message on failure
      logical, intent(in), optional :: check        !< check the deck (default .true.)
      integer :: unit, ios
      character(len=msg_len) :: msg
      logical :: exists
      stat = failed
      inquire (file=path // '/.', exist=exists)
      if (exists) errmsg = path // ': is a directory, not a deck file'
      if (exists) return
      open (newunit=unit, file=path, status='old', action='read', form='formatted', &
         access='sequential', iostat=ios, iomsg=msg)
      if (ios /= 0) errmsg = path // ': cannot open the deck: ' // trim(msg)
      if (ios /= 0) return
      call read_deck(unit, path, deck, stat, errmsg, check)
      close (unit, iostat=ios)
   end subroutine read_deck_file

   !> `impact --set group.var=value`: one variable from its text, then the deck
   !> checked unless check = .false.
   subroutine set_variable(deck, setting, stat, errmsg, check)
      type(deck_t), intent(inout) :: deck           !< the deck, changed
      character(len=*), intent(in) :: setting       !< 'group.var=value'
      integer, intent(out) :: stat                  !< 0 when the setting and the deck are valid
      character(len=*), intent(inout) :: errmsg     !< the message on failure
      logical, intent(in), optional :: check        !< check the deck (default .true.)
      character(len=:), allocatable :: what, key, group, name, text
      type(item_t), allocatable :: items(:)
      integer :: eq, dot, iv
      type(value_t) :: v
      stat = failed
      eq = index(setting, '=')
      key = lower_case(adjustl(setting(:max(eq - 1, 0))))
      dot = index(key, '.')
      if (eq == 0 .or. dot < 2) then
         errmsg = '--set ' // setting // ': give group.variable=value (e.g. --set analysis.dt=1e-6)'
         return
      end if
      group = trim(key(:dot - 1));  name = trim(key(dot + 1:))
      text = trim(adjustl(setting(eq + 1:)))
      iv = find_var(group, name)
      if (iv == 0) then
         what = unknown_name(group, name)
      else if (len(text) == 0) then
         what = '&' // group // ': ' // name // ' = (nothing): give a value'
      else
         call split_value_text(text, items, stat, what)
         if (stat == 0) call convert(iv, items, v, stat, what)
         if (stat /= 0) what = '&' // group // ': ' // name // ' = ' // shown_text(text) // ': ' // what
      end if
      if (len(what) > 0) then
         errmsg = '--set: ' // what
         return
      end if
      call deck_bind(deck, iv, v, .true.)
      deck%given(iv) = .true.
      ! -- recorded as a command line would give it (the echo, /deck settings)
      if (.not. allocated(deck%settings)) deck%settings = ''
      if (len(deck%settings) > 0) deck%settings = deck%settings // ' '
      what = text
      if (index(text, ' ') > 0 .and. index('''"', text(1:1)) == 0) what = "'" // text // "'"
      deck%settings = deck%settings // '--set ' // group // '.' // name // '=' // what
      stat = 0
      if (present(check)) then
         if (.not. check) return
      end if
      call validate_deck(deck, stat, errmsg)
      if (stat /= 0) errmsg = '--set ' // group // '.' // name // '=' // shown_text(text) // ': ' // trim(errmsg)
   end subroutine set_variable

   !> The value of entry iv from its items, checked for its kind (not its range):
   !> a real finite (NaN is "not given"), an integer in +-huge(0).
   subroutine convert(iv, items, v, stat, what)
      integer, intent(in) :: iv                          !< entry of deck_vars
      type(item_t), intent(in) :: items(:)               !< the values as written
      type(value_t), intent(out) :: v                    !< the value
      integer, intent(out) :: stat                       !< 0, or failed
      character(len=:), allocatable, intent(out) :: what !< what is wrong
      integer(int64) :: count
      integer :: kind, k, n
      what = ''
      kind = deck_vars(iv)%kind
      count = sum(int(items%repeat, int64))
      if (kind /= kind_reals .and. count /= 1) then
         what = 'one value expected, ' // int_str(int(min(count, int(huge(n), int64)))) // ' given'
         if (any(items%counted)) what = what // ' (a repeat count r*c gives r values)'
      else if (kind == kind_reals .and. count > max_list_len) then
         what = 'more than ' // int_str(max_list_len) // ' values'
      else if (kind /= kind_reals) then
         call convert_item(iv, kind, items(1), v, what)
      else                                   ! a list: each r*c expanded to r copies of c
         allocate (v%list(count))
         n = 0
         do k = 1, size(items)
            call convert_item(iv, kind_real, items(k), v, what)
            if (len(what) > 0) then
               what = 'item ' // int_str(k) // ', ''' // shown_text(item_written(items(k))) // ''': ' // what
               exit
            end if
            v%list(n + 1:n + items(k)%repeat) = v%r
            n = n + items(k)%repeat
         end do
      end if
      stat = merge(failed, 0, len(what) > 0)
   end subroutine convert

   !> One value of entry iv, of the kind given, from its item: v%r (finite),
   !> v%i, v%l or v%s (a word in lower case); what is '' or what is wrong.
   subroutine convert_item(iv, kind, item, v, what)
      integer, intent(in) :: iv                          !< entry of deck_vars
      integer, intent(in) :: kind                        !< kind_real, ... (not kind_reals)
      type(item_t), intent(in) :: item                   !< the value as written
      type(value_t), intent(inout) :: v                  !< the value
      character(len=:), allocatable, intent(inout) :: what !< '' or what is wrong
      character(len=:), allocatable :: unit
      logical :: digits
      integer :: ios, j, k
      unit = trim(deck_vars(iv)%unit)
      select case (kind)
      case (kind_real, kind_integer)
         if (item%quoted) then
            what = 'a number, not a quoted string, expected'
         else if (kind == kind_real) then
            read (item%text, *, iostat=ios) v%r
            digits = verify(item%text, '+-.0123456789eEdD') == 0
            if (ios == 0 .and. digits .and. ieee_is_finite(v%r)) return
            what = 'must be a real number'
            if (unit /= '-' .and. len(unit) > 0) what = what // ' (' // unit // ')'
            if (ios == 0 .and. digits) then
               what = what // ' within the range of a double (magnitude below 1.8e308)'
            else if (ios == 0 .and. .not. ieee_is_finite(v%r)) then
               what = what // ': NaN and Inf are not values'
               if (len_trim(deck_vars(iv)%default) == 0) what = what // ' (leave the variable out for "not given")'
            end if
         else
            read (item%text, *, iostat=ios) v%i
            if (ios /= 0 .or. verify(trim(adjustl(item%text)), '+-0123456789') /= 0 .or. v%i < -huge(v%i)) &
               what = 'must be a whole number (from ' // int_str(-huge(v%i)) // ' to ' // int_str(huge(v%i)) // ')'
         end if
      case (kind_logical)
         read (item%text, *, iostat=ios) v%l
         if (ios /= 0 .or. item%quoted .or. index(item%text, '/') > 0) what = 'must be .true. or .false.'
      case (kind_word, kind_path)
         v%s = trim(adjustl(item%text))
         if (kind == kind_word) v%s = lower_case(v%s)
         k = findloc([(iachar(v%s(j:j)) < 32 .or. iachar(v%s(j:j)) == 127, j = 1, len(v%s))], .true., dim=1)
         if (kind == kind_word .and. len(v%s) > max_word_len) then
            what = 'longer than ' // int_str(max_word_len) // ' characters'
         else if (len(v%s) > max_path_len) then
            what = 'longer than ' // int_str(max_path_len) // ' characters'
         else if (k > 0) then
            what = 'holds a control character (code ' // int_str(iachar(v%s(k:k))) // ')'
         end if
      end select
   end subroutine convert_item

   !> Checks every value against its range and the combinations the program
   !> needs, to the first bad one; keywords come back in lower case.
   subroutine validate_deck(deck, stat, errmsg)
      type(deck_t), intent(inout) :: deck           !< the deck; its keywords come back in lower case
      integer, intent(out) :: stat                  !< 0 when every value is acceptable
      character(len=*), intent(inout) :: errmsg     !< the message on failure
      type(checks_t) :: c
      type(value_t) :: v
      integer :: iv
      if (.not. allocated(deck%source)) deck%source = '<deck>'
      do iv = 1, size(deck_vars)           ! each variable against its range, keywords in lower case
         call deck_bind(deck, iv, v, .false.)
         if (deck_vars(iv)%kind == kind_word) then
            v%s = lower_case(trim(adjustl(v%s)))
            call deck_bind(deck, iv, v, .true.)
         end if
         call check_range(c, deck, iv, v)
         if (c%stat /= 0) exit
      end do
      if (c%stat == 0) call check_plate(deck, c)
      if (c%stat == 0) call check_domain(deck, c)
      if (c%stat == 0) call check_analysis(deck, c)
      if (c%stat == 0) call check_prefix(deck, c)
      if (c%stat == 0) call check_strength(deck, c)
      stat = c%stat
      if (stat /= 0) errmsg = c%message
   end subroutine validate_deck

   !> &plate, &lamina, &laminate, &impactor, &output gauge_x, gauge_y: a thin
   !> plate, a positive definite lamina, a ply, the nose and the gauge on the plate.
   subroutine check_plate(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      call need(c, deck, deck%h < min(deck%a, deck%b), 'plate', 'h', 'the thickness must be smaller than a and b')
      call need(c, deck, deck%nu12**2 < deck%e1/deck%e2, 'lamina', 'nu12', 'nu12**2 must be less than e1/e2 = ' &
         // real_str(deck%e1/deck%e2) // ' (else the lamina stiffness is not positive definite)')
      call need(c, deck, size(deck%angles) >= 1, 'laminate', 'angles', 'give at least one ply', '(none)')
      call need(c, deck, deck%diameter < min(deck%a, deck%b), 'impactor', 'diameter', &
         'the nose must be smaller than the plate: diameter < min(a, b) = ' // real_str(min(deck%a, deck%b)) // ' m')
      call need(c, deck, abs(deck%x0) <= 0.5_dp*(deck%a - deck%diameter), 'impactor', 'x0', &
         'the nose must lie on the plate: |x0| <= (a - diameter)/2 = ' // real_str(0.5_dp*(deck%a - deck%diameter)) &
         // ' m (x0 is measured from the plate centre)')
      call need(c, deck, abs(deck%y0) <= 0.5_dp*(deck%b - deck%diameter), 'impactor', 'y0', &
         'the nose must lie on the plate: |y0| <= (b - diameter)/2 = ' // real_str(0.5_dp*(deck%b - deck%diameter)) &
         // ' m (y0 is measured from the plate centre)')
      if (is_given(deck, 'output', 'gauge_x')) call need(c, deck, abs(deck%gauge_x) <= 0.5_dp*deck%a, 'output', &
         'gauge_x', 'the gauge must lie on the plate: |gauge_x| <= a/2 = ' // real_str(0.5_dp*deck%a) &
         // ' m (gauge_x is measured from the plate centre)')
      if (is_given(deck, 'output', 'gauge_y')) call need(c, deck, abs(deck%gauge_y) <= 0.5_dp*deck%b, 'output', &
         'gauge_y', 'the gauge must lie on the plate: |gauge_y| <= b/2 = ' // real_str(0.5_dp*deck%b) &
         // ' m (gauge_y is measured from the plate centre)')
   end subroutine check_plate

   !> &output prefix: a name for the result files, on a writable file system.
   subroutine check_prefix(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      character(len=:), allocatable :: why
      why = prefix_problem(deck%prefix)
      call need(c, deck, len(why) == 0, 'output', 'prefix', why, "'" // shown_text(deck%prefix) // "'")
      if (c%stat /= 0) return
      call need(c, deck, .not. read_only_file_system(deck%prefix), 'output', 'prefix', 'is on a read-only ' &
         // 'file system (' // shown_text(nearest_directory(deck%prefix)) // ' is mounted read-only): ' &
         // 'choose a prefix where the results can be written', "'" // shown_text(deck%prefix) // "'")
   end subroutine check_prefix

   !> &mesh domain: D16 = D26 = 0 and the impact point on its symmetry lines,
   !> a symmetric layup for a quarter or a strip.
   subroutine check_domain(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      integer :: n, i
      if (deck%domain /= 'full' .and. deck%domain /= 'auto') &
         call need(c, deck, deck%bend_twist /= 'keep', 'laminate', 'bend_twist', "the symmetry lines of " &
         // "&mesh domain = '" // deck%domain // "' need D16 = D26 = 0 (section 3.1): use domain = 'full'")
      if (deck%average_bend_twist) call need(c, deck, deck%bend_twist /= 'keep', 'laminate', 'bend_twist', &
         'contradicts &mesh average_bend_twist = .true., which accepts D16 = D26 = 0')
      if (deck%domain == 'quarter' .or. deck%domain == 'strip') &
         call need(c, deck, deck%x0 == 0.0_dp .and. deck%y0 == 0.0_dp, 'mesh', 'domain', &
         'needs the impact point at the centre, but &impactor x0 = ' // real_str(deck%x0) // ' m, y0 = ' &
         // real_str(deck%y0) // " m: use domain = 'auto', 'half' or 'full'")
      if (deck%domain == 'half') call need(c, deck, deck%x0 == 0.0_dp .or. deck%y0 == 0.0_dp, 'mesh', 'domain', &
         'needs the impact point on a centre line (x0 = 0 or y0 = 0), but &impactor x0 = ' &
         // real_str(deck%x0) // ' m, y0 = ' // real_str(deck%y0) // " m: use domain = 'auto' or 'full'")
      if (c%stat /= 0 .or. .not. (deck%domain == 'quarter' .or. deck%domain == 'strip')) return
      n = size(deck%angles)
      i = findloc([(deck%angles(i) == deck%angles(n + 1 - i), i = 1, n/2)], .false., dim=1)
      if (i > 0) call need(c, deck, .false., 'laminate', 'angles', 'not symmetric about the mid-plane (ply ' &
         // int_str(i) // ' at ' // real_str(deck%angles(i)) // ' deg, ply ' // int_str(n + 1 - i) // ' at ' &
         // real_str(deck%angles(n + 1 - i)) // " deg), but &mesh domain = '" // deck%domain &
         // "' assumes B = 0: use domain = 'full'", list_str(deck%angles, max_quoted))
   end subroutine check_domain

   !> &analysis: theory, dt, cr1, what the run needs, the storage of modes.
   subroutine check_analysis(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      if (deck%theory == 'auto') call need(c, deck, deck%analysis_kind == 'impact', 'analysis', 'theory', &
         "chooses from the impact's deflection estimate: give 'linear' or 'nonlinear' for kind = '" &
         // deck%analysis_kind // "'")
      if (is_given(deck, 'analysis', 'dt')) call need(c, deck, deck%dt < deck%t_end, 'analysis', 'dt', &
         'must be less than t_end = ' // real_str(deck%t_end))
      call need(c, deck, deck%cr1 >= min_cr1, 'analysis', 'cr1', 'must be at least ' // real_str(min_cr1) &
         // ' (100 eps): eq. (17) cannot be met below the rounding of the force')
      if (c%stat == 0) call check_needs(deck, c)
      if (deck%analysis_kind == 'modes') call need(c, deck, deck%storage == 'band' .or. deck%storage == 'auto', &
         'analysis', 'storage', "kind = 'modes' needs storage = 'band' or 'auto' (LAPACK's banded " &
         // "eigensolver dsbgvx)")
   end subroutine check_analysis

   !> What the run would need, before any of it is allocated: at most max_steps
   !> steps, its memory and its files within the machine's (docs/ROBUSTNESS.md).
   subroutine check_needs(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      real(dp), parameter :: max_steps = 1.0e8_dp, text_row_bytes = 230.0_dp, row_bytes = 360.0_dp, &
                             h5_fixed_bytes = 65536.0_dp
      real(dp) :: steps, rows, neq, memory, machine, output, room, biggest
      ! dt, nx, ny not given: checked once chosen from the scene (src/model/scene_settings.f90)
      if (.not. (is_given(deck, 'analysis', 'dt') .and. is_given(deck, 'mesh', 'nx') &
                 .and. is_given(deck, 'mesh', 'ny'))) return
      steps = deck%t_end/deck%dt
      call need(c, deck, steps <= max_steps, 'analysis', 'dt', 'gives t_end/dt = ' // real_short(steps) &
         // ' time steps, more than the limit of ' // real_short(max_steps) // ' (a longer dt, or a shorter t_end)')
      if (c%stat /= 0) return
      call model_size(deck, neq, memory)
      machine = memory_available()
      if (machine > 0.0_dp) call need(c, deck, memory < machine, 'mesh', 'nx', 'with ny = ' // int_str(deck%ny) &
         // ' the model would need about ' // real_short(memory/gib) // ' GiB of memory (' // real_short(neq) &
         // ' equations), more than the ' // real_short(machine/gib) // ' GiB free for it on this machine ' &
         // '(MemAvailable, its control group''s limit): a coarser mesh, or a graded one (&mesh grading)')
      room = memory_room()
      if (room >= 0.0_dp) call need(c, deck, model_share*memory + library_bytes < room, 'mesh', 'nx', &
         'with ny = ' // int_str(deck%ny) // ' the model would need about ' &
         // real_short((model_share*memory + library_bytes)/mib) // ' MiB of memory (' // real_short(neq) &
         // ' equations), more than the ' // real_short(room/mib) // ' MiB this process may still take ' &
         // '(its limit, ulimit -v or -d): a coarser mesh, or a higher limit')
      if (c%stat /= 0 .or. deck%analysis_kind == 'modes' .or. deck%analysis_kind == 'static') return
      rows = steps/real(deck%every, dp) + 1.0_dp
      output = rows*row_bytes
      if (deck%hdf5 .and. deck%analysis_kind == 'impact') output = output + h5_fixed_bytes &
         + (steps/real(deck%fields_every, dp) + 5.0_dp)*neq*8.0_dp
      biggest = max(output - rows*text_row_bytes, rows*text_row_bytes)
      room = file_size_limit()
      if (room > 0.0_dp) call need(c, deck, biggest < room, 'output', 'every', 'with fields_every = ' &
         // int_str(deck%fields_every) // ' a result file would reach about ' // real_short(biggest/mib) &
         // ' MiB, more than the ' // real_short(room/mib) // ' MiB this process may write to one file ' &
         // '(ulimit -f): write fewer rows (a larger every, fields_every) or set hdf5 = .false.')
      room = free_disk_space(deck%prefix)
      if (room > 0.0_dp) call need(c, deck, output < room, 'output', 'every', 'with fields_every = ' &
         // int_str(deck%fields_every) // ' the results would take about ' // real_short(output/gib) &
         // ' GiB, more than the ' // real_short(room/gib) // ' GiB free where they go (prefix ''' &
         // deck%prefix // '''): write fewer rows (a larger every, fields_every) or set hdf5 = .false.')
   end subroutine check_needs

   !> The model of the deck's mesh: (2 ex + 1)(2 ey + 1) nodes of 5 freedoms,
   !> half-bandwidth 10 (2 min(ex, ey) + 1), the matrices in their storage.
   pure subroutine model_size(deck, neq, memory)
      type(deck_t), intent(in) :: deck              !< the deck, nx and ny given or chosen
      real(dp), intent(out) :: neq                  !< the equations
      real(dp), intent(out) :: memory               !< the matrices' memory (bytes)
      real(dp) :: ex, ey, kd
      ex = real(deck%nx, dp);  ey = real(deck%ny, dp)
      if (deck%domain == 'auto' .or. deck%domain == 'half') then
         ex = 2.0_dp*ex;  ey = 2.0_dp*ey
      end if
      neq = 5.0_dp*(2.0_dp*ex + 1.0_dp)*(2.0_dp*ey + 1.0_dp)
      kd = 10.0_dp*(2.0_dp*min(ex, ey) + 1.0_dp)
      memory = matrices_memory(resolve_storage(deck%storage, nint(min(neq, 1.0e9_dp)), deck%analysis_kind == 'modes'), &
                               neq, kd)
   end subroutine model_size

   !> &strength: all six strengths or none, the criterion and the ply fracture
   !> energies only with them, all of it for the impact analysis only.
   subroutine check_strength(deck, c)
      type(deck_t), intent(in) :: deck              !< the deck
      type(checks_t), intent(inout) :: c            !< the checks so far
      logical :: missing(6)
      integer :: k
      do k = 1, size(toughness_names)
         if (.not. is_given(deck, 'strength', trim(toughness_names(k)))) cycle
         call need(c, deck, k <= 2 .or. strength_given(deck), 'strength', trim(toughness_names(k)), &
            'a ply fracture energy needs the six ply strengths xt, xc, yt, yc, s12, s23')
         call need(c, deck, deck%analysis_kind == 'impact', 'strength', trim(toughness_names(k)), &
            "the fracture toughnesses are used by kind = 'impact' only")
      end do
      missing = [(.not. is_given(deck, 'strength', trim(strength_names(k))), k = 1, size(strength_names))]
      k = findloc(missing, .true., dim=1)
      if (any(missing) .and. .not. all(missing)) call need(c, deck, .false., 'strength', trim(strength_names(k)), &
         'give all six strengths (xt, xc, yt, yc, s12, s23) or none')
      if (deck%given(find_var('strength', 'criterion'))) call need(c, deck, .not. all(missing), 'strength', &
         'criterion', 'needs the ply strengths xt, xc, yt, yc, s12, s23 (the paper gives none)')
      if (strength_given(deck)) call need(c, deck, deck%analysis_kind == 'impact', 'strength', 'xt', &
         "the ply stresses and failure indices are computed by kind = 'impact' only")
   end subroutine check_strength

   !> Entry iv's value against the schema's range.
   subroutine check_range(c, deck, iv, v)
      type(checks_t), intent(inout) :: c            !< the checks so far
      type(deck_t), intent(in) :: deck              !< the deck, entry iv's value v
      integer, intent(in) :: iv                     !< entry of deck_vars
      type(value_t), intent(in) :: v                !< its value
      type(deck_var_t) :: e
      integer :: j, k
      e = deck_vars(iv)      ! (a copy: gfortran 12 loses an associate name of a constant's element)
      select case (e%kind)
      case (kind_real, kind_integer)
         if (v%given) call need(c, deck, in_interval(merge(v%r, real(v%i, dp), e%kind == kind_real), e%range), &
            trim(e%group), trim(e%name), interval_text(e%range, e%unit))
      case (kind_reals)
         if (len_trim(e%range) == 0) return
         k = findloc([(in_interval(v%list(j), e%range), j = 1, size(v%list))], .false., dim=1)
         if (k > 0) call need(c, deck, .false., trim(e%group), trim(e%name) // '(' // int_str(k) // ')', &
            interval_text(e%range, e%unit), real_str(v%list(k)))
      case (kind_word)
         call need(c, deck, index(' ' // words_of(e%range) // ' ', ' ' // v%s // ' ') > 0 .and. len(v%s) > 0, &
            trim(e%group), trim(e%name), 'must be one of ' // words_quoted(e%range))
      case (kind_path)
         call need(c, deck, len(v%s) <= max_path_len, trim(e%group), trim(e%name), &
            'longer than ' // int_str(max_path_len) // ' characters', shown_text(v%s))
         if (len(v%s) > 0) call need(c, deck, len(path_problem(v%s)) == 0, trim(e%group), trim(e%name), &
            path_problem(v%s), shown_text(v%s))
      end select
   end subroutine check_range

   !> Fails with "<deck>: &group: name = value: what" unless ok (the first
   !> failure wins); the value as the echo shows it unless given.
   subroutine need(c, deck, ok, group, name, what, value)
      type(checks_t), intent(inout) :: c            !< the checks so far
      type(deck_t), intent(in) :: deck              !< the deck
      logical, intent(in) :: ok                     !< the check passes
      character(len=*), intent(in) :: group         !< the group, without '&'
      character(len=*), intent(in) :: name          !< the variable
      character(len=*), intent(in) :: what          !< what is wrong
      character(len=*), intent(in), optional :: value   !< its value, as a message shows it
      if (c%stat /= 0 .or. ok) return
      c%stat = failed
      if (present(value)) then
         c%message = deck%source // ': &' // group // ': ' // name // ' = ' // value // ': ' // what
      else
         c%message = deck%source // ': &' // group // ': ' // name // ' = ' &
            // deck_value_text(deck, find_var(group, name)) // ': ' // what
      end if
   end subroutine need

   !> x is finite and in the interval written as '(lo, hi)', '[lo, hi]', ...
   pure logical function in_interval(x, range)
      real(dp), intent(in) :: x
      character(len=*), intent(in) :: range
      real(dp) :: lo, hi
      logical :: lo_open, hi_open
      call interval(range, lo, hi, lo_open, hi_open)
      in_interval = ieee_is_finite(x) .and. merge(x > lo, x >= lo, lo_open) .and. merge(x < hi, x <= hi, hi_open)
   end function in_interval

   !> The items as they were written, for a message, cut after max_quoted characters.
   function items_text(items) result(text)
      type(item_t), intent(in) :: items(:)
      character(len=:), allocatable :: text
      integer :: k
      text = ''
      do k = 1, size(items)
         if (k > 1) text = text // ', '
         text = text // item_written(items(k))
         if (len(text) > max_quoted) exit
      end do
      text = shown_text(text)
   end function items_text

   !> An item as it was written: r*c, a string in quotes.
   function item_written(item) result(text)
      type(item_t), intent(in) :: item
      character(len=:), allocatable :: text
      text = item%text(:min(len(item%text), max_quoted + 1))
      if (item%quoted) text = "'" // text // "'"
      if (item%counted) text = int_str(item%repeat) // '*' // text
   end function item_written

end module input_deck
