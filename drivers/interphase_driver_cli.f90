!> Command line of the stand-alone programs (`interphase-point`, `interphase-fe2d`,
!> `interphase-calibrate`): arguments of any length, the common `CASE.nml [--output-dir DIR]
!> [--no-plot]` form, creating an output folder, and running gnuplot when it is there.
module interphase_driver_cli
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use interphase_driver_text, only: int_to_string, shell_quote, join_path
   use interphase_driver_version, only: INTERPHASE_VERSION
   implicit none
   private
   public :: run_arguments_type, parse_run_arguments, get_argument, make_directory, gnuplot_available, &
      run_gnuplot, exit_program, rename_file, remove_file, file_exists, print_version, is_special_file, &
      refuse_special_output, open_failure, OPEN_MESSAGE_LEN, is_directory, refuse_extra_arguments, &
      check_output_folder, digits_value

   interface
      !> C's exit(): ends the program with a status and no "STOP" line or backtrace.
      subroutine c_exit(status) bind(c, name='exit')
         import :: c_int
         integer(c_int), value :: status
      end subroutine c_exit
      !> C's rename(): atomic within one file system.
      integer(c_int) function c_rename(from, to) bind(c, name='rename')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: from(*), to(*)
      end function c_rename
      !> 1 when the path names a file that is not a regular one (interphase_driver_posix.c).
      integer(c_int) function c_is_special_file(path) bind(c, name='interphase_driver_is_special_file')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_is_special_file
      !> 1 when the path names an existing directory (interphase_driver_posix.c).
      integer(c_int) function c_is_directory(path) bind(c, name='interphase_driver_is_directory')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_is_directory
      !> C's remove().
      integer(c_int) function c_remove(path) bind(c, name='remove')
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
      end function c_remove
   end interface

   !> `PROGRAM CASE.nml [--output-dir DIR] [--no-plot]` (or `-h`/`--help`, `--version`).
   type :: run_arguments_type
      character(len=:), allocatable :: case_path     !! the case file
      character(len=:), allocatable :: output_dir    !! '' = current directory
      logical :: no_plot = .false.                   !! --no-plot given
      logical :: help = .false.                      !! -h or --help given
      logical :: version = .false.                   !! --version given
   end type run_arguments_type

   !> Length of an `iomsg` buffer for `open_failure`: the compiler's message holds the path, and
   !> the reason after it must not be cut.
   integer, parameter :: OPEN_MESSAGE_LEN = 16384

