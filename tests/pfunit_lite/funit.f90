!> pfunit_lite runtime: the subset of pFUnit 4.x's `funit` module that interphase's `.pf` suites
!> use, for machines without pFUnit (see cmake/InterphasePfunit.cmake).
!>
!> Generated test code records the `.pf` location with funit_location() before each assertion and
!> leaves the test when anyExceptions() is true; the generated driver calls funit_initialize(),
!> funit_run_test() once per @test, then funit_finalize(), which prints `N passed, N failed`.
!> Nothing here stops the program: the generated driver turns the result into the exit status.
module funit
   use, intrinsic :: iso_fortran_env, only: dp => real64, output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite
   implicit none
   private

   ! ---- assertions (same generic names and keywords as pFUnit) ----
   public :: assertEqual, assertRelativelyEqual, assertTrue, assertFalse
   public :: assertLessThan, assertLessThanOrEqual, assertGreaterThan, assertGreaterThanOrEqual
   public :: assertAll, assertAny, assertIsFinite, anyExceptions
   ! ---- used by the generated code ----
   public :: funit_location, funit_initialize, funit_run_test, funit_finalize, funit_test_procedure

   ! ---- the names real pFUnit's `funit` exports too ----
   ! A module that uses funit cannot define one of these at its own scope with real pFUnit
   ! (gfortran: "already defined", "conflicts with symbol from module"): pfunit_lite's funit exports
   ! them too, each the same kind of entity as in pFUnit (a type, a constant, a procedure, an
   ! abstract interface, or a generic interface where pFUnit's name is one, which a suite may
   ! extend), so that such a module is refused here as well. The procedures take an argument of a
   ! private type: no call compiles (but `not`'s, as pFUnit's, takes anything: below).
   ! Where the names come from (pFUnit's sources, src/funit, read 2026-12 in the versions of the
   ! 4.1x releases, which 4.12 and 4.14 share): module FUnit has no `private` statement, so it
   ! exports its own procedures and everything the modules it uses export:
   !  - FUnit itself: initialize, run, generic_run, finalize, get_context, stub; iso_fortran_env's
   !    OUTPUT_UNIT;
   !  - FUnit_Core (core/FUnit_Core.F90, its public list; RemoteRunner and RobustRunner under
   !    `Robust`, which pFUnit's build defines unless SKIP_ROBUST);
   !  - PF_Assert (asserts/Assert.F90, its public list: not PF_AssertBasic's fail, assertIsNotNaN,
   !    assertIsInfinite, conformable, nonConformable or UnusableArgument, which it leaves out);
   !  - fHamcrest (fhamcrest/fHamcrest.F90, no `private` either): the public names of
   !    pf_MatcherDescription, pf_StringDescription, pf_MatcherAssert, pf_AbstractMatcher, pf_Is,
   !    pf_IsNot, pf_IsEqual, pf_IsNear, pf_IsRelativelyNear, pf_AnyOf, pf_AllOf, pf_Every,
   !    pf_StringContains, pf_StringStartsWith, pf_StringEndsWith, pf_IsArrayWithSize, pf_Matchable.
   ! Not here: names seen only in some versions of pFUnit's sources and not shown to be in 4.12 or
   ! 4.14 (a name refused here that pFUnit accepts is as wrong as the other way round): fHamcrest's
   ! IsTrueOrFalse, true, false, IsNear_32, IsNear_64 and relational matchers (greater_than, ...),
   ! PF_Assert's assertRelMinEqual and assertApprox.
   ! The assertions and anyExceptions of the first section are among the names (real ones here).
   ! Test, TestSuite and TestMethod are also the names real pFUnit's generated suite function
   ! refers to (so does wrap_<module>'s <module>_suite, with funit_suite_scope).
   ! from FUnit
   public :: initialize, run, generic_run, finalize, get_context, stub, LoadTests_interface
   public :: output_unit
   ! from FUnit_Core
   public :: SourceLocation, Test, TestSuite, TestMethod, TestResult, TestRunner, BaseTestRunner
   public :: RemoteRunner, RobustRunner, TestListener, TestListenerVector, ListenerPointer
   public :: ResultPrinter, XmlPrinter, DebugListener, NameFilter, TestCase, AbstractTestParameter
   public :: ParameterizedTestCase, ParallelContext, SerialContext, throw, catchNext, catch
   public :: Expectation, Subject, Predicate, wasCalled, wasNotCalled, wasCalledOnce
   public :: TestAnnotation, StringTestAnnotationMap, Disable, TimeoutAnnotation, TapListener
   ! from PF_Assert
   public :: assertFail, assertExceptionRaised, assertSameShape, assertNone, assertNotAll
   public :: assertNotEqual, assertIsNan, WhitespaceOptions
   public :: IGNORE_ALL, TRIM_ALL, KEEP_ALL, IGNORE_DIFFERENCES
   ! from fHamcrest
   public :: MatcherDescription, StringDescription, assert_that, AbstractMatcher, Is, IsNot, not
   public :: IsEqual, equal_to, IsNear, near, IsRelativelyNear, relatively_near, AnyOf, any_of
   public :: AllOf, all_of, Every, every_item, StringContains, contains_string, StringStartsWith
   public :: starts_with, StringEndsWith, ends_with, IsArrayWithSize, array_with_size, empty_array
   public :: Matchable
   public :: funit_suite_scope
   ! (types)
   !> Where a failure happened, as pFUnit's (its components in pFUnit's order, so that
   !> SourceLocation(file, line) constructs one): `throw` reports it.
   type :: SourceLocation
      character(len=255) :: fileName = '<unknown file>'
      integer :: lineNumber = -1
   end type SourceLocation
   type :: Test
   end type Test
   type, extends(Test) :: TestMethod
   end type TestMethod
   type, extends(Test) :: TestSuite
   end type TestSuite
   type, extends(Test) :: TestCase
   end type TestCase
   type, extends(TestCase) :: ParameterizedTestCase
   end type ParameterizedTestCase
   type :: TestResult
   end type TestResult
   type :: BaseTestRunner
   end type BaseTestRunner
   type, extends(BaseTestRunner) :: TestRunner
   end type TestRunner
   type, extends(BaseTestRunner) :: RemoteRunner
   end type RemoteRunner
   type, extends(BaseTestRunner) :: RobustRunner
   end type RobustRunner
   type :: TestListener
   end type TestListener
   type :: TestListenerVector
   end type TestListenerVector
   type :: ListenerPointer
   end type ListenerPointer
   type, extends(TestListener) :: ResultPrinter
   end type ResultPrinter
   type, extends(TestListener) :: XmlPrinter
   end type XmlPrinter
   type, extends(TestListener) :: DebugListener
   end type DebugListener
   type, extends(TestListener) :: TapListener
   end type TapListener
   type :: NameFilter
   end type NameFilter
   type :: AbstractTestParameter
   end type AbstractTestParameter
   type :: ParallelContext
   end type ParallelContext
   type, extends(ParallelContext) :: SerialContext
   end type SerialContext
   type :: Subject
   end type Subject
   type :: Predicate
   end type Predicate
   type :: Expectation
   end type Expectation
   type, extends(Predicate) :: wasCalled
   end type wasCalled
   type, extends(Predicate) :: wasNotCalled
   end type wasNotCalled
   type, extends(Predicate) :: wasCalledOnce
   end type wasCalledOnce
   type :: TestAnnotation
   end type TestAnnotation
   type, extends(TestAnnotation) :: TimeoutAnnotation
   end type TimeoutAnnotation
   type :: StringTestAnnotationMap
   end type StringTestAnnotationMap
   type :: WhitespaceOptions
   end type WhitespaceOptions
   type :: MatcherDescription
   end type MatcherDescription
   type, extends(MatcherDescription) :: StringDescription
   end type StringDescription
   type :: AbstractMatcher
   end type AbstractMatcher
   type, extends(AbstractMatcher) :: Is
   end type Is
   type, extends(AbstractMatcher) :: IsNot
   end type IsNot
   type, extends(AbstractMatcher) :: IsEqual
   end type IsEqual
   type, extends(AbstractMatcher) :: IsNear
   end type IsNear
   type, extends(AbstractMatcher) :: IsRelativelyNear
   end type IsRelativelyNear
   type, extends(AbstractMatcher) :: AnyOf
   end type AnyOf
   type, extends(AbstractMatcher) :: AllOf
   end type AllOf
   type, extends(AbstractMatcher) :: Every
   end type Every
   type, extends(AbstractMatcher) :: StringContains
   end type StringContains
   type, extends(AbstractMatcher) :: StringStartsWith
   end type StringStartsWith
   type, extends(AbstractMatcher) :: StringEndsWith
   end type StringEndsWith
   type, extends(AbstractMatcher) :: IsArrayWithSize
   end type IsArrayWithSize
   type :: Matchable
   end type Matchable
   ! (constants; pFUnit's Disable is a variable, of a type it keeps private)
   type(WhitespaceOptions), parameter :: IGNORE_ALL = WhitespaceOptions(), TRIM_ALL = WhitespaceOptions(), &
      KEEP_ALL = WhitespaceOptions(), IGNORE_DIFFERENCES = WhitespaceOptions()
   type(TestAnnotation), parameter :: Disable = TestAnnotation()
   ! (abstract interface)
   abstract interface
      function LoadTests_interface() result(suite)
         import :: TestSuite
         type(TestSuite) :: suite
      end function LoadTests_interface
   end interface
   ! (generic interfaces where pFUnit's names are generics, which a suite may extend: each with
   ! one placeholder specific, a subroutine or a function as pFUnit's, that no call matches ...)
   ! (throw is pFUnit's, not a placeholder: a message and an optional location, and the running
   ! test fails; a suite's own specific taking a message alone is ambiguous here, as with pFUnit)
   interface throw
      module procedure throw_message
   end interface throw
   interface catch
      module procedure placeholder_catch
   end interface catch
   interface assertFail
      module procedure placeholder_assert_fail
   end interface assertFail
   interface assertExceptionRaised
      module procedure placeholder_assert_exception_raised
   end interface assertExceptionRaised
   interface assertIsNan
      module procedure placeholder_assert_is_nan
   end interface assertIsNan
   interface assertNotEqual
      module procedure placeholder_assert_not_equal
   end interface assertNotEqual
   interface assert_that
      module procedure placeholder_assert_that
   end interface assert_that
   interface is
      module procedure placeholder_is
   end interface is
   ! (is, equal_to and not take any value, as pFUnit's specifics do (class(*); equal_to a scalar
   ! or a 1-D array): a suite's own specific of these generics is ambiguous here, as with pFUnit)
   interface equal_to
      module procedure placeholder_equal_to, placeholder_equal_to_1d
   end interface equal_to
   interface near
      module procedure placeholder_near
   end interface near
   interface relatively_near
      module procedure placeholder_relatively_near
   end interface relatively_near
   interface any_of
      module procedure placeholder_any_of
   end interface any_of
   interface all_of
      module procedure placeholder_all_of
   end interface all_of
   interface every_item
      module procedure placeholder_every_item
   end interface every_item
   interface contains_string
      module procedure placeholder_contains_string
   end interface contains_string
   interface starts_with
      module procedure placeholder_starts_with
   end interface starts_with
   interface ends_with
      module procedure placeholder_ends_with
   end interface ends_with
   interface array_with_size
      module procedure placeholder_array_with_size
   end interface array_with_size
   ! (... but `not`, whose pFUnit specific takes class(*): a reference to the intrinsic not(i)
   ! where funit is in scope resolves to it and does not compile with pFUnit, nor here)
   interface not
      module procedure placeholder_not
   end interface not

   !> funit_initialize() status: run the tests, usage shown on request, bad command line.
   integer, parameter, public :: FUNIT_RUN = 0, FUNIT_HELP_SHOWN = 1, FUNIT_USAGE_ERROR = 2

   !> Length of the buffer a number is written into.
   integer, parameter :: NUMBER_LEN = 48
   !> Above this magnitude a - b may overflow, so differences are formed from halves.
   real(dp), parameter :: HALF_HUGE = 0.5_dp * huge(1.0_dp)
   !> Real pFUnit names a module's suite `<module>_suite` and its tests `<module>_suite.<test>`.
   character(len=*), parameter :: SUITE_SUFFIX = '_suite'
   !> Line number meaning "no .pf location recorded".
   integer, parameter :: NO_LINE = 0

   abstract interface
      !> A @test, @before or @after procedure.
      subroutine funit_test_procedure()
      end subroutine funit_test_procedure
   end interface

   interface assertEqual
      module procedure equal_int, equal_int_1d, equal_int_0_1d, equal_logical, equal_string
      module procedure equal_r0, equal_r0_tol, equal_r1, equal_r1_tol, equal_r0_r1, equal_r0_r1_tol
      module procedure equal_r2, equal_r2_tol, equal_r0_r2, equal_r0_r2_tol
   end interface assertEqual

   interface assertRelativelyEqual
      module procedure relatively_equal_r0, relatively_equal_r1, relatively_equal_r0_r1
   end interface assertRelativelyEqual

   interface assertTrue
      module procedure true_0d, true_1d
   end interface assertTrue

   interface assertFalse
      module procedure false_0d, false_1d
   end interface assertFalse

   interface assertLessThan
      module procedure less_than_int, less_than_real
   end interface assertLessThan

   interface assertLessThanOrEqual
      module procedure less_equal_int, less_equal_real
   end interface assertLessThanOrEqual

   interface assertGreaterThan
      module procedure greater_than_int, greater_than_real
   end interface assertGreaterThan

   interface assertGreaterThanOrEqual
      module procedure greater_equal_int, greater_equal_real
   end interface assertGreaterThanOrEqual

   interface assertIsFinite
      module procedure is_finite_r0
   end interface assertIsFinite

   interface anyExceptions
      module procedure any_exceptions
   end interface anyExceptions

   !> As pFUnit's KeywordEnforcer: an optional dummy of a type no caller can name, placed
   !> before `message` where pFUnit has one (logical assertEqual, integer orderings), so that a
   !> positional message matches no specific procedure and does not compile, as with pFUnit.
   type :: keyword_enforcer_type
   end type keyword_enforcer_type

   ! ---- state of the run ----
   character(len=:), allocatable :: location_file   !! .pf file of the assertion being checked
   integer :: location_line = NO_LINE               !! its line, NO_LINE when unknown
   character(len=:), allocatable :: current_test    !! "<module>_suite.test" of the running test
   logical :: current_failed = .false.              !! an assertion of the running test failed
   character(len=:), allocatable :: name_filter     !! run only tests whose name contains this
   logical :: verbose = .false.                     !! print one line per test run
   integer :: n_passed = 0, n_failed = 0

contains

   ! =============================== driver side ===============================

   !> Does nothing: wrap_<module>'s <module>_suite declares real pFUnit's suite function's locals
   !> (`type(TestSuite) :: suite`, `class(Test), allocatable :: t`) and hands them here.
   subroutine funit_suite_scope(suite, t)
      type(TestSuite), intent(in) :: suite
      class(Test), intent(in) :: t
      associate (unused_suite => suite, unused_t => t)
      end associate
   end subroutine funit_suite_scope

   ! (placeholders for real pFUnit's procedures of these names: see the public statements;
   ! a subroutine where pFUnit's is one, else a function)
   subroutine initialize(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine initialize
   subroutine finalize(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine finalize
   subroutine stub(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine stub
   subroutine assertSameShape(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine assertSameShape
   subroutine assertNone(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine assertNone
   subroutine assertNotAll(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine assertNotAll
   !> throw(message[, location]): the running test fails with the message (pFUnit's exception),
   !> at the location given (else '(unknown location)': the generated code marks assertions only).
   subroutine throw_message(message, location)
      character(len=*), intent(in) :: message
      type(SourceLocation), intent(in), optional :: location
      if (present(location)) then
         location_file = trim(location%fileName)
         location_line = location%lineNumber
      end if
      call conclude(.false., 'throw', message)
   end subroutine throw_message
   subroutine placeholder_assert_fail(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine placeholder_assert_fail
   subroutine placeholder_assert_exception_raised(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine placeholder_assert_exception_raised
   subroutine placeholder_assert_is_nan(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine placeholder_assert_is_nan
   subroutine placeholder_assert_not_equal(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine placeholder_assert_not_equal
   subroutine placeholder_assert_that(unusable)
      type(keyword_enforcer_type), intent(in) :: unusable
      associate (unused => unusable)
      end associate
   end subroutine placeholder_assert_that
   function run(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      logical :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = .false.
   end function run
   function generic_run(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      logical :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = .false.
   end function generic_run
   function get_context(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(ParallelContext) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = ParallelContext()
   end function get_context
   function catchNext(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(TestResult) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = TestResult()
   end function catchNext
   function empty_array(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(IsArrayWithSize) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = IsArrayWithSize()
   end function empty_array
   function placeholder_catch(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      logical :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = .false.
   end function placeholder_catch
   function placeholder_is(value) result(placeholder)
      class(*), intent(in) :: value
      type(Is) :: placeholder
      associate (unused => value)
      end associate
      placeholder = Is()
   end function placeholder_is
   function placeholder_equal_to(operand) result(placeholder)
      class(*), intent(in) :: operand
      type(IsEqual) :: placeholder
      associate (unused => operand)
      end associate
      placeholder = IsEqual()
   end function placeholder_equal_to
   function placeholder_equal_to_1d(operand) result(placeholder)
      class(*), intent(in) :: operand(:)
      type(IsEqual) :: placeholder
      associate (unused => operand)
      end associate
      placeholder = IsEqual()
   end function placeholder_equal_to_1d
   function placeholder_near(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(IsNear) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = IsNear()
   end function placeholder_near
   function placeholder_relatively_near(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(IsRelativelyNear) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = IsRelativelyNear()
   end function placeholder_relatively_near
   function placeholder_any_of(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(AnyOf) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = AnyOf()
   end function placeholder_any_of
   function placeholder_all_of(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(AllOf) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = AllOf()
   end function placeholder_all_of
   function placeholder_every_item(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(Every) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = Every()
   end function placeholder_every_item
   function placeholder_contains_string(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(StringContains) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = StringContains()
   end function placeholder_contains_string
   function placeholder_starts_with(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(StringStartsWith) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = StringStartsWith()
   end function placeholder_starts_with
   function placeholder_ends_with(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(StringEndsWith) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = StringEndsWith()
   end function placeholder_ends_with
   function placeholder_array_with_size(unusable) result(placeholder)
      type(keyword_enforcer_type), intent(in) :: unusable
      type(IsArrayWithSize) :: placeholder
      associate (unused => unusable)
      end associate
      placeholder = IsArrayWithSize()
   end function placeholder_array_with_size
   !> pFUnit's not(value) takes any value (class(*)): so does this one, which returns a matcher.
   function placeholder_not(value) result(placeholder)
      class(*), intent(in) :: value
      type(IsNot) :: placeholder
      associate (unused => value)
      end associate
      placeholder = IsNot()
   end function placeholder_not

   !> Reads the command line: `[-f|--filter] NAME`, `-v|--verbose`, `-h|--help`.
   subroutine funit_initialize(status)
      integer, intent(out) :: status   !! FUNIT_RUN, FUNIT_HELP_SHOWN or FUNIT_USAGE_ERROR
      integer :: i, n_args
      character(len=:), allocatable :: arg

      status = FUNIT_RUN
      n_args = command_argument_count()
      i = 0
      do while (i < n_args)
         i = i + 1
         arg = argument(i)
         select case (arg)
         case ('-h', '--help')
            call print_usage(output_unit)
            status = FUNIT_HELP_SHOWN
            return
         case ('-v', '--verbose', '-d', '--debug')
            verbose = .true.
         case ('-f', '--filter')
            if (i == n_args .or. allocated(name_filter)) then
               status = FUNIT_USAGE_ERROR
            else
               i = i + 1
               name_filter = lower(argument(i))
            end if
         case default
            if (arg(1:min(1, len(arg))) == '-' .or. allocated(name_filter)) then
               status = FUNIT_USAGE_ERROR
            else
               name_filter = lower(arg)
            end if
         end select
         if (status == FUNIT_USAGE_ERROR) then
            write (error_unit, '(3a)') 'funit: unexpected argument "', arg, '"'
            call print_usage(error_unit)
            return
         end if
      end do
   end subroutine funit_initialize

   !> Runs one test (unless filtered out): before, then the test and after if before passed; tallies.
   subroutine funit_run_test(suite, name, test, before, after)
      character(len=*), intent(in) :: suite   !! module of the test
      character(len=*), intent(in) :: name    !! test procedure
      procedure(funit_test_procedure) :: test
      procedure(funit_test_procedure), optional :: before, after

      ! (real pFUnit's name of the test: its suite is `<module>_suite`, ../shared/PFUNIT.md)
      current_test = suite // SUITE_SUFFIX // '.' // name
      if (allocated(name_filter)) then
         if (index(lower(current_test), name_filter) == 0) return
      end if
      current_failed = .false.
      if (present(before)) call before()
      ! as pFUnit's TestCase%runBare: the test and the after procedure only when before raised nothing
      if (.not. current_failed) then
         call test()
         if (present(after)) call after()
      end if
      if (current_failed) then
         n_failed = n_failed + 1
         if (verbose) write (output_unit, '(2a)') 'FAILED  ', current_test
      else
         n_passed = n_passed + 1
         if (verbose) write (output_unit, '(2a)') 'passed  ', current_test
      end if
      location_line = NO_LINE
   end subroutine funit_run_test

   !> Prints the closing line `N passed, N failed`.
   subroutine funit_finalize(all_passed)
      logical, intent(out) :: all_passed   !! no test failed
      if (allocated(name_filter) .and. n_passed + n_failed == 0) then
         write (output_unit, '(3a)') 'funit: no test name contains "', name_filter, '"'
      end if
      write (output_unit, '(i0, a, i0, a)') n_passed, ' passed, ', n_failed, ' failed'
      flush (output_unit)
      all_passed = n_failed == 0
   end subroutine funit_finalize

   !> Records where the next assertion is written (set by the generated code).
   subroutine funit_location(file, line)
      character(len=*), intent(in) :: file   !! .pf file name
      integer, intent(in) :: line            !! line in that file
      location_file = file
      location_line = line
   end subroutine funit_location

   !> anyExceptions(): true once an assertion of the running test has failed (pFUnit's name, a
   !> generic there too).
   logical function any_exceptions()
      any_exceptions = current_failed
   end function any_exceptions

   ! ================================ equality =================================

   subroutine equal_int(expected, actual, message)
      integer, intent(in) :: expected, actual
      character(len=*), intent(in), optional :: message
      call conclude(expected == actual, 'assertEqual', &
         'expected <' // int_str(expected) // '> but found <' // int_str(actual) // '>', message)
   end subroutine equal_int

   subroutine equal_int_1d(expected, actual, message)
      integer, intent(in) :: expected(:), actual(:)
      character(len=*), intent(in), optional :: message
      integer :: k, n_bad

      if (.not. same_shape('assertEqual', shape(expected), shape(actual), message)) return
      n_bad = count(expected /= actual)
      if (n_bad == 0) then
         call conclude(.true., 'assertEqual', '', message)
      else
         k = findloc(expected /= actual, .true., dim=1)
         call conclude(.false., 'assertEqual', 'expected <' // int_str(expected(k)) // '> but found <' &
            // int_str(actual(k)) // '>' // where_str(k, shape(actual), n_bad), message)
      end if
   end subroutine equal_int_1d

   subroutine equal_int_0_1d(expected, actual, message)
      integer, intent(in) :: expected, actual(:)
      character(len=*), intent(in), optional :: message
      integer :: e(size(actual))
      e = expected
      call equal_int_1d(e, actual, message)
   end subroutine equal_int_0_1d

   subroutine equal_logical(expected, actual, unused, message)
      logical, intent(in) :: expected, actual
      type(keyword_enforcer_type), intent(in), optional :: unused
      character(len=*), intent(in), optional :: message
      if (present(unused)) continue
      call conclude(expected .eqv. actual, 'assertEqual', &
         'expected <' // logical_str(expected) // '> but found <' // logical_str(actual) // '>', message)
   end subroutine equal_logical

   !> Strings are equal when they differ only by leading and trailing whitespace, blanks and tabs
   !> (pFUnit's default, TRIM_ALL: its trimAll strips both, then the rest must be the same).
   !> The second argument is `found`, as in pFUnit's string assertion (its numeric ones call it
   !> `actual`), so that a keyword call compiles here only where it compiles with pFUnit.
   subroutine equal_string(expected, found, message)
      character(len=*), intent(in) :: expected, found
      character(len=*), intent(in), optional :: message
      character(len=:), allocatable :: e, f
      e = trim_whitespace(expected)
      f = trim_whitespace(found)
      call conclude(len(e) == len(f) .and. e == f, 'assertEqual', &
         'expected <"' // e // '"> but found <"' // f // '">', message)
   end subroutine equal_string

   !> text without its leading and trailing blanks and tabs.
   function trim_whitespace(text) result(trimmed)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: trimmed
      character(len=*), parameter :: WHITESPACE = ' ' // achar(9)
      integer :: first, last
      first = verify(text, WHITESPACE)
      if (first == 0) then
         trimmed = ''
      else
         last = verify(text, WHITESPACE, back=.true.)
         trimmed = text(first:last)
      end if
   end function trim_whitespace

   subroutine equal_r0(expected, actual, message)
      real(dp), intent(in) :: expected, actual
      character(len=*), intent(in), optional :: message
      call check_reals('assertEqual', [expected], [actual], 0.0_dp, .false., [integer ::], message)
   end subroutine equal_r0

   subroutine equal_r0_tol(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected, actual, tolerance
      character(len=*), intent(in), optional :: message
      call check_reals('assertEqual', [expected], [actual], tolerance, .false., [integer ::], message)
   end subroutine equal_r0_tol

   subroutine equal_r1(expected, actual, message)
      real(dp), intent(in) :: expected(:), actual(:)
      character(len=*), intent(in), optional :: message
      call equal_r1_tol(expected, actual, 0.0_dp, message)
   end subroutine equal_r1

   subroutine equal_r1_tol(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected(:), actual(:), tolerance
      character(len=*), intent(in), optional :: message
      if (.not. same_shape('assertEqual', shape(expected), shape(actual), message)) return
      call check_reals('assertEqual', expected, actual, tolerance, .false., shape(actual), message)
   end subroutine equal_r1_tol

   subroutine equal_r0_r1(expected, actual, message)
      real(dp), intent(in) :: expected, actual(:)
      character(len=*), intent(in), optional :: message
      call equal_r0_r1_tol(expected, actual, 0.0_dp, message)
   end subroutine equal_r0_r1

   subroutine equal_r0_r1_tol(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected, actual(:), tolerance
      character(len=*), intent(in), optional :: message
      real(dp) :: e(size(actual))
      e = expected
      call check_reals('assertEqual', e, actual, tolerance, .false., shape(actual), message)
   end subroutine equal_r0_r1_tol

   subroutine equal_r2(expected, actual, message)
      real(dp), intent(in) :: expected(:, :), actual(:, :)
      character(len=*), intent(in), optional :: message
      call equal_r2_tol(expected, actual, 0.0_dp, message)
   end subroutine equal_r2

   subroutine equal_r2_tol(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected(:, :), actual(:, :), tolerance
      character(len=*), intent(in), optional :: message
      if (.not. same_shape('assertEqual', shape(expected), shape(actual), message)) return
      call check_reals('assertEqual', reshape(expected, [size(expected)]), reshape(actual, [size(actual)]), &
         tolerance, .false., shape(actual), message)
   end subroutine equal_r2_tol

   subroutine equal_r0_r2(expected, actual, message)
      real(dp), intent(in) :: expected, actual(:, :)
      character(len=*), intent(in), optional :: message
      call equal_r0_r2_tol(expected, actual, 0.0_dp, message)
   end subroutine equal_r0_r2

   subroutine equal_r0_r2_tol(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected, actual(:, :), tolerance
      character(len=*), intent(in), optional :: message
      real(dp) :: e(size(actual))
      e = expected
      call check_reals('assertEqual', e, reshape(actual, [size(actual)]), tolerance, .false., shape(actual), message)
   end subroutine equal_r0_r2_tol

   subroutine relatively_equal_r0(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected, actual, tolerance
      character(len=*), intent(in), optional :: message
      call check_reals('assertRelativelyEqual', [expected], [actual], tolerance, .true., [integer ::], message)
   end subroutine relatively_equal_r0

   subroutine relatively_equal_r1(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected(:), actual(:), tolerance
      character(len=*), intent(in), optional :: message
      if (.not. same_shape('assertRelativelyEqual', shape(expected), shape(actual), message)) return
      call check_reals('assertRelativelyEqual', expected, actual, tolerance, .true., shape(actual), message)
   end subroutine relatively_equal_r1

   subroutine relatively_equal_r0_r1(expected, actual, tolerance, message)
      real(dp), intent(in) :: expected, actual(:), tolerance
      character(len=*), intent(in), optional :: message
      real(dp) :: e(size(actual))
      e = expected
      call check_reals('assertRelativelyEqual', e, actual, tolerance, .true., shape(actual), message)
   end subroutine relatively_equal_r0_r1

   !> Element-wise check |e - a| <= tol (relative: <= tol*|e|, and e must not be 0, as in pFUnit).
   !> actual_shape is empty for a scalar, else the shape used to print the first bad index.
   subroutine check_reals(assertion, expected, actual, tolerance, relative, actual_shape, message)
      character(len=*), intent(in) :: assertion
      real(dp), intent(in) :: expected(:), actual(:), tolerance
      logical, intent(in) :: relative
      integer, intent(in) :: actual_shape(:)
      character(len=*), intent(in), optional :: message
      logical :: ok(size(actual))
      integer :: k, n_bad
      character(len=:), allocatable :: detail

      do k = 1, size(actual)
         if (relative) then
            ok(k) = relatively_within(expected(k), actual(k), tolerance)
         else
            ok(k) = within(expected(k), actual(k), tolerance)
         end if
      end do
      n_bad = count(.not. ok)
      if (n_bad == 0) then
         call conclude(.true., assertion, '', message)
         return
      end if
      k = findloc(ok, .false., dim=1)
      detail = 'expected <' // real_str(expected(k)) // '> but found <' // real_str(actual(k)) // '>'
      if (size(actual_shape) > 0) detail = detail // where_str(k, actual_shape, n_bad)
      if (relative .and. is_zero(expected(k))) then
         detail = detail // '; expected value is zero, a relative tolerance is meaningless'
      else if (relative) then
         detail = detail // '; ' // difference_str(expected(k), actual(k)) // &
            'relative tolerance ' // real_str(tolerance) // ' * |expected|'
      else
         detail = detail // '; ' // difference_str(expected(k), actual(k)) // 'tolerance ' // real_str(tolerance)
      end if
      call conclude(.false., assertion, detail, message)
   end subroutine check_reals

   !> |e - a| <= tol without floating-point exceptions (NaN never passes; equal infinities do).
   !> Operands are tested for NaN before any ordered comparison: a comparison with NaN raises
   !> the invalid flag, which traps when the tests run with -ffpe-trap=invalid.
   elemental logical function within(e, a, tol)
      real(dp), intent(in) :: e, a, tol
      if (ieee_is_nan(e) .or. ieee_is_nan(a) .or. ieee_is_nan(tol)) then
         within = .false.
      else if (.not. (e < a .or. e > a)) then
         within = .true.
      else if (.not. (ieee_is_finite(e) .and. ieee_is_finite(a))) then
         within = .false.
      else if (max(abs(e), abs(a)) > HALF_HUGE) then
         within = abs(0.5_dp * e - 0.5_dp * a) <= 0.5_dp * tol
      else
         within = abs(e - a) <= tol
      end if
   end function within

   !> |e - a| <= tol*|e|; a zero expected value always fails, as in pFUnit, and so does an infinite
   !> one (pFUnit's |a - e| is NaN for a = e = Inf, and Inf <= tol*Inf would pass any finite a: never
   !> accepted here).
   elemental logical function relatively_within(e, a, tol)
      real(dp), intent(in) :: e, a, tol
      if (ieee_is_nan(e) .or. is_zero(e) .or. .not. ieee_is_finite(e)) then
         relatively_within = .false.
      else
         relatively_within = within(e, a, tol * abs(e))
      end if
   end function relatively_within

   elemental logical function is_zero(x)
      real(dp), intent(in) :: x
      is_zero = .false.
      if (.not. ieee_is_nan(x)) is_zero = .not. (abs(x) > 0.0_dp)
   end function is_zero

   ! ============================ logical conditions ============================

   subroutine true_0d(condition, message)
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: message
      call conclude(condition, 'assertTrue', 'condition is false', message)
   end subroutine true_0d

   subroutine true_1d(condition, message)
      logical, intent(in) :: condition(:)
      character(len=*), intent(in), optional :: message
      call check_logicals('assertTrue', condition, .true., message)
   end subroutine true_1d

   subroutine false_0d(condition, message)
      logical, intent(in) :: condition
      character(len=*), intent(in), optional :: message
      call conclude(.not. condition, 'assertFalse', 'condition is true', message)
   end subroutine false_0d

   subroutine false_1d(condition, message)
      logical, intent(in) :: condition(:)
      character(len=*), intent(in), optional :: message
      call check_logicals('assertFalse', condition, .false., message)
   end subroutine false_1d

   subroutine assertAll(conditions, message)
      logical, intent(in) :: conditions(:)
      character(len=*), intent(in), optional :: message
      call check_logicals('assertAll', conditions, .true., message)
   end subroutine assertAll

   subroutine assertAny(conditions, message)
      logical, intent(in) :: conditions(:)
      character(len=*), intent(in), optional :: message
      call conclude(any(conditions), 'assertAny', 'all ' // int_str(size(conditions)) // ' elements are false', &
         message)
   end subroutine assertAny

   !> Every element of conditions must equal wanted.
   subroutine check_logicals(assertion, conditions, wanted, message)
      character(len=*), intent(in) :: assertion
      logical, intent(in) :: conditions(:), wanted
      character(len=*), intent(in), optional :: message
      integer :: n_bad

      n_bad = count(conditions .neqv. wanted)
      if (n_bad == 0) then
         call conclude(.true., assertion, '', message)
      else
         call conclude(.false., assertion, 'element is ' // logical_str(.not. wanted) &
            // where_str(findloc(conditions, .not. wanted, dim=1), shape(conditions), n_bad), message)
      end if
   end subroutine check_logicals

   subroutine is_finite_r0(x, message)
      real(dp), intent(in) :: x
      character(len=*), intent(in), optional :: message
      call conclude(ieee_is_finite(x), 'assertIsFinite', 'value is <' // real_str(x) // '>', message)
   end subroutine is_finite_r0


   ! =============================== orderings =================================

   subroutine less_than_int(lhs, rhs, unused, message)
      integer, intent(in) :: lhs, rhs
      type(keyword_enforcer_type), intent(in), optional :: unused
      character(len=*), intent(in), optional :: message
      if (present(unused)) continue
      call conclude(lhs < rhs, 'assertLessThan', int_str(lhs) // ' is not < ' // int_str(rhs), message)
   end subroutine less_than_int

   subroutine less_equal_int(lhs, rhs, unused, message)
      integer, intent(in) :: lhs, rhs
      type(keyword_enforcer_type), intent(in), optional :: unused
      character(len=*), intent(in), optional :: message
      if (present(unused)) continue
      call conclude(lhs <= rhs, 'assertLessThanOrEqual', int_str(lhs) // ' is not <= ' // int_str(rhs), message)
   end subroutine less_equal_int

   subroutine greater_than_int(lhs, rhs, unused, message)
      integer, intent(in) :: lhs, rhs
      type(keyword_enforcer_type), intent(in), optional :: unused
      character(len=*), intent(in), optional :: message
      if (present(unused)) continue
      call conclude(lhs > rhs, 'assertGreaterThan', int_str(lhs) // ' is not > ' // int_str(rhs), message)
   end subroutine greater_than_int

   subroutine greater_equal_int(lhs, rhs, unused, message)
      integer, intent(in) :: lhs, rhs
      type(keyword_enforcer_type), intent(in), optional :: unused
      character(len=*), intent(in), optional :: message
      if (present(unused)) continue
      call conclude(lhs >= rhs, 'assertGreaterThanOrEqual', int_str(lhs) // ' is not >= ' // int_str(rhs), message)
   end subroutine greater_equal_int

   subroutine less_than_real(lhs, rhs, message)
      real(dp), intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      call check_order('assertLessThan', lhs, rhs, '<', message)
   end subroutine less_than_real

   subroutine less_equal_real(lhs, rhs, message)
      real(dp), intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      call check_order('assertLessThanOrEqual', lhs, rhs, '<=', message)
   end subroutine less_equal_real

   subroutine greater_than_real(lhs, rhs, message)
      real(dp), intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      call check_order('assertGreaterThan', lhs, rhs, '>', message)
   end subroutine greater_than_real

   subroutine greater_equal_real(lhs, rhs, message)
      real(dp), intent(in) :: lhs, rhs
      character(len=*), intent(in), optional :: message
      call check_order('assertGreaterThanOrEqual', lhs, rhs, '>=', message)
   end subroutine greater_equal_real

   !> lhs <relation> rhs for reals; a NaN operand fails without being compared, so that the
   !> comparison cannot raise an invalid-operation trap (tests may run with -ffpe-trap=invalid).
   subroutine check_order(assertion, lhs, rhs, relation, message)
      character(len=*), intent(in) :: assertion
      real(dp), intent(in) :: lhs, rhs
      character(len=*), intent(in) :: relation   !! '<', '<=', '>' or '>='
      character(len=*), intent(in), optional :: message
      logical :: holds

      holds = .false.
      if (.not. (ieee_is_nan(lhs) .or. ieee_is_nan(rhs))) then
         select case (relation)
         case ('<')
            holds = lhs < rhs
         case ('<=')
            holds = lhs <= rhs
         case ('>')
            holds = lhs > rhs
         case ('>=')
            holds = lhs >= rhs
         end select
      end if
      call conclude(holds, assertion, real_str(lhs) // ' is not ' // relation // ' ' // real_str(rhs), message)
   end subroutine check_order

   ! ================================ reporting ================================

   !> Ends every assertion: on failure marks the test failed and prints one line
   !> `file.pf:LINE: FAILED suite.test: assertion: detail; message: "..."`.
   subroutine conclude(passed, assertion, detail, message)
      logical, intent(in) :: passed
      character(len=*), intent(in) :: assertion, detail
      character(len=*), intent(in), optional :: message
      character(len=:), allocatable :: where, who, note

      if (.not. passed) then
         current_failed = .true.
         if (location_line == NO_LINE) then
            where = '(unknown location)'
         else
            where = location_file // ':' // int_str(location_line)
         end if
         who = '(outside a test)'
         if (allocated(current_test)) who = current_test
         note = ''
         if (present(message)) then
            if (len_trim(message) > 0) note = '; message: "' // trim(message) // '"'
         end if
         write (output_unit, '(a)') where // ': FAILED ' // who // ': ' // assertion // ': ' // detail // note
      end if
      location_line = NO_LINE
   end subroutine conclude

   !> Fails with a shape message unless the shapes agree; returns whether they do.
   logical function same_shape(assertion, expected_shape, actual_shape, message)
      character(len=*), intent(in) :: assertion
      integer, intent(in) :: expected_shape(:), actual_shape(:)
      character(len=*), intent(in), optional :: message
      same_shape = all(expected_shape == actual_shape)
      if (.not. same_shape) call conclude(.false., assertion, 'expected shape ' // shape_str(expected_shape) &
         // ' but found shape ' // shape_str(actual_shape), message)
   end function same_shape

   !> " at index (i,j) (n of m elements differ)" for element k (array element order) of an array.
   function where_str(k, array_shape, n_bad) result(text)
      integer, intent(in) :: k, array_shape(:), n_bad
      character(len=:), allocatable :: text
      integer :: position(size(array_shape)), rest, d

      rest = k - 1
      do d = 1, size(array_shape)
         position(d) = mod(rest, array_shape(d)) + 1
         rest = rest / array_shape(d)
      end do
      text = ' at index ' // shape_str(position) // ' (' // int_str(n_bad) // ' of ' &
         // int_str(product(array_shape)) // ' elements differ)'
   end function where_str

   function shape_str(values) result(text)
      integer, intent(in) :: values(:)
      character(len=:), allocatable :: text
      integer :: d
      text = '('
      do d = 1, size(values)
         text = text // int_str(values(d))
         if (d < size(values)) text = text // ','
      end do
      text = text // ')'
   end function shape_str

   !> "|difference| d > " when |e - a| can be formed without an exception, else "".
   function difference_str(e, a) result(text)
      real(dp), intent(in) :: e, a
      character(len=:), allocatable :: text
      text = ''
      if (.not. (ieee_is_finite(e) .and. ieee_is_finite(a))) return   ! no ordered compare of NaN
      if (max(abs(e), abs(a)) <= HALF_HUGE) text = '|difference| ' // real_str(abs(e - a)) // ' > '
   end function difference_str

   function int_str(value) result(text)
      integer, intent(in) :: value
      character(len=:), allocatable :: text
      character(len=NUMBER_LEN) :: buffer
      write (buffer, '(i0)') value
      text = trim(buffer)
   end function int_str

   function real_str(value) result(text)
      real(dp), intent(in) :: value
      character(len=:), allocatable :: text
      character(len=NUMBER_LEN) :: buffer
      ! g0.17 and the leading zero written out: the same text with every compiler (the zero of
      ! a magnitude below 1 is processor dependent: gfortran writes 0.5, flang .5)
      write (buffer, '(g0.17)') value
      text = trim(adjustl(buffer))
      if (text(1:1) == '.') then
         text = '0'//text
      else if (len(text) > 1) then
         if (text(1:2) == '-.') text = '-0'//text(2:)
      end if
   end function real_str

   function logical_str(value) result(text)
      logical, intent(in) :: value
      character(len=:), allocatable :: text
      if (value) then
         text = '.true.'
      else
         text = '.false.'
      end if
   end function logical_str

   !> Command argument i, any length.
   function argument(i) result(arg)
      integer, intent(in) :: i
      character(len=:), allocatable :: arg
      integer :: arg_len
      call get_command_argument(i, length=arg_len)
      allocate (character(len=arg_len) :: arg)
      call get_command_argument(i, arg(:))
   end function argument

   pure function lower(text) result(low)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: low
      integer, parameter :: CASE_SHIFT = iachar('a') - iachar('A')
      integer :: i
      low = text
      do i = 1, len(text)
         if (lge(text(i:i), 'A') .and. lle(text(i:i), 'Z')) low(i:i) = achar(iachar(text(i:i)) + CASE_SHIFT)
      end do
   end function lower

   subroutine print_usage(unit)
      integer, intent(in) :: unit
      write (unit, '(a)') 'usage: <test executable> [-v|--verbose] [[-f|--filter] NAME]', &
         '  runs every test (or those whose "<module>_suite.<test>" name contains NAME, ignoring case)', &
         '  and ends with the line "N passed, N failed"; exit status 1 if any test failed.'
   end subroutine print_usage

end module funit
