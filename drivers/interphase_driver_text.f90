!> Text and path helpers of the single-point driver `interphase-point`: number formatting,
!> line reading, tokenising, lower-casing, path splitting and shell quoting. No physics here.
module interphase_driver_text
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use, intrinsic :: iso_c_binding, only: c_char, c_null_char, c_ptr, c_associated
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text
   use interphase_text_input, only: text_file_type, open_text_file, read_text_line, close_text_file, &
      TEXT_LINE, TEXT_END, to_lower
   implicit none
   private
   public :: int_to_string, count_text, real_to_string, real_to_csv, to_lower
   public :: text_file_type, open_line_file, read_line, close_text_file
   public :: split_words, directory_of, base_name, stem_of, join_path, shell_quote, gnuplot_quote, same_path, same_file

contains

   !> Decimal text of an integer, without blanks.
   pure function int_to_string(value) result(text)
      integer, intent(in) :: value                !! the integer
      character(len=:), allocatable :: text
      character(len=24) :: buffer

      write (buffer, '(i0)') value
      text = trim(buffer)
   end function int_to_string

   !> A count and its noun for messages, the noun singular for one: '1 column', '3 columns'
   !> (`noun` singular; the plural adds an s).
   pure function count_text(count, noun) result(text)
      integer, intent(in) :: count                !! how many
      character(len=*), intent(in) :: noun        !! the noun, singular
      character(len=:), allocatable :: text

      text = int_to_string(count)//' '//noun
      if (count /= 1) text = text//'s'
   end function count_text

   !> Text of a real for messages (`g0.17`, with its leading zero: the same with every compiler).
   function real_to_string(value) result(text)
      real(dp), intent(in) :: value               !! the number
      character(len=:), allocatable :: text

      text = real_text(value)
   end function real_to_string

   !> Full-precision text of a real for CSV files (`es24.16e3`: 17 significant digits), no blanks.
   function real_to_csv(value) result(text)
      real(dp), intent(in) :: value               !! the number
      character(len=:), allocatable :: text
      character(len=24) :: buffer

      write (buffer, '(es24.16e3)') value
      text = trim(adjustl(buffer))
   end function real_to_csv

   !> Open a text file for read_line (interphase_text_input's bounded reader). iostat is 0, or
   !> non-zero with the reason in `iomsg` (a directory is refused).
   subroutine open_line_file(path, file, iostat, iomsg)
      character(len=*), intent(in) :: path        !! the file
      type(text_file_type), intent(out) :: file
      integer, intent(out) :: iostat              !! 0 when open
      character(len=*), intent(inout) :: iomsg    !! reason when not open
      character(len=512) :: message
      logical :: ok

      call open_text_file(path, file, ok, message)
      iostat = 0
      if (ok) return
      iostat = 1
      if (index(message, 'cannot open: ') == 1) then
         iomsg = message(len('cannot open: ') + 1:)
      else
         iomsg = message
      end if
   end subroutine open_line_file

   !> Read one whole line, up to MAX_LINE_LEN characters (interphase_text_input): a longer line
   !> (or a file without line ends, such as /dev/zero) is an error, not read to its end. A last
   !> line without a newline is returned as a line. `iostat` is 0, `iostat_end` at the end of
   !> the file, or an error code (then `iomsg` says why).
   subroutine read_line(file, line, iostat, iomsg)
      type(text_file_type), intent(inout) :: file !! opened with open_line_file
      character(len=:), allocatable, intent(out) :: line  !! the line, without its newline
      integer, intent(out) :: iostat              !! 0, iostat_end or an error code
      character(len=*), intent(inout) :: iomsg    !! error text when iostat is an error code
      character(len=512) :: message
      integer :: outcome

      call read_text_line(file, outcome, message)
      select case (outcome)
      case (TEXT_LINE)
         iostat = 0
         line = file%buffer(1:file%length)
      case (TEXT_END)
         iostat = iostat_end
         line = ''
      case default
         iostat = 1
         iomsg = message
         line = ''
      end select
   end subroutine read_line

   !> Split a line into blank-separated words (blanks: space, tab, carriage return).
   !> `starts(i):ends(i)` is word i.
   pure subroutine split_words(line, starts, ends)
      character(len=*), intent(in) :: line        !! the text to split
      integer, allocatable, intent(out) :: starts(:)  !! first character of each word
      integer, allocatable, intent(out) :: ends(:)    !! last character of each word
      integer :: i, nwords
      logical :: in_word

      allocate (starts(len(line)/2 + 1), ends(len(line)/2 + 1))
      nwords = 0
      in_word = .false.
      do i = 1, len(line)
         if (is_blank(line(i:i))) then
            if (in_word) ends(nwords) = i - 1
            in_word = .false.
         else if (.not. in_word) then
            nwords = nwords + 1
            starts(nwords) = i
            in_word = .true.
         end if
      end do
      if (in_word) ends(nwords) = len(line)
      starts = starts(:nwords)
      ends = ends(:nwords)
   end subroutine split_words

   !> True for the characters that separate words: space, tab, carriage return.
   pure logical function is_blank(character)
      character(len=1), intent(in) :: character   !! one character

      is_blank = character == ' ' .or. character == achar(9) .or. character == achar(13)
   end function is_blank

   !> Directory part of a path, with its trailing '/', or '' when the path has none.
   pure function directory_of(path) result(directory)
      character(len=*), intent(in) :: path        !! a file path
      character(len=:), allocatable :: directory

      directory = path(:index(path, '/', back=.true.))
   end function directory_of

   !> File-name part of a path (after the last '/').
   pure function base_name(path) result(name)
      character(len=*), intent(in) :: path        !! a file path
      character(len=:), allocatable :: name

      name = path(index(path, '/', back=.true.) + 1:)
   end function base_name

   !> File name without directory and without its last extension: 'cases/h1I.nml' -> 'h1I'.
   pure function stem_of(path) result(stem)
      character(len=*), intent(in) :: path        !! a file path
      character(len=:), allocatable :: stem
      integer :: dot

      stem = base_name(path)
      dot = index(stem, '.', back=.true.)
      if (dot > 1) stem = stem(:dot - 1)
   end function stem_of

   !> `relative` placed under `directory`, unless it is absolute or `directory` is empty.
   pure function join_path(directory, relative) result(path)
      character(len=*), intent(in) :: directory   !! base directory ('' for none)
      character(len=*), intent(in) :: relative    !! a path, absolute or relative
      character(len=:), allocatable :: path

      if (len(relative) > 0) then
         if (relative(1:1) == '/') then
            path = relative
            return
         end if
      end if
      if (len(directory) == 0) then
         path = relative
      else if (directory(len(directory):) == '/') then
         path = directory//relative
      else
         path = directory//'/'//relative
      end if
   end function join_path

   !> Whether two paths name the same file as text says it: both normalised (repeated and
   !> trailing '/', '.' segments and 'name/..' pairs removed) and compared. Paths that differ in
   !> this form may still be one file (a symbolic link, one absolute and one relative): false.
   pure logical function same_path(a, b)
      character(len=*), intent(in) :: a, b
      same_path = normal_path(a) == normal_path(b)
   end function same_path

   !> Whether two paths name one existing file: both resolved by the C library's realpath
   !> (symbolic links, '.', '..', the current directory) and compared. A path that does not
   !> resolve (a file not yet written) names no existing file: false, unless the two are one
   !> path as text (`same_path`).
   logical function same_file(a, b)
      character(len=*), intent(in) :: a, b
      character(len=:), allocatable :: real_a, real_b
      logical :: ok_a, ok_b
      same_file = same_path(a, b)
      if (same_file) return
      call resolved_path(a, real_a, ok_a)
      call resolved_path(b, real_b, ok_b)
      if (ok_a .and. ok_b) same_file = real_a == real_b
   end function same_file

   !> The canonical absolute path of an existing file (the C library's realpath); ok false when
   !> it does not resolve.
   subroutine resolved_path(path, resolved, ok)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: resolved
      logical, intent(out) :: ok
      !> PATH_MAX of Linux, with the NUL
      integer, parameter :: RESOLVED_LEN = 4096
      interface
         function c_realpath(name, buffer) bind(c, name='realpath') result(p)
            import :: c_char, c_ptr
            character(kind=c_char), intent(in) :: name(*)
            character(kind=c_char), intent(out) :: buffer(*)
            type(c_ptr) :: p
         end function c_realpath
      end interface
      character(kind=c_char) :: name(len(path) + 1), buffer(RESOLVED_LEN)
      integer :: i, n
      ok = .false.
      resolved = ''
      if (len(path) == 0) return
      do i = 1, len(path)
         name(i) = path(i:i)
      end do
      name(len(path) + 1) = c_null_char
      buffer = c_null_char
      if (.not. c_associated(c_realpath(name, buffer))) return
      n = 0
      do i = 1, RESOLVED_LEN
         if (buffer(i) == c_null_char) exit
         n = i
      end do
      resolved = repeat(' ', n)
      do i = 1, n
         resolved(i:i) = buffer(i)
      end do
      ok = .true.
   end subroutine resolved_path

   !> `a` with repeated '/', '.' segments and 'name/..' pairs removed ('' stays '').
   pure function normal_path(a) result(path)
      character(len=*), intent(in) :: a
      character(len=:), allocatable :: path, segment
      character(len=len(a)) :: parts(len(a) + 1)
      integer :: n, start, k
      logical :: absolute
      absolute = len(a) > 0
      if (absolute) absolute = a(1:1) == '/'
      n = 0
      start = 1
      do k = 1, len(a) + 1
         if (k <= len(a)) then
            if (a(k:k) /= '/') cycle
         end if
         segment = a(start:k - 1)
         start = k + 1
         if (len(segment) == 0 .or. segment == '.') cycle
         if (segment == '..' .and. n > 0) then
            if (parts(n) /= '..') then
               n = n - 1
               cycle
            end if
         end if
         n = n + 1
         parts(n) = segment
      end do
      path = ''
      if (absolute) path = '/'
      do k = 1, n
         if (k > 1) path = path//'/'
         path = path//trim(parts(k))
      end do
   end function normal_path

   !> A string quoted for the POSIX shell: 'it''s' becomes 'it'\''s'.
   pure function shell_quote(text) result(quoted)
      character(len=*), intent(in) :: text        !! any text
      character(len=:), allocatable :: quoted
      quoted = single_quoted(text, "'\''")
   end function shell_quote

   !> `text` as a gnuplot string in single quotes (where nothing is special but the quote,
   !> written twice): a file name with '"', '\' or '@' cannot end the string or run a command.
   pure function gnuplot_quote(text) result(quoted)
      character(len=*), intent(in) :: text        !! any text
      character(len=:), allocatable :: quoted
      quoted = single_quoted(text, "''")
   end function gnuplot_quote

   !> `text` in single quotes, each quote inside it written as `escaped`.
   pure function single_quoted(text, escaped) result(quoted)
      character(len=*), intent(in) :: text, escaped
      character(len=:), allocatable :: quoted
      integer :: i

      quoted = "'"
      do i = 1, len(text)
         if (text(i:i) == "'") then
            quoted = quoted//escaped
         else
            quoted = quoted//text(i:i)
         end if
      end do
      quoted = quoted//"'"
   end function single_quoted

end module interphase_driver_text