contains

   !> Parse the command line; on failure `ok` is false and `message` says why.
   subroutine parse_run_arguments(args, ok, message)
      type(run_arguments_type), intent(out) :: args
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      character(len=:), allocatable :: argument
      integer :: i, nargs

      ok = .false.
      message = ''
      args%case_path = ''
      args%output_dir = ''
      nargs = command_argument_count()
      ! --help and --version stand alone: an argument beside them would be ignored
      message = refuse_extra_arguments()
      if (len(message) > 0) return
      i = 0
      do while (i < nargs)
         i = i + 1
         call get_argument(i, argument)
         select case (argument)
         case ('-h', '--help')
            args%help = .true.
            ok = .true.
            return
         case ('--version')
            args%version = .true.
            ok = .true.
            return
         case ('')
            message = 'argument '//int_to_string(i)//' is empty (an empty case file or folder name)'
            return
         case ('--no-plot')
            if (args%no_plot) then
               message = '--no-plot given twice'
               return
            end if
            args%no_plot = .true.
         case ('--output-dir')
            ! (given twice: which one counts is not for us to guess, as for a case file's entries)
            if (len(args%output_dir) > 0) then
               message = '--output-dir given twice'
               return
            end if
            if (i == nargs) then
               message = '--output-dir needs a directory'
               return
            end if
            i = i + 1
            call get_argument(i, args%output_dir)
            message = check_output_folder('--output-dir', args%output_dir)
            if (len(message) > 0) return
         case default
            if (len(argument) > 0) then
               if (argument(1:1) == '-') then
                  message = 'unknown option '//argument
                  return
               end if
            end if
            if (len(args%case_path) > 0) then
               message = 'only one case file may be given (got '//args%case_path//' and '//argument//')'
               return
            end if
            args%case_path = argument
         end select
      end do
      if (len(args%case_path) == 0) then
         message = 'no case file given'
         return
      end if
      ok = .true.
   end subroutine parse_run_arguments

   !> '' when the command line is not `--help`, `-h` or `--version` with other arguments beside
   !> it; else the message that refuses them, naming them (they would be ignored).
   function refuse_extra_arguments() result(message)
      character(len=:), allocatable :: message
      character(len=:), allocatable :: argument, option, others
      integer :: i, nargs
      message = ''
      option = ''
      others = ''
      nargs = command_argument_count()
      do i = 1, nargs
         call get_argument(i, argument)
         if (len(option) == 0 .and. (argument == '-h' .or. argument == '--help' .or. argument == '--version')) then
            option = argument
         else
            if (len(others) > 0) others = others//' '
            others = others//''''//argument//''''
         end if
      end do
      if (len(option) > 0 .and. len(others) > 0) message = option//' stands alone, but other arguments are '// &
         'given: '//others
   end function refuse_extra_arguments

   !> '' when `folder`, the value of the option `option`, can name an output folder; else why not:
   !> empty, an option (beginning with '-': write ./-name for a folder named so), or an existing
   !> file that is not a folder. A folder that does not exist yet is fine (it is created).
   function check_output_folder(option, folder) result(message)
      character(len=*), intent(in) :: option      !! '--output-dir'
      character(len=*), intent(in) :: folder      !! its value
      character(len=:), allocatable :: message
      message = ''
      if (len(folder) == 0) then
         message = option//' needs a non-empty directory'
      else if (folder(1:1) == '-') then
         message = option//' needs a directory, got '''//folder//''', which begins with ''-'' like an option '// &
            '(a folder named so: write ./'//folder//')'
      else if (file_exists(folder)) then
         ! (nested, not with .and.: is_directory is impure and must not be skipped)
         if (.not. is_directory(folder)) message = option//' '//folder//' is not a folder (a file of that name exists)'
      end if
   end function check_output_folder

   !> The value of `text` when it is a whole number written with 1 to 9 digits (no sign, no
   !> blank, no exponent: a command-line count read as a whole), else -1.
   pure integer function digits_value(text) result(value)
      character(len=*), intent(in) :: text
      integer :: ios
      value = -1
      if (len(text) < 1 .or. len(text) > 9) return
      if (verify(text, '0123456789') /= 0) return
      read (text, '(i9)', iostat=ios) value
      if (ios /= 0) value = -1
   end function digits_value

   !> Whether `path` names an existing directory (symbolic links followed).
   logical function is_directory(path)
      character(len=*), intent(in) :: path
      is_directory = c_is_directory(path//c_null_char) /= 0
   end function is_directory

   !> Command-line argument number n, of any length.
   subroutine get_argument(n, value)
      integer, intent(in) :: n                    !! argument number
      character(len=:), allocatable, intent(out) :: value  !! its text
      integer :: length

      call get_command_argument(n, length=length)
      allocate (character(len=length) :: value)
      if (length > 0) call get_command_argument(n, value(:))
   end subroutine get_argument

   !> Create a directory and its parents (`mkdir -p`) unless it is '' (current directory).
   subroutine make_directory(directory, ok, message)
      character(len=*), intent(in) :: directory   !! directory path, may end in '/'
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      integer :: exitstat, cmdstat
      character(len=256) :: cmdmsg

      ok = .true.
      message = ''
      if (len(directory) == 0) return
      exitstat = 0
      cmdmsg = ''
      ! ('--': a folder whose name begins with '-' is not read as an option)
      call execute_command_line('mkdir -p -- '//shell_quote(directory), exitstat=exitstat, &
         cmdstat=cmdstat, cmdmsg=cmdmsg)
      if (cmdstat /= 0) then
         ok = .false.
         message = 'cannot run mkdir -p '//directory//': '//trim(cmdmsg)
      else if (exitstat /= 0) then
         ok = .false.
         message = 'mkdir -p '//directory//' failed (exit status '//int_to_string(exitstat)//')'
      end if
   end subroutine make_directory

   !> True when `gnuplot` is on PATH.
   logical function gnuplot_available()
      integer :: exitstat, cmdstat
      character(len=256) :: cmdmsg
      exitstat = 1
      cmdmsg = ''
      call execute_command_line('command -v gnuplot > /dev/null 2>&1', exitstat=exitstat, &
         cmdstat=cmdstat, cmdmsg=cmdmsg)
      gnuplot_available = cmdstat == 0 .and. exitstat == 0
   end function gnuplot_available

   !> Run gnuplot on a script inside `directory` ('' = current directory).
   subroutine run_gnuplot(directory, script_name, ok, message)
      character(len=*), intent(in) :: directory, script_name
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      character(len=:), allocatable :: folder
      integer :: exitstat, cmdstat
      character(len=256) :: cmdmsg
      ok = .false.
      message = ''
      folder = directory
      if (len(folder) == 0) folder = '.'
      exitstat = 0
      cmdmsg = ''
      call execute_command_line('cd '//shell_quote(folder)//' && gnuplot '//shell_quote(script_name), &
         exitstat=exitstat, cmdstat=cmdstat, cmdmsg=cmdmsg)
      if (cmdstat /= 0) then
         message = 'cannot run gnuplot: '//trim(cmdmsg)
      else if (exitstat /= 0) then
         message = 'gnuplot failed on '//join_path(folder, script_name)//' (exit status '// &
            int_to_string(exitstat)//')'
      else
         ok = .true.
      end if
   end subroutine run_gnuplot

   !> End the program with exit status `status`, after flushing standard output and error,
   !> without the "STOP n" line of Fortran's stop.
   subroutine exit_program(status)
      integer, intent(in) :: status               !! exit status
      flush (output_unit)
      flush (error_unit)
      call c_exit(int(status, c_int))
   end subroutine exit_program

   !> Rename (move) a file, replacing `to` if it is a regular file or does not exist; a `to` that
   !> is not a regular file (a device such as /dev/null, a directory, a pipe) is not replaced.
   subroutine rename_file(from, to, ok, message)
      character(len=*), intent(in) :: from, to    !! paths
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      message = ''
      ok = .not. is_special_file(to)
      if (.not. ok) then
         message = 'cannot rename '//from//' to '//to//': '//to//' is not a regular file'
         return
      end if
      ok = c_rename(from//c_null_char, to//c_null_char) == 0
      if (.not. ok) message = 'cannot rename '//from//' to '//to
   end subroutine rename_file

   !> Whether `path` names an existing file that is not a regular file: a device (/dev/null), a
   !> directory, a named pipe or a socket (symbolic links followed).
   logical function is_special_file(path)
      character(len=*), intent(in) :: path
      is_special_file = c_is_special_file(path//c_null_char) /= 0
   end function is_special_file

   !> The message (or '') that refuses an output file `path` that is not a regular file: the
   !> drivers' outputs are regular files, and the CSV's rename from CSV.part would replace a device
   !> node (as root, /dev/null itself) with one. `what` names the output ('output = ...').
   function refuse_special_output(path, what) result(message)
      character(len=*), intent(in) :: path, what
      character(len=:), allocatable :: message
      message = ''
      if (is_special_file(path)) message = what//' would write '//path//', which is not a regular file '// &
         '(a device such as /dev/null, a directory or a pipe): each output is written as a regular file '// &
         'in its place; name a file'
   end function refuse_special_output

   !> The message of a failed `open` of `path` for writing: 'cannot write WHAT: REASON: PATH', the
   !> reason first (a path of hundreds of characters does not hide it). `iomsg` is the open's
   !> message (OPEN_MESSAGE_LEN long); where it quotes the path ("Cannot open file 'PATH': why")
   !> the reason is the text after it, else the whole message.
   function open_failure(what, path, iomsg) result(message)
      character(len=*), intent(in) :: what       !! the file's role: 'the CSV file'
      character(len=*), intent(in) :: path       !! the file
      character(len=*), intent(in) :: iomsg      !! the open's message
      character(len=:), allocatable :: message
      character(len=:), allocatable :: reason
      integer :: k
      reason = trim(iomsg)
      k = index(reason, ''''//path//'''')
      if (k > 0) then
         reason = adjustl(reason(k + len(path) + 2:))
         if (len(reason) > 0) then
            if (reason(1:1) == ':') reason = adjustl(reason(2:))
         end if
         reason = trim(reason)
         if (len(reason) == 0) reason = trim(iomsg(:k - 1))
      end if
      message = 'cannot write '//what//': '//reason//': '//path
   end function open_failure

   !> Remove a file if it exists (nothing happens otherwise).
   subroutine remove_file(path)
      character(len=*), intent(in) :: path        !! the file
      integer(c_int) :: status
      if (file_exists(path)) status = c_remove(path//c_null_char)
   end subroutine remove_file

   !> Whether a file exists.
   logical function file_exists(path)
      character(len=*), intent(in) :: path        !! the file
      inquire (file=path, exist=file_exists)
   end function file_exists

   !> `PROGRAM VERSION` on standard output (the answer to --version).
   subroutine print_version(program_name)
      character(len=*), intent(in) :: program_name  !! e.g. 'interphase-point'
      write (output_unit, '(a)') program_name//' (interphase) '//INTERPHASE_VERSION
   end subroutine print_version

end module interphase_driver_cli
