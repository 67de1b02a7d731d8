!> Test host for the adapters: records the last message (and the first since the last reset)
!> instead of printing or stopping.
module host_recorder
   implicit none
   private
   public :: recorder_reset
   integer, public :: recorded_count = 0
   integer, public :: recorded_severity = 0
   character(len=1024), public :: recorded_message = ''
   !> the first message since the last reset (a call that reports twice: both are seen)
   character(len=1024), public :: recorded_first_message = ''
contains
   subroutine recorder_reset()
      recorded_count = 0
      recorded_severity = 0
      recorded_message = ''
      recorded_first_message = ''
   end subroutine recorder_reset
end module host_recorder

!> The message hook as the tests link it.
subroutine interphase_host_message(severity, message)
   use host_recorder, only: recorded_count, recorded_severity, recorded_message, recorded_first_message
   implicit none
   integer, intent(in) :: severity
   character(len=*), intent(in) :: message
   recorded_count = recorded_count + 1
   recorded_severity = severity
   recorded_message = message
   if (recorded_count == 1) recorded_first_message = message
end subroutine interphase_host_message
