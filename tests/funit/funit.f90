!> Stand-in for pFUnit 4's `funit` module: just enough for the subset of the
!> .pf syntax that tests/funit/pf2f90.py accepts, so that `make test` needs
!> nothing but a Fortran compiler and Python.
!>
!> The names, argument order and pass rules are pFUnit 4's:
!>   assertEqual(expected, actual [, tolerance=t] [, message=m])
!>       integer, real(dp) and logical scalars and arrays (rank 1 and 2; a
!>       scalar expected stands for every element), character scalars;
!>       reals pass when actual == expected or |actual - expected| <= t
!>       (t = 0 when absent); strings ignore leading and trailing blanks.
!>   assertRelativelyEqual(expected, actual, tolerance=t [, message=m])
!>       real(dp) scalar and rank 1: |actual - expected| <= t*|expected|;
!>       a zero expected value fails.
!>   assertLessThan(lhs, rhs)            lhs <  rhs (+ t for reals)
!>   assertLessThanOrEqual(lhs, rhs)     lhs <= rhs (+ t)
!>   assertGreaterThan(lhs, rhs)         lhs >  rhs (- t)
!>   assertGreaterThanOrEqual(lhs, rhs)  lhs >= rhs (- t)
!>       integer and real(dp) scalars; lhs may be an integer against a real
!>       rhs, not the other way round (as in pFUnit).
!>   assertTrue(condition), assertFalse(condition)   scalar or rank 1
!>   assertIsFinite(x)                    real(dp) scalar
!>
!> Every assertion records the first failure of the running test (where and
!> why); the code pf2f90.py generates returns from the test right after a
!> failed assertion, as pFUnit's does (`if (anyExceptions()) return`).
!> The generated driver runs each test through funit_run and ends with
!> funit_summary.
!>
!> The state of the running test lives in this module (a test harness cannot
!> do without it); funit_run resets it before every test.
module funit
   use, intrinsic :: iso_fortran_env, only: dp => real64, output_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   implicit none
   private

   ! What the translated .pf files use (pFUnit 4 names).
   public :: SourceLocation, anyExceptions
   public :: assertEqual, assertRelativelyEqual
   public :: assertLessThan, assertLessThanOrEqual
   public :: assertGreaterThan, assertGreaterThanOrEqual
   public :: assertTrue, assertFalse, assertIsFinite
   ! What the generated driver uses.
   public :: funit_test_procedure, funit_run, funit_summary

   !> Where an assertion stands in its .pf file.
   type :: SourceLocation
      !> Path of the .pf file, as given to pf2f90.py.
      character(len=256) :: file_name = '<unknown file>'
      !> Line of the assertion in that file.
      integer :: line_number = 0
   end type SourceLocation

   !> Outcome so far of the running test: its first failure only.
   type :: test_state
      logical :: failed = .false.
      !> "file:line" of the first failed assertion.
      character(len=:), allocatable :: where
      !> Why it failed, after the user's message if one was given.
      character(len=:), allocatable :: what
   end type test_state

   abstract interface
      !> A test, or the @before / @after of its module.
      subroutine funit_test_procedure()
      end subroutine funit_test_procedure
   end interface

   interface
      !> C's exit: ends the run with a status and without a STOP banner.
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   interface assertEqual
      module procedure equal_int_0_0, equal_int_0_1, equal_int_1_1, &
         equal_int_0_2, equal_int_2_2
      module procedure equal_real_0_0, equal_real_0_1, equal_real_1_1, &
         equal_real_0_2, equal_real_2_2
      module procedure equal_int_real_0_0, equal_int_real_0_1, equal_int_real_0_2
      module procedure equal_logical_0_0, equal_logical_0_1, equal_logical_1_1
      module procedure equal_character
   end interface assertEqual

   interface assertRelativelyEqual
      module procedure relative_0_0, relative_0_1, relative_1_1
   end interface assertRelativelyEqual

   interface assertLessThan
      module procedure less_int, less_real, less_int_real
   end interface assertLessThan

   interface assertLessThanOrEqual
      module procedure less_equal_int, less_equal_real, less_equal_int_real
   end interface assertLessThanOrEqual

   interface assertGreaterThan
      module procedure greater_int, greater_real, greater_int_real
   end interface assertGreaterThan

   interface assertGreaterThanOrEqual
      module procedure greater_equal_int, greater_equal_real, greater_equal_int_real
   end interface assertGreaterThanOrEqual

   interface assertTrue
      module procedure true_0, true_1
   end interface assertTrue

   interface assertFalse
      module procedure false_0, false_1
   end interface assertFalse

   interface assertIsFinite
      module procedure is_finite_0, is_finite_1
   end interface assertIsFinite

   !> The four orderings of the comparison assertions.
   integer, parameter :: op_lt = 1, op_le = 2, op_gt = 3, op_ge = 4
   character(len=*), parameter :: op_words(4) = [character(len=24) :: &
      'less than', 'less than or equal to', 'greater than', 'greater than or equal to']

   type(test_state) :: current
   integer :: n_passed = 0
   integer :: n_failed = 0

