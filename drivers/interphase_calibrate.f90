!> `interphase-calibrate`: the paper's calibration of the simplified model (section 5.2: "for
!> the simplified model the values of s0_T and s0_N are properly modified in order to recover
!> the same fracture energy").
!>
!>     interphase-calibrate CASE.nml [--increments N] [--write FILE.nml]
!>
!> CASE.nml is a micromechanical case file (its &loading group is not used and may be left out). The program runs
!> the monotonic mode-I and mode-II tests (h1I, h1II) to 1.01 sf through `umat`, refuses a test
!> that ends before full damage (D < 1: the fracture law's crack growth is not bounded by sf),
!> takes the fracture energies G_I, G_II as the dissipated energy at the end (SPD) and the
!> stiffnesses K_N, K_T as the slopes at the start of each test (the UMAT's DDSDDE of the virgin
!> point at 1e-9 s0 in the test's direction, whatever the step: with an initial crack D0 > 0 the
!> opening and the frictionless slip at s_N = 0, not the closed crack's stick at s = 0), and sets
!>     s0_N = 2 G_I/(K_N sf_N),   s0_T = 2 G_II/(K_T sf_T)
!> so that the simplified model's fracture energies 1/2 K s0 sf equal them (sf kept). It prints
!> the numbers and, with --write, a `&material` group of the calibrated simplified model.
program interphase_calibrate
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use interphase_kinds, only: dp
   use interphase_layout, only: PROP_MODEL, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, PROP_SF_T, &
      MODEL_MICROMECHANICAL
   use interphase_micro_coefficients, only: custom_table_source
   use interphase_layout, only: PROP_TABLE, SV_DAMAGE
   use interphase_driver_case, only: case_type, read_case, load_start_up_data, d0_entry_of, writes_an_input
   use interphase_driver_namelist, only: with_entry_line
   use interphase_driver_replay, only: point_state_type, new_point, call_umat
   use interphase_driver_text, only: int_to_string, real_to_string
   use interphase_params, only: law_params_type, from_props
   use interphase_status, only: STATUS_OK, MESSAGE_LEN
   use interphase_driver_cli, only: get_argument, exit_program, print_version, refuse_extra_arguments, &
      refuse_special_output, is_directory, open_failure, OPEN_MESSAGE_LEN, digits_value
   use interphase_driver_text, only: directory_of
   implicit none

   !> Where the slope at the start of a test is taken: this fraction of s0 (of sf, were it smaller) (-)
   real(dp), parameter :: S_START = 1.0e-9_dp

   type(case_type) :: run
   type(law_params_type) :: params
   character(len=:), allocatable :: case_path, write_path, message, argument
   character(len=MESSAGE_LEN) :: why
   character(len=OPEN_MESSAGE_LEN) :: open_message
   integer :: increments, i, nargs, unit, ios, status
   logical :: ok, increments_given
   real(dp) :: g_i, g_ii, k_n, k_t, peak_n, peak_t, s_peak_n, s_peak_t, s0_n, s0_t

   increments = 20000
   increments_given = .false.
   case_path = ''
   write_path = ''
   nargs = command_argument_count()
   ! --help and --version stand alone: an argument beside them would be ignored
   message = refuse_extra_arguments()
   if (len(message) > 0) call fail(message)
   i = 0
   do while (i < nargs)
      i = i + 1
      call get_argument(i, argument)
      select case (argument)
      case ('-h', '--help')
         call print_usage(output_unit)
         call exit_program(0)
      case ('--version')
         call print_version('interphase-calibrate')
         call exit_program(0)
      case ('--increments')
         ! an option given twice: which one counts is not guessed
         if (increments_given) call fail('--increments given twice')
         increments_given = .true.
         if (i == nargs) call fail('--increments needs a whole number from 10 to 999999999')
         i = i + 1
         call get_argument(i, argument)
         ! a whole number of at most 9 digits, at least 10
         increments = digits_value(argument)
         if (increments < 0) call fail("--increments needs a whole number from 10 to 999999999, got '"//argument//"'")
         if (increments < 10) call fail('--increments needs at least 10, got '//argument)
      case ('--write')
         if (len(write_path) > 0) call fail('--write given twice')
         if (i == nargs) call fail('--write needs a file name')
         i = i + 1
         call get_argument(i, write_path)
         if (len(write_path) == 0) call fail('--write needs a file name')
         if (write_path(1:1) == '-') call fail('--write needs a file name, got '''//write_path//''', which '// &
            'begins with ''-'' like an option (a file named so: write ./'//write_path//')')
      case ('')
         call fail('argument '//int_to_string(i)//' is empty (an empty case file name)')
      case default
         if (argument(1:1) == '-') call fail('unknown option '//argument)
         if (len(case_path) > 0) call fail('one case file only: '//case_path//' and '//argument//' given')
         case_path = argument
      end select
   end do
   if (len(case_path) == 0) then
      write (error_unit, '(a)') 'interphase-calibrate: error: no case file given'
      call print_usage(error_unit)
      call exit_program(1)
   end if

   ! (the &loading group, which the calibration does not use, may be left out; where given it is
   ! read, and --write may not replace its history)
   call read_case(case_path, run, ok, message, material_only=.true.)
   if (.not. ok) call fail(message)
   ! --write must not replace an input (the paths resolved and compared: drivers/README.md), and is
   ! a regular file in a folder that exists: checked before the calibration runs
   if (len(write_path) > 0) then
      if (writes_an_input(run, write_path)) &
         call fail('--write '//write_path//' is an input of this run: name another file')
      message = refuse_special_output(write_path, '--write '//write_path)
      if (len(message) > 0) call fail(message)
      if (len(directory_of(write_path)) > 0) then
         if (.not. is_directory(directory_of(write_path))) call fail('--write '//write_path//': the folder '// &
            directory_of(write_path)//' does not exist (or is not a folder): create it first')
      end if
   end if
   if (nint(run%props(PROP_MODEL)) /= MODEL_MICROMECHANICAL) &
      call fail(case_path//": the case must use model = 'micromechanical' (the calibration maps a "// &
      "micromechanical material onto the simplified model; under the displacement-driven law a simplified material's "// &
      "peaks are K_N s0_N and K_T s0_T and its fracture energies (1/2) K_N s0_N sf_N and (1/2) K_T s0_T sf_T: "// &
      "interphase-point replays them)")
   ! the tests are quasi-static, one second a step: a viscous damage would depend on the step
   call from_props(run%props, params, status, why)
   if (status /= STATUS_OK) call fail(case_path//': '//trim(why))
   if (params%viscosity > 0.0_dp) call fail(case_path//': &material: viscosity = '// &
      real_to_string(params%viscosity)//' s: the calibration''s tests are quasi-static (rate-independent '// &
      'fracture energies): set it to 0')
   ! (the R-curve's coverage of D0 checked too; a refusal names the entry's line)
   call load_start_up_data(run%table_path, run%rcurve_path, case_path//': &material: ', ok, message, props=run%props, &
      d0_entry=d0_entry_of(run%lines, 'material'))
   if (.not. ok) call fail(with_entry_line(message, case_path, run%lines))

   call monotonic(1, 'N', run%props(PROP_S0_N), run%props(PROP_SF_N), g_i, k_n, peak_n, s_peak_n)
   call monotonic(2, 'T', run%props(PROP_S0_T), run%props(PROP_SF_T), g_ii, k_t, peak_t, s_peak_t)
   s0_n = 2.0_dp*g_i/(k_n*run%props(PROP_SF_N))
   s0_t = 2.0_dp*g_ii/(k_t*run%props(PROP_SF_T))

   write (output_unit, '(a)') 'interphase-calibrate: micromechanical model of '//case_path
   write (output_unit, '(a)') '  table: '//custom_table_source(nint(run%props(PROP_TABLE)))
   write (output_unit, '(a,i0,a)') '  monotonic tests h1I, h1II to 1.01 sf, ', increments, ' increments each'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  K_N  = ', k_n, ' MPa/mm   K_T  = ', k_t, ' MPa/mm'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  G_I  = ', g_i, ' N/mm     G_II = ', g_ii, ' N/mm'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  peak Sigma_N = ', peak_n, ' MPa at s_N = ', s_peak_n, ' mm'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  peak Sigma_T = ', peak_t, ' MPa at s_T = ', s_peak_t, ' mm'
   write (output_unit, '(a)') '  simplified model with the same K, sf and fracture energies (s0 = 2 G/(K sf)):'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  s0_N = ', s0_n, ' mm (given ', run%props(PROP_S0_N), ')'
   write (output_unit, '(a,es16.8,a,es16.8,a)') '  s0_T = ', s0_t, ' mm (given ', run%props(PROP_S0_T), ')'
   call check_below_sf('I', 'N', g_i, k_n, s0_n, run%props(PROP_SF_N))
   call check_below_sf('II', 'T', g_ii, k_t, s0_t, run%props(PROP_SF_T))

   if (len(write_path) > 0) then
      open (newunit=unit, file=write_path, status='replace', action='write', iostat=ios, iomsg=open_message)
      if (ios /= 0) call fail(open_failure('--write', write_path, open_message))
      write (unit, '(a)') '! Simplified model calibrated by interphase-calibrate on '//case_path
      write (unit, '(a)') '! (same K, sf and fracture energies as the micromechanical model; table '// &
         custom_table_source(nint(run%props(PROP_TABLE)))//')'
      write (unit, '(a,es24.16,a,es24.16)') '! G_I = ', g_i, ' N/mm, G_II = ', g_ii
      write (unit, '(a)') '&material'
      write (unit, '(a)') "  model = 'simplified'"
      write (unit, '(a)') "  damage_law = 'displacement'"
      write (unit, '(a,es24.16)') '  mu = ', run%props(PROP_MU)
      write (unit, '(a,es24.16)') '  s0_n = ', s0_n
      write (unit, '(a,es24.16)') '  sf_n = ', run%props(PROP_SF_N)
      write (unit, '(a,es24.16)') '  s0_t = ', s0_t
      write (unit, '(a,es24.16)') '  sf_t = ', run%props(PROP_SF_T)
      write (unit, '(a,es24.16)') '  k_n = ', k_n
      write (unit, '(a,es24.16)') '  k_t = ', k_t
      write (unit, '(a)') '/'
      close (unit)
      write (output_unit, '(a)') '  written: '//write_path
   end if

contains

   !> Monotonic pure-mode test (component 1: s_N, 2: s_T) from 0 to 1.01 sf in `increments`
   !> steps: dissipated energy at the end, the slope at the start, peak traction. A test that
   !> ends with D < 1 is refused: its dissipated energy is not the fracture energy.
   subroutine monotonic(component, mode, s0, sf, energy, stiffness, peak, s_peak)
      integer, intent(in) :: component
      character(len=1), intent(in) :: mode        !! 'N' or 'T', for the messages
      real(dp), intent(in) :: s0, sf              !! the case's s0 and sf of the mode (mm)
      real(dp), intent(out) :: energy, stiffness, peak, s_peak
      type(point_state_type) :: point, probe
      real(dp) :: s(2), pnewdt, ddsdde(2, 2)
      integer :: k
      point = new_point(2, 0.0_dp)
      peak = 0.0_dp
      s_peak = 0.0_dp
      ! the slope at the start of the test: the tangent of the virgin point (an increment whose
      ! state is not kept) at 1e-9 s0 in the test's direction (below the onset of damage), not
      ! that of the first step, which may already pass s0; not at s = 0 either, where an initial crack (D0 > 0) is closed and
      ! sticks (the intact stiffness) while the test opens it, or slips at s_N = 0 without friction
      probe = point
      s = 0.0_dp
      s(component) = S_START*min(s0, sf)
      call call_umat(run%props, probe, s, 0.0_dp, pnewdt, ddsdde)
      if (pnewdt < 1.0_dp) call fail('the UMAT failed at the start of the monotonic test; see its message above')
      stiffness = ddsdde(component, component)
      do k = 1, increments
         s = 0.0_dp
         s(component) = 1.01_dp*sf*real(k, dp)/real(increments, dp)
         call call_umat(run%props, point, s, real(k, dp), pnewdt, ddsdde)
         if (pnewdt < 1.0_dp) call fail('the UMAT failed at step '//int_to_string(k)// &
            ' of the monotonic test; see its message above')
         if (abs(point%stress(component)) > peak) then
            peak = abs(point%stress(component))
            s_peak = s(component)
         end if
      end do
      energy = point%spd
      if (.not. (point%statev(SV_DAMAGE) >= 1.0_dp)) call fail('the mode-'//trim(merge('I ', 'II', mode == 'N'))// &
         ' test ended at D = '//real_to_string(point%statev(SV_DAMAGE))//' with Sigma_'//mode//' = '// &
         real_to_string(point%stress(component))//' MPa at s_'//mode//' = 1.01 sf_'//mode//' = '// &
         real_to_string(1.01_dp*sf)//' mm: the crack did not reach b, so the dissipated energy '// &
         real_to_string(energy)//' N/mm is not the fracture energy (with the fracture law sf_'//mode// &
         ' does not bound the growth: raise it until the test breaks the interface)')
   end subroutine monotonic

   !> A simplified model with the stiffness K and the full-crack separation sf dissipates at most
   !> 1/2 K sf^2 (at s0 = sf): a larger G has no s0 < sf, and the failure names the mode, the
   !> values and the case's entry to change.
   subroutine check_below_sf(roman, mode, energy, stiffness, s0, sf)
      character(len=*), intent(in) :: roman       !! 'I' or 'II', for the message
      character(len=1), intent(in) :: mode        !! 'N' or 'T', for the message
      real(dp), intent(in) :: energy, stiffness   !! G (N/mm) and K (MPa/mm) of the test
      real(dp), intent(in) :: s0, sf              !! the calibrated s0 and the case's sf (mm)
      character(len=:), allocatable :: entry
      if (s0 < sf) return
      entry = 'sf_'//merge('n', 't', mode == 'N')
      call fail('no simplified model matches the mode-'//roman//' test: s0_'//mode//' = 2 G_'//roman// &
         '/(K_'//mode//' sf_'//mode//') = '//real_to_string(s0)//' mm is not below sf_'//mode//' = '// &
         real_to_string(sf)//' mm (&material: '//entry//'): G_'//roman//' = '//real_to_string(energy)// &
         ' N/mm exceeds the most the simplified model with K_'//mode//' = '//real_to_string(stiffness)// &
         ' MPa/mm and this sf_'//mode//' dissipates, 1/2 K_'//mode//' sf_'//mode//'^2 = '// &
         real_to_string(0.5_dp*stiffness*sf**2)//' N/mm (with the fracture law sf_'//mode// &
         ' only sets how far the tests go: raise '//entry//')')
   end subroutine check_below_sf

   subroutine fail(text)
      character(len=*), intent(in) :: text
      write (error_unit, '(a)') 'interphase-calibrate: error: '//text
      call exit_program(1)
   end subroutine fail

   !> How to call the program.
   subroutine print_usage(unit)
      integer, intent(in) :: unit                 !! where to print
      write (unit, '(a)') 'usage: interphase-calibrate MICRO_CASE.nml [--increments N] [--write SIMPLIFIED.nml]', &
         '       interphase-calibrate --help | --version', &
         '  Runs the monotonic mode-I and mode-II tests of a micromechanical case to 1.01 sf (refusing', &
         '  a test that does not break the interface) and', &
         '  prints K_N, K_T, G_I, G_II, the peaks and the simplified model''s s0_N, s0_T with the same', &
         '  fracture energies (the paper''s section 5.2); --write saves that simplified &material.', &
         '  --increments N: steps per test (default 20000, at least 10).', &
         '  MICRO_CASE.nml: an interphase-point case (its &material is used), e.g.', &
         '  share/interphase/cases/micro/h1I.nml; documented in drivers/README.md.'
   end subroutine print_usage

end program interphase_calibrate
