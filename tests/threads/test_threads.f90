!> Thread safety of the Abaqus entry points: every OpenMP thread calls `umat` (2-D and 3-D points)
!> and `vumat` (2-D blocks) at the same time, each on its own points, each point along the paper's
!> mixed history with its own scaling and direction; every traction, state variable and energy
!> after every increment must be bit-identical to a serial run. Run with OMP_NUM_THREADS >= 4.
program test_threads
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   use omp_lib, only: omp_get_max_threads, omp_get_thread_num
   use interphase_kinds, only: dp
   use interphase_layout, only: NPROPS_SIMPLIFIED, NSTATV_REQUIRED, NSTATV_VUMAT
   use interphase_abaqus_interfaces, only: umat, vumat
   implicit none

   !> UMAT points (odd ones 2-D, even ones 3-D) and VUMAT blocks of NB points (2-D).
   integer, parameter :: NPOINTS = 48, NBLOCKS = 12, NB = 8
   !> Increments per segment of the mixed history; number of increments.
   integer, parameter :: NSUB = 40, NINC = 7*NSUB
   !> Values recorded per UMAT point and increment: stress(3), statev(4), sse, spd.
   integer, parameter :: NREC_UMAT = 9
   !> Values recorded per VUMAT point and increment: stress(2), state(8), two energies.
   integer, parameter :: NREC_VUMAT = 2 + NSTATV_VUMAT + 2
   !> Repetitions of the parallel run.
   integer, parameter :: NREPEAT = 3

   real(dp), allocatable :: serial_umat(:, :, :), parallel_umat(:, :, :)
   real(dp), allocatable :: serial_vumat(:, :, :, :), parallel_vumat(:, :, :, :)
   integer, allocatable :: thread_of(:)
   integer :: k, repeat, nthreads, used, failures

   allocate (serial_umat(NREC_UMAT, 0:NINC, NPOINTS), parallel_umat(NREC_UMAT, 0:NINC, NPOINTS))
   allocate (serial_vumat(NREC_VUMAT, NB, 0:NINC, NBLOCKS), parallel_vumat(NREC_VUMAT, NB, 0:NINC, NBLOCKS))
   allocate (thread_of(NPOINTS + NBLOCKS))

   do k = 1, NPOINTS
      call run_umat_point(k, serial_umat(:, :, k))
   end do
   do k = 1, NBLOCKS
      call run_vumat_block(k, serial_vumat(:, :, :, k))
   end do

   nthreads = omp_get_max_threads()
   failures = 0
   used = 0
   do repeat = 1, NREPEAT
      parallel_umat = -1.0_dp
      parallel_vumat = -1.0_dp
      thread_of = -1
      !$omp parallel do schedule(dynamic, 1) default(shared) private(k)
      do k = 1, NPOINTS + NBLOCKS
         thread_of(k) = omp_get_thread_num()
         if (k <= NPOINTS) then
            call run_umat_point(k, parallel_umat(:, :, k))
         else
            call run_vumat_block(k - NPOINTS, parallel_vumat(:, :, :, k - NPOINTS))
         end if
      end do
      !$omp end parallel do
      used = max(used, count_distinct(thread_of))
      if (.not. same_bits(reshape(serial_umat, [size(serial_umat)]), reshape(parallel_umat, [size(parallel_umat)]))) then
         write (error_unit, '(a,i0,a)') 'FAILED: repetition ', repeat, ': umat results differ from the serial run'
         failures = failures + 1
      end if
      if (.not. same_bits(reshape(serial_vumat, [size(serial_vumat)]), reshape(parallel_vumat, [size(parallel_vumat)]))) then
         write (error_unit, '(a,i0,a)') 'FAILED: repetition ', repeat, ': vumat results differ from the serial run'
         failures = failures + 1
      end if
   end do

   write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'threads: ', nthreads, ' available, ', used, &
      ' used; ', NPOINTS, ' umat points and ', NBLOCKS, ' vumat blocks of ', NB, ' points'
   if (nthreads < 2) then
      write (error_unit, '(a)') 'FAILED: only one OpenMP thread: set OMP_NUM_THREADS >= 2 (the test sets 4)'
      failures = failures + 1
   else if (used < 2) then
      write (error_unit, '(a)') 'FAILED: the parallel loop ran on one thread only'
      failures = failures + 1
   end if
   if (failures > 0) then
      write (error_unit, '(i0,a)') failures, ' check(s) failed'
      error stop 1
   end if
   write (output_unit, '(a,i0,a)') 'bit-identical to the serial run in all ', NREPEAT, ' parallel repetitions'

