!> Message hook for Abaqus/Standard (UMAT): passes the adapter's message to Abaqus's message utility
!> STDB_ABQERR(LOP, STRING, INTV, REALV, CHARV), which writes it to the .msg file (and .sta)
!> with the job's other messages. LOP: 1 information, -1 warning, -3 error that terminates the
!> analysis. STRING is a format in which %I, %R and %S take values from INTV, REALV and CHARV;
!> interphase puts every value into the text itself, so a '%' in the message is written as
!> 'pct' and the value arrays are dummies. Abaqus limits STRING to 500 characters.
!>
!> Link exactly one hook: this file in an Abaqus/Standard build (the STDB_ABQERR symbol exists
!> only inside Abaqus; here the file is compiled but never linked), host_abaqus_explicit.f90 for the
!> other solver, host_stderr.f90 for stand-alone programs.
subroutine interphase_host_message(severity, message)
   use interphase_kinds, only: dp
   use interphase_status, only: SEVERITY_INFO, SEVERITY_WARNING, SEVERITY_FATAL
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value

   interface
      !> Abaqus/Standard (UMAT) message utility (provided by Abaqus).
      subroutine stdb_abqerr(lop, string, intv, realv, charv)
         import :: dp
         integer, intent(in) :: lop
         character(len=*), intent(in) :: string
         integer, intent(in) :: intv(*)
         real(dp), intent(in) :: realv(*)
         character(len=8), intent(in) :: charv(*)
      end subroutine stdb_abqerr
   end interface

   !> Longest message Abaqus accepts.
   integer, parameter :: ABAQUS_MESSAGE_LEN = 500
   !> Abaqus message levels.
   integer, parameter :: LOP_INFO = 1, LOP_WARNING = -1, LOP_FATAL = -3

   character(len=ABAQUS_MESSAGE_LEN) :: text
   integer :: intv(1), lop, i, n
   real(dp) :: realv(1)
   character(len=8) :: charv(1)

   select case (severity)
   case (SEVERITY_INFO)
      lop = LOP_INFO
   case (SEVERITY_WARNING)
      lop = LOP_WARNING
   case (SEVERITY_FATAL)
      lop = LOP_FATAL
   case default
      lop = LOP_WARNING
   end select

   ! copy the message, writing '%' (a format character for Abaqus) as 'pct'
   text = 'interphase: '
   n = len_trim(text) + 1
   do i = 1, len_trim(message)
      if (message(i:i) == '%') then
         if (n + 3 > ABAQUS_MESSAGE_LEN) exit
         text(n + 1:n + 3) = 'pct'
         n = n + 3
      else
         if (n + 1 > ABAQUS_MESSAGE_LEN) exit
         text(n + 1:n + 1) = message(i:i)
         n = n + 1
      end if
   end do
   intv = 0
   realv = 0.0_dp
   charv = ' '
   call stdb_abqerr(lop, text(1:n), intv, realv, charv)
end subroutine interphase_host_message
