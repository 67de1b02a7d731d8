!> The UMAT's failure path, out of line: a failed call asks for a cut-back and reports, with
!> where it happened, to the host (docs/abaqus.md, 'Failure behaviour'). Kept apart from `umat`
!> so that the update, which every call runs, carries none of its frame.
module interphase_umat_failure
   use interphase_kinds, only: dp
   use interphase_status, only: MESSAGE_LEN, status_message, STATUS_BAD_NSTATV
   use interphase_abaqus_interfaces, only: interphase_host_message
   use interphase_replay_file, only: write_replay, replay_note
   implicit none
   private
   public :: umat_fail, PNEWDT_CUTBACK

   !> Factor applied to PNEWDT when an update fails (the host retries a smaller increment).
   real(dp), parameter :: PNEWDT_CUTBACK = 0.25_dp

contains

   !> Ask for a cut-back and pass the message, with where it happened, to the host. Abaqus
   !> passes PNEWDT large and keeps the smallest value the points return; CalculiX passes -1 (no
   !> request) and takes any value > 0 as the factor, the smallest over the points: so the request
   !> is PNEWDT_CUTBACK unless a smaller positive one is there already. With the CalculiX host
   !> option DDSDDE is set to zero (ccx passes it uninitialised and stores it even from a call that
   !> asks for a cut-back). With INTERPHASE_REPLAY_DIR set, the call's inputs go to a replay file
   !> first (its path is named, or why none could be written).
   subroutine umat_fail(code, severity, message, calculix, pnewdt, ddsdde, cmname, noel, npt, kinc, &
         props, statev, stress, sse, spd, stran, dstran, time, dtime, ndi, nshr)
      integer, intent(in) :: code, severity            !! STATUS_* and SEVERITY_* codes
      character(len=*), intent(in) :: message          !! what went wrong, with the values
      logical, intent(in) :: calculix                  !! the CalculiX host option is set
      real(dp), intent(inout) :: pnewdt, ddsdde(:, :)
      character(len=80), intent(in) :: cmname
      integer, intent(in) :: noel, npt, kinc, ndi, nshr
      real(dp), intent(in) :: props(:), statev(:), stress(:), sse, spd, stran(:), dstran(:), time(2), dtime
      character(len=2*MESSAGE_LEN) :: full
      character(len=:), allocatable :: replay, why
      if (.not. (pnewdt > 0.0_dp .and. pnewdt <= PNEWDT_CUTBACK)) pnewdt = PNEWDT_CUTBACK
      if (calculix) ddsdde = 0.0_dp
      write (full, '(a,a,i0,a,i0,a,a,a,a)') trim(cmname), ' element ', noel, ' point ', npt, &
         ': ', status_message(code), ': ', trim(message)
      ! (the host's name for NSTATV, which the shared STATEV reader cannot give: the C API and
      ! Python pass arrays)
      if (code == STATUS_BAD_NSTATV) full = trim(full)//' (the deck''s *DEPVAR)'
      call write_replay('umat', trim(full), props, statev, stress, sse, spd, stran, dstran, time, dtime, &
         noel, npt, kinc, replay, ndi, nshr, why)
      ! (the replay file's note after the message, whole: no fixed length cuts the path short)
      call interphase_host_message(severity, trim(full)//replay_note(replay, why))
   end subroutine umat_fail

end module interphase_umat_failure
