!> Message hook for stand-alone hosts (the single-point driver, benchmarks, research codes):
!> writes the adapter's message to standard error. It never stops the program: the caller sees
!> the failure through PNEWDT < 1 and decides.
subroutine interphase_host_message(severity, message)
   use, intrinsic :: iso_fortran_env, only: error_unit
   use interphase_status, only: severity_label
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value

   write (error_unit, '(a)') 'interphase: '//severity_label(severity)//': '//trim(message)
end subroutine interphase_host_message
