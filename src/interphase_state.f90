!> The history state of one interface point and its one load/store pair with Abaqus STATEV.
module interphase_state
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_layout, only: SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, NSTATV_REQUIRED, &
      REGIME_INTACT, REGIME_SLIP
   use interphase_status, only: STATUS_OK, STATUS_BAD_STATE, STATUS_BAD_NSTATV, MESSAGE_LEN
   implicit none
   private
   public :: interface_state_type, state_unpack, state_pack

   !> History variables of one interface point.
   type :: interface_state_type
      real(dp) :: d = 0.0_dp                  !! damage D = a/b (-), history maximum
      real(dp) :: slip(2) = 0.0_dp            !! frictional slip lambda (mm); slip(2) = 0 in 2-D
      integer :: regime = REGIME_INTACT       !! REGIME_* of the last update (output only)
   end type interface_state_type

contains

   !> Read the state from STATEV, checking it: 0 <= D <= 1, finite slip, a known regime code.
   pure subroutine state_unpack(statev, ntens, state, status, message)
      real(dp), intent(in) :: statev(:)                  !! STATEV as given by the host
      integer, intent(in) :: ntens                       !! 2 (2-D) or 3 (3-D)
      type(interface_state_type), intent(out) :: state
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      integer :: regime, candidate

      status = STATUS_OK
      if (size(statev) < NSTATV_REQUIRED) then
         status = STATUS_BAD_NSTATV
         write (message, '(a,i0,a,i0)') 'NSTATV = ', size(statev), &
            ' but interphase needs at least ', NSTATV_REQUIRED
         return
      end if
      state%d = statev(SV_DAMAGE)
      state%slip(1) = statev(SV_SLIP_1)
      state%slip(2) = 0.0_dp
      if (ntens == 3) state%slip(2) = statev(SV_SLIP_2)
      ! the regime code, by bit pattern (no floating-point exception for NaN or a fraction)
      regime = -1
      do candidate = REGIME_INTACT, REGIME_SLIP
         if (transfer(statev(SV_REGIME), 0_int64) == transfer(real(candidate, dp), 0_int64)) regime = candidate
      end do
      state%regime = regime
      if (.not. in_unit_interval(state%d)) then
         status = STATUS_BAD_STATE
         write (message, '(a,i0,a,es12.5,a)') 'STATEV(', SV_DAMAGE, ') D = ', state%d, &
            ' must lie in [0, 1]'
      else if (.not. all(is_finite(state%slip))) then
         status = STATUS_BAD_STATE
         write (message, '(a,i0,a,i0,a)') 'STATEV(', SV_SLIP_1, ':', SV_SLIP_2, &
            ') slip is not finite'
      else if (regime < REGIME_INTACT) then
         status = STATUS_BAD_STATE
         write (message, '(a,i0,a,es12.5,a)') 'STATEV(', SV_REGIME, ') regime = ', &
            statev(SV_REGIME), ' is not a regime code 0..3'
      end if
   end subroutine state_unpack

   !> 0 <= x <= 1 (false for NaN without an invalid-operation exception).
   pure logical function in_unit_interval(x)
      real(dp), intent(in) :: x
      in_unit_interval = .false.
      if (is_finite(x)) in_unit_interval = x >= 0.0_dp .and. x <= 1.0_dp
   end function in_unit_interval

   !> Store the state into STATEV (slots beyond NSTATV_REQUIRED are left alone).
   pure subroutine state_pack(state, statev)
      type(interface_state_type), intent(in) :: state
      real(dp), intent(inout) :: statev(:)               !! STATEV, size >= NSTATV_REQUIRED
      statev(SV_DAMAGE) = state%d
      statev(SV_SLIP_1) = state%slip(1)
      statev(SV_SLIP_2) = state%slip(2)
      statev(SV_REGIME) = real(state%regime, dp)
   end subroutine state_pack

end module interphase_state
