!> Abaqus/Explicit VEXTERNALDB: at the start of the analysis (lOp = 0, also the start of a
!> restarted analysis) it loads the custom RVE table named by the environment variable
!> INTERPHASE_TABLE and the tabulated R-curve named by INTERPHASE_RCURVE
!> (interphase_external_data), before any VUMAT call. Abaqus/Explicit does not call UEXTERNALDB:
!> a VUMAT run that needs these files links this routine. Without the variables the built-in
!> table serves. A file that is loaded already is not read again. A file that cannot be read or
!> fails its checks is a fatal error (through interphase_host_message, i.e. XPLB_ABQERR) naming
!> the file, the line and the failed check.
subroutine vexternaldb(lop, i_array, niarray, r_array, nrarray)
   use interphase_kinds, only: dp
   use interphase_external_data, only: load_external_data
   implicit none
   integer, intent(in) :: lop                 !! 0 start of the analysis, 1 start of a step, ...
   integer, intent(in) :: niarray, nrarray    !! sizes of i_array and r_array
   integer, intent(in) :: i_array(niarray)    !! nodes, elements, step, increment, ... (unused)
   real(dp), intent(in) :: r_array(nrarray)   !! times (unused)

   !> lOp of the start of the analysis.
   integer, parameter :: LOP_START_ANALYSIS = 0
   logical :: ok

   if (lop /= LOP_START_ANALYSIS) return
   call load_external_data('VEXTERNALDB', ok)
end subroutine vexternaldb
