!> The coefficient set at a damage D from the model's provider (simplified formulas or the
!> micromechanical RVE table), with its first and, on request, second D-derivatives; and the
!> check that the data a material needs at run time (a custom RVE table, a tabulated R-curve)
!> has been loaded, for hosts to make its absence a setup error rather than a failed update.
module interphase_provider
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text
   use interphase_params, only: law_params_type
   use interphase_layout, only: PROP_TABLE
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, TABLE_CUSTOM_CODE, DAMAGE_FRACTURE, &
      RCURVE_TABULATED
   use interphase_status, only: STATUS_OK, STATUS_MODEL_UNAVAILABLE, STATUS_TABLE_NOT_LOADED, &
      STATUS_RCURVE_NOT_LOADED, STATUS_RCURVE_OUT_OF_RANGE, MESSAGE_LEN
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, micro_ufbar, custom_table_loaded
   use interphase_rcurve, only: rcurve_loaded, rcurve_covers, rcurve_coverage
   implicit none
   private
   public :: coefficients_at, ufbar_at, check_run_time_data

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
         if (present(d2c)) d2c = NO_COEFFICIENTS   ! linear in D
         status = STATUS_OK
      case (MODEL_MICROMECHANICAL)
         call micro_coefficients(params%table, d, c, dc, status, d2c)
      case default
         status = STATUS_MODEL_UNAVAILABLE
      end select
   end subroutine coefficients_at

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
         status = STATUS_MODEL_UNAVAILABLE
      end select
   end subroutine ufbar_at

   !> STATUS_OK when the data `params` needs at run time is loaded; else STATUS_TABLE_NOT_LOADED
   !> (micromechanical model on the custom table) or STATUS_RCURVE_NOT_LOADED (fracture law with
   !> the tabulated R-curve), with a message that says how to load it, or
   !> STATUS_RCURVE_OUT_OF_RANGE when the loaded R-curve does not cover D0 (naming file and D0). Called by the UMAT at every
   !> update: two integer tests when all is well (`message` is then left alone, not blanked).
   pure subroutine check_run_time_data(params, status, message)
      type(law_params_type), intent(in) :: params
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(inout) :: message
      integer :: ios
      status = STATUS_OK
      if (params%model == MODEL_MICROMECHANICAL .and. params%table == TABLE_CUSTOM_CODE) then
         if (.not. custom_table_loaded()) then
            status = STATUS_TABLE_NOT_LOADED
            write (message, '(a,i0,a)') 'PROPS(', PROP_TABLE, ') = 1 selects the custom RVE table, but none was '// &
               'loaded at start-up: set INTERPHASE_TABLE to the table file and link uexternaldb (Abaqus/Standard) '// &
               'or vexternaldb (Abaqus/Explicit), docs/abaqus.md'
            return
         end if
      end if
      if (params%damage_law == DAMAGE_FRACTURE .and. params%rcurve == RCURVE_TABULATED) then
         if (.not. rcurve_loaded()) then
            status = STATUS_RCURVE_NOT_LOADED
            message = 'the R-curve selector 3 selects the tabulated R-curve, but none was loaded at start-up: '// &
               'set INTERPHASE_RCURVE to the R-curve file and link uexternaldb (Abaqus/Standard) or vexternaldb '// &
               '(Abaqus/Explicit), docs/abaqus.md'
         else if (.not. rcurve_covers(params%d0)) then
            status = STATUS_RCURVE_OUT_OF_RANGE
            write (message, '(a,a,a)', iostat=ios) rcurve_coverage(), ', not the initial crack D0 = ', real_text(params%d0, 6)
         end if
      end if
   end subroutine check_run_time_data

   ! the simplified model's coefficients, here where `coefficients_at` inlines them
   ! (interphase_coefficients' public one, from the same source)
   include 'interphase_simplified.inc'

end module interphase_provider
