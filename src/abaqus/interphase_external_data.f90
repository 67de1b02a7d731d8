!> The start-up loads of the Abaqus start-of-analysis hooks (UEXTERNALDB for Abaqus/Standard,
!> VEXTERNALDB for Abaqus/Explicit), in one place: the custom RVE table named by the environment
!> variable INTERPHASE_TABLE (the micromechanical model uses it where PROPS(8) = 1) and the
!> tabulated R-curve named by INTERPHASE_RCURVE (the fracture-mechanics law, R-curve selector 3).
!> Without a variable nothing is loaded (the built-in table serves). A variable that is set but
!> empty (`export INTERPHASE_TABLE=$UNSET_NAME` in a job script) loads nothing either, and is
!> reported as a warning naming it: a material that needs the file then fails at its first update.
!>
!> Loading writes the library's only shared data (`protected` module data that the updates only
!> read), so it must happen before any material point is updated and never while updates run:
!> Abaqus calls these hooks at the start of the analysis, once per process and before any UMAT
!> or VUMAT call. A file that is already loaded (same path) is not read again, so that a later
!> start-of-analysis call (a restart) never rewrites data that updates may be reading. There is
!> no lock: two threads calling a hook for the first time at once would race (Abaqus does not do
!> that; a host of its own must call it once, from one thread). A file that cannot be read or
!> fails its checks is a fatal error naming the variable, the file, the line and the failed check.
module interphase_external_data
   use interphase_status, only: STATUS_OK, MESSAGE_LEN, SEVERITY_INFO, SEVERITY_WARNING, SEVERITY_FATAL, status_message, &
      file_loader, message_path
   use interphase_enums, only: TABLE_CUSTOM_CODE
   use interphase_layout, only: PROP_TABLE
   use interphase_micro_coefficients, only: load_custom_table, custom_table_source
   use interphase_rcurve, only: load_rcurve, rcurve_loaded_path
   use interphase_abaqus_interfaces, only: interphase_host_message
   use interphase_text_input, only: tried_path
   implicit none
   private
   public :: load_external_data, load_table_file, load_rcurve_file

   !> Environment variables naming the files.
   character(len=*), parameter :: TABLE_VARIABLE = 'INTERPHASE_TABLE'
   character(len=*), parameter :: RCURVE_VARIABLE = 'INTERPHASE_RCURVE'

contains

   !> Load what the environment names; `caller` ('UEXTERNALDB', 'VEXTERNALDB') heads the messages.
   !> Each file is loaded (or refused) on its own: a refused RVE table does not keep a good R-curve
   !> from loading, so that a host whose message hook returns (interphase::host_stderr) runs the
   !> materials that need only the R-curve, and a material that needs a refused file finds that
   !> file's own error at the start of the run. ok = .false. after a fatal error (already
   !> reported to the host).
   subroutine load_external_data(caller, ok)
      character(len=*), intent(in) :: caller
      logical, intent(out) :: ok
      character(len=:), allocatable :: path
      logical :: table_ok, rcurve_ok
      table_ok = .true.
      rcurve_ok = .true.
      if (environment(caller, TABLE_VARIABLE, 'custom RVE table', path)) call load_table_file(caller, path, table_ok)
      if (environment(caller, RCURVE_VARIABLE, 'R-curve', path)) call load_rcurve_file(caller, path, rcurve_ok)
      ok = table_ok .and. rcurve_ok
   end subroutine load_external_data

   !> Load the custom RVE table from `path` (unless that file is loaded already) and report. The
   !> report says which materials use it: a loaded table changes nothing for a material whose
   !> table selector PROPS(8) is 0 (the built-in table), and a user who forgot PROPS(8) = 1 must
   !> not read "loaded" as "in use".
   subroutine load_table_file(caller, path, ok)
      character(len=*), intent(in) :: caller, path
      logical, intent(out) :: ok
      character(len=4) :: index_text
      write (index_text, '(i0)') PROP_TABLE
      call load_named_file(caller, TABLE_VARIABLE, 'custom RVE table', path, &
         custom_table_source(TABLE_CUSTOM_CODE), load_custom_table, ok, &
         used_by='; used by the micromechanical materials with the table selector PROPS('//trim(index_text)// &
         ') = 1 only (PROPS('//trim(index_text)//') = 0: the built-in table)')
   end subroutine load_table_file

   !> Load the tabulated R-curve from `path` (unless that file is loaded already) and report.
   subroutine load_rcurve_file(caller, path, ok)
      character(len=*), intent(in) :: caller, path
      logical, intent(out) :: ok
      call load_named_file(caller, RCURVE_VARIABLE, 'R-curve', path, rcurve_loaded_path(), load_rcurve, ok)
   end subroutine load_rcurve_file

   !> Call `loader` on `path` unless `loaded_from` is that path already; report success (info,
   !> followed by `used_by`) or failure (fatal, naming the variable, the file and the loader's
   !> message).
   subroutine load_named_file(caller, variable, what, path, loaded_from, loader, ok, used_by)
      character(len=*), intent(in) :: caller, variable, what, path
      character(len=*), intent(in) :: loaded_from       !! the file loaded now ('' or a note if none)
      procedure(file_loader) :: loader                  !! the loader to call
      logical, intent(out) :: ok
      character(len=*), intent(in), optional :: used_by !! which materials use the file, for the report
      character(len=MESSAGE_LEN) :: message
      character(len=:), allocatable :: users
      integer :: status
      logical :: loaded
      users = ''
      if (present(used_by)) users = used_by
      ok = .true.
      ! (the loaders keep the path as opened, absolute: a relative one names the same file)
      loaded = loaded_from == path
      if (.not. loaded) loaded = loaded_from == tried_path(path)
      if (loaded) then
         call interphase_host_message(SEVERITY_INFO, caller//': '//what//' '//message_path(tried_path(path))//' already loaded')
         return
      end if
      call loader(path, status, message)
      ok = status == STATUS_OK
      if (.not. ok) then
         call interphase_host_message(SEVERITY_FATAL, caller//': '//variable//' = '//message_path(path)//': '// &
            status_message(status)//': '//trim(message))
         return
      end if
      ! (the path shortened so that the whole report fits in a message)
      call interphase_host_message(SEVERITY_INFO, caller//': '//what//' loaded from '// &
         message_path(tried_path(path), MESSAGE_LEN - len(caller) - len(what) - len(users) - 16)//users)
   end subroutine load_named_file

   !> The value of a non-empty environment variable. A variable that is set but empty names no
   !> file: a warning says so (`caller` heads it, `what` is the data it would have named), since a
   !> material that needs the file would otherwise fail later with no start-up message to explain it.
   logical function environment(caller, name, what, value)
      character(len=*), intent(in) :: caller, name, what
      character(len=:), allocatable, intent(out) :: value
      integer :: length, stat
      call get_environment_variable(name, length=length, status=stat)
      environment = stat == 0 .and. length > 0
      if (stat == 0 .and. length == 0) then
         call interphase_host_message(SEVERITY_WARNING, caller//': '//name//' is set but empty: no '//what// &
            ' loaded (unset it, or set it to the file)')
      end if
      if (.not. environment) return
      allocate (character(len=length) :: value)
      call get_environment_variable(name, value(:))
   end function environment

end module interphase_external_data
