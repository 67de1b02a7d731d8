!> The UMAT's path for its most common call: the simplified model with the displacement-driven
!> law and no option constants (NPROPS = 9) on a 2-D cohesive element (NDI = 1, NSHR = 1,
!> NTENS = 2). The UMAT calls `simplified_cohesive_path` first (where NPROPS = 9 and NTENS = 2);
!> it decides, in one place, whether the call is served here: only where every check of the
!> general path passes, made by the same procedures (the PROPS decoder's one-pass test, the
!> STATEV reader, the range tests of the host's values and of the separation). It then runs
!> update_point's displacement-driven update (the same statements and procedures, from the same
!> sources, in the same order: interphase_displacement_damage.inc, respond, update_outputs) and
!> writes the general path's outputs (cohesive_outputs, pack_statev), compiled here for that
!> material alone: NTENS and the option parameters are constants, the response is inlined, the
!> parameters and the state never leave this unit. The numbers are the general path's, bit for
!> bit (tests/test_umat_simplified_path.f90); every other call, and every call the general path
!> would refuse, is left to the general path, which decides and reports. No module data; pure.
module interphase_umat_simplified
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite, is_finite_nonnegative, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, MAGNITUDE_MASK
   use interphase_params, only: law_params_type, SLIP_ONSET_ROUNDOFF, SLIP_MAX, SEPARATION_MAX, HOST_VALUE_MAX, &
      HOST_INCREMENT_MAX, DEFAULT_PARAMS, WINDOW_MIN_BITS, WINDOW_MAX_BITS, TWO_BITS, THREE_BITS
   use interphase_layout, only: NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, PROP_TABLE, &
      PROP_MODEL, PROP_DAMAGE_LAW, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, PROP_SF_T, PROP_K_N, PROP_K_T, &
      NPROPS_OPTIONS, LFM_D0, LFM_RCURVE, LFM_GC_I, LFM_GC_II, OPT_GROWTH_SLIP, OPT_CONTACT_BAND, OPT_VISCOSITY, &
      OPT_STIFFNESS, OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, OPT_HOST, OPTION_DEFAULTS, SV_DAMAGE, SV_SLIP_1, &
      SV_SLIP_2, SV_REGIME, SV_DAMAGE_INVISCID, NSTATV_REQUIRED, NSTATV_VISCOUS
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      TABLE_DEFAULT_CODE, GROWTH_FIXED_PI, STIFFNESS_SYMMETRIC, STIFFNESS_FIXED_DAMAGE, REGIME_INTACT, REGIME_OPEN, &
      REGIME_STICK, REGIME_SLIP
   use interphase_status, only: STATUS_OK, STATUS_BAD_TIME_INCREMENT, STATUS_BAD_COEFFICIENTS, &
      STATUS_MODEL_UNAVAILABLE, STATUS_BAD_NSTATV, STATUS_BAD_STATE, MESSAGE_LEN
   use interphase_state, only: interface_state_type, ONE_BITS, SLIP_MAX_BITS, SIGN_BIT, REGIME_BITS
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, micro_values, table_curvature_type
   use interphase_damage, only: damage_terms_type
   use interphase_response, only: response_type, slip_measure
   implicit none
   private
   public :: simplified_cohesive_path

   !> The element the path serves: 2-D cohesive (NDI = 1, NSHR = 1). (The 3-D element in the
   !> same unit, measured: the response is then called from two places and no longer inlined,
   !> which costs the 2-D path about 170 instructions a call; docs/performance.md.)
   integer, parameter, public :: PATH_NTENS = 2

