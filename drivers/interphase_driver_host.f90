!> The message hook of the drivers (interphase-point, interphase-calibrate,
!> interphase-check-deck): like `interphase::host_stderr` it writes every adapter message to
!> standard error and never stops; in addition it keeps the last fatal message, so that the
!> driver can tell a setup error found during the run (e.g. a tabulated R-curve that does not
!> cover the damage reached) from a failed update that a smaller increment may cure, and report
!> the real reason instead of halving the step. The drivers are single-threaded programs: the
!> module data written here is theirs, not the library's.
module interphase_driver_host
   implicit none
   private
   public :: reset_fatal_message, fatal_message_reported, last_fatal_message, driver_host_message

   logical :: fatal_seen = .false.
   character(len=:), allocatable :: fatal_text

contains

   !> Forget the fatal message recorded so far (before a UMAT call whose outcome is judged).
   subroutine reset_fatal_message()
      fatal_seen = .false.
      fatal_text = ''
   end subroutine reset_fatal_message

   !> Whether a fatal message arrived since the last reset.
   logical function fatal_message_reported()
      fatal_message_reported = fatal_seen
   end function fatal_message_reported

   !> The last fatal message ('' when none arrived since the last reset).
   function last_fatal_message() result(text)
      character(len=:), allocatable :: text
      text = ''
      if (fatal_seen) text = fatal_text
   end function last_fatal_message

   !> What the hook below does with a message: standard error ('interphase: <severity>:
   !> <message>', as src/abaqus/host_stderr.f90 writes it), and the record of a fatal one.
   subroutine driver_host_message(severity, message)
      use, intrinsic :: iso_fortran_env, only: error_unit
      use interphase_status, only: SEVERITY_FATAL, severity_label
      integer, intent(in) :: severity            !! one of the SEVERITY_* codes
      character(len=*), intent(in) :: message    !! what went wrong, with the offending value
      write (error_unit, '(a)') 'interphase: '//severity_label(severity)//': '//trim(message)
      if (severity /= SEVERITY_FATAL) return
      fatal_seen = .true.
      fatal_text = trim(message)
   end subroutine driver_host_message

end module interphase_driver_host

!> The hook the adapters call (interphase_abaqus_interfaces), for the drivers.
subroutine interphase_host_message(severity, message)
   use interphase_driver_host, only: driver_host_message
   implicit none
   integer, intent(in) :: severity             !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message     !! what went wrong
   call driver_host_message(severity, message)
end subroutine interphase_host_message
