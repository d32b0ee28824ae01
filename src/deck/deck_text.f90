!> The text of a deck: its namelist groups and their assignments, found
!> with their line numbers, before anything is known of what they mean
!> (src/deck/input_deck.f90 checks them against the schema, src/deck/deck_schema.f90).
!>
!> The syntax is Fortran's namelist input, the part of it a deck needs:
!>
!>     ! a comment, to the end of the line
!>     &group  name = value, name = value1, value2, ...
!>             name = 'a string', name = .true. /
!>
!> A group starts at '&name' and ends at '/' (or '&end'); names are
!> case-insensitive; values are separated by commas or blanks and may run
!> over several lines; strings are quoted with ' or " (a doubled quote
!> stands for itself); '!' outside a string starts a comment. An item r*v
!> is the value v repeated r times.
!>
!> Stricter than a compiler's namelist reader, so that nothing in a deck is
!> silently ignored or merged: outside the groups only blank lines and
!> comments (text after a group's '/' is an error, not a comment); each
!> assignment names one variable (no array elements, name(3) = ...) and has
!> at least one value, no empty one between commas; a string ends on its
!> line. An error comes back as the line it is on and what is wrong.
module deck_text
   use, intrinsic :: iso_fortran_env, only: iostat_end, iostat_eor
   implicit none
   private
   public :: item_t, group_text_t, read_deck_text, lower_case

   !> One value as written: its text (without quotes) and whether it was quoted.
   type :: item_t
      character(len=:), allocatable :: text
      logical :: quoted = .false.
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
      logical :: closed = .false.               !< its '/' was found
   end type group_text_t

   !> Kinds of token.
   integer, parameter :: tok_word = 1, tok_string = 2, tok_equals = 3, tok_comma = 4, tok_end = 5
   !> Characters read per chunk of a line.
   integer, parameter :: chunk_len = 256

   type :: token_t
      integer :: kind = 0
      character(len=:), allocatable :: text
      integer :: line = 0
   end type token_t

contains

   !> Reads the deck on `unit` (formatted, sequential, read once to its end:
   !> standard input is fine) and returns its groups. On a syntax error stat
   !> is 1, line the line it is on (0: the whole deck) and what says what is
   !> wrong, naming the group where there is one.
   subroutine read_deck_text(unit, groups, stat, line, what)
      integer, intent(in) :: unit                              !< the deck's unit
      type(group_text_t), allocatable, intent(out) :: groups(:) !< its groups, in order
      integer, intent(out) :: stat                             !< 0, or 1 on an error
      integer, intent(out) :: line                             !< line of the error
      character(len=:), allocatable, intent(out) :: what       !< what is wrong
      type(token_t), allocatable :: toks(:)
      character(len=:), allocatable :: text
      character(len=256) :: msg
      integer :: ios, nline, ntok, g, from

      allocate (groups(0), toks(0))
      stat = 0;  line = 0;  what = ''
      ntok = 0;  nline = 0;  g = 0
      lines_loop: do
         call read_line(unit, text, ios, msg)
         if (ios == iostat_end) exit lines_loop
         nline = nline + 1
         if (ios /= 0) then
            call fail(nline, 'cannot read the line: ' // trim(msg))
            return
         end if
         call scan_line(text, nline)
         if (stat /= 0) return
      end do lines_loop
      if (g > 0) then
         if (.not. groups(g)%closed) then
            call fail(groups(g)%line, '&' // groups(g)%name // ": no closing '/' (the group runs to the end of the deck)")
            return
         end if
      end if

   contains

      !> Tokens of one line: group starts and ends are handled here; the
      !> tokens inside a group are collected and parsed at its end.
      subroutine scan_line(s, ln)
         character(len=*), intent(in) :: s
         integer, intent(in) :: ln
         integer :: i, j
         character :: c
         logical :: inside
         i = 1
         chars: do while (i <= len(s))
            c = s(i:i)
            inside = .false.
            if (g > 0) inside = .not. groups(g)%closed
            if (c == ' ' .or. c == achar(9) .or. c == achar(13)) then
               i = i + 1
            else if (c == '!') then
               exit chars
            else if (.not. inside) then
               if (c == '&' .and. i < len(s)) then
                  j = name_end(s, i + 1)
                  if (j > i .and. lower_case(s(i+1:j)) /= 'end') then
                     call add_group(lower_case(s(i+1:j)), ln)
                     ntok = 0;  from = 0
                     i = j + 1
                     cycle chars
                  end if
               end if
               if (g > 0) then
                  call fail(ln, "text after the closing '/' of &" // groups(g)%name // ": '" // trim(s(i:)) &
                     // "' (outside the groups only comments, after '!')")
               else
                  call fail(ln, "text outside a namelist group: '" // trim(s(i:)) &
                     // "' (a group starts with &name; comments start with '!')")
               end if
               return
            else if (c == '/') then
               call close_group()
               if (stat /= 0) return
               i = i + 1
            else if (c == '&') then
               j = name_end(s, i + 1)
               if (j > i) then
                  if (lower_case(s(i+1:j)) == 'end') then
                     call close_group()
                     if (stat /= 0) return
                     i = j + 1
                     cycle chars
                  end if
               end if
               call fail(ln, '&' // groups(g)%name // ": no closing '/' before the next group " // trim(s(i:j)))
               return
            else if (c == '''' .or. c == '"') then
               call quoted(s, i, ln)
               if (stat /= 0) return
            else if (c == '=') then
               call push(tok_equals, '=', ln);  i = i + 1
            else if (c == ',') then
               call push(tok_comma, ',', ln);  i = i + 1
            else
               j = i
               do while (j < len(s))
                  if (index(' ,=/!''"' // achar(9), s(j+1:j+1)) > 0) exit
                  j = j + 1
               end do
               call push(tok_word, s(i:j), ln)
               i = j + 1
            end if
         end do chars
      end subroutine scan_line

      !> A quoted string starting at s(i:i); i moves past it.
      subroutine quoted(s, i, ln)
         character(len=*), intent(in) :: s
         integer, intent(inout) :: i
         integer, intent(in) :: ln
         character :: q
         character(len=:), allocatable :: body
         integer :: j
         q = s(i:i)
         body = ''
         j = i + 1
         do
            if (j > len(s)) then
               call fail(ln, '&' // groups(g)%name // ': a string has no closing ' // q // ' on its line')
               return
            end if
            if (s(j:j) == q) then
               if (j < len(s)) then
                  if (s(j+1:j+1) == q) then
                     body = body // q
                     j = j + 2
                     cycle
                  end if
               end if
               exit
            end if
            body = body // s(j:j)
            j = j + 1
         end do
         call push(tok_string, body, ln)
         i = j + 1
      end subroutine quoted

      subroutine push(kind, text, ln)
         integer, intent(in) :: kind, ln
         character(len=*), intent(in) :: text
         type(token_t), allocatable :: grown(:)
         if (ntok == size(toks)) then
            allocate (grown(max(64, 2*ntok)))
            grown(:ntok) = toks(:ntok)
            call move_alloc(grown, toks)
         end if
         ntok = ntok + 1
         toks(ntok) = token_t(kind, text, ln)
      end subroutine push

      subroutine add_group(name, ln)
         character(len=*), intent(in) :: name
         integer, intent(in) :: ln
         type(group_text_t), allocatable :: grown(:)
         allocate (grown(g + 1))
         grown(:g) = groups(:g)
         grown(g + 1)%name = name
         grown(g + 1)%line = ln
         allocate (grown(g + 1)%assignments(0))
         call move_alloc(grown, groups)
         g = g + 1
      end subroutine add_group

      !> The group's '/': its tokens become assignments.
      subroutine close_group()
         integer :: k, n, first
         type(assignment_t) :: a
         groups(g)%closed = .true.
         k = 1
         assignments: do while (k <= ntok)
            if (toks(k)%kind == tok_comma) then
               k = k + 1
               cycle assignments
            end if
            if (toks(k)%kind /= tok_word .or. k == ntok) then
               call fail(toks(k)%line, '&' // groups(g)%name // ": '" // toks(k)%text &
                  // "' is not an assignment 'name = value'")
               return
            end if
            if (toks(k+1)%kind /= tok_equals) then
               call fail(toks(k)%line, '&' // groups(g)%name // ": '" // toks(k)%text &
                  // "' is not an assignment 'name = value'")
               return
            end if
            if (name_end(toks(k)%text, 1) /= len(toks(k)%text)) then
               call fail(toks(k)%line, '&' // groups(g)%name // ': ' // toks(k)%text &
                  // ': not a variable name (give a whole variable, not an element name(i) = ...)')
               return
            end if
            a%name = lower_case(toks(k)%text)
            a%line = toks(k)%line
            k = k + 2
            first = k
            ! values up to the next 'name =' or the end
            n = 0
            values: do while (k <= ntok)
               if (k < ntok) then
                  if (toks(k)%kind == tok_word .and. toks(k+1)%kind == tok_equals) exit values
               end if
               if (toks(k)%kind == tok_equals) then
                  call fail(toks(k)%line, '&' // groups(g)%name // ': ' // a%name // " = ...: a second '='")
                  return
               end if
               if (toks(k)%kind == tok_comma) then
                  if (k > first) then
                     if (toks(k-1)%kind == tok_comma .and. k + 1 <= ntok) then
                        call fail(toks(k)%line, '&' // groups(g)%name // ': ' // a%name &
                           // ' = ...: an empty value between two commas')
                        return
                     end if
                  end if
               else
                  n = n + 1
               end if
               k = k + 1
            end do values
            if (n == 0) then
               call fail(a%line, '&' // groups(g)%name // ': ' // a%name // ' = (nothing): give a value')
               return
            end if
            allocate (a%items(n))
            n = 0
            do first = first, k - 1
               if (toks(first)%kind == tok_word .or. toks(first)%kind == tok_string) then
                  n = n + 1
                  a%items(n)%text = toks(first)%text          ! (not a constructor: gfortran 12 drops the text)
                  a%items(n)%quoted = toks(first)%kind == tok_string
               end if
            end do
            groups(g)%assignments = [groups(g)%assignments, a]
            deallocate (a%items)
         end do assignments
         ntok = 0
      end subroutine close_group

      subroutine fail(ln, message)
         integer, intent(in) :: ln
         character(len=*), intent(in) :: message
         stat = 1
         line = ln
         what = message
      end subroutine fail

   end subroutine read_deck_text

   !> One line of any length; ios = iostat_end at the end of the file.
   subroutine read_line(unit, line, ios, msg)
      integer, intent(in) :: unit
      character(len=:), allocatable, intent(out) :: line
      integer, intent(out) :: ios
      character(len=*), intent(inout) :: msg
      character(len=chunk_len) :: chunk
      integer :: nread
      line = ''
      do
         read (unit, '(a)', advance='no', iostat=ios, iomsg=msg, size=nread) chunk
         if (ios == 0) then
            line = line // chunk
         else if (ios == iostat_eor) then
            line = line // chunk(:nread)
            ios = 0
            return
         else if (ios == iostat_end) then
            if (len(line) > 0) ios = 0    ! a last line without its end of line
            return
         else
            return
         end if
      end do
   end subroutine read_line

   !> Index of the last character of the name that starts at s(first:), or
   !> first - 1 when none does (a letter, then letters, digits and '_').
   pure function name_end(s, first) result(last)
      character(len=*), intent(in) :: s
      integer, intent(in) :: first
      integer :: last
      last = first - 1
      if (first > len(s)) return
      if (.not. is_letter(s(first:first))) return
      last = first
      do while (last < len(s))
         if (.not. (is_letter(s(last+1:last+1)) .or. is_digit(s(last+1:last+1)) .or. s(last+1:last+1) == '_')) exit
         last = last + 1
      end do
   end function name_end

   !> s with A-Z turned to a-z.
   pure function lower_case(s) result(lower)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: lower
      integer, parameter :: shift = iachar('a') - iachar('A')
      integer :: i
      lower = s
      do i = 1, len(s)
         if (lge(s(i:i), 'A') .and. lle(s(i:i), 'Z')) lower(i:i) = achar(iachar(s(i:i)) + shift)
      end do
   end function lower_case

   pure logical function is_letter(c)
      character, intent(in) :: c
      is_letter = (lge(c, 'a') .and. lle(c, 'z')) .or. (lge(c, 'A') .and. lle(c, 'Z'))
   end function is_letter

   pure logical function is_digit(c)
      character, intent(in) :: c
      is_digit = lge(c, '0') .and. lle(c, '9')
   end function is_digit

end module deck_text
