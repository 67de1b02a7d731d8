!> The coefficient set at a damage D from the model's provider (simplified formulas or the
!> micromechanical RVE table), with its first and, on request, second D-derivatives.
module interphase_provider
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_layout, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL
   use interphase_status, only: STATUS_OK, STATUS_MODEL_UNAVAILABLE
   use interphase_coefficients, only: coefficient_set_type, simplified_coefficients
   use interphase_micro_coefficients, only: micro_coefficients
   implicit none
   private
   public :: coefficients_at

contains

   !> Coefficients at D (and d/dD; d2/dD2 when `d2c` is present).
   pure subroutine coefficients_at(params, d, c, dc, status, d2c)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d                                   !! damage D = a/b
      type(coefficient_set_type), intent(out) :: c, dc            !! coefficients and d/dD
      integer, intent(out) :: status
      type(coefficient_set_type), intent(out), optional :: d2c    !! d2/dD2
      select case (params%model)
      case (MODEL_SIMPLIFIED)
         call simplified_coefficients(params%k_n, params%k_t, d, c, dc)
         if (present(d2c)) d2c = coefficient_set_type()   ! linear in D
         status = STATUS_OK
      case (MODEL_MICROMECHANICAL)
         call micro_coefficients(params%table, d, c, dc, status, d2c)
      case default
         status = STATUS_MODEL_UNAVAILABLE
      end select
   end subroutine coefficients_at

end module interphase_provider
