!> Test hook for ctest calculix_pnewdt_cutback (cutback-probe.sh), never shipped in a user library:
!> the entry point of libINTERPHASEPROBE.so, exported as UMAT. It calls interphase's umat
!> unchanged, except that in an increment longer than INTERPHASE_PROBE_FAIL_ABOVE (time units)
!> it passes a NaN normal strain increment, which the real umat refuses with a cut-back request
!> through PNEWDT. So the test sees how CalculiX treats interphase's request (no physical input
!> makes the UMAT ask for one).
subroutine umat_cutback_probe(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
      stran, dstran, time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, &
      nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, &
      layer, kspt, jstep, kinc)
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   implicit none
   integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
   integer, intent(in) :: jstep(4)
   double precision, intent(inout) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens)
   double precision, intent(inout) :: sse, spd, scd, rpl, pnewdt
   double precision, intent(inout) :: ddsddt(ntens), drplde(ntens), drpldt
   double precision, intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp
   double precision, intent(in) :: predef(*), dpred(*), props(nprops), coords(3), drot(3, 3)
   double precision, intent(in) :: celent, dfgrd0(3, 3), dfgrd1(3, 3)
   character(len=80), intent(in) :: cmname
   external :: umat
   double precision :: limit, probe(ntens)
   character(len=64) :: text
   integer :: length, ios
   limit = huge(1.0d0)
   call get_environment_variable('INTERPHASE_PROBE_FAIL_ABOVE', text, length)
   if (length > 0) then
      read (text(1:length), *, iostat=ios) limit
      if (ios /= 0) limit = huge(1.0d0)
   end if
   probe = dstran
   if (dtime > limit) probe(2) = ieee_value(probe(2), ieee_quiet_nan)
   call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
      stran, probe, time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, &
      nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, &
      layer, kspt, jstep, kinc)
end subroutine umat_cutback_probe
