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
   use interphase_params, only: law_params_type, SLIP_ONSET_ROUNDOFF
   use interphase_enums, only: RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED, GROWTH_FIXED_PI, &
      MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP
   use interphase_status, only: STATUS_OK, STATUS_STAGGER_NOT_CONVERGED, STATUS_BAD_COEFFICIENTS, &
      STATUS_MODEL_UNAVAILABLE
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR
   use interphase_micro_coefficients, only: micro_coefficients, table_curvature_type
   use interphase_rve_table, only: N_COEFFICIENTS, IC_K_N, IC_K_T, IC_KC_N, IC_KC_T, IC_DBAR_N, IC_DBAR_T, IC_TC_T, &
      IC_SC_N, IC_DTF, IC_UFBAR
   use interphase_rcurve, only: tabulated_rcurve
   use interphase_response, only: response_type, shared_respond => respond
   use interphase_provider, only: provider_values_at => coefficient_values_at
   implicit none
   private
   ! (growth_point: public for the tests, which check the search's roots against g itself)
   public :: crack_load_type, growth_point_type, grow_crack, growth_point

   !> The model the included coefficient providers serve (interphase_coefficients_at.inc): every
   !> model, the one PROPS select.
   integer, parameter :: PROVIDER_MODEL = 0

   !> What the crack sees in the increment: the separation at its end and the slip at its
   !> start (the friction step at each trial D starts from it, or from the slip that conserves
   !> pi = m lambda: `growth_trial_slip`). No default initialisation (the update's hot path: it
   !> would cost stores at every call, and with flang a run-time call): the caller sets s_n, st
   !> and slip_old, grow_crack d_from and m_from.
   type :: crack_load_type
      real(dp) :: s_n                     !! normal separation (mm)
      real(dp) :: st(2)                   !! tangential separation (mm)
      real(dp) :: slip_old(2)             !! frictional slip lambda_n at the start (mm)
      real(dp) :: d_from                  !! damage at the start, D_n (-)
      real(dp) :: m_from                  !! m(D_n) = D_n ufbar(D_n) (-); set by grow_crack when the crack grows
   end type crack_load_type

   !> One evaluation of the growth function at D (`growth_point`): g, its partial derivatives,
   !> its slope along the slip lambda(D), and the response at D.
   type :: growth_point_type
      real(dp) :: d                     !! damage D (-)
      real(dp) :: g                     !! g(D) (-)
      real(dp) :: g_s(3)                !! dg/ds at fixed lambda, D (1/mm)
      real(dp) :: g_lam(2)              !! dg/dlambda at fixed s, D (1/mm)
      real(dp) :: g_d                   !! dg/dD at fixed s, lambda (-)
      real(dp) :: m                     !! m(D) = D ufbar(D) (-), as `slip_measure` gives it
      !> the search's function h(g) (`search_function`) and its slope dh/dD along lambda(D), from
      !> dg/dD = g_d + g_lam . lambda_D (-): set where the derivatives are formed, undefined where
      !> growth_point returns at D_n with g < 0
      real(dp) :: h
      real(dp) :: dh_dd
      type(response_type) :: r          !! the response at D (friction from the trial slip at D)
   end type growth_point_type

   !> Geometric scan towards D = 1 that bounds the root search: points per run.
   integer, parameter :: N_SCAN = 12
   !> The scan's last point: 1 - D is reduced by this factor.
   real(dp), parameter :: SCAN_DEPTH = 1.0e-7_dp
   !> Root tolerance in D and the largest number of evaluations of g in the root search.
   real(dp), parameter :: ROOT_TOL = 1.0e-15_dp
   integer, parameter :: MAX_ROOT_ITERATIONS = 200

contains

   !> g(D) of eq 24 for the increment's separation: the friction step at D (D frozen, from the
   !> trial slip of `growth_trial_slip` and its D-derivative) gives the slip lambda(D) and the
   !> response at D (what the update returns when D is the root), then the release rates at D
   !> with that slip (lambda frozen). Where the crack grows (g >= 0, or D > D_n) also the partial
   !> derivatives dg/ds (Abaqus order, normal first), dg/dlambda and dg/dD at fixed lambda (these
   !> need the coefficients' second derivatives), and the search's h with its slope dh/dD along
   !> lambda(D) (at D = D_n, that of the side D > D_n); elsewhere the partial derivatives are zero
   !> and h, dh/dD undefined. load%d_from (D_n) and load%m_from are those `grow_crack` sets.
   pure subroutine growth_point(params, d, load, ntens, at, status)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d
      type(crack_load_type), intent(in) :: load
      integer, intent(in) :: ntens
      type(growth_point_type), intent(out) :: at
      integer, intent(out) :: status

      type(coefficient_set_type) :: c, dc, d2c
      type(table_curvature_type) :: curvature
      real(dp) :: slip_trial(2), dslip_dd(2), slip(2), g, g_s(3), g_lam(2), g_d, dlam_dd(2)
      real(dp) :: t2, gi, gii, gi_s(3), gii_s(3), gii_lam(2), gi_d, gii_d
      real(dp) :: gc(2), dgc(2), sig_n, sig_t, dsig_n, dsig_t, a1, a2, b1, b2, lam_s, lam2, kappa, dkappa
      real(dp) :: ratio, dratio, band_g, band_grad(3), q, dq, d2q, tau(2), tau_norm, n_dir(2), n_dot
      real(dp) :: dg_dd                   ! dg/dD along lambda(D) (-)
      logical :: closed, in_band, equivalent_open
      integer :: nt

      nt = ntens - 1
      a1 = 0.0_dp
      b1 = 0.0_dp
      a2 = 0.0_dp
      b2 = 0.0_dp
      at%d = d
      call coefficients_at(params, d, c, dc, status, curvature)
      if (status /= STATUS_OK) return
      at%m = 0.0_dp
      if (d > 0.0_dp) at%m = d*c%ufbar
      t2 = load%st(1)**2 + load%st(2)**2
      ! friction with D frozen, from the slip the crack faces carry at D (at D_n itself lambda_n,
      ! as growth_trial_slip gives it there)
      if (d > load%d_from) then
         call growth_trial_slip(params%growth_slip, load%d_from, load%m_from, d, c, dc, load%slip_old, &
            slip_trial, dslip_dd)
      else
         slip_trial = load%slip_old
         dslip_dd = 0.0_dp
      end if
      call respond(params, c, dc, d, slip_trial, load%s_n, load%st, ntens, .true., at%r, status, dslip_dd)
      if (status /= STATUS_OK) return
      closed = at%r%closed
      slip = at%r%slip
      ! the contact band (open crack, 0 < s_N < chi |s_T|): psi holds 1/2 q g, so G_II holds -q' g
      in_band = .false.
      ! (q and its slopes set outside the band too: only to keep the compiler's uninitialised-use
      ! analysis quiet, they are read only in the band)
      q = 0.0_dp
      dq = 0.0_dp
      d2q = 0.0_dp
      if (params%contact_band > 0.0_dp .and. params%model == MODEL_MICROMECHANICAL .and. .not. closed &
         .and. params%rcurve /= RCURVE_EQUIVALENT) then
         call contact_band_shape(params%contact_band, load%s_n, load%st, ntens, in_band, band_g, band_grad)
         ! (q and dq here; d2q, from the second derivatives, below where the crack grows)
         if (in_band) call band_stiffness(c, dc, NO_COEFFICIENTS, q, dq, d2q)
      end if

      ! g: energy release rates (eq-20 convention) over the R-curve
      gi = 0.0_dp
      equivalent_open = params%rcurve == RCURVE_EQUIVALENT .and. .not. closed
      if (equivalent_open) then
         ! G/G_c with G_c = -k' sigma(D)^2: the provider's k' cancels, g = sum (s/sigma(D))^2 - 1
         ! (in the contact band G_II = -(k_t' + q'(1 - W)) |s_T|^2 and the equivalent R-curve's
         ! G_cII = -(k_t' + q'(1 - W)) sigma_T^2, so g is the same: it goes over continuously into
         ! the closed crack's (G_cII = kappa sigma_T^2, kappa = -(k_t' + q') in pure mode II), and
         ! the law stays equivalent to the displacement law, whose D the band does not change)
         call equivalent_open_g(params, d, load%s_n, t2, g, gi, gii, sig_n, sig_t, dsig_n, dsig_t)
      else
         if (.not. closed) then
            if (load%s_n > 0.0_dp) gi = -dc%k_n*load%s_n**2
            gii = -dc%k_t*t2
            if (in_band) gii = gii - dq*band_g
         else
            call closed_release_factors(params%growth_slip, c, dc, d, a1, b1)
            lam_s = slip(1)*load%st(1) + slip(2)*load%st(2)
            lam2 = slip(1)**2 + slip(2)**2
            gii = -((dc%k_n + dc%kc_n)*load%s_n**2 + (dc%k_t + dc%kc_t)*t2) - 2.0_dp*a1*lam_s + b1*lam2
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
            ratio = c%tc_t/c%tf
            kappa = -(dc%k_t + dc%kc_t) + 2.0_dp*a1*ratio + b1*ratio*ratio
            gc(1) = 1.0_dp
            gc(2) = kappa*sig_t**2
         end select
         ! gi = 0 when the crack is closed or s_N <= 0 (no mode-I term then)
         g = gii/gc(2) - 1.0_dp
         if (abs(gi) > 0.0_dp) g = g + gi/gc(1)
      end if
      at%g = g
      ! no growth at D_n: neither the search nor the tangent needs the derivatives
      if (g < 0.0_dp .and. .not. (d > load%d_from)) then
         at%g_s = 0.0_dp
         at%g_lam = 0.0_dp
         at%g_d = 0.0_dp
         return
      end if

      ! the coefficients' second derivatives at D (formed only here: at D_n most calls stop above)
      call second_derivatives_at(params, d, c, dc, curvature, d2c)
      if (in_band) call band_stiffness(c, dc, d2c, q, dq, d2q)
      g_s = 0.0_dp
      g_lam = 0.0_dp
      if (equivalent_open) then
         if (load%s_n > 0.0_dp) g_s(1) = 2.0_dp*load%s_n/sig_n**2
         g_s(2) = 2.0_dp*load%st(1)/sig_t**2
         if (ntens == 3) g_s(3) = 2.0_dp*load%st(2)/sig_t**2
         g_d = -2.0_dp*gi*dsig_n/sig_n - 2.0_dp*gii*dsig_t/sig_t
      else
         gi_s = 0.0_dp
         gii_s = 0.0_dp
         gii_lam = 0.0_dp
         gi_d = 0.0_dp
         if (.not. closed) then
            if (load%s_n > 0.0_dp) then
               gi_s(1) = -2.0_dp*dc%k_n*load%s_n
               gi_d = -d2c%k_n*load%s_n**2
            end if
            gii_s(2) = -2.0_dp*dc%k_t*load%st(1)
            if (ntens == 3) gii_s(3) = -2.0_dp*dc%k_t*load%st(2)
            gii_d = -d2c%k_t*t2
            if (in_band) then
               gii_s(1:ntens) = gii_s(1:ntens) - dq*band_grad(1:ntens)
               gii_d = gii_d - d2q*band_g
            end if
         else
            call closed_release_slopes(params%growth_slip, c, dc, d2c, d, a2, b2)
            gii_s(1) = -2.0_dp*(dc%k_n + dc%kc_n)*load%s_n
            gii_s(2) = -2.0_dp*(dc%k_t + dc%kc_t)*load%st(1) - 2.0_dp*a1*slip(1)
            gii_lam(1) = -2.0_dp*a1*load%st(1) + 2.0_dp*b1*slip(1)
            if (ntens == 3) then
               gii_s(3) = -2.0_dp*(dc%k_t + dc%kc_t)*load%st(2) - 2.0_dp*a1*slip(2)
               gii_lam(2) = -2.0_dp*a1*load%st(2) + 2.0_dp*b1*slip(2)
            end if
            gii_d = -((d2c%k_n + d2c%kc_n)*load%s_n**2 + (d2c%k_t + d2c%kc_t)*t2) - 2.0_dp*a2*lam_s &
               + b2*lam2
         end if
         if (params%rcurve /= RCURVE_CONSTANT .and. params%rcurve /= RCURVE_TABULATED) then
            ! d kappa/dD of the closed crack's equivalent R-curve
            dratio = dc%tc_t/c%tf - c%tc_t*dc%tf/c%tf**2
            dkappa = -(d2c%k_t + d2c%kc_t) + 2.0_dp*(a2*ratio + a1*dratio) + b2*ratio*ratio &
               + 2.0_dp*b1*ratio*dratio
            dgc(1) = 0.0_dp
            dgc(2) = dkappa*sig_t**2 + 2.0_dp*kappa*sig_t*dsig_t
         end if
         g_s = gii_s/gc(2)
         g_lam = gii_lam/gc(2)
         g_d = (gii_d*gc(2) - gii*dgc(2))/gc(2)**2
         if (abs(gi) > 0.0_dp) then
            g_s = g_s + gi_s/gc(1)
            g_d = g_d + (gi_d*gc(1) - gi*dgc(1))/gc(1)**2
         end if
      end if
      at%g_s = g_s
      at%g_lam = g_lam
      at%g_d = g_d
      ! along lambda(D): dg/dD = g_D + g_lambda . lambda_D
      dlam_dd = at%r%dlam_dd
      if (closed .and. .not. (d > load%d_from) .and. params%growth_slip == GROWTH_FIXED_PI) then
         ! At D_n itself the trial slip is lambda_n (the response without growth), but it falls
         ! like 1/m(D) as soon as D grows: the search starts with the slope of the side D > D_n,
         ! lambda_D changed by what the trial slip's derivative adds in the response (respond):
         ! all of it in stick; in slip (1 - phi/|tau|) times its part across the shear stress
         ! direction (none in 2-D).
         dslip_dd = -load%slip_old*((c%ufbar + d*dc%ufbar)*(1.0_dp/max(d*c%ufbar, tiny(1.0_dp))))
         if (at%r%regime == REGIME_STICK) then
            dlam_dd = dlam_dd + dslip_dd
         else if (at%r%regime == REGIME_SLIP .and. nt == 2) then
            tau = c%tc_t*load%st + c%tf*slip_trial
            tau_norm = sqrt(tau(1)**2 + tau(2)**2)
            if (tau_norm > 0.0_dp) then
               n_dir = tau/tau_norm
               n_dot = n_dir(1)*dslip_dd(1) + n_dir(2)*dslip_dd(2)
               dlam_dd = dlam_dd - (params%mu*c%sc_n*load%s_n/tau_norm)*(dslip_dd - n_dot*n_dir)
            end if
         end if
      end if
      dg_dd = g_d + g_lam(1)*dlam_dd(1) + g_lam(2)*dlam_dd(2)
      call search_function(g, dg_dd, at%h, at%dh_dd)
   end subroutine growth_point

   !> The function whose root the search finds (docs/theory.md, the fracture law's 'The update'):
   !> h = sqrt(1 + g) - 1, formed as g/(1 + sqrt(1 + g)) (no cancellation; h has g's sign and the
   !> same root), and dh/dD = (dg/dD)/(2 sqrt(1 + g)). 1 + g is eq 24's sum
   !> G_I/(2 G_cI) + G_II/(2 G_cII), quadratic in the separation; with the equivalent R-curve each
   !> mode's G_c holds sigma(D)^2, sigma(D) = s0/(1 - D (1 - eta)), and the square root takes both
   !> out: h is linear in D in mode I (open crack) and in mode II (closed crack at s_N = 0, without
   !> friction), where Newton from D_n lands on the root and g itself is a quadratic (nearly so in
   !> open mixed mode, where eta_N and eta_T differ little). Below g = -3/4 (a release rate under
   !> a quarter of the toughness, far below any root) h = g + 1/4, which joins the square root's
   !> branch with the same value and slope (dh/dg = 1) and keeps g's sign: the slope of h stays
   !> bounded where 1 + g reaches 0 (a closed crack's G_II can change sign), so that a Newton step
   !> |h/h'| is never below two thirds of g's |g/g'|.
   elemental subroutine search_function(g, dg_dd, h, dh_dd)
      real(dp), intent(in) :: g, dg_dd                !! g(D) and dg/dD along lambda(D) (-)
      real(dp), intent(out) :: h, dh_dd               !! h(D) and dh/dD (-)
      real(dp) :: root
      if (g > -0.75_dp) then
         root = sqrt(1.0_dp + g)
         h = g/(1.0_dp + root)
         dh_dd = dg_dd/(2.0_dp*root)
      else
         h = g + 0.25_dp
         dh_dd = dg_dd
      end if
   end subroutine search_function

   !> The factors of the closed crack's release rate, G_II = -kk' s.s - 2 A lambda.s_T + B |lambda|^2.
   !> With m = D ufbar: GROWTH_FIXED_PI: A = C^f' - C^f m'/m, B = T^f' m - T^f m';
   !> GROWTH_FIXED_LAMBDA: A = C^f', B = q' with q = D T^f ufbar = T^f m.
   pure subroutine closed_release_factors(growth_slip, c, dc, d, a1, b1)
      integer, intent(in) :: growth_slip
      type(coefficient_set_type), intent(in) :: c, dc
      real(dp), intent(in) :: d
      real(dp), intent(out) :: a1, b1
      real(dp) :: m, m1
      m = d*c%ufbar
      m1 = c%ufbar + d*dc%ufbar
      if (growth_slip == GROWTH_FIXED_PI) then
         a1 = dc%cf_t - c%cf_t*m1/m
         b1 = dc%tf*m - c%tf*m1
      else
         a1 = dc%cf_t
         b1 = dc%tf*m + c%tf*m1
      end if
   end subroutine closed_release_factors

   !> The derivatives d/dD of the factors A and B of `closed_release_factors`, a2 = A', b2 = B'
   !> (d2c: the coefficients' second derivatives).
   pure subroutine closed_release_slopes(growth_slip, c, dc, d2c, d, a2, b2)
      integer, intent(in) :: growth_slip
      type(coefficient_set_type), intent(in) :: c, dc, d2c
      real(dp), intent(in) :: d
      real(dp), intent(out) :: a2, b2
      real(dp) :: m, m1, m2
      m = d*c%ufbar
      m1 = c%ufbar + d*dc%ufbar
      m2 = 2.0_dp*dc%ufbar + d*d2c%ufbar
      if (growth_slip == GROWTH_FIXED_PI) then
         a2 = d2c%cf_t - (dc%cf_t*m1 + c%cf_t*m2)/m + c%cf_t*(m1/m)**2
         b2 = d2c%tf*m - c%tf*m2
      else
         a2 = d2c%cf_t
         b2 = d2c%tf*m + 2.0_dp*dc%tf*m1 + c%tf*m2
      end if
   end subroutine closed_release_slopes

   !> The separation at which the displacement-driven law reaches D in a pure mode,
   !> sigma(D) = s0/(1 - D(1 - eta)), and its derivative: the R-curve equivalent to that law
   !> is G_c(D) = -k'(D) sigma(D)^2 (the paper's remark after eq 24). The denominator
   !> 1 - D(1 - eta) is formed as (1 - D) + D eta: the same number, without the cancellation near
   !> D = 1 (where it is eta, not the 0 that 1 - D(1 - eta) rounds to when eta < eps/2, sf/s0 >
   !> 1e16: a division by zero before).
   elemental subroutine equivalent_scale(s0, eta, d, sigma, dsigma_dd)
      real(dp), intent(in) :: s0, eta, d
      real(dp), intent(out) :: sigma, dsigma_dd
      sigma = s0/((1.0_dp - d) + d*eta)
      dsigma_dd = (1.0_dp - eta)*sigma*sigma/s0
   end subroutine equivalent_scale

   !> Crack growth in the increment from D_from (eqs 41-42, 50): the predictor keeps D_from when
   !> g(D_from) < 0; otherwise D is the first root of g in (D_from, 1], found by a safeguarded
   !> Newton iteration from D_from along the slip lambda(D) on h(g) = sqrt(1 + g) - 1
   !> (`search_function`: the same root and sign as g, nearly linear in D where g is quadratic;
   !> slope dh/dD from dg/dD = g_D + g_lambda . lambda_D, the tangent's denominator); from the
   !> second evaluation on, the Newton point is corrected for the curvature of h by the inverse
   !> cubic Hermite interpolant through the last two evaluations (`hermite_root`), so that a
   !> growing increment mostly ends at its second or third evaluation (D_n, the Newton point, the
   !> root). The search never passes the points of a
   !> geometric scan towards D = 1 (N_SCAN points per run, down to 1 - D = SCAN_DEPTH (1 -
   !> D_from)) without evaluating them: a step beyond the next scan point, or uphill
   !> (dh/dD >= 0), is replaced by that point, or by the bisection of a bracket once g < 0 has been
   !> seen (as is a step inside the bracket longer than half the step before the last); g >= 0 at
   !> every scan point lets the crack run to b (D = 1). Converged when the Newton
   !> step |h/(dh/dD)| at a point is at most ROOT_TOL + 4 eps D (D is that point), or when a
   !> bracket g(D_lo) >= 0 > g(D_hi) has shrunk to ROOT_TOL + 4 eps D_hi (D is D_lo). For a closed
   !> crack every evaluation of g alternates the two sub-problems of the paper's staggered scheme
   !> (friction with D frozen, damage with lambda frozen), so the root is the staggered scheme's
   !> fixed point; no convergence in MAX_ROOT_ITERATIONS evaluations is
   !> STATUS_STAGGER_NOT_CONVERGED. at(which) is the evaluation at the returned D (its response
   !> and derivatives; two slots, so that the search copies none); which = 0 when D = 1.
   pure subroutine grow_crack(params, d_from, load, ntens, d_new, status, at, which)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d_from
      type(crack_load_type), intent(inout) :: load    !! on return with m_from set when the crack grows
      integer, intent(in) :: ntens
      real(dp), intent(out) :: d_new
      integer, intent(out) :: status
      type(growth_point_type), intent(out) :: at(2)   !! evaluations, at(which) the one at d_new
      integer, intent(out) :: which                   !! 1 or 2: at(which) is at d_new; 0: none (D = 1)

      real(dp) :: d_lo, d_hi, d_bound, d_next, step, dx_last, dx_older
      integer :: iter, scan, how
      logical :: have_hi, have_two, arrested
      integer :: k, lo
      integer, parameter :: BY_NEWTON = 1, BY_BISECTION = 2, BY_SCAN = 3

      d_new = d_from
      which = 0
      load%d_from = d_from
      load%m_from = 0.0_dp
      status = STATUS_OK
      ! a crack that has reached b cannot grow: g is not evaluated there (the equivalent R-curve's
      ! closed-crack toughness vanishes at D = 1, and g would be 0/0)
      if (d_from >= 1.0_dp) return
      k = 1
      ! an open crack under the equivalent R-curve: g at D_n from the separation alone, and where
      ! it stays below 0 the response from the coefficients' values alone (open_arrest)
      if (params%rcurve == RCURVE_EQUIVALENT) then
         call open_arrest(params, d_from, load, ntens, at(k), arrested, status)
         if (status /= STATUS_OK) return
         if (arrested) then
            which = k
            return
         end if
      end if
      call growth_point(params, d_from, load, ntens, at(k), status)
      if (status /= STATUS_OK) return
      if (at(k)%g < 0.0_dp) then
         which = k
         return
      end if
      ! the crack grows: m(D_n) for the slip the faces carry at a larger D (growth_trial_slip);
      ! at D_from itself the trial slip is lambda_n either way, so `at` stands
      if (params%growth_slip == GROWTH_FIXED_PI) load%m_from = at(k)%m
      d_lo = d_from
      d_hi = 1.0_dp
      have_hi = .false.
      lo = k
      have_two = .false.
      dx_last = 1.0_dp
      dx_older = 1.0_dp
      scan = 1
      d_bound = scan_point(d_from, scan)
      do iter = 1, MAX_ROOT_ITERATIONS
         ! at(k) is the latest evaluation, at(lo) the one at d_lo
         step = 0.0_dp
         how = BY_SCAN
         if (have_hi) how = BY_BISECTION
         if (at(k)%dh_dd < 0.0_dp) then
            step = -at(k)%h/at(k)%dh_dd
            if (abs(step) <= ROOT_TOL + 4.0_dp*epsilon(1.0_dp)*at(k)%d) then
               d_new = at(k)%d                  ! >= d_from: every point searched is
               which = k
               return
            end if
            d_next = at(k)%d + step
            ! with a second evaluation, the root of the cubic through both (inverse Hermite)
            if (have_two) then
               call hermite_root(at(3 - k), at(k), step, d_next)
               step = d_next - at(k)%d
            end if
            if (d_next > d_lo .and. d_next < min(d_hi, d_bound)) how = BY_NEWTON
         end if
         ! inside a bracket, a Newton step longer than half the step before the last gives way
         ! to a bisection (the bracket then at least halves every other evaluation)
         if (how == BY_NEWTON .and. have_hi .and. .not. (2.0_dp*abs(step) <= dx_older)) how = BY_BISECTION
         select case (how)
         case (BY_NEWTON)
         case (BY_BISECTION)
            d_next = 0.5_dp*(d_lo + d_hi)
         case default
            d_next = d_bound
         end select
         dx_older = dx_last
         dx_last = abs(d_next - at(k)%d)
         ! the next evaluation goes to the slot that does not hold d_lo's
         k = 3 - lo
         have_two = .true.
         call growth_point(params, d_next, load, ntens, at(k), status)
         if (status /= STATUS_OK) return
         if (at(k)%g >= 0.0_dp) then
            d_lo = d_next
            lo = k
            if (how == BY_SCAN) then
               if (scan == N_SCAN) then
                  d_new = 1.0_dp              ! no arrest: the crack runs to b
                  return
               end if
               scan = scan + 1
               d_bound = scan_point(d_from, scan)
            end if
         else
            d_hi = d_next
            have_hi = .true.
         end if
         if (have_hi .and. d_hi - d_lo <= ROOT_TOL + 4.0_dp*epsilon(1.0_dp)*d_hi) then
            ! the bracket has closed (where rounding in g keeps the Newton step above the
            ! tolerance): D is its lower end
            d_new = d_lo
            which = lo
            return
         end if
      end do
      status = STATUS_STAGGER_NOT_CONVERGED
   end subroutine grow_crack

   !> g of an open crack under the equivalent R-curve at D, from the separation alone (G/G_c with
   !> G_c = -k' sigma(D)^2: k' cancels), g = gi + gii - 1, gi = (s_N/sigma_N(D))^2 (0 unless
   !> s_N > 0), gii = |s_T|^2/sigma_T(D)^2, with the scales sigma(D) and their slopes.
   pure subroutine equivalent_open_g(params, d, s_n, t2, g, gi, gii, sig_n, sig_t, dsig_n, dsig_t)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d, s_n, t2          !! D (-), s_N (mm), |s_T|^2 (mm^2)
      real(dp), intent(out) :: g, gi, gii         !! (-)
      real(dp), intent(out) :: sig_n, sig_t, dsig_n, dsig_t     !! sigma(D) (mm), d sigma/dD (mm)
      call equivalent_scale(params%s0_n, params%eta_n, d, sig_n, dsig_n)
      call equivalent_scale(params%s0_t, params%eta_t, d, sig_t, dsig_t)
      gi = 0.0_dp
      if (s_n > 0.0_dp) gi = (s_n/sig_n)**2
      gii = t2/sig_t**2
      g = gi + gii - 1.0_dp
   end subroutine equivalent_open_g

   !> growth_point at D_n for an open crack under the equivalent R-curve, where the crack does not
   !> grow, at a third of its cost: there g needs no coefficient (equivalent_open_g), and the
   !> response at a D that does not grow needs the coefficients' values alone
   !> (coefficient_values_at: the numbers coefficients_at gives, bit for bit), not their
   !> derivatives (most of a table lookup). arrested = .true.: `at` holds what
   !> growth_point gives there (g < 0, g's derivatives zero, the response, whose dtrac_dd, read
   !> only by a growing crack's tangent, is formed from zeros). arrested = .false.: g >= 0 (or
   !> NaN), or the response finds the crack closed at D_n (s_N <= 0 at D_n > 0 is not tried; the
   !> table's Dbar_NN <= 0, which check_interpolant refuses only at its samples of the table
   !> grid): growth_point
   !> decides, and `at` is undefined. (The provider's and the response module's entries, out of
   !> line: a second call of this module's own copies would keep the compiler from inlining them
   !> into growth_point.)
   pure subroutine open_arrest(params, d, load, ntens, at, arrested, status)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d                       !! D_n (-)
      type(crack_load_type), intent(in) :: load
      integer, intent(in) :: ntens
      type(growth_point_type), intent(out) :: at
      logical, intent(out) :: arrested
      integer, intent(out) :: status
      type(coefficient_set_type) :: c, zeros
      real(dp) :: sig_n, sig_t, dsig_n, dsig_t, gi, gii
      arrested = .false.
      status = STATUS_OK
      if (.not. (load%s_n > 0.0_dp .or. .not. (d > 0.0_dp))) return
      call equivalent_open_g(params, d, load%s_n, load%st(1)**2 + load%st(2)**2, at%g, gi, gii, sig_n, sig_t, &
         dsig_n, dsig_t)
      if (.not. (at%g < 0.0_dp)) return
      call provider_values_at(params, d, c, zeros, status)
      if (status /= STATUS_OK) return
      call shared_respond(params, c, zeros, d, load%slip_old, load%s_n, load%st, ntens, .false., at%r, status)
      if (at%r%closed) then
         status = STATUS_OK                           ! (growth_point answers for a closed crack)
         return
      end if
      if (status /= STATUS_OK) return
      at%d = d
      at%g_s = 0.0_dp
      at%g_lam = 0.0_dp
      at%g_d = 0.0_dp
      at%m = merge(d*c%ufbar, 0.0_dp, d > 0.0_dp)
      arrested = .true.
   end subroutine open_arrest

   !> The search's step from two evaluations of h (`search_function`) with their slopes: at the
   !> latest, p1 (D_1, h_1, h_1' < 0, Newton step s = -h_1/h_1'), and another, p0 (D_0, h_0,
   !> h_0' < 0). D(h), the inverse of h between them, is interpolated by the cubic that matches D
   !> and dD/dh = 1/h' at both (Hermite); its value at h = 0, with u = h_1/(h_1 - h_0),
   !>   D = D_1 + (1 - u)^2 s + u ((1 - u) h_1/h_0' + u (3 - 2u)(D_0 - D_1)),
   !> is the Newton point D_1 + s corrected for the curvature of h: its error is of the order of
   !> (D_0 - D)^2 (D_1 - D)^2 where Newton's is (D_1 - D)^2, so that from D_n and one Newton point
   !> the next point is mostly the root to the search's tolerance. Used (d_next returned changed)
   !> only where h falls from p0 to p1 and the correction is at most half the Newton step;
   !> otherwise d_next stays the Newton point.
   pure subroutine hermite_root(p0, p1, s, d_next)
      type(growth_point_type), intent(in) :: p0, p1
      real(dp), intent(in) :: s                    !! Newton step from p1 (-)
      real(dp), intent(inout) :: d_next            !! in: p1%d + s; out: the step's end (-)
      real(dp) :: u, d_h
      if (.not. (p0%dh_dd < 0.0_dp .and. (p1%d - p0%d)*(p1%h - p0%h) < 0.0_dp)) return
      u = p1%h/(p1%h - p0%h)
      d_h = p1%d + (1.0_dp - u)**2*s + u*((1.0_dp - u)*p1%h/p0%dh_dd + u*(3.0_dp - 2.0_dp*u)*(p0%d - p1%d))
      if (abs(d_h - d_next) <= 0.5_dp*abs(s)) d_next = d_h
   end subroutine hermite_root

   !> Point j of the geometric scan from D_from towards D = 1: 1 - D = (1 - D_from) SCAN_DEPTH^(j/N_SCAN).
   pure real(dp) function scan_point(d_from, j)
      real(dp), intent(in) :: d_from
      integer, intent(in) :: j
      scan_point = 1.0_dp - (1.0_dp - d_from)*SCAN_DEPTH**(real(j, dp)/real(N_SCAN, dp))
   end function scan_point

   !> The coefficients' second derivatives d2/dD2 at D, from what coefficients_at gave there
   !> (c, dc and the table's `curvature`): the micromechanical table's (micro_second_derivatives),
   !> zeros for the simplified model (linear in D; curvature not read).
   pure subroutine second_derivatives_at(params, d, c, dc, curvature, d2c)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d                                   !! damage D = a/b
      type(coefficient_set_type), intent(in) :: c, dc             !! coefficients_at's set and d/dD
      type(table_curvature_type), intent(in) :: curvature         !! coefficients_at's, at D
      type(coefficient_set_type), intent(out) :: d2c              !! d2/dD2
      if (params%model == MODEL_MICROMECHANICAL) then
         call micro_second_derivatives(d, c, dc, curvature, d2c)
      else
         d2c = NO_COEFFICIENTS
      end if
   end subroutine second_derivatives_at

   ! the response at fixed D, here where the compiler inlines it into the search's evaluation
   ! (interphase_response's, from the same source: a private copy)
   include 'interphase_response.inc'
   ! the coefficient set at D with its derivatives, here where the compiler inlines it into the
   ! growth function (interphase_provider's, from the same source: private copies)
   include 'interphase_coefficients_at.inc'
   include 'interphase_simplified.inc'
   ! the table's second derivatives, here where growth_point inlines them (interphase_micro_coefficients',
   ! from the same source: a private copy)
   include 'interphase_second_derivatives.inc'

end module interphase_fracture
