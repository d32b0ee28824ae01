!> The text of a deck: its namelist groups and assignments with their lines,
!> before their meaning (input_deck checks them against the schema). The
!> namelist syntax a deck needs ('&group name = value, ... /', quotes, '!'
!> comments, r*c), read stricter than a compiler's: nothing is silently
!> ignored. Time linear in the deck's length. More: docs/DECK.md.
module deck_text
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use number_text, only: int_str
   use file_system, only: read_line
   implicit none
   private
   public :: item_t, group_text_t, read_deck_text, split_value_text, lower_case, shown_text

   !> The longest deck (bytes): 1 MiB, which bounds the reading of a wrong file.
   integer, parameter :: max_deck_bytes = 1048576
   !> Bytes of the deck's text a message shows before it is cut ('...').
   integer, parameter :: max_shown = 60

   !> One value as written: its text (without quotes), quoted or not, r of r*c.
   type :: item_t
      character(len=:), allocatable :: text
      logical :: quoted = .false.
      integer :: repeat = 1                     !< r of r*c; 1 when no count is written
      logical :: counted = .false.              !< written with a repeat count r*
   end type item_t

   !> name = item, item, ...
   type :: assignment_t
      character(len=:), allocatable :: name     !< lower case
      type(item_t), allocatable :: items(:)     !< the values, in order
      integer :: line = 0                       !< line of the name
   end type assignment_t

   !> &name ... /
   type :: group_text_t
      character(len=:), allocatable :: name     !< lower case, without '&'
      type(assignment_t), allocatable :: assignments(:)
      integer :: line = 0                       !< line of '&name'
   end type group_text_t

   !> Kinds of token.
   integer, parameter :: tok_word = 1, tok_string = 2, tok_equals = 3, tok_comma = 4
   !> Characters that end a word in a group and in a --set value.
   character(len=*), parameter :: word_ends = ' ,=/!''"' // achar(9), value_word_ends = ' ,''"' // achar(9)
   !> Characters of a name: a letter, then these.
   character(len=*), parameter :: letters = 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ', &
      name_chars = letters // '0123456789_'
   !> Digits a repeat count may have: up to 999999999.
   integer, parameter :: max_count_digits = 9
   !> UTF-8's byte-order mark, EF BB BF.
   character(len=*), parameter :: byte_order_mark = char(239) // char(187) // char(191)

   !> One token of a group: a word, a string, '=' or ','.
   type :: token_t
      integer :: kind = 0                       !< tok_word, ...
      character(len=:), allocatable :: text     !< as written; a string without its quotes
      integer :: line = 0                       !< line it is on
      logical :: glued = .false.                !< a string right after a word's '*' (r*'text')
   end type token_t

   !> The first error of the reading.
   type :: text_error_t
      integer :: stat = 0                       !< 0, or 1 on an error
      integer :: line = 0                       !< line it is on (0: the whole deck)
      character(len=:), allocatable :: what     !< what is wrong
   end type text_error_t

   !> The reading so far: the groups, the open group's tokens, the first error.
   type :: reader_t
      type(group_text_t), allocatable :: groups(:)   !< the groups, in order, groups(:ngroup)
      integer :: ngroup = 0                          !< groups in groups
      type(token_t), allocatable :: toks(:)          !< tokens of the open group, toks(:ntok)
      integer :: ntok = 0                            !< tokens in toks
      logical :: inside = .false.                    !< in groups(ngroup), before its '/'
      type(text_error_t) :: err                      !< the first error
   end type reader_t

