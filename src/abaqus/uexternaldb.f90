!> Abaqus/Standard UEXTERNALDB: at the start of an analysis (LOP = 0) and of a restart (LOP = 4)
!> it loads the custom RVE table named by the environment variable INTERPHASE_TABLE and the
!> tabulated R-curve named by INTERPHASE_RCURVE (interphase_external_data), before any material
!> point is updated. Without the variables the built-in table serves and nothing is loaded.
!> Abaqus calls UEXTERNALDB at these points before any UMAT call; a file that is loaded already
!> is not read again. A file that cannot be read or fails its checks is a fatal error (through
!> interphase_host_message) naming the file, the line and the failed check.
subroutine uexternaldb(lop, lrestart, time, dtime, kstep, kinc)
   use interphase_kinds, only: dp
   use interphase_external_data, only: load_external_data
   implicit none
   integer, intent(in) :: lop, lrestart, kstep, kinc
   real(dp), intent(in) :: time(2), dtime

   !> LOP values at which the files are loaded: start of the analysis, start of a restart.
   integer, parameter :: LOP_START = 0, LOP_RESTART = 4
   logical :: ok

   if (lop /= LOP_START .and. lop /= LOP_RESTART) return
   call load_external_data('UEXTERNALDB', ok)
end subroutine uexternaldb
