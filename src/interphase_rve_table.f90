!> RVE coefficient tables (`tables/README.md` gives the format): reading a table file, checking
!> it against the exact identities of the RVE problems (docs/rve.md), and turning it
!> into the interpolation data of the micromechanical coefficient provider.
!>
!> A table may carry one more column, I_fNT = int sigma^f D_NT dx over the crack (format 2 of
!> tables/README.md); the Betti relations (ii') and (iii') of docs/rve.md are then checked too.
!>
!> This is set-up code (it reads files); the pure update never calls it. A table is read once,
!> at start-up, and its interpolant is immutable afterwards.
!>
!> **Interpolation variable.** Near a = b the ligament 2(b - a) carries the load and every
!> coefficient tends to its a = b value only like 1/ln(1/(b - a)). In a the functions have an
!> infinite slope at b and no polynomial interpolates them well; in
!>     w = 1/(1 + ln(b/(b - a))) = 1/(1 - ln(1 - D)),     w(0) = 1, w(b) = 0,
!> that behaviour becomes linear (C ~ c w as w -> 0), so a cubic in w converges. The knots are
!> the table's rows in ascending w (descending a). dX/dD = (dX/dw)(dw/dD), dw/dD = -w^2/(1 - D).
!> This is the default (`interpolation_variable = w` in the header, or no such key); a table may
!> instead declare `interpolation_variable = D` (knots in ascending D), e.g. a table of
!> coefficients that are polynomials in D, such as the simplified model's.
module interphase_rve_table
   use interphase_finite, only: is_finite, PROPS_VALUE_MIN, PROPS_VALUE_MAX
   use interphase_logarithm, only: ln_positive
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text, es_field
   use interphase_spline, only: SPLINE_NOT_A_KNOT, cubic_locate, cubic_eval
   use interphase_text_input, only: text_file_type, open_text_file, read_text_line, close_text_file, &
      parse_real, tried_path, clip_text, to_lower, TEXT_LINE, TEXT_END, path_problem
   use interphase_status, only: message_path, STATUS_OK, STATUS_TABLE_UNREADABLE, STATUS_TABLE_BAD_HEADER, &
      STATUS_TABLE_MISSING_COLUMN, STATUS_TABLE_MISSING_KEY, STATUS_TABLE_BAD_ROW, &
      STATUS_TABLE_NONFINITE, STATUS_TABLE_NOT_INCREASING, STATUS_TABLE_BAD_RANGE, &
      STATUS_TABLE_IDENTITY, MESSAGE_LEN
   implicit none
   private
   public :: rve_table_type, read_rve_table, check_rve_table, interpolation_data, crack_variable, &
      short_crack_a_tf, oscillation_index

   !> Interpolation variables: w = 1/(1 - ln(1 - D)) (default) or D itself.
   integer, parameter, public :: VARIABLE_LOG_LIGAMENT = 1
   integer, parameter, public :: VARIABLE_DAMAGE = 2

   !> Interpolant of the coefficient tables (SPLINE_* of interphase_spline); see docs/theory.md
   !> for the choice.
   integer, parameter, public :: TABLE_SPLINE_METHOD = SPLINE_NOT_A_KNOT

   !> Number of columns of a table file.
   integer, parameter, public :: N_TABLE_COLUMNS = 23
   !> Column names of a table file, in the documented order.
   character(len=8), parameter, public :: TABLE_COLUMNS(N_TABLE_COLUMNS) = [character(len=8) :: &
      'a', 'D', 'C_TT', 'C_TN', 'C_NT', 'C_NN', 'Dbar_TT', 'Dbar_TN', 'Dbar_NT', 'Dbar_NN', &
      'Cc_TT', 'Cc_TN', 'Cc_NT', 'Cc_NN', 'Tc_T', 'Tc_N', 'Sc_T', 'Sc_N', 'Cf_T', 'Cf_N', 'Tf', &
      'Sf', 'ufbar']
   !> Optional column (format 2): I = int over the crack of sigma^f(x) D_NT(x) dx (MPa mm), the
   !> p3 normal crack stress per unit slip against the p1 normal jump per unit E_T.
   character(len=8), parameter, public :: BETTI_COLUMN = 'I_fNT'
   integer, parameter :: COL_A = 1, COL_D = 2, COL_C_TT = 3, COL_C_TN = 4, COL_C_NT = 5, &
      COL_C_NN = 6, COL_DBAR_TT = 7, COL_DBAR_TN = 8, COL_DBAR_NT = 9, COL_DBAR_NN = 10, &
      COL_CC_TT = 11, COL_CC_TN = 12, COL_CC_NT = 13, COL_CC_NN = 14, COL_TC_T = 15, &
      COL_TC_N = 16, COL_SC_T = 17, COL_SC_N = 18, COL_CF_T = 19, COL_CF_N = 20, COL_TF = 21, &
      COL_SF = 22, COL_UFBAR = 23

   !> Interpolated columns, in interface units (per unit separation; docs/theory.md): the
   !> members of `coefficient_set_type`, in this order, except that T^f, which grows like 1/D
   !> as D -> 0, is interpolated as D T^f (IC_DTF), which is smooth with a finite limit at D = 0
   !> (`short_crack_a_tf`); the provider divides by D. C^f_T is not among them: the provider forms
   !> it from the reciprocity relation C^f_T = -tc_t D ufbar (interphase_micro_coefficients,
   !> `reciprocal_cf`; the table's column is checked against the relation at its rows).
   integer, parameter, public :: N_COEFFICIENTS = 10
   integer, parameter, public :: IC_K_N = 1, IC_K_T = 2, IC_KC_N = 3, IC_KC_T = 4, &
      IC_DBAR_N = 5, IC_DBAR_T = 6, IC_TC_T = 7, IC_SC_N = 8, IC_DTF = 9, IC_UFBAR = 10

   !> Relative tolerance of the identity checks: the FreeFEM tables satisfy them to ~1e-11.
   real(dp), parameter, public :: IDENTITY_TOL = 1.0e-8_dp
   !> Relative tolerance of the Betti relations (i), (ii') and (iii') in a table that carries
   !> I_fNT (residual of (ii') and (iii') relative to the relation's largest term, of (i) to
   !> C(0)): round-off. Measured on the committed tables and the ctest runs: (i) <= 1.1e-14,
   !> (ii') <= 1.5e-12 (a = 0.05 mm, where C^f_T is 1e-3 of C_TT(0)/h), (iii') <= 1.3e-13.
   real(dp), parameter, public :: BETTI_TOL = 1.0e-10_dp

   !> The largest magnitude of a table's value: a value beyond it is no RVE's (moduli and lengths
   !> lie in [1e-20, 1e20]), and the identity checks and the spline multiply and divide the values,
   !> which must not overflow (a T^f of -1.7e308 did, in the spline).
   real(dp), parameter, public :: TABLE_VALUE_MAX = 1.0e100_dp

   !> A table as read from its file.
   type :: rve_table_type
      character(len=:), allocatable :: source     !! file it came from (for messages)
      real(dp) :: b = 0.0_dp                      !! RVE half-length (mm)
      real(dp) :: h = 0.0_dp                      !! RVE height h = h_m + h_b (mm)
      integer :: variable = VARIABLE_LOG_LIGAMENT !! VARIABLE_* of the interpolation
      real(dp) :: a_tf_limit = 0.0_dp             !! lim a T^f as a -> 0 (MPa), short_crack_a_tf
      real(dp), allocatable :: rows(:, :)         !! rows(i, column) in the file's units
      integer, allocatable :: line(:)             !! file line of each row (for messages)
      logical :: has_betti = .false.              !! the file has the column BETTI_COLUMN
      real(dp), allocatable :: i_fnt(:)           !! I_fNT of each row (MPa mm); only with has_betti
      logical :: has_elastic = .false.            !! the header gives E_m, nu_m, E_b, nu_b
      real(dp) :: elastic(4) = 0.0_dp             !! E_m (MPa), nu_m, E_b (MPa), nu_b; with has_elastic
      !> the header gives the layers' heights h_m, h_b (mm): their sum is checked against h, and
      !> with the elastic constants the intact laminate's closed forms against the a = 0 row
      !> (check_rve_table)
      logical :: has_layers = .false.
      real(dp) :: layers(2) = 0.0_dp              !! h_m, h_b (mm); with has_layers
      !> the header's closed forms Chat_TT, Chat_NN (MPa; per unit E), checked against the a = 0 row
      logical :: has_chat(2) = .false.
      real(dp) :: chat(2) = 0.0_dp
   end type rve_table_type

contains

   !> Read a table file: header `# key = value` lines (keys b and h required, each once), the
   !> `# columns:` line (every documented column once, any order; BETTI_COLUMN optional), then one row per a, each
   !> field one real literal (interphase_text_input: no list-directed reading). Lines and the
   !> file are bounded (MAX_LINE_LEN, MAX_FILE_BYTES). Errors name the file (as tried) and
   !> line. The identities are checked separately (`check_rve_table`).
   subroutine read_rve_table(path, table, status, message)
      character(len=*), intent(in) :: path                 !! table file
      type(rve_table_type), intent(out) :: table
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      integer, parameter :: MAX_FIELDS = 64
      type(text_file_type) :: file
      character(len=MESSAGE_LEN) :: text
      character(len=32) :: why
      integer :: starts(MAX_FIELDS + 1), ends(MAX_FIELDS + 1)
      integer :: outcome, nfields, position(N_TABLE_COLUMNS), ncols, nrows, j, k, first, eq, position_i
      integer :: columns_line        !! the line of the "# columns:" line
      real(dp) :: values(MAX_FIELDS), b, h, a_tf_limit, elastic(4), layers(2), chat(2)
      real(dp), allocatable :: rows(:, :)
      integer, allocatable :: lines(:)
      logical :: ok, have_columns, have_b, have_h, have_variable, have_limit, have_elastic(4), have_layers(2), &
         have_chat(2), have_format, known
      integer :: format_number
      integer :: limit_line, elastic_line(4), layer_line(2)   !! the header lines of those keys
      real(dp) :: from_elastic

      status = STATUS_OK
      message = ''
      table%source = tried_path(path)
      if (len(path_problem(path)) > 0) then
         status = STATUS_TABLE_UNREADABLE
         message = 'cannot open: '//path_problem(path)
         if (len_trim(path) > 0) message = message_path(table%source)//': '//trim(message)
         return
      end if
      call open_text_file(path, file, ok, text)
      if (.not. ok) then
         status = STATUS_TABLE_UNREADABLE
         message = message_path(table%source)//': '//trim(text)
         return
      end if
      have_columns = .false.
      columns_line = 0
      have_b = .false.
      have_h = .false.
      have_variable = .false.
      have_limit = .false.
      have_elastic = .false.
      have_layers = .false.
      have_chat = .false.
      have_format = .false.
      format_number = 0
      a_tf_limit = 0.0_dp
      limit_line = 0
      elastic_line = 0
      layer_line = 0
      elastic = 0.0_dp
      layers = 0.0_dp
      chat = 0.0_dp
      position = 0
      position_i = 0
      ncols = 0
      nrows = 0
      b = 0.0_dp
      h = 0.0_dp
      allocate (rows(N_TABLE_COLUMNS + 1, 64), lines(64))
      read_lines: do
         call read_text_line(file, outcome, text)
         if (outcome == TEXT_END) exit read_lines
         if (outcome /= TEXT_LINE) then
            call fail(STATUS_TABLE_UNREADABLE, trim(text))
            return
         end if
         associate (line => file%buffer(1:file%length))
            first = verify(line, ' '//achar(9))
            if (first == 0) cycle read_lines
            if (line(first:first) == '#') then
               ! a tab in a header or comment line is a blank, as in the rest of the readers
               ! (`# Chat_TT<TAB>= 1` is the key Chat_TT)
               do j = first + 1, len(line)
                  if (line(j:j) == achar(9)) line(j:j) = ' '
               end do
               first = first + verify(line(first + 1:)//'x', ' '//achar(9))
               if (have_columns) then
                  ! comments after the header; a second "# columns:" line is refused (one of the two
                  ! would be ignored), and so is a key this reader reads, or one spelt like it: the
                  ! header ends at "# columns:", so it would be ignored
                  eq = index(line(first:), ' = ')
                  if (eq >= 2) then
                     if (len(near_reader_key(line(first:first + eq - 2))) > 0) then
                        write (text, '(a,i0,a)') 'key "'//clip_text(trim(line(first:first + eq - 2)))// &
                           '" after the "# columns:" line (line ', columns_line, &
                           '), where the header has ended and it would not be read: move it above that line'
                        call fail(STATUS_TABLE_BAD_HEADER, trim(text))
                        return
                     end if
                  end if
                  if (first + 7 <= len(line)) then
                     if (line(first:first + 7) == 'columns:') then
                        write (text, '(a,i0,a)') 'a second "# columns:" line (the first on line ', columns_line, &
                           '): a table has exactly one'
                        call fail(STATUS_TABLE_BAD_HEADER, trim(text))
                        return
                     end if
                  end if
                  cycle read_lines
               end if
               if (first + 7 <= len(line)) then
                  if (line(first:first + 7) == 'columns:') then
                     call split(line(first + 8:), starts, ends, nfields)
                     if (nfields > MAX_FIELDS) then
                        write (text, '(a,i0,a)') 'more than ', MAX_FIELDS, ' columns on the "# columns:" line'
                        call fail(STATUS_TABLE_BAD_HEADER, trim(text))
                        return
                     end if
                     starts(1:nfields) = starts(1:nfields) + first + 7
                     ends(1:nfields) = ends(1:nfields) + first + 7
                     do j = 2, nfields
                        do k = 1, j - 1
                           if (line(starts(j):ends(j)) == line(starts(k):ends(k))) then
                              call fail(STATUS_TABLE_BAD_HEADER, 'the "# columns:" line names column "'// &
                                 clip_text(line(starts(j):ends(j)))//'" twice')
                              return
                           end if
                        end do
                     end do
                     ncols = nfields
                     do j = 1, N_TABLE_COLUMNS
                        position(j) = 0
                        do k = 1, nfields
                           if (line(starts(k):ends(k)) == trim(TABLE_COLUMNS(j))) position(j) = k
                        end do
                        if (position(j) == 0) then
                           call fail(STATUS_TABLE_MISSING_COLUMN, 'the "# columns:" line lacks column '// &
                              trim(TABLE_COLUMNS(j)))
                           return
                        end if
                     end do
                     do k = 1, nfields
                        if (line(starts(k):ends(k)) == trim(BETTI_COLUMN)) position_i = k
                        ! a name that is no column of the format (a misspelt I_fNT would otherwise
                        ! make a format-1 table of it, without the Betti checks)
                        known = line(starts(k):ends(k)) == trim(BETTI_COLUMN)
                        do j = 1, N_TABLE_COLUMNS
                           if (line(starts(k):ends(k)) == trim(TABLE_COLUMNS(j))) known = .true.
                        end do
                        if (.not. known) then
                           call fail(STATUS_TABLE_BAD_HEADER, 'the "# columns:" line names column "'// &
                              clip_text(line(starts(k):ends(k)))//'", which is not a table column (tables/'// &
                              'README.md: the 23 of format 1, and '//trim(BETTI_COLUMN)//' in format 2)')
                           return
                        end if
                     end do
                     if (format_number == 2 .and. position_i == 0) then
                        call fail(STATUS_TABLE_MISSING_COLUMN, 'the header says format 2, but the "# columns:" '// &
                           'line lacks its column '//trim(BETTI_COLUMN))
                        return
                     else if (format_number == 1 .and. position_i > 0) then
                        call fail(STATUS_TABLE_BAD_HEADER, 'the header says format 1, but the "# columns:" '// &
                           'line names the format-2 column '//trim(BETTI_COLUMN))
                        return
                     end if
                     if (.not. (have_b .and. have_h)) then
                        call fail(STATUS_TABLE_MISSING_KEY, 'the header before "# columns:" must give '// &
                           '"b = ..." and "h = ..." (mm)')
                        return
                     end if
                     have_columns = .true.
                     columns_line = file%line_number
                     cycle read_lines
                  end if
               end if
               eq = index(line(first:), ' = ')
               if (eq < 2) then
                  ! (say what a header line is: an R-curve file's '# D G_cI G_cII', loaded as a
                  ! table, was named with no hint of what was expected)
                  call fail(STATUS_TABLE_BAD_HEADER, 'header line "# '//clip_text(line(first:))// &
                     '" is not "# key = value" (a blank either side of =) nor the "# columns:" line (tables/README.md)')
                  return
               end if
               eq = first + eq - 1
               select case (line(first:eq - 1))
               case ('b')
                  call header_number('b', line(eq + 3:), 'mm', b, have_b)
                  if (status /= STATUS_OK) return
               case ('h')
                  call header_number('h', line(eq + 3:), 'mm', h, have_h)
                  if (status /= STATUS_OK) return
               case ('a_Tf_limit')
                  ! (a_Tf_limit = -E*/(4(1 - beta^2)) is a modulus: the window of the PROPS values, so
                  ! that the interpolated D T^f, a_Tf_limit/b at a = 0, cannot overflow the spline)
                  call header_real('a_Tf_limit', line(eq + 3:), -PROPS_VALUE_MAX, 0.0_dp, .true., a_tf_limit, &
                     have_limit, closed_below=.true.)
                  if (status /= STATUS_OK) return
                  limit_line = file%line_number
               case ('E_m')
                  call header_number('E_m', line(eq + 3:), 'MPa', elastic(1), have_elastic(1))
                  if (status /= STATUS_OK) return
                  elastic_line(1) = file%line_number
               case ('nu_m')
                  call header_real('nu_m', line(eq + 3:), -1.0_dp, 0.5_dp, .false., elastic(2), have_elastic(2))
                  if (status /= STATUS_OK) return
                  elastic_line(2) = file%line_number
               case ('E_b')
                  call header_number('E_b', line(eq + 3:), 'MPa', elastic(3), have_elastic(3))
                  if (status /= STATUS_OK) return
                  elastic_line(3) = file%line_number
               case ('nu_b')
                  call header_real('nu_b', line(eq + 3:), -1.0_dp, 0.5_dp, .false., elastic(4), have_elastic(4))
                  if (status /= STATUS_OK) return
                  elastic_line(4) = file%line_number
               case ('h_m')
                  call header_number('h_m', line(eq + 3:), 'mm', layers(1), have_layers(1))
                  if (status /= STATUS_OK) return
                  layer_line(1) = file%line_number
               case ('h_b')
                  call header_number('h_b', line(eq + 3:), 'mm', layers(2), have_layers(2))
                  if (status /= STATUS_OK) return
                  layer_line(2) = file%line_number
               case ('Chat_TT')
                  call header_number('Chat_TT', line(eq + 3:), 'MPa', chat(1), have_chat(1))
                  if (status /= STATUS_OK) return
               case ('Chat_NN')
                  call header_number('Chat_NN', line(eq + 3:), 'MPa', chat(2), have_chat(2))
                  if (status /= STATUS_OK) return
               case ('format')
                  if (have_format) then
                     call fail(STATUS_TABLE_BAD_HEADER, 'key "format" given twice')
                     return
                  end if
                  have_format = .true.
                  select case (trim(adjustl(line(eq + 3:))))
                  case ('interphase-rve-table 1')
                     format_number = 1
                  case ('interphase-rve-table 2')
                     format_number = 2
                  case default
                     call fail(STATUS_TABLE_BAD_HEADER, 'format = "'//clip_text(trim(adjustl(line(eq + 3:))))// &
                        '" is not one this reader knows ("interphase-rve-table 1" or "interphase-rve-table 2")')
                     return
                  end select
               case ('interpolation_variable')
                  if (have_variable) then
                     call fail(STATUS_TABLE_BAD_HEADER, 'key "interpolation_variable" given twice')
                     return
                  end if
                  have_variable = .true.
                  select case (trim(adjustl(line(eq + 3:))))
                  case ('w')
                     table%variable = VARIABLE_LOG_LIGAMENT
                  case ('D')
                     table%variable = VARIABLE_DAMAGE
                  case default
                     call fail(STATUS_TABLE_BAD_HEADER, 'interpolation_variable must be w or D, not "'// &
                        clip_text(trim(adjustl(line(eq + 3:))))//'"')
                     return
                  end select
               case default
                  ! a key this reader does not read is provenance; one spelt like a key it reads is a
                  ! mistake that would drop the setting in silence
                  if (len(near_reader_key(line(first:eq - 1))) > 0) then
                     call fail(STATUS_TABLE_BAD_HEADER, 'unknown key "'//clip_text(trim(line(first:eq - 1)))// &
                        '": is it "'//near_reader_key(line(first:eq - 1))//'"? (the keys are case-sensitive; '// &
                        'tables/README.md)')
                     return
                  end if
               end select
               cycle read_lines
            end if
            if (.not. have_columns) then
               call fail(STATUS_TABLE_MISSING_COLUMN, 'data before the "# columns:" line')
               return
            end if
            call split(line, starts, ends, nfields)
            if (nfields /= ncols) then
               if (nfields > MAX_FIELDS) then
                  write (text, '(a,i0,a,i0)') 'more than ', MAX_FIELDS, ' numbers where the "# columns:" line names ', &
                     ncols
               else
                  write (text, '(i0,a,i0)') nfields, ' numbers where the "# columns:" line names ', ncols
               end if
               call fail(STATUS_TABLE_BAD_ROW, trim(text))
               return
            end if
            do j = 1, nfields
               call parse_real(line(starts(j):ends(j)), values(j), ok, why)
               if (.not. ok) then
                  write (text, '(a,i0,a)') 'column ', j, ' ('//trim(column_name(j))//') is '//trim(why)//': "'// &
                     clip_text(line(starts(j):ends(j)))//'"'
                  if (index(why, 'finite') > 0) then
                     call fail(STATUS_TABLE_NONFINITE, trim(text))
                  else
                     call fail(STATUS_TABLE_BAD_ROW, trim(text))
                  end if
                  return
               end if
               if (abs(values(j)) > TABLE_VALUE_MAX) then
                  write (text, '(a,i0,a)') 'column ', j, ' ('//trim(column_name(j))//') = "'// &
                     clip_text(line(starts(j):ends(j)))//'" lies beyond 1e100 in magnitude, the window of '// &
                     'a table''s values (tables/README.md)'
                  call fail(STATUS_TABLE_BAD_ROW, trim(text))
                  return
               end if
            end do
         end associate
         nrows = nrows + 1
         if (nrows > size(lines)) call grow(rows, lines)
         rows(1:N_TABLE_COLUMNS, nrows) = values(position)
         rows(N_TABLE_COLUMNS + 1, nrows) = 0.0_dp
         if (position_i > 0) rows(N_TABLE_COLUMNS + 1, nrows) = values(position_i)
         lines(nrows) = file%line_number
      end do read_lines
      ! (what the whole file lacks is named without a line: the end of the file is not where)
      if (.not. have_columns) then
         call fail_file(STATUS_TABLE_MISSING_COLUMN, 'no "# columns:" line')
         return
      end if
      ! a key whose partner is missing would go unused: the layers' heights are checked against h
      ! in pairs, and the elastic constants (the intact laminate at a = 0, the short-crack limit) in
      ! fours
      if (any(have_layers) .and. .not. all(have_layers)) then
         call fail_partner(layer_line, [character(len=4) :: 'h_m', 'h_b'], have_layers, &
            'h = h_m + h_b is checked with both')
         return
      end if
      if (any(have_elastic) .and. .not. all(have_elastic)) then
         call fail_partner(elastic_line, [character(len=4) :: 'E_m', 'nu_m', 'E_b', 'nu_b'], have_elastic, &
            'the short-crack limit and the intact laminate at a = 0 follow from all four')
         return
      end if
      if (have_limit .and. all(have_elastic)) then
         ! both: they must agree (docs/rve.md, 'Short cracks'), or the header contradicts itself
         from_elastic = short_crack_a_tf(elastic(1), elastic(2), elastic(3), elastic(4))
         if (abs(a_tf_limit - from_elastic) > IDENTITY_TOL*abs(from_elastic)) then
            write (text, '(a,i0,a,i0,a)') 'a_Tf_limit = '//trim(real_text(a_tf_limit))//' MPa contradicts the '// &
               'header''s E_m, nu_m, E_b, nu_b (lines ', minval(elastic_line), '-', maxval(elastic_line), &
               '), which give -E*/(4(1 - beta^2)) = '//trim(real_text(from_elastic))// &
               ' MPa (docs/rve.md, ''Short cracks''; 1e-8 relative): drop the line or correct it'
            call fail_at(limit_line, STATUS_TABLE_BAD_HEADER, trim(text))
            return
         end if
      end if
      if (.not. have_limit) then
         if (.not. all(have_elastic)) then
            call fail_file(STATUS_TABLE_MISSING_KEY, 'the header must give the short-crack limit '// &
               '"a_Tf_limit = ..." (MPa) or the layers'' "E_m", "nu_m", "E_b", "nu_b" (plane strain) it '// &
               'follows from')
            return
         end if
         a_tf_limit = short_crack_a_tf(elastic(1), elastic(2), elastic(3), elastic(4))
      end if
      call close_text_file(file)
      table%b = b
      table%h = h
      table%a_tf_limit = a_tf_limit
      table%rows = transpose(rows(1:N_TABLE_COLUMNS, 1:nrows))
      table%line = lines(1:nrows)
      table%has_betti = position_i > 0
      if (table%has_betti) then
         table%i_fnt = rows(N_TABLE_COLUMNS + 1, 1:nrows)
      end if
      table%has_elastic = all(have_elastic)
      if (table%has_elastic) table%elastic = elastic
      table%has_layers = all(have_layers)
      if (table%has_layers) table%layers = layers
      table%has_chat = have_chat
      table%chat = chat

   contains

      !> Set the status and the message 'file:line: text', and close the file (once).
      subroutine fail(code, what)
         integer, intent(in) :: code
         character(len=*), intent(in) :: what
         integer :: ios
         status = code
         ! (the path shortened so that the whole reason fits in the message)
         write (message, '(a,a,i0,a,a)', iostat=ios) message_path(table%source, MESSAGE_LEN - 16 - len(what)), ':', &
            file%line_number, ': ', what
         call close_text_file(file)
      end subroutine fail

      !> Set the status and the message 'file:at: text' (a line before the current one), and close
      !> the file.
      subroutine fail_at(at, code, what)
         integer, intent(in) :: at
         integer, intent(in) :: code
         character(len=*), intent(in) :: what
         integer :: ios
         status = code
         write (message, '(a,a,i0,a,a)', iostat=ios) message_path(table%source, MESSAGE_LEN - 16 - len(what)), ':', &
            at, ': ', what
         call close_text_file(file)
      end subroutine fail_at

      !> A key given without its partners: the message at the first key given names it and the
      !> missing ones (STATUS_TABLE_MISSING_KEY).
      subroutine fail_partner(key_line, keys, given, why)
         integer, intent(in) :: key_line(:)          !! the line of each key (0 where not given)
         character(len=*), intent(in) :: keys(:)     !! the keys of the group
         logical, intent(in) :: given(:)             !! which of them the header gives
         character(len=*), intent(in) :: why         !! what they are read for
         character(len=:), allocatable :: have, lack
         integer :: kk
         have = ''
         lack = ''
         do kk = 1, size(keys)
            if (given(kk)) then
               have = have//merge(', ', '  ', len(have) > 0)//trim(keys(kk))
            else
               lack = lack//merge(', ', '  ', len(lack) > 0)//trim(keys(kk))
            end if
         end do
         ! (the leading two characters of each list are blanks)
         call fail_at(minval(key_line, mask=given), STATUS_TABLE_MISSING_KEY, 'the header gives '//have(3:)// &
            ' but not '//lack(3:)//': '//why//', and without them the rest go unused (tables/README.md)')
      end subroutine fail_partner

      !> Set the status and the message 'file: text' (no line), and close the file.
      subroutine fail_file(code, what)
         integer, intent(in) :: code
         character(len=*), intent(in) :: what
         integer :: ios
         status = code
         write (message, '(a,a,a)', iostat=ios) message_path(table%source, MESSAGE_LEN - 4 - len(what)), ': ', what
         call close_text_file(file)
      end subroutine fail_file

      !> The name of field k of a data row, from the "# columns:" line.
      function column_name(k) result(name)
         integer, intent(in) :: k
         character(len=16) :: name
         integer :: jj
         name = '?'
         if (k == position_i) name = BETTI_COLUMN
         do jj = 1, N_TABLE_COLUMNS
            if (position(jj) == k) name = TABLE_COLUMNS(jj)
         end do
      end function column_name

      !> A header length or modulus: one positive number in the window of the PROPS values,
      !> [1e-20, 1e20] in its unit (the short-crack limit and the intact-laminate identities
      !> divide by them), the key given once.
      subroutine header_number(key, field, unit, value, found)
         character(len=*), intent(in) :: key, field
         character(len=*), intent(in) :: unit         !! the value's unit, for the message
         real(dp), intent(out) :: value
         logical, intent(inout) :: found
         logical :: ok_number
         character(len=32) :: why_number
         if (found) then
            call fail(STATUS_TABLE_BAD_HEADER, 'key "'//key//'" given twice')
            return
         end if
         call parse_real(field, value, ok_number, why_number)
         if (.not. ok_number .and. index(why_number, 'out of range') > 0) then
            ! (a literal beyond the doubles' range, or below the smallest normal one: said so)
            call fail(STATUS_TABLE_BAD_HEADER, key//' = "'//clip_text(trim(adjustl(field)))//'" is '// &
               trim(why_number))
            return
         end if
         if (ok_number) ok_number = value > 0.0_dp
         if (.not. ok_number) then
            call fail(STATUS_TABLE_BAD_HEADER, key//' = "'//clip_text(trim(adjustl(field)))// &
               '" is not one positive number')
            return
         end if
         if (value < PROPS_VALUE_MIN .or. value > PROPS_VALUE_MAX) then
            call fail(STATUS_TABLE_BAD_HEADER, key//' = "'//clip_text(trim(adjustl(field)))// &
               '" lies outside [1e-20, 1e20] '//unit)
            return
         end if
         found = .true.
      end subroutine header_number

      !> A header number in (lower, upper), or with `closed_above` (lower, upper], with
      !> `closed_below` [lower, ... (a_Tf_limit: [-1e20, 0]; Poisson's ratios: (-1, 0.5)), the key
      !> given once.
      subroutine header_real(key, field, lower, upper, closed_above, value, found, closed_below)
         character(len=*), intent(in) :: key, field
         real(dp), intent(in) :: lower, upper
         logical, intent(in) :: closed_above
         real(dp), intent(out) :: value
         logical, intent(inout) :: found
         logical, intent(in), optional :: closed_below   !! [lower, ...: lower itself allowed
         logical :: with_lower
         logical :: ok_number
         character(len=32) :: why_number
         character(len=40) :: range
         if (found) then
            call fail(STATUS_TABLE_BAD_HEADER, 'key "'//key//'" given twice')
            return
         end if
         call parse_real(field, value, ok_number, why_number)
         if (.not. ok_number .and. index(why_number, 'out of range') > 0) then
            call fail(STATUS_TABLE_BAD_HEADER, key//' = "'//clip_text(trim(adjustl(field)))//'" is '// &
               trim(why_number))
            return
         end if
         with_lower = .false.
         if (present(closed_below)) with_lower = closed_below
         if (ok_number) ok_number = (value > lower .or. (with_lower .and. .not. value < lower)) .and. &
            (value < upper .or. (closed_above .and. .not. value > upper))
         if (.not. ok_number) then
            range = merge('[', '(', with_lower)//trim(adjustl(es_field(lower, 10, 2)))//', '// &
               trim(adjustl(es_field(upper, 10, 2)))//merge(']', ')', closed_above)
            call fail(STATUS_TABLE_BAD_HEADER, key//' = "'//clip_text(trim(adjustl(field)))// &
               '" is not one number in '//trim(range))
            return
         end if
         found = .true.
      end subroutine header_real

   end subroutine read_rve_table

   !> The header key this reader reads that `key` is or looks like a misspelling of ('' when none),
   !> case ignored: the same after the characters '_', '-' and blanks are dropped; for the keys of
   !> six characters or more, one character left out, one added or two neighbours swapped
   !> (`fromat`, `Chat_T`); for the keys of sixteen or more (interpolation_variable), any two edits.
   !> One character replaced in a short key is not taken for a misspelling: symbols differ that way
   !> (a user's `Chat_NT` or `a_Tc_limit` is provenance). The provenance keys of tables/README.md are
   !> never taken for one.
   pure function near_reader_key(key) result(near)
      character(len=*), intent(in) :: key
      character(len=:), allocatable :: near
      character(len=*), parameter :: READ_KEYS(13) = [character(len=22) :: 'b', 'h', 'a_Tf_limit', 'E_m', &
         'nu_m', 'E_b', 'nu_b', 'h_m', 'h_b', 'Chat_TT', 'Chat_NN', 'format', 'interpolation_variable']
      character(len=*), parameter :: PROVENANCE_KEYS(30) = [character(len=21) :: 'title', 'command', &
         'params_file', 'params_sha256', 'params_line', 'script', 'script_sha256', 'freefem_version', 'date', &
         'units', 'model', 'crack_jump', 'element', 'mesh', 'hmax', 'ftip', 'htipmax', 'grow', 'fseg', 'huni', &
         'refine', 'smallest_tip_spacing', 'unknowns_min', 'unknowns_max', 'n_a', 'a0_row', 'crack_means', &
         'I_fNT', 'wall_time_s', 'warning']
      integer :: k
      near = ''
      if (len_trim(key) == 0) return
      if (any(PROVENANCE_KEYS == trim(key))) return
      do k = 1, size(READ_KEYS)
         if (trim(key) == trim(READ_KEYS(k)) .or. squeezed(key) == squeezed(READ_KEYS(k))) then
            near = trim(READ_KEYS(k))
            return
         end if
      end do
      do k = 1, size(READ_KEYS)
         if (len_trim(READ_KEYS(k)) >= 16) then
            if (edit_distance(to_lower(trim(key)), to_lower(trim(READ_KEYS(k)))) <= 2) near = trim(READ_KEYS(k))
         else if (len_trim(READ_KEYS(k)) >= 6) then
            if (one_slip(to_lower(trim(key)), to_lower(trim(READ_KEYS(k))))) near = trim(READ_KEYS(k))
         end if
         if (len(near) > 0) return
      end do
   contains
      !> s is t with one character left out or added, or with two different neighbours swapped.
      pure logical function one_slip(s, t)
         character(len=*), intent(in) :: s, t
         integer :: i
         one_slip = dropped_one(s, t) .or. dropped_one(t, s)
         if (len(s) /= len(t)) return
         do i = 1, len(t) - 1
            if (t(i:i) /= t(i + 1:i + 1) .and. s == t(1:i - 1)//t(i + 1:i + 1)//t(i:i)//t(i + 2:)) one_slip = .true.
         end do
      end function one_slip
      !> s is t with one character left out.
      pure logical function dropped_one(s, t)
         character(len=*), intent(in) :: s, t
         integer :: i
         dropped_one = .false.
         if (len(s) /= len(t) - 1) return
         do i = 1, len(t)
            if (s == t(1:i - 1)//t(i + 1:)) dropped_one = .true.
         end do
      end function dropped_one
      pure function squeezed(s) result(t)
         character(len=*), intent(in) :: s
         character(len=:), allocatable :: t
         character(len=len(s)) :: low
         integer :: i
         low = to_lower(s)
         t = ''
         do i = 1, len_trim(low)
            if (index('_- '//achar(9), low(i:i)) == 0) t = t//low(i:i)
         end do
      end function squeezed
      pure integer function edit_distance(s, t) result(d)
         character(len=*), intent(in) :: s, t
         integer :: row(0:len(t)), diagonal, above, i, j
         do j = 0, len(t)
            row(j) = j
         end do
         do i = 1, len(s)
            diagonal = row(0)
            row(0) = i
            do j = 1, len(t)
               above = row(j)
               row(j) = min(row(j) + 1, row(j - 1) + 1, diagonal + merge(0, 1, s(i:i) == t(j:j)))
               diagonal = above
            end do
         end do
         d = row(len(t))
      end function edit_distance
   end function near_reader_key

   !> Check a table against the exact identities of docs/rve.md, to IDENTITY_TOL relative
   !> (scales: C(0) for stiffnesses and crack stresses, h for jumps, C_TT(0)/h per unit slip):
   !> a from 0 to b strictly increasing, D = a/b; the symmetry zeros; eq 52 C + C^c = C(0);
   !> T^c_T = C_TT(0) and S^c_N = C_NN(0); the reciprocity relations C^c_TT = C_TT(0) D Dbar_TT/h,
   !> C^c_NN = C_NN(0) D Dbar_NN/h and C^f_T = -(C_TT(0)/h) D ufbar; at a = b C = 0, Dbar = h I,
   !> ufbar = 1 and T^f = -C_TT(0)/h; the signs and ranges T^f < 0, 0 < ufbar <= 1, Dbar >= 0,
   !> C >= 0 and non-increasing in a; the Betti relation (i) C = C(0) (1 - D Dbar/h). With the
   !> column I_fNT (has_betti) also (ii') C^f_T = D T^f Dbar_TT/h + I/(2bh), (iii') Dbar_TT T^f
   !> + ufbar T^c_T = -I/(2a) for a > 0 and I = 0 at a = 0, and (i), all to BETTI_TOL (docs/rve.md,
   !> 'Betti relations'). The message names the identity, the file line, the value and a.
   pure subroutine check_rve_table(table, status, message)
      type(rve_table_type), intent(in) :: table
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      real(dp) :: c0_t, c0_n, scale_c, scale_f, tol_i, term(3)
      integer :: i, n, j, k, ios
      character(len=:), allocatable :: range_text
      integer, parameter :: ZERO_STIFF(6) = [COL_C_TN, COL_C_NT, COL_CC_TN, COL_CC_NT, COL_TC_N, COL_SC_T]
      integer, parameter :: ZERO_JUMP(2) = [COL_DBAR_TN, COL_DBAR_NT]
      integer, parameter :: ZERO_SLIP(2) = [COL_CF_N, COL_SF]

      status = STATUS_OK
      n = size(table%rows, 1)
      associate (r => table%rows, b => table%b, h => table%h)
         if (n < 2) then
            status = STATUS_TABLE_BAD_RANGE
            message = message_path(table%source)//': fewer than two rows'
            return
         end if
         if (abs(r(1, COL_A)) > 0.0_dp .or. abs(r(n, COL_A) - b) > 1.0e-12_dp*b) then
            status = STATUS_TABLE_BAD_RANGE
            ! (every value in full: a last a within a hair of b must show that it differs; the path
            ! shortened where the message would not fit otherwise)
            range_text = ': a runs from '//trim(real_text(r(1, COL_A)))//' to '//trim(real_text(r(n, COL_A)))// &
               ' mm, not from 0 to b = '//trim(real_text(b))//' mm (the header''s b, to 1e-12 b)'
            message = message_path(table%source, MESSAGE_LEN - len(range_text))//range_text
            return
         end if
         do i = 2, n
            if (.not. (r(i, COL_A) > r(i - 1, COL_A))) then
               status = STATUS_TABLE_NOT_INCREASING
               write (message, '(a,a,i0,a,es24.16,a,es24.16)', iostat=ios) message_path(table%source), ':', table%line(i), &
                  ': a = ', r(i, COL_A), ' does not exceed the previous a = ', r(i - 1, COL_A)
               return
            end if
         end do
         c0_t = r(1, COL_C_TT)
         c0_n = r(1, COL_C_NN)
         if (.not. (c0_t > 0.0_dp .and. c0_n > 0.0_dp)) then
            call identity(1, 'C_TT(0) > 0 and C_NN(0) > 0', min(c0_t, c0_n), status, message)
            return
         end if
         ! the header's layers add up to its h (wherever both are given), the intact laminate (a = 0)
         ! in closed form from its layers and elastic constants (plane strain, layers in series:
         ! shear moduli G, and constrained moduli M for s_N), and its own Chat: a header that does
         ! not describe the data is refused
         if (table%has_layers) then
            if (abs(table%layers(1) + table%layers(2) - h) > 1.0e-12_dp*h) then
               status = STATUS_TABLE_IDENTITY
               message = message_path(table%source)//': the header''s h = '//real_text(h)// &
                  ' mm is not h_m + h_b = '//real_text(table%layers(1) + table%layers(2))//' mm'
               return
            end if
         end if
         if (table%has_layers .and. table%has_elastic) then
            term(1) = h/(table%layers(1)/shear_modulus(table%elastic(1), table%elastic(2)) + &
               table%layers(2)/shear_modulus(table%elastic(3), table%elastic(4)))
            term(2) = h/(table%layers(1)/constrained_modulus(table%elastic(1), table%elastic(2)) + &
               table%layers(2)/constrained_modulus(table%elastic(3), table%elastic(4)))
            if (abs(c0_t - term(1)) > IDENTITY_TOL*term(1)) then
               call identity(1, 'C_TT(0) = h/(h_m/G_m + h_b/G_b) from the header''s E, nu, h', c0_t, status, message, &
                  term(1), IDENTITY_TOL*term(1))
               return
            end if
            if (abs(c0_n - term(2)) > IDENTITY_TOL*term(2)) then
               call identity(1, 'C_NN(0) = h/(h_m/M_m + h_b/M_b), M = E(1 - nu)/((1 + nu)(1 - 2 nu)), from the '// &
                  'header''s E, nu, h', c0_n, status, message, term(2), IDENTITY_TOL*term(2))
               return
            end if
         end if
         term(1:2) = [c0_t, c0_n]
         do j = 1, 2
            if (.not. table%has_chat(j)) cycle
            if (abs(term(j) - table%chat(j)) > IDENTITY_TOL*table%chat(j)) then
               call identity(1, trim(merge('C_TT(0) = Chat_TT (header)', 'C_NN(0) = Chat_NN (header)', j == 1)), &
                  term(j), status, message, table%chat(j), IDENTITY_TOL*table%chat(j))
               return
            end if
         end do
         scale_c = max(c0_t, c0_n)
         scale_f = c0_t/h
         tol_i = IDENTITY_TOL
         if (table%has_betti) tol_i = BETTI_TOL
         if (table%has_betti) then
            if (abs(table%i_fnt(1))/(2.0_dp*b*h) > BETTI_TOL*scale_f) then
               call identity(1, 'I_fNT = 0 at a = 0 (limit a -> 0+)', table%i_fnt(1), status, message)
               return
            end if
         end if
         ! the a = 0 row's mean crack jumps: the limit a -> 0+ is 0 for a crack between two elastic
         ! layers (a header with their elastic constants); a table of another model (no elastic
         ! constants, e.g. the simplified model's, Dbar = h at every D) keeps them within the jump
         ! of the split RVE, [0, h]. (C^c, C^f, S^f at a = 0 are 0 and T^c, S^c C(0) by the checks
         ! below; T^f and ufbar there are not used as such: tables/README.md)
         do j = 1, 2
            k = merge(COL_DBAR_TT, COL_DBAR_NN, j == 1)
            if (table%has_elastic) then
               if (abs(r(1, k)) > IDENTITY_TOL*h) then
                  call identity(1, trim(TABLE_COLUMNS(k))//' = 0 at a = 0 (limit a -> 0+)', r(1, k), status, &
                     message, 0.0_dp, IDENTITY_TOL*h)
                  return
               end if
            else if (r(1, k) < -IDENTITY_TOL*h .or. r(1, k) > h*(1.0_dp + IDENTITY_TOL)) then
               call identity(1, '0 <= '//trim(TABLE_COLUMNS(k))//' <= h at a = 0', r(1, k), status, message)
               return
            end if
         end do
         do i = 1, n
            if (abs(r(i, COL_D) - r(i, COL_A)/b) > 1.0e-12_dp) then
               call identity(i, 'D = a/b', r(i, COL_D), status, message, r(i, COL_A)/b, 1.0e-12_dp)
               return
            end if
            do j = 1, size(ZERO_STIFF)
               if (abs(r(i, ZERO_STIFF(j))) > IDENTITY_TOL*scale_c) then
                  call identity(i, trim(TABLE_COLUMNS(ZERO_STIFF(j)))//' = 0 (symmetry)', r(i, ZERO_STIFF(j)), status, message)
                  return
               end if
            end do
            do j = 1, size(ZERO_JUMP)
               if (abs(r(i, ZERO_JUMP(j))) > IDENTITY_TOL*h) then
                  call identity(i, trim(TABLE_COLUMNS(ZERO_JUMP(j)))//' = 0 (symmetry)', r(i, ZERO_JUMP(j)), status, message)
                  return
               end if
            end do
            do j = 1, size(ZERO_SLIP)
               if (abs(r(i, ZERO_SLIP(j))) > IDENTITY_TOL*scale_f) then
                  call identity(i, trim(TABLE_COLUMNS(ZERO_SLIP(j)))//' = 0 (symmetry)', r(i, ZERO_SLIP(j)), status, message)
                  return
               end if
            end do
            if (abs(r(i, COL_C_TT) + r(i, COL_CC_TT) - c0_t) > IDENTITY_TOL*scale_c) then
               call identity(i, 'C_TT + Cc_TT = C_TT(0) (eq 52)', r(i, COL_C_TT) + r(i, COL_CC_TT), status, message, &
                  c0_t, IDENTITY_TOL*scale_c)
               return
            end if
            if (abs(r(i, COL_C_NN) + r(i, COL_CC_NN) - c0_n) > IDENTITY_TOL*scale_c) then
               call identity(i, 'C_NN + Cc_NN = C_NN(0) (eq 52)', r(i, COL_C_NN) + r(i, COL_CC_NN), status, message, &
                  c0_n, IDENTITY_TOL*scale_c)
               return
            end if
            if (abs(r(i, COL_TC_T) - c0_t) > IDENTITY_TOL*scale_c) then
               call identity(i, 'Tc_T = C_TT(0)', r(i, COL_TC_T), status, message, c0_t, IDENTITY_TOL*scale_c)
               return
            end if
            if (abs(r(i, COL_SC_N) - c0_n) > IDENTITY_TOL*scale_c) then
               call identity(i, 'Sc_N = C_NN(0)', r(i, COL_SC_N), status, message, c0_n, IDENTITY_TOL*scale_c)
               return
            end if
            if (.not. (r(i, COL_TF) < 0.0_dp)) then
               call identity(i, 'Tf < 0', r(i, COL_TF), status, message)
               return
            end if
            if (.not. (r(i, COL_UFBAR) > 0.0_dp .and. r(i, COL_UFBAR) <= 1.0_dp + IDENTITY_TOL)) then
               call identity(i, '0 < ufbar <= 1', r(i, COL_UFBAR), status, message)
               return
            end if
            if (r(i, COL_DBAR_TT) < -IDENTITY_TOL*h .or. r(i, COL_DBAR_NN) < -IDENTITY_TOL*h) then
               call identity(i, 'Dbar_TT >= 0 and Dbar_NN >= 0', min(r(i, COL_DBAR_TT), r(i, COL_DBAR_NN)), status, message)
               return
            end if
            if (r(i, COL_C_TT) < -IDENTITY_TOL*scale_c .or. r(i, COL_C_NN) < -IDENTITY_TOL*scale_c) then
               call identity(i, 'C_TT >= 0 and C_NN >= 0', min(r(i, COL_C_TT), r(i, COL_C_NN)), status, message)
               return
            end if
            if (i > 1) then
               if (r(i, COL_C_TT) > r(i - 1, COL_C_TT) + IDENTITY_TOL*scale_c) then
                  call identity(i, 'C_TT non-increasing in a', r(i, COL_C_TT), status, message)
                  return
               end if
               if (r(i, COL_C_NN) > r(i - 1, COL_C_NN) + IDENTITY_TOL*scale_c) then
                  call identity(i, 'C_NN non-increasing in a', r(i, COL_C_NN), status, message)
                  return
               end if
            end if
            ! reciprocity (docs/rve.md, 'Exact identities'): C^c = C(0) D Dbar/h, C^f_T = -(C_TT(0)/h) D ufbar
            if (abs(r(i, COL_CC_TT) - c0_t*r(i, COL_D)*r(i, COL_DBAR_TT)/h) > IDENTITY_TOL*scale_c) then
               call identity(i, 'Cc_TT = C_TT(0) D Dbar_TT/h (reciprocity)', r(i, COL_CC_TT), status, message, &
                  c0_t*r(i, COL_D)*r(i, COL_DBAR_TT)/h, IDENTITY_TOL*scale_c)
               return
            end if
            if (abs(r(i, COL_CC_NN) - c0_n*r(i, COL_D)*r(i, COL_DBAR_NN)/h) > IDENTITY_TOL*scale_c) then
               call identity(i, 'Cc_NN = C_NN(0) D Dbar_NN/h (reciprocity)', r(i, COL_CC_NN), status, message, &
                  c0_n*r(i, COL_D)*r(i, COL_DBAR_NN)/h, IDENTITY_TOL*scale_c)
               return
            end if
            if (abs(r(i, COL_CF_T) + scale_f*r(i, COL_D)*r(i, COL_UFBAR)) > IDENTITY_TOL*scale_f) then
               call identity(i, 'Cf_T = -(C_TT(0)/h) D ufbar (reciprocity)', r(i, COL_CF_T), status, message, &
                  -scale_f*r(i, COL_D)*r(i, COL_UFBAR), IDENTITY_TOL*scale_f)
               return
            end if
            ! Betti relations (docs/rve.md): (i) is free of I; (ii') and (iii') carry it
            if (abs(r(i, COL_C_TT) - c0_t*(1.0_dp - r(i, COL_D)*r(i, COL_DBAR_TT)/h)) > tol_i*c0_t) then
               call identity(i, 'C_TT = C_TT(0) (1 - D Dbar_TT/h) (Betti i)', r(i, COL_C_TT), status, message, &
                  c0_t*(1.0_dp - r(i, COL_D)*r(i, COL_DBAR_TT)/h), tol_i*c0_t)
               return
            end if
            if (abs(r(i, COL_C_NN) - c0_n*(1.0_dp - r(i, COL_D)*r(i, COL_DBAR_NN)/h)) > tol_i*c0_n) then
               call identity(i, 'C_NN = C_NN(0) (1 - D Dbar_NN/h) (Betti i)', r(i, COL_C_NN), status, message, &
                  c0_n*(1.0_dp - r(i, COL_D)*r(i, COL_DBAR_NN)/h), tol_i*c0_n)
               return
            end if
            if (table%has_betti .and. i > 1) then
               term = [r(i, COL_CF_T), -r(i, COL_D)*r(i, COL_TF)*r(i, COL_DBAR_TT)/h, -table%i_fnt(i)/(2.0_dp*b*h)]
               if (abs(sum(term)) > BETTI_TOL*maxval(abs(term))) then
                  ! (the value shown is the row's I_fNT, and the I_fNT the relation needs from its other terms)
                  call identity(i, 'Cf_T = D Tf Dbar_TT/h + I_fNT/(2bh) (Betti ii'')', table%i_fnt(i), status, message, &
                     table%i_fnt(i) + 2.0_dp*b*h*sum(term), 2.0_dp*b*h*BETTI_TOL*maxval(abs(term)), 'I_fNT')
                  return
               end if
               term = [r(i, COL_DBAR_TT)*r(i, COL_TF), r(i, COL_UFBAR)*r(i, COL_TC_T), table%i_fnt(i)/(2.0_dp*r(i, COL_A))]
               if (abs(sum(term)) > BETTI_TOL*maxval(abs(term))) then
                  call identity(i, 'Dbar_TT Tf + ufbar Tc_T = -I_fNT/(2a) (Betti iii'')', table%i_fnt(i), status, &
                     message, table%i_fnt(i) - 2.0_dp*r(i, COL_A)*sum(term), 2.0_dp*r(i, COL_A)*BETTI_TOL*maxval(abs(term)), &
                     'I_fNT')
                  return
               end if
            end if
         end do
         if (max(abs(r(n, COL_C_TT)), abs(r(n, COL_C_NN))) > IDENTITY_TOL*scale_c) then
            call identity(n, 'C = 0 at a = b', max(abs(r(n, COL_C_TT)), abs(r(n, COL_C_NN))), status, message)
            return
         end if
         if (max(abs(r(n, COL_DBAR_TT) - h), abs(r(n, COL_DBAR_NN) - h)) > IDENTITY_TOL*h) then
            call identity(n, 'Dbar = h I at a = b', r(n, COL_DBAR_TT), status, message)
            return
         end if
         if (abs(r(n, COL_UFBAR) - 1.0_dp) > IDENTITY_TOL) then
            call identity(n, 'ufbar = 1 at a = b', r(n, COL_UFBAR), status, message)
            return
         end if
         if (abs(r(n, COL_TF) + scale_f) > IDENTITY_TOL*scale_f) then
            call identity(n, 'Tf = -C_TT(0)/h at a = b', r(n, COL_TF), status, message)
            return
         end if
      end associate

   contains

      !> The failure of an identity at a row: what, the value found and, for an equation, the value
      !> it gives (expected) and the largest difference it allows (allowed). The value is the
      !> identity's left-hand side unless `named` names the quantity it is (a term on the right,
      !> such as I_fNT of the Betti relations): then the message says `<named> = value, but the
      !> relation needs expected`, both values being that quantity's.
      pure subroutine identity(row, what, value, status, message, expected, allowed, named)
         integer, intent(in) :: row
         character(len=*), intent(in) :: what
         real(dp), intent(in) :: value
         integer, intent(out) :: status
         character(len=MESSAGE_LEN), intent(out) :: message
         real(dp), intent(in), optional :: expected, allowed
         character(len=*), intent(in), optional :: named
         character(len=:), allocatable :: rest
         character(len=12) :: line_text
         integer :: ios
         status = STATUS_TABLE_IDENTITY
         write (line_text, '(i0)', iostat=ios) table%line(row)
         if (present(named)) then
            rest = ':'//trim(line_text)//': identity '//what//' fails: '//named//' = '//trim(real_text(value))
         else
            rest = ':'//trim(line_text)//': identity '//what//' fails: value '//trim(real_text(value))
         end if
         if (present(expected) .and. present(allowed)) then
            if (present(named)) then
               rest = rest//', but the relation needs '//trim(real_text(expected))
            else
               rest = rest//', expected '//trim(real_text(expected))
            end if
            ! (es_field: a three-digit exponent keeps its E, 1.1E-308, not 1.1-308)
            rest = rest//' (difference '//trim(adjustl(es_field(abs(value - expected), 9, 1)))//', allowed '// &
               trim(adjustl(es_field(allowed, 9, 1)))//')'
         end if
         rest = rest//' at a = '//trim(real_text(table%rows(row, COL_A)))//' mm'
         ! the path shortened where the message would not fit otherwise: what fails is never cut
         message = message_path(table%source, MESSAGE_LEN - len(rest))//rest
      end subroutine identity

   end subroutine check_rve_table

   !> The shear modulus G = E/(2(1 + nu)) (MPa).
   elemental real(dp) function shear_modulus(e, nu)
      real(dp), intent(in) :: e, nu
      shear_modulus = e/(2.0_dp*(1.0_dp + nu))
   end function shear_modulus

   !> The constrained (plane-strain uniaxial-strain) modulus M = E(1 - nu)/((1 + nu)(1 - 2 nu)) (MPa).
   elemental real(dp) function constrained_modulus(e, nu)
      real(dp), intent(in) :: e, nu
      constrained_modulus = e*(1.0_dp - nu)/((1.0_dp + nu)*(1.0_dp - 2.0_dp*nu))
   end function constrained_modulus

   !> The knots (ascending values of the table's interpolation variable) and the interpolated
   !> columns in interface units (divided by h where the paper's coefficient is per unit E).
   pure subroutine interpolation_data(table, x, y)
      type(rve_table_type), intent(in) :: table
      real(dp), intent(out) :: x(:)                   !! x(n), ascending
      real(dp), intent(out) :: y(:, :)                !! y(n, N_COEFFICIENTS)
      integer :: i, k, n
      real(dp) :: dx, d2x
      n = size(table%rows, 1)
      do i = 1, n
         k = i                                        ! ascending D: the file's order
         if (table%variable == VARIABLE_LOG_LIGAMENT) k = n + 1 - i   ! ascending w: descending D
         associate (r => table%rows(k, :), h => table%h)
            call crack_variable(table%variable, r(COL_D), x(i), dx, d2x)
            y(i, IC_K_N) = r(COL_C_NN)/h
            y(i, IC_K_T) = r(COL_C_TT)/h
            y(i, IC_KC_N) = r(COL_CC_NN)/h
            y(i, IC_KC_T) = r(COL_CC_TT)/h
            y(i, IC_DBAR_N) = r(COL_DBAR_NN)/h
            y(i, IC_DBAR_T) = r(COL_DBAR_TT)/h
            y(i, IC_TC_T) = r(COL_TC_T)/h
            y(i, IC_SC_N) = r(COL_SC_N)/h
            ! D T^f: the a = 0 row's T^f (no finite value) is replaced by the exact limit
            if (r(COL_D) > 0.0_dp) then
               y(i, IC_DTF) = r(COL_D)*r(COL_TF)
            else
               y(i, IC_DTF) = table%a_tf_limit/table%b
            end if
            y(i, IC_UFBAR) = r(COL_UFBAR)
         end associate
      end do
   end subroutine interpolation_data

   !> lim a T^f as a -> 0 (MPa) for a crack on the interface of two elastic layers in plane
   !> strain: a short crack sees two half-planes, and the closed (zero normal jump),
   !> frictionless crack under a uniform shear stress tau slides elliptically with the largest
   !> jump 4 a (1 - beta^2) tau/E*, so T^f (crack shear stress per unit largest slip) is
   !> -E*/(4 a (1 - beta^2)): 2/E* = 1/E'_m + 1/E'_b with E' = E/(1 - nu^2), and beta is
   !> Dundurs' second parameter, (mu_m (kappa_b - 1) - mu_b (kappa_m - 1))/(mu_m (kappa_b + 1)
   !> + mu_b (kappa_m + 1)), kappa = 3 - 4 nu (docs/rve.md, 'Short cracks').
   pure real(dp) function short_crack_a_tf(e_m, nu_m, e_b, nu_b) result(a_tf)
      real(dp), intent(in) :: e_m, nu_m          !! mortar Young's modulus (MPa), Poisson's ratio
      real(dp), intent(in) :: e_b, nu_b          !! brick Young's modulus (MPa), Poisson's ratio
      real(dp) :: e_star
      e_star = 2.0_dp/((1.0_dp - nu_m**2)/e_m + (1.0_dp - nu_b**2)/e_b)
      a_tf = -e_star/(4.0_dp*(1.0_dp - dundurs_beta(e_m, nu_m, e_b, nu_b)**2))
   end function short_crack_a_tf

   !> The bimaterial oscillation index eps = ln((1 - beta)/(1 + beta))/(2 pi) of the mortar-brick
   !> interface in plane strain (beta as in short_crack_a_tf). A short crack's Betti defect,
   !> -Dbar_TT T^f/(ufbar T^c_T) - 1 = I/(2 a ufbar T^c_T), tends to 4 eps^2 (docs/rve.md).
   pure real(dp) function oscillation_index(e_m, nu_m, e_b, nu_b) result(eps)
      real(dp), intent(in) :: e_m, nu_m          !! mortar Young's modulus (MPa), Poisson's ratio
      real(dp), intent(in) :: e_b, nu_b          !! brick Young's modulus (MPa), Poisson's ratio
      real(dp), parameter :: PI = acos(-1.0_dp)
      real(dp) :: beta
      beta = dundurs_beta(e_m, nu_m, e_b, nu_b)
      eps = log((1.0_dp - beta)/(1.0_dp + beta))/(2.0_dp*PI)
   end function oscillation_index

   !> Dundurs' second parameter beta of the mortar (m) - brick (b) pair in plane strain.
   pure real(dp) function dundurs_beta(e_m, nu_m, e_b, nu_b) result(beta)
      real(dp), intent(in) :: e_m, nu_m          !! mortar Young's modulus (MPa), Poisson's ratio
      real(dp), intent(in) :: e_b, nu_b          !! brick Young's modulus (MPa), Poisson's ratio
      real(dp) :: g_m, g_b, k_m, k_b
      g_m = e_m/(2.0_dp*(1.0_dp + nu_m))
      g_b = e_b/(2.0_dp*(1.0_dp + nu_b))
      k_m = 3.0_dp - 4.0_dp*nu_m
      k_b = 3.0_dp - 4.0_dp*nu_b
      beta = (g_m*(k_b - 1.0_dp) - g_b*(k_m - 1.0_dp))/(g_m*(k_b + 1.0_dp) + g_b*(k_m + 1.0_dp))
   end function dundurs_beta

   ! (the source is shared with interphase_micro_coefficients, which includes it where it can be
   ! inlined)
   include 'interphase_crack_variable.inc'

   !> Split a line at blanks (spaces, tabs) into fields text(starts(i):ends(i)); nfields counts
   !> them all, but only the first size(starts) are stored.
   pure subroutine split(text, starts, ends, nfields)
      character(len=*), intent(in) :: text
      integer, intent(out) :: starts(:), ends(:)
      integer, intent(out) :: nfields
      integer :: i
      logical :: in_field, blank
      nfields = 0
      in_field = .false.
      starts = 0
      ends = 0
      do i = 1, len(text)
         blank = text(i:i) == ' ' .or. text(i:i) == achar(9)
         if (blank .and. in_field) then
            if (nfields <= size(ends)) ends(nfields) = i - 1
            in_field = .false.
         else if (.not. blank .and. .not. in_field) then
            nfields = nfields + 1
            if (nfields <= size(starts)) starts(nfields) = i
            in_field = .true.
         end if
      end do
      if (in_field .and. nfields <= size(ends)) ends(nfields) = len(text)
   end subroutine split

   !> Double the row capacity.
   pure subroutine grow(rows, lines)
      real(dp), allocatable, intent(inout) :: rows(:, :)
      integer, allocatable, intent(inout) :: lines(:)
      real(dp), allocatable :: new_rows(:, :)
      integer, allocatable :: new_lines(:)
      allocate (new_rows(size(rows, 1), 2*size(rows, 2)), new_lines(2*size(lines)))
      new_rows(:, 1:size(rows, 2)) = rows
      new_lines(1:size(lines)) = lines
      call move_alloc(new_rows, rows)
      call move_alloc(new_lines, lines)
   end subroutine grow

end module interphase_rve_table
