!> Tabulated R-curves of the fracture-mechanics damage law: G_cI(D) and G_cII(D) read from a
!> file once at start-up (Abaqus: UEXTERNALDB with INTERPHASE_RCURVE; the driver: its case
!> file) into `protected` data, and evaluated by pure code.
!>
!> File format: plain text, `#` comments and blank lines allowed; one row per point,
!> `D G_cI G_cII` with D = a/b strictly increasing in [0, 1] (at least two rows, consecutive D at
!> least 1e-9 apart) and the toughnesses in [1e-20, 1e20] N/mm, the window of the PROPS
!> toughness (energy per unit crack area, as measured; the eq-20 release rate G is twice it;
!> docs/theory.md). Between the rows a monotone cubic (Fritsch-Carlson) interpolates, so the
!> R-curve keeps the shape of the data; outside the rows it is an error, never an extrapolation.
!> A comment that gives a column another unit (`# D G_cI (J/m^2) G_cII (J/m^2)`, `D (mm)`) is
!> refused: its numbers would be read as N/mm (`foreign_unit`).
module interphase_rcurve
   use interphase_finite, only: is_finite, PROPS_VALUE_MIN, PROPS_VALUE_MAX
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text
   use interphase_status, only: message_path, separation_text, STATUS_OK, STATUS_RCURVE_UNREADABLE, STATUS_RCURVE_MALFORMED, &
      STATUS_RCURVE_NEGATIVE, STATUS_RCURVE_BAD_RANGE, STATUS_RCURVE_BAD_TOUGHNESS, STATUS_RCURVE_NOT_LOADED, MESSAGE_LEN, &
      STATUS_RCURVE_OUT_OF_RANGE, STATUS_SPLINE_OUT_OF_RANGE, status_message
   use interphase_text_input, only: text_file_type, open_text_file, read_text_line, close_text_file, &
      parse_real, tried_path, clip_text, TEXT_LINE, TEXT_END, path_problem, to_lower, next_parenthesised, &
      LENGTH_UNIT_WORDS
   use interphase_spline, only: spline_type, spline_build, spline_export, cubic_locate, cubic_eval, &
      SPLINE_MONOTONE
   implicit none
   private
   public :: load_rcurve, tabulated_rcurve, rcurve_source, rcurve_loaded, rcurve_covers, rcurve_coverage, &
      rcurve_overrun, rcurve_loaded_path

   !> Smallest difference of consecutive rows' D. With toughnesses in the PROPS window
   !> [1e-20, 1e20] N/mm it keeps the interpolant's divided differences below about 1e29 N/mm
   !> and its cubic coefficients below 1e48 (no overflow in the spline or the fracture law's
   !> derivatives); 1e-9 b is far below any measured crack length.
   real(dp), parameter :: D_SPACING_MIN = 1.0e-9_dp

   real(dp), allocatable, protected :: rcurve_knots(:)          !! D of the rows
   real(dp), allocatable, protected :: rcurve_coef(:, :, :)     !! monotone cubic, 2 columns
   character(len=:), allocatable, protected :: loaded_source    !! file it came from, as given
   character(len=:), allocatable, protected :: loaded_tried     !! the same as tried (absolute)

