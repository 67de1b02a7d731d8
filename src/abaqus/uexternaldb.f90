!> Abaqus UEXTERNALDB: at the start of an analysis (LOP = 0) and of a restart (LOP = 4) it
!> loads the custom RVE table named by the environment variable INTERPHASE_TABLE, once, before
!> any material point is updated; the micromechanical model uses it where PROPS(8) = 1.
!> Without the variable the built-in table (tables/paper.dat) serves and nothing is loaded.
!> Abaqus calls UEXTERNALDB from one thread at these points, so the load does not race with
!> updates. A table that cannot be read or fails its checks is a fatal error (severity error,
!> through interphase_host_message) naming the file, the line and the failed check.
subroutine uexternaldb(lop, lrestart, time, dtime, kstep, kinc)
   use interphase_kinds, only: dp
   use interphase_status, only: STATUS_OK, MESSAGE_LEN, SEVERITY_INFO, SEVERITY_FATAL, &
      status_message
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_abaqus_interfaces, only: interphase_host_message
   implicit none
   integer, intent(in) :: lop, lrestart, kstep, kinc
   real(dp), intent(in) :: time(2), dtime

   !> LOP values at which the table is (re)loaded: start of the analysis, start of a restart.
   integer, parameter :: LOP_START = 0, LOP_RESTART = 4
   character(len=*), parameter :: VARIABLE = 'INTERPHASE_TABLE'

   character(len=:), allocatable :: path
   character(len=MESSAGE_LEN) :: message
   integer :: length, status

   if (lop /= LOP_START .and. lop /= LOP_RESTART) return
   call get_environment_variable(VARIABLE, length=length, status=status)
   if (status /= 0 .or. length == 0) return
   allocate (character(len=length) :: path)
   call get_environment_variable(VARIABLE, path)
   call load_custom_table(path, status, message)
   if (status /= STATUS_OK) then
      call interphase_host_message(SEVERITY_FATAL, 'UEXTERNALDB: '//VARIABLE//' = '//path//': '// &
         status_message(status)//': '//trim(message))
      return
   end if
   call interphase_host_message(SEVERITY_INFO, 'UEXTERNALDB: custom RVE table loaded from '//path)
end subroutine uexternaldb
