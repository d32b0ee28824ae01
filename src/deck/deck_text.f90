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
!>
!> Why a reader of our own and not `read (unit, nml=...)`: gfortran's
!> namelist read (tried with gfortran 12) answers a bad value, `a = abc`,
!> with "Cannot match namelist object name abc", naming neither the group,
!> the variable nor the line, and without iostat= stops the program there
!> with a backtrace; it passes over a misspelt group (&plaet), text before
!> a group and after its '/', and reads only the first of a group given
!> twice and the last of a variable given twice, all without a word; it
!> merges `angles(3) = 7` into the list it had, leaves the elements past a
!> shorter list as they were, and cuts a string longer than its variable
!> (a deferred-length one too, to its current length); and a variable
!> given its default value cannot be told from one not given (deck_t%given:
!> &strength criterion = 'hashin' is refused without the strengths,
!> although 'hashin' is its default).
!>
!> The reading is in two halves: the tokenizer (scan_line and the routines
!> under it) turns the characters of each line into tokens and finds where
!> the groups start and end; the group builder (begin_group, end_group,
!> build_assignments and the routines under it) makes the groups and, at
!> each group's end, turns its tokens into its assignments. The first
!> error stops both.
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
   integer, parameter :: tok_word = 1, tok_string = 2, tok_equals = 3, tok_comma = 4
   !> Characters read per chunk of a line.
   integer, parameter :: chunk_len = 256
   !> Characters that end a word (besides the end of the line).
   character(len=*), parameter :: word_ends = ' ,=/!''"' // achar(9)

   !> One token of a group: a word, a string, '=' or ','.
   type :: token_t
      integer :: kind = 0                       !< tok_word, ...
      character(len=:), allocatable :: text     !< as written; a string without its quotes
      integer :: line = 0                       !< line it is on
   end type token_t

   !> The first error of the reading.
   type :: text_error_t
      integer :: stat = 0                       !< 0, or 1 on an error
      integer :: line = 0                       !< line it is on (0: the whole deck)
      character(len=:), allocatable :: what     !< what is wrong
   end type text_error_t

   !> The reading so far: the groups found, the tokens of the open group
   !> (the last one, while it has no '/'), the first error.
   type :: reader_t
      type(group_text_t), allocatable :: groups(:)   !< the groups, in order
      type(token_t), allocatable :: toks(:)          !< tokens of the open group, toks(:ntok)
      integer :: ntok = 0                            !< tokens in toks
      type(text_error_t) :: err                      !< the first error
   end type reader_t

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
      type(reader_t) :: r
      character(len=:), allocatable :: text
      character(len=256) :: msg
      integer :: ios, nline

      allocate (r%groups(0), r%toks(0))
      r%err%what = ''
      nline = 0
      lines_loop: do
         call read_line(unit, text, ios, msg)
         if (ios == iostat_end) exit lines_loop
         nline = nline + 1
         if (ios /= 0) then
            call fail(r%err, nline, 'cannot read the line: ' // trim(msg))
            exit lines_loop
         end if
         call scan_line(r, text, nline)
         if (r%err%stat /= 0) exit lines_loop
      end do lines_loop
      if (r%err%stat == 0 .and. group_open(r)) call fail(r%err, r%groups(size(r%groups))%line, &
         open_group_name(r) // ": no closing '/' (the group runs to the end of the deck)")
      call move_alloc(r%groups, groups)
      stat = r%err%stat
      line = r%err%line
      what = r%err%what
   end subroutine read_deck_text

   ! ============================================================ tokenizer

   !> The tokens of one line: outside a group only a group's start, blanks
   !> and a comment; inside one its tokens, collected until its end.
   subroutine scan_line(r, s, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(in) :: ln                 !< its number
      integer :: i
      i = 1
      chars: do while (i <= len(s) .and. r%err%stat == 0)
         select case (s(i:i))
         case (' ', achar(9), achar(13))
            i = i + 1
         case ('!')
            exit chars
         case default
            if (group_open(r)) then
               call scan_token(r, s, i, ln)
            else
               call scan_group_start(r, s, i, ln)
            end if
         end select
      end do chars
   end subroutine scan_line

   !> Outside a group, at s(i:i): '&name' starts a group (i moves past the
   !> name); anything else is an error.
   subroutine scan_group_start(r, s, i, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(inout) :: i               !< where the text starts; past the group's name
      integer, intent(in) :: ln                 !< the line's number
      integer :: j
      if (s(i:i) == '&' .and. i < len(s)) then
         j = name_end(s, i + 1)
         if (j > i .and. lower_case(s(i+1:j)) /= 'end') then
            call begin_group(r, lower_case(s(i+1:j)), ln)
            i = j + 1
            return
         end if
      end if
      if (size(r%groups) > 0) then
         call fail(r%err, ln, "text after the closing '/' of " // open_group_name(r) // ": '" // trim(s(i:)) &
            // "' (outside the groups only comments, after '!')")
      else
         call fail(r%err, ln, "text outside a namelist group: '" // trim(s(i:)) &
            // "' (a group starts with &name; comments start with '!')")
      end if
   end subroutine scan_group_start

   !> Inside a group, at s(i:i): its end ('/' or '&end'), a string, '=',
   !> ',' or a word; i moves past it.
   subroutine scan_token(r, s, i, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(inout) :: i               !< where the token starts; past it
      integer, intent(in) :: ln                 !< the line's number
      integer :: j
      select case (s(i:i))
      case ('/')
         call end_group(r)
         i = i + 1
      case ('&')
         j = name_end(s, i + 1)
         if (j > i) then
            if (lower_case(s(i+1:j)) == 'end') then
               call end_group(r)
               i = j + 1
               return
            end if
         end if
         call fail(r%err, ln, open_group_name(r) // ": no closing '/' before the next group " // trim(s(i:j)))
      case ('''', '"')
         call scan_string(r, s, i, ln)
      case ('=')
         call push(r, tok_equals, '=', ln)
         i = i + 1
      case (',')
         call push(r, tok_comma, ',', ln)
         i = i + 1
      case default
         j = i
         do while (j < len(s))
            if (index(word_ends, s(j+1:j+1)) > 0) exit
            j = j + 1
         end do
         call push(r, tok_word, s(i:j), ln)
         i = j + 1
      end select
   end subroutine scan_token

   !> A quoted string starting at s(i:i), a doubled quote standing for
   !> itself; i moves past it.
   subroutine scan_string(r, s, i, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: s         !< the line
      integer, intent(inout) :: i               !< where its quote is; past its closing quote
      integer, intent(in) :: ln                 !< the line's number
      character :: q
      character(len=:), allocatable :: body
      integer :: j
      q = s(i:i)
      body = ''
      j = i + 1
      do
         if (j > len(s)) then
            call fail(r%err, ln, open_group_name(r) // ': a string has no closing ' // q // ' on its line')
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
      call push(r, tok_string, body, ln)
      i = j + 1
   end subroutine scan_string

   !> Appends a token to the open group's.
   subroutine push(r, kind, text, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      integer, intent(in) :: kind               !< tok_word, ...
      character(len=*), intent(in) :: text      !< its text
      integer, intent(in) :: ln                 !< its line
      type(token_t), allocatable :: grown(:)
      if (r%ntok == size(r%toks)) then
         allocate (grown(max(64, 2*r%ntok)))
         grown(:r%ntok) = r%toks(:r%ntok)
         call move_alloc(grown, r%toks)
      end if
      r%ntok = r%ntok + 1
      r%toks(r%ntok) = token_t(kind, text, ln)
   end subroutine push

   ! ======================================================== group builder

   !> A new group, '&name' on line ln, open until its '/'.
   subroutine begin_group(r, name, ln)
      type(reader_t), intent(inout) :: r        !< the reading
      character(len=*), intent(in) :: name      !< its name, lower case
      integer, intent(in) :: ln                 !< line of '&name'
      type(group_text_t), allocatable :: grown(:)
      integer :: g
      g = size(r%groups)
      allocate (grown(g + 1))
      grown(:g) = r%groups
      grown(g + 1)%name = name
      grown(g + 1)%line = ln
      allocate (grown(g + 1)%assignments(0))
      call move_alloc(grown, r%groups)
      r%ntok = 0
   end subroutine begin_group

   !> The open group's '/': its tokens become its assignments.
   subroutine end_group(r)
      type(reader_t), intent(inout) :: r        !< the reading
      integer :: g
      g = size(r%groups)
      r%groups(g)%closed = .true.
      call build_assignments(r%toks(:r%ntok), r%groups(g)%name, r%groups(g)%assignments, r%err)
      r%ntok = 0
   end subroutine end_group

   !> The assignments 'name = value, value, ...' of a group's tokens; commas
   !> between assignments are left out.
   subroutine build_assignments(toks, group, assignments, err)
      type(token_t), intent(in) :: toks(:)                          !< the group's tokens
      character(len=*), intent(in) :: group                         !< its name, for messages
      type(assignment_t), allocatable, intent(inout) :: assignments(:) !< the group's, added to
      type(text_error_t), intent(inout) :: err                      !< the first error
      type(assignment_t) :: a
      integer :: k
      k = 1
      do while (k <= size(toks))
         if (toks(k)%kind == tok_comma) then
            k = k + 1
         else
            call next_assignment(toks, k, group, a, err)
            if (err%stat /= 0) return
            assignments = [assignments, a]
         end if
      end do
   end subroutine build_assignments

   !> The assignment that starts at toks(k): its name, '=' and its values,
   !> up to the next 'name =' or the group's end; k moves past it.
   subroutine next_assignment(toks, k, group, a, err)
      type(token_t), intent(in) :: toks(:)      !< the group's tokens
      integer, intent(inout) :: k               !< its first token; the token after it
      character(len=*), intent(in) :: group     !< the group's name, for messages
      type(assignment_t), intent(out) :: a      !< the assignment
      type(text_error_t), intent(inout) :: err  !< the first error
      integer :: first, last, n, j
      if (.not. starts_assignment(toks, k)) then
         call fail(err, toks(k)%line, '&' // group // ": '" // toks(k)%text // "' is not an assignment 'name = value'")
         return
      end if
      if (name_end(toks(k)%text, 1) /= len(toks(k)%text)) then
         call fail(err, toks(k)%line, '&' // group // ': ' // toks(k)%text &
            // ': not a variable name (give a whole variable, not an element name(i) = ...)')
         return
      end if
      a%name = lower_case(toks(k)%text)
      a%line = toks(k)%line
      first = k + 2
      call find_values(toks, first, '&' // group // ': ' // a%name, last, n, err)
      if (err%stat /= 0) return
      if (n == 0) then
         call fail(err, a%line, '&' // group // ': ' // a%name // ' = (nothing): give a value')
         return
      end if
      allocate (a%items(n))
      n = 0
      do j = first, last
         if (toks(j)%kind == tok_word .or. toks(j)%kind == tok_string) then
            n = n + 1
            a%items(n)%text = toks(j)%text          ! (not a constructor: gfortran 12 drops the text)
            a%items(n)%quoted = toks(j)%kind == tok_string
         end if
      end do
      k = last + 1
   end subroutine next_assignment

   !> The values of an assignment, from toks(first) to toks(last), the token
   !> before the next 'name =' or the group's last; n of them are values
   !> (words or strings), the others commas. A second '=' or an empty value
   !> between two commas is an error.
   subroutine find_values(toks, first, where, last, n, err)
      type(token_t), intent(in) :: toks(:)      !< the group's tokens
      integer, intent(in) :: first              !< the token after '='
      character(len=*), intent(in) :: where     !< '&group: name', for messages
      integer, intent(out) :: last              !< the values' last token (first - 1: none; on an error)
      integer, intent(out) :: n                 !< how many values
      type(text_error_t), intent(inout) :: err  !< the first error
      integer :: k
      n = 0
      last = first - 1
      k = first
      values: do while (k <= size(toks))
         if (starts_assignment(toks, k)) exit values
         select case (toks(k)%kind)
         case (tok_equals)
            call fail(err, toks(k)%line, where // " = ...: a second '='")
            return
         case (tok_comma)
            if (k > first .and. k < size(toks)) then
               if (toks(k-1)%kind == tok_comma) then
                  call fail(err, toks(k)%line, where // ' = ...: an empty value between two commas')
                  return
               end if
            end if
         case default
            n = n + 1
         end select
         k = k + 1
      end do values
      last = k - 1
   end subroutine find_values

   !> toks(k) and toks(k+1) are 'name ='.
   pure logical function starts_assignment(toks, k)
      type(token_t), intent(in) :: toks(:)      !< the group's tokens
      integer, intent(in) :: k                  !< where to look
      starts_assignment = .false.
      if (k >= size(toks)) return
      starts_assignment = toks(k)%kind == tok_word .and. toks(k+1)%kind == tok_equals
   end function starts_assignment

   ! ============================================================== helpers

   !> The reading is inside a group: the last one has no '/' yet.
   pure logical function group_open(r)
      type(reader_t), intent(in) :: r           !< the reading
      group_open = .false.
      if (size(r%groups) > 0) group_open = .not. r%groups(size(r%groups))%closed
   end function group_open

   !> '&name' of the last group, for messages.
   pure function open_group_name(r) result(name)
      type(reader_t), intent(in) :: r           !< the reading, with a group
      character(len=:), allocatable :: name
      name = '&' // r%groups(size(r%groups))%name
   end function open_group_name

   !> Records the first error: stat 1, its line and what is wrong.
   subroutine fail(err, ln, message)
      type(text_error_t), intent(inout) :: err  !< the error
      integer, intent(in) :: ln                 !< its line
      character(len=*), intent(in) :: message   !< what is wrong
      err%stat = 1
      err%line = ln
      err%what = message
   end subroutine fail

   !> One line of any length; ios = iostat_end at the end of the file.
   subroutine read_line(unit, line, ios, msg)
      integer, intent(in) :: unit                          !< the deck's unit
      character(len=:), allocatable, intent(out) :: line   !< the line, without its end of line
      integer, intent(out) :: ios                          !< 0, iostat_end, or the read's error
      character(len=*), intent(inout) :: msg               !< the read's message on an error
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
      character(len=*), intent(in) :: s         !< the text
      integer, intent(in) :: first              !< where the name would start
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
      character(len=*), intent(in) :: s         !< the text
      character(len=len(s)) :: lower
      integer, parameter :: shift = iachar('a') - iachar('A')
      integer :: i
      lower = s
      do i = 1, len(s)
         if (lge(s(i:i), 'A') .and. lle(s(i:i), 'Z')) lower(i:i) = achar(iachar(s(i:i)) + shift)
      end do
   end function lower_case

   !> c is a letter, A-Z or a-z.
   pure logical function is_letter(c)
      character, intent(in) :: c                !< the character
      is_letter = (lge(c, 'a') .and. lle(c, 'z')) .or. (lge(c, 'A') .and. lle(c, 'Z'))
   end function is_letter

   !> c is a digit, 0-9.
   pure logical function is_digit(c)
      character, intent(in) :: c                !< the character
      is_digit = lge(c, '0') .and. lle(c, '9')
   end function is_digit

end module deck_text
