!> The UMAT's path for the micromechanical model's fracture-law call: the fracture-mechanics
!> damage law and no option constants (NPROPS = 12: the built-in table, or a custom table loaded
!> at start-up; the constant, the equivalent or, if it is loaded and covers D0, the tabulated
!> R-curve) on a 2-D cohesive element (NDI = 1, NSHR = 1, NTENS = 2). The same decision and
!> update as the other paths (interphase_umat_simplified_fracture for the simplified model),
!> from the same source (interphase_umat_cohesive_path.inc), in a unit of its own: update_point's
!> fracture-law step (fracture_update, interphase_fracture_update.inc, calling the general
!> path's grow_crack out of line), the response where the crack ran to b, and the outputs,
!> compiled for this material with NTENS and the option parameters constants. The numbers are
!> the general path's, bit for bit (tests/test_umat_simplified_path.f90); every other call,
!> every call the general path would refuse, and every call whose update fails is left to the
!> general path, which decides and reports. No module data; pure.
module interphase_umat_micromechanical_fracture
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite, is_finite_nonnegative, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, MAGNITUDE_MASK
   use interphase_params, only: law_params_type, SLIP_ONSET_ROUNDOFF, SLIP_MAX, SEPARATION_MAX, HOST_VALUE_MAX, &
      HOST_INCREMENT_MAX, DEFAULT_PARAMS, WINDOW_MIN_BITS, WINDOW_MAX_BITS, TWO_BITS, THREE_BITS, &
      D0_MIN_BITS
   use interphase_layout, only: NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, PROP_TABLE, &
      PROP_MODEL, PROP_DAMAGE_LAW, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, PROP_SF_T, PROP_K_N, PROP_K_T, &
      NPROPS_OPTIONS, LFM_D0, LFM_RCURVE, LFM_GC_I, LFM_GC_II, OPT_GROWTH_SLIP, OPT_CONTACT_BAND, OPT_VISCOSITY, &
      OPT_STIFFNESS, OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, OPT_HOST, OPTION_DEFAULTS, SV_DAMAGE, SV_SLIP_1, &
      SV_SLIP_2, SV_REGIME, SV_DAMAGE_INVISCID, NSTATV_REQUIRED, NSTATV_VISCOUS
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, RCURVE_TABULATED, GROWTH_FIXED_PI, STIFFNESS_SYMMETRIC, &
      STIFFNESS_FIXED_DAMAGE, REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP
   use interphase_status, only: STATUS_OK, STATUS_BAD_TIME_INCREMENT, STATUS_BAD_COEFFICIENTS, &
      STATUS_MODEL_UNAVAILABLE, STATUS_BAD_NSTATV, STATUS_BAD_STATE, STATUS_TABLE_NOT_LOADED, &
      STATUS_RCURVE_NOT_LOADED, STATUS_RCURVE_OUT_OF_RANGE, MESSAGE_LEN
   use interphase_state, only: interface_state_type, ONE_BITS, SLIP_MAX_BITS, SIGN_BIT, REGIME_BITS
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, micro_values, table_curvature_type, &
      custom_table_loaded
   use interphase_real_text, only: real_text
   use interphase_rcurve, only: rcurve_loaded, rcurve_covers, rcurve_coverage
   use interphase_damage, only: damage_terms_type
   use interphase_response, only: response_type, slip_measure
   use interphase_fracture, only: crack_load_type, growth_point_type, grow_crack
   implicit none
   private
   public :: cohesive_path

   !> The material the path serves: the micromechanical model, the fracture-mechanics law, no
   !> option constants.
   integer, parameter :: PATH_MODEL = MODEL_MICROMECHANICAL, PATH_DAMAGE_LAW = DAMAGE_FRACTURE, &
      PATH_NPROPS = NPROPS_MICROMECHANICAL + NPROPS_FRACTURE_EXTRA
   !> The element the path serves: 2-D cohesive (NDI = 1, NSHR = 1), as the other paths'.
   integer, parameter, public :: PATH_NTENS = 2

contains

   ! (the decision, the update and the procedures they call: one source for the four paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_micromechanical_fracture
