!> Bounded, strict reading of the text files interphase takes at start-up (RVE tables, R-curves,
!> and the drivers' case and history files): one line at a time with a limit on its length and
!> on the whole file, so that no file (a device such as /dev/zero, a line without end) is read
!> forever; numbers taken only when the whole field is one real literal; file names shown as
!> the path that was tried.
!>
!> Set-up code (I/O); the pure update never calls it.
module interphase_text_input
   use, intrinsic :: iso_fortran_env, only: iostat_end, int64
   use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_size_t, c_ptr, c_associated
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_real_text, only: literal_overflows, exponent_too_long
   implicit none
   private
   public :: text_file_type, open_text_file, read_text_line, close_text_file, parse_real, &
      is_real_literal, tried_path, clip_text, to_lower, text_before, path_problem, next_parenthesised

   !> Longest line a reader takes (characters, without the newline).
   integer, parameter, public :: MAX_LINE_LEN = 65536
   !> Largest file a reader takes (bytes, newlines included): 64 MiB.
   integer(int64), parameter, public :: MAX_FILE_BYTES = 67108864_int64

   !> Outcomes of read_text_line: a line, the end of the file, a line too long, a file too
   !> large, a read error.
   integer, parameter, public :: TEXT_LINE = 0, TEXT_END = 1, TEXT_LINE_TOO_LONG = 2, &
      TEXT_FILE_TOO_LARGE = 3, TEXT_READ_ERROR = 4

   !> Length units as a comment may name them in parentheses (lower case; `um` and the micro sign
   !> or Greek mu before `m` in UTF-8 for micrometres): the readers' unit checks refuse them where
   !> a column is read in mm (other than `mm`) or is a ratio (R-curve's D).
   character(len=*), parameter, public :: LENGTH_UNIT_WORDS(23) = [character(len=11) :: 'mm', 'm', 'cm', &
      'dm', 'km', 'um', char(194)//char(181)//'m', char(206)//char(188)//'m', 'nm', 'in', 'inch', 'inches', &
      'ft', 'mil', 'micron', 'microns', 'micrometre', 'micrometer', 'micrometres', 'metre', 'meter', &
      'metres', 'meters']

   !> Why parse_real refuses a nonzero literal whose magnitude is below tiny(1.0_dp).
   character(len=*), parameter, public :: UNDERFLOW_WHY = 'out of range (|x| < 2.2e-308)'

   !> Bytes read from the file at once (its size permitting).
   integer, parameter :: CHUNK_LEN = 4096

   !> An open text file read line by line. It is read as a stream of bytes, not as formatted
   !> records: some Fortran run-times (flang's) take a whole record into memory before the
   !> first non-advancing read returns, so that a file without newlines (a device such as
   !> /dev/zero) would never return; here every read is bounded.
   type :: text_file_type
      integer :: unit = -1                       !! the unit, -1 when not open
      integer :: line_number = 0                 !! lines read so far
      integer(int64) :: bytes = 0_int64          !! bytes read so far
      character(len=:), allocatable :: buffer    !! the last line (its first `length` characters)
      integer :: length = 0                      !! length of the last line
      integer(int64) :: size = -1_int64          !! bytes of a regular file; <= 0: not known
      integer(int64) :: fetched = 0_int64        !! bytes taken from the file into `chunk`
      character(len=CHUNK_LEN) :: chunk = ''     !! bytes read ahead ...
      integer :: chunk_next = 1                  !! ... the next one to take ...
      integer :: chunk_end = 0                   !! ... and the last one
   end type text_file_type

   interface
      !> POSIX getcwd(3).
      function c_getcwd(buf, size) result(p) bind(C, name='getcwd')
         import :: c_char, c_size_t, c_ptr
         implicit none
         character(kind=c_char), intent(out) :: buf(*)
         integer(c_size_t), value, intent(in) :: size
         type(c_ptr) :: p
      end function c_getcwd
   end interface

contains

   !> The next group in parentheses or square brackets of a comment `text` from position `i` on,
   !> for the readers' unit checks (`# columns: t s_T (mm) Sigma_N (MPa)`, an R-curve's
   !> `G_cI (N/mm)` or `G_cI [J/m^2]`): `found` false when there is none; else `content`, what the
   !> group holds (to its ')' or ']', nested groups of its kind counted, or to the end; blanks
   !> trimmed), `word`, the word right before it as written (blanks between allowed; a blank,
   !> tab, comma, semicolon, ')' or ']' ends it; '' when none), and `i` moved past the group.
   pure subroutine next_parenthesised(text, i, found, content, word)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: i
      logical, intent(out) :: found
      character(len=:), allocatable, intent(out) :: content, word
      integer :: depth, close, word_start, word_end
      character(len=1) :: opening, closing
      content = ''
      word = ''
      found = .false.
      if (i < 1) i = 1
      do while (i <= len(text))
         if (text(i:i) == '(' .or. text(i:i) == '[') exit
         i = i + 1
      end do
      if (i > len(text)) return
      found = .true.
      opening = text(i:i)
      closing = merge(')', ']', opening == '(')
      close = i
      depth = 0
      do while (close <= len(text))
         if (text(close:close) == opening) depth = depth + 1
         if (text(close:close) == closing) depth = depth - 1
         if (depth == 0) exit
         close = close + 1
      end do
      content = trim(adjustl(text(i + 1:min(close, len(text) + 1) - 1)))
      word_end = len_trim(text(:i - 1))
      word_start = word_end
      do while (word_start > 1)
         if (index(' ,;)]'//achar(9), text(word_start - 1:word_start - 1)) > 0) exit
         word_start = word_start - 1
      end do
      if (word_end >= 1) word = text(word_start:word_end)
      i = close + 1
   end subroutine next_parenthesised

   !> Lower-case copy of an ASCII string (other characters as they are).
   pure function to_lower(text) result(lower)
      character(len=*), intent(in) :: text        !! any text
      character(len=len(text)) :: lower
      integer :: i, code

      lower = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('A') .and. code <= iachar('Z')) lower(i:i) = achar(code + 32)
      end do
   end function to_lower

   !> Open `path` for reading. ok = .false. with `message` (the processor's reason) when it
   !> cannot be opened; a directory is refused here too.
   subroutine open_text_file(path, file, ok, message)
      character(len=*), intent(in) :: path            !! the file
      type(text_file_type), intent(out) :: file
      logical, intent(out) :: ok
      character(len=*), intent(out) :: message        !! reason when not ok
      integer :: ios, k
      ! (room for a run-time library's message that repeats the path: the reason comes after it)
      character(len=len(path) + 256) :: iomsg
      ok = .false.
      message = ''
      iomsg = ''
      ! a directory opens (and reads as empty) with some compilers: refuse it by name
      inquire (file=trim(path)//'/.', exist=ok)
      if (ok) then
         ok = .false.
         message = 'cannot open: is a directory'
         return
      end if
      open (newunit=file%unit, file=path, status='old', action='read', form='unformatted', &
         access='stream', iostat=ios, iomsg=iomsg)
      if (ios /= 0) then
         file%unit = -1
         ! the reason alone when the message names the file ("Cannot open file 'PATH': reason"):
         ! the caller names it, and shortens it for its message; the reason must survive that
         k = index(iomsg, "'"//trim(path)//"':", back=.true.)
         if (k > 0) then
            k = k + len_trim(path) + 3
            if (len_trim(iomsg(k:)) > 0) iomsg = adjustl(iomsg(k:))
         end if
         message = 'cannot open: '//trim(iomsg)
         ! (a file's path written as a folder's: 'mybrick.dat/' says 'Not a directory', or names no file)
         if (len_trim(path) > 1) then
            if (path(len_trim(path):len_trim(path)) == '/') message = trim(message)// &
               " (the path ends in '/', as a folder's does: a file's path does not)"
         end if
         return
      end if
      ! the size of a regular file; a device or a pipe has none (0 or -1): read byte by byte
      inquire (unit=file%unit, size=file%size, iostat=ios)
      if (ios /= 0) file%size = -1_int64
      allocate (character(len=1024) :: file%buffer)
      ok = .true.
   end subroutine open_text_file

   !> Read the next line into file%buffer(1:file%length), in pieces, in time linear in its
   !> length. Returns TEXT_LINE, TEXT_END, or (with `message`) TEXT_LINE_TOO_LONG (more than
   !> MAX_LINE_LEN characters), TEXT_FILE_TOO_LARGE (more than MAX_FILE_BYTES read) or
   !> TEXT_READ_ERROR (also for a UTF-8 byte-order mark that starts the file). A last line
   !> without a newline is a line; a trailing carriage return is dropped. Reading stops at the
   !> limit: a line without end is never read to its end.
   subroutine read_text_line(file, outcome, message)
      type(text_file_type), intent(inout) :: file
      integer, intent(out) :: outcome                 !! TEXT_*
      character(len=*), intent(out) :: message        !! reason when not TEXT_LINE/TEXT_END
      character(len=:), allocatable :: grown
      character(len=256) :: iomsg
      integer :: ios, take, newline
      logical :: started

      message = ''
      file%length = 0
      started = .false.
      do
         if (file%chunk_next > file%chunk_end) then
            call fetch(file, ios, iomsg)
            if (is_iostat_end(ios)) then
               if (started) exit                      ! a last line without a newline
               outcome = TEXT_END
               return
            else if (ios /= 0) then
               outcome = TEXT_READ_ERROR
               message = 'read error: '//trim(iomsg)
               return
            end if
         end if
         started = .true.
         newline = index(file%chunk(file%chunk_next:file%chunk_end), achar(10))
         if (newline == 0) then
            take = file%chunk_end - file%chunk_next + 1
            file%bytes = file%bytes + take
         else
            take = newline - 1
            file%bytes = file%bytes + take + 1
         end if
         if (file%length + take > MAX_LINE_LEN) then
            outcome = TEXT_LINE_TOO_LONG
            file%line_number = file%line_number + 1
            write (message, '(a,i0,a)') 'line longer than ', MAX_LINE_LEN, ' characters'
            return
         end if
         if (file%bytes > MAX_FILE_BYTES) then
            outcome = TEXT_FILE_TOO_LARGE
            file%line_number = file%line_number + 1
            write (message, '(a,i0,a)') 'file larger than ', MAX_FILE_BYTES, ' bytes'
            return
         end if
         if (file%length + take > len(file%buffer)) then
            allocate (character(len=max(2*len(file%buffer), file%length + take)) :: grown)
            grown(1:file%length) = file%buffer(1:file%length)
            ! an assignment, not move_alloc: flang -pedantic flags move_alloc of deferred-length
            ! character scalars (their semantics change in Fortran 2023); one more copy per
            ! doubling of the buffer
            file%buffer = grown
            deallocate (grown)
         end if
         file%buffer(file%length + 1:file%length + take) = &
            file%chunk(file%chunk_next:file%chunk_next + take - 1)
         file%length = file%length + take
         file%chunk_next = file%chunk_next + take
         if (newline /= 0) then
            file%chunk_next = file%chunk_next + 1     ! past the newline
            exit
         end if
      end do
      file%line_number = file%line_number + 1
      if (file%length > 0) then
         if (file%buffer(file%length:file%length) == achar(13)) file%length = file%length - 1
      end if
      ! a UTF-8 byte-order mark (some Windows editors write one) would make the first line's first
      ! word unreadable with a message about that word: named for what it is
      if (file%line_number == 1 .and. file%length >= 3) then
         if (file%buffer(1:3) == char(239)//char(187)//char(191)) then
            outcome = TEXT_READ_ERROR
            message = 'the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it without one'
            return
         end if
      end if
      outcome = TEXT_LINE
   end subroutine read_text_line

   !> Read the next bytes into file%chunk: CHUNK_LEN of them, or the rest of a regular file,
   !> or one from a file of unknown size (a stream read past the end leaves unknown how many
   !> bytes it transferred). ios: 0, an end-of-file code, or an error code with iomsg.
   subroutine fetch(file, ios, iomsg)
      type(text_file_type), intent(inout) :: file
      integer, intent(out) :: ios
      character(len=*), intent(out) :: iomsg
      integer :: n
      iomsg = ''
      if (file%size > 0_int64) then
         n = int(min(int(CHUNK_LEN, int64), file%size - file%fetched))
         if (n <= 0) then
            ios = iostat_end
            return
         end if
      else
         n = 1
      end if
      read (file%unit, iostat=ios, iomsg=iomsg) file%chunk(1:n)
      if (ios /= 0) return
      file%fetched = file%fetched + n
      file%chunk_next = 1
      file%chunk_end = n
   end subroutine fetch

   !> Close the file (once: a second call does nothing).
   subroutine close_text_file(file)
      type(text_file_type), intent(inout) :: file
      integer :: ios
      if (file%unit /= -1) close (file%unit, iostat=ios)
      file%unit = -1
   end subroutine close_text_file

   !> True when `text` (no leading or trailing blanks) is one real literal:
   !> [sign] (digits [. [digits]] | . digits) [(e|E|d|D) [sign] digits]. Nothing else: no
   !> separators (`,` `/`), no repeat counts (`2*`), no exponent without its letter (`1-2`).
   pure logical function is_real_literal(text)
      character(len=*), intent(in) :: text
      integer :: i, n, mantissa_digits
      n = len(text)
      is_real_literal = .false.
      i = 1
      if (n == 0) return
      if (text(1:1) == '+' .or. text(1:1) == '-') i = 2
      mantissa_digits = 0
      do while (i <= n)
         if (.not. is_digit(text(i:i))) exit
         mantissa_digits = mantissa_digits + 1
         i = i + 1
      end do
      if (i <= n) then
         if (text(i:i) == '.') then
            i = i + 1
            do while (i <= n)
               if (.not. is_digit(text(i:i))) exit
               mantissa_digits = mantissa_digits + 1
               i = i + 1
            end do
         end if
      end if
      if (mantissa_digits == 0) return
      if (i <= n) then
         if (scan(text(i:i), 'eEdD') == 0) return
         i = i + 1
         if (i <= n) then
            if (text(i:i) == '+' .or. text(i:i) == '-') i = i + 1
         end if
         if (i > n) return
         do while (i <= n)
            if (.not. is_digit(text(i:i))) return
            i = i + 1
         end do
      end if
      is_real_literal = .true.
   end function is_real_literal

   !> The number in `field` when the whole field (leading and trailing blanks aside) is one
   !> finite real literal (is_real_literal); else ok = .false. and `why` says what is wrong.
   !> A literal with a nonzero digit whose magnitude is below the smallest normal double,
   !> tiny(1.0_dp) = 2.2250738585072014e-308 (it would read as 0, or as a subnormal with fewer
   !> digits than written), is refused as out of range (UNDERFLOW_WHY), as one beyond
   !> huge(1.0_dp) is: a value is never silently changed to another. A zero (0, 0.0e-999) is read.
   subroutine parse_real(field, value, ok, why)
      character(len=*), intent(in) :: field
      real(dp), intent(out) :: value
      logical, intent(out) :: ok
      character(len=*), intent(out) :: why            !! 'not a number', 'not finite (...)' or UNDERFLOW_WHY
      integer :: ios, first, last
      value = 0.0_dp
      ok = .false.
      why = 'not a number'
      first = verify(field, ' '//achar(9))
      last = len_trim(field)
      if (first == 0) return
      if (.not. is_real_literal(field(first:last))) then
         if (is_nonfinite_word(field(first:last))) why = 'not finite (NaN or Inf)'
         return
      end if
      if (literal_overflows(field(first:last))) then
         why = 'not finite (out of range)'
         return
      end if
      if (vanishes(field(first:last))) then
         why = UNDERFLOW_WHY
         return
      end if
      read (field(first:last), *, iostat=ios) value
      if (ios /= 0) return
      if (.not. is_finite(value)) then
         value = 0.0_dp
         why = 'not finite (out of range)'
         return
      end if
      if (abs(value) < tiny(value) .and. verify(text_before(field(first:last), 'eEdD'), '+-0.') > 0) then
         ! a nonzero literal read as 0 or as a subnormal
         value = 0.0_dp
         why = UNDERFLOW_WHY
         return
      end if
      ok = .true.
   end subroutine parse_real

   !> What is wrong with a file name given with its real length ('' when nothing): an empty or
   !> blank one, or one that ends in a blank, which Fortran's `open` would drop (`'good.dat  '`
   !> opened good.dat). The loaders' callers know the length: the C API, Python, the environment.
   pure function path_problem(path) result(why)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: why
      why = ''
      if (len(path) == 0) then
         why = 'the path is empty'
      else if (len_trim(path) == 0) then
         why = 'the path is blank ("'//clip_text(path)//'")'
      else if (path(len(path):len(path)) == ' ') then
         ! (its end shown: the blanks are what is wrong)
         if (len(path) <= 60) then
            why = clip_text(path)
         else
            why = '...'//clip_text(path(len(path) - 56:))
         end if
         why = 'the path "'//why//'" ends in a blank, which opening the file would drop: remove it'
      end if
   end function path_problem

   !> The path as it was tried: a relative path is shown after the current directory
   !> ('cases/x.dat' -> '/home/u/run/cases/x.dat'), so that a message says which file it was.
   !> An absolute path (or one when the current directory is not known) is returned as is.
   function tried_path(path) result(full)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: full
      integer, parameter :: CWD_LEN = 4096
      character(kind=c_char) :: buf(CWD_LEN)
      integer :: n
      full = trim(path)
      if (len(full) == 0) return
      if (full(1:1) == '/') return
      if (.not. c_associated(c_getcwd(buf, int(CWD_LEN, c_size_t)))) return
      n = 0
      do while (n < CWD_LEN)
         if (buf(n + 1) == c_null_char) exit
         n = n + 1
      end do
      if (n == 0 .or. n == CWD_LEN) return
      block
         character(len=n) :: cwd
         integer :: i
         do i = 1, n
            cwd(i:i) = buf(i)
         end do
         do while (len(full) >= 2)
            if (full(1:2) /= './') exit
            full = full(3:)
         end do
         if (cwd(n:n) == '/') then
            full = cwd//full
         else
            full = cwd//'/'//full
         end if
      end block
   end function tried_path



   !> Whether a real literal (is_real_literal) with a nonzero digit has a negative exponent too
   !> long to read (exponent_too_long): its value is below tiny(1.0_dp), decided without reading
   !> it.
   pure logical function vanishes(literal)
      character(len=*), intent(in) :: literal
      integer :: mark
      vanishes = .false.
      mark = scan(literal, 'eEdD')
      if (mark == 0) return
      if (literal(mark + 1:mark + 1) /= '-') return
      vanishes = exponent_too_long(literal(mark + 1:)) .and. verify(literal(1:mark - 1), '+-0.') > 0
   end function vanishes

   !> The part of `text` before its first character of `set` (all of it without one): a real
   !> literal's mantissa (set 'eEdD'), a keyword line's keyword (set ',').
   pure function text_before(text, set) result(head)
      character(len=*), intent(in) :: text, set
      character(len=:), allocatable :: head
      integer :: mark
      mark = scan(text, set)
      if (mark == 0) then
         head = text
      else
         head = text(1:mark - 1)
      end if
   end function text_before

   !> At most the first 60 characters of `text`, with '...' when cut, and a control character
   !> other than a tab as '?' (for messages).
   pure function clip_text(text) result(short)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: short
      integer :: i
      if (len(text) <= 60) then
         short = text
      else
         short = text(1:57)//'...'
      end if
      ! control characters other than a tab (a binary file read as text) shown as '?'
      do i = 1, len(short)
         if ((iachar(short(i:i)) < 32 .and. iachar(short(i:i)) /= 9) .or. iachar(short(i:i)) == 127) short(i:i) = '?'
      end do
   end function clip_text

   !> NaN, Inf or Infinity (any case, optional sign, NaN(...) too).
   pure logical function is_nonfinite_word(text)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: lower
      integer :: i, first
      lower = text
      do i = 1, len(text)
         if (text(i:i) >= 'A' .and. text(i:i) <= 'Z') lower(i:i) = achar(iachar(text(i:i)) + 32)
      end do
      first = 1
      if (len(lower) > 0) then
         if (lower(1:1) == '+' .or. lower(1:1) == '-') first = 2
      end if
      is_nonfinite_word = lower(first:) == 'inf' .or. lower(first:) == 'infinity' .or. lower(first:) == 'nan'
      if (len(lower) >= first + 3) is_nonfinite_word = is_nonfinite_word .or. lower(first:first + 3) == 'nan('
   end function is_nonfinite_word

   pure logical function is_digit(c)
      character(len=1), intent(in) :: c
      is_digit = c >= '0' .and. c <= '9'
   end function is_digit

end module interphase_text_input
