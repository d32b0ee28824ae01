!> The command line of `impact`: impact [options] [deck.nml], the deck from
!> standard input when none is named; options before or after it. A second
!> deck, an unknown option or a missing value is an error. What each option
!> does: `impact --help` and docs/DECK.md. Not from the paper.
module command_line
   use input_deck, only: deck_t, read_deck, read_deck_file, set_variable, validate_deck
   use deck_schema, only: not_given_real
   use number_text, only: int_str
   implicit none
   private
   public :: options_t, parse_command_line, read_input_deck

   !> What the command line asks for.
   type :: options_t
      character(len=16) :: action = 'run'          !< 'run', 'help', 'version', 'schema' or 'deck-table'
      character(len=:), allocatable :: deck_path   !< the deck, '' for standard input
      character(len=8192), allocatable :: settings(:)   !< the --set values, in order
      character(len=:), allocatable :: trace       !< the --trace steps, '' for none
      character(len=:), allocatable :: accuracy    !< the --accuracy value, '' for none
      logical :: check = .false.                   !< --check
      logical :: overwrite = .false.               !< --overwrite
      logical :: restart = .false.                 !< --restart
      logical :: single = .false.                  !< --single: &accuracy target left aside
   end type options_t

contains

   !> The options of the command line; stat /= 0 and errmsg on a wrong one.
   subroutine parse_command_line(opts, stat, errmsg)
      type(options_t), intent(out) :: opts          !< the options
      integer, intent(out) :: stat                  !< 0, or 1 for a wrong command line
      character(len=*), intent(inout) :: errmsg     !< what is wrong
      character(len=:), allocatable :: arg, value, what
      integer :: i, n
      allocate (opts%settings(0))
      opts%deck_path = '';  opts%trace = '';  opts%accuracy = ''
      what = ''
      value = ''          ! (else gfortran 12 at -O2 takes its length for unset in the loop)
      n = command_argument_count()
      i = 0
      options: do while (i < n .and. len(what) == 0)
         i = i + 1
         arg = argument(i)
         select case (arg)
         case ('--help', '-h'); opts%action = 'help'
         case ('--version', '--schema', '--deck-table'); opts%action = arg(3:)
         case ('--check'); opts%check = .true.
         case ('--overwrite'); opts%overwrite = .true.
         case ('--restart'); opts%restart = .true.
         case ('--single'); opts%single = .true.
         case ('--set', '--trace', '--accuracy')
            if (i < n) value = argument(i + 1)
            if (i == n) then
               what = arg // ' needs a value'
            else if (len_trim(value) == 0) then        ! (an unset variable in a job script)
               what = arg // ' needs a value: it is empty'
            else if (arg == '--set' .and. len(value) > len(opts%settings)) then   ! it would be cut
               what = '--set: longer than ' // int_str(len(opts%settings)) // ' characters'
            else if (arg == '--set') then
               opts%settings = [opts%settings, value]
            else if (arg == '--trace') then
               opts%trace = value
            else
               opts%accuracy = value
            end if
            i = i + 1
         case default
            if (arg(1:min(1, len(arg))) == '-' .and. len(arg) > 1) then
               what = 'unknown option ' // arg
            else if (len(opts%deck_path) > 0) then
               what = 'one deck only: ''' // arg // ''' follows the deck ' // opts%deck_path
            else
               opts%deck_path = arg
            end if
         end select
      end do options
      stat = merge(1, 0, len(what) > 0)
      if (stat /= 0) errmsg = what
   end subroutine parse_command_line

   !> The deck the options name, with --set, --accuracy, --single and
   !> --overwrite over it, then checked once.
   subroutine read_input_deck(opts, unit, deck, stat, errmsg)
      type(options_t), intent(in) :: opts           !< the options
      integer, intent(in) :: unit                   !< standard input's unit
      type(deck_t), intent(out) :: deck             !< the deck
      integer, intent(out) :: stat                  !< 0 on success
      character(len=*), intent(inout) :: errmsg     !< the one-line message on failure
      integer :: i
      if (len(opts%deck_path) > 0) then
         call read_deck_file(opts%deck_path, deck, stat, errmsg, check=.false.)
      else
         call read_deck(unit, '<stdin>', deck, stat, errmsg, check=.false.)
      end if
      if (stat /= 0) return
      do i = 1, size(opts%settings)
         call set_variable(deck, trim(opts%settings(i)), stat, errmsg, check=.false.)
         if (stat /= 0) return
      end do
      if (len(opts%accuracy) > 0) &
         call set_variable(deck, 'accuracy.target=' // opts%accuracy, stat, errmsg, check=.false.)
      if (stat /= 0) errmsg = '--accuracy ' // opts%accuracy // ': ' // trim(errmsg)
      if (stat == 0 .and. opts%single .and. len(opts%accuracy) > 0) then
         errmsg = '--single and --accuracy: one run, or a ladder of runs, not both'
         stat = 1
      end if
      if (stat /= 0) return
      if (opts%single) deck%accuracy_target = not_given_real()
      if (opts%overwrite) deck%overwrite = .true.
      call validate_deck(deck, stat, errmsg)
      if (stat /= 0 .and. len(deck%settings) > 0) errmsg = trim(errmsg) // ' (with ' // deck%settings // ')'
   end subroutine read_input_deck

   !> Command-line argument i, whole.
   function argument(i) result(arg)
      integer, intent(in) :: i
      character(len=:), allocatable :: arg
      integer :: n
      call get_command_argument(i, length=n)
      allocate (character(len=n) :: arg)
      if (n > 0) call get_command_argument(i, arg)
   end function argument

end module command_line
