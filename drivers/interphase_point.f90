!> `interphase-point`: single material-point driver of the interphase UMAT.
!>
!>     interphase-point CASE.nml [--output-dir DIR] [--no-plot]
!>
!> Reads the case file (namelists `&material` and `&loading`, see `interphase_driver_case`),
!> replays its history of separations and tractions (see `interphase_driver_history`,
!> `interphase_driver_replay`) through `umat` and writes a CSV table (see
!> `interphase_driver_output`); when `plot` is true, `--no-plot` is not given and gnuplot is on
!> PATH, also a gnuplot script and a PNG next to the CSV. Relative `output` paths are taken
!> relative to DIR, or to the current directory. The CSV is written to `CSV.part` and renamed to
!> `CSV` when the run succeeds: a failed run leaves a previous CSV as it was and its own rows in
!> `CSV.part`. Every error is printed to standard error and ends the program with exit status 1;
!> a tangent check above its tolerance also gives exit status 1, after the CSV is written.
program interphase_point
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type, from_props
   use interphase_enums, only: STIFFNESS_CONSISTENT
   use interphase_status, only: STATUS_OK, MESSAGE_LEN
   use interphase_driver_case, only: case_type, read_case, load_start_up_data, d0_entry_of, material_summary, writes_an_input, &
      STIFFNESS_WORDS, &
      data_files_summary
   use interphase_driver_cli, only: run_arguments_type, parse_run_arguments, make_directory, &
      gnuplot_available, run_gnuplot, exit_program, rename_file, print_version, refuse_special_output, remove_file, &
      open_failure, OPEN_MESSAGE_LEN
   use interphase_driver_history, only: history_type, read_history
   use interphase_driver_namelist, only: with_entry_line
   use interphase_driver_output, only: csv_header, write_plot_script
   use interphase_driver_replay, only: replay_history, replay_report_type
   use interphase_driver_replay_call, only: replay_call_type, is_replay_file, read_replay_call, repeat_replay_call
   use interphase_driver_text, only: int_to_string, real_to_string, directory_of, base_name, stem_of, &
      join_path
   implicit none

   character(len=:), allocatable :: case_path, output_dir, csv_path, part_path, message, summary
   !> the table and R-curve files the run read ('' when none)
   character(len=:), allocatable :: files
   type(run_arguments_type) :: cli
   type(replay_report_type) :: report
   type(case_type) :: run
   type(history_type) :: history
   logical :: no_plot, ok
   integer :: unit, ios, nrows
   character(len=OPEN_MESSAGE_LEN) :: open_message

   ! ---- command line ----
   call parse_run_arguments(cli, ok, message)
   if (cli%help) then
      call print_usage(output_unit)
      call exit_program(0)
   end if
   if (cli%version) then
      call print_version('interphase-point')
      call exit_program(0)
   end if
   if (.not. ok) call fail(message, usage=.true.)
   ! the hosts' start-up variables are not read here: a user who set one is told (standard error)
   call note_unused_variable('INTERPHASE_TABLE', 'the RVE table is the case file''s table entry (the built-in '// &
      'table when none)')
   call note_unused_variable('INTERPHASE_RCURVE', 'the tabulated R-curve is the case file''s rcurve_file entry')
   case_path = cli%case_path
   output_dir = cli%output_dir
   no_plot = cli%no_plot

   ! ---- a replay file: repeat its one UMAT call ----
   if (is_replay_file(case_path)) call repeat_replay(case_path)

   ! ---- inputs ----
   call read_case(case_path, run, ok, message)
   if (.not. ok) call fail(message)
   call read_history(run%history_path, history, ok, message, named_by=run%history_entry)
   if (.not. ok) call fail(message)
   ! start-up: custom RVE table and R-curve read once, before any update (as UEXTERNALDB does), and
   ! the R-curve's coverage of D0 checked; a refusal names the entry's line
   call load_start_up_data(run%table_path, run%rcurve_path, case_path//': &material: ', ok, message, props=run%props, &
      d0_entry=d0_entry_of(run%lines, 'material'))
   if (.not. ok) call fail(with_entry_line(message, case_path, run%lines))
   summary = material_summary(run%props)
   write (output_unit, '(a)') run%name//': '//summary
   ! (the table and R-curve files the run read, which PROPS cannot name)
   files = data_files_summary(run%table_path, run%rcurve_path)
   if (len(files) > 0) write (output_unit, '(a)') run%name//': '//files

   ! ---- replay into the CSV ----
   csv_path = join_path(output_dir, run%output)
   call refuse_overwriting_inputs()
   call make_directory(directory_of(csv_path), ok, message)
   if (.not. ok) call fail(message)
   ! the rows go to CSV.part, renamed to CSV at the end: a failed run leaves a previous CSV as it was
   part_path = csv_path//'.part'
   open (newunit=unit, file=part_path, status='replace', action='write', form='formatted', &
      iostat=ios, iomsg=open_message)
   if (ios /= 0) call fail(open_failure('the CSV file', part_path, open_message))
   write (unit, '(a)') csv_header(history%ntens, tangent_error=run%tangent_check > 0.0_dp)
   call replay_history(run, history, unit, nrows, ok, message, report, &
      replay_path=join_path(directory_of(csv_path), stem_of(csv_path)//'.replay.nml'))
   close (unit)
   if (.not. ok) then
      if (nrows == 0) then
         ! (the probe before the first step, or the first step, failed: nothing to look at)
         call remove_file(part_path)
         call fail(message//' (no row was written; '//csv_path//' was not written)')
      end if
      call fail(message//' (the rows up to the failure are in '//part_path//'; '//csv_path//' was not written)')
   end if
   call rename_file(part_path, csv_path, ok, message)
   if (.not. ok) call fail(message)
   write (output_unit, '(a)') run%name//': '//int_to_string(nrows)//' rows ('// &
      int_to_string(history%ntens)//'-D) written to '//csv_path

   ! ---- plot ----
   if (run%plot .and. .not. no_plot) call plot_csv()

   ! ---- tangent check ----
   if (run%tangent_check > 0.0_dp) then
      write (output_unit, '(a)') run%name//': tangent check: worst relative error of DDSDDE against the '// &
         'central finite difference '//real_to_string(report%worst_tangent_error)//' at t = '// &
         real_to_string(report%worst_tangent_time)//' over '//int_to_string(report%checked_steps)// &
         ' steps (step '//real_to_string(run%tangent_step)//' mm; '//int_to_string(report%kink_steps)// &
         ' with a kink within the step, compared one-sided; '//int_to_string(report%unchecked_steps)// &
         ' not checked: a perturbed call failed); tolerance '//real_to_string(run%tangent_check)
      if (report%checked_steps == 0) then
         ! (every perturbed call failed: nothing was compared, and a check of nothing does not pass)
         write (error_unit, '(a)') 'interphase-point: error: '//run%path//': the tangent check compared no '// &
            'step: a perturbed call failed at every step ('//int_to_string(report%unchecked_steps)// &
            ' not checked; tangent_step = '//real_to_string(run%tangent_step)//' mm)'
         call exit_program(1)
      end if
      if (report%worst_tangent_error > run%tangent_check) then
         write (error_unit, '(a)') 'interphase-point: error: '//run%path//': the tangent check failed: '// &
            'worst relative error '//real_to_string(report%worst_tangent_error)//' at t = '// &
            real_to_string(report%worst_tangent_time)//' is above tangent_check = '// &
            real_to_string(run%tangent_check)//' (column tangent_error of '//csv_path//')'//stiffness_note()
         call exit_program(1)
      end if
   end if

contains

   !> Why a tangent check fails by design: '' for the consistent tangent (the default), else a
   !> note that the material's stiffness option is not the update's derivative.
   function stiffness_note() result(note)
      character(len=:), allocatable :: note
      type(law_params_type) :: params
      integer :: status
      character(len=MESSAGE_LEN) :: decode_message
      note = ''
      call from_props(run%props, params, status, decode_message)
      if (status /= STATUS_OK .or. params%stiffness == STIFFNESS_CONSISTENT) return
      note = '; the material''s stiffness = '''//trim(STIFFNESS_WORDS(params%stiffness))//''' is by design not '// &
         'the derivative of the update '// &
         '(docs/abaqus.md, PROPS): the check is for stiffness = ''consistent'', the default'
   end function stiffness_note

   !> Print the message to standard error and stop with exit status 1.
   subroutine fail(text, usage)
      character(len=*), intent(in) :: text        !! what went wrong
      logical, intent(in), optional :: usage      !! also print the usage line

      write (error_unit, '(a)') 'interphase-point: error: '//text
      if (present(usage)) then
         if (usage) call print_usage(error_unit)
      end if
      call exit_program(1)
   end subroutine fail

   !> A note on standard error when the environment variable `name` is set (and not empty): the
   !> hosts' start-up (UEXTERNALDB, VEXTERNALDB, the CalculiX hook) loads the file it names;
   !> interphase-point does not read it, its case file (or replay file) names the file.
   subroutine note_unused_variable(name, instead)
      character(len=*), intent(in) :: name        !! the environment variable
      character(len=*), intent(in) :: instead     !! where interphase-point takes the file from
      integer :: length, stat
      call get_environment_variable(name, length=length, status=stat)
      if (stat /= 0 .or. length == 0) return
      write (error_unit, '(a)') 'interphase-point: note: '//name//' is set, but interphase-point does not '// &
         'read it: '//instead//'; a replay file names its own (drivers/README.md)'
      ! (at once: flang buffers standard error, which would put the note after the run's output)
      flush (error_unit)
   end subroutine note_unused_variable

   !> Repeat the UMAT call of a replay file (`&replay`) and end: exit status 1 when it fails again.
   subroutine repeat_replay(path)
      character(len=*), intent(in) :: path
      type(replay_call_type) :: replayed
      logical :: failed
      call read_replay_call(path, replayed, ok, message)
      if (.not. ok) call fail(message)
      write (output_unit, '(a)') path//': the '//trim(replayed%source)//' call of element '// &
         int_to_string(replayed%noel)//', point '//int_to_string(replayed%npt)//', increment '// &
         int_to_string(replayed%kinc)//' that failed with: '//trim(replayed%failure)
      write (output_unit, '(a)') 'material: '//material_summary(replayed%props(1:replayed%nprops))
      call load_start_up_data(trim(replayed%table), trim(replayed%rcurve), &
         path//': &replay (the files the run had loaded): ', ok, message, rcurve_entry='rcurve')
      if (.not. ok) call fail(message)
      call repeat_replay_call(replayed, failed)
      if (failed) call exit_program(1)
      call exit_program(0)
   end subroutine repeat_replay

   !> Print how to call the program.
   subroutine print_usage(unit)
      integer, intent(in) :: unit                 !! where to print

      write (unit, '(a)') 'usage: interphase-point CASE.nml [--output-dir DIR] [--no-plot]', &
         '       interphase-point --help | --version', &
         '  Replays the history of CASE.nml through the interphase UMAT at one material point and', &
         '  writes a CSV table (and a PNG of the curves if gnuplot is on PATH).', &
         '  CASE.nml: &material  model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t (simplified),', &
         '                       table, d0, rcurve, rcurve_file, g_ci, g_cii, growth_slip,', &
         '                       contact_band, viscosity, stiffness;', &
         '                       or props (the UMAT''s PROPS, 1 to 20 values) with table, rcurve_file', &
         '            &loading   history, increments, output, plot, traction_tolerance,', &
         '                       output_every, tangent_check, tangent_step', &
         '  History: columns t s_T s_N (3-D: t s_T1 s_T2 s_N); a line "# columns: t s_T Sigma_N"', &
         '  imposes a traction (Sigma_*) instead of a separation on a component.', &
         '  interphase-point REPLAY.nml repeats the failed call of a replay file (&replay; written', &
         '  next to the CSV when an update fails, and by the UMAT/VUMAT into INTERPHASE_REPLAY_DIR).', &
         '  Documented in drivers/README.md (installed: share/doc/interphase/drivers/README.md);', &
         '  cases to start from in share/interphase/cases.'
   end subroutine print_usage

   !> The files the run writes (the CSV, CSV.part, the replay file, the plot script and the PNG)
   !> must not be the case file, its history, RVE table or R-curve file: a case whose output names
   !> one of them would replace it.
   subroutine refuse_overwriting_inputs()
      character(len=:), allocatable :: stem, directory
      directory = directory_of(csv_path)
      stem = stem_of(csv_path)
      call refuse(csv_path)
      call refuse(csv_path//'.part')
      call refuse(join_path(directory, stem//'.replay.nml'))
      call refuse(join_path(directory, stem//'.gp'))
      call refuse(join_path(directory, stem//'.png'))
   end subroutine refuse_overwriting_inputs

   !> Stop when `written` is one of the run's input files, or not a regular file.
   subroutine refuse(written)
      character(len=*), intent(in) :: written
      character(len=:), allocatable :: refusal
      if (writes_an_input(run, written)) &
         call fail(run%output_entry//' would write '//written//', which is an input of this run: name another file')
      refusal = refuse_special_output(written, run%output_entry)
      if (len(refusal) > 0) call fail(refusal)
   end subroutine refuse

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
         stem//'.png', run%name, summary, history%ntens, ok, message, moving=report%moving)
      if (.not. ok) call fail(message)
      call run_gnuplot(directory, script_name, ok, message)
      if (.not. ok) call fail(message)
      write (output_unit, '(a)') run%name//': plot written to '//join_path(directory, stem//'.png')
   end subroutine plot_csv

end program interphase_point
