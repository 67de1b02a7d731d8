!> `interphase_csv_compare`: compare a CSV written by interphase-point with a stored reference.
!>
!>     interphase_csv_compare ACTUAL.csv REFERENCE.csv
!>
!> Passes (exit 0) when both files have the same header, the same number of rows and fields,
!> every numeric field agrees within |actual - reference| <= ABS_TOL + REL_TOL*|reference|, and
!> the text column `state` is identical. Otherwise it names each mismatch (data row, file line,
!> column name, both values; at most MAX_REPORTED of them) and exits with status 1.
program csv_compare
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, iostat_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
   use interphase_kinds, only: dp
   implicit none

   !> Absolute tolerance on every number (same unit as the column).
   real(dp), parameter :: ABS_TOL = 1.0e-12_dp
   !> Relative tolerance on every number.
   real(dp), parameter :: REL_TOL = 1.0e-9_dp
   !> Columns compared as text, character for character.
   character(len=*), parameter :: TEXT_COLUMN = 'state'
   !> Mismatches printed before the summary.
   integer, parameter :: MAX_REPORTED = 10

   !> One line or one field of text.
   type :: field_type
      character(len=:), allocatable :: text
   end type field_type
   character(len=:), allocatable :: actual_path, reference_path
   type(field_type), allocatable :: actual_lines(:), reference_lines(:)
   type(field_type), allocatable :: names(:), actual(:), reference(:)
   integer :: row, column, mismatches, nrows
   character(len=512) :: iomsg
   real(dp) :: a, b
   logical :: a_ok, b_ok

   if (command_argument_count() /= 2) then
      write (error_unit, '(a)') 'usage: interphase_csv_compare ACTUAL.csv REFERENCE.csv'
      stop 2
   end if
   call get_argument(1, actual_path)
   call get_argument(2, reference_path)
   call read_lines(actual_path, actual_lines)
   call read_lines(reference_path, reference_lines)

   if (size(reference_lines) == 0) call fail(reference_path//': empty file (no header)')
   if (size(actual_lines) == 0) call fail(actual_path//': empty file (no header)')
   if (actual_lines(1)%text /= reference_lines(1)%text) call fail('headers differ:'// &
      new_line('a')//'  actual:    '//actual_lines(1)%text//new_line('a')//'  reference: '// &
      reference_lines(1)%text)
   if (size(actual_lines) /= size(reference_lines)) call fail('different numbers of data '// &
      'rows: '//actual_path//' has '//str(size(actual_lines) - 1)//', '//reference_path// &
      ' has '//str(size(reference_lines) - 1))
   call split(reference_lines(1)%text, names)
   nrows = size(reference_lines) - 1

   mismatches = 0
   do row = 1, nrows
      call split(actual_lines(row + 1)%text, actual)
      call split(reference_lines(row + 1)%text, reference)
      if (size(actual) /= size(names) .or. size(reference) /= size(names)) then
         call fail('data row '//str(row)//' (line '//str(row + 1)//'): '//str(size(actual))// &
            ' fields in '//actual_path//', '//str(size(reference))//' in '//reference_path// &
            ', header has '//str(size(names)))
      end if
      do column = 1, size(names)
         if (names(column)%text == TEXT_COLUMN) then
            if (actual(column)%text /= reference(column)%text) then
               call report('"'//actual(column)%text//'" /= "'//reference(column)%text//'"')
            end if
            cycle
         end if
         call parse(actual(column)%text, a, a_ok)
         call parse(reference(column)%text, b, b_ok)
         if (.not. b_ok) call fail(reference_path//': data row '//str(row)//', column '// &
            names(column)%text//": cannot read '"//reference(column)%text//"' as a number")
         if (.not. a_ok) then
            call report("'"//actual(column)%text//"' is not a number (reference "// &
               reference(column)%text//')')
         else if (.not. within(a, b)) then
            call report(actual(column)%text//' /= '//reference(column)%text//' (difference '// &
               real_str(a - b)//', allowed '//real_str(ABS_TOL + REL_TOL*abs(b))//')')
         end if
      end do
   end do

   if (mismatches > 0) then
      if (mismatches > MAX_REPORTED) write (error_unit, '(a)') '  ... '// &
         str(mismatches - MAX_REPORTED)//' more'
      call fail(str(mismatches)//' mismatching fields in '//str(nrows)//' data rows of '// &
         actual_path//' against '//reference_path)
   end if
   write (output_unit, '(a)') 'csv_compare: '//actual_path//' matches '//reference_path//' ('// &
      str(nrows)//' rows, '//str(size(names))//' columns, abs tol '//real_str(ABS_TOL)// &
      ', rel tol '//real_str(REL_TOL)//')'

contains

   !> Print the message and stop with exit status 1.
   subroutine fail(text)
      character(len=*), intent(in) :: text        !! what differs

      write (error_unit, '(a)') 'csv_compare: FAILED: '//text
      stop 1
   end subroutine fail

   !> Count one mismatch at the current row and column, printing the first MAX_REPORTED.
   subroutine report(text)
      character(len=*), intent(in) :: text        !! the two values

      mismatches = mismatches + 1
      if (mismatches <= MAX_REPORTED) write (error_unit, '(a)') 'csv_compare: data row '// &
         str(row)//' (line '//str(row + 1)//'), column '//str(column)//' ('// &
         names(column)%text//'): '//text
   end subroutine report

   !> |a - b| within the tolerances; NaN never matches.
   logical function within(actual_value, reference_value)
      real(dp), intent(in) :: actual_value        !! number from the actual file
      real(dp), intent(in) :: reference_value     !! number from the reference

      if (ieee_is_nan(actual_value) .or. ieee_is_nan(reference_value)) then
         within = .false.
      else
         within = abs(actual_value - reference_value) <= ABS_TOL + REL_TOL*abs(reference_value)
      end if
   end function within

   !> Read a number; ok false if the text is not a plain real literal.
   subroutine parse(text, value, ok)
      character(len=*), intent(in) :: text        !! field text
      real(dp), intent(out) :: value              !! the number when ok
      logical, intent(out) :: ok                  !! true on success
      integer :: ios

      value = 0.0_dp
      ok = .false.
      if (len(text) == 0) return
      if (verify(text, '0123456789+-.eEdD') /= 0 .or. scan(text, '0123456789') == 0) return
      read (text, *, iostat=ios) value
      ok = ios == 0
   end subroutine parse

   !> Split a CSV line at commas (no quoting: interphase-point never writes quotes).
   subroutine split(line, fields)
      character(len=*), intent(in) :: line        !! one CSV line
      type(field_type), allocatable, intent(out) :: fields(:)  !! its fields, trimmed
      integer :: start, comma, n

      allocate (fields(count_commas(line) + 1))
      start = 1
      do n = 1, size(fields)
         comma = index(line(start:), ',')
         if (comma == 0) then
            fields(n)%text = trim(adjustl(line(start:)))
         else
            fields(n)%text = trim(adjustl(line(start:start + comma - 2)))
            start = start + comma
         end if
      end do
   end subroutine split

   !> Number of commas in a line.
   pure integer function count_commas(line)
      character(len=*), intent(in) :: line        !! text
      integer :: i

      count_commas = 0
      do i = 1, len(line)
         if (line(i:i) == ',') count_commas = count_commas + 1
      end do
   end function count_commas

   !> All lines of a file (trailing blanks and carriage returns removed), or fail.
   subroutine read_lines(path, lines)
      character(len=*), intent(in) :: path        !! file to read
      type(field_type), allocatable, intent(out) :: lines(:)  !! its lines
      type(field_type), allocatable :: grown(:)
      character(len=:), allocatable :: line
      character(len=1024) :: buffer
      integer :: unit, ios, nread, n

      open (newunit=unit, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
      if (ios /= 0) call fail(path//': cannot open: '//trim(iomsg))
      allocate (lines(256))
      n = 0
      file: do
         line = ''
         do
            read (unit, '(a)', advance='no', iostat=ios, iomsg=iomsg, size=nread) buffer
            if (ios > 0) call fail(path//': read error: '//trim(iomsg))
            line = line//buffer(:nread)
            if (ios == iostat_end .and. len(line) == 0) exit file
            if (ios /= 0) exit
         end do
         if (len(line) > 0) then
            if (line(len(line):) == achar(13)) line = line(:len(line) - 1)
         end if
         if (n == size(lines)) then
            allocate (grown(2*n))
            grown(:n) = lines
            call move_alloc(grown, lines)
         end if
         n = n + 1
         lines(n)%text = trim(line)
      end do file
      close (unit)
      lines = lines(:n)
   end subroutine read_lines

   !> Command-line argument n of any length.
   subroutine get_argument(n, value)
      integer, intent(in) :: n                    !! argument number
      character(len=:), allocatable, intent(out) :: value  !! its text
      integer :: length

      call get_command_argument(n, length=length)
      allocate (character(len=length) :: value)
      if (length > 0) call get_command_argument(n, value(:))
   end subroutine get_argument

   !> Decimal text of an integer.
   function str(value) result(text)
      integer, intent(in) :: value                !! the integer
      character(len=:), allocatable :: text
      character(len=24) :: buffer

      write (buffer, '(i0)') value
      text = trim(buffer)
   end function str

   !> Short text of a real.
   function real_str(value) result(text)
      real(dp), intent(in) :: value               !! the number
      character(len=:), allocatable :: text
      character(len=32) :: buffer

      write (buffer, '(es10.3)') value
      text = trim(adjustl(buffer))
   end function real_str

end program csv_compare
