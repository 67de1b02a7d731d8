!> `interphase-point`: single material-point driver of the interphase UMAT.
!>
!>     interphase-point CASE.nml [--output-dir DIR] [--no-plot]
!>
!> Reads the case file (namelists `&material` and `&loading`, see `interphase_driver_case`),
!> replays its separation history (see `interphase_driver_history`) through `umat` and writes a
!> CSV table (see `interphase_driver_output`); when `plot` is true, `--no-plot` is not given and
!> gnuplot is on PATH, also a gnuplot script and a PNG of the traction-separation curves next
!> to the CSV. Relative `output` paths are taken relative to DIR, or to the current directory.
!> Every error is printed to standard error and ends the program with exit status 1 (`stop 1`).
program interphase_point
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use interphase_driver_case, only: case_type, read_case, load_start_up_data
   use interphase_driver_cli, only: run_arguments_type, parse_run_arguments, make_directory, &
      gnuplot_available, run_gnuplot
   use interphase_driver_history, only: history_type, read_history
   use interphase_driver_output, only: csv_header, write_plot_script
   use interphase_driver_replay, only: replay_history
   use interphase_driver_text, only: int_to_string, directory_of, base_name, stem_of, &
      join_path
   implicit none

   character(len=:), allocatable :: case_path, output_dir, csv_path, message
   type(run_arguments_type) :: cli
   type(case_type) :: run
   type(history_type) :: history
   logical :: no_plot, ok
   integer :: unit, ios, nrows
   character(len=512) :: iomsg

   ! ---- command line ----
   call parse_run_arguments(cli, ok, message)
   if (cli%help) then
      call print_usage(output_unit)
      stop
   end if
   if (.not. ok) call fail(message, usage=.true.)
   case_path = cli%case_path
   output_dir = cli%output_dir
   no_plot = cli%no_plot

   ! ---- inputs ----
   call read_case(case_path, run, ok, message)
   if (.not. ok) call fail(message)
   call read_history(run%history_path, history, ok, message)
   if (.not. ok) call fail(message)
   ! start-up: custom RVE table and R-curve read once, before any update (as UEXTERNALDB does)
   call load_start_up_data(run%table_path, run%rcurve_path, ok, message)
   if (.not. ok) call fail(message)

   ! ---- replay into the CSV ----
   csv_path = join_path(output_dir, run%output)
   call make_directory(directory_of(csv_path), ok, message)
   if (.not. ok) call fail(message)
   open (newunit=unit, file=csv_path, status='replace', action='write', form='formatted', &
      iostat=ios, iomsg=iomsg)
   if (ios /= 0) call fail(csv_path//': cannot write the CSV file: '//trim(iomsg))
   write (unit, '(a)') csv_header(history%ntens)
   call replay_history(run, history, unit, nrows, ok, message)
   close (unit)
   if (.not. ok) call fail(message//' (the CSV '//csv_path//' is incomplete)')
   write (output_unit, '(a)') run%name//': '//int_to_string(nrows)//' rows ('// &
      int_to_string(history%ntens)//'-D) written to '//csv_path

   ! ---- plot ----
   if (run%plot .and. .not. no_plot) call plot_csv()

contains

   !> Print the message to standard error and stop with exit status 1.
   subroutine fail(text, usage)
      character(len=*), intent(in) :: text        !! what went wrong
      logical, intent(in), optional :: usage      !! also print the usage line

      write (error_unit, '(a)') 'interphase-point: error: '//text
      if (present(usage)) then
         if (usage) call print_usage(error_unit)
      end if
      stop 1
   end subroutine fail

   !> Print how to call the program.
   subroutine print_usage(unit)
      integer, intent(in) :: unit                 !! where to print

      write (unit, '(a)') 'usage: interphase-point CASE.nml [--output-dir DIR] [--no-plot]', &
         '  Replays the separation history of CASE.nml through the interphase UMAT and writes', &
         '  a CSV table (and a PNG of the traction-separation curves if gnuplot is on PATH).'
   end subroutine print_usage

   !> Write the gnuplot script next to the CSV and run it, or say why not.
   subroutine plot_csv()
      character(len=:), allocatable :: directory, stem, script_name

      if (.not. gnuplot_available()) then
         write (output_unit, '(a)') 'gnuplot not found: PNG skipped (install Debian package gnuplot-nox)'
         return
      end if
      directory = directory_of(csv_path)
      stem = stem_of(csv_path)
      script_name = stem//'.gp'
      call write_plot_script(join_path(directory, script_name), base_name(csv_path), &
         stem//'.png', run%name, history%ntens, ok, message)
      if (.not. ok) call fail(message)
      call run_gnuplot(directory, script_name, ok, message)
      if (.not. ok) call fail(message)
      write (output_unit, '(a)') run%name//': plot written to '//join_path(directory, stem//'.png')
   end subroutine plot_csv

end program interphase_point
