!> Replay files: one failed UMAT or VUMAT call, written so that `interphase-point FILE` repeats
!> it through the UMAT (docs/abaqus.md, 'Replay files'; drivers/README.md).
!>
!> When the environment variable INTERPHASE_REPLAY_DIR names a folder, an adapter whose update
!> fails writes the call's inputs there, as the namelist group `&replay` (PROPS, the incoming
!> STATEV, STRESS, SSE and SPD, STRAN, DSTRAN, TIME, DTIME, the element, point and increment, the
!> message, and the files INTERPHASE_TABLE and INTERPHASE_RCURVE name), every real with 17
!> significant digits so that it reads back bit for bit. One file per failed call, never one
!> written over: interphase-replay-<source>-e<NOEL>-p<NPT>-k<KINC>.nml, or with -2, -3, ... before
!> `.nml` where that name is taken (a retried increment, a later step whose increments count
!> from 1 again, another block of the VUMAT's at the same block point, an earlier run). Without
!> the variable nothing is written and nothing is looked up but the variable.
!>
!> Thread-safe: no module data; each call opens its own unit (`newunit`) on a file it creates
!> (status 'new': two calls never write one file; of two that take the same name at the same
!> instant, the one whose open fails takes the next copy's name, and with flang 19, whose failed
!> open as new deletes the existing file, the other's can be lost).
module interphase_replay_file
   use interphase_kinds, only: dp
   use interphase_enums, only: TABLE_CUSTOM_CODE
   use interphase_micro_coefficients, only: custom_table_loaded, custom_table_source
   use interphase_rcurve, only: rcurve_loaded, rcurve_loaded_path
   use interphase_text_input, only: tried_path
   implicit none
   private
   public :: write_replay, write_replay_group, replay_note, REPLAY_VARIABLE, REPLAY_MAX_PROPS, REPLAY_MAX_STATEV

   !> The environment variable naming the folder of the replay files.
   character(len=*), parameter :: REPLAY_VARIABLE = 'INTERPHASE_REPLAY_DIR'
   !> Largest PROPS and STATEV a replay file holds.
   integer, parameter :: REPLAY_MAX_PROPS = 64, REPLAY_MAX_STATEV = 64
   !> Most files of one name (the name itself, then -2 ... -REPLAY_MAX_COPIES).
   integer, parameter :: REPLAY_MAX_COPIES = 999
   !> Most failed opens of one call (each tries the next copy's name) before it gives up: a name
   !> another thread took between the look-up and the open is retried, a folder that cannot take
   !> a file at all costs only these.
   integer, parameter :: REPLAY_MAX_OPEN_FAILURES = 8

contains

   !> Write the replay file of a failed call if INTERPHASE_REPLAY_DIR names a folder; `written`
   !> is its path ('' when none was written: no variable, the file could not be created, or
   !> REPLAY_MAX_COPIES files of its name exist), and `why` says why none was written where the
   !> variable is set ('' otherwise).
   subroutine write_replay(source, message, props, statev, stress, sse, spd, stran, dstran, time, &
         dtime, noel, npt, kinc, written, ndi, nshr, why)
      character(len=*), intent(in) :: source       !! 'umat' or 'vumat'
      character(len=*), intent(in) :: message      !! why the call failed
      real(dp), intent(in) :: props(:), statev(:)  !! PROPS, the incoming STATEV
      real(dp), intent(in) :: stress(:)            !! incoming STRESS (MPa)
      real(dp), intent(in) :: sse, spd             !! incoming energies per unit area (N/mm)
      real(dp), intent(in) :: stran(:), dstran(:)  !! separation at the start, its increment (mm)
      real(dp), intent(in) :: time(2), dtime       !! step and total time at the start, increment
      integer, intent(in) :: noel, npt, kinc       !! element, point, increment
      character(len=:), allocatable, intent(out) :: written
      integer, intent(in), optional :: ndi, nshr  !! the host's NDI, NSHR (default 1, NTENS - 1)
      character(len=:), allocatable, intent(out), optional :: why
      character(len=:), allocatable :: folder, given, path
      character(len=64) :: name
      character(len=8) :: copy
      character(len=256) :: iomsg
      character(len=:), allocatable :: first_failure
      integer :: unit, ios, n, failed_opens
      logical :: exists

      written = ''
      if (present(why)) why = ''
      if (.not. environment(REPLAY_VARIABLE, folder)) return
      given = folder
      write (name, '(a,a,a,i0,a,i0,a,i0)') 'interphase-replay-', source, '-e', noel, '-p', npt, '-k', kinc
      if (folder(len(folder):len(folder)) /= '/') folder = folder//'/'
      failed_opens = 0
      first_failure = ''
      do n = 1, REPLAY_MAX_COPIES
         copy = ''
         if (n > 1) write (copy, '(a,i0)') '-', n
         path = folder//trim(name)//trim(copy)//'.nml'
         ! a name that is taken: the next copy's. (Looked up before the open, not after a failed
         ! one: flang 19's run time deletes the existing file when an OPEN with status 'new' fails.)
         inquire (file=path, exist=exists)
         if (exists) then
            if (n == REPLAY_MAX_COPIES) then
               if (present(why)) then
                  write (copy, '(a,i0)') '-', REPLAY_MAX_COPIES
                  why = trim(name)//'.nml and its copies up to '//trim(copy)//' exist already in '// &
                     REPLAY_VARIABLE//' = '//given
               end if
               return
            end if
            cycle
         end if
         ! status 'new': a call that takes the same name at the same instant (another thread) makes
         ! this open fail, rather than both writing one file; this call then tries the next copy's
         ! name, as for a name taken before the look-up
         iomsg = ''
         open (newunit=unit, file=path, status='new', action='write', form='formatted', iostat=ios, iomsg=iomsg)
         if (ios == 0) exit
         ! no folder, not writable, or the name taken just now: the first failure is the one named
         if (failed_opens == 0) first_failure = 'cannot create '//trim(name)//trim(copy)//'.nml in '// &
            REPLAY_VARIABLE//' = '//given//': '//trim(iomsg)
         failed_opens = failed_opens + 1
         if (failed_opens < REPLAY_MAX_OPEN_FAILURES .and. n < REPLAY_MAX_COPIES) cycle
         if (present(why)) why = first_failure
         return
      end do
      call write_replay_group(unit, source, message, props, statev, stress, sse, spd, stran, dstran, &
         time, dtime, noel, npt, kinc, ios, ndi=ndi, nshr=nshr)
      close (unit)
      if (ios == 0) then
         written = path
      else if (present(why)) then
         why = 'cannot write '//path//' (in '//REPLAY_VARIABLE//')'
      end if
   end subroutine write_replay

   !> The note a host message of a failed call ends with: ' (replay file: PATH)' where one was
   !> written, ' (no replay file: WHY)' where INTERPHASE_REPLAY_DIR is set but none could be, else ''
   !> (`written` and `why` as write_replay returns them).
   pure function replay_note(written, why) result(note)
      character(len=*), intent(in) :: written, why
      character(len=:), allocatable :: note
      note = ''
      if (len(written) > 0) then
         note = ' (replay file: '//written//')'
      else if (len(why) > 0) then
         note = ' (no replay file: '//why//')'
      end if
   end function replay_note

   !> Write the `&replay` group on an open unit (`ios` /= 0 when a write failed).
   subroutine write_replay_group(unit, source, message, props, statev, stress, sse, spd, stran, &
         dstran, time, dtime, noel, npt, kinc, ios, table_file, rcurve_file, ndi, nshr)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: source, message
      real(dp), intent(in) :: props(:), statev(:), stress(:), sse, spd, stran(:), dstran(:), time(2), dtime
      integer, intent(in) :: noel, npt, kinc
      integer, intent(out) :: ios
      !> the custom RVE table and R-curve files loaded (default: the files the run loaded, as they
      !> were opened, absolute; else what INTERPHASE_TABLE and INTERPHASE_RCURVE name, a relative
      !> path made absolute: the replay file is read back from another folder)
      character(len=*), intent(in), optional :: table_file, rcurve_file
      integer, intent(in), optional :: ndi, nshr   !! the host's NDI, NSHR (default 1, NTENS - 1)
      character(len=:), allocatable :: table, rcurve
      integer :: ndi_used, nshr_used

      if (present(table_file)) then
         table = table_file
      else if (custom_table_loaded()) then
         table = custom_table_source(TABLE_CUSTOM_CODE)
      else if (environment('INTERPHASE_TABLE', table)) then
         table = tried_path(table)
      else
         table = ''
      end if
      if (present(rcurve_file)) then
         rcurve = rcurve_file
      else if (rcurve_loaded()) then
         rcurve = rcurve_loaded_path()
      else if (environment('INTERPHASE_RCURVE', rcurve)) then
         rcurve = tried_path(rcurve)
      else
         rcurve = ''
      end if
      write (unit, '(a)', iostat=ios) '! A failed '//source//' call of interphase. Repeat it through the UMAT with', &
         '!   interphase-point THIS_FILE', &
         '! (drivers/README.md, ''Replay files''). STRESS, STRAN, DSTRAN in the host''s order.', &
         '&replay', &
         '  source = '''//source//'''', &
         '  failure = '''//quoted(message)//''''
      if (ios /= 0) return
      write (unit, '(a,i0,a,i0,a,i0)', iostat=ios) '  noel = ', noel, ', npt = ', npt, ', kinc = ', kinc
      if (ios /= 0) return
      ndi_used = 1
      nshr_used = size(stran) - 1
      if (present(ndi)) ndi_used = ndi
      if (present(nshr)) nshr_used = nshr
      write (unit, '(a,i0,a,i0,a,i0,a,i0,a,i0)', iostat=ios) '  ntens = ', size(stran), ', ndi = ', ndi_used, &
         ', nshr = ', nshr_used, ', nprops = ', size(props), ', nstatv = ', size(statev)
      if (ios /= 0) return
      call put('props', props)
      call put('statev', statev)
      call put('stress', stress)
      call put('sse', [sse])
      call put('spd', [spd])
      call put('stran', stran)
      call put('dstran', dstran)
      call put('time', time)
      call put('dtime', [dtime])
      if (ios /= 0) return
      write (unit, '(a)', iostat=ios) '  table = '''//quoted(table)//'''', '  rcurve = '''//quoted(rcurve)//'''', '/'

   contains

      subroutine put(key, values)
         character(len=*), intent(in) :: key
         real(dp), intent(in) :: values(:)
         character(len=25) :: field
         character(len=:), allocatable :: line
         integer :: i
         if (ios /= 0) return
         line = '  '//key//' ='
         do i = 1, size(values)
            write (field, '(es25.16e3)') values(i)
            line = line//' '//trim(adjustl(field))
            if (i < size(values)) line = line//','
         end do
         write (unit, '(a)', iostat=ios) line
      end subroutine put

   end subroutine write_replay_group

   !> A text for a single-quoted namelist string: quotes doubled.
   pure function quoted(text) result(safe)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: safe
      integer :: i
      safe = ''
      do i = 1, len_trim(text)
         safe = safe//text(i:i)
         if (text(i:i) == '''') safe = safe//''''
      end do
   end function quoted

   !> The value of an environment variable, if it is set and not empty.
   logical function environment(variable, value)
      character(len=*), intent(in) :: variable
      character(len=:), allocatable, intent(out) :: value
      integer :: length, status
      environment = .false.
      call get_environment_variable(variable, length=length, status=status)
      if (status /= 0 .or. length == 0) then
         value = ''
         return
      end if
      allocate (character(len=length) :: value)
      call get_environment_variable(variable, value(:), status=status)
      environment = status == 0
   end function environment

end module interphase_replay_file
