!> Explicit interfaces of the Abaqus-style entry points of interphase, for Fortran hosts (the
!> single-point driver, the tests, a research FE code) that call `umat` directly.
module interphase_abaqus_interfaces
   use interphase_kinds, only: dp
   implicit none
   private
   public :: umat, interphase_host_message

   interface
      !> Abaqus/Standard UMAT (cohesive elements, RESPONSE=TRACTION SEPARATION).
      subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
            stran, dstran, time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, &
            nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, &
            layer, kspt, jstep, kinc)
         import :: dp
         integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
         integer, intent(in) :: jstep(4)
         real(dp), intent(inout) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens)
         real(dp), intent(inout) :: sse, spd, scd, rpl, pnewdt
         real(dp), intent(inout) :: ddsddt(ntens), drplde(ntens), drpldt
         real(dp), intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp
         real(dp), intent(in) :: predef(*), dpred(*), props(nprops), coords(3), drot(3, 3)
         real(dp), intent(in) :: celent, dfgrd0(3, 3), dfgrd1(3, 3)
         character(len=80), intent(in) :: cmname
      end subroutine umat

      !> Message hook every adapter calls on failure; each host links exactly one
      !> implementation (Abaqus: its error routine; the driver: standard error; tests: a
      !> recorder). `severity` is one of the SEVERITY_* codes of `interphase_status`.
      subroutine interphase_host_message(severity, message)
         integer, intent(in) :: severity
         character(len=*), intent(in) :: message
      end subroutine interphase_host_message
   end interface

end module interphase_abaqus_interfaces
