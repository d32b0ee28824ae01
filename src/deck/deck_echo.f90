!> The deck as people read it, from the schema (deck_schema.f90): the echo of
!> a run's values (terminal, result files, /deck of <prefix>.h5), the table of
!> docs/DECK.md (impact --deck-table), the tab-separated schema (impact
!> --schema) and the schema in the words of input_deck's messages.
module deck_echo
   use kinds, only: dp
   use number_text, only: real_str, int_str, list_str
   use deck_schema, only: deck_t, value_t, deck_var_t, deck_vars, deck_groups, deck_bind, strength_given, accuracy_wanted, &
      toughness_given, words_quoted, kind_real, kind_integer, kind_logical, kind_word, kind_path, kind_reals, kind_names
   implicit none
   private
   public :: echo_deck, write_deck_table, write_schema, deck_value_text
   public :: unknown_name, interval, interval_text

   !> Width of the echo's lines (the group column included), and of its group column.
   integer, parameter :: echo_width = 100, group_column = 11

contains

   !> True when the echo shows the group: &strength with its strengths or a
   !> toughness, &damage with the strengths, &accuracy for an accuracy run,
   !> &contact, &load and &modes for the analyses that use them.
   pure logical function group_applies(group, deck)
      character(len=*), intent(in) :: group         !< the group, without '&'
      type(deck_t), intent(in) :: deck              !< the deck
      select case (trim(group))
      case ('strength'); group_applies = strength_given(deck) .or. toughness_given(deck)
      case ('damage');   group_applies = strength_given(deck)
      case ('accuracy'); group_applies = accuracy_wanted(deck)
      case ('contact');  group_applies = deck%analysis_kind == 'impact'
      case ('load');     group_applies = deck%analysis_kind == 'static' .or. deck%analysis_kind == 'pressure'
      case ('modes');    group_applies = deck%analysis_kind == 'modes'
      case default;      group_applies = .true.
      end select
   end function group_applies

   !> Entry iv's value as a deck gives it ('0.15', "'clamped'", '.true.'), or
   !> '(not given)'; reals with the fewest digits that read back the same double.
   function deck_value_text(deck, iv) result(text)
      type(deck_t), intent(in) :: deck              !< the deck
      integer, intent(in) :: iv                     !< entry of deck_vars
      character(len=:), allocatable :: text
      type(deck_t) :: copy
      type(value_t) :: v
      copy = deck
      call deck_bind(copy, iv, v, .false.)
      select case (deck_vars(iv)%kind)
      case (kind_real); text = real_str(v%r)
      case (kind_integer); text = int_str(v%i)
      case (kind_logical); text = trim(merge('.true. ', '.false.', v%l))
      case (kind_word, kind_path); text = "'" // v%s // "'"
      case (kind_reals); text = list_str(v%list, huge(1))
      end select
      if (.not. v%given) text = '(not given)'      ! an optional real or integer
   end function deck_value_text

   !> Writes the deck's values, 'name = value unit', by group, each line led by `lead`.
   subroutine echo_deck(deck, unit, lead)
      type(deck_t), intent(in) :: deck              !< the deck to echo
      integer, intent(in) :: unit                   !< open formatted unit
      character(len=*), intent(in) :: lead          !< text that starts every line
      integer :: ig
      write (unit, '(a)') lead // 'deck       source = ''' // deck%source // ''''
      if (allocated(deck%settings)) then
         if (len(deck%settings) > 0) write (unit, '(a)') lead // 'deck       command line: ' // deck%settings
      end if
      do ig = 1, size(deck_groups)
         if (group_applies(deck_groups(ig), deck)) call echo_group(deck, deck_groups(ig), unit, lead)
      end do
   end subroutine echo_deck

   !> The echo's lines of one group, as many variables to a line as echo_width holds.
   subroutine echo_group(deck, group, unit, lead)
      type(deck_t), intent(in) :: deck              !< the deck to echo
      character(len=*), intent(in) :: group         !< the group, without '&'
      integer, intent(in) :: unit                   !< open formatted unit
      character(len=*), intent(in) :: lead          !< text that starts every line
      character(len=:), allocatable :: line, piece
      character(len=group_column) :: column
      integer :: iv
      column = '&' // group
      line = ''
      piece = ''          ! (else gfortran 12 at -O2 takes its length for unset in the loop)
      vars: do iv = 1, size(deck_vars)
         if (deck_vars(iv)%group /= group) cycle vars
         piece = trim(deck_vars(iv)%name) // ' = ' // deck_value_text(deck, iv)     ! no unit for '-'
         if (trim(deck_vars(iv)%unit) /= '-') piece = piece // ' ' // trim(deck_vars(iv)%unit)
         if (len(line) > 0 .and. group_column + len(line) + 2 + len(piece) > echo_width) then
            write (unit, '(a)') lead // column // line // ','
            column = ''
            line = ''
         end if
         if (len(line) > 0) line = line // ', '
         line = line // piece
      end do vars
      write (unit, '(a)') lead // column // line
      ! -- settings chosen from the scene, one line each
      column = ''
      if (group == 'analysis' .and. len_trim(deck%dt_chosen) > 0) write (unit, '(a)') lead // column // trim(deck%dt_chosen)
      if (group == 'mesh' .and. len_trim(deck%mesh_chosen) > 0) write (unit, '(a)') lead // column // trim(deck%mesh_chosen)
   end subroutine echo_group

   !> The deck table of docs/DECK.md (Markdown), from the schema.
   subroutine write_deck_table(unit)
      integer, intent(in) :: unit                   !< open formatted unit
      integer :: iv
      character(len=:), allocatable :: group, meaning, default
      character(len=len(deck_vars%group)) :: previous
      type(deck_var_t) :: e
      write (unit, '(a)') '| group | variable | unit | default | meaning |'
      write (unit, '(a)') '|---|---|---|---|---|'
      previous = ''
      do iv = 1, size(deck_vars)
         e = deck_vars(iv)
         group = ''                                 ! the group on its first row only
         if (e%group /= previous) group = '`&' // trim(e%group) // '`'
         previous = e%group
         meaning = trim(e%meaning)
         if (e%kind == kind_word) meaning = meaning // ' (' // words_quoted(e%range) // ')'
         if ((e%kind == kind_real .or. e%kind == kind_integer) .and. trim(e%range) /= '(-inf, inf)') &
            meaning = meaning // '; in ' // trim(e%range)
         default = '`' // trim(e%default) // '`'
         if (e%kind == kind_word .or. e%kind == kind_path) default = "`'" // trim(e%default) // "'`"
         if (len_trim(e%default) == 0) default = 'not given'
         write (unit, '(a)') '| ' // group // ' | `' // trim(e%name) // '` | ' // trim(e%unit) // ' | ' &
            // default // ' | ' // meaning // ' |'
      end do
   end subroutine write_deck_table

   !> The schema, one tab-separated line per variable (impact --schema).
   subroutine write_schema(unit)
      integer, intent(in) :: unit                   !< open formatted unit
      integer :: iv
      type(deck_var_t) :: e
      character, parameter :: tab = achar(9)
      write (unit, '(a)') '# group' // tab // 'name' // tab // 'kind' // tab // 'unit' // tab // 'default' &
         // tab // 'range' // tab // 'meaning'
      do iv = 1, size(deck_vars)
         e = deck_vars(iv)
         write (unit, '(a)') trim(e%group) // tab // trim(e%name) // tab // trim(kind_names(e%kind)) // tab &
            // trim(e%unit) // tab // trim(e%default) // tab // trim(e%range) // tab // trim(e%meaning)
      end do
   end subroutine write_schema

   !> The message on an unknown group, or an unknown variable of a known group.
   function unknown_name(group, name) result(text)
      character(len=*), intent(in) :: group, name
      character(len=:), allocatable :: text
      if (any(deck_groups == group)) then
         text = '&' // group // ': ' // name // ': unknown variable (the variables of &' // group // ' are ' &
            // name_list(pack(deck_vars%name, deck_vars%group == group), '') // ')'
      else
         text = '&' // group // ': unknown namelist group (the groups are ' // name_list(deck_groups, '&') // ')'
      end if
   end function unknown_name

   !> The names as 'a, b, h', each led by `lead`.
   pure function name_list(names, lead) result(list)
      character(len=*), intent(in) :: names(:), lead
      character(len=:), allocatable :: list
      integer :: i
      list = ''
      do i = 1, size(names)
         if (i > 1) list = list // ', '
         list = list // lead // trim(names(i))
      end do
   end function name_list

   !> The bounds of an interval text, 'inf' as the largest double.
   pure subroutine interval(range, lo, hi, lo_open, hi_open)
      character(len=*), intent(in) :: range
      real(dp), intent(out) :: lo, hi
      logical, intent(out) :: lo_open, hi_open
      character(len=len(range)) :: r
      integer :: comma, ios
      r = adjustl(range)
      comma = index(r, ',')
      lo_open = r(1:1) == '('
      hi_open = r(len_trim(r):len_trim(r)) == ')'
      read (r(2:comma - 1), *, iostat=ios) lo
      if (ios /= 0) lo = 0.0_dp
      read (r(comma + 1:len_trim(r) - 1), *, iostat=ios) hi
      if (ios /= 0) hi = 0.0_dp
      lo = max(lo, -huge(lo))
      hi = min(hi, huge(hi))
   end subroutine interval

   !> What the interval asks, in words: 'must be positive (m)', 'must be in [1, 3]', ...
   pure function interval_text(range, unit) result(text)
      character(len=*), intent(in) :: range, unit
      character(len=:), allocatable :: text
      real(dp) :: lo, hi
      logical :: lo_open, hi_open
      call interval(range, lo, hi, lo_open, hi_open)
      if (hi == huge(1.0_dp) .and. lo == 0.0_dp .and. lo_open) then
         text = 'must be positive'
      else if (hi == huge(1.0_dp) .and. lo == 0.0_dp) then
         text = 'must be zero or positive'
      else if (hi == huge(1.0_dp) .and. lo == -huge(1.0_dp)) then
         text = 'must be finite'
      else if (hi == huge(1.0_dp) .and. .not. lo_open) then
         text = 'must be at least ' // real_str(lo)
      else
         text = 'must be in ' // trim(adjustl(range))
      end if
      if (trim(unit) /= '-' .and. len_trim(unit) > 0) text = text // ' (' // trim(unit) // ')'
   end function interval_text

end module deck_echo
