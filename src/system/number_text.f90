!> Numbers as text, for messages, echoes and the summary: one place for
!> the formats.
!>
!>  - real_str: the fewest significant digits that read back to the same
!>    double (0.15, 1.2e11, 2.5e-6): the deck's echo and its messages;
!>  - real_short: rounded to four significant digits: warnings;
!>  - int_str: an integer without blanks.
module number_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use kinds, only: dp
   implicit none
   private
   public :: real_str, real_short, int_str, list_str

contains

   !> An integer without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buf
      write (buf, '(i0)') i
      s = trim(buf)
   end function int_str

   !> x with the fewest significant digits that read back to the same
   !> double: 0.15, 1.2E+11, 2.5E-06.
   pure function real_str(x) result(s)
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

   !> x rounded to four significant digits, written as real_str writes it:
   !> 5.004, 1.843e-3, 1.2e11.
   pure function real_short(x) result(s)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=24) :: buf
      real(dp) :: rounded
      integer :: ios
      if (.not. ieee_is_finite(x)) then
         s = real_str(x)
         return
      end if
      write (buf, '(es24.3e4)') x
      read (buf, *, iostat=ios) rounded
      if (ios /= 0) rounded = x
      s = real_str(rounded)
   end function real_short

   !> The reals of x as 'x1, x2, ...', cut short after max_chars characters.
   function list_str(x, max_chars) result(s)
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: max_chars              !< cut after this many characters
      character(len=:), allocatable :: s
      integer :: i, limit
      limit = max_chars
      s = ''
      do i = 1, size(x)
         if (i > 1) s = s // ', '
         s = s // real_str(x(i))
         if (len(s) > limit) then
            s = s // ', ...'
            return
         end if
      end do
   end function list_str


end module number_text
