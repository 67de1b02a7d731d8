!> History files of the single-point driver: a plain table of prescribed separations.
!>
!>     # comments and blank lines are allowed; '#' also starts a trailing comment
!>     # t    s_T    s_N          (2-D, NTENS = 2)
!>     0      0      0
!>     1      0      0.05
!>
!> or `t s_T1 s_T2 s_N` (3-D, NTENS = 3). Times are arbitrary units, strictly increasing, each
!> step finite; separations in mm, within the update's range (|s| <= SEPARATION_MAX, 1e20 mm).
!> Every data line has the same number of columns. Errors name the file and the line. The table
!> is stored in the UMAT's component order: normal first, then shear(s).
!>
!> Mixed control: a comment line `# columns: t s_T Sigma_N` names the columns; each component
!> is given either as its separation (`s_T`, `s_T1`, `s_T2`, `s_N`; mm) or as its traction
!> (`Sigma_T`, `Sigma_T1`, `Sigma_T2`, `Sigma_N`; MPa), in the order t, shear(s), normal, and a
!> word in parentheses (a unit) is skipped. The names hold for the rows below the line, up to
!> the next `# columns:` line: the segment that ends at a row is controlled as that row's names
!> say. Without such a line every column is a separation. The line holds nothing before its
!> `#`; a comment that starts `column:` or `columns :`, or whose words name traction columns
!> without the key (`# t s_T Sigma_N`; `columns_line_kind`), or separation columns with a length
!> unit other than mm (`# t s_T (m) s_N (m)`), is refused.
module interphase_driver_history
   use, intrinsic :: iso_fortran_env, only: iostat_end, int64
   use interphase_kinds, only: dp
   use interphase_driver_text, only: int_to_string, count_text, real_to_string, read_line, split_words, to_lower, &
      text_file_type, open_line_file, close_text_file
   use interphase_text_input, only: parse_real, clip_text, tried_path, MAX_FILE_BYTES, next_parenthesised, &
      LENGTH_UNIT_WORDS
   use interphase_params, only: SEPARATION_MAX, HOST_VALUE_MAX
   use interphase_finite, only: difference_is_finite
   implicit none
   private
   public :: history_type, read_history, carriage_return_message, parse_number, separator_hint, foreign_length_unit_after

   !> A prescribed separation history.
   type :: history_type
      !> Number of traction components: 2 (2-D) or 3 (3-D).
      integer :: ntens = 0
      !> Number of rows (>= 2).
      integer :: nrows = 0
      !> Time of each row (strictly increasing).
      real(dp), allocatable :: time(:)
      !> Value of each row, (ntens, nrows), UMAT order: normal first, then shear(s): the
      !> separation (mm), or the traction (MPa) where `traction` is true.
      real(dp), allocatable :: separation(:, :)
      !> Line number of each row in the file (for messages).
      integer, allocatable :: line(:)
      !> (ntens, nrows), UMAT order: true where the row's value is a traction (MPa), false
      !> where it is a separation (mm). The segment from row k to k + 1 is controlled as row
      !> k + 1 says.
      logical, allocatable :: traction(:, :)
   end type history_type

   !> Column names of a `# columns:` line, file order after t: 2-D and 3-D, separation then
   !> traction form.
   character(len=*), parameter :: NAMES_2D(2, 2) = reshape([character(len=8) :: 's_T', 's_N', &
      'Sigma_T', 'Sigma_N'], [2, 2])
   character(len=*), parameter :: NAMES_3D(3, 2) = reshape([character(len=8) :: 's_T1', 's_T2', 's_N', &
      'Sigma_T1', 'Sigma_T2', 'Sigma_N'], [3, 2])

   !> `columns_line_kind`'s answers.
   integer, parameter :: PLAIN_COMMENT = 0, COLUMNS_LINE = 1, MISSPELLED_COLUMNS = 2, NAMES_WITHOUT_KEY = 3, &
      NAMES_OUT_OF_ORDER = 4, NAMES_FOREIGN_UNIT = 5

