!> `fe2d_csv_compare ACTUAL.csv REFERENCE.csv`: compare a load-displacement CSV of
!> interphase-fe2d with a stored reference. Passes (exit 0) when the headers are identical,
!> the numbers of rows and fields agree and every number is within REL_TOL times the largest
!> magnitude of its column in the reference (plus ABS_TOL): the curve is the result of Newton
!> iterations stopped at a tolerance, so round-off of other builds (Release, LTO, another
!> LAPACK) may move the last digits. Otherwise names each mismatch and exits with status 1.
program fe2d_csv_compare
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit, iostat_end
   use interphase_kinds, only: dp
   use interphase_driver_text, only: read_line, int_to_string, real_to_string, text_file_type, open_line_file, &
      close_text_file
   implicit none

   real(dp), parameter :: REL_TOL = 1.0e-7_dp
   real(dp), parameter :: ABS_TOL = 1.0e-12_dp
   integer, parameter :: MAX_REPORTED = 10
   character(len=:), allocatable :: actual_path, reference_path, header_a, header_r
   real(dp), allocatable :: a(:, :), r(:, :), scale(:)
   integer :: row, column, mismatches, length

   if (command_argument_count() /= 2) then
      write (error_unit, '(a)') 'usage: fe2d_csv_compare ACTUAL.csv REFERENCE.csv'
      error stop 2
   end if
   call get_command_argument(1, length=length)
   allocate (character(len=length) :: actual_path)
   call get_command_argument(1, actual_path(:))
   call get_command_argument(2, length=length)
   allocate (character(len=length) :: reference_path)
   call get_command_argument(2, reference_path(:))
   call read_table(actual_path, header_a, a)
   call read_table(reference_path, header_r, r)
   if (header_a /= header_r) call fail('headers differ: '//header_a//' | '//header_r)
   if (size(a, 1) /= size(r, 1) .or. size(a, 2) /= size(r, 2)) call fail('tables differ in '// &
      'size: '//int_to_string(size(a, 2))//' rows of '//int_to_string(size(a, 1))//' fields against '// &
      int_to_string(size(r, 2))//' rows of '//int_to_string(size(r, 1)))
   allocate (scale(size(r, 1)))
   scale = maxval(abs(r), dim=2)
   mismatches = 0
   do row = 1, size(r, 2)
      do column = 1, size(r, 1)
         if (abs(a(column, row) - r(column, row)) > REL_TOL*scale(column) + ABS_TOL) then
            mismatches = mismatches + 1
            if (mismatches <= MAX_REPORTED) write (error_unit, '(a)') 'data row '// &
               int_to_string(row)//', column '//int_to_string(column)//': '// &
               real_to_string(a(column, row))//' against reference '//real_to_string(r(column, row))
         end if
      end do
   end do
   if (mismatches > 0) call fail(int_to_string(mismatches)//' mismatches')
   write (output_unit, '(a)') 'ok: '//int_to_string(size(r, 2))//' rows agree within '// &
      real_to_string(REL_TOL)//' of each column''s scale'

contains

   subroutine fail(text)
      character(len=*), intent(in) :: text
      write (error_unit, '(a)') 'fe2d_csv_compare: '//actual_path//' vs '//reference_path//': '//text
      error stop 1
   end subroutine fail

   subroutine read_table(path, header, table)
      character(len=*), intent(in) :: path
      character(len=:), allocatable, intent(out) :: header
      real(dp), allocatable, intent(out) :: table(:, :)
      character(len=:), allocatable :: line
      character(len=512) :: iomsg
      real(dp), allocatable :: grow(:, :)
      integer :: ios, ncol, n
      type(text_file_type) :: unit

      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) call fail(path//': '//trim(iomsg))
      call read_line(unit, header, ios, iomsg)
      if (ios /= 0) call fail(path//': no header')
      ncol = 1 + count([(header(n:n) == ',', n=1, len(header))])
      allocate (table(ncol, 0))
      do
         call read_line(unit, line, ios, iomsg)
         if (ios == iostat_end) exit
         if (ios /= 0) call fail(path//': '//trim(iomsg))
         if (len_trim(line) == 0) cycle
         allocate (grow(ncol, size(table, 2) + 1))
         grow(:, 1:size(table, 2)) = table
         read (line, *, iostat=ios) grow(:, size(grow, 2))
         if (ios /= 0) call fail(path//': cannot read row '//int_to_string(size(grow, 2)))
         call move_alloc(grow, table)
      end do
      call close_text_file(unit)
   end subroutine read_table

end program fe2d_csv_compare
