!> Timing of the one-file Abaqus/Explicit source (make-user-file.sh --explicit) compiled alone, as
!> Abaqus compiles a user subroutine: one block of 4096 points of the simplified model (2-D, the
!> paper's Table 1 data, displacement-driven damage) under a constant small compression and a
!> cyclic shear (4 increments forward, 4 back, a different amplitude per point), the block's arrays
!> (~0.7 MB) held in the L2 cache; 250 cycles (2000 increments), the best of 5 runs.
!> Prints ns per point update and a few state figures to check that the run did something.
!> Built and run by bench-user-file.sh, after the one-file source (whose modules it uses);
!> XPLB_ABQERR (Abaqus's message utility) is stubbed below.
program bench_user_file
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use interphase_kinds, only: dp
   use interphase_abaqus_interfaces, only: vumat
   implicit none

   !> Points per block, state variables (docs/abaqus.md), increments per cycle, cycles, runs.
   integer, parameter :: NB = 4096, NSV = 9, NINC = 8, NCYCLE = 250, NRUN = 5
   !> The simplified model with the paper's Table 1 data (PROPS as in docs/abaqus.md).
   real(dp), parameter :: PROPS(9) = [1.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, 0.04_dp, 0.00072_dp, 0.06_dp, &
      544000.0_dp/1127.0_dp, 32000.0_dp/161.0_dp]
   !> Normal strain increment (compression) and tensor shear strain increment amplitude (-).
   real(dp), parameter :: E_N = -1.0e-5_dp, E_T = 4.0e-4_dp
   !> Density (tonne/mm^3).
   real(dp), parameter :: RHO = 2.0e-9_dp

   real(dp) :: strain(NB, 2, NINC), stress(NB, 2, 0:1), state(NB, NSV, 0:1), ei(NB, 0:1), eie(NB, 0:1)
   real(dp) :: density(NB), coord(NB, 3), charl(NB), spin(NB, 1), temp(NB), stretch(NB, 2)
   real(dp) :: defgrad(NB, 3), field(NB, 1), best, ns
   integer(int64) :: t0, t1, rate
   integer :: j, i, icycle, irun, cur
   character(len=80) :: cmname

   cmname = 'BENCH-USER-FILE'
   coord = 0.0_dp
   charl = 1.0_dp
   spin = 0.0_dp
   temp = 0.0_dp
   stretch = 1.0_dp
   defgrad = 1.0_dp
   field = 0.0_dp
   density = RHO
   do i = 1, NINC
      do j = 1, NB
         strain(j, 1, i) = E_N
         strain(j, 2, i) = merge(1.0_dp, -1.0_dp, i <= NINC/2)*E_T*(0.5_dp + real(j, dp)/real(NB, dp))
      end do
   end do

   best = huge(1.0_dp)
   cur = 0
   do irun = 1, NRUN
      stress = 0.0_dp
      state = 0.0_dp
      ei = 0.0_dp
      eie = 0.0_dp
      cur = 0
      call system_clock(t0, rate)
      do icycle = 1, NCYCLE
         do i = 1, NINC
            call vumat(NB, 1, 1, NSV, 1, size(PROPS), 0, 1.0_dp, 1.0_dp, 1.0e-3_dp, cmname, coord, charl, &
               PROPS, density, strain(:, :, i), spin, temp, stretch, defgrad, field, stress(:, :, cur), &
               state(:, :, cur), ei(:, cur), eie(:, cur), temp, stretch, defgrad, field, stress(:, :, 1 - cur), &
               state(:, :, 1 - cur), ei(:, 1 - cur), eie(:, 1 - cur))
            cur = 1 - cur
         end do
      end do
      call system_clock(t1)
      ns = 1.0e9_dp*real(t1 - t0, dp)/real(rate, dp)/real(NB*NINC*NCYCLE, dp)
      best = min(best, ns)
   end do
   write (output_unit, '(a,f9.2,a,f5.3,a,f5.3,a)') 'ns per point update:', best, '  (check: largest D = ', &
      maxval(state(:, 1, cur)), ', share of damaged points = ', &
      real(count(state(:, 1, cur) > 0.0_dp), dp)/real(NB, dp), ')'
end program bench_user_file

!> Stand-in for Abaqus/Explicit's message utility: prints the message.
subroutine xplb_abqerr(lop, string, intv, realv, charv)
   use, intrinsic :: iso_fortran_env, only: output_unit, dp => real64
   implicit none
   integer, intent(in) :: lop
   character(len=*), intent(in) :: string
   integer, intent(in) :: intv(*)
   real(dp), intent(in) :: realv(*)
   character(len=8), intent(in) :: charv(*)
   write (output_unit, '(a,i0,a,a)') 'XPLB_ABQERR(', lop, '): ', string
end subroutine xplb_abqerr