contains

   !> The groups of the deck on `unit` (read once to its end); on a syntax
   !> error stat = 1, its line (0: the whole deck) and what is wrong.
   subroutine read_deck_text(unit, groups, stat, line, what)
      integer, intent(in) :: unit                              !< the deck's unit
      type(group_text_t), allocatable, intent(out) :: groups(:) !< its groups, in order
      integer, intent(out) :: stat                             !< 0, or 1 on an error
      integer, intent(out) :: line                             !< line of the error
      character(len=:), allocatable, intent(out) :: what       !< what is wrong
      type(reader_t) :: r
      character(len=:), allocatable :: text
      character(len=256) :: msg
      integer :: ios, nline, bytes
      logical :: over
      allocate (r%groups(8), r%toks(64))
      r%err%what = ''
      nline = 0
      bytes = 0
      lines_loop: do while (r%err%stat == 0)
         call read_line(unit, max_deck_bytes - bytes, text, ios, msg, over)
         if (ios == iostat_end) exit lines_loop
         nline = nline + 1
         if (over) then
            call fail(r%err, 0, 'longer than ' // int_str(max_deck_bytes/1048576) // ' MiB (' &
               // int_str(max_deck_bytes) // ' bytes), the most a deck may be (a deck ' &
               // 'is a few kilobytes of text: is this the deck?)')
         else if (ios /= 0) then
            call fail(r%err, nline, 'cannot read the line: ' // trim(msg))
         else
            bytes = bytes + len(text) + 1
            if (nline == 1 .and. index(text, byte_order_mark) == 1) text = text(len(byte_order_mark) + 1:)
            call scan_line(r, text, nline)
         end if
      end do lines_loop
      if (r%err%stat == 0 .and. r%inside) call fail(r%err, r%groups(r%ngroup)%line, '&' &
         // r%groups(r%ngroup)%name // ": no closing '/' (the group runs to the end of the deck)")
      groups = r%groups(:r%ngroup)
      stat = r%err%stat
      line = r%err%line
      what = r%err%what
   end subroutine read_deck_text

   !> The values of impact --set group.name=value, read as after 'name =' in a
   !> deck, but '=', '/', '&' and '!' belong to a word ('out/run' needs no quotes).
   subroutine split_value_text(text, items, stat, what)
      character(len=*), intent(in) :: text                 !< the value text
      type(item_t), allocatable, intent(out) :: items(:)   !< its values
      integer, intent(out) :: stat                         !< 0, or 1 on an error
      character(len=:), allocatable, intent(out) :: what   !< what is wrong
      type(reader_t) :: r
      integer :: i
      allocate (r%toks(64))
      i = 1
      do while (i <= len(text) .and. r%err%stat == 0)
         call scan_token(r, text, i, 1, value_word_ends)
      end do
      if (r%err%stat == 0) call make_items(r%toks(:r%ntok), 'the value', items, r%err)
      if (.not. allocated(items)) allocate (items(0))
      stat = r%err%stat
      what = ''
      if (stat /= 0) what = r%err%what
   end subroutine split_value_text

   !> The tokens of one line. Outside a group: a group's start '&name', blanks
   !> and a comment; inside one: its end ('/' or '&end') and its tokens.
   subroutine scan_line(r, s, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(in) :: ln                 !< its number
      character(len=:), allocatable :: name
      integer :: i, j
      i = 1
      chars: do while (i <= len(s) .and. r%err%stat == 0)
         j = i                                  ! '&name': j the end of the name
         if (s(i:i) == '&') j = name_end(s, i + 1)
         name = lower_case(s(i + 1:j))
         select case (s(i:i))
         case (' ', achar(9), achar(13))
         case ('!'); exit chars
         case default
            if (.not. r%inside .and. j > i .and. name /= 'end') then
               call begin_group(r, name, ln)
            else if (.not. r%inside .and. r%ngroup > 0) then
               call fail(r%err, ln, "text after the closing '/' of &" // r%groups(r%ngroup)%name &
                  // ": '" // shown_text(trim(s(i:))) // "' (outside the groups only comments, " &
                  // "after '!')")
            else if (.not. r%inside) then
               call fail(r%err, ln, "text outside a namelist group: '" // shown_text(trim(s(i:))) &
                  // "' (a group starts with &name; comments start with '!')")
            else if (s(i:i) == '/' .or. name == 'end') then      ! its tokens become its assignments
               r%inside = .false.
               call build_assignments(r%toks(:r%ntok), r%groups(r%ngroup)%name, &
                  r%groups(r%ngroup)%assignments, r%err)
            else if (s(i:i) == '&') then
               call fail(r%err, ln, '&' // r%groups(r%ngroup)%name // ": no closing '/' before " &
                  // 'the next group ' // shown_text(s(i:j)))
            else
               call scan_token(r, s, i, ln, word_ends)
               cycle chars
            end if
         end select
         i = j + 1
      end do chars
   end subroutine scan_line

   !> The token at s(i:i), i moved past it: a string, ',', '=' (when `ends`
   !> holds it), a word up to the next of `ends`, or none at a blank.
   subroutine scan_token(r, s, i, ln, ends)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(inout) :: i               !< where the token starts; past it
      integer, intent(in) :: ln                 !< the line's number
      character(len=*), intent(in) :: ends      !< the characters that end a word
      integer :: j
      j = i
      if (s(i:i) == '''' .or. s(i:i) == '"') then
         call scan_string(r, s, i, ln)
         return
      else if (s(i:i) == ',') then
         call push(r, tok_comma, ',', ln)
      else if (s(i:i) == '=' .and. index(ends, '=') > 0) then
         call push(r, tok_equals, '=', ln)
      else if (s(i:i) /= ' ' .and. s(i:i) /= achar(9)) then     ! a word; a blank is passed over
         j = word_end(s, i, ends)
         call push(r, tok_word, s(i:j), ln)
      end if
      i = j + 1
   end subroutine scan_token

   !> The string whose quote is s(i:i), a doubled quote made single; i moved
   !> past its closing quote. Glued: right after a word's '*' (r*'text').
   subroutine scan_string(r, s, i, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(inout) :: i               !< where its quote is; past its closing quote
      integer, intent(in) :: ln                 !< the line's number
      character(len=:), allocatable :: body
      character :: q
      integer :: j, n
      allocate (character(len=len(s)) :: body)
      q = s(i:i)
      n = 0
      j = i + 1
      do while (j <= len(s))
         if (s(j:j) == q .and. s(j + 1:min(j + 1, len(s))) /= q) exit     ! the closing quote
         if (s(j:j) == q) j = j + 1                                      ! a doubled quote
         n = n + 1
         body(n:n) = s(j:j)
         j = j + 1
      end do
      if (j > len(s) .and. r%ngroup == 0) then            ! a --set value
         call fail(r%err, ln, 'a string has no closing ' // q)
      else if (j > len(s)) then
         call fail(r%err, ln, '&' // r%groups(r%ngroup)%name // ': a string has no closing ' // q &
            // ' on its line')
      else
         call push(r, tok_string, body(:n), ln)
         r%toks(r%ntok)%glued = s(max(1, i - 1):i - 1) == '*'   ! '*' ends the word before it
         i = j + 1
      end if
   end subroutine scan_string

   !> Appends a token to the open group's.
   subroutine push(r, kind, text, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      integer, intent(in) :: kind               !< tok_word, ...
      character(len=*), intent(in) :: text      !< its text
      integer, intent(in) :: ln                 !< its line
      type(token_t), allocatable :: grown(:)
      if (r%ntok == size(r%toks)) then
         allocate (grown(2*r%ntok))
         grown(:r%ntok) = r%toks(:r%ntok)
         call move_alloc(grown, r%toks)
      end if
      r%ntok = r%ntok + 1
      r%toks(r%ntok) = token_t(kind, text, ln)
   end subroutine push

   !> A new group, '&name' on line ln, open until its '/'.
   subroutine begin_group(r, name, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: name      !< its name, lower case
      integer, intent(in) :: ln                 !< line of '&name'
      type(group_text_t), allocatable :: grown(:)
      if (r%ngroup == size(r%groups)) then
         allocate (grown(2*r%ngroup))
         grown(:r%ngroup) = r%groups(:r%ngroup)
         call move_alloc(grown, r%groups)
      end if
      r%ngroup = r%ngroup + 1
      r%groups(r%ngroup)%name = name
      r%groups(r%ngroup)%line = ln
      r%ntok = 0
      r%inside = .true.
   end subroutine begin_group

   !> The assignments 'name = value, value, ...' of a group's tokens.
   subroutine build_assignments(toks, group, assignments, err)
      type(token_t), intent(in) :: toks(:)                          !< the group's tokens
      character(len=*), intent(in) :: group                         !< its name, for messages
      type(assignment_t), allocatable, intent(inout) :: assignments(:) !< the group's
      type(text_error_t), intent(inout) :: err                      !< the first error
      type(assignment_t), allocatable :: list(:)
      character(len=:), allocatable :: where
      integer :: k, n, last
      allocate (list(count(toks%kind == tok_equals)))     ! each assignment has its '='
      n = 0
      k = 1
      where = ''        ! (else gfortran 12 at -O2 takes its length for unset in the loop)
      do while (k <= size(toks) .and. err%stat == 0)
         if (toks(k)%kind == tok_comma) then
            k = k + 1
         else if (.not. starts_assignment(toks, k)) then
            call fail(err, toks(k)%line, '&' // group // ": '" // shown_text(toks(k)%text) &
               // "' is not an assignment 'name = value'")
         else if (name_end(toks(k)%text, 1) /= len(toks(k)%text)) then
            call fail(err, toks(k)%line, '&' // group // ': ' // shown_text(toks(k)%text) &
               // ': not a variable name (give a whole variable, not an element name(i) = ...)')
         else
            n = n + 1
            list(n)%name = lower_case(toks(k)%text)
            list(n)%line = toks(k)%line
            where = '&' // group // ': ' // list(n)%name
            call find_values(toks, k + 2, where, last, err)
            if (err%stat == 0) call make_items(toks(k + 2:last), where, list(n)%items, err)
            k = last + 1
         end if
      end do
      assignments = list(:n)
   end subroutine build_assignments

   !> The values toks(first:last) up to the next 'name ='; none, a second '='
   !> or an empty value is an error.
   subroutine find_values(toks, first, where, last, err)
      type(token_t), intent(in) :: toks(:)      !< the group's tokens
      integer, intent(in) :: first              !< the token after '='
      character(len=*), intent(in) :: where     !< '&group: name', for messages
      integer, intent(out) :: last              !< the values' last token (first - 1: none; on an error)
      type(text_error_t), intent(inout) :: err  !< the first error
      integer :: k
      last = first - 1
      do k = first, size(toks)
         if (starts_assignment(toks, k)) exit
         if (toks(k)%kind == tok_equals) then
            call fail(err, toks(k)%line, where // " = ...: a second '='")
            return
         end if
         if (k > first .and. k < size(toks) .and. toks(k)%kind == tok_comma &
             .and. toks(k - 1)%kind == tok_comma) then
            call fail(err, toks(k)%line, where // ' = ...: an empty value between two commas')
            return
         end if
      end do
      if (all(toks(first:k - 1)%kind == tok_comma)) then
         call fail(err, toks(first - 2)%line, where // ' = (nothing): give a value')
         return
      end if
      last = k - 1
   end subroutine find_values

   !> toks(k) and toks(k+1) are 'name ='.
   pure logical function starts_assignment(toks, k)
      type(token_t), intent(in) :: toks(:)      !< the group's tokens
      integer, intent(in) :: k                  !< where to look
      starts_assignment = .false.
      if (k < size(toks)) starts_assignment = toks(k)%kind == tok_word .and. toks(k+1)%kind == tok_equals
   end function starts_assignment

   !> The items of an assignment's value tokens: r*c is c with its count r,
   !> r* glued to a string that string r times, r* alone an error (r nulls).
   subroutine make_items(toks, where, items, err)
      type(token_t), intent(in) :: toks(:)                 !< the value tokens
      character(len=*), intent(in) :: where                !< '&group: name', for messages
      type(item_t), allocatable, intent(out) :: items(:)   !< the values
      type(text_error_t), intent(inout) :: err             !< the first error
      character(len=:), allocatable :: rest, why
      integer :: j, n
      allocate (items(size(toks)))
      n = 0
      j = 0
      tokens: do while (j < size(toks))
         j = j + 1
         if (toks(j)%kind == tok_comma) cycle tokens
         n = n + 1
         items(n)%text = toks(j)%text             ! (not a constructor: gfortran 12 drops the text)
         items(n)%quoted = toks(j)%kind == tok_string
         if (items(n)%quoted) cycle tokens
         call repeat_count(toks(j)%text, items(n)%repeat, rest, why)
         items(n)%counted = len(rest) < len(toks(j)%text)
         if (len(why) == 0 .and. items(n)%counted .and. len(rest) == 0 .and. j < size(toks)) then
            if (toks(j + 1)%glued) then          ! r*'text'
               j = j + 1
               rest = toks(j)%text
               items(n)%quoted = .true.
            end if
         end if
         if (len(why) == 0 .and. items(n)%counted .and. len(rest) == 0 .and. .not. items(n)%quoted) &
            why = 'r* with no value after it is r null values, which leave the values as they were: ' &
            // 'give the values'
         if (len(why) > 0) then
            call fail(err, toks(j)%line, where // ' = ' // shown_text(toks(j)%text) // ': ' // why)
            exit tokens
         end if
         items(n)%text = rest
      end do tokens
      items = items(:n)
   end subroutine make_items

   !> The repeat count r and value c of a word r*c (r = 1 and the whole word
   !> without a count); why is '' or what is wrong with the count.
   pure subroutine repeat_count(word, r, rest, why)
      character(len=*), intent(in) :: word                 !< the word
      integer, intent(out) :: r                            !< the count
      character(len=:), allocatable, intent(out) :: rest   !< the value after 'r*'
      character(len=:), allocatable, intent(out) :: why    !< '' or what is wrong
      integer :: star
      r = 1
      rest = word
      why = ''
      star = index(word, '*')
      if (star < 2) return
      if (verify(word(:star - 1), '0123456789') /= 0) return
      if (star - 1 > max_count_digits) then
         why = 'a repeat count r*c of more than ' // int_str(max_count_digits) // ' digits'
         return
      end if
      read (word(:star - 1), *) r
      if (r < 1) why = 'a repeat count r*c needs r >= 1'
      rest = word(star + 1:)
   end subroutine repeat_count

   !> Records the first error: stat 1, its line and what is wrong.
   subroutine fail(err, ln, message)
      type(text_error_t), intent(inout) :: err  !< the error
      integer, intent(in) :: ln                 !< its line
      character(len=*), intent(in) :: message   !< what is wrong
      err%stat = 1
      err%line = ln
      err%what = message
   end subroutine fail

   !> The end of the name (a letter, then letters, digits, '_') at s(first:), or first - 1.
   pure integer function name_end(s, first) result(last)
      character(len=*), intent(in) :: s         !< the text
      integer, intent(in) :: first              !< where the name would start
      last = first - 1
      if (first > len(s)) return
      if (scan(s(first:first), letters) == 0) return
      last = verify(s(first:), name_chars)
      last = merge(len(s), first + last - 2, last == 0)
   end function name_end

   !> The end of the word at s(i:i): before the next of `ends`, or the end of s.
   pure integer function word_end(s, i, ends) result(j)
      character(len=*), intent(in) :: s         !< the text
      integer, intent(in) :: i                  !< where the word starts
      character(len=*), intent(in) :: ends      !< the characters that end it
      j = scan(s(i+1:), ends)
      j = merge(len(s), i + j - 1, j == 0)
   end function word_end

   !> s with A-Z turned to a-z.
   pure function lower_case(s) result(lower)
      character(len=*), intent(in) :: s         !< the text
      character(len=len(s)) :: lower
      integer, parameter :: shift = iachar('a') - iachar('A')
      integer :: i
      lower = s
      do i = 1, len(s)
         if (lge(s(i:i), 'A') .and. lle(s(i:i), 'Z')) lower(i:i) = achar(iachar(s(i:i)) + shift)
      end do
   end function lower_case

   !> s as a message shows it: printable ASCII and whole UTF-8 characters as
   !> they are; control bytes, DEL, non-UTF-8 bytes, C1 controls and the
   !> byte-order mark as \xNN; cut after max_shown bytes with '...'.
   pure function shown_text(s) result(shown)
      character(len=*), intent(in) :: s             !< the text, as the deck holds it
      character(len=:), allocatable :: shown
      character(len=*), parameter :: hex = '0123456789ABCDEF'
      integer :: i, m, code
      shown = ''
      i = 1
      do while (i <= min(len(s), max_shown))
         code = ichar(s(i:i))
         m = merge(utf8_length(s, i), 1, code >= 128)
         if (code < 32 .or. code == 127 .or. m == 0) then
            shown = shown // '\x' // hex(code/16 + 1:code/16 + 1) // hex(mod(code, 16) + 1:mod(code, 16) + 1)
            m = 1
         else
            shown = shown // s(i:i + m - 1)
         end if
         i = i + m
      end do
      if (i <= len(s)) shown = shown // '...'
   end function shown_text

   !> Bytes of the whole UTF-8 character at s(i:i) (a byte >= 128); 0 for a
   !> stray, cut, overlong or surrogate form, a C1 control or the byte-order mark.
   pure integer function utf8_length(s, i) result(m)
      character(len=*), intent(in) :: s         !< the text
      integer, intent(in) :: i                  !< where the character starts
      integer :: b0, b1, k, n, lo, hi
      b0 = ichar(s(i:i))
      m = 0
      if (b0 < 194 .or. b0 > 244) return
      n = 2 + merge(1, 0, b0 >= 224) + merge(1, 0, b0 >= 240)
      if (i + n - 1 > len(s)) return
      lo = 128;  hi = 191
      if (b0 == 194) lo = 160                   ! C1 controls
      if (b0 == 224) lo = 160
      if (b0 == 237) hi = 159
      if (b0 == 240) lo = 144
      if (b0 == 244) hi = 143
      b1 = ichar(s(i+1:i+1))
      if (b1 < lo .or. b1 > hi .or. s(i:i + n - 1) == byte_order_mark) return
      if (any([(ichar(s(k:k)) < 128 .or. ichar(s(k:k)) > 191, k = i + 2, i + n - 1)])) return
      m = n
   end function utf8_length

end module deck_text
