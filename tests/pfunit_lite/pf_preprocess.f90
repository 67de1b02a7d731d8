!> pfunit_lite preprocessor: translates one pFUnit `.pf` test file into Fortran.
!>
!>    pf_preprocess <input.pf> <output.F90>
!>
!> Supported (the subset of pFUnit 4.x that interphase uses): `@test` (without options), `@before`,
!> `@after`, each on its own line before a module subroutine without arguments, and one-line
!> assertions `@assertXxx(...)` whose names are in ASSERTIONS. Other lines are copied
!> verbatim. An assertion becomes `call funit_location(file, line)`, `call assertXxx(...)` and
!> `if (anyExceptions()) return`, with `#line` markers so that compiler messages (and backtraces)
!> point at the .pf lines. After the file a module `wrap_<module>` is appended whose `<module>_suite` runs the
!> tests in file order through funit_run_test. Anything else starting with `@`, an assertion with a
!> trailing comment, an @assert line that real pFUnit would truncate (over 132 - 8 columns without
!> its indentation), a @test/@before/@after before anything but a line of the one form real pFUnit
!> reads, `subroutine name()` with an optional comment (it skips `recursive subroutine`,
!> `subroutine name() bind(c)`, a continued line etc. in silence after @test, and stops after
!> @before/@after, where a `#` line is not allowed either), @test options (real pFUnit gives them
!> meaning: ifdef=, npes=, ...), a file whose `module name` lines (the form real pFUnit reads:
!> nothing after the name, not even a comment) are not exactly one, named like the file, a module
!> name longer than 57 characters (real pFUnit's suite function `<module>_suite`), or a test whose
!> registration line in real pFUnit's generated code (`      <test>, setUp=<before>,
!> tearDown=<after>))`) would pass 132 columns is an error: message `file:line: error: ...`
!> on standard error, no output file, exit status 1.
program pf_preprocess
   use, intrinsic :: iso_fortran_env, only: error_unit, iostat_eor, iostat_end
   implicit none

   !> Longest Fortran name.
   integer, parameter :: MAX_NAME_LEN = 63
   !> Suffix of the suite function real pFUnit generates for a module (`<module>_suite`).
   character(len=*), parameter :: PFUNIT_SUITE_SUFFIX = '_suite'
   !> Longest free-form line; a longer generated statement is continued on further lines
   !> (pieces of at least MIN_CHUNK_LEN characters, whatever the indentation).
   integer, parameter :: MAX_LINE_LEN = 132, MIN_CHUNK_LEN = 60
   !> Columns real pFUnit adds to an @assert line (without its indentation) when it writes the
   !> assertion on one generated line (docs: ../shared/PFUNIT.md).
   integer, parameter :: PFUNIT_EXTRA_COLUMNS = 8
   !> Buffer length when reading a line piecewise.
   integer, parameter :: READ_CHUNK = 256
   !> Prefix of the appended module that registers the tests.
   character(len=*), parameter :: WRAP_PREFIX = 'wrap_'
   !> What the pending `@` line announced: nothing, a test, the before or the after procedure.
   integer, parameter :: NONE = 0, TEST = 1, BEFORE = 2, AFTER = 3
   character(len=*), parameter :: DIRECTIVE_NAMES(0:3) = ['       ', '@test  ', '@before', '@after ']
   !> Supported assertions, spelled as in pFUnit (directives are matched ignoring case).
   character(len=*), parameter :: ASSERTIONS(11) = [character(len=24) :: &
      'assertEqual', 'assertRelativelyEqual', 'assertTrue', 'assertFalse', 'assertLessThan', &
      'assertLessThanOrEqual', 'assertGreaterThan', 'assertGreaterThanOrEqual', 'assertAll', &
      'assertAny', 'assertIsFinite']
   character(len=*), parameter :: TAB = achar(9), CR = achar(13)

   !> A test in a growing list: its name and the line of its subroutine statement.
   type :: name_t
      character(len=:), allocatable :: s
      integer :: line = 0
   end type name_t

   character(len=:), allocatable :: in_path, out_path, pf_file, module_name, line, text
   character(len=:), allocatable :: before_name, after_name
   type(name_t), allocatable :: tests(:)
   !> the `module name` lines read (more than one, or one named otherwise than the file, is refused)
   integer :: module_lines
   integer :: in_unit, out_unit, ios, line_no, out_line, pending, pending_line
   logical :: at_end

   call get_arguments(in_path, out_path)
   pf_file = base_name(in_path)
   if (index(pf_file, '.') > 0) then
      module_name = pf_file(1:index(pf_file, '.', back=.true.) - 1)
   else
      module_name = pf_file
   end if

   open (newunit=in_unit, file=in_path, status='old', action='read', iostat=ios)
   if (ios /= 0) call stop_usage('cannot read ' // in_path)
   open (newunit=out_unit, file=out_path, status='replace', action='write', iostat=ios)
   if (ios /= 0) call stop_usage('cannot write ' // out_path)

   allocate (tests(0))
   module_lines = 0
   before_name = ''
   after_name = ''
   pending = NONE
   pending_line = 0
   line_no = 0
   out_line = 0
   call emit('#line 1 "' // in_path // '"')
   do
      call read_line(in_unit, line, at_end)
      if (at_end) exit
      line_no = line_no + 1
      text = trim(strip_leading(line))
      if (text(1:min(1, len(text))) == '@') then
         call translate_directive()
      else
         ! (real pFUnit reads the line after @before/@after skipping only blank and `!` lines)
         if ((pending == BEFORE .or. pending == AFTER) .and. text(1:min(1, len(text))) == '#') &
            call fail(line_no, trim(DIRECTIVE_NAMES(pending)) // ' (line ' // int_str(pending_line) // &
            ') must be followed by its subroutine line: real pFUnit reads the next line that is not blank or ' &
            // 'a "!" comment as the subroutine statement, and stops at a preprocessor line')
         if (pending /= NONE .and. is_statement(text)) call take_procedure()
         call check_module_statement()
         call emit(line)
      end if
   end do
   close (in_unit)
   if (pending /= NONE) call fail(pending_line, trim(DIRECTIVE_NAMES(pending)) // ' is not followed by a subroutine')
   if (module_lines == 0) call fail(1, 'no "module ' // module_name // '" statement: pFUnit needs each .pf file to ' &
      // 'hold one module named like the file')
   if (len(module_name) + len(PFUNIT_SUITE_SUFFIX) > MAX_NAME_LEN) call fail(1, 'module name "' // module_name // &
      '" is ' // int_str(len(module_name)) // ' characters: real pFUnit names the suite function "' // module_name // &
      PFUNIT_SUITE_SUFFIX // '", longer than ' // int_str(MAX_NAME_LEN) // ' (at most ' // &
      int_str(MAX_NAME_LEN - len(PFUNIT_SUITE_SUFFIX)) // ' characters)')
   call check_registration_lines()
   call emit_wrapper()
   close (out_unit)

contains

   !> Handles a line starting with `@` (text is the line without leading blanks).
   subroutine translate_directive()
      character(len=:), allocatable :: name, rest, canonical
      integer :: i, close_at

      i = 2
      do while (i <= len(text))
         if (.not. is_name_char(text(i:i))) exit
         i = i + 1
      end do
      name = text(2:i - 1)
      rest = trim(adjustl(text(i:)))
      if (pending /= NONE) call fail(pending_line, trim(DIRECTIVE_NAMES(pending)) // &
         ' is not followed by a subroutine')

      select case (lower(name))
      case ('test', 'before', 'after')
         if (lower(name) == 'test') then
            pending = TEST
            ! (`@test()`, empty parentheses, is a plain @test for real pFUnit too)
            if (len(rest) > 0) then
               if (rest(1:1) /= '(' .or. matching_paren(rest) /= len(rest)) &
                  call fail(line_no, 'expected "@test" alone on the line')
               if (len_trim(rest(2:len(rest) - 1)) > 0) &
                  call fail(line_no, 'test options ("@test' // rest // '") are not supported by pfunit_lite: real ' &
                  // 'pFUnit gives them meaning (ifdef= leaves the test out unless the macro is defined, npes= ' &
                  // 'makes it an MPI test, ...) that pfunit_lite cannot reproduce; write "@test" alone')
            end if
         else
            pending = merge(BEFORE, AFTER, lower(name) == 'before')
            if (len(rest) > 0) call fail(line_no, 'expected "@' // name // '" alone on the line')
         end if
         pending_line = line_no
         call emit(line(1:index(line, '@') - 1) // '! ' // trim(text))
         return
      end select

      canonical = ''
      do i = 1, size(ASSERTIONS)
         if (lower(name) == lower(trim(ASSERTIONS(i)))) canonical = trim(ASSERTIONS(i))
      end do
      if (len(canonical) == 0) call fail(line_no, 'unsupported directive "@' // name // '" (pfunit_lite knows ' &
         // '@test, @before, @after and @assert + Equal, RelativelyEqual, True, False, LessThan[OrEqual], ' &
         // 'GreaterThan[OrEqual], All, Any, IsFinite)')
      if (rest(1:min(1, len(rest))) /= '(') call fail(line_no, '"@' // name // '" must be followed by "(arguments)"')
      close_at = matching_paren(rest)
      if (close_at == 0) call fail(line_no, 'unbalanced parentheses in "@' // name // '": an assertion must be on one line')
      if (close_at < len(rest)) then
         if (adjustl(rest(close_at + 1:)) == '&') then
            call fail(line_no, 'an assertion must be on one line (no "&" continuation)')
         else if (index(rest(close_at + 1:), '!') > 0) then
            call fail(line_no, 'trailing comment on an @assert line: real pFUnit does not translate such a line; ' &
               // 'put the comment on its own line')
         else
            call fail(line_no, 'unexpected text after the closing parenthesis of "@' // name // '"')
         end if
      end if

      if (len(text) + PFUNIT_EXTRA_COLUMNS > MAX_LINE_LEN) call fail(line_no, '"@' // name // '" line is ' // &
         int_str(len(text)) // ' columns without its indentation: real pFUnit writes it on one line about ' // &
         int_str(PFUNIT_EXTRA_COLUMNS) // ' columns longer, over ' // int_str(MAX_LINE_LEN) // ' ("Line truncated")')
      associate (indent => line(1:index(line, '@') - 1))
         call emit(indent // 'call funit_location(''' // quoted(pf_file) // ''', ' // int_str(line_no) // ')')
         call emit('#line ' // int_str(line_no) // ' "' // in_path // '"')
         call emit_statement(indent, 'call ' // canonical // rest)
         call emit(indent // 'if (anyExceptions()) return')
      end associate
      call emit('#line ' // int_str(line_no + 1) // ' "' // in_path // '"')
   end subroutine translate_directive

   !> Reads the name of the subroutine announced by the pending @test/@before/@after.
   subroutine take_procedure()
      character(len=:), allocatable :: word, rest, after_name_text, statement
      integer :: close_at

      statement = text
      do
         call split_word(statement, word, rest)
         select case (lower(word))
         case ('recursive', 'non_recursive', 'impure', 'pure', 'elemental', 'module')
            call fail(line_no, trim(DIRECTIVE_NAMES(pending)) // ' (line ' // int_str(pending_line) // &
               ') must be followed by a line that starts with "subroutine"; real pFUnit silently skips "' // &
               word // ' subroutine" (it takes the next plain subroutine instead)')
         case ('subroutine')
            exit
         case default
            call fail(line_no, trim(DIRECTIVE_NAMES(pending)) // ' (line ' // int_str(pending_line) // &
               ') must be followed by a module subroutine, found "' // text // '"')
         end select
      end do
      call split_word(rest, word, after_name_text)
      if (len(word) == 0) call fail(line_no, 'subroutine name expected')
      if (.not. pfunit_reads_tail(after_name_text)) then
         if (pending == TEST) then
            call fail(line_no, '@test (line ' // int_str(pending_line) // ') must be followed by a line of the form ' &
               // '"subroutine ' // word // '()", with nothing after it but a comment: real pFUnit reads no other ' &
               // 'form of the line (a continued line, bind(c), a second statement ...) and skips it in silence, ' &
               // 'taking the next plain subroutine as the test')
         else
            call fail(line_no, trim(DIRECTIVE_NAMES(pending)) // ' (line ' // int_str(pending_line) // &
               ') must be followed by a line of the form "subroutine ' // word // '()", with nothing after it ' &
               // 'but a comment: real pFUnit stops at any other form ("Improper format in declaration of test ' &
               // 'procedure")')
         end if
      end if
      if (len(after_name_text) > 0) then
         if (after_name_text(1:1) == '(') then
            close_at = index(after_name_text, ')')
            if (len_trim(after_name_text(2:close_at - 1)) > 0) call fail(line_no, 'test procedure "' // word // &
               '" must take no arguments (parameterised tests, @testCase, are not supported by pfunit_lite)')
         end if
      end if

      select case (pending)
      case (TEST)
         tests = [tests, name_t(word, line_no)]
      case (BEFORE)
         if (len(before_name) > 0) call fail(line_no, 'a second @before in the module')
         before_name = word
      case (AFTER)
         if (len(after_name) > 0) call fail(line_no, 'a second @after in the module')
         after_name = word
      end select
      pending = NONE
   end subroutine take_procedure

   !> What may follow the name on a test procedure's line for real pFUnit, whose pattern is
   !> `\s*subroutine\s+(\w*)\s*(\([\w\s,]*\))?\s*(!.*)*$`: nothing, a comment, or a parenthesised
   !> list of names, blanks and commas followed by nothing or a comment (tail: left-adjusted, trimmed).
   pure logical function pfunit_reads_tail(tail)
      character(len=*), intent(in) :: tail
      character(len=:), allocatable :: after
      integer :: close_at, i
      pfunit_reads_tail = .true.
      if (len(tail) == 0) return
      if (tail(1:1) == '!') return
      pfunit_reads_tail = .false.
      if (tail(1:1) /= '(') return
      close_at = index(tail, ')')
      if (close_at == 0) return
      do i = 2, close_at - 1
         if (.not. (is_name_char(tail(i:i)) .or. tail(i:i) == ' ' .or. tail(i:i) == TAB .or. tail(i:i) == ',')) return
      end do
      after = strip_leading(tail(close_at + 1:))
      pfunit_reads_tail = len(after) == 0
      if (.not. pfunit_reads_tail) pfunit_reads_tail = after(1:1) == '!'
   end function pfunit_reads_tail

   !> A `module` line (text): real pFUnit takes every line `\s*module\s+(\w*)\s*$` as the suite's
   !> module, the last one winning, and no other form (a trailing comment makes the file module-less
   !> for it). Exactly one such line, named like the file, is accepted here.
   subroutine check_module_statement()
      character(len=:), allocatable :: word, rest, name, tail
      call split_word(text, word, rest)
      if (lower(word) /= 'module') return
      call split_word(rest, name, tail)
      if (len(tail) == 0 .and. len(rest) == len(name)) then
         module_lines = module_lines + 1
         if (module_lines > 1) call fail(line_no, 'a second module statement ("' // text // '"): real pFUnit ' &
            // 'takes the last "module name" line of a .pf file as the module of its tests; keep one module ' &
            // 'in a .pf file, named like the file')
         if (lower(name) /= lower(module_name)) call fail(line_no, 'module "' // name // '": pFUnit needs each ' &
            // '.pf file to hold one module named like the file, "' // module_name // '"')
      else if (lower(name) == lower(module_name) .and. tail(1:min(1, len(tail))) == '!') then
         call fail(line_no, 'a comment after "module ' // name // '": real pFUnit reads the module statement ' &
            // 'only with nothing after the name, and would take the file as holding no module; put the ' &
            // 'comment on its own line')
      end if
   end subroutine check_module_statement

   !> Real pFUnit registers each test with a generated line `      <test>, setUp=<before>,
   !> tearDown=<after>))` (the hooks only where given), which gfortran refuses beyond 132 columns
   !> ("Line truncated").
   subroutine check_registration_lines()
      integer :: i, columns
      do i = 1, size(tests)
         columns = 6 + len(tests(i)%s) + 2
         if (len(before_name) > 0) columns = columns + len(', setUp=') + len(before_name)
         if (len(after_name) > 0) columns = columns + len(', tearDown=') + len(after_name)
         if (columns > MAX_LINE_LEN) call fail(tests(i)%line, 'test "' // tests(i)%s // '": real pFUnit registers ' &
            // 'it with a generated line of ' // int_str(columns) // ' columns (the test''s name, then setUp= and ' &
            // 'tearDown= with the @before and @after names), over ' // int_str(MAX_LINE_LEN) // &
            ' ("Line truncated"): shorten the names')
      end do
   end subroutine check_registration_lines

   !> Appends `module wrap_<module>` with `<module>_suite`, which runs every test in file order.
   subroutine emit_wrapper()
      character(len=:), allocatable :: wrap_name, suite_name, hooks
      integer :: i

      wrap_name = WRAP_PREFIX // lower(module_name)
      suite_name = module_name // PFUNIT_SUITE_SUFFIX
      ! (within MAX_NAME_LEN: the module name is checked against real pFUnit's shorter limit)
      hooks = ''
      if (len(before_name) > 0) hooks = hooks // ', before=' // before_name
      if (len(after_name) > 0) hooks = hooks // ', after=' // after_name

      call emit('#line ' // int_str(out_line + 2) // ' "' // out_path // '"')
      call emit('! ---- generated by pfunit_lite: runs the tests of ' // pf_file // ' ----')
      call emit('module ' // wrap_name)
      call emit('   implicit none')
      call emit('   private')
      call emit('   public :: ' // suite_name)
      call emit('contains')
      ! (the scope of real pFUnit's suite function <module>_suite: its own name, all of funit and
      ! of the module, and its locals suite and t; a public name of the module that clashes there
      ! fails here too)
      call emit('   subroutine ' // suite_name // '()')
      call emit('      ! As in real pFUnit''s suite function of this name: its name, all of funit and of the')
      call emit('      ! module, and the locals suite and t. A public name of the module that clashes with these')
      call emit('      ! fails with real pFUnit too.')
      call emit('      use funit')
      call emit('      use ' // module_name)
      call emit('      type(TestSuite) :: suite')
      call emit('      class(Test), allocatable :: t')
      call emit('      allocate (t, source=TestMethod())')
      call emit('      call funit_suite_scope(suite, t)')
      do i = 1, size(tests)
         call emit_statement('      ', 'call funit_run_test(''' // module_name // ''', ''' // tests(i)%s // ''', ' &
            // tests(i)%s // hooks // ')')
      end do
      call emit('   end subroutine ' // suite_name)
      call emit('end module ' // wrap_name)
   end subroutine emit_wrapper

   ! ------------------------------------------------------------------ output

   subroutine emit(out_text)
      character(len=*), intent(in) :: out_text
      write (out_unit, '(a)') out_text
      out_line = out_line + 1
   end subroutine emit

   !> Writes indent // statement, continued with `&` ... `&` pieces when longer than a line.
   !> Pieces never end or start next to a quote or `&`, so a split inside a string stays valid.
   subroutine emit_statement(indent, statement)
      character(len=*), intent(in) :: indent, statement
      integer :: first, last, chunk
      character(len=1) :: lead

      if (len(indent) + len(statement) <= MAX_LINE_LEN) then
         call emit(indent // statement)
         return
      end if
      chunk = max(MIN_CHUNK_LEN, MAX_LINE_LEN - len(indent) - 2)
      first = 1
      lead = ' '
      do while (len(statement) - first + 1 > chunk)
         last = first + chunk - 1
         do while (last > first + 1 .and. (scan(statement(last:last + 1), '''"&') > 0))
            last = last - 1
         end do
         call emit(indent // trim(lead) // statement(first:last) // '&')
         first = last + 1
         lead = '&'
      end do
      call emit(indent // '&' // statement(first:))
   end subroutine emit_statement

   ! ----------------------------------------------------------------- parsing

   !> Position in text of the parenthesis closing text(1:1), ignoring parentheses in strings;
   !> 0 when unbalanced or when a `!` comment starts first.
   pure integer function matching_paren(paren_text) result(close_at)
      character(len=*), intent(in) :: paren_text
      integer :: i, depth
      character(len=1) :: quote

      close_at = 0
      depth = 0
      quote = ' '
      i = 0
      do while (i < len(paren_text))
         i = i + 1
         associate (c => paren_text(i:i))
            if (quote /= ' ') then
               if (c == quote) quote = ' '   ! a doubled quote closes and reopens: same result
            else if (c == '''' .or. c == '"') then
               quote = c
            else if (c == '!') then
               return
            else if (c == '(') then
               depth = depth + 1
            else if (c == ')') then
               depth = depth - 1
               if (depth == 0) then
                  close_at = i
                  return
               end if
            end if
         end associate
      end do
   end function matching_paren

   !> Leading name (letters, digits, _) of source after blanks, and what follows it, left-adjusted.
   pure subroutine split_word(source, word, rest)
      character(len=*), intent(in) :: source
      character(len=:), allocatable, intent(out) :: word, rest
      character(len=:), allocatable :: s
      integer :: i

      s = strip_leading(source)
      i = 1
      do while (i <= len(s))
         if (.not. is_name_char(s(i:i))) exit
         i = i + 1
      end do
      word = s(1:i - 1)
      rest = trim(strip_leading(s(i:)))
   end subroutine split_word

   !> Not blank, not a comment, not a preprocessor line.
   pure logical function is_statement(stripped)
      character(len=*), intent(in) :: stripped
      is_statement = len_trim(stripped) > 0
      if (is_statement) is_statement = stripped(1:1) /= '!' .and. stripped(1:1) /= '#'
   end function is_statement

   elemental logical function is_name_char(c)
      character(len=1), intent(in) :: c
      is_name_char = (lge(c, 'a') .and. lle(c, 'z')) .or. (lge(c, 'A') .and. lle(c, 'Z')) &
         .or. (lge(c, '0') .and. lle(c, '9')) .or. c == '_'
   end function is_name_char

   ! --------------------------------------------------------------- utilities

   !> One line of any length, without the end-of-line (and a DOS carriage return).
   subroutine read_line(unit, whole, at_end)
      integer, intent(in) :: unit
      character(len=:), allocatable, intent(out) :: whole
      logical, intent(out) :: at_end
      character(len=READ_CHUNK) :: buffer
      integer :: n_read, read_status

      whole = ''
      at_end = .false.
      do
         read (unit, '(a)', advance='no', size=n_read, iostat=read_status) buffer
         whole = whole // buffer(1:n_read)
         if (read_status == iostat_eor) exit
         if (read_status == iostat_end) then
            at_end = len(whole) == 0
            exit
         end if
         if (read_status /= 0) call fail(line_no + 1, 'read error')
      end do
      if (len(whole) > 0) then
         if (whole(len(whole):) == CR) whole = whole(1:len(whole) - 1)
      end if
   end subroutine read_line

   pure function strip_leading(source) result(stripped)
      character(len=*), intent(in) :: source
      character(len=:), allocatable :: stripped
      integer :: i
      i = verify(source, ' ' // TAB)
      if (i == 0) then
         stripped = ''
      else
         stripped = source(i:)
      end if
   end function strip_leading

   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: name
      name = path(scan(path, '/\', back=.true.) + 1:)
   end function base_name

   !> text with each quote doubled, for a '...' literal.
   pure function quoted(raw) result(literal)
      character(len=*), intent(in) :: raw
      character(len=:), allocatable :: literal
      integer :: i
      literal = ''
      do i = 1, len(raw)
         literal = literal // raw(i:i)
         if (raw(i:i) == '''') literal = literal // ''''
      end do
   end function quoted

   pure function lower(source) result(low)
      character(len=*), intent(in) :: source
      character(len=len(source)) :: low
      integer, parameter :: CASE_SHIFT = iachar('a') - iachar('A')
      integer :: i
      low = source
      do i = 1, len(source)
         if (lge(source(i:i), 'A') .and. lle(source(i:i), 'Z')) low(i:i) = achar(iachar(source(i:i)) + CASE_SHIFT)
      end do
   end function lower

   pure function int_str(value) result(digits)
      integer, intent(in) :: value
      character(len=:), allocatable :: digits
      character(len=24) :: buffer
      write (buffer, '(i0)') value
      digits = trim(buffer)
   end function int_str

   subroutine get_arguments(input, output)
      character(len=:), allocatable, intent(out) :: input, output
      integer :: arg_len
      if (command_argument_count() /= 2) call stop_usage('expected 2 arguments')
      call get_command_argument(1, length=arg_len)
      allocate (character(len=arg_len) :: input)
      call get_command_argument(1, input(:))
      call get_command_argument(2, length=arg_len)
      allocate (character(len=arg_len) :: output)
      call get_command_argument(2, output(:))
   end subroutine get_arguments

   !> Reports `file:line: error: why`, removes the partial output and exits with status 1.
   subroutine fail(at_line, why)
      integer, intent(in) :: at_line
      character(len=*), intent(in) :: why
      logical :: is_open
      write (error_unit, '(a)') in_path // ':' // int_str(at_line) // ': error: ' // why
      ! (before the STOP's own line, which would otherwise come first where standard error is buffered)
      flush (error_unit)
      inquire (unit=out_unit, opened=is_open)
      if (is_open) close (out_unit, status='delete')
      stop 1
   end subroutine fail

   subroutine stop_usage(why)
      character(len=*), intent(in) :: why
      write (error_unit, '(a)') 'pf_preprocess: ' // why, 'usage: pf_preprocess <input.pf> <output.F90>'
      stop 2
   end subroutine stop_usage

end program pf_preprocess
