!> The coefficient set at a damage D from the model's provider (simplified formulas or the
!> micromechanical RVE table), with its first D-derivatives (and, on request, what the table
!> provider needs for the second: interphase_micro_coefficients' table_curvature_type); and the
!> check that the data a material needs at run time (a custom RVE table, a tabulated R-curve)
!> has been loaded, for hosts to make its absence a setup error rather than a failed update.
module interphase_provider
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text
   use interphase_params, only: law_params_type, constants_count
   use interphase_layout, only: PROP_TABLE, LFM_RCURVE
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, TABLE_CUSTOM_CODE, DAMAGE_FRACTURE, &
      RCURVE_TABULATED
   use interphase_status, only: STATUS_OK, STATUS_MODEL_UNAVAILABLE, STATUS_TABLE_NOT_LOADED, &
      STATUS_RCURVE_NOT_LOADED, STATUS_RCURVE_OUT_OF_RANGE, MESSAGE_LEN
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, micro_values, micro_ufbar, custom_table_loaded, &
      table_curvature_type
   use interphase_rcurve, only: rcurve_loaded, rcurve_covers, rcurve_coverage
   implicit none
   private
   public :: coefficients_at, coefficient_values_at, ufbar_at, check_run_time_data

   !> The model the included coefficient providers serve (interphase_coefficients_at.inc): every
   !> model, the one PROPS select.
   integer, parameter :: PROVIDER_MODEL = 0

contains

   include 'interphase_coefficients_at.inc'
   include 'interphase_coefficient_values_at.inc'

   !> ufbar(D) alone (-), the number coefficients_at's set holds (bit for bit), for the slip
   !> measure m = D ufbar; the same statuses.
   pure subroutine ufbar_at(params, d, ufbar, status)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d                                   !! damage D = a/b
      real(dp), intent(out) :: ufbar
      integer, intent(out) :: status
      select case (params%model)
      case (MODEL_SIMPLIFIED)
         ufbar = SIMPLIFIED_UFBAR
         status = STATUS_OK
      case (MODEL_MICROMECHANICAL)
         call micro_ufbar(params%table, d, ufbar, status)
      case default
         ufbar = 0.0_dp
         status = STATUS_MODEL_UNAVAILABLE
      end select
   end subroutine ufbar_at

   ! (the source is shared with the UMAT, which includes it where it can be inlined)
   include 'interphase_run_time_data.inc'

   ! the simplified model's coefficients, here where `coefficients_at` inlines them
   ! (interphase_coefficients' public one, from the same source)
   include 'interphase_simplified.inc'

end module interphase_provider
