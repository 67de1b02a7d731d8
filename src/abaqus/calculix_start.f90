!> CalculiX's start of an analysis: CalculiX calls no UEXTERNALDB, so libINTERPHASE.so
!> (examples/calculix/build-calculix.sh) calls this once when ccx opens it, through the load-time
!> hook of calculix_start.c, before any material point is updated. It loads the custom RVE table
!> named by INTERPHASE_TABLE and the tabulated R-curve named by INTERPHASE_RCURVE, as UEXTERNALDB
!> does in Abaqus (interphase_external_data); without the variables nothing is loaded. A file that
!> cannot be read or fails its checks is a fatal error: the CalculiX message hook ends the run
!> with the file, the line and the failed check.
subroutine interphase_calculix_start() bind(C, name='interphase_calculix_start')
   use interphase_external_data, only: load_external_data
   implicit none
   logical :: ok
   call load_external_data('CalculiX start', ok)
end subroutine interphase_calculix_start
