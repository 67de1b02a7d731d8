!> The names the UMAT's paths use (interphase_umat_simplified, interphase_umat_micromechanical,
!> interphase_umat_simplified_fracture, interphase_umat_micromechanical_fracture for the 2-D
!> cohesive element, and their 3-D twins, the same names with _3d): the procedures
!> and constants that their shared source, interphase_umat_cohesive_path.inc, and the sources it
!> includes need, in one list, re-exported, so that each path's unit uses this module alone. No
!> data, no procedures.
module interphase_umat_path_names
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
   use interphase_closing, only: closing_slip, add_closing_share
   implicit none
   private
   public :: int64, dp, is_finite, is_finite_nonnegative, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, &
      MAGNITUDE_MASK, law_params_type, SLIP_ONSET_ROUNDOFF, SLIP_MAX, SEPARATION_MAX, HOST_VALUE_MAX, &
      HOST_INCREMENT_MAX, DEFAULT_PARAMS, WINDOW_MIN_BITS, WINDOW_MAX_BITS, TWO_BITS, THREE_BITS, &
      D0_MIN_BITS, NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, PROP_TABLE, &
      PROP_MODEL, PROP_DAMAGE_LAW, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, PROP_SF_T, PROP_K_N, &
      PROP_K_T, NPROPS_OPTIONS, LFM_D0, LFM_RCURVE, LFM_GC_I, LFM_GC_II, OPT_GROWTH_SLIP, &
      OPT_CONTACT_BAND, OPT_VISCOSITY, OPT_STIFFNESS, OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, OPT_HOST, &
      OPTION_DEFAULTS, SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, SV_DAMAGE_INVISCID, NSTATV_REQUIRED, &
      NSTATV_VISCOUS, MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, RCURVE_TABULATED, GROWTH_FIXED_PI, STIFFNESS_SYMMETRIC, &
      STIFFNESS_FIXED_DAMAGE, REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, STATUS_OK, &
      STATUS_BAD_TIME_INCREMENT, STATUS_BAD_COEFFICIENTS, STATUS_MODEL_UNAVAILABLE, STATUS_BAD_NSTATV, &
      STATUS_BAD_STATE, STATUS_TABLE_NOT_LOADED, STATUS_RCURVE_NOT_LOADED, STATUS_RCURVE_OUT_OF_RANGE, &
      MESSAGE_LEN, interface_state_type, ONE_BITS, SLIP_MAX_BITS, SIGN_BIT, REGIME_BITS, &
      coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR, micro_coefficients, micro_values, &
      table_curvature_type, custom_table_loaded, real_text, rcurve_loaded, rcurve_covers, &
      rcurve_coverage, damage_terms_type, response_type, slip_measure, crack_load_type, &
      growth_point_type, grow_crack, closing_slip, add_closing_share
end module interphase_umat_path_names