contains

   ! ------------------------------------------------------------------
   ! Running tests
   ! ------------------------------------------------------------------

   !> Run one test with its module's @before and @after around it and print
   !> "PASS name" or "FAIL name  file:line  message". When the program was
   !> given arguments, only tests whose name contains one of them run.
   subroutine funit_run(module_name, test_name, test, before, after)
      !> the test's module and its own name, printed as module.test
      character(len=*), intent(in) :: module_name, test_name
      !> the @test subroutine
      procedure(funit_test_procedure) :: test
      !> the module's @before and @after subroutines, if any
      procedure(funit_test_procedure), optional :: before, after
      character(len=:), allocatable :: name

      name = module_name // '.' // test_name
      if (.not. selected(name)) return
      current = test_state()
      if (present(before)) call before()
      if (.not. current%failed) call test()
      if (present(after)) call after()

      if (current%failed) then
         n_failed = n_failed + 1
         write(output_unit, '(a)') 'FAIL ' // name // '  ' // current%where // '  ' // current%what
      else
         n_passed = n_passed + 1
         write(output_unit, '(a)') 'PASS ' // name
      end if
      flush(output_unit)
   end subroutine funit_run

   !> Print "N passed, N failed" as the last line; exit with status 1 when a
   !> test failed.
   subroutine funit_summary()
      write(output_unit, '(i0, a, i0, a)') n_passed, ' passed, ', n_failed, ' failed'
      flush(output_unit)
      if (n_failed > 0) call c_exit(1_c_int)
   end subroutine funit_summary

   !> Whether the test called name runs: always, unless the program has
   !> arguments and none of them is part of the name.
   logical function selected(name)
      !> module.test
      character(len=*), intent(in) :: name
      character(len=256) :: pattern
      integer :: i

      selected = command_argument_count() == 0
      do i = 1, command_argument_count()
         call get_command_argument(i, pattern)
         if (index(name, trim(pattern)) > 0) selected = .true.
      end do
   end function selected

   !> Whether the running test has failed (pFUnit's name).
   logical function anyExceptions()
      anyExceptions = current%failed
   end function anyExceptions

   !> Record a failure unless the running test already has one.
   subroutine record_failure(detail, message, location)
      !> what went wrong
      character(len=*), intent(in) :: detail
      !> the user's message= argument
      character(len=*), intent(in), optional :: message
      !> where the assertion stands in its .pf file
      type(SourceLocation), intent(in), optional :: location

      if (current%failed) return
      current%failed = .true.
      current%where = '<unknown location>'
      if (present(location)) then
         current%where = trim(location%file_name) // ':' // int_str(location%line_number)
      end if
      current%what = detail
      if (present(message)) then
         if (len_trim(message) > 0) current%what = trim(message) // ': ' // detail
      end if
   end subroutine record_failure

   !> Record that expected and actual do not have the same shape.
   subroutine fail_shape(expected_shape, actual_shape, message, location)
      !> shapes of the two arguments
      integer, intent(in) :: expected_shape(:), actual_shape(:)
      !> the user's message= argument
      character(len=*), intent(in), optional :: message
      !> where the assertion stands
      type(SourceLocation), intent(in), optional :: location

      call record_failure('nonconforming arrays: expected shape ' // shape_str(expected_shape) &
         // ' but found shape ' // shape_str(actual_shape), message, location)
   end subroutine fail_shape

   ! ------------------------------------------------------------------
   ! Formatting
   ! ------------------------------------------------------------------

   !> An integer without blanks.
   pure function int_str(i) result(s)
      integer, intent(in) :: i
      character(len=:), allocatable :: s
      character(len=24) :: buffer

      write(buffer, '(i0)') i
      s = trim(buffer)
   end function int_str

   !> A real with all its digits and without blanks.
   function real_str(x) result(s)
      real(dp), intent(in) :: x
      character(len=:), allocatable :: s
      character(len=48) :: buffer

      write(buffer, '(g0)') x
      s = trim(adjustl(buffer))
   end function real_str

   !> ".true." or ".false.".
   pure function logical_str(l) result(s)
      logical, intent(in) :: l
      character(len=:), allocatable :: s

      if (l) then
         s = '.true.'
      else
         s = '.false.'
      end if
   end function logical_str

   !> A shape as "(3,4)"; a scalar as "()".
   pure function shape_str(shp) result(s)
      integer, intent(in) :: shp(:)
      character(len=:), allocatable :: s
      integer :: i

      s = '('
      do i = 1, size(shp)
         if (i > 1) s = s // ','
         s = s // int_str(shp(i))
      end do
      s = s // ')'
   end function shape_str

   !> " at index (i)" or " at index (i,j)" for element k (in array element
   !> order) of an array of shape shp; nothing for a scalar.
   pure function at_index(k, shp) result(s)
      !> position of the element in array element order
      integer, intent(in) :: k
      !> shape of the array (empty for a scalar)
      integer, intent(in) :: shp(:)
      character(len=:), allocatable :: s

      select case (size(shp))
      case (0)
         s = ''
      case (1)
         s = ' at index (' // int_str(k) // ')'
      case default
         s = ' at index (' // int_str(mod(k - 1, shp(1)) + 1) // ',' &
            // int_str((k - 1) / shp(1) + 1) // ')'
      end select
   end function at_index

   !> s without leading and trailing blanks and tabs.
   pure function strip(s) result(t)
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      character(len=*), parameter :: blanks = ' ' // achar(9)
      integer :: first, last

      first = verify(s, blanks)
      last = verify(s, blanks, back=.true.)
      if (first == 0) then
         t = ''
      else
         t = s(first:last)
      end if
   end function strip

   ! ------------------------------------------------------------------
   ! The checks every assertion ends in (arrays flattened to rank 1)
   ! ------------------------------------------------------------------

   !> Integers, element by element.
   subroutine check_equal_int(expected, actual, shp, message, location)
      !> expected and actual values, same size
      integer, intent(in) :: expected(:), actual(:)
      !> shape of actual as written in the test
      integer, intent(in) :: shp(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      integer :: k

      do k = 1, size(actual)
         if (expected(k) /= actual(k)) then
            call record_failure('expected <' // int_str(expected(k)) // '> but found <' &
               // int_str(actual(k)) // '>' // at_index(k, shp), message, location)
            return
         end if
      end do
   end subroutine check_equal_int

   !> Reals, element by element: equal, or within tolerance (pFUnit's rule).
   subroutine check_equal_real(expected, actual, tolerance, shp, message, location)
      !> expected and actual values, same size
      real(dp), intent(in) :: expected(:), actual(:)
      !> largest accepted |actual - expected|; 0 when absent
      real(dp), intent(in), optional :: tolerance
      !> shape of actual as written in the test
      integer, intent(in) :: shp(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      real(dp) :: tol
      integer :: k

      tol = 0.0_dp
      if (present(tolerance)) tol = tolerance
      do k = 1, size(actual)
         if (actual(k) == expected(k)) cycle
         if (abs(actual(k) - expected(k)) <= tol) cycle
         call record_failure('expected <' // real_str(expected(k)) // '> but found <' &
            // real_str(actual(k)) // '>' // at_index(k, shp) // ', difference <' &
            // real_str(actual(k) - expected(k)) // '> not within tolerance <' &
            // real_str(tol) // '>', message, location)
         return
      end do
   end subroutine check_equal_real

   !> Logicals, element by element.
   subroutine check_equal_logical(expected, actual, shp, message, location)
      !> expected and actual values, same size
      logical, intent(in) :: expected(:), actual(:)
      !> shape of actual as written in the test
      integer, intent(in) :: shp(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      integer :: k

      do k = 1, size(actual)
         if (expected(k) .neqv. actual(k)) then
            call record_failure('expected <' // logical_str(expected(k)) // '> but found <' &
               // logical_str(actual(k)) // '>' // at_index(k, shp), message, location)
            return
         end if
      end do
   end subroutine check_equal_logical

   !> Reals, element by element: |actual - expected| <= tolerance*|expected|.
   subroutine check_relative(expected, actual, tolerance, shp, message, location)
      !> expected and actual values, same size
      real(dp), intent(in) :: expected(:), actual(:)
      !> largest accepted relative difference
      real(dp), intent(in) :: tolerance
      !> shape of actual as written in the test
      integer, intent(in) :: shp(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      integer :: k

      do k = 1, size(actual)
         if (expected(k) == 0.0_dp) then
            call record_failure('zero expected value' // at_index(k, shp) &
               // ': a relative difference is undefined', message, location)
            return
         end if
         if (abs(actual(k) - expected(k)) <= tolerance * abs(expected(k))) cycle
         call record_failure('expected <' // real_str(expected(k)) // '> but found <' &
            // real_str(actual(k)) // '>' // at_index(k, shp) // ', relative difference <' &
            // real_str((actual(k) - expected(k)) / expected(k)) &
            // '> not within tolerance <' // real_str(tolerance) // '>', message, location)
         return
      end do
   end subroutine check_relative

   !> lhs <op> rhs for reals, the tolerance widening the accepted side.
   subroutine check_order_real(lhs, rhs, op, tolerance, message, location)
      !> the two sides of the comparison
      real(dp), intent(in) :: lhs, rhs
      !> op_lt, op_le, op_gt or op_ge
      integer, intent(in) :: op
      !> slack in favour of passing; 0 when absent
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      real(dp) :: tol
      logical :: holds

      tol = 0.0_dp
      if (present(tolerance)) tol = tolerance
      select case (op)
      case (op_lt)
         holds = lhs < rhs + tol
      case (op_le)
         holds = lhs <= rhs + tol
      case (op_gt)
         holds = lhs > rhs - tol
      case default
         holds = lhs >= rhs - tol
      end select
      if (holds) return
      if (tol > 0.0_dp) then
         call record_failure('expected <' // real_str(lhs) // '> to be ' // trim(op_words(op)) &
            // ' <' // real_str(rhs) // '> within tolerance <' // real_str(tol) // '>', &
            message, location)
      else
         call record_failure('expected <' // real_str(lhs) // '> to be ' // trim(op_words(op)) &
            // ' <' // real_str(rhs) // '>', message, location)
      end if
   end subroutine check_order_real

   !> lhs <op> rhs for integers.
   subroutine check_order_int(lhs, rhs, op, message, location)
      !> the two sides of the comparison
      integer, intent(in) :: lhs, rhs
      !> op_lt, op_le, op_gt or op_ge
      integer, intent(in) :: op
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location
      logical :: holds

      select case (op)
      case (op_lt)
         holds = lhs < rhs
      case (op_le)
         holds = lhs <= rhs
      case (op_gt)
         holds = lhs > rhs
      case default
         holds = lhs >= rhs
      end select
      if (.not. holds) call record_failure('expected <' // int_str(lhs) // '> to be ' &
         // trim(op_words(op)) // ' <' // int_str(rhs) // '>', message, location)
   end subroutine check_order_int

   ! ------------------------------------------------------------------
   ! assertEqual
   ! ------------------------------------------------------------------

   subroutine equal_int_0_0(expected, actual, message, location)
      integer, intent(in) :: expected, actual
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_int([expected], [actual], shape(actual), message, location)
   end subroutine equal_int_0_0

   subroutine equal_int_0_1(expected, actual, message, location)
      integer, intent(in) :: expected, actual(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_int(spread(expected, 1, size(actual)), actual, shape(actual), &
         message, location)
   end subroutine equal_int_0_1

   subroutine equal_int_1_1(expected, actual, message, location)
      integer, intent(in) :: expected(:), actual(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (size(expected) /= size(actual)) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_equal_int(expected, actual, shape(actual), message, location)
   end subroutine equal_int_1_1

   subroutine equal_int_0_2(expected, actual, message, location)
      integer, intent(in) :: expected, actual(:,:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_int(spread(expected, 1, size(actual)), reshape(actual, [size(actual)]), &
         shape(actual), message, location)
   end subroutine equal_int_0_2

   subroutine equal_int_2_2(expected, actual, message, location)
      integer, intent(in) :: expected(:,:), actual(:,:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (any(shape(expected) /= shape(actual))) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_equal_int(reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), &
         shape(actual), message, location)
   end subroutine equal_int_2_2

   subroutine equal_real_0_0(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected, actual
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_real([expected], [actual], tolerance, shape(actual), message, location)
   end subroutine equal_real_0_0

   subroutine equal_real_0_1(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected, actual(:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_real(spread(expected, 1, size(actual)), actual, tolerance, shape(actual), &
         message, location)
   end subroutine equal_real_0_1

   subroutine equal_real_1_1(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected(:), actual(:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (size(expected) /= size(actual)) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_equal_real(expected, actual, tolerance, shape(actual), message, location)
   end subroutine equal_real_1_1

   subroutine equal_real_0_2(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected, actual(:,:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_real(spread(expected, 1, size(actual)), reshape(actual, [size(actual)]), &
         tolerance, shape(actual), message, location)
   end subroutine equal_real_0_2

   subroutine equal_real_2_2(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected(:,:), actual(:,:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (any(shape(expected) /= shape(actual))) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_equal_real(reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), &
         tolerance, shape(actual), message, location)
   end subroutine equal_real_2_2

   subroutine equal_int_real_0_0(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(dp), intent(in) :: actual
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call equal_real_0_0(real(expected, dp), actual, tolerance, message, location)
   end subroutine equal_int_real_0_0

   subroutine equal_int_real_0_1(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(dp), intent(in) :: actual(:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call equal_real_0_1(real(expected, dp), actual, tolerance, message, location)
   end subroutine equal_int_real_0_1

   subroutine equal_int_real_0_2(expected, actual, tolerance, message, location)
      integer, intent(in) :: expected
      real(dp), intent(in) :: actual(:,:)
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call equal_real_0_2(real(expected, dp), actual, tolerance, message, location)
   end subroutine equal_int_real_0_2

   subroutine equal_logical_0_0(expected, actual, message, location)
      logical, intent(in) :: expected, actual
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_logical([expected], [actual], shape(actual), message, location)
   end subroutine equal_logical_0_0

   subroutine equal_logical_0_1(expected, actual, message, location)
      logical, intent(in) :: expected, actual(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_equal_logical(spread(expected, 1, size(actual)), actual, shape(actual), &
         message, location)
   end subroutine equal_logical_0_1

   subroutine equal_logical_1_1(expected, actual, message, location)
      logical, intent(in) :: expected(:), actual(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (size(expected) /= size(actual)) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_equal_logical(expected, actual, shape(actual), message, location)
   end subroutine equal_logical_1_1

   !> Strings are equal when they are once leading and trailing blanks and
   !> tabs are removed (pFUnit's default, TRIM_ALL).
   subroutine equal_character(expected, actual, message, location)
      character(len=*), intent(in) :: expected, actual
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (strip(expected) == strip(actual)) return
      call record_failure('expected <"' // strip(expected) // '"> but found <"' &
         // strip(actual) // '">', message, location)
   end subroutine equal_character

   ! ------------------------------------------------------------------
   ! assertRelativelyEqual
   ! ------------------------------------------------------------------

   subroutine relative_0_0(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected, actual
      real(dp), intent(in) :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_relative([expected], [actual], tolerance, shape(actual), message, location)
   end subroutine relative_0_0

   subroutine relative_0_1(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected, actual(:)
      real(dp), intent(in) :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_relative(spread(expected, 1, size(actual)), actual, tolerance, shape(actual), &
         message, location)
   end subroutine relative_0_1

   subroutine relative_1_1(expected, actual, tolerance, message, location)
      real(dp), intent(in) :: expected(:), actual(:)
      real(dp), intent(in) :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (size(expected) /= size(actual)) then
         call fail_shape(shape(expected), shape(actual), message, location)
         return
      end if
      call check_relative(expected, actual, tolerance, shape(actual), message, location)
   end subroutine relative_1_1

   ! ------------------------------------------------------------------
   ! assertLessThan, assertLessThanOrEqual, assertGreaterThan,
   ! assertGreaterThanOrEqual: (lhs, rhs) passes when lhs <op> rhs
   ! ------------------------------------------------------------------

   subroutine less_int(lhs, rhs, message, location)
      integer, intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_int(lhs, rhs, op_lt, message, location)
   end subroutine less_int

   subroutine less_real(lhs, rhs, tolerance, message, location)
      real(dp), intent(in) :: lhs, rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(lhs, rhs, op_lt, tolerance, message, location)
   end subroutine less_real

   subroutine less_int_real(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(dp), intent(in) :: rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(real(lhs, dp), rhs, op_lt, tolerance, message, location)
   end subroutine less_int_real

   subroutine less_equal_int(lhs, rhs, message, location)
      integer, intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_int(lhs, rhs, op_le, message, location)
   end subroutine less_equal_int

   subroutine less_equal_real(lhs, rhs, tolerance, message, location)
      real(dp), intent(in) :: lhs, rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(lhs, rhs, op_le, tolerance, message, location)
   end subroutine less_equal_real

   subroutine less_equal_int_real(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(dp), intent(in) :: rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(real(lhs, dp), rhs, op_le, tolerance, message, location)
   end subroutine less_equal_int_real

   subroutine greater_int(lhs, rhs, message, location)
      integer, intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_int(lhs, rhs, op_gt, message, location)
   end subroutine greater_int

   subroutine greater_real(lhs, rhs, tolerance, message, location)
      real(dp), intent(in) :: lhs, rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(lhs, rhs, op_gt, tolerance, message, location)
   end subroutine greater_real

   subroutine greater_int_real(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(dp), intent(in) :: rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(real(lhs, dp), rhs, op_gt, tolerance, message, location)
   end subroutine greater_int_real

   subroutine greater_equal_int(lhs, rhs, message, location)
      integer, intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_int(lhs, rhs, op_ge, message, location)
   end subroutine greater_equal_int

   subroutine greater_equal_real(lhs, rhs, tolerance, message, location)
      real(dp), intent(in) :: lhs, rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(lhs, rhs, op_ge, tolerance, message, location)
   end subroutine greater_equal_real

   subroutine greater_equal_int_real(lhs, rhs, tolerance, message, location)
      integer, intent(in) :: lhs
      real(dp), intent(in) :: rhs
      real(dp), intent(in), optional :: tolerance
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call check_order_real(real(lhs, dp), rhs, op_ge, tolerance, message, location)
   end subroutine greater_equal_int_real

   ! ------------------------------------------------------------------
   ! assertTrue, assertFalse, assertIsFinite
   ! ------------------------------------------------------------------

   subroutine true_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (.not. condition) call record_failure('expected .true. but found .false.', &
         message, location)
   end subroutine true_0

   subroutine true_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (.not. all(condition)) call record_failure('expected .true. but found .false.' &
         // at_index(findloc_false(condition), shape(condition)), message, location)
   end subroutine true_1

   subroutine false_0(condition, message, location)
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (condition) call record_failure('expected .false. but found .true.', message, location)
   end subroutine false_0

   subroutine false_1(condition, message, location)
      logical, intent(in) :: condition(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (any(condition)) call record_failure('expected .false. but found .true.' &
         // at_index(findloc_false(.not. condition), shape(condition)), message, location)
   end subroutine false_1

   !> Position of the first .false. in l (0 if none).
   pure integer function findloc_false(l)
      logical, intent(in) :: l(:)
      integer :: k

      findloc_false = 0
      do k = 1, size(l)
         if (.not. l(k)) then
            findloc_false = k
            return
         end if
      end do
   end function findloc_false

   subroutine is_finite_0(x, message, location)
      real(dp), intent(in) :: x
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      if (.not. ieee_is_finite(x)) call record_failure('expected a finite value but found <' &
         // real_str(x) // '>', message, location)
   end subroutine is_finite_0

   !> pFUnit 4's assertIsFinite takes a scalar only, so a .pf file that passes
   !> it an array would not compile there: fail, saying what to write instead.
   subroutine is_finite_1(x, message, location)
      real(dp), intent(in) :: x(:)
      character(len=*), intent(in), optional :: message
      type(SourceLocation), intent(in), optional :: location

      call record_failure('@assertIsFinite takes a scalar in pFUnit 4 (array of size ' &
         // int_str(size(x)) // ' given): write @assertTrue(all(ieee_is_finite(x)))', &
         message, location)
   end subroutine is_finite_1

end module funit
