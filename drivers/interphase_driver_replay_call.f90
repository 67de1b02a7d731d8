!> Replay files (`&replay`, src/abaqus/interphase_replay_file.f90): one failed UMAT or VUMAT
!> call, written by the adapters when INTERPHASE_REPLAY_DIR names a folder and by
!> interphase-point when an update fails. `interphase-point FILE` reads it here and repeats the
!> call through the UMAT (`repeat_replay_call`).
module interphase_driver_replay_call
   use, intrinsic :: iso_fortran_env, only: output_unit, iostat_end
   use interphase_kinds, only: dp
   use interphase_replay_file, only: REPLAY_MAX_PROPS, REPLAY_MAX_STATEV
   use interphase_abaqus_interfaces, only: umat
   use interphase_driver_text, only: int_to_string, real_to_string, read_line, to_lower, text_file_type, &
      open_line_file, close_text_file
   use interphase_text_input, only: tried_path
   use interphase_driver_namelist, only: open_namelist_file, check_namelist_file, entry_kind_type, entry_line_type, &
      with_entry_line, KIND_REAL, KIND_INTEGER, KIND_STRING
   implicit none
   private
   public :: replay_call_type, is_replay_file, read_replay_call, repeat_replay_call

   !> Lengths of the `&replay` strings: the writer's word, its message, a file's path (a longer
   !> value is refused, not cut short).
   integer, parameter :: SOURCE_LEN = 16, FAILURE_LEN = 8192, PATH_LEN = 4096

   !> The entries of `&replay`, their kinds and the arrays' sizes (the case files' pre-check,
   !> `check_namelist_file`, takes them).
   type(entry_kind_type), parameter :: REPLAY_ENTRIES(21) = [ &
      entry_kind_type('replay.source', KIND_STRING, SOURCE_LEN), &
      entry_kind_type('replay.failure', KIND_STRING, FAILURE_LEN), &
      entry_kind_type('replay.noel', KIND_INTEGER), entry_kind_type('replay.npt', KIND_INTEGER), &
      entry_kind_type('replay.kinc', KIND_INTEGER), entry_kind_type('replay.ntens', KIND_INTEGER), &
      entry_kind_type('replay.ndi', KIND_INTEGER), entry_kind_type('replay.nshr', KIND_INTEGER), &
      entry_kind_type('replay.nprops', KIND_INTEGER), entry_kind_type('replay.nstatv', KIND_INTEGER), &
      entry_kind_type('replay.props', KIND_REAL, 0, REPLAY_MAX_PROPS), &
      entry_kind_type('replay.statev', KIND_REAL, 0, REPLAY_MAX_STATEV), &
      entry_kind_type('replay.stress', KIND_REAL, 0, 6), entry_kind_type('replay.sse', KIND_REAL), &
      entry_kind_type('replay.spd', KIND_REAL), entry_kind_type('replay.stran', KIND_REAL, 0, 6), &
      entry_kind_type('replay.dstran', KIND_REAL, 0, 6), entry_kind_type('replay.time', KIND_REAL, 0, 2), &
      entry_kind_type('replay.dtime', KIND_REAL), entry_kind_type('replay.table', KIND_STRING, PATH_LEN), &
      entry_kind_type('replay.rcurve', KIND_STRING, PATH_LEN)]

   !> The inputs of one call.
   type :: replay_call_type
      character(len=SOURCE_LEN) :: source = ''
      character(len=FAILURE_LEN) :: failure = ''      !! the adapter's message
      integer :: noel = 0, npt = 0, kinc = 0, ntens = 0, ndi = 1, nshr = 1, nprops = 0, nstatv = 0
      real(dp) :: props(REPLAY_MAX_PROPS) = 0.0_dp, statev(REPLAY_MAX_STATEV) = 0.0_dp
      !> (cohesive elements: 2 or 3 components, normal first; a thin layer's continuum: up to 6)
      real(dp) :: stress(6) = 0.0_dp, sse = 0.0_dp, spd = 0.0_dp, stran(6) = 0.0_dp, dstran(6) = 0.0_dp
      real(dp) :: time(2) = 0.0_dp, dtime = 0.0_dp
      character(len=PATH_LEN) :: table = '', rcurve = ''
   end type replay_call_type

contains

   !> Whether a file holds a `&replay` group (a line that starts with it).
   logical function is_replay_file(path)
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: line
      type(text_file_type) :: unit
      integer :: ios
      character(len=256) :: iomsg
      is_replay_file = .false.
      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) return
      do
         call read_line(unit, line, ios, iomsg)
         if (ios /= 0) exit
         line = to_lower(adjustl(line))
         if (len(line) >= 7) then
            if (line(1:7) == '&replay') then
               is_replay_file = .true.
               exit
            end if
         end if
      end do
      call close_text_file(unit)
   end function is_replay_file

   !> Read the `&replay` group of a file, as strictly as a case file: the pre-check of the case
   !> files first (`check_namelist_file`: bounded lines, nothing outside the group, each entry
   !> once, known and of its kind, a number only where the whole value is one and finite, a
   !> string no longer than its variable, an array no longer than its size), then the namelist
   !> read, then every entry given (but ndi and nshr), the ranges and the lengths of the arrays.
   !> Messages name the file, the line and the entry ('path:line: &replay: entry ...').
   subroutine read_replay_call(path, call_data, ok, message)
      character(len=*), intent(in) :: path
      type(replay_call_type), intent(out) :: call_data
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      character(len=SOURCE_LEN) :: source
      character(len=FAILURE_LEN) :: failure
      integer :: noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv
      real(dp) :: props(REPLAY_MAX_PROPS), statev(REPLAY_MAX_STATEV), stress(6), sse, spd, stran(6), dstran(6)
      real(dp) :: time(2), dtime
      character(len=PATH_LEN) :: table, rcurve
      namelist /replay/ source, failure, noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv, props, statev, stress, sse, spd, &
         stran, dstran, time, dtime, table, rcurve
      type(entry_line_type), allocatable :: lines(:)
      integer :: unit, ios, i
      character(len=512) :: iomsg
      character(len=:), allocatable :: name

      ok = .false.
      ! the case files' pre-check, with the entries of &replay
      call check_namelist_file(path, REPLAY_ENTRIES, ok, message, lines, file_kind='replay file', subnormals=.true.)
      if (.not. ok) then
         if (index(message, path//': cannot open') == 1) message = tried_path(path)//message(len(path) + 1:)
         return
      end if
      ok = .false.
      source = ''
      failure = ''
      noel = 0; npt = 0; kinc = 0; ntens = 0; ndi = 1; nshr = 1; nprops = 0; nstatv = 0
      props = 0.0_dp; statev = 0.0_dp; stress = 0.0_dp; sse = 0.0_dp; spd = 0.0_dp
      stran = 0.0_dp; dstran = 0.0_dp; time = 0.0_dp; dtime = 0.0_dp
      table = ''; rcurve = ''
      ! (a scratch copy with a newline after every line: open_namelist_file)
      call open_namelist_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = tried_path(path)//': cannot open the replay file: '//trim(iomsg)
         return
      end if
      read (unit, nml=replay, iostat=ios, iomsg=iomsg)
      close (unit)
      if (ios == iostat_end) then
         message = path//': &replay: group not found'
         return
      else if (ios /= 0) then
         message = path//': &replay: cannot read the group: '//trim(iomsg)
         return
      end if
      ! every entry the writers write, but ndi and nshr (default 1 and ntens - 1)
      do i = 1, size(REPLAY_ENTRIES)
         name = trim(REPLAY_ENTRIES(i)%name(len('replay.') + 1:))
         if (name == 'ndi' .or. name == 'nshr') cycle
         if (values_given(name) < 0) then
            message = path//': &replay: missing entry '//name//' (a replay file gives every entry but ndi and '// &
               'nshr, as the UMAT and the VUMAT write it)'
            return
         end if
      end do
      select case (trim(source))
      case ('vumat', 'umat', 'interphase-point')
      case default
         call refuse('source = '''//trim(source)//''' is not ''umat'', ''vumat'' or ''interphase-point'' '// &
            '(the writers of replay files)')
         return
      end select
      if (ntens < 2 .or. ntens > 6) then
         call refuse('ntens = '//int_to_string(ntens)//' is not 2 to 6')
         return
      end if
      if (values_given('ndi') < 0) ndi = 1
      if (ndi < 0 .or. ndi > ntens) then
         call refuse('ndi = '//int_to_string(ndi)//' is not 0 to ntens = '//int_to_string(ntens))
         return
      end if
      if (values_given('nshr') < 0) nshr = ntens - ndi
      if (nshr /= ntens - ndi) then
         call refuse('nshr = '//int_to_string(nshr)//' is not ntens - ndi = '//int_to_string(ntens - ndi))
         return
      end if
      if (noel < 1) then
         call refuse('noel = '//int_to_string(noel)//' is not an element (or a VUMAT''s block point) number: '// &
            '1 or more')
         return
      end if
      if (npt < 0) then
         call refuse('npt = '//int_to_string(npt)//' is not an integration point number: 0 (a VUMAT''s) or more')
         return
      end if
      ! (kinc 0: the VUMAT's failed block point has npt 0 and the increment totalTime/dt, 0 at
      ! t = 0; a repeat of its file through the UMAT passes both on, and with INTERPHASE_REPLAY_DIR
      ! set writes them into a 'umat' file, which must be readable too)
      if (kinc < 0) then
         call refuse('kinc = '//int_to_string(kinc)//' is not an increment number: 0 or more')
         return
      end if
      if (nprops < 1 .or. nprops > REPLAY_MAX_PROPS) then
         call refuse('nprops = '//int_to_string(nprops)//' is not 1 to '//int_to_string(REPLAY_MAX_PROPS))
         return
      end if
      if (nstatv < 1 .or. nstatv > REPLAY_MAX_STATEV) then
         call refuse('nstatv = '//int_to_string(nstatv)//' is not 1 to '//int_to_string(REPLAY_MAX_STATEV))
         return
      end if
      call check_length('props', nprops, 'nprops = '//int_to_string(nprops), ok)
      if (ok) call check_length('statev', nstatv, 'nstatv = '//int_to_string(nstatv), ok)
      if (ok) call check_length('stress', ntens, 'ntens = '//int_to_string(ntens), ok)
      if (ok) call check_length('stran', ntens, 'ntens = '//int_to_string(ntens), ok)
      if (ok) call check_length('dstran', ntens, 'ntens = '//int_to_string(ntens), ok)
      if (ok) call check_length('time', 2, 'time holds (step time, total time)', ok)
      if (.not. ok) return
      ok = .false.
      if (dtime < 0.0_dp) then
         call refuse('dtime = '//real_to_string(dtime)//' is negative: a time increment is 0 or more')
         return
      end if
      call_data = replay_call_type(source, failure, noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv, props, statev, &
         stress, sse, spd, stran, dstran, time, dtime, table, rcurve)
      ok = .true.

   contains

      !> The number of values the file gave `entry` (-1: not given).
      integer function values_given(entry) result(n)
         character(len=*), intent(in) :: entry
         integer :: j
         n = -1
         do j = 1, size(lines)
            if (trim(lines(j)%name) == 'replay.'//entry) n = lines(j)%values
         end do
      end function values_given

      !> message = 'path:line: &replay: why' (`why` starts with the entry's name).
      subroutine refuse(why)
         character(len=*), intent(in) :: why
         message = with_entry_line(path//': &replay: '//why, path, lines)
      end subroutine refuse

      !> Whether array `entry` holds exactly the n values its size entry gives; if not (`good`
      !> false), the message names it, its line, how many values it holds and what n says.
      subroutine check_length(entry, n, expected, good)
         character(len=*), intent(in) :: entry
         integer, intent(in) :: n
         character(len=*), intent(in) :: expected    !! what gives n
         logical, intent(out) :: good
         integer :: held
         held = values_given(entry)
         good = held == n
         if (good) return
         call refuse(entry//' holds '//int_to_string(held)//' value'//trim(merge('s', ' ', held /= 1))// &
            '; expected '//int_to_string(n)//' ('//expected//')')
      end subroutine check_length

   end subroutine read_replay_call

   !> Call the UMAT once with the replayed inputs; `failed` tells whether it failed again (its
   !> message went to the host hook, standard error). The outputs are printed.
   subroutine repeat_replay_call(call_data, failed)
      type(replay_call_type), intent(in) :: call_data
      logical, intent(out) :: failed
      character(len=80), parameter :: CMNAME = 'INTERPHASE-REPLAY'
      real(dp) :: stress(6), statev(REPLAY_MAX_STATEV), sse, spd, scd, rpl, ddsddt(6), drplde(6)
      real(dp) :: drpldt, temp, dtemp, predef(1), dpred(1), coords(3), drot(3, 3), dfgrd(3, 3), pnewdt
      real(dp), allocatable :: ddsdde(:, :)
      integer :: n, i, jstep(4)

      n = call_data%ntens
      allocate (ddsdde(n, n))
      stress = call_data%stress
      statev = call_data%statev
      ddsdde = 0.0_dp
      sse = call_data%sse
      spd = call_data%spd
      scd = 0.0_dp; rpl = 0.0_dp; ddsddt = 0.0_dp; drplde = 0.0_dp; drpldt = 0.0_dp
      temp = 0.0_dp; dtemp = 0.0_dp; predef = 0.0_dp; dpred = 0.0_dp; coords = 0.0_dp
      drot = 0.0_dp
      dfgrd = 0.0_dp
      do i = 1, 3
         drot(i, i) = 1.0_dp
         dfgrd(i, i) = 1.0_dp
      end do
      jstep = [1, 0, 0, 0]
      pnewdt = 1.0_dp
      call umat(stress(1:n), statev(1:call_data%nstatv), ddsdde, sse, spd, scd, rpl, ddsddt(1:n), &
         drplde(1:n), drpldt, call_data%stran(1:n), call_data%dstran(1:n), call_data%time, call_data%dtime, &
         temp, dtemp, predef, dpred, CMNAME, call_data%ndi, call_data%nshr, n, call_data%nstatv, &
         call_data%props(1:call_data%nprops), &
         call_data%nprops, coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, call_data%noel, call_data%npt, 1, 1, &
         jstep, call_data%kinc)
      failed = pnewdt < 1.0_dp
      if (failed) then
         write (output_unit, '(a)') 'the call fails again (PNEWDT = '//real_to_string(pnewdt)//'; its message above)'
      else
         write (output_unit, '(a)') 'the call succeeds here:'
         write (output_unit, '(a,6es25.16e3)') '  STRESS (MPa) =', stress(1:n)
         write (output_unit, '(a,16es25.16e3)') '  STATEV =', statev(1:min(call_data%nstatv, 16))
         write (output_unit, '(a,es25.16e3,a,es25.16e3)') '  SSE = ', sse, ', SPD = ', spd
         do i = 1, n
            write (output_unit, '(a,i0,a,6es25.16e3)') '  DDSDDE(', i, ', :) =', ddsdde(i, 1:n)
         end do
      end if
   end subroutine repeat_replay_call

end module interphase_driver_replay_call
