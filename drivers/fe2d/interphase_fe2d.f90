!> `interphase-fe2d`: a small 2-D finite-element host of the interphase UMAT running the
!> masonry shear test (brick couplet or triplet: precompression, then monotonic or cyclic
!> shear).
!>
!>     interphase-fe2d CASE.nml [--output-dir DIR] [--no-plot]
!>
!> Bricks are linear elastic plane-strain Q4 elements; the mortar joints are zero-thickness
!> 4-node interface elements whose integration points call `umat` as Abaqus/Standard would.
!> Writes the load-displacement table (CSV), the Newton iteration log (.log) and, when gnuplot
!> is on PATH and plotting is not disabled, a PNG of shear force against shear displacement.
!> The CSV is written to CSV.part and renamed when the run succeeds (a failed run leaves a previous
!> CSV as it was, its converged increments in CSV.part). A run longer than 2 s prints progress
!> lines to standard error. Every error is printed to standard error and ends the program with
!> exit status 1.
program interphase_fe2d
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use interphase_layout, only: PROP_MU
   use interphase_fe2d_case, only: fe2d_case_type, read_fe2d_case
   use interphase_driver_case, only: load_start_up_data, d0_entry_of, material_summary, data_files_summary
   use interphase_driver_namelist, only: with_entry_line
   use interphase_driver_cli, only: run_arguments_type, parse_run_arguments, make_directory, &
      gnuplot_available, run_gnuplot, exit_program, print_version, rename_file, refuse_special_output, &
      open_failure, OPEN_MESSAGE_LEN
   use interphase_fe2d_mesh, only: fe2d_mesh_type, build_mesh
   use interphase_fe2d_solver, only: fe2d_options_type, fe2d_result_type, run_analysis, &
      CSV_COLUMNS, COL_SHEAR, COL_NORMAL, COL_STEP
   use interphase_fe2d_output, only: write_curve_csv, write_curve_plot_script
   use interphase_real_text, only: real_text
   use interphase_driver_text, only: int_to_string, directory_of, base_name, &
      stem_of, join_path
   implicit none

   character(len=:), allocatable :: case_path, output_dir, csv_path, log_path, message
   !> the table and R-curve files the run read ('' when none)
   character(len=:), allocatable :: files
   type(run_arguments_type) :: cli
   type(fe2d_case_type) :: run
   type(fe2d_mesh_type) :: mesh
   type(fe2d_options_type) :: options
   type(fe2d_result_type) :: result
   logical :: no_plot, ok
   integer :: ios, peak
   character(len=OPEN_MESSAGE_LEN) :: iomsg

   call parse_run_arguments(cli, ok, message)
   if (cli%help) then
      call print_usage(output_unit)
      call exit_program(0)
   end if
   if (cli%version) then
      call print_version('interphase-fe2d')
      call exit_program(0)
   end if
   if (.not. ok) call fail(message, usage=.true.)
   case_path = cli%case_path
   output_dir = cli%output_dir
   no_plot = cli%no_plot

   call read_fe2d_case(case_path, run, ok, message)
   if (.not. ok) call fail(message)
   ! start-up: custom RVE table and R-curve read once, before any update (as UEXTERNALDB does)
   ! (and the R-curve's coverage of D0 checked; a refusal names the entry's line)
   call load_start_up_data(run%table_path, run%rcurve_path, case_path//': &joint: ', ok, message, props=run%props, &
      d0_entry=d0_entry_of(run%lines, 'joint'))
   if (.not. ok) call fail(with_entry_line(message, case_path, run%lines))
   call build_mesh(run, mesh)
   ! the joint's material, as interphase-point names it (model, table, law, key parameters)
   write (output_unit, '(a)') run%name//': joint: '//material_summary(run%props)
   ! (the table and R-curve files the run read, which PROPS cannot name; in the log too)
   files = data_files_summary(run%table_path, run%rcurve_path)
   if (len(files) > 0) write (output_unit, '(a)') run%name//': joint: '//files

   csv_path = join_path(output_dir, run%output)
   ! (before the run: an output that is a device would be replaced by the rename at its end)
   message = refuse_special_output(csv_path, run%output_entry)
   if (len(message) == 0) message = refuse_special_output(csv_path//'.part', run%output_entry)
   if (len(message) > 0) call fail(message)
   call make_directory(directory_of(csv_path), ok, message)
   if (.not. ok) call fail(message)
   log_path = join_path(directory_of(csv_path), stem_of(csv_path)//'.log')
   open (newunit=options%log_unit, file=log_path, status='replace', action='write', &
      iostat=ios, iomsg=iomsg)
   if (ios /= 0) call fail(open_failure('the log', log_path, iomsg))
   options%log = .true.
   options%progress = .true.
   options%name = run%name
   write (options%log_unit, '(a)') 'interphase-fe2d '//case_path//': '// &
      int_to_string(run%bricks)//' bricks, '//int_to_string(run%nx)//' x '// &
      int_to_string(run%ny)//' elements per brick, '//int_to_string(mesh%nfree)// &
      ' free equations, half bandwidth '//int_to_string(mesh%bandwidth)
   write (options%log_unit, '(a)') 'joint: '//material_summary(run%props)
   if (len(files) > 0) write (options%log_unit, '(a)') 'joint: '//files
   write (options%log_unit, '(a)') 'residual = ||R_free|| / max(||F_ext||, |shear reaction|); '// &
      'correction = ||du|| / ||u_free||'
   call run_analysis(run, mesh, options, result)
   close (options%log_unit)

   ! CSV.part, renamed to CSV when the run succeeded: a failed run leaves a previous CSV as it was
   call write_curve_csv(csv_path//'.part', CSV_COLUMNS, result%rows(:, 1:result%nrows), ok, message)
   if (.not. ok) call fail(message)
   if (.not. result%ok) call fail(run%path//': '//result%message//' (the converged increments are in '// &
      csv_path//'.part; '//csv_path//' was not written; see '//log_path//')')
   call rename_file(csv_path//'.part', csv_path, ok, message)
   if (.not. ok) call fail(message)
   peak = maxloc(abs(result%rows(COL_SHEAR, 1:result%nrows)), 1)
   write (output_unit, '(a)') run%name//': '//int_to_string(result%nrows)//' rows written to '// &
      csv_path//' ('//int_to_string(result%nincrements)//' increments, '// &
      int_to_string(result%iterations)//' iterations, '//int_to_string(result%cutbacks)// &
      ' cut-backs; log '//log_path//')'
   if (result%roundoff_increments > 0) write (output_unit, '(a)') run%name//': note: '// &
      int_to_string(result%roundoff_increments)//' increments converged only to the round-off '// &
      'of the assembly, above tolerance x the reference force (a vanishing load or an '// &
      'ill-conditioned brick; see the log)'
   ! (7 significant digits: the CSV holds every digit)
   write (output_unit, '(a)') run%name//': peak |shear force| '// &
      real_text(abs(result%rows(COL_SHEAR, peak)), 7)//' N; final shear force '// &
      real_text(result%rows(COL_SHEAR, result%nrows), 7)//' N at normal force '// &
      real_text(result%rows(COL_NORMAL, result%nrows), 7)//' N (step '// &
      int_to_string(nint(result%rows(COL_STEP, result%nrows)))//')'
   ! the gnuplot script whenever the case plots (with --no-plot too: `gnuplot SCRIPT` draws the
   ! figure later), the PNG unless --no-plot
   if (run%plot) call plot_csv(.not. no_plot)

contains

   subroutine fail(text, usage)
      character(len=*), intent(in) :: text        !! what went wrong
      logical, intent(in), optional :: usage      !! also print the usage line

      write (error_unit, '(a)') 'interphase-fe2d: error: '//text
      if (present(usage)) then
         if (usage) call print_usage(error_unit)
      end if
      call exit_program(1)
   end subroutine fail

   subroutine print_usage(unit)
      integer, intent(in) :: unit                 !! where to print

      write (unit, '(a)') 'usage: interphase-fe2d CASE.nml [--output-dir DIR] [--no-plot]', &
         '       interphase-fe2d --help | --version', &
         '  Runs the masonry shear test of CASE.nml (bricks: plane-strain Q4; joints: interface', &
         '  elements calling the interphase UMAT) and writes the load-displacement CSV, the', &
         '  Newton log and a PNG of the shear force against the shear displacement (gnuplot).', &
         '  CASE.nml: &geometry  bricks, brick_length, brick_height, thickness, sides', &
         '            &mesh      nx, ny, integration', &
         '            &brick     e, nu', &
         '            &joint     interphase-point''s material entries (model, damage_law, mu,', &
         '                       s0_n, sf_n, s0_t, sf_t, k_n, k_t, table, d0, rcurve, rcurve_file, g_ci,', &
         '                       g_cii, growth_slip, contact_band, viscosity, stiffness; or props)', &
         '            &loading   precompression, precompression_increments, history, increments,', &
         '                       tolerance, displacement_tolerance, max_iterations, min_increment,', &
         '                       output, plot, assembly', &
         '  Documented in drivers/fe2d/README.md (installed:', &
         '  share/doc/interphase/drivers/fe2d/README.md);', &
         '  cases to start from in share/interphase/fe2d-cases.'
   end subroutine print_usage

   !> Write the gnuplot script next to the CSV and, when `draw` and gnuplot is on PATH, run it.
   subroutine plot_csv(draw)
      logical, intent(in) :: draw                 !! run gnuplot (not --no-plot)
      character(len=:), allocatable :: directory, stem, script_name

      directory = directory_of(csv_path)
      stem = stem_of(csv_path)
      script_name = stem//'.gp'
      message = refuse_special_output(join_path(directory, script_name), case_path//': the plot script')
      if (len(message) > 0) call fail(message)
      call write_curve_plot_script(join_path(directory, script_name), base_name(csv_path), &
         stem//'.png', run%name, run%props(PROP_MU), ok, message)
      if (.not. ok) call fail(message)
      if (.not. draw) then
         write (output_unit, '(a)') run%name//': plot script written to '//join_path(directory, script_name)// &
            ' (--no-plot; in its folder, gnuplot '//script_name//' draws '//stem//'.png)'
         return
      end if
      if (.not. gnuplot_available()) then
         write (output_unit, '(a)') 'gnuplot not found: PNG skipped (install Debian package gnuplot-nox); in '// &
            'the folder of '//script_name//', gnuplot '//script_name//' draws it later'
         return
      end if
      call run_gnuplot(directory, script_name, ok, message)
      if (.not. ok) call fail(message)
      write (output_unit, '(a)') run%name//': plot written to '//join_path(directory, stem//'.png')
   end subroutine plot_csv

end program interphase_fe2d
