!> The update of one interface point (the paper's section 4), written once against the
!> coefficient set of `interphase_coefficients`, for every coefficient provider, in 2-D
!> (s_N, s_T) and 3-D (s_N, s_T1, s_T2; isotropic in the interface plane, vector slip), with
!> either damage law.
!>
!> Component order everywhere is Abaqus's for cohesive elements: normal first, then the
!> shear(s). Separations in mm, tractions in MPa, tangent in MPa/mm, energy in N/mm.
!>
!> The response at a given damage D (`respond`):
!>   D = 0: intact, t = k s.
!>   mean crack opening dbar_n s_N > 0, i.e. s_N > 0 (dbar_n > 0 for every crack): open crack,
!>   t = k s, crack faces free, the slip
!>   follows the mean tangential jump: lambda = dbar_t s_T / ufbar.
!>   otherwise closed: trial crack stresses sigma = sc_n s_N, tau = tc_t s_T + T^f lambda_n,
!>   phi = mu sigma + |tau| (eq 43); phi <= 0 (or within its round-off, SLIP_ONSET_ROUNDOFF):
!>   stick; phi > 0: slip, return mapping along
!>   tau_trial (eqs 44-48): lambda = lambda_n + (phi/(-T^f)) tau/|tau| (and a second step that
!>   takes tau at that slip onto the cone to round-off).
!>   t_N = (k_n + kc_n) s_N, t_T = (k_t + kc_t) s_T + C^f_T lambda.
!> The damage:
!>   displacement-driven law (eqs 13-18, 39): D = max(D_n, min(1, D^(s))), independent of
!>   contact and friction, so it comes first;
!>   fracture-mechanics law (eqs 20-24, 40-42, 49-50): D from g(D) = 0 (interphase_fracture);
!>   open crack: predictor D_n, corrector by a bracketed root; closed crack: the staggered
!>   scheme of section 4.2 (damage with lambda frozen, friction with D frozen) solved for its
!>   fixed point as a bracketed root in D, each trial D running the friction return mapping.
!> The consistent tangent adds (dt/dD)(dD/ds) while the crack grows (for the fracture law with
!> dD/ds from the implicit function g = 0, including the slip's dependence on s and D).
!> Stored energy: open or intact psi = 1/2 t.s; closed psi = 1/2 t.s + 1/2 C^f lambda.s_T
!> - 1/2 D T^f ufbar |lambda|^2 (docs/theory.md).
module interphase_kernel
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_finite, only: is_finite, is_finite_nonnegative, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, MAGNITUDE_MASK
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type, SEPARATION_MAX, SLIP_ONSET_ROUNDOFF
   use interphase_enums, only: DAMAGE_DISPLACEMENT, GROWTH_FIXED_PI, STIFFNESS_SYMMETRIC, STIFFNESS_FIXED_DAMAGE, &
      REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_NONFINITE_SEPARATION, STATUS_BAD_TIME_INCREMENT, &
      STATUS_SEPARATION_OUT_OF_RANGE, STATUS_BAD_COEFFICIENTS, STATUS_MODEL_UNAVAILABLE
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, micro_values, table_curvature_type
   use interphase_damage, only: damage_terms_type
   use interphase_fracture, only: crack_load_type, growth_point_type, grow_crack
   use interphase_response, only: response_type, slip_measure
   use interphase_closing, only: closing_slip, add_closing_share
   use interphase_state, only: interface_state_type
   implicit none
   private
   public :: interface_update, update_point, closes_within

   !> The model the included coefficient providers serve (interphase_coefficients_at.inc): every
   !> model, the one PROPS select.
   integer, parameter :: PROVIDER_MODEL = 0

contains

   !> Update one interface point from the old state and the separation at the end of the
   !> increment. On a non-zero status the outputs are undefined and must not be used.
   pure subroutine interface_update(params, old, s, traction, tangent, new, psi, status, dt, s_old)
      type(law_params_type), intent(in) :: params        !! material parameters
      type(interface_state_type), intent(in) :: old      !! state at the start of the increment
      real(dp), intent(in) :: s(:)                       !! separation (s_N, s_T[, s_T2]) (mm)
      real(dp), intent(out) :: traction(:)               !! traction, same order (MPa)
      real(dp), intent(out) :: tangent(:, :)             !! dtraction/ds (MPa/mm), unsymmetric
      type(interface_state_type), intent(out) :: new     !! state at the end of the increment
      real(dp), intent(out) :: psi                       !! stored energy per unit area (N/mm)
      integer, intent(out) :: status                     !! STATUS_OK or a failure code
      !> time increment (s): needed with viscous regularisation (params%viscosity > 0), where it
      !> must be finite and >= 0 (else STATUS_BAD_TIME_INCREMENT); not used otherwise
      real(dp), intent(in), optional :: dt
      !> separation at the start of the increment (mm), same order and size as s: where the
      !> state at the start is open and the crack closes within the increment, the friction
      !> step starts from the slip where s_N passed through zero on the straight path from s_old
      !> to s (docs/theory.md, 'An increment across which the crack closes'); without it, from
      !> the state's slip
      real(dp), intent(in), optional :: s_old(:)

      real(dp) :: s3(3), traction3(3), tangent3(3, 3), s_old3(3)
      integer :: ntens, j

      ntens = size(s)
      if (ntens /= 2 .and. ntens /= 3) then
         status = STATUS_BAD_NTENS
         return
      end if
      s3(1) = s(1)
      s3(2) = s(2)
      if (ntens == 3) s3(3) = s(3)
      if (present(s_old)) then
         if (size(s_old) /= ntens) then
            status = STATUS_BAD_NTENS
            return
         end if
         if (.not. all_within(ntens, s_old, SEPARATION_MAX)) then
            status = merge(STATUS_SEPARATION_OUT_OF_RANGE, STATUS_NONFINITE_SEPARATION, all(is_finite(s_old)))
            return
         end if
         s_old3(1) = s_old(1)
         s_old3(2) = s_old(2)
         s_old3(3) = 0.0_dp
         if (ntens == 3) s_old3(3) = s_old(3)
         call update_point(params, old, ntens, s3, traction3, tangent3, new, psi, status, dt, s_old3)
      else
         call update_point(params, old, ntens, s3, traction3, tangent3, new, psi, status, dt)
      end if
      if (status /= STATUS_OK) return
      ! (component by component, the 2-D and 3-D cases written apart: with array sections of a
      ! run-time extent GCC's link-time inlining warns of writes beyond a caller's arrays)
      traction(1) = traction3(1)
      traction(2) = traction3(2)
      if (ntens == 2) then
         tangent(1, 1) = tangent3(1, 1)
         tangent(2, 1) = tangent3(2, 1)
         tangent(1, 2) = tangent3(1, 2)
         tangent(2, 2) = tangent3(2, 2)
      else
         traction(3) = traction3(3)
         do j = 1, 3
            tangent(1:3, j) = tangent3(1:3, j)
         end do
      end if
   end subroutine interface_update

   !> `interface_update` on arrays of fixed size (the first NTENS components used), assigning
   !> every component of `new`: no descriptors and no default initialisation at the call (the
   !> UMAT's entry). On a non-zero status the outputs are undefined and must not be used.
   pure subroutine update_point(params, old, ntens, s, traction, tangent, new, psi, status, dt, s_old)
      type(law_params_type), intent(in) :: params        !! material parameters
      type(interface_state_type), intent(in) :: old      !! state at the start of the increment
      integer, intent(in) :: ntens                       !! 2 (s_N, s_T) or 3 (s_N, s_T1, s_T2)
      real(dp), intent(in) :: s(3)                       !! separation (s_N, s_T[, s_T2]) (mm)
      real(dp), intent(out) :: traction(3)               !! traction, same order (MPa)
      real(dp), intent(out) :: tangent(3, 3)             !! dtraction/ds (MPa/mm), unsymmetric
      type(interface_state_type), intent(inout) :: new   !! state at the end of the increment
      real(dp), intent(out) :: psi                       !! stored energy per unit area (N/mm)
      integer, intent(out) :: status                     !! STATUS_OK or a failure code
      !> time increment (s), as for `interface_update`
      real(dp), intent(in), optional :: dt
      !> the separation at the start of the increment (mm, the first NTENS components), as
      !> interface_update's s_old; absent, or not finite within SEPARATION_MAX: not known
      real(dp), intent(in), optional :: s_old(3)

      type(coefficient_set_type) :: c, dc
      type(response_type) :: r
      type(growth_point_type) :: at(2)          ! the fracture law's root search's evaluations
      type(damage_terms_type) :: terms
      real(dp) :: s_n, st(2), t, t_sq, d_hat, dd_dsn, dd_dt, d, dd_ds(3), slip_trial(2), dslip_dd(2), m_from
      real(dp) :: d_law
      ! the slip the friction step starts from (interphase_law_update.inc's): lambda_n, or for a
      ! crack that closes within the increment the slip where its faces met
      real(dp) :: slip_from(2), dfrom_ds(2, 3), d_start, m_start, d_from, dd_from_ds(3), dm_from
      logical :: closing
      integer :: nt, which
      !> the damage law's D is on its growing branch (displacement law: D_law < D^ < 1; fracture
      !> law: D_n < D < 1), the only case where dD/ds can be non-zero and the tangent needs dt/dD
      !> (D can change otherwise too: a jump to 1, viscous relaxation; dD/ds is 0 there)
      logical :: grows
      !> the response at D is still to be formed (by `respond`, from c, dc and the trial slip):
      !> the displacement law, and the fracture law's crack that ran to b
      logical :: form_response

      nt = ntens - 1
      if (ntens /= 2 .and. ntens /= 3) then
         status = STATUS_BAD_NTENS
         return
      end if
      ! finite and within |s_i| <= SEPARATION_MAX (beyond, the arithmetic would overflow:
      ! interphase_params), in one pass; which of the two failed is looked at only on failure
      if (.not. all_within(ntens, s, SEPARATION_MAX)) then
         status = merge(STATUS_SEPARATION_OUT_OF_RANGE, STATUS_NONFINITE_SEPARATION, all(is_finite(s(1:ntens))))
         return
      end if
      ! the slip the friction step starts from: lambda_n, or where the crack closes within the
      ! increment (open at its start, s_N,n > 0, closed at its end) the slip where s_N passed
      ! through zero (closes_within decides, interphase_closes_within.inc; interphase_closing
      ! forms it). (The regime first, as an integer: the one test most calls stop at.)
      slip_from = old%slip
      d_from = old%d
      closing = .false.
      if (present(s_old)) then
         if (old%regime == REGIME_OPEN) closing = closes_within(real(REGIME_OPEN, dp), old%d, s_old(1), s(1))
         ! (a start beyond the separation's range, which a host's STRAN may hold, is taken as not
         ! known: the start slip is formed from it only where its arithmetic is the separation's)
         if (closing) closing = all_within(ntens, s_old, SEPARATION_MAX)
         if (closing) then
            s_n = s(1)
            st(1) = s(2)
            st(2) = 0.0_dp
            if (ntens == 3) st(2) = s(3)
            call closing_slip(params, old, s_old, s_n, st(1), st(2), ntens, slip_from, dfrom_ds, d_from, dd_from_ds, &
               dm_from, status)
            if (status /= STATUS_OK) return
         end if
      end if
      ! the damage law's step, the response and the outputs (one source with the UMAT's paths)
      ! (update_law: interphase_law_update.inc's name of the damage law, DAMAGE_*)
      associate (update_law => params%damage_law)
         include 'interphase_law_update.inc'
      end associate
   end subroutine update_point

   ! the fracture-mechanics law's step (one source with the UMAT's paths,
   ! interphase_umat_cohesive_path.inc)
   include 'interphase_fracture_update.inc'

   ! the separation's range test, here where the compiler inlines it (interphase_finite's, from
   ! the same source)
   include 'interphase_binary64_bits.inc'
   include 'interphase_within.inc'
   ! the response at fixed D, here where the compiler inlines it into the update
   ! (interphase_response's, from the same source: a private copy)
   include 'interphase_response.inc'
   include 'interphase_closes_within.inc'
   ! the displacement law, here where the compiler inlines it into the update (interphase_damage's,
   ! from the same source: a private copy)
   include 'interphase_damage.inc'
   ! the coefficient set at D, here where the compiler inlines it into the update
   ! (interphase_provider's, from the same source: private copies)
   include 'interphase_coefficients_at.inc'
   include 'interphase_coefficient_values_at.inc'
   include 'interphase_simplified.inc'
   include 'interphase_update_outputs.inc'

end module interphase_kernel
