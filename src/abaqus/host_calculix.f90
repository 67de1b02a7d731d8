!> Message hook for CalculiX (a ccx built with external-behaviour support, examples/calculix):
!> writes the adapter's message to standard output, where ccx writes its own, in ccx's form
!> (' *WARNING in interphase: ...', ' *ERROR in interphase: ...'). A fatal message (bad PROPS,
!> sizes, STATEV or host input: no smaller increment can help) ends the run as ccx's own input
!> errors do, with exit status 201; a warning comes with a cut-back request through PNEWDT, which
!> ccx honours under automatic incrementation.
!>
!> Link exactly one hook: this file in a CalculiX build (examples/calculix/build-calculix.sh),
!> host_abaqus_standard.f90 for Abaqus/Standard, host_stderr.f90 for stand-alone programs.
subroutine interphase_host_message(severity, message)
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use interphase_status, only: SEVERITY_FATAL, SEVERITY_WARNING
   implicit none
   integer, intent(in) :: severity            !! one of the SEVERITY_* codes
   character(len=*), intent(in) :: message    !! what went wrong, with the offending value

   interface
      !> The C library's exit: ends the process as ccx does after an input error.
      subroutine c_exit(code) bind(C, name='exit')
         import :: c_int
         integer(c_int), value, intent(in) :: code
      end subroutine c_exit
   end interface

   select case (severity)
   case (SEVERITY_FATAL)
      write (output_unit, '(a)') ' *ERROR in interphase: '//trim(message)
      flush (output_unit)
      call c_exit(201_c_int)
   case (SEVERITY_WARNING)
      write (output_unit, '(a)') ' *WARNING in interphase: '//trim(message)
   case default
      write (output_unit, '(a)') ' *INFO in interphase: '//trim(message)
   end select
end subroutine interphase_host_message
