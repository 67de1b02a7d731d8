!> The fracture-mechanics damage law (paper eqs 20-24, 40-42, 49-50): energy release rates of
!> the RVE at fixed separation (and, when the crack is closed, fixed crack-face slip), the
!> R-curves, the growth function g = G_I/(2 G_cI) + G_II/(2 G_cII) - 1 (eq 24 with the
!> toughness per unit crack area) and the crack-growth solve.
!>
!> Conventions (docs/theory.md): energies per unit interface area; G per unit advance of the
!> half-length a and unit RVE width, as in eq 20: G = -d(U/w)/da = -2 d(psi)/dD with
!> U/w = 2b psi (V/w = 2b h). A two-tip crack makes the area 2 w da, so the release per unit
!> crack area is G/2: the toughness G_c (PROPS, R-curve files) is energy per unit crack area,
!> as experiments report it, and the crack grows where G/2 = G_c. The damage dissipation per
!> unit interface area is then G_c dD.
!> Open crack (eq 40): G_I = -k_n' s_N^2 (only while s_N > 0), G_II = -k_t' |s_T|^2.
!> Closed crack: the RVE energy also holds the crack faces' share,
!>   psi = 1/2 kk_n s_N^2 + 1/2 kk_t |s_T|^2 + C^f lambda.s_T - 1/2 q |lambda|^2,  q = D T^f ufbar,
!> all mode II (s_N <= 0). With m = D ufbar and the integrated slip pi = m lambda held fixed
!> (GROWTH_FIXED_PI, the default),
!>   G = -(kk_n' s_N^2 + kk_t' |s_T|^2) - 2 A lambda.s_T + B |lambda|^2,
!>   A = C^f' - C^f m'/m = m (C^f/m)',  B = T^f' m - T^f m' = m^2 (T^f/m)';
!> with lambda held fixed (GROWTH_FIXED_LAMBDA, the paper's) A = C^f' and B = q'. Eq 49 keeps
!> only the first part (from 1/2 Sigma.E); the rest is the work of the crack-face tractions,
!> without which the energy balance fails (docs/theory.md).
module interphase_fracture
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_enums, only: RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED, GROWTH_FIXED_PI, &
      MODEL_MICROMECHANICAL
   use interphase_status, only: STATUS_OK, STATUS_STAGGER_NOT_CONVERGED
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS
   use interphase_provider, only: coefficients_at
   use interphase_rcurve, only: tabulated_rcurve
   use interphase_response, only: response_type, respond, growth_trial_slip, slip_measure, contact_band_shape, &
      band_stiffness
   implicit none
   private
   public :: crack_load_type, growth_function, grow_crack

   !> What the crack sees in the increment: the separation at its end and the slip at its
   !> start (the friction step at each trial D starts from it, or from the slip that conserves
   !> pi = m lambda: `growth_trial_slip`).
   type :: crack_load_type
      real(dp) :: s_n = 0.0_dp            !! normal separation (mm)
      real(dp) :: st(2) = 0.0_dp          !! tangential separation (mm)
      real(dp) :: slip_old(2) = 0.0_dp    !! frictional slip lambda_n at the start (mm)
      real(dp) :: d_from = 0.0_dp         !! damage at the start, D_n (-)
      real(dp) :: m_from = 0.0_dp         !! m(D_n) = D_n ufbar(D_n) (-); set by grow_crack when the crack grows
   end type crack_load_type

   !> Geometric scan towards D = 1 before the bracketed solve: points per run.
   integer, parameter :: N_SCAN = 12
   !> The scan's last point: 1 - D is reduced by this factor.
   real(dp), parameter :: SCAN_DEPTH = 1.0e-7_dp
   !> Root tolerance in D and the largest number of Illinois steps.
   real(dp), parameter :: ROOT_TOL = 1.0e-15_dp
   integer, parameter :: MAX_ROOT_ITERATIONS = 200

contains

   !> g(D) of eq 24 for the increment's separation: the friction step at D (D frozen) gives the
   !> slip lambda(D), then the release rates at D with that slip (lambda frozen). With
   !> `want_derivatives`, also the partial derivatives dg/ds (Abaqus order, normal first),
   !> dg/dlambda and dg/dD at fixed lambda (these need the coefficients' second derivatives);
   !> the caller adds the slip's dependence.
   pure subroutine growth_function(params, d, load, ntens, g, status, want_derivatives, g_s, g_lam, g_d)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d
      type(crack_load_type), intent(in) :: load
      integer, intent(in) :: ntens
      real(dp), intent(out) :: g
      integer, intent(out) :: status
      logical, intent(in) :: want_derivatives
      real(dp), intent(out) :: g_s(3), g_lam(2), g_d

      type(coefficient_set_type) :: c, dc, d2c
      type(response_type) :: r
      real(dp) :: slip(2), slip_trial(2), dslip_dd(2)
      logical :: closed
      real(dp) :: t2, gi, gii, gi_s(3), gii_s(3), gii_lam(2), gi_d, gii_d
      real(dp) :: gc(2), dgc(2), sig_n, sig_t, dsig_n, dsig_t, a1, a2, b1, b2, lam_s, lam2, kappa, dkappa
      real(dp) :: band_g, band_grad(3), q, dq, d2q
      logical :: in_band
      integer :: nt

      nt = ntens - 1
      g_s = 0.0_dp
      g_lam = 0.0_dp
      g_d = 0.0_dp
      if (want_derivatives) then
         call coefficients_at(params, d, c, dc, status, d2c)
      else
         call coefficients_at(params, d, c, dc, status)
         d2c = NO_COEFFICIENTS
      end if
      if (status /= STATUS_OK) return
      t2 = load%st(1)**2 + load%st(2)**2
      ! friction with D frozen, from the slip the crack faces carry at D
      call growth_trial_slip(params%growth_slip, load%d_from, load%m_from, d, c, dc, load%slip_old, &
         slip_trial, dslip_dd)
      call respond(params, c, dc, d, slip_trial, load%s_n, load%st, ntens, r, status)
      if (status /= STATUS_OK) return
      closed = r%closed
      slip = r%slip
      ! the contact band (open crack, 0 < s_N < chi |s_T|): psi holds 1/2 q g, so G_II holds -q' g
      in_band = .false.
      if (params%contact_band > 0.0_dp .and. params%model == MODEL_MICROMECHANICAL .and. .not. closed &
         .and. params%rcurve /= RCURVE_EQUIVALENT) then
         call contact_band_shape(params%contact_band, load%s_n, load%st, ntens, in_band, band_g, band_grad)
         if (in_band) call band_stiffness(c, dc, d2c, q, dq, d2q)
      end if

      if (params%rcurve == RCURVE_EQUIVALENT .and. .not. closed) then
         ! G/G_c with G_c = -k' sigma(D)^2: the provider's k' cancels, g = sum (s/sigma(D))^2 - 1
         call equivalent_scale(params%s0_n, params%eta_n, d, sig_n, dsig_n)
         call equivalent_scale(params%s0_t, params%eta_t, d, sig_t, dsig_t)
         gi = 0.0_dp
         if (load%s_n > 0.0_dp) gi = (load%s_n/sig_n)**2
         gii = t2/sig_t**2
         g = gi + gii - 1.0_dp
         if (want_derivatives) then
            if (load%s_n > 0.0_dp) g_s(1) = 2.0_dp*load%s_n/sig_n**2
            g_s(2:ntens) = 2.0_dp*load%st(1:nt)/sig_t**2
            g_d = -2.0_dp*gi*dsig_n/sig_n - 2.0_dp*gii*dsig_t/sig_t
         end if
         ! In the contact band G_II = -(k_t' + q'(1 - W)) |s_T|^2 and the equivalent R-curve's
         ! G_cII = -(k_t' + q'(1 - W)) sigma_T^2, so g is the same: it goes over continuously into
         ! the closed crack's (G_cII = kappa sigma_T^2, kappa = -(k_t' + q') in pure mode II), and
         ! the law stays equivalent to the displacement law, whose D the band does not change.
         return
      end if

      ! energy release rates (eq-20 convention) and their derivatives
      gi_s = 0.0_dp
      gii_s = 0.0_dp
      gii_lam = 0.0_dp
      gi_d = 0.0_dp
      if (.not. closed) then
         gi = 0.0_dp
         if (load%s_n > 0.0_dp) then
            gi = -dc%k_n*load%s_n**2
            gi_s(1) = -2.0_dp*dc%k_n*load%s_n
            gi_d = -d2c%k_n*load%s_n**2
         end if
         gii = -dc%k_t*t2
         gii_s(2:ntens) = -2.0_dp*dc%k_t*load%st(1:nt)
         gii_d = -d2c%k_t*t2
         if (in_band) then
            gii = gii - dq*band_g
            gii_s(1:ntens) = gii_s(1:ntens) - dq*band_grad(1:ntens)
            gii_d = gii_d - d2q*band_g
         end if
      else
         call closed_release_factors(params%growth_slip, c, dc, d2c, d, a1, b1, a2, b2)
         lam_s = slip(1)*load%st(1) + slip(2)*load%st(2)
         lam2 = slip(1)**2 + slip(2)**2
         gi = 0.0_dp
         gii = -((dc%k_n + dc%kc_n)*load%s_n**2 + (dc%k_t + dc%kc_t)*t2) - 2.0_dp*a1*lam_s + b1*lam2
         gii_s(1) = -2.0_dp*(dc%k_n + dc%kc_n)*load%s_n
         gii_s(2:ntens) = -2.0_dp*(dc%k_t + dc%kc_t)*load%st(1:nt) - 2.0_dp*a1*slip(1:nt)
         gii_lam(1:nt) = -2.0_dp*a1*load%st(1:nt) + 2.0_dp*b1*slip(1:nt)
         gii_d = -((d2c%k_n + d2c%kc_n)*load%s_n**2 + (d2c%k_t + d2c%kc_t)*t2) - 2.0_dp*a2*lam_s &
            + b2*lam2
      end if

      ! R-curve
      select case (params%rcurve)
      ! gc is the toughness in the eq-20 convention of G: twice the toughness per unit crack
      ! area that PROPS and R-curve files give
      case (RCURVE_CONSTANT)
         gc = 2.0_dp*[params%gc_i, params%gc_ii]
         dgc = 0.0_dp
      case (RCURVE_TABULATED)
         call tabulated_rcurve(d, gc, dgc, status)
         if (status /= STATUS_OK) return
         gc = 2.0_dp*gc
         dgc = 2.0_dp*dgc
      case default     ! RCURVE_EQUIVALENT, closed crack (mode II only)
         ! In pure mode II (s_N = 0) the closed crack slips without friction, tau = 0:
         ! lambda = -(T^c_T/T^f) s_T, and G_II = kappa s_T^2 with
         ! kappa = -kk_t' + 2 A (T^c_T/T^f) + B (T^c_T/T^f)^2. The equivalent R-curve of the
         ! closed crack is therefore G_cII = kappa(D) sigma_T(D)^2 (for the simplified model
         ! kappa = K_T = -k_t', the open crack's value, with either growth-slip rule).
         call equivalent_scale(params%s0_t, params%eta_t, d, sig_t, dsig_t)
         call closed_mode_two_stiffness(params%growth_slip, c, dc, d2c, d, kappa, dkappa)
         gc = [1.0_dp, kappa*sig_t**2]
         dgc = [0.0_dp, dkappa*sig_t**2 + 2.0_dp*kappa*sig_t*dsig_t]
      end select

      ! gi = 0 when the crack is closed or s_N <= 0 (no mode-I term then)
      g = gii/gc(2) - 1.0_dp
      if (abs(gi) > 0.0_dp) g = g + gi/gc(1)
      if (want_derivatives) then
         g_s = gii_s/gc(2)
         g_lam = gii_lam/gc(2)
         g_d = (gii_d*gc(2) - gii*dgc(2))/gc(2)**2
         if (abs(gi) > 0.0_dp) then
            g_s = g_s + gi_s/gc(1)
            g_d = g_d + (gi_d*gc(1) - gi*dgc(1))/gc(1)**2
         end if
      end if
   end subroutine growth_function

   !> The factors of the closed crack's release rate, G_II = -kk' s.s - 2 A lambda.s_T + B |lambda|^2,
   !> and their derivatives d/dD (a2 = A', b2 = B'; they need the second derivatives d2c, which
   !> may be zero when g_D is not wanted). With m = D ufbar:
   !> GROWTH_FIXED_PI: A = C^f' - C^f m'/m, B = T^f' m - T^f m'; GROWTH_FIXED_LAMBDA: A = C^f',
   !> B = q' with q = D T^f ufbar = T^f m.
   pure subroutine closed_release_factors(growth_slip, c, dc, d2c, d, a1, b1, a2, b2)
      integer, intent(in) :: growth_slip
      type(coefficient_set_type), intent(in) :: c, dc, d2c
      real(dp), intent(in) :: d
      real(dp), intent(out) :: a1, b1, a2, b2
      real(dp) :: m, m1, m2
      m = d*c%ufbar
      m1 = c%ufbar + d*dc%ufbar
      m2 = 2.0_dp*dc%ufbar + d*d2c%ufbar
      if (growth_slip == GROWTH_FIXED_PI) then
         a1 = dc%cf_t - c%cf_t*m1/m
         b1 = dc%tf*m - c%tf*m1
         a2 = d2c%cf_t - (dc%cf_t*m1 + c%cf_t*m2)/m + c%cf_t*(m1/m)**2
         b2 = d2c%tf*m - c%tf*m2
      else
         a1 = dc%cf_t
         b1 = dc%tf*m + c%tf*m1
         a2 = d2c%cf_t
         b2 = d2c%tf*m + 2.0_dp*dc%tf*m1 + c%tf*m2
      end if
   end subroutine closed_release_factors

   !> kappa(D) of the closed crack in pure mode II (see growth_function) and d kappa/dD.
   pure subroutine closed_mode_two_stiffness(growth_slip, c, dc, d2c, d, kappa, dkappa)
      integer, intent(in) :: growth_slip
      type(coefficient_set_type), intent(in) :: c, dc, d2c
      real(dp), intent(in) :: d
      real(dp), intent(out) :: kappa, dkappa
      real(dp) :: r, dr, a1, b1, a2, b2
      r = c%tc_t/c%tf
      dr = dc%tc_t/c%tf - c%tc_t*dc%tf/c%tf**2
      call closed_release_factors(growth_slip, c, dc, d2c, d, a1, b1, a2, b2)
      kappa = -(dc%k_t + dc%kc_t) + 2.0_dp*a1*r + b1*r*r
      dkappa = -(d2c%k_t + d2c%kc_t) + 2.0_dp*(a2*r + a1*dr) + b2*r*r + 2.0_dp*b1*r*dr
   end subroutine closed_mode_two_stiffness

   !> The separation at which the displacement-driven law reaches D in a pure mode,
   !> sigma(D) = s0/(1 - D(1 - eta)), and its derivative: the R-curve equivalent to that law
   !> is G_c(D) = -k'(D) sigma(D)^2 (the paper's remark after eq 24).
   elemental subroutine equivalent_scale(s0, eta, d, sigma, dsigma_dd)
      real(dp), intent(in) :: s0, eta, d
      real(dp), intent(out) :: sigma, dsigma_dd
      sigma = s0/(1.0_dp - d*(1.0_dp - eta))
      dsigma_dd = (1.0_dp - eta)*sigma*sigma/s0
   end subroutine equivalent_scale

   !> Crack growth in the increment from D_from (eqs 41-42, 50): the predictor keeps D_from when
   !> g(D_from) < 0; otherwise the first root of g in (D_from, 1] is bracketed by a geometric scan
   !> towards D = 1 and refined by the Illinois (modified regula falsi) method; with no root the
   !> crack runs to b (D = 1). For a closed crack every evaluation of g alternates the two
   !> sub-problems of the paper's staggered scheme (friction with D frozen, damage with lambda
   !> frozen), so the root is the staggered scheme's fixed point; a bracket that does not shrink
   !> to ROOT_TOL in MAX_ROOT_ITERATIONS is STATUS_STAGGER_NOT_CONVERGED.
   pure subroutine grow_crack(params, d_from, load, ntens, d_new, status)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d_from
      type(crack_load_type), intent(inout) :: load    !! on return with m_from set when the crack grows
      integer, intent(in) :: ntens
      real(dp), intent(out) :: d_new
      integer, intent(out) :: status

      real(dp) :: g_lo, g_hi, d_lo, d_hi, d_mid, g_mid, unused_s(3), unused_lam(2), unused_d
      integer :: j, iter, side

      d_new = d_from
      load%d_from = d_from
      load%m_from = 0.0_dp
      status = STATUS_OK
      ! a crack that has reached b cannot grow: g is not evaluated there (the equivalent R-curve's
      ! closed-crack toughness vanishes at D = 1, and g would be 0/0)
      if (d_from >= 1.0_dp) return
      call growth_function(params, d_from, load, ntens, g_lo, status, .false., unused_s, unused_lam, unused_d)
      if (status /= STATUS_OK .or. g_lo < 0.0_dp) return
      ! the crack grows: m(D_n) for the slip the faces carry at a larger D (growth_trial_slip)
      if (params%growth_slip == GROWTH_FIXED_PI) then
         call slip_measure(params, d_from, load%m_from, status)
         if (status /= STATUS_OK) return
      end if
      d_lo = d_from
      d_hi = 1.0_dp
      g_hi = 0.0_dp
      do j = 1, N_SCAN
         d_hi = 1.0_dp - (1.0_dp - d_from)*SCAN_DEPTH**(real(j, dp)/real(N_SCAN, dp))
         call growth_function(params, d_hi, load, ntens, g_hi, status, .false., unused_s, unused_lam, unused_d)
         if (status /= STATUS_OK) return
         if (g_hi < 0.0_dp) exit
         d_lo = d_hi
         g_lo = g_hi
      end do
      if (.not. (g_hi < 0.0_dp)) then
         d_new = 1.0_dp                       ! no arrest: the crack runs to b
         return
      end if
      ! Illinois: g(d_lo) >= 0 > g(d_hi)
      side = 0
      d_mid = d_lo
      do iter = 1, MAX_ROOT_ITERATIONS
         d_mid = (d_lo*g_hi - d_hi*g_lo)/(g_hi - g_lo)
         if (.not. (d_mid > d_lo .and. d_mid < d_hi)) d_mid = 0.5_dp*(d_lo + d_hi)
         call growth_function(params, d_mid, load, ntens, g_mid, status, .false., unused_s, unused_lam, unused_d)
         if (status /= STATUS_OK) return
         if (g_mid >= 0.0_dp) then
            d_lo = d_mid
            g_lo = g_mid
            if (side == -1) g_hi = 0.5_dp*g_hi
            side = -1
         else
            d_hi = d_mid
            g_hi = g_mid
            if (side == 1) g_lo = 0.5_dp*g_lo
            side = 1
         end if
         if (d_hi - d_lo <= ROOT_TOL + 4.0_dp*epsilon(1.0_dp)*d_hi) exit
         if (iter == MAX_ROOT_ITERATIONS) then
            status = STATUS_STAGGER_NOT_CONVERGED
            return
         end if
      end do
      d_new = max(d_from, d_lo)
   end subroutine grow_crack

end module interphase_fracture
