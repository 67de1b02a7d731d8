!> Message hook for Abaqus/Explicit (VUMAT): passes the adapter's message to Abaqus's message
!> utility XPLB_ABQERR(LOP, STRING, INTV, REALV, CHARV), which writes it to the .msg file
!> (and .sta) with the job's other messages. Level and text: interphase_abaqus_message.
!>
!> Link exactly one hook: this file in an Abaqus/Explicit build (the XPLB_ABQERR symbol exists
!> only inside Abaqus; here the file is compiled but never linked), host_abaqus_standard.f90 for
!> Abaqus/Standard, host_stderr.f90 for stand-alone programs.
subroutine interphase_host_message(severity, message)
   use interphase_kinds, only: dp
   use interphase_abaqus_message, only: ABAQUS_MESSAGE_LEN, abaqus_message
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value

   interface
      !> Abaqus/Explicit message utility (provided by Abaqus).
      subroutine xplb_abqerr(lop, string, intv, realv, charv)
         import :: dp
         integer, intent(in) :: lop
         character(len=*), intent(in) :: string
         integer, intent(in) :: intv(*)
         real(dp), intent(in) :: realv(*)
         character(len=8), intent(in) :: charv(*)
      end subroutine xplb_abqerr
   end interface

   character(len=ABAQUS_MESSAGE_LEN) :: text
   integer :: intv(1), lop, n
   real(dp) :: realv(1)
   character(len=8) :: charv(1)

   call abaqus_message(severity, message, lop, text, n)
   intv = 0
   realv = 0.0_dp
   charv = ' '
   call xplb_abqerr(lop, text(1:n), intv, realv, charv)
end subroutine interphase_host_message
