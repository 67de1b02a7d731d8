!> `interphase-bench`: cost of one `umat` call, simplified and micromechanical (built-in table) models.
!>
!>     interphase-bench [CALLS_PER_RUN [RUNS [CASE [POINTS]]]]   (defaults 1000000, 5, all cases, 1)
!>
!> CASE 1..8 runs one row of the table only (in the order printed: simplified + displacement
!> law 2-D, 3-D, micromechanical + displacement law 2-D, 3-D, simplified + LFM 2-D, 3-D,
!> micromechanical + LFM 2-D, 3-D), e.g. for an instruction count of one case under callgrind
!> (tools/bench-ratios.sh). CASE 9..16 runs case CASE - 8 with the growth-slip option constant
!> at its default appended to PROPS (NPROPS one more: the same material and the same numbers,
!> through the UMAT's general path instead of the path of its own; tests/threads/
!> check_umat_dispatch.sh, docs/performance.md); these rows are printed only when asked for.
!>
!> POINTS > 1 calls the UMAT as a host's element loop does: each increment updates POINTS points
!> one after the other, each with its own STRESS, STATEV, STRAN and energies, and each replaying
!> the history with its shear scaled by 0.5 + p/POINTS (p = 1..POINTS), so that the points reach
!> different damages (some D = 1) and take different branches from call to call; CALLS_PER_RUN /
!> (6 POINTS) increments per segment.
!>
!> Replays the paper's mixed-mode history (Table 4: s_N = -0.005 mm throughout, s_T = 0, 0,
!> 0.05, 0, 0.08, -0.05, 0 mm at t = 0..6) in 2-D and its 3-D version with the shear rotated by
!> 30 degrees into (s_T1, s_T2), with CALLS_PER_RUN / 6 equal increments per segment, RUNS
!> times each from the virgin state, and prints the best and median wall time per call
!> (`system_clock`, int64). The sum of all returned tractions is printed as a checksum so the
!> calls cannot be optimised away. Material: the paper's Table 1 data as in drivers/cases.
!> The time per call includes this program's own loop and the call with its 37 arguments (and
!> CMNAME's hidden length): tools/bench-ratios.sh times the same program linked with an empty
!> UMAT (about 12 ns a call compiled as the CMake Release build without LTO compiles it, 7.6-8.9
!> ns at -O2; with LTO the UMAT is specialised to the constant arguments; docs/performance.md).
program bench_umat
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_REQUIRED
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, TABLE_DEFAULT_CODE, DAMAGE_FRACTURE, &
      RCURVE_EQUIVALENT, DAMAGE_DISPLACEMENT
   use interphase_params, only: law_params_type, to_props
   use interphase_abaqus_interfaces, only: umat
   use interphase_driver_version, only: INTERPHASE_VERSION
   use interphase_driver_cli, only: exit_program, get_argument, refuse_extra_arguments, digits_value
   use interphase_driver_text, only: int_to_string
   implicit none

   !> Number of history segments of the mixed-mode history.
   integer, parameter :: NSEGMENTS = 6
   !> Shear separation of Table 4 at t = 0..6 (mm).
   real(dp), parameter :: SHEAR(0:NSEGMENTS) = [0.0_dp, 0.0_dp, 0.05_dp, 0.0_dp, 0.08_dp, &
      -0.05_dp, 0.0_dp]
   !> Normal separation of Table 4, constant (mm).
   real(dp), parameter :: NORMAL = -0.005_dp
   !> Rotation of the shear in 3-D (degrees).
   real(dp), parameter :: ANGLE_DEGREES = 30.0_dp

   real(dp), allocatable :: props(:)
   integer :: model, law, variant
   real(dp), allocatable :: ns_per_call(:)
   real(dp) :: checksum
   integer :: calls_per_run, runs, increments, ntens, run, only_case, npoints
   integer(int64) :: count_rate
   character(len=:), allocatable :: argument, message
   integer :: nargs, k
   character(len=*), parameter :: ROW_FORMAT = '(a20, a12, i6, i12, i6, 2f16.1, es24.15)'

   calls_per_run = 1000000
   runs = 5
   only_case = 0
   npoints = 1
   nargs = command_argument_count()
   if (nargs >= 1) then
      ! (--help and --version stand alone: an argument beside them would be ignored)
      message = refuse_extra_arguments()
      if (len(message) > 0) call fail(message)
      call get_argument(1, argument)
      if (argument == '-h' .or. argument == '--help') then
         write (*, '(a)') 'usage: interphase-bench [CALLS_PER_RUN [RUNS [CASE [POINTS]]]]', &
            '       interphase-bench --help | --version', &
            '  ns per umat call over the paper''s mixed history, 2-D and 3-D, both models (POINTS > 1:', &
            '  that many points per increment, in a host''s order); build it', &
            '  in a Release tree. Figures and commands: docs/performance.md.'
         call exit_program(0)
      else if (argument == '--version') then
         write (*, '(a)') 'interphase-bench (interphase) '//INTERPHASE_VERSION
         call exit_program(0)
      end if
   end if
   if (nargs > 4) then
      message = ''
      do k = 5, nargs
         call get_argument(k, argument)
         message = message//" '"//argument//"'"
      end do
      call fail('at most 4 arguments (CALLS_PER_RUN RUNS CASE POINTS), got '//int_to_string(nargs)// &
         '; the extra ones:'//message, usage=.true.)
   end if
   if (nargs >= 1) calls_per_run = positive_argument(1, 'CALLS_PER_RUN')
   if (nargs >= 2) runs = positive_argument(2, 'RUNS')
   if (nargs >= 3) then
      only_case = positive_argument(3, 'CASE')
      if (only_case > 16) call fail('CASE (argument 3) must be 1..16, got '//int_to_string(only_case), usage=.true.)
   end if
   if (nargs >= 4) npoints = positive_argument(4, 'POINTS')
   increments = max(1, calls_per_run/(NSEGMENTS*npoints))
   ! a run makes NSEGMENTS x POINTS x increments calls: said when that is not CALLS_PER_RUN
   if (NSEGMENTS*npoints*increments /= calls_per_run) write (error_unit, '(a)') 'interphase-bench: note: '// &
      'CALLS_PER_RUN = '//int_to_string(calls_per_run)//' is not a multiple of '//int_to_string(NSEGMENTS)// &
      ' segments x '//int_to_string(npoints)//' point(s): each run makes '// &
      int_to_string(NSEGMENTS*npoints*increments)//' calls ('//int_to_string(increments)//' increment(s) per segment)'


   call system_clock(count_rate=count_rate)
   allocate (ns_per_call(runs))
   write (output_unit, '(a)') 'interphase-bench: umat, paper Table 1 data, mixed-mode history'
   write (output_unit, '(a, i0, a, i0, a, i0, a, i0, a)') 'increments per segment: ', increments, &
      ' (', NSEGMENTS*increments*npoints, ' calls per run), runs: ', runs, &
      ', clock resolution: ', count_rate, ' ticks/s'
   if (npoints > 1) write (output_unit, '(a, i0, a)') 'host order: ', npoints, &
      ' points per increment, each with its own state and its shear scaled by 0.5 + p/POINTS'
   write (output_unit, '(a20, a12, a6, a12, a6, 2a16, a24)') 'model + damage law', 'history', 'NTENS', 'calls/run', &
      'runs', 'best ns/call', 'median ns/call', 'checksum (MPa)'
   do variant = 1, 4
   model = merge(MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, variant == 1 .or. variant == 3)
   law = merge(DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, variant <= 2)
   call set_props(model, law)
   ! (cases 9..16: the same material with the growth-slip option at its default, the general path)
   if (only_case > 8) props = [props, 0.0_dp]
   do ntens = 2, 3
      if (only_case > 0 .and. modulo(only_case - 1, 8) + 1 /= 2*(variant - 1) + ntens - 1) cycle
      do run = 1, runs
         if (npoints == 1) then
            call one_run(ntens, ns_per_call(run), checksum)
         else
            call host_run(ntens, npoints, ns_per_call(run), checksum)
         end if
      end do
      if (only_case > 8) then
         write (output_unit, ROW_FORMAT) model_name(model, law), 'general '//merge('2-D', '3-D', ntens == 2), ntens, &
            NSEGMENTS*increments*npoints, runs, minval(ns_per_call), median(ns_per_call), checksum
      else if (ntens == 2) then
         write (output_unit, ROW_FORMAT) model_name(model, law), 'mixed 2-D', ntens, NSEGMENTS*increments*npoints, &
            runs, minval(ns_per_call), median(ns_per_call), checksum
      else
         write (output_unit, ROW_FORMAT) model_name(model, law), 'mixed 3-D', ntens, NSEGMENTS*increments*npoints, &
            runs, minval(ns_per_call), median(ns_per_call), checksum
      end if
   end do
   end do

contains

   !> PROPS of the paper's Table 1 data, mu = 0.75 (our assumption): the simplified model with K
   !> from the closed forms of docs/rve.md, 'Exact identities', or the micromechanical model on the
   !> built-in table.
   subroutine set_props(which, damage_law)
      integer, intent(in) :: which, damage_law
      type(law_params_type) :: p
      p%model = which
      p%damage_law = damage_law
      p%mu = 0.75_dp
      p%s0_n = 0.00044_dp
      p%sf_n = 0.04_dp
      p%s0_t = 0.00072_dp
      p%sf_t = 0.06_dp
      if (which == MODEL_SIMPLIFIED) then
         p%k_n = 544000.0_dp/1127.0_dp
         p%k_t = 32000.0_dp/161.0_dp
      else
         p%table = TABLE_DEFAULT_CODE
      end if
      if (damage_law == DAMAGE_FRACTURE) then
         ! initial crack D0 = 0.02, the R-curve equivalent to the displacement law
         p%d0 = 0.02_dp
         p%rcurve = RCURVE_EQUIVALENT
      end if
      props = to_props(p)
   end subroutine set_props

   pure function model_name(which, damage_law) result(name)
      integer, intent(in) :: which, damage_law
      character(len=:), allocatable :: name
      name = 'simplified'
      if (which == MODEL_MICROMECHANICAL) name = 'micromech.'
      if (damage_law == DAMAGE_FRACTURE) then
         name = name//' + LFM'
      else
         name = name//' + disp.'
      end if
   end function model_name

   !> Replay the history once from the virgin state; time per call (ns) and checksum (MPa).
   subroutine one_run(ntens, ns, checksum)
      integer, intent(in) :: ntens                !! 2 or 3
      real(dp), intent(out) :: ns                 !! wall time per call (ns)
      real(dp), intent(out) :: checksum           !! sum of all tractions returned (MPa)
      real(dp) :: stress(ntens), stran(ntens), dstran(ntens), s_a(ntens), s_b(ntens), s_new(ntens)
      real(dp) :: ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), statev(NSTATV_REQUIRED)
      real(dp) :: sse, spd, scd, rpl, drpldt, time(2), dtime, predef(1), dpred(1), coords(3)
      real(dp) :: drot(3, 3), dfgrd(3, 3), pnewdt, theta, direction(2)
      integer(int64) :: start, finish
      integer :: segment, j, kinc
      character(len=80), parameter :: CMNAME = 'INTERPHASE'

      direction = [1.0_dp, 0.0_dp]
      if (ntens == 3) direction = [cos(ANGLE_DEGREES*acos(-1.0_dp)/180.0_dp), &
         sin(ANGLE_DEGREES*acos(-1.0_dp)/180.0_dp)]
      stress = 0.0_dp
      statev = 0.0_dp
      sse = 0.0_dp
      spd = 0.0_dp
      call fixed_arguments(ddsdde, ddsddt, drplde, scd, rpl, drpldt, predef, dpred, coords, drot, dfgrd)
      dtime = 1.0_dp/real(increments, dp)
      checksum = 0.0_dp
      kinc = 0
      ! The history starts at s_N = -0.005 mm: the clock starts after a first (elastic) call
      ! from zero to that separation, which is not counted.
      stran = 0.0_dp
      s_new = separation(0, ntens, direction)
      dstran = s_new
      time = 0.0_dp
      pnewdt = 1.0_dp
      call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, &
         dstran, time, 0.0_dp, 0.0_dp, 0.0_dp, predef, dpred, CMNAME, 1, ntens - 1, ntens, &
         NSTATV_REQUIRED, props, size(props), coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, &
         1, 1, 1, 1, [1, 0, 0, 0], kinc)
      call check(pnewdt, 0.0_dp)
      stran = s_new

      call system_clock(start)
      do segment = 1, NSEGMENTS
         s_a = separation(segment - 1, ntens, direction)
         s_b = separation(segment, ntens, direction)
         do j = 1, increments
            theta = real(j, dp)/real(increments, dp)
            s_new = (1.0_dp - theta)*s_a + theta*s_b
            dstran = s_new - stran
            time = real(segment - 1, dp) + real(j - 1, dp)*dtime
            kinc = kinc + 1
            pnewdt = 1.0_dp
            call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
               stran, dstran, time, dtime, 0.0_dp, 0.0_dp, predef, dpred, CMNAME, 1, ntens - 1, &
               ntens, NSTATV_REQUIRED, props, size(props), coords, drot, pnewdt, 1.0_dp, &
               dfgrd, dfgrd, 1, 1, 1, 1, [1, 0, 0, 0], kinc)
            if (pnewdt < 1.0_dp) call check(pnewdt, time(2))
            stran = s_new
            checksum = checksum + sum(stress) + ddsdde(1, 1)*1.0e-6_dp
         end do
      end do
      call system_clock(finish)
      ns = 1.0e9_dp*real(finish - start, dp)/real(count_rate, dp)/real(kinc, dp)
      checksum = checksum + spd
   end subroutine one_run

   !> The UMAT arguments the benchmark holds fixed: zeros, and identity rotation and deformation.
   subroutine fixed_arguments(ddsdde, ddsddt, drplde, scd, rpl, drpldt, predef, dpred, coords, drot, dfgrd)
      real(dp), intent(out) :: ddsdde(:, :), ddsddt(:), drplde(:), scd, rpl, drpldt, predef(:), dpred(:)
      real(dp), intent(out) :: coords(3), drot(3, 3), dfgrd(3, 3)
      integer :: i
      ddsdde = 0.0_dp
      ddsddt = 0.0_dp
      drplde = 0.0_dp
      scd = 0.0_dp
      rpl = 0.0_dp
      drpldt = 0.0_dp
      predef = 0.0_dp
      dpred = 0.0_dp
      coords = 0.0_dp
      drot = 0.0_dp
      dfgrd = 0.0_dp
      do i = 1, 3
         drot(i, i) = 1.0_dp
         dfgrd(i, i) = 1.0_dp
      end do
   end subroutine fixed_arguments

   !> Replay the history at npoints points in a host's order (each increment, every point in
   !> turn, each with its own state; point p's shear scaled by 0.5 + p/npoints), from the virgin
   !> state; time per call (ns) and checksum (MPa).
   subroutine host_run(ntens, npoints, ns, checksum)
      integer, intent(in) :: ntens                !! 2 or 3
      integer, intent(in) :: npoints              !! points per increment (> 1)
      real(dp), intent(out) :: ns                 !! wall time per call (ns)
      real(dp), intent(out) :: checksum           !! sum of all tractions returned (MPa)
      real(dp) :: stress(ntens, npoints), stran(ntens, npoints), statev(NSTATV_REQUIRED, npoints)
      real(dp) :: sse(npoints), spd(npoints), scale(npoints)
      real(dp) :: dstran(ntens), s_a(ntens), s_b(ntens), s_new(ntens)
      real(dp) :: ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens)
      real(dp) :: scd, rpl, drpldt, time(2), dtime, predef(1), dpred(1), coords(3)
      real(dp) :: drot(3, 3), dfgrd(3, 3), pnewdt, theta, direction(2)
      integer(int64) :: start, finish
      integer :: segment, j, kinc, p
      character(len=80), parameter :: CMNAME = 'INTERPHASE'

      direction = [1.0_dp, 0.0_dp]
      if (ntens == 3) direction = [cos(ANGLE_DEGREES*acos(-1.0_dp)/180.0_dp), &
         sin(ANGLE_DEGREES*acos(-1.0_dp)/180.0_dp)]
      do p = 1, npoints
         scale(p) = 0.5_dp + real(p, dp)/real(npoints, dp)
      end do
      stress = 0.0_dp
      statev = 0.0_dp
      sse = 0.0_dp
      spd = 0.0_dp
      call fixed_arguments(ddsdde, ddsddt, drplde, scd, rpl, drpldt, predef, dpred, coords, drot, dfgrd)
      dtime = 1.0_dp/real(increments, dp)
      checksum = 0.0_dp
      kinc = 0
      ! the first (elastic) call from zero to s_N = -0.005 mm at every point, not counted
      time = 0.0_dp
      stran = 0.0_dp
      do p = 1, npoints
         dstran = separation(0, ntens, direction)
         pnewdt = 1.0_dp
         call umat(stress(:, p), statev(:, p), ddsdde, sse(p), spd(p), scd, rpl, ddsddt, drplde, drpldt, &
            stran(:, p), dstran, time, 0.0_dp, 0.0_dp, 0.0_dp, predef, dpred, CMNAME, 1, ntens - 1, ntens, &
            NSTATV_REQUIRED, props, size(props), coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, &
            p, 1, 1, 1, [1, 0, 0, 0], kinc)
         call check(pnewdt, 0.0_dp)
         stran(:, p) = dstran
      end do

      call system_clock(start)
      do segment = 1, NSEGMENTS
         s_a = separation(segment - 1, ntens, direction)
         s_b = separation(segment, ntens, direction)
         do j = 1, increments
            theta = real(j, dp)/real(increments, dp)
            time = real(segment - 1, dp) + real(j - 1, dp)*dtime
            kinc = kinc + 1
            do p = 1, npoints
               s_new = (1.0_dp - theta)*s_a + theta*s_b
               s_new(2:) = scale(p)*s_new(2:)
               dstran = s_new - stran(:, p)
               pnewdt = 1.0_dp
               call umat(stress(:, p), statev(:, p), ddsdde, sse(p), spd(p), scd, rpl, ddsddt, drplde, drpldt, &
                  stran(:, p), dstran, time, dtime, 0.0_dp, 0.0_dp, predef, dpred, CMNAME, 1, ntens - 1, &
                  ntens, NSTATV_REQUIRED, props, size(props), coords, drot, pnewdt, 1.0_dp, &
                  dfgrd, dfgrd, p, 1, 1, 1, [1, 0, 0, 0], kinc)
               if (pnewdt < 1.0_dp) call check(pnewdt, time(2))
               stran(:, p) = s_new
               checksum = checksum + sum(stress(:, p)) + ddsdde(1, 1)*1.0e-6_dp
            end do
         end do
      end do
      call system_clock(finish)
      ns = 1.0e9_dp*real(finish - start, dp)/real(count_rate, dp)/real(kinc*npoints, dp)
      checksum = checksum + sum(spd)
   end subroutine host_run

   !> Separation of history row k in UMAT order (normal first), mm.
   pure function separation(k, ntens, direction) result(s)
      integer, intent(in) :: k                    !! row 0..NSEGMENTS
      integer, intent(in) :: ntens                !! 2 or 3
      real(dp), intent(in) :: direction(2)        !! unit shear direction in (T1, T2)
      real(dp) :: s(ntens)

      s(1) = NORMAL
      s(2:) = SHEAR(k)*direction(:ntens - 1)
   end function separation

   !> Stop the benchmark if the UMAT asked for a cut-back (it must not on this history).
   subroutine check(pnewdt, time)
      real(dp), intent(in) :: pnewdt              !! as returned by umat
      real(dp), intent(in) :: time                !! time at the start of the call

      if (pnewdt < 1.0_dp) then
         write (error_unit, '(a, g0)') 'interphase-bench: error: umat asked for a cut-back at t = ', &
            time
         call exit_program(1)
      end if
   end subroutine check

   !> Median of a short array (sorted copy).
   pure real(dp) function median(values)
      real(dp), intent(in) :: values(:)           !! samples
      real(dp) :: sorted(size(values)), swap
      integer :: i, j, n

      sorted = values
      n = size(sorted)
      do i = 2, n
         swap = sorted(i)
         j = i - 1
         do while (j >= 1)
            if (sorted(j) <= swap) exit
            sorted(j + 1) = sorted(j)
            j = j - 1
         end do
         sorted(j + 1) = swap
      end do
      if (mod(n, 2) == 1) then
         median = sorted((n + 1)/2)
      else
         median = 0.5_dp*(sorted(n/2) + sorted(n/2 + 1))
      end if
   end function median

   !> Command-line argument `position` as a positive integer: the whole argument one, digits only
   !> (no sign, no exponent), at most 9 of them; else the program ends with a message naming it.
   integer function positive_argument(position, name) result(value)
      integer, intent(in) :: position             !! argument number
      character(len=*), intent(in) :: name        !! its name for the message
      character(len=:), allocatable :: text
      call get_argument(position, text)
      value = digits_value(text)
      if (value < 1) call fail(name//' (argument '//int_to_string(position)//') must be a whole '// &
         "number from 1 to 999999999 (digits only), got '"//text//"'", usage=.true.)
   end function positive_argument

   !> Print the message (and the usage line) to standard error and end with exit status 1.
   subroutine fail(text, usage)
      character(len=*), intent(in) :: text        !! what went wrong
      logical, intent(in), optional :: usage      !! also print the usage line
      write (error_unit, '(a)') 'interphase-bench: error: '//text
      if (present(usage)) then
         if (usage) write (error_unit, '(a)') 'usage: interphase-bench [CALLS_PER_RUN [RUNS [CASE [POINTS]]]]'
      end if
      call exit_program(1)
   end subroutine fail

end program bench_umat
