!> The response of one interface point at a fixed damage D (the paper's section 4 for a given
!> crack length): regime (intact, open, stick, slip), traction, tangent at fixed D, dt/dD, the
!> slip with its sensitivities, and the stored energy. Used by the update for both damage laws.
module interphase_response
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type, SLIP_ONSET_ROUNDOFF
   use interphase_enums, only: REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, GROWTH_FIXED_PI, MODEL_MICROMECHANICAL
   use interphase_status, only: STATUS_OK, STATUS_BAD_COEFFICIENTS
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS
   use interphase_provider, only: ufbar_at
   implicit none
   private
   public :: response_type, respond, growth_trial_slip, slip_measure, contact_band_shape, band_stiffness

   !> The response at fixed D. No default initialisation (this is on the hot path): `respond`
   !> sets the components 1:ntens of every field it returns.
   type :: response_type
      real(dp) :: traction(3)          !! t (MPa)
      real(dp) :: tangent(3, 3)        !! dt/ds at fixed D (MPa/mm)
      real(dp) :: dtrac_dd(3)          !! dt/dD at fixed s (MPa)
      real(dp) :: slip(2)              !! lambda (mm)
      real(dp) :: dlam_ds(2, 3)        !! d lambda/ds at fixed D (zero unless slipping)
      real(dp) :: dlam_dd(2)           !! d lambda/dD at fixed s (zero unless slipping)
      real(dp) :: psi                  !! stored energy (N/mm)
      integer :: regime                !! REGIME_*
      logical :: closed                !! crack closed (contact)
   end type response_type

contains

   !> m(D) = D ufbar(D) (-), which turns the faces' mean slip into the integrated slip
   !> pi = m lambda that crack growth conserves (0 at D = 0: no crack).
   pure subroutine slip_measure(params, d, m, status)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d                           !! damage D (-)
      real(dp), intent(out) :: m                          !! m(D) (-)
      integer, intent(out) :: status
      real(dp) :: ufbar
      status = STATUS_OK
      m = 0.0_dp
      if (.not. (d > 0.0_dp)) return
      ! (ufbar alone: the one coefficient m needs, not the set)
      call ufbar_at(params, d, ufbar, status)
      if (status == STATUS_OK) m = d*ufbar
   end subroutine slip_measure

   include 'interphase_response.inc'

end module interphase_response