contains

   function paper_props() result(props)
      real(dp) :: props(NPROPS_SIMPLIFIED)
      props = [1.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, 0.04_dp, 0.00072_dp, 0.06_dp, &
         544000.0_dp/1127.0_dp, 32000.0_dp/161.0_dp]
   end function paper_props

   !> Separation of history `id` after increment i: the mixed history (Table 4) scaled by
   !> 0.6 + 0.9 id/(NPOINTS + NBLOCKS*NB), the shear along the angle 0.37 id in 3-D.
   pure function separation(id, i, ntens) result(s)
      integer, intent(in) :: id, i, ntens
      real(dp) :: s(ntens)
      real(dp), parameter :: S_T(0:7) = [0.0_dp, 0.0_dp, 0.0_dp, 0.05_dp, 0.0_dp, 0.08_dp, -0.05_dp, 0.0_dp]
      real(dp) :: scale, st, frac
      integer :: seg
      scale = 0.6_dp + 0.9_dp*real(id, dp)/real(NPOINTS + NBLOCKS*NB, dp)
      if (i == 0) then
         s = 0.0_dp
         return
      end if
      seg = (i - 1)/NSUB
      frac = real(i - seg*NSUB, dp)/real(NSUB, dp)
      st = scale*(S_T(seg) + frac*(S_T(seg + 1) - S_T(seg)))
      s(1) = -0.005_dp*scale
      if (seg == 0) s(1) = -0.005_dp*scale*frac
      s(2) = st
      if (ntens == 3) then
         s(2) = st*cos(0.37_dp*real(id, dp))
         s(3) = st*sin(0.37_dp*real(id, dp))
      end if
   end function separation

   !> The whole history of UMAT point k; rec(:, i) after increment i.
   subroutine run_umat_point(k, rec)
      integer, intent(in) :: k
      real(dp), intent(out) :: rec(NREC_UMAT, 0:NINC)
      real(dp) :: stress(3), statev(NSTATV_REQUIRED), sse, spd, scd, rpl, pnewdt
      real(dp) :: ddsdde(2 + mod(k + 1, 2), 2 + mod(k + 1, 2))
      real(dp) :: ddsddt(3), drplde(3), drpldt, stran(3), dstran(3), time(2), predef(1), dpred(1)
      real(dp) :: coords(3), drot(3, 3), dfgrd(3, 3)
      character(len=80) :: cmname
      integer :: i, n
      n = 2 + mod(k + 1, 2)
      stress = 0.0_dp
      statev = 0.0_dp
      ddsdde = 0.0_dp
      sse = 0.0_dp
      spd = 0.0_dp
      scd = 0.0_dp
      rpl = 0.0_dp
      ddsddt = 0.0_dp
      drplde = 0.0_dp
      drpldt = 0.0_dp
      stran = 0.0_dp
      predef = 0.0_dp
      dpred = 0.0_dp
      coords = 0.0_dp
      drot = 0.0_dp
      dfgrd = 0.0_dp
      cmname = 'THREADS'
      rec = 0.0_dp
      do i = 1, NINC
         pnewdt = 1.0_dp
         time = real(i, dp)
         dstran(1:n) = separation(k, i, n) - stran(1:n)
         call umat(stress(1:n), statev, ddsdde, sse, spd, scd, rpl, ddsddt(1:n), drplde(1:n), &
            drpldt, stran(1:n), dstran(1:n), time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, cmname, 1, n - 1, n, &
            NSTATV_REQUIRED, paper_props(), NPROPS_SIMPLIFIED, coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, &
            k, 1, 1, 1, [1, 1, 0, 0], i)
         stran(1:n) = stran(1:n) + dstran(1:n)
         rec(1:3, i) = stress
         rec(4:7, i) = statev
         rec(8, i) = sse
         rec(9, i) = spd
      end do
   end subroutine run_umat_point

   !> The whole history of VUMAT block b (2-D); rec(:, j, i) for its point j after increment i.
   subroutine run_vumat_block(b, rec)
      integer, intent(in) :: b
      real(dp), intent(out) :: rec(NREC_VUMAT, NB, 0:NINC)
      real(dp) :: stress(NB, 2), state(NB, NSTATV_VUMAT), ei(NB), eie(NB), density(NB)
      real(dp) :: stress_new(NB, 2), state_new(NB, NSTATV_VUMAT), ei_new(NB), eie_new(NB)
      real(dp) :: strain_inc(NB, 2), coord(NB, 3), char_length(NB), spin(NB, 1), temp(NB)
      real(dp) :: stretch(NB, 2), defgrad(NB, 3), field(NB, 1), s_old(2), s_new(2)
      character(len=80) :: cmname
      integer :: i, j, id
      stress = 0.0_dp
      state = 0.0_dp
      ei = 0.0_dp
      eie = 0.0_dp
      density = 2.0e-9_dp
      coord = 0.0_dp
      char_length = 1.0_dp
      spin = 0.0_dp
      temp = 0.0_dp
      stretch = 1.0_dp
      defgrad = 1.0_dp
      field = 0.0_dp
      cmname = 'THREADS'
      rec = 0.0_dp
      do i = 1, NINC
         do j = 1, NB
            id = NPOINTS + (b - 1)*NB + j
            s_old = separation(id, i - 1, 2)
            s_new = separation(id, i, 2)
            strain_inc(j, 1) = s_new(1) - s_old(1)
            strain_inc(j, 2) = 0.5_dp*(s_new(2) - s_old(2))
         end do
         call vumat(NB, 1, 1, NSTATV_VUMAT, 1, NPROPS_SIMPLIFIED, 0, real(i, dp), real(i, dp), 1.0_dp, &
            cmname, coord, char_length, paper_props(), density, strain_inc, spin, temp, stretch, defgrad, &
            field, stress, state, ei, eie, temp, stretch, defgrad, field, stress_new, state_new, ei_new, eie_new)
         stress = stress_new
         state = state_new
         ei = ei_new
         eie = eie_new
         do j = 1, NB
            rec(1:2, j, i) = stress(j, :)
            rec(3:2 + NSTATV_VUMAT, j, i) = state(j, :)
            rec(NREC_VUMAT - 1, j, i) = ei(j)
            rec(NREC_VUMAT, j, i) = eie(j)
         end do
      end do
   end subroutine run_vumat_block

   !> Bitwise equality of two arrays (no floating-point comparison).
   pure logical function same_bits(a, b)
      real(dp), intent(in) :: a(:), b(:)
      same_bits = all(transfer(a, 0_int64, size(a)) == transfer(b, 0_int64, size(b)))
   end function same_bits

   !> Number of distinct non-negative values in v.
   pure integer function count_distinct(v)
      integer, intent(in) :: v(:)
      integer :: i
      count_distinct = 0
      do i = 0, maxval(v)
         if (any(v == i)) count_distinct = count_distinct + 1
      end do
   end function count_distinct

end program test_threads
