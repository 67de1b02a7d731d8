!> The text and level of a message for Abaqus's message utilities (STDB_ABQERR in
!> Abaqus/Standard, XPLB_ABQERR in Abaqus/Explicit), shared by the two host hooks
!> host_abaqus_standard.f90 and host_abaqus_explicit.f90, which differ only in the utility they
!> call (Abaqus compiles one of them into the user file).
!>
!> LOP: 1 information, -1 warning, -3 error that terminates the analysis. The utility's STRING is
!> a format in which %I, %R and %S take values from its INTV, REALV and CHARV arrays; interphase
!> puts every value into the text itself, so a '%' in the message is written as 'pct' and the
!> value arrays are dummies. Abaqus limits STRING to 500 characters.
module interphase_abaqus_message
   use interphase_status, only: SEVERITY_INFO, SEVERITY_WARNING, SEVERITY_FATAL
   implicit none
   private
   public :: ABAQUS_MESSAGE_LEN, abaqus_message

   !> Longest message Abaqus accepts.
   integer, parameter :: ABAQUS_MESSAGE_LEN = 500
   !> Abaqus message levels.
   integer, parameter :: LOP_INFO = 1, LOP_WARNING = -1, LOP_FATAL = -3

contains

   !> The Abaqus level and text(1:length) for a message of interphase.
   pure subroutine abaqus_message(severity, message, lop, text, length)
      integer, intent(in) :: severity                         !! one of the SEVERITY_* codes
      character(len=*), intent(in) :: message                 !! what went wrong
      integer, intent(out) :: lop                             !! Abaqus message level
      character(len=ABAQUS_MESSAGE_LEN), intent(out) :: text  !! 'interphase: ' + message
      integer, intent(out) :: length                          !! characters of text to pass
      integer :: i

      select case (severity)
      case (SEVERITY_INFO)
         lop = LOP_INFO
      case (SEVERITY_FATAL)
         lop = LOP_FATAL
      case (SEVERITY_WARNING)
         lop = LOP_WARNING
      case default
         lop = LOP_WARNING
      end select

      ! copy the message, writing '%' (a format character for Abaqus) as 'pct'
      text = 'interphase: '
      length = len_trim(text) + 1
      do i = 1, len_trim(message)
         if (message(i:i) == '%') then
            if (length + 3 > ABAQUS_MESSAGE_LEN) exit
            text(length + 1:length + 3) = 'pct'
            length = length + 3
         else
            if (length + 1 > ABAQUS_MESSAGE_LEN) exit
            text(length + 1:length + 1) = message(i:i)
            length = length + 1
         end if
      end do
   end subroutine abaqus_message

end module interphase_abaqus_message
