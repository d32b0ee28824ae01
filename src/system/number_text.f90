!> Numbers as text, one place for the formats: real_str (the fewest digits
!> that read back to the same double), real_short (four digits), int_str, and
!> put_es16_7e3, put_f16_4, put_i6: the history's numbers as those edit
!> descriptors write them, byte for byte, without the formatted write (which
!> takes a number near a rounding boundary). The proof: tests/test_number_text.pf.
module number_text
   use, intrinsic :: iso_fortran_env, only: int64
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use kinds, only: dp
   implicit none
   private
   public :: real_str, real_short, int_str, list_str, put_es16_7e3, put_f16_4, put_i6

   !> The powers of ten a double holds exactly (10**22 is the last).
   real(dp), parameter :: exact_pow10(0:22) = [1.0e0_dp, 1.0e1_dp, 1.0e2_dp, 1.0e3_dp, 1.0e4_dp, 1.0e5_dp, &
      1.0e6_dp, 1.0e7_dp, 1.0e8_dp, 1.0e9_dp, 1.0e10_dp, 1.0e11_dp, 1.0e12_dp, 1.0e13_dp, 1.0e14_dp, 1.0e15_dp, &
      1.0e16_dp, 1.0e17_dp, 1.0e18_dp, 1.0e19_dp, 1.0e20_dp, 1.0e21_dp, 1.0e22_dp]
   !> The fast paths' margin to a rounding boundary, in units of the last digit: the scaled value
   !> is within some 10 roundings (2.2e-15 relative, 2.2e-7 of a digit at 1e8) of the exact one,
   !> so a margin of 1e-5 leaves the rounding of every number it passes certain.
   real(dp), parameter :: tie_margin = 1.0e-5_dp
   !> Magnitudes es16.7e3's fast path takes: their scaling is at most a
   !> few roundings (10.0**p by repeated products beyond 10**22).
   real(dp), parameter :: es_lowest = 1.0e-280_dp, es_highest = 1.0e280_dp
   !> f16.4's fast path: below this the 1e4 multiple is below 1e10, where
   !> its one rounding (half an ulp, under 1e-6) stays well inside tie_margin
   !> (times in us: up to 1 s; later ones by the formatted write).
   real(dp), parameter :: f_highest = 1.0e6_dp
   !> The digits, for the fast paths.
   character(len=10), parameter :: digit_chars = '0123456789'

