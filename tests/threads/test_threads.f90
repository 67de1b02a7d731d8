!> Thread safety of the Abaqus entry points: every OpenMP thread calls `umat` and `vumat` at the
!> same time (all threads start together after a barrier and each takes every nthreads-th item),
!> each on its own points, each point along the paper's mixed history with its own scaling and
!> direction; every traction, state variable and energy after every increment must be
!> bit-identical to a serial run, and every thread must have worked.
!> The UMAT points cycle through the simplified model, the micromechanical model on the built-in
!> table and on a custom table, and the fracture-mechanics law on a tabulated R-curve (the last
!> two read the data loaded at start-up), in 2-D and 3-D; the VUMAT blocks through the vectorised
!> simplified update in 2-D and 3-D and the micromechanical model on the custom table (point
!> update). The custom table (tables/paper-resolution.dat, through INTERPHASE_SOURCE_DIR) and an
!> R-curve written by the test are loaded before the parallel runs, as UEXTERNALDB would.
!> Run with OMP_NUM_THREADS >= 4.
program test_threads
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   use omp_lib, only: omp_get_max_threads, omp_get_thread_num, omp_get_num_threads, omp_get_wtime
   use interphase_kinds, only: dp
   use interphase_layout, only: NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, &
      NSTATV_REQUIRED, NSTATV_VUMAT, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, RCURVE_TABULATED, PROP_DAMAGE_LAW, LFM_D0, LFM_RCURVE, &
      LFM_GC_I, LFM_GC_II
   use interphase_abaqus_interfaces, only: umat, vumat
   use interphase_external_data, only: load_table_file, load_rcurve_file
   implicit none

   !> UMAT points (odd ones 2-D, even ones 3-D) and VUMAT blocks of NB points (2-D).
   integer, parameter :: NPOINTS = 48, NBLOCKS = 12, NB = 8
   !> Increments per segment of the mixed history; number of increments.
   integer, parameter :: NSUB = 40, NINC = 7*NSUB
   !> Values recorded per UMAT point and increment: stress(3), statev(4), sse, spd.
   integer, parameter :: NREC_UMAT = 9
   !> Values recorded per VUMAT point and increment: stress(3), state(8), two energies.
   integer, parameter :: NREC_VUMAT = 3 + NSTATV_VUMAT + 2
   !> Repetitions of the parallel run, and passes over its items per repetition (every pass
   !> checked; the passes keep the threads inside the library together for a while).
   integer, parameter :: NREPEAT = 3, NPASS = 10
   !> Largest number of threads recorded.
   integer, parameter :: MAX_THREADS = 64
   !> Material variants of the UMAT points and VUMAT blocks (see the header).
   integer, parameter :: SIMPLIFIED = 0, MICRO_BUILT_IN = 1, MICRO_CUSTOM = 2, FRACTURE_TABULATED = 3

   real(dp), allocatable :: serial_umat(:, :, :), parallel_umat(:, :, :)
   real(dp), allocatable :: serial_vumat(:, :, :, :), parallel_vumat(:, :, :, :)
   integer, allocatable :: thread_of(:)
   real(dp) :: t_start(0:MAX_THREADS - 1), t_end(0:MAX_THREADS - 1), overlap
   integer :: k, repeat, nthreads, used, failures, tid, nteam, pass, mismatches
   logical :: ok
   character(len=4096) :: source_dir

   allocate (serial_umat(NREC_UMAT, 0:NINC, NPOINTS), parallel_umat(NREC_UMAT, 0:NINC, NPOINTS))
   allocate (serial_vumat(NREC_VUMAT, NB, 0:NINC, NBLOCKS), parallel_vumat(NREC_VUMAT, NB, 0:NINC, NBLOCKS))
   allocate (thread_of(NPOINTS + NBLOCKS))

   ! the start-up loads (UEXTERNALDB's work), before any update
   call get_environment_variable('INTERPHASE_SOURCE_DIR', source_dir)
   call load_table_file('TEST', trim(source_dir)//'/tables/paper-resolution.dat', ok)
   if (.not. ok) error stop 'test_threads: the custom table could not be loaded (INTERPHASE_SOURCE_DIR?)'
   call write_rcurve('threads_rcurve.txt')
   call load_rcurve_file('TEST', 'threads_rcurve.txt', ok)
   if (.not. ok) error stop 'test_threads: the R-curve could not be loaded'

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
      t_start = 0.0_dp
      t_end = 0.0_dp
      nteam = 0
      ! every thread takes every nteam-th item, all starting together after the barrier
      mismatches = 0
      !$omp parallel default(shared) private(k, tid, pass) reduction(+:mismatches)
      tid = omp_get_thread_num()
      !$omp single
      nteam = omp_get_num_threads()
      !$omp end single
      !$omp barrier
      t_start(min(tid, MAX_THREADS - 1)) = omp_get_wtime()
      do pass = 1, NPASS
         do k = tid + 1, NPOINTS + NBLOCKS, nteam
            thread_of(k) = tid
            if (k <= NPOINTS) then
               call run_umat_point(k, parallel_umat(:, :, k))
               if (.not. same_bits(reshape(serial_umat(:, :, k), [size(serial_umat(:, :, k))]), &
                  reshape(parallel_umat(:, :, k), [size(parallel_umat(:, :, k))]))) mismatches = mismatches + 1
            else
               call run_vumat_block(k - NPOINTS, parallel_vumat(:, :, :, k - NPOINTS))
               if (.not. same_bits(reshape(serial_vumat(:, :, :, k - NPOINTS), [size(serial_vumat(:, :, :, 1))]), &
                  reshape(parallel_vumat(:, :, :, k - NPOINTS), [size(parallel_vumat(:, :, :, 1))]))) &
                  mismatches = mismatches + 1
            end if
         end do
      end do
      t_end(min(tid, MAX_THREADS - 1)) = omp_get_wtime()
      !$omp end parallel
      if (mismatches > 0) then
         write (error_unit, '(a,i0,a,i0,a)') 'FAILED: repetition ', repeat, ': ', mismatches, &
            ' point or block histories differ from the serial run'
         failures = failures + 1
      end if
      used = count_distinct(thread_of)
      if (used /= nteam .or. nteam /= nthreads) then
         write (error_unit, '(a,i0,a,i0,a,i0,a)') 'FAILED: repetition ', repeat, ': ', used, ' of ', nteam, &
            ' threads worked'
         failures = failures + 1
      end if
      ! the time all threads were inside the library together (information: the OS schedules them)
      overlap = minval(t_end(0:min(nteam, MAX_THREADS) - 1)) - maxval(t_start(0:min(nteam, MAX_THREADS) - 1))
      write (output_unit, '(a,i0,a,f8.4,a)') 'repetition ', repeat, ': all threads inside the library together for ', &
         max(overlap, 0.0_dp), ' s'
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
   end if
   if (failures > 0) then
      write (error_unit, '(i0,a)') failures, ' check(s) failed'
      error stop 1
   end if
   write (output_unit, '(a,i0,a,i0,a)') 'bit-identical to the serial run in all ', NREPEAT, ' parallel repetitions of ', &
      NPASS, ' passes'

contains

   function paper_props() result(props)
      real(dp) :: props(NPROPS_SIMPLIFIED)
      props = [1.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, 0.04_dp, 0.00072_dp, 0.06_dp, &
         544000.0_dp/1127.0_dp, 32000.0_dp/161.0_dp]
   end function paper_props

   !> PROPS(1:nprops) of a material variant (the paper's Table 1 damage data throughout). Not the
   !> test-support builders: that library carries the tests' message recorder, which would take
   !> the place of host_stderr's interphase_host_message in this program.
   subroutine variant_props(variant, props, nprops)
      integer, intent(in) :: variant
      real(dp), intent(out) :: props(NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA)
      integer, intent(out) :: nprops
      props = 0.0_dp
      select case (variant)
      case (MICRO_BUILT_IN, MICRO_CUSTOM)
         nprops = NPROPS_MICROMECHANICAL
         props(1:nprops) = [real(MODEL_MICROMECHANICAL, dp), real(DAMAGE_DISPLACEMENT, dp), 0.75_dp, 0.00044_dp, &
            0.04_dp, 0.00072_dp, 0.06_dp, real(TABLE_DEFAULT_CODE, dp)]
         if (variant == MICRO_CUSTOM) props(nprops) = real(TABLE_CUSTOM_CODE, dp)
      case (FRACTURE_TABULATED)
         nprops = NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA
         props(1:NPROPS_SIMPLIFIED) = paper_props()
         props(PROP_DAMAGE_LAW) = real(DAMAGE_FRACTURE, dp)
         props(NPROPS_SIMPLIFIED + LFM_D0) = 0.05_dp
         props(NPROPS_SIMPLIFIED + LFM_RCURVE) = real(RCURVE_TABULATED, dp)
         props(NPROPS_SIMPLIFIED + LFM_GC_I) = 0.0_dp
         props(NPROPS_SIMPLIFIED + LFM_GC_II) = 0.0_dp
      case default
         nprops = NPROPS_SIMPLIFIED
         props(1:nprops) = paper_props()
      end select
   end subroutine variant_props

   !> A rising R-curve (D, G_cI, G_cII in N/mm) for the fracture-mechanics points.
   subroutine write_rcurve(path)
      character(len=*), intent(in) :: path
      integer :: unit
      open (newunit=unit, file=path, status='replace', action='write')
      write (unit, '(a)') '# D  G_cI (N/mm)  G_cII (N/mm)'
      write (unit, '(a)') '0.0  0.004  0.004'
      write (unit, '(a)') '0.5  0.006  0.007'
      write (unit, '(a)') '1.0  0.008  0.010'
      close (unit)
   end subroutine write_rcurve

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

   !> The whole history of UMAT point k (material variant mod(k - 1, 4); 2-D for the first four
   !> of every eight points, 3-D for the others); rec(:, i) after increment i.
   subroutine run_umat_point(k, rec)
      integer, intent(in) :: k
      real(dp), intent(out) :: rec(NREC_UMAT, 0:NINC)
      real(dp) :: stress(3), statev(NSTATV_REQUIRED), sse, spd, scd, rpl, pnewdt
      real(dp), allocatable :: ddsdde(:, :)
      real(dp) :: ddsddt(3), drplde(3), drpldt, stran(3), dstran(3), time(2), predef(1), dpred(1)
      real(dp) :: coords(3), drot(3, 3), dfgrd(3, 3)
      real(dp) :: props(NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA)
      character(len=80) :: cmname
      integer :: i, n, nprops
      n = 2 + mod((k - 1)/4, 2)
      allocate (ddsdde(n, n))
      call variant_props(mod(k - 1, 4), props, nprops)
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
            NSTATV_REQUIRED, props(1:nprops), nprops, coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, &
            k, 1, 1, 1, [1, 1, 0, 0], i)
         if (pnewdt < 1.0_dp) error stop 'test_threads: a UMAT update failed (see the message above)'
         stran(1:n) = stran(1:n) + dstran(1:n)
         rec(1:3, i) = stress
         rec(4:7, i) = statev
         rec(8, i) = sse
         rec(9, i) = spd
      end do
   end subroutine run_umat_point

   !> The whole history of VUMAT block b: the simplified model in 2-D (b odd) or 3-D (b = 2, 6,
   !> ...), the micromechanical model on the custom table in 2-D (b = 4, 8, ...); rec(:, j, i)
   !> for its point j after increment i (the third traction 0 in 2-D).
   subroutine run_vumat_block(b, rec)
      integer, intent(in) :: b
      real(dp), intent(out) :: rec(NREC_VUMAT, NB, 0:NINC)
      real(dp) :: stress(NB, 3), state(NB, NSTATV_VUMAT), ei(NB), eie(NB), density(NB)
      real(dp) :: stress_new(NB, 3), state_new(NB, NSTATV_VUMAT), ei_new(NB), eie_new(NB)
      real(dp) :: strain_inc(NB, 3), coord(NB, 3), char_length(NB), spin(NB, 2), temp(NB)
      real(dp) :: stretch(NB, 3), defgrad(NB, 5), field(NB, 1), s_old(3), s_new(3)
      real(dp) :: props(NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA)
      character(len=80) :: cmname
      integer :: i, j, id, nt, ntens, nprops
      stress = 0.0_dp
      stress_new = 0.0_dp
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
      nt = 1
      if (mod(b, 4) == 2) nt = 2
      ntens = 1 + nt
      if (mod(b, 4) == 0) then
         call variant_props(MICRO_CUSTOM, props, nprops)
      else
         call variant_props(SIMPLIFIED, props, nprops)
      end if
      do i = 1, NINC
         do j = 1, NB
            id = NPOINTS + (b - 1)*NB + j
            s_old(1:ntens) = separation(id, i - 1, ntens)
            s_new(1:ntens) = separation(id, i, ntens)
            strain_inc(j, 1) = s_new(1) - s_old(1)
            strain_inc(j, 2:ntens) = 0.5_dp*(s_new(2:ntens) - s_old(2:ntens))
         end do
         call vumat(NB, 1, nt, NSTATV_VUMAT, 1, nprops, 0, real(i, dp), real(i, dp), 1.0_dp, &
            cmname, coord, char_length, props(1:nprops), density, strain_inc(:, 1:ntens), spin(:, 1:nt), temp, &
            stretch(:, 1:ntens), defgrad(:, 1:ntens + nt), field, stress(:, 1:ntens), state, ei, eie, temp, &
            stretch(:, 1:ntens), defgrad(:, 1:ntens + nt), field, stress_new(:, 1:ntens), state_new, ei_new, eie_new)
         stress(:, 1:ntens) = stress_new(:, 1:ntens)
         state = state_new
         ei = ei_new
         eie = eie_new
         if (any(state(:, NSTATV_VUMAT) > 0.5_dp)) error stop 'test_threads: a VUMAT point failed'
         do j = 1, NB
            rec(1:ntens, j, i) = stress(j, 1:ntens)
            rec(4:3 + NSTATV_VUMAT, j, i) = state(j, :)
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
