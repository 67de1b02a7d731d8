!> Abaqus UEXTERNALDB: at the start of an analysis (LOP = 0) and of a restart (LOP = 4) it
!> loads the custom RVE table named by the environment variable INTERPHASE_TABLE, once, before
!> any material point is updated; the micromechanical model uses it where PROPS(8) = 1. In the
!> same way it loads the tabulated R-curve of the fracture-mechanics law named by
!> INTERPHASE_RCURVE (used where the R-curve selector is 3).
!> Without the variable the built-in table (tables/paper.dat) serves and nothing is loaded.
!> Abaqus calls UEXTERNALDB from one thread at these points, so the load does not race with
!> updates. A table that cannot be read or fails its checks is a fatal error (severity error,
!> through interphase_host_message) naming the file, the line and the failed check.
subroutine uexternaldb(lop, lrestart, time, dtime, kstep, kinc)
   use interphase_kinds, only: dp
   use interphase_status, only: STATUS_OK, MESSAGE_LEN, SEVERITY_INFO, SEVERITY_FATAL, &
      status_message
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_rcurve, only: load_rcurve
   use interphase_abaqus_interfaces, only: interphase_host_message
   implicit none
   integer, intent(in) :: lop, lrestart, kstep, kinc
   real(dp), intent(in) :: time(2), dtime

   !> LOP values at which the table is (re)loaded: start of the analysis, start of a restart.
   integer, parameter :: LOP_START = 0, LOP_RESTART = 4
   character(len=*), parameter :: VARIABLE = 'INTERPHASE_TABLE'
   character(len=*), parameter :: RCURVE_VARIABLE = 'INTERPHASE_RCURVE'

   character(len=:), allocatable :: path
   character(len=MESSAGE_LEN) :: message
   integer :: status

   if (lop /= LOP_START .and. lop /= LOP_RESTART) return
   if (environment(VARIABLE, path)) then
      call load_custom_table(path, status, message)
      if (status /= STATUS_OK) then
         call interphase_host_message(SEVERITY_FATAL, 'UEXTERNALDB: '//VARIABLE//' = '//path//': '// &
            status_message(status)//': '//trim(message))
         return
      end if
      call interphase_host_message(SEVERITY_INFO, 'UEXTERNALDB: custom RVE table loaded from '//path)
   end if
   if (environment(RCURVE_VARIABLE, path)) then
      call load_rcurve(path, status, message)
      if (status /= STATUS_OK) then
         call interphase_host_message(SEVERITY_FATAL, 'UEXTERNALDB: '//RCURVE_VARIABLE//' = '//path//': '// &
            status_message(status)//': '//trim(message))
         return
      end if
      call interphase_host_message(SEVERITY_INFO, 'UEXTERNALDB: R-curve loaded from '//path)
   end if

contains

   !> The value of a non-empty environment variable.
   logical function environment(name, value)
      character(len=*), intent(in) :: name
      character(len=:), allocatable, intent(out) :: value
      integer :: length, stat
      call get_environment_variable(name, length=length, status=stat)
      environment = stat == 0 .and. length > 0
      if (.not. environment) return
      allocate (character(len=length) :: value)
      call get_environment_variable(name, value)
   end function environment

end subroutine uexternaldb
