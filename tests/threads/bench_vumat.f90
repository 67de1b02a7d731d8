!> Benchmark of the VUMAT: nanoseconds per material-point update at nblock = 1, 136 and 4096
!> (the paper's mixed history with a different scaling per point), beside a plain copy of the
!> same arrays (old -> new stress, state and energies, reading the strain increments): the
!> memory-bound limit of any VUMAT on these arrays. Four cases, each on the vectorised block
!> update: the simplified model in 2-D (the figure of issue 5) and 3-D, and the micromechanical
!> model (built-in table) in 2-D and 3-D. Each figure is the best of
!> NREPEAT measurements (each a fresh start of the whole history).
!>
!>   interphase-bench-vumat [points [case]]   (default 65536 points; Release build recommended)
!>
!> With a case (1 simplified 2-D, 2 simplified 3-D, 3 micromechanical 2-D, 4 micromechanical
!> 3-D) only that case runs, at nblock = 4096 and once: for an instruction count under callgrind
!> (tools/bench-ratios.sh counts `vumat_` and `plain_copy` per point that way).
program bench_vumat
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   use interphase_kinds, only: dp
   use interphase_layout, only: NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NSTATV_VUMAT
   use interphase_abaqus_interfaces, only: vumat
   use, intrinsic :: iso_c_binding, only: c_int
   implicit none

   interface
      !> C's exit(): ends the program with a status and no "ERROR STOP" line or backtrace.
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
   end interface

   !> Block sizes measured (136 is Abaqus/Explicit's usual vector length).
   integer, parameter :: NBLOCK_SIZES(3) = [1, 136, 4096]
   !> Increments per segment of the mixed history and sweeps (increments) timed.
   integer, parameter :: NSUB = 20, NSWEEP = 7*NSUB
   !> Measurements per figure; the best one is printed.
   integer, parameter :: NREPEAT = 5

   !> The paper's Table 1 data (simplified model: K_N, K_T of the paper's RVE).
   real(dp), parameter :: SIMPLIFIED_PROPS(NPROPS_SIMPLIFIED) = [1.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, &
      0.04_dp, 0.00072_dp, 0.06_dp, 544000.0_dp/1127.0_dp, 32000.0_dp/161.0_dp]
   real(dp), parameter :: MICRO_PROPS(NPROPS_MICROMECHANICAL) = [2.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, &
      0.04_dp, 0.00072_dp, 0.06_dp, 0.0_dp]

   integer :: npoints, only_case, nrepeat_used, nblock_first
   character(len=*), parameter :: TITLES(4) = [character(len=44) :: 'simplified model, 2-D', &
      'simplified model, 3-D', 'micromechanical model (built-in table), 2-D', &
      'micromechanical model (built-in table), 3-D']

   npoints = 65536
   only_case = 0
   nrepeat_used = NREPEAT
   nblock_first = 1
   if (command_argument_count() > 2) then
      write (error_unit, '(a,i0,a)') 'interphase-bench-vumat: at most 2 arguments (points case), got ', &
         command_argument_count(), '; usage: interphase-bench-vumat [points [case]]'
      call stop_with(2)
   end if
   if (command_argument_count() >= 1) npoints = positive_argument(1, 'points')
   if (command_argument_count() >= 2) then
      only_case = positive_argument(2, 'case')
      if (only_case > 4) then
         write (error_unit, '(a)') 'interphase-bench-vumat: case must be 1..4'
         call stop_with(2)
      end if
      nrepeat_used = 1
      nblock_first = size(NBLOCK_SIZES)
   end if

   if (only_case == 0 .or. only_case == 1) call run_case(trim(TITLES(1)), 1, SIMPLIFIED_PROPS)
   if (only_case == 0 .or. only_case == 2) call run_case(trim(TITLES(2)), 2, SIMPLIFIED_PROPS)
   if (only_case == 0 .or. only_case == 3) call run_case(trim(TITLES(3)), 1, MICRO_PROPS)
   if (only_case == 0 .or. only_case == 4) call run_case(trim(TITLES(4)), 2, MICRO_PROPS)

contains

   !> Command argument `position` as a positive integer: the whole field must be one.
   integer function positive_argument(position, name) result(value)
      integer, intent(in) :: position
      character(len=*), intent(in) :: name
      character(len=32) :: text
      integer :: length, status, ios
      call get_command_argument(position, text, length, status)
      value = 0
      if (status == 0 .and. length > 0 .and. verify(trim(text), '0123456789') == 0) then
         read (text, '(i32)', iostat=ios) value
         if (ios /= 0) value = 0
      end if
      if (value < 1) then
         write (error_unit, '(a)') 'interphase-bench-vumat: '//name//' must be a positive integer, not '''// &
            trim(text)//''''
         call stop_with(2)
      end if
   end function positive_argument

   !> End with exit status `status` after flushing the output, without a backtrace.
   subroutine stop_with(status)
      integer, intent(in) :: status
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(status, c_int))
   end subroutine stop_with

   subroutine run_case(title, nshr, props)
      character(len=*), intent(in) :: title
      integer, intent(in) :: nshr
      real(dp), intent(in) :: props(:)
      real(dp) :: ns_vumat, ns_copy, best_vumat, best_copy
      integer :: i, rep
      write (output_unit, '(a,a,a,i0,a,i0,a,i0,a)') 'VUMAT, ', title, ', mixed history: ', npoints, &
         ' points x ', NSWEEP, ' increments per measurement, best of ', nrepeat_used
      write (output_unit, '(a)') '  nblock   ns/point (vumat)   ns/point (plain copy)   ratio'
      do i = nblock_first, size(NBLOCK_SIZES)
         ! the best of NREPEAT measurements of each (the machine's other work only adds time)
         best_vumat = huge(1.0_dp)
         best_copy = huge(1.0_dp)
         do rep = 1, nrepeat_used
            call measure(NBLOCK_SIZES(i), npoints, nshr, props, ns_vumat, ns_copy)
            best_vumat = min(best_vumat, ns_vumat)
            best_copy = min(best_copy, ns_copy)
         end do
         write (output_unit, '(i8,f19.2,f24.2,f8.2)') NBLOCK_SIZES(i), best_vumat, best_copy, best_vumat/best_copy
      end do
   end subroutine run_case

   subroutine measure(nb, npoints, nshr, props, ns_vumat, ns_copy)
      integer, intent(in) :: nb, npoints, nshr
      real(dp), intent(in) :: props(:)
      real(dp), intent(out) :: ns_vumat, ns_copy
      real(dp), allocatable :: stress(:, :, :, :), state(:, :, :, :), ei(:, :, :), eie(:, :, :)
      real(dp), allocatable :: strain_inc(:, :, :, :), density(:, :), coord(:, :), char_length(:)
      real(dp), allocatable :: spin(:, :), temp(:), stretch(:, :), defgrad(:, :), field(:, :)
      real(dp) :: checksum, inc(2), angle
      character(len=80) :: cmname
      integer :: nblocks, ib, sweep, cur, j, ntens
      integer(int64) :: t0, t1, rate

      ntens = 1 + nshr
      nblocks = max(1, npoints/nb)
      allocate (stress(nb, ntens, nblocks, 0:1), state(nb, NSTATV_VUMAT, nblocks, 0:1))
      allocate (ei(nb, nblocks, 0:1), eie(nb, nblocks, 0:1), density(nb, nblocks))
      allocate (strain_inc(nb, ntens, nblocks, NSWEEP), coord(nb, 3), char_length(nb), spin(nb, nshr))
      allocate (temp(nb), stretch(nb, ntens), defgrad(nb, ntens + nshr), field(nb, 1))
      cmname = 'BENCH'
      coord = 0.0_dp
      char_length = 1.0_dp
      spin = 0.0_dp
      temp = 0.0_dp
      stretch = 1.0_dp
      defgrad = 1.0_dp
      field = 0.0_dp
      density = 2.0e-9_dp
      do sweep = 1, NSWEEP
         do ib = 1, nblocks
            do j = 1, nb
               inc = increment(sweep, real((ib - 1)*nb + j, dp)/real(nb*nblocks, dp))
               ! in 3-D the shear of each point in its own direction
               angle = 0.001_dp*real(j, dp)
               strain_inc(j, 1, ib, sweep) = inc(1)
               if (nshr == 1) then
                  strain_inc(j, 2, ib, sweep) = inc(2)
               else
                  strain_inc(j, 2:3, ib, sweep) = inc(2)*[cos(angle), sin(angle)]
               end if
            end do
         end do
      end do

      ! the VUMAT along the whole history (state restarted from zero)
      stress = 0.0_dp
      state = 0.0_dp
      ei = 0.0_dp
      eie = 0.0_dp
      call system_clock(t0, rate)
      cur = 0
      do sweep = 1, NSWEEP
         do ib = 1, nblocks
            call vumat(nb, 1, nshr, NSTATV_VUMAT, 1, size(props), 0, real(sweep, dp), real(sweep, dp), &
               1.0_dp, cmname, coord, char_length, props, density(:, ib), strain_inc(:, :, ib, sweep), spin, &
               temp, stretch, defgrad, field, stress(:, :, ib, cur), state(:, :, ib, cur), ei(:, ib, cur), &
               eie(:, ib, cur), temp, stretch, defgrad, field, stress(:, :, ib, 1 - cur), &
               state(:, :, ib, 1 - cur), ei(:, ib, 1 - cur), eie(:, ib, 1 - cur))
         end do
         cur = 1 - cur
      end do
      call system_clock(t1)
      ns_vumat = 1.0e9_dp*real(t1 - t0, dp)/real(rate, dp)/(real(NSWEEP, dp)*real(nb*nblocks, dp))
      checksum = sum(eie(:, :, cur))

      ! a plain copy of the same arrays
      stress = 0.0_dp
      state = 0.0_dp
      ei = 0.0_dp
      eie = 0.0_dp
      call system_clock(t0, rate)
      cur = 0
      do sweep = 1, NSWEEP
         do ib = 1, nblocks
            call plain_copy(nb, ntens, strain_inc(:, :, ib, sweep), stress(:, :, ib, cur), state(:, :, ib, cur), &
               ei(:, ib, cur), eie(:, ib, cur), stress(:, :, ib, 1 - cur), state(:, :, ib, 1 - cur), &
               ei(:, ib, 1 - cur), eie(:, ib, 1 - cur))
         end do
         cur = 1 - cur
      end do
      call system_clock(t1)
      ns_copy = 1.0e9_dp*real(t1 - t0, dp)/real(rate, dp)/(real(NSWEEP, dp)*real(nb*nblocks, dp))
      checksum = checksum + sum(stress(:, 1, :, cur))
      if (.not. (checksum > -huge(1.0_dp))) write (output_unit, '(a)') 'checksum not finite'

   end subroutine measure

   !> Strain increment (normal, tensor shear) of the mixed history at increment `sweep` for a
   !> point whose history is scaled by 0.5 + frac.
   pure function increment(sweep, frac) result(inc)
      integer, intent(in) :: sweep
      real(dp), intent(in) :: frac
      real(dp) :: inc(2)
      real(dp), parameter :: S_T(0:7) = [0.0_dp, 0.0_dp, 0.0_dp, 0.05_dp, 0.0_dp, 0.08_dp, -0.05_dp, 0.0_dp]
      integer :: seg
      seg = (sweep - 1)/NSUB
      inc(1) = 0.0_dp
      if (seg == 0) inc(1) = -0.005_dp*(0.5_dp + frac)/real(NSUB, dp)
      inc(2) = 0.5_dp*(0.5_dp + frac)*(S_T(seg + 1) - S_T(seg))/real(NSUB, dp)
   end function increment

   !> The memory traffic of a VUMAT without its arithmetic.
   subroutine plain_copy(nb, ntens, strain_inc, stress_old, state_old, ei_old, eie_old, stress_new, &
         state_new, ei_new, eie_new)
      integer, intent(in) :: nb, ntens
      real(dp), intent(in) :: strain_inc(nb, ntens), stress_old(nb, ntens), state_old(nb, NSTATV_VUMAT)
      real(dp), intent(in) :: ei_old(nb), eie_old(nb)
      real(dp), intent(out) :: stress_new(nb, ntens), state_new(nb, NSTATV_VUMAT), ei_new(nb), eie_new(nb)
      stress_new = stress_old + strain_inc
      state_new = state_old
      ei_new = ei_old
      eie_new = eie_old
   end subroutine plain_copy

end program bench_vumat