contains

   !> Read and check an R-curve file; call once at start-up, before any update. Each field must
   !> be one real literal (interphase_text_input); lines and the file are bounded. Errors name
   !> the file (as tried) and the line.
   subroutine load_rcurve(path, status, message)
      character(len=*), intent(in) :: path
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      type(text_file_type) :: file
      character(len=MESSAGE_LEN) :: text
      character(len=32) :: why
      character(len=:), allocatable :: source
      real(dp), allocatable :: rows(:, :), grown(:, :)
      real(dp) :: v(3)
      integer :: outcome, n, first, last, i, j, field, starts(3), ends(3)
      logical :: ok
      type(spline_type) :: spline

      status = STATUS_OK
      message = ''
      source = tried_path(path)
      if (len(path_problem(path)) > 0) then
         status = STATUS_RCURVE_UNREADABLE
         message = 'cannot open: '//path_problem(path)
         if (len_trim(path) > 0) message = message_path(source)//': '//trim(message)
         return
      end if
      call open_text_file(path, file, ok, text)
      if (.not. ok) then
         status = STATUS_RCURVE_UNREADABLE
         message = message_path(source)//': '//trim(text)
         return
      end if
      allocate (rows(3, 32))
      n = 0
      read_lines: do
         call read_text_line(file, outcome, text)
         if (outcome == TEXT_END) exit read_lines
         if (outcome /= TEXT_LINE) then
            call fail(STATUS_RCURVE_UNREADABLE, trim(text))
            return
         end if
         associate (line => file%buffer(1:file%length))
            first = verify(line, ' '//achar(9))
            if (first == 0) cycle read_lines
            if (line(first:first) == '#') then
               ! a comment that gives the columns other units than the reader's (`G_cI (J/m^2)`)
               text = foreign_unit(line(first + 1:))
               if (len_trim(text) > 0) then
                  call fail(STATUS_RCURVE_MALFORMED, trim(text))
                  return
               end if
               cycle read_lines
            end if
            ! a comment after the numbers ends the row, as in the drivers' history files (and is
            ! checked for units as a comment line is)
            last = index(line, '#') - 1
            if (last >= 0) then
               text = foreign_unit(line(last + 2:))
               if (len_trim(text) > 0) then
                  call fail(STATUS_RCURVE_MALFORMED, trim(text))
                  return
               end if
            else
               last = len(line)
            end if
            ! exactly three blank-separated fields, each one number
            field = 0
            i = first
            do while (i <= last)
               j = i
               do while (j <= last)
                  if (line(j:j) == ' ' .or. line(j:j) == achar(9)) exit
                  j = j + 1
               end do
               field = field + 1
               if (field <= 3) then
                  starts(field) = i
                  ends(field) = j - 1
               end if
               i = j
               do while (i <= last)
                  if (line(i:i) /= ' ' .and. line(i:i) /= achar(9)) exit
                  i = i + 1
               end do
            end do
            if (field /= 3) then
               write (text, '(a,i0,a)') 'expected three finite numbers "D G_cI G_cII", found ', field, ' fields: '
               call fail(STATUS_RCURVE_MALFORMED, trim(text)//' '//clip_text(line(first:)))
               return
            end if
            do field = 1, 3
               call parse_real(line(starts(field):ends(field)), v(field), ok, why)
               if (.not. ok) then
                  call fail(STATUS_RCURVE_MALFORMED, 'expected three finite numbers "D G_cI G_cII"; field "'// &
                     clip_text(line(starts(field):ends(field)))//'" is '//trim(why))
                  return
               end if
            end do
            if (.not. (v(2) > 0.0_dp .and. v(3) > 0.0_dp)) then
               call fail(STATUS_RCURVE_NEGATIVE, 'toughness must be > 0 N/mm: '//clip_text(line(first:)))
               return
            end if
            ! the window of the PROPS toughness G_c (the fracture law divides by G_c**2)
            do field = 2, 3
               if (v(field) < PROPS_VALUE_MIN .or. v(field) > PROPS_VALUE_MAX) then
                  call fail(STATUS_RCURVE_BAD_TOUGHNESS, trim(merge('G_cI ', 'G_cII', field == 2))//' = '// &
                     clip_text(line(starts(field):ends(field)))//' lies outside [1e-20, 1e20] N/mm (as the '// &
                     'PROPS toughness): '//clip_text(line(first:)))
                  return
               end if
            end do
            if (v(1) < 0.0_dp .or. v(1) > 1.0_dp) then
               call fail(STATUS_RCURVE_BAD_RANGE, 'D must lie in [0, 1]: '//clip_text(line(first:)))
               return
            end if
            if (n > 0) then
               if (.not. (v(1) > rows(1, n))) then
                  call fail(STATUS_RCURVE_BAD_RANGE, 'D does not increase: '//clip_text(line(first:)))
                  return
               end if
               ! (with the rounding of the rows' D as read: rows written 1e-9 apart pass)
               if (v(1) - rows(1, n) < D_SPACING_MIN*(1.0_dp - 1.0e-6_dp)) then
                  call fail(STATUS_RCURVE_BAD_RANGE, 'D = '//clip_text(line(starts(1):ends(1)))// &
                     " lies closer than 1e-9 to the previous row's D = "//real_text(rows(1, n))// &
                     ' (rows must be at least 1e-9 apart): '//clip_text(line(first:)))
                  return
               end if
            end if
         end associate
         n = n + 1
         if (n > size(rows, 2)) then
            allocate (grown(3, 2*size(rows, 2)))
            grown(:, 1:n - 1) = rows(:, 1:n - 1)
            call move_alloc(grown, rows)
         end if
         rows(:, n) = v
      end do read_lines
      call close_text_file(file)
      if (n < 2) then
         status = STATUS_RCURVE_BAD_RANGE
         message = message_path(source)//': fewer than two rows "D G_cI G_cII"'
         return
      end if
      call spline_build(rows(1, 1:n), transpose(rows(2:3, 1:n)), SPLINE_MONOTONE, spline, status)
      if (status /= STATUS_OK) then
         message = message_path(source)//': '//status_message(status)
         return
      end if
      call spline_export(spline, rcurve_knots, rcurve_coef)
      loaded_source = path
      loaded_tried = source

   contains

      subroutine fail(code, what)
         integer, intent(in) :: code
         character(len=*), intent(in) :: what
         integer :: ios
         status = code
         ! (the path shortened so that the whole reason fits in the message)
         write (message, '(a,a,i0,a,a)', iostat=ios) message_path(source, MESSAGE_LEN - 16 - len(what)), ':', &
            file%line_number, ': ', what
         call close_text_file(file)
      end subroutine fail

   end subroutine load_rcurve

   !> '' when no word in parentheses right after a column's name in an R-curve file's comment
   !> (`comment`, the text after '#') is a unit other than the reader's; else the message. A
   !> toughness (G_cI, G_cII, G_c, G_f, ... any case) is read in N/mm: a group whose first word
   !> (`unit_word`: up to a blank, comma or semicolon, `J / m^2` as `J/m^2`, `J m^-2` as `J.m^-2`,
   !> `kJ/m²` as `kJ/m2`) is a quotient (a '/' or a negative power) and not N/mm or the same
   !> unit written otherwise (kJ/m^2, kJ m^-2, kN/m, N mm^-1, mJ/mm^2; `*`, `.` and `**` as
   !> products and powers) names another one (J/m^2 = 1e-3 N/mm); D is a/b: a length unit after it (mm, m; `in` alone, not
   !> `D (in [0, 1])`) names a crack length. Other words in parentheses are a remark.
   pure function foreign_unit(comment) result(message)
      character(len=*), intent(in) :: comment
      character(len=:), allocatable :: message
      character(len=*), parameter :: TOUGHNESS_NAMES(20) = [character(len=6) :: 'g_ci', 'g_cii', 'gci', 'gcii', &
         'g_c', 'gc', 'g_ic', 'g_iic', 'gic', 'giic', 'g_i', 'g_ii', 'gi', 'gii', 'g_f', 'gf', 'g_fi', 'g_fii', &
         'gfi', 'gfii']
      ! (as `unit_form` writes them: lower case, `**` as `^`, no `*`, `.` or middle dot)
      character(len=*), parameter :: SAME_UNITS(16) = [character(len=8) :: 'n/mm', 'kj/m2', 'kj/m^2', &
         'kn/m', 'mj/mm2', 'mj/mm^2', 'nmm/mm2', 'nmm/mm^2', 'kjm^-2', 'kjm-2', 'knm^-1', 'knm-1', 'nmm^-1', &
         'nmm-1', 'mjmm^-2', 'mjmm-2']
      character(len=:), allocatable :: name, unit, item
      integer :: i
      logical :: found, rest
      message = ''
      i = 1
      do
         call next_parenthesised(comment, i, found, unit, name)
         if (.not. found) exit
         ! its first word (up to a blank, comma or semicolon; blanks around a '/' and UTF-8
         ! superscripts and minus signs as written: `J / m^2`, `kJ/m²`, `J m⁻²`), lower case
         call unit_word(unit, item, rest)
         item = to_lower(item)
         if (any(to_lower(name) == TOUGHNESS_NAMES) .and. is_quotient(item)) then
            if (any(unit_form(item) == SAME_UNITS)) cycle
            message = 'the comment gives '//name//' the unit ('//unit//'), but an R-curve file''s toughnesses are '// &
               'read in N/mm (1 N/mm = 1 kJ/m^2 = 1000 J/m^2): convert the column, and write (N/mm) or no unit'
            return
         end if
         ! (`in` followed by more words is the preposition: `D (in [0, 1])`)
         if (to_lower(name) == 'd' .and. any(item == LENGTH_UNIT_WORDS) .and. .not. (item == 'in' .and. rest)) then
            message = 'the comment gives D the unit ('//unit//'), but D is the crack''s relative length a/b '// &
               '(no unit, in [0, 1]): divide the crack lengths by b'
            return
         end if
      end do
   contains
      !> a unit with a '/' or a negative power (`m^-2`, `m**-2`, `m-2`)
      pure logical function is_quotient(word)
         character(len=*), intent(in) :: word
         is_quotient = index(word, '/') > 0 .or. negative_power(word)
      end function is_quotient
      !> `word` without the marks of a product (`*`, `.`, a UTF-8 middle dot), `**` written `^`
      pure function unit_form(word) result(form)
         character(len=*), intent(in) :: word
         character(len=:), allocatable :: form
         integer :: k
         form = ''
         k = 1
         do while (k <= len(word))
            if (word(k:min(k + 1, len(word))) == '**') then
               form = form//'^'
               k = k + 2
               cycle
            else if (word(k:min(k + 1, len(word))) == char(194)//char(183)) then
               k = k + 2
               cycle
            end if
            if (word(k:k) /= '*' .and. word(k:k) /= '.') form = form//word(k:k)
            k = k + 1
         end do
      end function unit_form
   end function foreign_unit

   !> A negative power in a unit: `^-` or `**-`, or a factor (between `.`, `*` or a middle dot)
   !> that is a length to a power written without a caret, `m-2`, `mm-1`, `cm-2`, `in-1` (any
   !> case), alone or right after the symbol of an energy or a force (`Jm-2`, `kJm-2`, `Nm-1`,
   !> `Nmm-1`: one unit written without a mark of the product); `mode-I`, `Set-1`, `beam-1`,
   !> `EN-1052` and `2-D` are not.
   pure logical function negative_power(word)
      character(len=*), intent(in) :: word
      character(len=*), parameter :: POWERS(12) = [character(len=4) :: 'm-1', 'm-2', 'm-3', 'mm-1', 'mm-2', &
         'mm-3', 'cm-1', 'cm-2', 'cm-3', 'in-1', 'in-2', 'in-3']
      !> the symbols written before a length power without a mark (lower case)
      character(len=*), parameter :: SYMBOLS(7) = [character(len=3) :: 'j', 'kj', 'mj', 'n', 'kn', 'mn', 'nmm']
      integer :: first, k
      negative_power = index(word, '^-') > 0 .or. index(word, '**-') > 0
      first = 1
      do k = 1, len(word) + 1
         if (negative_power) return
         if (k <= len(word)) then
            if (word(k:k) /= '.' .and. word(k:k) /= '*' .and. word(k:k) /= char(194) .and. word(k:k) /= char(183)) cycle
         end if
         if (k > first) negative_power = is_power(to_lower(word(first:k - 1)))
         first = k + 1
      end do
   contains
      !> `factor` is one of POWERS, or one of SYMBOLS followed by one
      pure logical function is_power(factor)
         character(len=*), intent(in) :: factor
         integer :: i, j
         is_power = .false.
         do i = 1, size(POWERS)
            ! (j: the length of what comes before the power)
            j = len(factor) - len_trim(POWERS(i))
            if (j < 0) cycle
            if (factor(j + 1:) /= trim(POWERS(i))) cycle
            is_power = j == 0
            if (.not. is_power) is_power = any(factor(1:j) == SYMBOLS)
            if (is_power) return
         end do
      end function is_power
   end function negative_power

   !> `word`, the first word of a group in parentheses (`content`, blanks trimmed) as
   !> `foreign_unit` reads a unit: up to a blank, tab, comma or semicolon, with blanks around a
   !> '/' joined to it (`J / m^2` is `J/m^2`), a negative power after a blank too, as a product
   !> (`J m^-2` is `J.m^-2`), and UTF-8 superscripts as their plain forms (`plain_superscripts`:
   !> `kJ/m²` is `kJ/m2`, `J m⁻²` is `J.m^-2`); `rest` true when a blank or tab and more words
   !> follow it.
   pure subroutine unit_word(raw_content, word, rest)
      character(len=*), intent(in) :: raw_content
      character(len=:), allocatable, intent(out) :: word
      logical, intent(out) :: rest
      character(len=1), parameter :: TAB = achar(9)
      character(len=:), allocatable :: content
      integer :: i, next
      content = plain_superscripts(raw_content)
      word = ''
      rest = .false.
      i = 1
      do while (i <= len(content))
         select case (content(i:i))
         case (',', ';')
            return
         case (' ', TAB)
            ! a blank before a '/', or after one, joins; else the word ends here
            next = verify(content(i:), ' '//TAB)
            if (next == 0) return
            next = i + next - 1
            if (content(next:next) /= '/' .and. .not. ends_with_slash(word)) then
               if (.not. negative_power(next_word(content(next:)))) then
                  rest = content(next:next) /= ',' .and. content(next:next) /= ';'
                  return
               end if
               ! a product: `J m^-2` is `J.m^-2`
               word = word//'.'
            end if
            i = next
            cycle
         end select
         word = word//content(i:i)
         i = i + 1
      end do
   contains
      !> `text` up to its first blank, tab, comma or semicolon
      pure function next_word(text) result(w)
         character(len=*), intent(in) :: text
         character(len=:), allocatable :: w
         integer :: k
         k = scan(text, ' ,;'//TAB)
         if (k == 0) k = len(text) + 1
         w = text(1:k - 1)
      end function next_word
      pure logical function ends_with_slash(text)
         character(len=*), intent(in) :: text
         ends_with_slash = .false.
         if (len(text) > 0) ends_with_slash = text(len(text):len(text)) == '/'
      end function ends_with_slash
   end subroutine unit_word

   !> `text` with the UTF-8 characters a unit is written with in their plain forms: the
   !> superscript minus (U+207B) as `^-` (as `-` right after a caret: `m^⁻²` is `m^-2`), the
   !> minus sign (U+2212) and the en dash (U+2013) of typeset text as `-`, the superscript digits
   !> (U+00B9, U+00B2, U+00B3, U+2070, U+2074 to U+2079) as the digits (`m⁻²` and `m−²` are
   !> `m^-2` and `m-2`, `m²` is `m2`), except a superscript one right after a letter, the power
   !> one, which is dropped (`N/mm¹` is `N/mm`).
   pure function plain_superscripts(text) result(plain)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: plain
      integer :: i, b2, b3
      plain = ''
      i = 1
      do while (i <= len(text))
         if (text(i:i) == char(194) .and. i < len(text)) then
            ! U+00B2, U+00B3, U+00B9: C2 B2, C2 B3, C2 B9
            b2 = ichar(text(i + 1:i + 1))
            if (b2 == 178 .or. b2 == 179) then
               plain = plain//achar(iachar('0') + b2 - 176)
               i = i + 2
               cycle
            else if (b2 == 185) then
               if (.not. after_letter(plain)) plain = plain//'1'
               i = i + 2
               cycle
            end if
         else if (text(i:i) == char(226) .and. i + 2 <= len(text)) then
            b2 = ichar(text(i + 1:i + 1))
            b3 = ichar(text(i + 2:i + 2))
            if (b2 == 129 .and. (b3 == 176 .or. (b3 >= 180 .and. b3 <= 185))) then
               ! U+2070, U+2074 to U+2079: E2 81 B0, E2 81 B4 to E2 81 B9 (U+2071 to U+2073 are not digits)
               plain = plain//achar(iachar('0') + b3 - 176)
               i = i + 3
               cycle
            else if (b2 == 129 .and. b3 == 187) then
               ! U+207B: E2 81 BB
               if (len(plain) > 0) then
                  if (plain(len(plain):len(plain)) == '^') then
                     plain = plain//'-'
                     i = i + 3
                     cycle
                  end if
               end if
               plain = plain//'^-'
               i = i + 3
               cycle
            else if ((b2 == 136 .and. b3 == 146) .or. (b2 == 128 .and. b3 == 147)) then
               ! U+2212 (E2 88 92), U+2013 (E2 80 93)
               plain = plain//'-'
               i = i + 3
               cycle
            end if
         end if
         plain = plain//text(i:i)
         i = i + 1
      end do
   contains
      pure logical function after_letter(so_far)
         character(len=*), intent(in) :: so_far
         after_letter = .false.
         if (len(so_far) > 0) after_letter = verify(so_far(len(so_far):len(so_far)), &
            'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ') == 0
      end function after_letter
   end function plain_superscripts

   !> G_cI, G_cII (N/mm) and their D-derivatives from the loaded R-curve at D: STATUS_OK,
   !> STATUS_RCURVE_NOT_LOADED, or STATUS_RCURVE_OUT_OF_RANGE when D lies outside the file's
   !> rows (a setup error of the file, not of the increment: rcurve_coverage says what).
   pure subroutine tabulated_rcurve(d, gc, dgc_dd, status)
      real(dp), intent(in) :: d              !! damage D = a/b
      real(dp), intent(out) :: gc(2)         !! (G_cI, G_cII)
      real(dp), intent(out) :: dgc_dd(2)     !! their derivatives d/dD
      integer, intent(out) :: status
      integer :: interval
      if (.not. allocated(rcurve_coef)) then
         status = STATUS_RCURVE_NOT_LOADED
         return
      end if
      call cubic_locate(rcurve_knots, d, interval, status)
      if (status == STATUS_SPLINE_OUT_OF_RANGE) status = STATUS_RCURVE_OUT_OF_RANGE
      if (status /= STATUS_OK) return
      call cubic_eval(rcurve_knots, rcurve_coef, interval, d, gc, dgc_dd)
   end subroutine tabulated_rcurve

   !> Whether a tabulated R-curve has been loaded (R-curve selector 3 needs one).
   pure logical function rcurve_loaded()
      rcurve_loaded = allocated(rcurve_coef)
   end function rcurve_loaded

   !> Whether the loaded R-curve's rows cover D (false when none is loaded).
   pure logical function rcurve_covers(d)
      real(dp), intent(in) :: d              !! damage D = a/b
      rcurve_covers = .false.
      if (.not. allocated(rcurve_knots)) return
      rcurve_covers = d >= rcurve_knots(1) .and. d <= rcurve_knots(size(rcurve_knots))
   end function rcurve_covers

   !> For messages: 'R-curve <file> covers D from <lo> to <hi>' (the file as tried, shortened to
   !> `room` characters when given, else to message_path's length: what the caller writes after
   !> it must fit in its message too).
   pure function rcurve_coverage(room) result(text)
      integer, intent(in), optional :: room     !! characters the file name may take
      character(len=:), allocatable :: text
      if (.not. allocated(rcurve_knots)) then
         text = 'no R-curve loaded'
         return
      end if
      text = 'R-curve '//message_path(loaded_tried, room)//' covers D from '//real_text(rcurve_knots(1), 6)// &
         ' to '//real_text(rcurve_knots(size(rcurve_knots)), 6)
   end function rcurve_coverage

   !> For the message of an update that needs the tabulated R-curve beyond its rows: its coverage
   !> (`rcurve_coverage(room)`), the damage the crack grows from and the separation (mm, normal
   !> first; 2 or 3 components).
   pure function rcurve_overrun(room, d_from, s) result(text)
      integer, intent(in) :: room               !! characters the file name may take
      real(dp), intent(in) :: d_from            !! D_n, or D0 for a crack that has not grown yet (-)
      real(dp), intent(in) :: s(:)              !! the separation (mm)
      character(len=:), allocatable :: text
      text = rcurve_coverage(room)//'; the crack grows beyond it from D = '//real_text(d_from, 6)// &
         ' at separation '//separation_text(s)
   end function rcurve_overrun

   !> The file of the loaded R-curve as it was opened, absolute ('' when none is loaded): what a
   !> replay file records, so that it reads back from any folder, and what a start-up hook compares
   !> a path with before loading it again.
   pure function rcurve_loaded_path() result(path)
      character(len=:), allocatable :: path
      path = ''
      if (allocated(loaded_tried)) path = loaded_tried
   end function rcurve_loaded_path

   !> The file the tabulated R-curve came from, as given to load_rcurve ('' when none is loaded).
   pure function rcurve_source() result(source)
      character(len=:), allocatable :: source
      source = ''
      if (allocated(loaded_source)) source = loaded_source
   end function rcurve_source

end module interphase_rcurve