contains

   !> An integer without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=12) :: buf                      ! -2147483648 at most
      integer(int64) :: m                           ! (-huge(i) - 1 has no default-kind twin)
      integer :: at
      ! the digits from the right, as i0 writes them (an internal write costs some 1 us)
      m = abs(int(i, int64))
      at = len(buf) + 1
      do
         at = at - 1
         buf(at:at) = digit_chars(mod(m, 10_int64) + 1:mod(m, 10_int64) + 1)
         m = m/10
         if (m == 0) exit
      end do
      if (i < 0) then
         at = at - 1
         buf(at:at) = '-'
      end if
      s = buf(at:)
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
      sign = trim(merge('-', ' ', x < 0.0_dp))
      if (x < 0.0_dp) buf = buf(2:)
      epos = index(buf, 'E')
      read (buf(epos + 1:), *) e
      digits = buf(1:1) // buf(3:epos - 1)          ! mantissa d.ddd without the point
      digits = digits(:max(1, verify(digits, '0', back=.true.)))      ! without its trailing zeros
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
      write (buf, '(es24.3e4)') x
      read (buf, *, iostat=ios) rounded
      if (ios /= 0 .or. .not. ieee_is_finite(x)) rounded = x     ! (NaN, Infinity: x itself)
      s = real_str(rounded)
   end function real_short

   !> The reals of x as 'x1, x2, ...', cut short after max_chars characters.
   function list_str(x, max_chars) result(s)
      real(dp), intent(in) :: x(:)
      integer, intent(in) :: max_chars              !< cut after this many characters
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(x)
         if (i > 1) s = s // ', '
         s = s // real_str(x(i))
         if (len(s) > max_chars) then
            s = s // ', ...'
            return
         end if
      end do
   end function list_str

   !> x as es16.7e3 writes it: '  1.2345678E+003', ' -5.0000000E-001'.
   pure subroutine put_es16_7e3(x, text)
      real(dp), intent(in) :: x                     !< the number
      character(len=16), intent(out) :: text        !< its text
      real(dp) :: ax, scaled
      integer(int64) :: n
      integer :: k, e, i, at
      ax = abs(x)
      if (x == 0.0_dp .and. sign(1.0_dp, x) > 0.0_dp) then
         text = '  0.0000000E+000'
         return
      end if
      if (.not. (ax >= es_lowest .and. ax <= es_highest)) then     ! NaN, Inf, -0, huge, tiny
         write (text, '(es16.7e3)') x
         return
      end if
      k = floor(log10(ax))
      scaled = times_pow10(ax, 7 - k)                ! in [1e7, 1e8) when k is right
      if (scaled < 1.0e7_dp) then
         k = k - 1
         scaled = times_pow10(ax, 7 - k)
      else if (scaled >= 1.0e8_dp) then
         k = k + 1
         scaled = times_pow10(ax, 7 - k)
      end if
      if (scaled < 1.0e7_dp + 1.0_dp .or. scaled >= 1.0e8_dp - 1.0_dp &
          .or. abs(scaled - aint(scaled) - 0.5_dp) < tie_margin) then
         write (text, '(es16.7e3)') x               ! near a boundary: the run-time decides
         return
      end if
      n = nint(scaled, int64)
      text = '   .       E+000'
      if (x < 0.0_dp) text(2:2) = '-'
      do i = 11, 4, -1                               ! the 7 decimals, then the leading digit
         at = int(mod(n, 10_int64)) + 1
         text(i:i) = digit_chars(at:at)
         n = n/10
      end do
      text(3:3) = text(4:4)
      text(4:4) = '.'
      if (k < 0) text(13:13) = '-'
      e = abs(k)
      do i = 16, 14, -1
         text(i:i) = digit_chars(mod(e, 10) + 1:mod(e, 10) + 1)
         e = e/10
      end do
   end subroutine put_es16_7e3

   !> x as f16.4 writes it: '       2500.0000'.
   pure subroutine put_f16_4(x, text)
      real(dp), intent(in) :: x                     !< the number
      character(len=16), intent(out) :: text        !< its text
      real(dp) :: scaled
      integer(int64) :: n
      integer :: i, at
      if (.not. (x >= 0.0_dp .and. x < f_highest) .or. (x == 0.0_dp .and. sign(1.0_dp, x) < 0.0_dp)) then
         write (text, '(f16.4)') x                   ! negative, -0, NaN, large: the run-time's
         return
      end if
      scaled = x*exact_pow10(4)
      if (abs(scaled - aint(scaled) - 0.5_dp) < tie_margin) then
         write (text, '(f16.4)') x
         return
      end if
      n = nint(scaled, int64)
      text = ''
      i = 16
      do
         at = int(mod(n, 10_int64)) + 1
         text(i:i) = digit_chars(at:at)
         n = n/10
         i = i - 1
         if (i == 12) then
            text(i:i) = '.'
            i = i - 1
         end if
         if (n == 0 .and. i < 11) exit
      end do
   end subroutine put_f16_4

   !> n as i6 writes it: '    12'.
   pure subroutine put_i6(n, text)
      integer, intent(in) :: n                      !< the number
      character(len=6), intent(out) :: text         !< its text
      text = '******'                                ! what i6 writes of a number it cannot hold
      if (n >= -99999 .and. n <= 999999) text = int_str(n)
      text = adjustr(text)
   end subroutine put_i6

   !> ax 10**p: one rounding for |p| <= 22 (a product or a quotient with an
   !> exact power), a few more beyond.
   pure real(dp) function times_pow10(ax, p)
      real(dp), intent(in) :: ax                    !< the number
      integer, intent(in) :: p                      !< the power
      if (p >= 0 .and. p <= 22) then
         times_pow10 = ax*exact_pow10(p)
      else if (p < 0 .and. p >= -22) then
         times_pow10 = ax/exact_pow10(-p)
      else if (p > 0) then
         times_pow10 = (ax*exact_pow10(22))*10.0_dp**(p - 22)
      else
         times_pow10 = (ax/exact_pow10(22))/10.0_dp**(-p - 22)
      end if
   end function times_pow10

end module number_text
