!> Message hook for stand-alone hosts (the single-point driver, benchmarks, research codes):
!> writes the adapter's message to standard error. It never stops the program: a UMAT caller sees
!> a failure through PNEWDT < 1, a VUMAT caller a failed point through its STATEV(9) = 1; a fatal
!> VUMAT error (the block held) only through this message: a host that must stop on it links its
!> own interphase_host_message instead (docs/abaqus.md).
subroutine interphase_host_message(severity, message)
   use, intrinsic :: iso_fortran_env, only: error_unit
   use interphase_status, only: severity_label
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value

   write (error_unit, '(a)') 'interphase: '//severity_label(severity)//': '//trim(message)
end subroutine interphase_host_message
