!> The history state of one interface point and its one load/store pair with Abaqus STATEV.
module interphase_state
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_params, only: SLIP_MAX, law_params_type
   use interphase_layout, only: SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, NSTATV_REQUIRED, &
      SV_DAMAGE_INVISCID, NSTATV_VISCOUS
   use interphase_enums, only: REGIME_INTACT, REGIME_SLIP
   use interphase_finite, only: HIGH_HALF, LOW_HALF, LOW_HALF_MASK
   use interphase_status, only: STATUS_OK, STATUS_BAD_STATE, STATUS_BAD_NSTATV, MESSAGE_LEN
   implicit none
   private
   public :: interface_state_type, state_unpack, state_pack, unpack_statev, pack_statev, count_invalid_states, state_slots
   ! (the bit-pattern constants below are public for the STATEV reader's second copy, in the
   ! UMAT: interphase_statev.inc)
   public :: ONE_BITS, SLIP_MAX_BITS, SIGN_BIT, REGIME_BITS

   !> Bit pattern of 1.0_dp.
   integer(int64), parameter :: ONE_BITS = int(z'3FF0000000000000', int64)
   !> Bit pattern of SLIP_MAX: a binary64 number x has |x| <= SLIP_MAX exactly when the bits of |x|
   !> (sign cleared) are at most these (NaN and Inf lie above every finite number).
   integer(int64), parameter :: SLIP_MAX_BITS = transfer(SLIP_MAX, 0_int64)
   !> Position of the sign bit of an IEEE binary64 number.
   integer, parameter :: SIGN_BIT = 63
   !> The bit patterns of the regime codes 0..3 as real numbers (constants: a `transfer` at run
   !> time is a library call with LLVM flang 19).
   integer(int64), parameter :: REGIME_BITS(REGIME_INTACT:REGIME_SLIP) = &
      transfer([0.0_dp, 1.0_dp, 2.0_dp, 3.0_dp], 0_int64, 4)

   !> History variables of one interface point.
   type :: interface_state_type
      real(dp) :: d = 0.0_dp                  !! damage D = a/b (-) the response uses: the history
                                              !! maximum, or with viscous regularisation D_v
      real(dp) :: slip(2) = 0.0_dp            !! frictional slip lambda (mm); slip(2) = 0 in 2-D
      integer :: regime = REGIME_INTACT       !! REGIME_* of the last update (output only)
      real(dp) :: d_inviscid = 0.0_dp         !! with viscous regularisation: the damage law's own
                                              !! D (history maximum), d <= d_inviscid <= 1
   end type interface_state_type

contains

   !> Read the state from STATEV, checking it: 0 <= D <= 1, slip |lambda_i| <= SLIP_MAX (finite),
   !> a known regime code.
   pure subroutine state_unpack(statev, ntens, state, status, message, viscous)
      real(dp), intent(in) :: statev(:)                  !! STATEV as given by the host
      integer, intent(in) :: ntens                       !! 2 (2-D) or 3 (3-D)
      type(interface_state_type), intent(out) :: state
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      !> the material has viscous regularisation: STATEV(SV_DAMAGE_INVISCID) is read too (default:
      !> not, and d_inviscid = d)
      logical, intent(in), optional :: viscous
      logical :: with_inviscid
      with_inviscid = .false.
      if (present(viscous)) with_inviscid = viscous
      call unpack_statev(size(statev), statev, ntens, with_inviscid, state, status, message)
   end subroutine state_unpack

   include 'interphase_binary64_bits.inc'
   ! (the STATEV reader and writer: the source is shared with the UMAT, which includes it where
   ! it can be inlined)
   include 'interphase_statev.inc'

   !> Number of STATEV slots a material's state takes: NSTATV_REQUIRED, or NSTATV_VISCOUS with
   !> viscous regularisation.
   pure integer function state_slots(params) result(n)
      type(law_params_type), intent(in) :: params
      n = merge(NSTATV_VISCOUS, NSTATV_REQUIRED, params%viscosity > 0.0_dp)
   end function state_slots

   !> Number of points whose incoming state `state_unpack` would refuse, for a host that holds a
   !> block of points column by column (the VUMAT): one branch-free pass that vectorises, so the
   !> culprit need be looked for only when the count is not zero. In 2-D (nt = 1) the values of
   !> lam2 are not used (the array must exist).
   pure integer function count_invalid_states(n, nt, d, lam1, lam2, regime) result(nbad)
      integer, intent(in) :: n, nt
      real(dp), intent(in) :: d(n), lam1(n), lam2(n), regime(n)
      integer(int64) :: bd, bl1, bl2, br, lam2_keep, nbad_bits
      integer :: k
      ! the bits of lam2 that count, without its sign: none in 2-D (lam2 read as +0 there)
      lam2_keep = merge(0_int64, huge(1_int64), nt == 1)
      nbad_bits = 0
      do k = 1, n
         ! every value loaded first and every test a 0/1 integer of the bit patterns' kind: a
         ! load or a logical operator behind a short-circuit would be a branch, and the loop would
         ! not vectorise; integers of another kind would cost conversions in every lane
         bd = transfer(d(k), 0_int64)
         bl1 = transfer(lam1(k), 0_int64)
         bl2 = iand(transfer(lam2(k), 0_int64), lam2_keep)
         br = transfer(regime(k), 0_int64)
         ! (an intact point, D = +-0, with a slip: unpack_statev refuses it. 0/1 integers combined
         ! by iand, not products: AVX2 has no 64-bit multiply)
         nbad_bits = nbad_bits + 1 - iand(iand(iand(damage_admissible(bd), slip_admissible(bl1)), &
            iand(slip_admissible(bl2), regime_known(br))), &
            ior(merge(1_int64, 0_int64, ibclr(bd, SIGN_BIT) /= 0_int64), &
            merge(1_int64, 0_int64, ior(ibclr(bl1, SIGN_BIT), bl2) == 0_int64)))
      end do
      nbad = int(nbad_bits)
   end function count_invalid_states

   !> 1 when bit pattern b is exactly the real number of a REGIME_* code, else 0.
   elemental integer(int64) function regime_known(b)
      integer(int64), intent(in) :: b
      integer :: candidate
      regime_known = 0
      do candidate = REGIME_INTACT, REGIME_SLIP
         regime_known = regime_known + merge(1_int64, 0_int64, b == REGIME_BITS(candidate))
      end do
   end function regime_known

   !> Store the state into STATEV (slots beyond NSTATV_REQUIRED, or NSTATV_VISCOUS with `viscous`,
   !> are left alone).
   pure subroutine state_pack(state, statev, viscous)
      type(interface_state_type), intent(in) :: state
      real(dp), intent(inout) :: statev(:)               !! STATEV, size >= NSTATV_REQUIRED
      logical, intent(in), optional :: viscous           !! write STATEV(SV_DAMAGE_INVISCID) too
      logical :: with_inviscid
      with_inviscid = .false.
      if (present(viscous)) with_inviscid = viscous
      call pack_statev(state, size(statev), statev, with_inviscid)
   end subroutine state_pack

end module interphase_state
