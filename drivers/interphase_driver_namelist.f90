!> A strict pre-check of a namelist case file, before Fortran's namelist read takes it: the file
!> is read with bounded lines (interphase_text_input's limits), and refused when a group comes
!> twice, when an entry of a group comes twice, or when an entry's value is not of its kind: one
!> real literal, one integer, one logical (.true./.false.) or one quoted string (an array entry:
!> one to its size of them, each checked, each named by its place). Messages name
!> the file, the line, the group and the entry (`&loading: plot = 'yes' (line 9) is not .true.
!> or .false.`). A group or an entry that the program does not read is refused, with the list of
!> those it reads (`&material: sf_tt (line 6) is not an entry of &material; its entries: ...`).
!> A string longer than the variable that receives it is refused (the read would cut it short),
!> and so is a string that holds '&' or '$' followed by the name of a group the program reads:
!> gfortran's namelist read, looking for a group, takes `&name` for its start wherever it is,
!> inside quotes too, and would read a group written inside a string of an earlier group in
!> place of the real one (`R&D`, `a$b.txt` are read as they are).
module interphase_driver_namelist
   use, intrinsic :: iso_fortran_env, only: iostat_end, int64
   use interphase_kinds, only: dp
   use interphase_text_input, only: parse_real, clip_text, MAX_FILE_BYTES, UNDERFLOW_WHY
   use interphase_driver_text, only: int_to_string, to_lower, read_line, text_file_type, open_line_file, &
      close_text_file
   implicit none
   private
   public :: check_namelist_file, entry_kind_type, entry_line_type, with_entry_line, given_values, KIND_REAL, KIND_INTEGER, &
      KIND_LOGICAL, KIND_STRING, open_namelist_file

   !> The characters of a Fortran name (a group's, an entry's).
   character(len=*), parameter :: NAME_CHARACTERS = 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_'

   !> Kinds of entry values.
   integer, parameter :: KIND_REAL = 1, KIND_INTEGER = 2, KIND_LOGICAL = 3, KIND_STRING = 4

   !> One known entry: 'group.name' (lower case), its kind and, for a string, the length of the
   !> variable that receives it (a longer value is refused: 0 refuses every string); for an array,
   !> the most values it takes (its size; 1: a scalar, which takes exactly one).
   type :: entry_kind_type
      character(len=64) :: name = ''
      integer :: kind = 0
      integer :: length = 0
      integer :: count = 1
   end type entry_kind_type

   !> Where an entry of a case file was given: 'group.name' (lower case), its line and how many
   !> values it was given.
   type :: entry_line_type
      character(len=64) :: name = ''
      integer :: line = 0
      integer :: values = 0
   end type entry_line_type

   !> A token of the file: its text (lower-cased for names), its line, and what it is.
   integer, parameter :: TOKEN_WORD = 1, TOKEN_STRING = 2, TOKEN_EQUALS = 3, TOKEN_COMMA = 4, &
      TOKEN_SLASH = 5, TOKEN_GROUP = 6

contains

   !> Open a case file for Fortran's namelist reads: a scratch copy of its lines, each ended by a
   !> newline (a carriage return before it dropped), positioned at its start. gfortran's namelist
   !> read meets the end of a file whose last line ('/') has no newline as the end of the file, and
   !> the group is then 'not found', though its entries were read; the copy has the newline. The
   !> lines are read as the pre-check reads them (bounded). `iostat` 0 when open; the caller
   !> closes `unit` (a scratch file is deleted then).
   subroutine open_namelist_file(path, unit, iostat, iomsg)
      character(len=*), intent(in) :: path        !! the case file
      integer, intent(out) :: unit
      integer, intent(out) :: iostat
      character(len=*), intent(inout) :: iomsg
      type(text_file_type) :: file
      character(len=:), allocatable :: line
      integer :: ios
      unit = -1
      call open_line_file(path, file, iostat, iomsg)
      if (iostat /= 0) return
      open (newunit=unit, status='scratch', action='readwrite', form='formatted', recl=2**20, iostat=iostat, &
         iomsg=iomsg)
      if (iostat /= 0) then
         call close_text_file(file)
         unit = -1
         return
      end if
      do
         call read_line(file, line, ios, iomsg)
         if (ios == iostat_end) exit
         if (ios /= 0) then
            iostat = ios
            exit
         end if
         write (unit, '(a)', iostat=iostat, iomsg=iomsg) line
         if (iostat /= 0) exit
      end do
      call close_text_file(file)
      if (iostat /= 0) then
         close (unit)
         unit = -1
         return
      end if
      rewind (unit)
   end subroutine open_namelist_file

   !> Check `path` against `known` (entries of every group the program reads). ok = .false. with
   !> `message` ('path:line: &group: ...') on the first problem.
   subroutine check_namelist_file(path, known, ok, message, lines, file_kind, subnormals, expected_groups)
      character(len=*), intent(in) :: path
      type(entry_kind_type), intent(in) :: known(:)
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      !> where each entry given was and its number of values (for the checks after the read:
      !> `with_entry_line`)
      type(entry_line_type), allocatable, intent(out), optional :: lines(:)
      !> what the file is, for the messages (default 'case file')
      character(len=*), intent(in), optional :: file_kind
      !> a real may be a subnormal (default no: a case file's nonzero value below 2.2e-308 is
      !> refused; a replay file holds the host's values as the adapters wrote them, bit for bit)
      logical, intent(in), optional :: subnormals
      !> the groups a file without any is told it needs, e.g. '&material and &loading' (default:
      !> every group of `known`)
      character(len=*), intent(in), optional :: expected_groups
      character(len=:), allocatable :: line, group, seen_groups, seen_entries, name, value, what
      !> the values of the current entry (its first max_count), each ended by a newline, and
      !> their kinds (KIND_STRING for a quoted string, else 0)
      character(len=:), allocatable :: values_given
      integer, allocatable :: kinds_given(:)
      integer :: max_count
      character(len=512) :: iomsg
      integer :: ios, line_number, i, n, first, k, entry_line, nvalues, value_kind
      type(text_file_type) :: unit
      integer(int64) :: bytes
      character(len=1) :: quote
      logical :: in_group, in_entry
      !> the last token was a comma (a comma after '=' or after another comma is an empty value,
      !> which the namelist read takes as 'unchanged' or misreads)
      logical :: after_comma
      !> a comma came between the current entry's first and second values (a decimal comma,
      !> 'mu = 0,75', reads as two values: the message then shows the number meant)
      logical :: comma_after_first

      ok = .false.
      what = 'case file'
      if (present(file_kind)) what = file_kind
      ! (at least the first three values are kept, so that 'needs one value, got 3' can show them)
      max_count = 3
      if (size(known) > 0) max_count = max(3, maxval(known%count))
      allocate (kinds_given(max_count))
      values_given = ''
      if (present(lines)) allocate (lines(0))
      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = path//': cannot open the '//what//': '//trim(iomsg)
         return
      end if
      in_group = .false.
      in_entry = .false.
      after_comma = .false.
      comma_after_first = .false.
      group = ''
      seen_groups = ' '
      seen_entries = ' '
      name = ''
      value = ''
      nvalues = 0
      entry_line = 0
      line_number = 0
      bytes = 0
      quote = ' '
      do
         call read_line(unit, line, ios, iomsg)
         if (ios == iostat_end) exit
         line_number = line_number + 1
         if (ios /= 0) then
            call fail('cannot read the line: '//trim(iomsg))
            return
         end if
         bytes = bytes + len(line) + 1
         if (bytes > MAX_FILE_BYTES) then
            call fail('the file is larger than '//int_to_string(int(MAX_FILE_BYTES))//' bytes')
            return
         end if
         n = len(line)
         ! a control character inside a line (a carriage return of old Mac line ends, inside a
         ! quoted name) is dropped or misread by the namelist read: refused, up to the '!' that
         ! starts a comment (a '!' inside quotes is the string's: the scan goes on)
         quote = ' '
         do i = 1, n
            if (quote /= ' ') then
               if (line(i:i) == quote) quote = ' '      ! (a doubled quote closes and reopens)
            else if (line(i:i) == '''' .or. line(i:i) == '"') then
               quote = line(i:i)
            else if (line(i:i) == '!') then
               exit                                      ! (a comment's text is not read)
            end if
            if (iachar(line(i:i)) < 32 .and. line(i:i) /= achar(9)) then
               call fail('a control character (code '//int_to_string(iachar(line(i:i)))//') in column '// &
                  int_to_string(i)//': only blanks and tabs may separate the text (a carriage return '// &
                  'alone ends lines on old Macs: save the file with Unix or Windows line ends)')
               return
            end if
         end do
         i = 1
         do while (i <= n)
            associate (c => line(i:i))
               if (c /= ',' .and. c /= ' ' .and. c /= achar(9) .and. c /= '!') after_comma = .false.
               if (c == ' ' .or. c == achar(9)) then
                  i = i + 1
               else if (c == '!') then
                  exit                                     ! comment to the end of the line
               else if (.not. in_group) then
                  if (c /= '&') then
                     call fail('text outside a group: "'//clip_text(line(i:))//'"')
                     return
                  end if
                  first = i + 1
                  i = scan_word_end(line, first)
                  group = to_lower(line(first:i - 1))
                  if (len(group_entries(group)) == 0) then
                     call fail('&'//clip_text(group)//' is not a group of this '//what//'; its groups: '// &
                        known_groups())
                     return
                  end if
                  if (index(seen_groups, ' '//group//' ') > 0) then
                     call fail('&'//group//' given twice: a '//what//' has one group of each name')
                     return
                  end if
                  seen_groups = seen_groups//group//' '
                  seen_entries = ' '
                  in_group = .true.
               else if (c == '/' .or. c == '&') then
                  if (c == '&') then
                     if (to_lower(line(i:min(n, i + 3))) /= '&end') then
                        call fail('&'//group//' is not closed by "/" before "'//clip_text(line(i:))//'"')
                        return
                     end if
                     i = i + 3
                  end if
                  if (.not. finish_entry()) return
                  in_group = .false.
                  i = i + 1
               else if (c == ',') then
                  if (in_entry .and. (nvalues == 0 .or. after_comma)) then
                     call fail('&'//group//': '//name//' has an empty value (a comma '// &
                        trim(merge('right after "="', 'after a comma  ', nvalues == 0))//'): give one value')
                     return
                  end if
                  after_comma = .true.
                  if (in_entry .and. nvalues == 1) comma_after_first = .true.
                  i = i + 1
               else if (c == '=') then
                  call fail('&'//group//': "=" without an entry name')
                  return
               else if (c == '''' .or. c == '"') then
                  quote = c
                  first = i
                  i = i + 1
                  do while (i <= n)
                     if (line(i:i) == quote) then
                        if (i < n) then
                           if (line(i + 1:i + 1) == quote) then
                              i = i + 2
                              cycle
                           end if
                        end if
                        exit
                     end if
                     i = i + 1
                  end do
                  if (i > n) then
                     call fail('&'//group//': a string that does not end on its line: '//clip_text(line(first:)))
                     return
                  end if
                  call add_value(line(first:i), KIND_STRING)
                  i = i + 1
               else
                  first = i
                  do while (i <= n)
                     if (scan(line(i:i), ' ,/=!'//achar(9)) > 0) exit
                     i = i + 1
                  end do
                  ! a word followed by '=' is the next entry's name
                  k = verify(line(i:)//'x', ' '//achar(9)) + i - 1
                  if (k <= n) then
                     if (line(k:k) == '=') then
                        if (.not. finish_entry()) return
                        name = to_lower(line(first:i - 1))
                        if (index(seen_entries, ' '//name//' ') > 0) then
                           call fail('&'//group//': entry '//name//' given twice')
                           return
                        end if
                        seen_entries = seen_entries//name//' '
                        if (present(lines)) lines = [lines, entry_line_type(group//'.'//name, line_number)]
                        in_entry = .true.
                        entry_line = line_number
                        nvalues = 0
                        comma_after_first = .false.
                        values_given = ''
                        i = k + 1
                        cycle
                     end if
                  end if
                  call add_value(line(first:i - 1), 0)
               end if
            end associate
            if (allocated(message)) return
         end do
      end do
      call close_text_file(unit)
      if (in_group) then
         message = path//': &'//group//' is not closed by "/"'
         return
      end if
      ! an empty file, or one of comments only: said so, not as a first group not found
      if (len_trim(seen_groups) == 0) then
         if (present(expected_groups)) then
            message = path//': no namelist group in the file (expected '//expected_groups//')'
         else
            message = path//': no namelist group in the file (expected '//known_groups(' and ')//')'
         end if
         return
      end if
      ok = .true.

   contains

      !> The end (one past) of the name starting at `from`.
      pure integer function scan_word_end(text, from) result(past)
         character(len=*), intent(in) :: text
         integer, intent(in) :: from
         past = from
         do while (past <= len(text))
            if (scan(text(past:past), ' ,/=!'//achar(9)) > 0) exit
            past = past + 1
         end do
      end function scan_word_end

      !> Record one value of the current entry (kind KIND_STRING for a quoted string, else 0).
      subroutine add_value(text, quoted)
         character(len=*), intent(in) :: text
         integer, intent(in) :: quoted
         integer :: marker
         if (.not. in_entry) then
            call fail('&'//group//': a value without an entry name: '//clip_text(text))
            return
         end if
         ! (a string's closing quote is in column i: its opening one in column i - len(text) + 1)
         marker = 0
         if (quoted == KIND_STRING) marker = group_marker(text)
         if (marker > 0) then
            call fail('&'//group//': '//name//' = '//clip_text(text)//' holds "'//text(marker:marker + &
               len(marked_group(text, marker)))//'" (column '//int_to_string(i - len(text) + marker)// &
               '), which Fortran''s namelist read takes for the start of that group even inside quotes: a '// &
               'string value cannot hold "&" or "$" followed by the name of a group')
            return
         end if
         nvalues = nvalues + 1
         if (nvalues <= max_count) then
            values_given = values_given//text//achar(10)
            kinds_given(nvalues) = quoted
         end if
      end subroutine add_value

      !> Check the entry just ended against its kind; false (message set) when it is wrong.
      logical function finish_entry() result(good)
         integer :: j, kind, length, count, start, past
         character(len=:), allocatable :: lower, where, shown
         real(dp) :: number
         character(len=32) :: why
         good = .true.
         if (.not. in_entry) return
         in_entry = .false.
         kind = 0
         length = 0
         count = 1
         do j = 1, size(known)
            if (trim(known(j)%name) == group//'.'//name) then
               kind = known(j)%kind
               length = known(j)%length
               count = known(j)%count
            end if
         end do
         if (present(lines)) lines(size(lines))%values = nvalues
         where = path//':'//int_to_string(entry_line)//': &'//group//': '//name
         if (kind == 0) then
            good = .false.
            message = path//':'//int_to_string(entry_line)//': &'//group//': '//clip_text(name)// &
               ' is not an entry of &'//group//'; its entries: '//group_entries(group)
            call close_text_file(unit)
            return
         end if
         if (count == 1 .and. nvalues /= 1) then
            good = .false.
            message = where//' needs one value, got '//int_to_string(nvalues)//values_shown(kind)
            call close_text_file(unit)
            return
         else if (nvalues < 1 .or. nvalues > count) then
            good = .false.
            message = where//' takes 1 to '//int_to_string(count)//' values, got '//int_to_string(nvalues)
            call close_text_file(unit)
            return
         end if
         start = 1
         do j = 1, nvalues
            past = start + index(values_given(start:), achar(10)) - 1
            value = values_given(start:past - 1)
            value_kind = kinds_given(j)
            start = past + 1
            ! (an array's value named by its place: 'props = 1e400 (value 3)')
            shown = clip_text(value)
            if (count > 1) shown = shown//' (value '//int_to_string(j)//')'
            lower = to_lower(value)
            select case (kind)
            case (KIND_REAL)
               ! one real literal, and a finite double (1e400 is not)
               good = .false.
               why = 'not a number'
               if (value_kind == 0) call parse_real(value, number, good, why)
               if (.not. good .and. why == UNDERFLOW_WHY .and. present(subnormals)) then
                  ! (a literal that reads as a nonzero subnormal; one that vanishes stays refused)
                  if (subnormals) then
                     read (value, *, iostat=ios) number
                     good = ios == 0 .and. abs(number) > 0.0_dp
                  end if
               end if
               if (.not. good) message = where//' = '//shown//' is '//trim(why)
            case (KIND_INTEGER)
               good = value_kind == 0 .and. len(value) > 0
               if (good) good = verify(value(merge(2, 1, scan(value(1:1), '+-') > 0):), '0123456789') == 0 &
                  .and. len(value) > merge(1, 0, scan(value(1:1), '+-') > 0)
               if (.not. good) then
                  message = where//' = '//shown//' is not an integer'
               else if (significant_digits(value) > 9) then
                  good = .false.
                  message = where//' = '//shown//' is too large: an integer of at most 9 digits'
               end if
            case (KIND_LOGICAL)
               good = value_kind == 0 .and. (lower == '.true.' .or. lower == '.false.' .or. lower == 't' &
                  .or. lower == 'f' .or. lower == '.t.' .or. lower == '.f.')
               if (.not. good) message = where//' = '//shown//' is not .true. or .false.'
            case (KIND_STRING)
               good = value_kind == KIND_STRING
               if (.not. good) then
                  message = where//' = '//shown//' is not a quoted string'
               else if (unquoted_length(value) > length) then
                  good = .false.
                  message = where//' = '//shown//' is '//int_to_string(unquoted_length(value))// &
                     ' characters long: this entry takes at most '//int_to_string(length)//' (a longer one '// &
                     'would be cut short)'
               end if
            end select
            if (.not. good) exit
         end do
         if (.not. good) call close_text_file(unit)
      end function finish_entry

      !> The values of an entry that takes one but got several, as written (': 0 and 75', ': 1,
      !> 2 and 3 more'), and, where a comma split a real in two ('mu = 0,75'), the number meant
      !> with a decimal point; '' for no value.
      function values_shown(kind) result(text)
         integer, intent(in) :: kind                   !! the entry's kind (the hint: KIND_REAL only)
         character(len=:), allocatable :: text
         character(len=:), allocatable :: first_value, second_value, joined
         integer :: j, start, past
         real(dp) :: number
         logical :: good
         character(len=32) :: why
         text = ''
         first_value = ''
         second_value = ''
         if (nvalues < 2) return
         start = 1
         do j = 1, min(nvalues, 2, max_count)
            past = start + index(values_given(start:), achar(10)) - 1
            if (j == 1) first_value = values_given(start:past - 1)
            if (j == 2) second_value = values_given(start:past - 1)
            start = past + 1
         end do
         text = ': '//clip_text(first_value)
         if (nvalues == 2) then
            text = text//' and '//clip_text(second_value)
         else
            text = text//', '//clip_text(second_value)//' and '//int_to_string(nvalues - 2)//' more'
         end if
         if (kind /= KIND_REAL .or. nvalues /= 2 .or. .not. comma_after_first) return
         if (kinds_given(1) /= 0 .or. kinds_given(2) /= 0) return
         ! a whole number, a comma, then digits (with an exponent or not): '0,75', '-1,5e-3'
         if (len(first_value) == 0 .or. len(second_value) == 0) return
         if (verify(first_value(merge(2, 1, scan(first_value(1:1), '+-') > 0):), '0123456789') /= 0) return
         if (scan(first_value(len(first_value):len(first_value)), '0123456789') == 0) return
         if (scan(second_value(1:1), '0123456789') == 0) return
         joined = first_value//'.'//second_value
         call parse_real(joined, number, good, why)
         if (.not. good) return
         text = text//' (a comma separates two values in a namelist; for the number '//clip_text(first_value)// &
            ','//clip_text(second_value)//' write a decimal point: '//clip_text(joined)//')'
      end function values_shown

      !> The length of the text of a quoted string (`quoted`: its quotes around it, a doubled quote
      !> for one), as the namelist read stores it.
      pure integer function unquoted_length(quoted) result(n)
         character(len=*), intent(in) :: quoted
         integer :: j
         n = 0
         j = 2
         do while (j < len(quoted))
            if (quoted(j:j) == quoted(1:1)) j = j + 1      ! (a doubled quote is one)
            n = n + 1
            j = j + 1
         end do
      end function unquoted_length

      !> The digits of an integer literal without its sign and leading zeros (at least 1).
      pure integer function significant_digits(literal) result(n)
         character(len=*), intent(in) :: literal
         integer :: first
         first = verify(literal, '+-0')
         if (first == 0) then
            n = 1
         else
            n = len(literal) - first + 1
         end if
      end function significant_digits

      subroutine fail(text)
         character(len=*), intent(in) :: text
         message = path//':'//int_to_string(line_number)//': '//text
         call close_text_file(unit)
      end subroutine fail

      !> The entries of `known` in group `g`, comma-separated ('' when g is not a group of it).
      function group_entries(g) result(list)
         character(len=*), intent(in) :: g
         character(len=:), allocatable :: list
         integer :: j
         list = ''
         do j = 1, size(known)
            if (index(known(j)%name, g//'.') /= 1) cycle
            if (len(list) > 0) list = list//', '
            list = list//trim(known(j)%name(len(g) + 2:))
         end do
      end function group_entries

      !> The column in `text` of the first '&' or '$' that the namelist read, searching the file
      !> for a group, would take for that group's start: followed by the name of a group of
      !> `known` (any case) that no name character continues; 0 if none (`R&D`, `a$b` are safe).
      integer function group_marker(text) result(at)
         character(len=*), intent(in) :: text
         integer :: k
         at = 0
         do k = 1, len(text)
            if (text(k:k) /= '&' .and. text(k:k) /= '$') cycle
            if (len(marked_group(text, k)) > 0) then
               at = k
               return
            end if
         end do
      end function group_marker

      !> The group of `known` whose name follows the marker at text(k:k) ('' if none).
      function marked_group(text, k) result(g)
         character(len=*), intent(in) :: text
         integer, intent(in) :: k
         character(len=:), allocatable :: g
         integer :: last
         g = ''
         last = k
         do while (last < len(text))
            if (verify(text(last + 1:last + 1), NAME_CHARACTERS) /= 0) exit
            last = last + 1
         end do
         if (last == k) return
         if (len(group_entries(to_lower(text(k + 1:last)))) == 0) return
         g = text(k + 1:last)
      end function marked_group

      !> The groups of `known`, in order of first appearance ('&material, &loading').
      function known_groups(last_separator) result(list)
         !> what goes before the last group (default ', ': '&a, &b, &c'; ' and ': '&a, &b and &c')
         character(len=*), intent(in), optional :: last_separator
         character(len=:), allocatable :: list
         integer :: j, dot, last
         list = ''
         last = 0
         do j = 1, size(known)
            dot = index(known(j)%name, '.')
            if (index(list//',', '&'//known(j)%name(:dot - 1)//',') > 0) cycle
            if (len(list) > 0) then
               last = len(list)
               list = list//', '
            end if
            list = list//'&'//known(j)%name(:dot - 1)
         end do
         if (present(last_separator) .and. last > 0) list = list(:last)//last_separator//list(last + 3:)
      end function known_groups

   end subroutine check_namelist_file

   !> `message` ('path: &group: name ...', a check after the namelist read) with the line where
   !> the entry `name` was given: 'path:line: &group: name ...'; as it is when it does not start
   !> so or names no entry of `lines`.
   function with_entry_line(message, path, lines) result(text)
      character(len=*), intent(in) :: message, path
      type(entry_line_type), intent(in) :: lines(:)
      character(len=:), allocatable :: text
      character(len=:), allocatable :: rest, group, word
      integer :: colon, j, last
      text = message
      if (index(message, path//': &') /= 1) return
      rest = message(len(path) + 4:)
      colon = index(rest, ': ')
      if (colon < 2) return
      group = rest(:colon - 1)
      rest = rest(colon + 2:)
      last = verify(rest//' ', 'abcdefghijklmnopqrstuvwxyz0123456789_') - 1
      if (last < 1) return
      word = rest(:last)
      do j = 1, size(lines)
         if (trim(lines(j)%name) == to_lower(group)//'.'//word) then
            text = path//':'//int_to_string(lines(j)%line)//': &'//group//': '//rest
            return
         end if
      end do
   end function with_entry_line

   !> How many values the entry `name` ('group.entry', lower case) was given in the file whose
   !> pre-check found `lines`: 0 where it was not given.
   pure integer function given_values(lines, name) result(n)
      type(entry_line_type), intent(in) :: lines(:)
      character(len=*), intent(in) :: name
      integer :: j
      n = 0
      do j = 1, size(lines)
         if (trim(lines(j)%name) == name) n = lines(j)%values
      end do
   end function given_values

end module interphase_driver_namelist
