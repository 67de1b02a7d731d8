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
   public :: reset_fatal_message, fatal_message_reported, last_fatal_message, record_message

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

   !> Record a message; called by the hook below only.
   subroutine record_message(severity, message)
      use interphase_status, only: SEVERITY_FATAL
      integer, intent(in) :: severity
      character(len=*), intent(in) :: message
      if (severity /= SEVERITY_FATAL) return
      fatal_seen = .true.
      fatal_text = trim(message)
   end subroutine record_message

end module interphase_driver_host

!> The hook the adapters call (interphase_abaqus_interfaces): standard error, as
!> src/abaqus/host_stderr.f90 writes it, and the record above.
subroutine interphase_host_message(severity, message)
   use, intrinsic :: iso_fortran_env, only: error_unit
   use interphase_status, only: severity_label
   use interphase_driver_host, only: record_message
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value
   write (error_unit, '(a)') 'interphase: '//severity_label(severity)//': '//trim(message)
   call record_message(severity, message)
end subroutine interphase_host_message
