!> Explicit interfaces of the Abaqus-style entry points of interphase, for Fortran hosts (the
!> single-point driver, the tests, a research FE code) that call `umat` or `vumat` directly.
module interphase_abaqus_interfaces
   use interphase_kinds, only: dp
   implicit none
   private
   public :: umat, vumat, uexternaldb, vexternaldb, interphase_host_message

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

      !> Abaqus/Explicit VUMAT (cohesive elements, RESPONSE=TRACTION SEPARATION, thickness 1).
      subroutine vumat(nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal, steptime, totaltime, &
            dt, cmname, coordmp, charlength, props, density, straininc, relspininc, tempold, &
            stretchold, defgradold, fieldold, stressold, stateold, enerinternold, enerinelasold, &
            tempnew, stretchnew, defgradnew, fieldnew, stressnew, statenew, enerinternnew, &
            enerinelasnew)
         import :: dp
         integer, intent(in) :: nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal
         real(dp), intent(in) :: steptime, totaltime, dt
         character(len=80), intent(in) :: cmname
         real(dp), intent(in) :: coordmp(nblock, *), charlength(nblock), props(nprops), density(nblock)
         real(dp), intent(in) :: straininc(nblock, ndir + nshr), relspininc(nblock, nshr), tempold(nblock)
         real(dp), intent(in) :: stretchold(nblock, ndir + nshr), defgradold(nblock, ndir + nshr + nshr)
         real(dp), intent(in) :: fieldold(nblock, nfieldv)
         real(dp), intent(in) :: stressold(nblock, ndir + nshr), stateold(nblock, nstatev)
         real(dp), intent(in) :: enerinternold(nblock), enerinelasold(nblock)
         real(dp), intent(in) :: tempnew(nblock), stretchnew(nblock, ndir + nshr)
         real(dp), intent(in) :: defgradnew(nblock, ndir + nshr + nshr), fieldnew(nblock, nfieldv)
         real(dp), intent(out) :: stressnew(nblock, ndir + nshr), statenew(nblock, nstatev)
         real(dp), intent(out) :: enerinternnew(nblock), enerinelasnew(nblock)
      end subroutine vumat

      !> Abaqus/Standard UEXTERNALDB: loads the custom RVE table (INTERPHASE_TABLE) and the
      !> R-curve (INTERPHASE_RCURVE) at LOP = 0 and 4.
      subroutine uexternaldb(lop, lrestart, time, dtime, kstep, kinc)
         import :: dp
         integer, intent(in) :: lop, lrestart, kstep, kinc
         real(dp), intent(in) :: time(2), dtime
      end subroutine uexternaldb

      !> Abaqus/Explicit VEXTERNALDB: the same loads at lOp = 0 (start of the analysis).
      subroutine vexternaldb(lop, i_array, niarray, r_array, nrarray)
         import :: dp
         integer, intent(in) :: lop, niarray, nrarray
         integer, intent(in) :: i_array(niarray)
         real(dp), intent(in) :: r_array(nrarray)
      end subroutine vexternaldb

      !> Message hook every adapter calls on failure; each host links exactly one
      !> implementation (Abaqus: its error routine; the driver: standard error; tests: a
      !> recorder). `severity` is one of the SEVERITY_* codes of `interphase_status`.
      subroutine interphase_host_message(severity, message)
         integer, intent(in) :: severity
         character(len=*), intent(in) :: message
      end subroutine interphase_host_message
   end interface

end module interphase_abaqus_interfaces
