!> History files of the single-point driver: a plain table of prescribed separations.
!>
!>     # comments and blank lines are allowed; '#' also starts a trailing comment
!>     # t    s_T    s_N          (2-D, NTENS = 2)
!>     0      0      0
!>     1      0      0.05
!>
!> or `t s_T1 s_T2 s_N` (3-D, NTENS = 3). Times are arbitrary units, strictly increasing;
!> separations in mm. Every data line has the same number of columns. Errors name the file and
!> the line. The table is stored in the UMAT's component order: normal first, then shear(s).
module interphase_driver_history
   use, intrinsic :: iso_fortran_env, only: iostat_end, int64
   use interphase_kinds, only: dp
   use interphase_driver_text, only: int_to_string, real_to_string, read_line, split_words, text_file_type, &
      open_line_file, close_text_file
   use interphase_text_input, only: parse_real, clip_text, tried_path, MAX_FILE_BYTES
   implicit none
   private
   public :: history_type, read_history

   !> A prescribed separation history.
   type :: history_type
      !> Number of traction components: 2 (2-D) or 3 (3-D).
      integer :: ntens = 0
      !> Number of rows (>= 2).
      integer :: nrows = 0
      !> Time of each row (strictly increasing).
      real(dp), allocatable :: time(:)
      !> Separation of each row, (ntens, nrows), UMAT order: normal first, then shear(s) (mm).
      real(dp), allocatable :: separation(:, :)
      !> Line number of each row in the file (for messages).
      integer, allocatable :: line(:)
   end type history_type

contains

   !> Read a history file. On failure `ok` is false and `message` names the file and line.
   subroutine read_history(path, history, ok, message)
      character(len=*), intent(in) :: path        !! history file
      type(history_type), intent(out) :: history  !! the table, valid when ok
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      character(len=:), allocatable :: line, where, shown
      integer, allocatable :: starts(:), ends(:)
      real(dp) :: values(4)
      integer :: ios, line_number, ncolumns, first_data_line, comment, i
      type(text_file_type) :: unit
      integer(int64) :: bytes
      character(len=512) :: iomsg

      ok = .false.
      shown = tried_path(path)
      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = shown//': cannot open the history file: '//trim(iomsg)
         return
      end if

      allocate (history%time(16), history%separation(3, 16), history%line(16))
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
         comment = index(line, '#')
         if (comment > 0) line = line(:comment - 1)
         call split_words(line, starts, ends)
         if (size(starts) == 0) cycle

         if (ncolumns == 0) then
            if (size(starts) /= 3 .and. size(starts) /= 4) then
               message = where//'found '//int_to_string(size(starts))//' columns; expected 3 '// &
                  '(t s_T s_N, 2-D) or 4 (t s_T1 s_T2 s_N, 3-D)'
               call close_text_file(unit)
               return
            end if
            ncolumns = size(starts)
            first_data_line = line_number
         else if (size(starts) /= ncolumns) then
            message = where//'found '//int_to_string(size(starts))//' columns, but line '// &
               int_to_string(first_data_line)//' has '//int_to_string(ncolumns)// &
               '; every data line must have the same number of columns'
            call close_text_file(unit)
            return
         end if
         do i = 1, ncolumns
            call parse_number(line(starts(i):ends(i)), values(i), ok, message)
            if (.not. ok) then
               message = where//'column '//int_to_string(i)//': '//message
               call close_text_file(unit)
               return
            end if
         end do
         ok = .false.

         if (history%nrows > 0) then
            if (.not. (values(1) > history%time(history%nrows))) then
               message = where//'time '//real_to_string(values(1))// &
                  ' is not greater than the previous time '// &
                  real_to_string(history%time(history%nrows))//' (line '// &
                  int_to_string(history%line(history%nrows))//'); times must increase strictly'
               call close_text_file(unit)
               return
            end if
         end if
         call append_row(history, line_number, values(1), values(2:ncolumns))
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
      ok = .true.
   end subroutine read_history

   !> Append one row; `shear_then_normal` is the file's order (s_T[1], [s_T2,] s_N).
   subroutine append_row(history, line_number, time, shear_then_normal)
      type(history_type), intent(inout) :: history  !! table being built
      integer, intent(in) :: line_number          !! line of the row in the file
      real(dp), intent(in) :: time                !! t
      real(dp), intent(in) :: shear_then_normal(:)  !! separations in file order (mm)
      real(dp), allocatable :: time_new(:), separation_new(:, :)
      integer, allocatable :: line_new(:)
      integer :: n, capacity

      capacity = size(history%time)
      if (history%nrows == capacity) then
         allocate (time_new(2*capacity), separation_new(3, 2*capacity), line_new(2*capacity))
         time_new(:capacity) = history%time
         separation_new(:, :capacity) = history%separation
         line_new(:capacity) = history%line
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
   end subroutine append_row

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
      else
         message = "cannot parse '"//clip_text(word)//"' as a number"
      end if
   end subroutine parse_number

end module interphase_driver_history