contains

   !> Read a history file. On failure `ok` is false and `message` names the file and line; a file
   !> that cannot be opened is named after `named_by`, where the path came from (the case file,
   !> the entry's line and the entry: 'case.nml:17: &loading: history: ').
   subroutine read_history(path, history, ok, message, named_by)
      character(len=*), intent(in) :: path        !! history file
      type(history_type), intent(out) :: history  !! the table, valid when ok
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      character(len=*), intent(in), optional :: named_by   !! where the path was given
      character(len=:), allocatable :: line, where, shown
      integer, allocatable :: starts(:), ends(:)
      real(dp) :: values(4)
      logical :: named(3), controls(3)
      integer :: ios, line_number, ncolumns, first_data_line, comment, i, named_columns, names_line
      type(text_file_type) :: unit
      integer(int64) :: bytes
      character(len=512) :: iomsg

      ok = .false.
      shown = tried_path(path)
      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = shown//': cannot open the history file: '//trim(iomsg)
         if (present(named_by)) message = named_by//message
         return
      end if

      allocate (history%time(16), history%separation(3, 16), history%line(16), history%traction(3, 16))
      named_columns = 0
      names_line = 0
      named = .false.
      ncolumns = 0
      first_data_line = 0
      line_number = 0
      bytes = 0
      do
         call read_line(unit, line, ios, iomsg)
         if (ios == iostat_end) exit
         line_number = line_number + 1
         where = shown//':'//int_to_string(line_number)//': '
         if (ios /= 0) then
            message = where//'cannot read the line: '//trim(iomsg)
            call close_text_file(unit)
            return
         end if
         bytes = bytes + len(line) + 1
         if (bytes > MAX_FILE_BYTES) then
            message = where//'the file is larger than '//int_to_string(int(MAX_FILE_BYTES))//' bytes'
            call close_text_file(unit)
            return
         end if
         ! a carriage return inside the line (the one before the newline is dropped): the file's
         ! lines end in a carriage return alone (old Mac), and the whole file reads as one line
         message = carriage_return_message(line)
         if (len(message) > 0) then
            message = where//message
            call close_text_file(unit)
            return
         end if
         comment = index(line, '#')
         if (comment > 0) then
            select case (columns_line_kind(line(comment + 1:)))
            case (MISSPELLED_COLUMNS)
               message = where//'"#'//trim(line(comment + 1:))//'" looks like a "# columns:" line, but is not '// &
                  'one: write the key "columns:" (one word, the colon right after it), e.g. "# columns: t s_T Sigma_N"'
               call close_text_file(unit)
               return
            case (NAMES_OUT_OF_ORDER)
               message = where//'"#'//trim(line(comment + 1:))//'" names the columns in another order than '// &
                  'the rows are read (t, the shear component(s), then the normal one: t s_T s_N or t s_T1 s_T2 '// &
                  's_N): reorder the columns and the comment'
               call close_text_file(unit)
               return
            case (NAMES_FOREIGN_UNIT)
               ! (below a "# columns:" line too: the rows are read in mm whatever the caption says)
               message = where//'"#'//trim(line(comment + 1:))//'" gives '// &
                  foreign_length_unit(tabs_as_blanks(line(comment + 1:)))//', but the driver reads separations '// &
                  'in mm: convert the columns, and write (mm) or no unit'
               call close_text_file(unit)
               return
            case (NAMES_WITHOUT_KEY)
               ! (a caption below a "# columns:" line is no mistake: the columns are named)
               if (named_columns == 0) then
                  message = where//'"#'//trim(line(comment + 1:))//'" names traction columns, but is not a '// &
                     '"# columns:" line, so every column would be read as a separation: write the key "columns:" '// &
                     'first, e.g. "# columns: t s_T Sigma_N"'
                  call close_text_file(unit)
                  return
               end if
            case (COLUMNS_LINE)
               if (verify(line(:comment - 1), ' '//char(9)) > 0) then
                  message = where//'a "# columns:" line holds nothing before the ''#'' (here '''// &
                     trim(adjustl(line(:comment - 1)))//'''): put the data row on a line of its own'
                  call close_text_file(unit)
                  return
               end if
               call read_column_names(tabs_as_blanks(line(comment + 1:)), named_columns, named, ok, message)
               if (.not. ok) then
                  message = where//message
                  call close_text_file(unit)
                  return
               end if
               ok = .false.
               if (ncolumns > 0 .and. named_columns /= ncolumns) then
                  message = where//'the "# columns:" line names '//count_text(named_columns, 'column')// &
                     ', but the data lines have '//int_to_string(ncolumns)
                  call close_text_file(unit)
                  return
               end if
               names_line = line_number
               cycle
            end select
            line = line(:comment - 1)
         end if
         call split_words(line, starts, ends)
         if (size(starts) == 0) cycle

         if (ncolumns == 0) then
            if (size(starts) /= 3 .and. size(starts) /= 4) then
               message = where//'found '//count_text(size(starts), 'column')//'; expected 3 '// &
                  '(t s_T s_N, 2-D) or 4 (t s_T1 s_T2 s_N, 3-D)'//separator_hint(line)
               call close_text_file(unit)
               return
            end if
            ncolumns = size(starts)
            first_data_line = line_number
            if (named_columns > 0 .and. named_columns /= ncolumns) then
               message = where//'found '//count_text(ncolumns, 'column')//', but the "# columns:" line '// &
                  '(line '//int_to_string(names_line)//') names '//int_to_string(named_columns)
               call close_text_file(unit)
               return
            end if
         else if (size(starts) /= ncolumns) then
            message = where//'found '//count_text(size(starts), 'column')//', but line '// &
               int_to_string(first_data_line)//' has '//int_to_string(ncolumns)// &
               '; every data line must have the same number of columns'//separator_hint(line)
            call close_text_file(unit)
            return
         end if
         do i = 1, ncolumns
            call parse_number(line(starts(i):ends(i)), values(i), ok, message)
            if (.not. ok) then
               message = where//'column '//int_to_string(i)//': '//message
               if (index(line(starts(i):ends(i)), '!') > 0) message = trim(message)//separator_hint('!')
               call close_text_file(unit)
               return
            end if
         end do
         ok = .false.
         controls = .false.
         if (named_columns > 0) controls(:ncolumns - 1) = named(:ncolumns - 1)
         ! a separation beyond the range the update admits (|s_i| <= SEPARATION_MAX) would fail only
         ! in the UMAT, in the middle of the replay; an imposed traction beyond the UMAT's bound on
         ! STRESS (HOST_VALUE_MAX) would overflow the mixed control's steps between the rows
         do i = 2, ncolumns
            if (controls(i - 1)) then
               if (abs(values(i)) > HOST_VALUE_MAX) then
                  message = where//'column '//int_to_string(i)//': traction '//real_to_string(values(i))// &
                     ' MPa is beyond the range the replay admits, |Sigma| <= '//real_to_string(HOST_VALUE_MAX)//' MPa'
                  call close_text_file(unit)
                  return
               end if
            else if (abs(values(i)) > SEPARATION_MAX) then
               message = where//'column '//int_to_string(i)//': separation '//real_to_string(values(i))// &
                  ' mm is beyond the range the update admits, |s| <= '//real_to_string(SEPARATION_MAX)//' mm'
               call close_text_file(unit)
               return
            end if
         end do

         if (history%nrows > 0) then
            if (.not. (values(1) > history%time(history%nrows))) then
               message = where//'time '//real_to_string(values(1))// &
                  ' is not greater than the previous time '// &
                  real_to_string(history%time(history%nrows))//' (line '// &
                  int_to_string(history%line(history%nrows))//'); times must increase strictly'
               call close_text_file(unit)
               return
            end if
            ! (the replay interpolates the time within the step: the step must be a number)
            if (.not. difference_is_finite(values(1), history%time(history%nrows))) then
               message = where//'time '//real_to_string(values(1))//': the time step from the previous time '// &
                  real_to_string(history%time(history%nrows))//' (line '// &
                  int_to_string(history%line(history%nrows))//') is not finite (beyond the largest double)'
               call close_text_file(unit)
               return
            end if
         end if
         call append_row(history, line_number, values(1), values(2:ncolumns), controls(:ncolumns - 1))
      end do
      call close_text_file(unit)

      if (history%nrows < 2) then
         message = shown//': needs at least 2 data rows, found '//int_to_string(history%nrows)
         return
      end if
      history%ntens = ncolumns - 1
      history%time = history%time(:history%nrows)
      history%line = history%line(:history%nrows)
      history%separation = history%separation(:history%ntens, :history%nrows)
      history%traction = history%traction(:history%ntens, :history%nrows)
      ok = .true.
   end subroutine read_history

   !> What a comment (the text after '#') is: COLUMNS_LINE when it starts with `columns:` (any
   !> case, after blanks), MISSPELLED_COLUMNS when it starts with `column` or `columns` and then,
   !> after blanks, a colon (`column:`, `columns :`: meant as the key, and read as a plain
   !> comment it would leave the columns as separations), NAMES_WITHOUT_KEY when its words are
   !> column names, at least one of them a traction's (`Sigma_`), after an optional word `column`
   !> or `columns` and with words in parentheses (units) skipped (`# t s_T Sigma_N`,
   !> `# columns t s_T Sigma_N`: meant to name the columns, and read as a plain comment it would
   !> run the tractions as separations), NAMES_OUT_OF_ORDER or NAMES_FOREIGN_UNIT for such words
   !> in another order than the rows' or with a length unit other than mm (`column_words_kind`),
   !> else PLAIN_COMMENT.
   pure integer function columns_line_kind(comment)
      character(len=*), intent(in) :: comment     !! text after '#'
      character(len=*), parameter :: KEY = 'columns:', STEM = 'column'
      character(len=len(comment)) :: text
      integer :: i
      ! (tabs read as blanks, as the data rows' words are split)
      text = to_lower(adjustl(tabs_as_blanks(comment)))
      columns_line_kind = column_words_kind(text)
      if (columns_line_kind /= PLAIN_COMMENT) return
      if (len(text) < len(STEM)) return
      if (text(:len(STEM)) /= STEM) return
      if (len(text) >= len(KEY)) then
         if (text(:len(KEY)) == KEY) then
            columns_line_kind = COLUMNS_LINE
            return
         end if
      end if
      i = len(STEM) + 1
      if (i <= len(text)) then
         if (text(i:i) == 's') i = i + 1
      end if
      do while (i <= len(text))
         if (text(i:i) /= ' ' .and. text(i:i) /= char(9)) exit
         i = i + 1
      end do
      if (i > len(text)) return
      if (text(i:i) == ':') columns_line_kind = MISSPELLED_COLUMNS
   end function columns_line_kind

   !> What a comment is when its words (`text`: lower case, blanks for tabs) are two or more
   !> column names, after an optional first word `column` or `columns`, words in parentheses
   !> skipped: NAMES_FOREIGN_UNIT when a separation's name has a length unit other than mm in
   !> parentheses after it (`foreign_length_unit`), NAMES_WITHOUT_KEY when one of them is a
   !> traction's, NAMES_OUT_OF_ORDER when they are not in the rows' order (t first, when named,
   !> then s_t s_n or s_t1 s_t2 s_n); else PLAIN_COMMENT (`columns_line_kind`).
   pure integer function column_words_kind(text) result(kind)
      character(len=*), intent(in) :: text
      character(len=*), parameter :: NAMES(9) = [character(len=8) :: 't', 's_t', 's_n', 's_t1', 's_t2', &
         'sigma_t', 'sigma_n', 'sigma_t1', 'sigma_t2']
      character(len=len(text)) :: kept
      integer, allocatable :: starts(:), ends(:)
      integer :: i, first, nnames
      logical :: traction
      character(len=8) :: order(4)

      kind = PLAIN_COMMENT
      kept = without_parentheses(text)
      ! (commas and semicolons separate the names too: `# t, s_T, Sigma_N`, a spreadsheet's header)
      do i = 1, len(kept)
         if (kept(i:i) == ',' .or. kept(i:i) == ';') kept(i:i) = ' '
      end do
      call split_words(kept, starts, ends)
      if (size(starts) == 0) return
      first = 1
      if (kept(starts(1):ends(1)) == 'column' .or. kept(starts(1):ends(1)) == 'columns') first = 2
      if (size(starts) < first + 1) return
      traction = .false.
      nnames = 0
      order = ''
      do i = first, size(starts)
         if (ends(i) - starts(i) + 1 > len(NAMES)) return
         if (.not. any(kept(starts(i):ends(i)) == NAMES)) return
         traction = traction .or. kept(starts(i):ends(i)) == 'sigma_t' .or. kept(starts(i):ends(i)) == 'sigma_n' &
            .or. kept(starts(i):ends(i)) == 'sigma_t1' .or. kept(starts(i):ends(i)) == 'sigma_t2'
         nnames = nnames + 1
         if (nnames <= size(order)) order(nnames) = kept(starts(i):ends(i))
      end do
      ! in mm, whatever they are (a caption below a "# columns:" line too): `# t s_T (m) s_N (m)`
      ! would run metres as millimetres
      if (len(foreign_length_unit(text)) > 0) then
         kind = NAMES_FOREIGN_UNIT
         return
      end if
      if (traction) then
         kind = NAMES_WITHOUT_KEY
         return
      end if
      ! separations only: in the rows' order, t first when it is named
      if (nnames > size(order)) then
         kind = NAMES_OUT_OF_ORDER
      else if (order(1) == 't') then
         if (.not. in_order(order(2:nnames))) kind = NAMES_OUT_OF_ORDER
      else
         if (.not. in_order(order(1:nnames))) kind = NAMES_OUT_OF_ORDER
      end if
   contains
      pure logical function in_order(names_given)
         character(len=*), intent(in) :: names_given(:)
         in_order = .false.
         if (size(names_given) == 2) then
            in_order = names_given(1) == 's_t' .and. names_given(2) == 's_n'
         else if (size(names_given) == 3) then
            in_order = names_given(1) == 's_t1' .and. names_given(2) == 's_t2' .and. names_given(3) == 's_n'
         end if
      end function in_order
   end function column_words_kind

   !> '' when no word in parentheses right after a separation's name in `text` (a comment of
   !> column names: `column_words_kind`) is a length unit other than mm (LENGTH_UNIT_WORDS, any case);
   !> else the first such name and unit as written (`s_T the unit (m)`). Other words in parentheses are a
   !> remark (`# t s_T s_N (2-D)`).
   pure function foreign_length_unit(text) result(found)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: found
      found = foreign_length_unit_after(text, [character(len=4) :: 's_t', 's_t1', 's_t2', 's_n'])
   end function foreign_length_unit

   !> foreign_length_unit for the separations named `names` (lower case; interphase-fe2d's history:
   !> `u_shear`, `u`): '' or the first name and foreign length unit as written.
   pure function foreign_length_unit_after(text, names) result(found)
      character(len=*), intent(in) :: text
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: found
      character(len=:), allocatable :: name, unit
      integer :: i
      logical :: group
      found = ''
      i = 1
      do
         call next_parenthesised(text, i, group, unit, name)
         if (.not. group) exit
         ! (the text as written: `µM` is lowered as `_files.py` lowers it, A-Z only)
         if (any(to_lower(name) == names) .and. any(to_lower(unit) == LENGTH_UNIT_WORDS) .and. to_lower(unit) /= 'mm') then
            found = name//' the unit ('//unit//')'
            return
         end if
      end do
   end function foreign_length_unit_after

   !> '' when `line` (a data line without its comment) holds no comma, semicolon or '!'; else the
   !> note that ends a wrong-column-count message: the fields of a history are separated by
   !> blanks, and `0,0,0` (a spreadsheet's CSV) is one field. A semicolon is the separator when
   !> there is one (`0,5;0;0`: a spreadsheet's CSV where the comma is the decimal mark, which the
   !> note names). A '!' (a Fortran or namelist comment) does not start a comment here: '#' does.
   pure function separator_hint(line) result(hint)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: hint
      character(len=1) :: separator
      hint = ''
      if (index(line, '!') > 0) then
         hint = ' (''!'' does not start a comment in a history file: ''#'' does)'
         return
      else if (index(line, ';') > 0) then
         separator = ';'
      else if (index(line, ',') > 0) then
         separator = ','
      else
         return
      end if
      hint = ' (the fields of a line are separated by blanks or tabs, not by '''//separator// &
         ''': write the values with blanks between them'
      if (separator == ';' .and. index(line, ',') > 0) hint = hint//', and a point for the decimal comma'
      hint = hint//')'
   end function separator_hint

   !> `text` with every group in parentheses or square brackets, nested ones included, blanked (an unclosed group runs
   !> to the end).
   pure function without_parentheses(text) result(kept)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: kept
      integer :: i, depth
      character(len=1) :: opening, closing
      kept = text
      depth = 0
      opening = '('
      closing = ')'
      do i = 1, len(kept)
         ! (a group in square brackets, `s_T [m]`, as one in parentheses)
         if (depth == 0 .and. (kept(i:i) == '(' .or. kept(i:i) == '[')) then
            opening = kept(i:i)
            closing = merge(')', ']', opening == '(')
         end if
         if (kept(i:i) == opening) depth = depth + 1
         if (depth > 0) then
            if (kept(i:i) == closing) depth = depth - 1
            kept(i:i) = ' '
         end if
      end do
   end function without_parentheses

   !> `text` with every tab a blank.
   pure function tabs_as_blanks(text) result(blanked)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: blanked
      integer :: i
      blanked = text
      do i = 1, len(text)
         if (blanked(i:i) == char(9)) blanked(i:i) = ' '
      end do
   end function tabs_as_blanks

   !> Read the names of a `columns:` comment: t, then the shear component(s) and the normal one,
   !> each `s_X` (separation) or `Sigma_X` (traction); words in parentheses are skipped.
   !> `traction` is in file order (shear(s) first).
   subroutine read_column_names(comment, ncolumns, traction, ok, message)
      character(len=*), intent(in) :: comment     !! text after '#', starting with 'columns:'
      integer, intent(out) :: ncolumns            !! number of columns named (t included)
      logical, intent(out) :: traction(3)         !! file order: true for a Sigma_ column
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      character(len=len(comment)) :: text
      character(len=:), allocatable :: expected
      character(len=16) :: words(4)
      integer, allocatable :: starts(:), ends(:)
      integer :: i, n, k

      ok = .false.
      ncolumns = 0
      traction = .false.
      text = adjustl(comment)
      text(:len('columns:')) = ''
      ! a unit in parentheses right after a name must be the one the driver reads (a history in m
      ! or kPa would run as mm or MPa)
      call check_units(text, message)
      if (len(message) > 0) return
      ! drop the parenthesised words (units)
      text = without_parentheses(text)
      call split_words(text, starts, ends)
      n = size(starts)
      if (n /= 3 .and. n /= 4) then
         message = '"# columns:" names '//count_text(n, 'column')//'; expected t and 2 (2-D) or 3 (3-D) '// &
            'components, e.g. "# columns: t s_T Sigma_N"'
         return
      end if
      do i = 1, n
         words(i) = text(starts(i):min(ends(i), starts(i) + len(words(i)) - 1))
      end do
      if (to_lower(trim(words(1))) /= 't') then   ! (any case, as the other names)
         message = '"# columns:" must start with t, got '''//trim(words(1))//''''
         return
      end if
      do i = 2, n
         traction(i - 1) = .false.
         do k = 1, 2
            if (n == 3) then
               if (to_lower(trim(words(i))) == to_lower(trim(NAMES_2D(i - 1, k)))) exit
            else
               if (to_lower(trim(words(i))) == to_lower(trim(NAMES_3D(i - 1, k)))) exit
            end if
         end do
         if (k > 2) then
            if (n == 3) then
               expected = trim(NAMES_2D(i - 1, 1))//' or '//trim(NAMES_2D(i - 1, 2))
            else
               expected = trim(NAMES_3D(i - 1, 1))//' or '//trim(NAMES_3D(i - 1, 2))
            end if
            message = '"# columns:" column '//int_to_string(i)//' is '''//trim(words(i))//'''; expected '// &
               expected//' (t, the shear component(s), then the normal one)'
            return
         end if
         traction(i - 1) = k == 2
      end do
      ncolumns = n
      ok = .true.
   end subroutine read_column_names

   !> '' when every unit in parentheses right after a column name of a `columns:` line (`text`,
   !> the names after the key) is the driver's: (mm) after s_X, (MPa) after Sigma_X, (s) after t
   !> (any case); else the message naming the first other one. Parentheses after anything else
   !> are a comment and skipped.
   subroutine check_units(text, message)
      character(len=*), intent(in) :: text
      character(len=:), allocatable, intent(out) :: message
      character(len=:), allocatable :: name, unit, wanted
      integer :: i
      logical :: found
      message = ''
      i = 1
      do
         call next_parenthesised(text, i, found, unit, name)
         if (.not. found) exit
         wanted = ''
         select case (to_lower(name))
         case ('t')
            wanted = 's'
         case ('s_t', 's_t1', 's_t2', 's_n')
            wanted = 'mm'
         case ('sigma_t', 'sigma_t1', 'sigma_t2', 'sigma_n')
            wanted = 'mpa'
         end select
         if (len(wanted) > 0 .and. to_lower(unit) /= wanted) then
            if (wanted == 'mpa') wanted = 'MPa'
            message = '"# columns:" gives '//name//' the unit ('//unit//'), but the driver reads '//name// &
               ' in '//wanted//': convert the column, and write ('//wanted//') or no unit'
            return
         end if
      end do
   end subroutine check_units

   !> Append one row; `shear_then_normal` is the file's order (s_T[1], [s_T2,] s_N).
   subroutine append_row(history, line_number, time, shear_then_normal, traction_then_normal)
      type(history_type), intent(inout) :: history  !! table being built
      integer, intent(in) :: line_number          !! line of the row in the file
      real(dp), intent(in) :: time                !! t
      real(dp), intent(in) :: shear_then_normal(:)  !! separations (mm) or tractions (MPa), file order
      logical, intent(in) :: traction_then_normal(:)  !! file order: true where a traction
      real(dp), allocatable :: time_new(:), separation_new(:, :)
      integer, allocatable :: line_new(:)
      logical, allocatable :: traction_new(:, :)
      integer :: n, capacity

      capacity = size(history%time)
      if (history%nrows == capacity) then
         allocate (time_new(2*capacity), separation_new(3, 2*capacity), line_new(2*capacity), &
            traction_new(3, 2*capacity))
         time_new(:capacity) = history%time
         separation_new(:, :capacity) = history%separation
         line_new(:capacity) = history%line
         traction_new(:, :capacity) = history%traction
         call move_alloc(traction_new, history%traction)
         call move_alloc(time_new, history%time)
         call move_alloc(separation_new, history%separation)
         call move_alloc(line_new, history%line)
      end if
      history%nrows = history%nrows + 1
      n = size(shear_then_normal)
      history%time(history%nrows) = time
      history%line(history%nrows) = line_number
      history%separation(:, history%nrows) = 0.0_dp
      history%separation(1, history%nrows) = shear_then_normal(n)
      history%separation(2:n, history%nrows) = shear_then_normal(1:n - 1)
      history%traction(:, history%nrows) = .false.
      history%traction(1, history%nrows) = traction_then_normal(n)
      history%traction(2:n, history%nrows) = traction_then_normal(1:n - 1)
   end subroutine append_row

   !> '' for a line without a carriage return, else the message (without file and line) that
   !> refuses it, naming its column: a carriage return inside a line (the one before the newline
   !> is dropped by the reader) means the file's lines end in a carriage return alone (old Mac),
   !> and the whole file reads as one line. The histories of interphase-point and interphase-fe2d
   !> refuse it alike.
   pure function carriage_return_message(line) result(message)
      character(len=*), intent(in) :: line        !! one line as read
      character(len=:), allocatable :: message
      integer :: i
      message = ''
      i = index(line, achar(13))
      if (i > 0) message = 'a carriage return inside the line (column '//int_to_string(i)//'): a carriage '// &
         'return alone ends lines on old Macs; save the file with Unix or Windows line ends'
   end function carriage_return_message

   !> Parse one number: the whole word one real literal (interphase_text_input: digits, sign,
   !> point, exponent with its letter e/d; not `1-2`, `2*0.5`, `,`), finite.
   subroutine parse_number(word, value, ok, message)
      character(len=*), intent(in) :: word        !! the text
      real(dp), intent(out) :: value              !! the number when ok
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      character(len=32) :: why

      call parse_real(word, value, ok, why)
      if (ok) return
      if (index(why, 'finite') > 0) then
         message = "'"//clip_text(word)//"' is not a finite number "//trim(why(len('not finite ') + 1:))
      else if (index(why, 'out of range') > 0) then
         ! (a nonzero literal below the smallest normal double)
         message = "'"//clip_text(word)//"' is "//trim(why)
      else
         message = "cannot parse '"//clip_text(word)//"' as a number"
      end if
   end subroutine parse_number

end module interphase_driver_history
