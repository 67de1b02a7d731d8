!> Replay files (`&replay`, src/abaqus/interphase_replay_file.f90): one failed UMAT or VUMAT
!> call, written by the adapters when INTERPHASE_REPLAY_DIR names a folder and by
!> interphase-point when an update fails. `interphase-point FILE` reads it here and repeats the
!> call through the UMAT (`repeat_replay_call`).
module interphase_driver_replay_call
   use, intrinsic :: iso_fortran_env, only: output_unit, iostat_end, int64
   use interphase_kinds, only: dp
   use interphase_replay_file, only: REPLAY_MAX_PROPS, REPLAY_MAX_STATEV
   use interphase_abaqus_interfaces, only: umat
   use interphase_driver_text, only: int_to_string, real_to_string, read_line, to_lower, text_file_type, &
      open_line_file, close_text_file
   use interphase_text_input, only: tried_path
   use interphase_driver_namelist, only: open_namelist_file
   implicit none
   private
   public :: replay_call_type, is_replay_file, read_replay_call, repeat_replay_call

   !> Marks a `&replay` array value the file did not set.
   real(dp), parameter :: UNSET = -huge(1.0_dp)

   !> The inputs of one call.
   type :: replay_call_type
      character(len=16) :: source = ''
      character(len=2048) :: failure = ''      !! the adapter's message
      integer :: noel = 0, npt = 0, kinc = 0, ntens = 0, ndi = 1, nshr = 1, nprops = 0, nstatv = 0
      real(dp) :: props(REPLAY_MAX_PROPS) = 0.0_dp, statev(REPLAY_MAX_STATEV) = 0.0_dp
      !> (cohesive elements: 2 or 3 components, normal first; a thin layer's continuum: up to 6)
      real(dp) :: stress(6) = 0.0_dp, sse = 0.0_dp, spd = 0.0_dp, stran(6) = 0.0_dp, dstran(6) = 0.0_dp
      real(dp) :: time(2) = 0.0_dp, dtime = 0.0_dp
      character(len=1024) :: table = '', rcurve = ''
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

   !> Read the `&replay` group of a file.
   subroutine read_replay_call(path, call_data, ok, message)
      character(len=*), intent(in) :: path
      type(replay_call_type), intent(out) :: call_data
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      character(len=16) :: source
      character(len=2048) :: failure
      integer :: noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv
      real(dp) :: props(REPLAY_MAX_PROPS), statev(REPLAY_MAX_STATEV), stress(6), sse, spd, stran(6), dstran(6)
      real(dp) :: time(2), dtime
      character(len=1024) :: table, rcurve
      namelist /replay/ source, failure, noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv, props, statev, stress, sse, spd, &
         stran, dstran, time, dtime, table, rcurve
      integer :: unit, ios
      character(len=512) :: iomsg

      ok = .false.
      message = ''
      source = ''
      failure = ''
      noel = 0; npt = 0; kinc = 0; ntens = 0; ndi = -1; nshr = -1; nprops = 0; nstatv = 0
      ! (the arrays marked unset, so that their lengths can be checked against nprops, nstatv, ntens)
      props = UNSET; statev = UNSET; stress = UNSET; sse = 0.0_dp; spd = 0.0_dp
      stran = UNSET; dstran = UNSET; time = UNSET; dtime = 0.0_dp
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
      if (ntens < 2 .or. ntens > 6) then
         message = path//': &replay: ntens must be 2 to 6, got '//int_to_string(ntens)
         return
      end if
      if (ndi < 0) ndi = 1
      if (nshr < 0) nshr = ntens - ndi
      if (nprops < 1 .or. nprops > REPLAY_MAX_PROPS .or. nstatv < 1 .or. nstatv > REPLAY_MAX_STATEV) then
         message = path//': &replay: nprops = '//int_to_string(nprops)//', nstatv = '//int_to_string(nstatv)// &
            ' (1 to '//int_to_string(REPLAY_MAX_PROPS)//' each)'
         return
      end if
      call check_length(path, 'props', props, nprops, ok, message)
      if (ok) call check_length(path, 'statev', statev, nstatv, ok, message)
      if (ok) call check_length(path, 'stress', stress, ntens, ok, message)
      if (ok) call check_length(path, 'stran', stran, ntens, ok, message)
      if (ok) call check_length(path, 'dstran', dstran, ntens, ok, message)
      if (ok) call check_length(path, 'time', time, 2, ok, message)
      if (.not. ok) return
      ok = .false.
      call_data = replay_call_type(source, failure, noel, npt, kinc, ntens, ndi, nshr, nprops, nstatv, props, statev, &
         stress, sse, spd, stran, dstran, time, dtime, table, rcurve)
      ok = .true.
   end subroutine read_replay_call

   !> Whether a `&replay` array holds exactly its first n values (each set, none after them); if
   !> not (ok false), the message names the array, how many values it holds and what n says.
   subroutine check_length(path, name, values, n, ok, message)
      character(len=*), intent(in) :: path, name
      real(dp), intent(in) :: values(:)
      integer, intent(in) :: n                    !! the length nprops, nstatv or ntens gives
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(inout) :: message
      character(len=:), allocatable :: expected
      integer :: held
      held = count(.not. unset_value(values))
      ok = held == n .and. .not. any(unset_value(values(:n)))
      if (ok) return
      select case (name)
      case ('props'); expected = 'nprops = '//int_to_string(n)
      case ('statev'); expected = 'nstatv = '//int_to_string(n)
      case ('time'); expected = 'time holds (step time, total time)'
      case default; expected = 'ntens = '//int_to_string(n)
      end select
      if (held == n) then
         message = path//': &replay: '//name//' holds '//int_to_string(held)//' values, but not its first '// &
            int_to_string(n)//' ('//expected//')'
      else
         message = path//': &replay: '//name//' holds '//int_to_string(held)//' values; expected '// &
            int_to_string(n)//' ('//expected//')'
      end if
   end subroutine check_length

   !> Whether a value is the UNSET mark, compared bit for bit (no floating-point comparison: a NaN
   !> is a value the file set, and a build that traps invalid operations does not stop on it).
   elemental logical function unset_value(x)
      real(dp), intent(in) :: x
      unset_value = transfer(x, 0_int64) == transfer(UNSET, 0_int64)
   end function unset_value


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