contains

   !> The simplified model's path for one UMAT call (its arguments as the UMAT receives them):
   !> `taken` where the call is served here, and then STRESS, DDSDDE, SSE, SPD and STATEV(1:4)
   !> are set as the general path sets them; else nothing has been written and the general path
   !> must run (it decides and reports). The call is taken only where it is the simplified model
   !> with the displacement-driven law and no option constants (NPROPS = 9) on a cohesive element
   !> (NDI = 1, NSHR = 1, NTENS = 2) and every check of the general path passes,
   !> made by the same procedures: the PROPS decoder, the STATEV reader, the host's values in
   !> range (STRAN, DSTRAN, STRESS, SSE, SPD), the separation in range. This is the one place
   !> that decides.
   pure subroutine simplified_cohesive_path(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, stress, &
         ddsdde, sse, spd, taken)
      integer, intent(in) :: nprops, ndi, nshr, ntens, nstatv    !! as the host passes them
      real(dp), intent(in) :: props(nprops)              !! PROPS
      real(dp), intent(inout) :: statev(nstatv)          !! STATEV
      real(dp), intent(in) :: stran(ntens), dstran(ntens)     !! STRAN, DSTRAN (mm)
      real(dp), intent(inout) :: stress(ntens)           !! STRESS (MPa)
      real(dp), intent(inout) :: ddsdde(ntens, ntens)    !! DDSDDE (MPa/mm)
      real(dp), intent(inout) :: sse, spd                !! SSE, SPD (N/mm)
      logical, intent(out) :: taken                      !! the call was served here

      type(law_params_type) :: params
      type(interface_state_type) :: old
      real(dp) :: s(3)
      integer :: status, k, model, damage_law, nprops_needed
      logical :: within, accepted
      character(len=MESSAGE_LEN) :: unused_message

      taken = .false.
      ! the decision
      if (.not. (nprops == NPROPS_SIMPLIFIED .and. ndi == 1 .and. nshr == 1 .and. ntens == PATH_NTENS)) return
      call accept_constants(nprops, props, model, damage_law, nprops_needed, accepted)
      if (.not. (accepted .and. model == MODEL_SIMPLIFIED .and. damage_law == DAMAGE_DISPLACEMENT)) return
      call unpack_statev(nstatv, statev, PATH_NTENS, .false., old, status, unused_message)
      if (status /= STATUS_OK) return
      within = is_within(sse, HOST_VALUE_MAX) .and. is_within(spd, HOST_VALUE_MAX)
      do k = 1, PATH_NTENS
         within = within .and. is_within(stran(k), HOST_INCREMENT_MAX) .and. &
            is_within(dstran(k), HOST_INCREMENT_MAX) .and. is_within(stress(k), HOST_VALUE_MAX)
         s(k) = stran(k) + dstran(k)
      end do
      if (.not. (within .and. all_within(PATH_NTENS, s, SEPARATION_MAX))) return
      ! the material, stored as decode_props stores it for PROPS without option constants
      call store_constants(nprops, props, model, damage_law, params)
      call store_options(OPTION_DEFAULTS, params)

      ! the update; on a status (none is reachable here: the general path would report it)
      ! nothing has been written
      call update_2d(params, old, s, dstran, stress, ddsdde, sse, spd, nstatv, statev, status)
      taken = status == STATUS_OK
   end subroutine simplified_cohesive_path

   !> update_point's displacement-driven update in 2-D (NTENS a named constant, so that the
   !> compiler specialises update_point's statements to it), and the UMAT's outputs of a cohesive
   !> element (STRESS, DDSDDE, SSE, SPD, STATEV). On a non-zero status nothing has been written.
   pure subroutine update_2d(params, old, s, dstran, stress, ddsdde, sse, spd, nstatv, statev, status, dt)
      integer, parameter :: ntens = PATH_NTENS
      type(law_params_type), intent(in) :: params        !! decoded from PROPS (checked)
      type(interface_state_type), intent(in) :: old      !! read from STATEV (checked)
      real(dp), intent(in) :: s(3)                       !! separation (mm), 1:2
      real(dp), intent(in) :: dstran(ntens)              !! DSTRAN (mm)
      real(dp), intent(inout) :: stress(ntens)           !! STRESS (MPa)
      real(dp), intent(inout) :: ddsdde(ntens, ntens)    !! DDSDDE (MPa/mm)
      real(dp), intent(inout) :: sse, spd                !! SSE, SPD (N/mm)
      integer, intent(in) :: nstatv                      !! NSTATV (>= NSTATV_REQUIRED)
      real(dp), intent(inout) :: statev(nstatv)          !! STATEV
      integer, intent(out) :: status
      !> the time increment, as update_point's (never present: without the option constants there
      !> is no viscous regularisation, which alone reads it)
      real(dp), intent(in), optional :: dt

      type(interface_state_type) :: new
      type(coefficient_set_type) :: c, dc
      type(response_type) :: r
      type(damage_terms_type) :: terms
      real(dp) :: s_n, st(2), t, t_sq, d_hat, dd_dsn, dd_dt, d, dd_ds(3), slip_trial(2), dslip_dd(2), m_from
      real(dp) :: d_law, traction(3), tangent(3, 3), psi
      integer :: nt
      logical :: grows

      ! update_point's statements for the displacement-driven law, in its order
      nt = ntens - 1
      s_n = s(1)
      st(1) = s(2)
      st(2) = 0.0_dp
      if (ntens == 3) st(2) = s(3)
      include 'interphase_displacement_damage.inc'
      call respond(params, c, dc, d, slip_trial, s_n, st, ntens, grows, r, status, dslip_dd)
      if (status /= STATUS_OK) return
      call update_outputs(params, d, grows, dd_ds, ntens, r, traction, tangent, new, psi)
      ! the UMAT's outputs, as its general path writes them
      call cohesive_outputs(ntens, .true., traction, tangent, psi, dstran, stress, ddsdde, sse, spd)
      call pack_statev(new, nstatv, statev, .false.)
   end subroutine update_2d

   ! the PROPS decoder (interphase_params'), the STATEV reader and writer (interphase_state's),
   ! the range tests (interphase_finite's), the update's procedures (interphase_kernel's) and the
   ! UMAT's outputs, from the same sources: private copies
   include 'interphase_binary64_bits.inc'
   include 'interphase_within.inc'
   include 'interphase_props_stores.inc'
   include 'interphase_statev.inc'
   include 'interphase_response.inc'
   include 'interphase_damage.inc'
   include 'interphase_coefficients_at.inc'
   include 'interphase_coefficient_values_at.inc'
   include 'interphase_simplified.inc'
   include 'interphase_update_outputs.inc'
   include 'interphase_cohesive_outputs.inc'

end module interphase_umat_simplified
