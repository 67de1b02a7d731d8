!> The response of one interface point at a fixed damage D (the paper's section 4 for a given
!> crack length): regime (intact, open, stick, slip), traction, tangent at fixed D, dt/dD, the
!> slip with its sensitivities, and the stored energy. Used by the update for both damage laws.
module interphase_response
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
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

   !> The slip from which the friction step at damage D starts, for a crack that has grown from
   !> D_from, where the faces' slip was lambda_n, and its derivative d/dD (D_from fixed).
   !> GROWTH_FIXED_PI (the default): the integrated slip pi = m lambda, m = D ufbar, is conserved
   !> (the faces made by the growth start with zero slip; docs/theory.md, 'Crack growth under
   !> slip'): lambda_trial = lambda_n m(D_from)/m(D). GROWTH_FIXED_LAMBDA (the paper's form):
   !> lambda_trial = lambda_n. Without growth (D <= D_from) lambda_trial = lambda_n in both.
   pure subroutine growth_trial_slip(growth_slip, d_from, m_from, d, c, dc, slip_old, slip_trial, dslip_dd)
      integer, intent(in) :: growth_slip                  !! GROWTH_* of interphase_layout
      real(dp), intent(in) :: d_from                      !! damage the slip belongs to (-)
      real(dp), intent(in) :: m_from                      !! m(D_from) = D_from ufbar(D_from) (-)
      real(dp), intent(in) :: d                           !! damage D (-)
      type(coefficient_set_type), intent(in) :: c, dc     !! coefficients at D and d/dD
      real(dp), intent(in) :: slip_old(2)                 !! lambda_n (mm)
      real(dp), intent(out) :: slip_trial(2)              !! lambda_trial (mm)
      real(dp), intent(out) :: dslip_dd(2)                !! d lambda_trial/dD (mm)
      real(dp) :: inv_m
      if (growth_slip == GROWTH_FIXED_PI .and. d > d_from) then
         ! m(D) > 0 where D > D_from >= 0; the guard only keeps a division by zero out of reach
         ! (interphase_block forms the same quotient for the simplified model, m = D)
         inv_m = 1.0_dp/max(d*c%ufbar, tiny(1.0_dp))
         slip_trial = slip_old*(m_from*inv_m)
         dslip_dd = -slip_trial*((c%ufbar + d*dc%ufbar)*inv_m)
      else
         slip_trial = slip_old
         dslip_dd = 0.0_dp
      end if
   end subroutine growth_trial_slip

   !> The response at a fixed damage D: regime, traction, tangent at fixed D, dt/dD, slip and
   !> its sensitivities, stored energy. The friction step starts from `slip_old`; when that slip
   !> itself depends on D (`growth_trial_slip`), `dslip_dd` gives its derivative, and dt/dD and
   !> d lambda/dD include it.
   !>
   !> (Written component by component for the hot path: each entry is set once, by the same
   !> expression, in the same operation order, as the array form it replaces; the shear
   !> components of traction and dt/dD as pairs, whose second member, beyond ntens in 2-D, is the
   !> 3-D formula's with s_T2 = 0; the tangent and d lambda/ds hold zeros beyond ntens.)
   pure subroutine respond(params, c, dc, d, slip_old, s_n, st, ntens, with_dd, r, status, dslip_dd)
      type(law_params_type), intent(in) :: params
      type(coefficient_set_type), intent(in) :: c, dc     !! coefficients at D and d/dD
      real(dp), intent(in) :: d                           !! damage D
      real(dp), intent(in) :: slip_old(2)                 !! slip the friction step starts from (mm)
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm)
      integer, intent(in) :: ntens
      !> also the closed crack's shear dt/dD and d lambda/dD (the tangent of a growing crack and
      !> the fracture law's search need them); without, those are zeros, and the rest of r%dtrac_dd
      !> is formed from dc as given (a caller without D-derivatives passes zeros:
      !> coefficient_values_at)
      logical, intent(in) :: with_dd
      type(response_type), intent(out) :: r
      integer, intent(out) :: status
      real(dp), intent(in), optional :: dslip_dd(2)       !! d(slip_old)/dD (mm), 0 if absent

      real(dp) :: kk_n, kk_t, sigma, tau(2), tau_norm, phi, kf, nvec(2), dgamma, ratio
      real(dp) :: dtau_dd(2), dphi_dd, proj_dtau(2), n_dot, slip(2), dlam_dd(2)
      real(dp) :: slip_scale, normal_scale, one_ratio, zero_ratio

      status = STATUS_OK
      if (d <= 0.0_dp .or. c%dbar_n*s_n > 0.0_dp) then
         ! intact, or open crack: Sigma = C E, crack faces traction-free
         r%closed = .false.
         r%traction(1) = c%k_n*s_n
         r%traction(2:3) = c%k_t*st
         call set_diagonal_tangent(c%k_n, c%k_t, ntens, r%tangent)
         r%dlam_ds = 0.0_dp
         r%dlam_dd = 0.0_dp
         r%dtrac_dd(1) = dc%k_n*s_n
         r%dtrac_dd(2:3) = dc%k_t*st
         if (d <= 0.0_dp) then
            r%slip = slip_old
            r%regime = REGIME_INTACT
         else
            r%slip(1) = c%dbar_t*st(1)/c%ufbar
            r%slip(2) = 0.0_dp
            if (ntens == 3) r%slip(2) = c%dbar_t*st(2)/c%ufbar
            r%regime = REGIME_OPEN
         end if
         r%psi = 0.5_dp*(r%traction(1)*s_n + shear_work(r%traction, st, ntens))
         ! (the simplified model has q = 0: the band would change nothing but rounding)
         if (params%contact_band > 0.0_dp .and. params%model == MODEL_MICROMECHANICAL .and. d > 0.0_dp) &
            call blend_contact_band(params%contact_band, c, dc, s_n, st, ntens, r, status)
         return
      end if

      ! closed crack: trial stick state, eq 43
      r%closed = .true.
      kk_n = c%k_n + c%kc_n
      kk_t = c%k_t + c%kc_t
      sigma = c%sc_n*s_n
      tau = c%tc_t*st + c%tf*slip_old
      if (ntens == 2) then
         tau_norm = abs(tau(1))
      else
         tau_norm = sqrt(tau(1)**2 + tau(2)**2)
      end if
      phi = params%mu*sigma + tau_norm
      r%traction(1) = kk_n*s_n
      r%dtrac_dd(1) = (dc%k_n + dc%kc_n)*s_n
      if (phi > 0.0_dp .and. tau_norm > 0.0_dp) then
         ! slip: return mapping along the trial crack shear stress, eqs 44-48
         kf = -c%tf
         if (.not. (kf > 0.0_dp)) then
            status = STATUS_BAD_COEFFICIENTS
            return
         end if
         ! (interphase_block forms the same products, bit for bit)
         if (ntens == 2) then
            nvec = [sign(1.0_dp, tau(1)), 0.0_dp]
         else
            nvec = tau*(1.0_dp/max(tau_norm, tiny(1.0_dp)))
         end if
         dgamma = phi*(1.0_dp/kf)
         slip = slip_old + dgamma*nvec
         r%slip = slip
         r%regime = REGIME_SLIP
         r%traction(2:3) = kk_t*st + c%cf_t*slip
         r%psi = closed_energy(c, d, s_n, st, ntens, r%traction, slip)
         if (with_dd) then
            ! d lambda/dD at fixed s
            dtau_dd = dc%tc_t*st + dc%tf*slip_old
            if (present(dslip_dd)) dtau_dd = dtau_dd + c%tf*dslip_dd
            n_dot = nvec(1)*dtau_dd(1) + nvec(2)*dtau_dd(2)
            dphi_dd = params%mu*dc%sc_n*s_n + n_dot
            proj_dtau = dtau_dd - n_dot*nvec
            dlam_dd = (nvec*dphi_dd + (phi/tau_norm)*proj_dtau)/kf + dgamma*nvec*dc%tf/kf
            if (present(dslip_dd)) dlam_dd = dlam_dd + dslip_dd
            r%dlam_dd = dlam_dd
            r%dtrac_dd(2:3) = (dc%k_t + dc%kc_t)*st + dc%cf_t*slip + c%cf_t*dlam_dd
         else
            r%dlam_dd = 0.0_dp
            r%dtrac_dd(2:3) = 0.0_dp
         end if
         ! d lambda/d s_T = (T^c_T/kf) [I + (mu sigma/|tau|)(I - n n)], d lambda/d s_N = (mu S^c_N/kf) n:
         ! entry (i, 1 + j) = (T^c_T/kf) (delta_ij (1 + ratio) - ratio n_i n_j), delta_ij (1 + ratio)
         ! formed as 1 (1 + ratio) and 0 (1 + ratio)
         ratio = params%mu*sigma/tau_norm
         slip_scale = c%tc_t/kf
         normal_scale = params%mu*c%sc_n/kf
         one_ratio = 1.0_dp + ratio
         zero_ratio = 0.0_dp*one_ratio
         r%dlam_ds(1, 1) = normal_scale*nvec(1)
         r%dlam_ds(1, 2) = slip_scale*(one_ratio - ratio*nvec(1)*nvec(1))
         if (ntens == 2) then
            r%dlam_ds(2, 1:2) = 0.0_dp
            r%dlam_ds(:, 3) = 0.0_dp
         else
            r%dlam_ds(2, 1) = normal_scale*nvec(2)
            r%dlam_ds(2, 2) = slip_scale*(zero_ratio - ratio*nvec(2)*nvec(1))
            r%dlam_ds(1, 3) = slip_scale*(zero_ratio - ratio*nvec(1)*nvec(2))
            r%dlam_ds(2, 3) = slip_scale*(one_ratio - ratio*nvec(2)*nvec(2))
         end if
         ! the tangent: row 1 kk_n e_1; rows 2:ntens C^f_T d lambda/ds + kk_t (0, I)
         r%tangent(1, 1) = kk_n
         r%tangent(2, 1) = c%cf_t*r%dlam_ds(1, 1)
         r%tangent(1, 2) = 0.0_dp
         r%tangent(2, 2) = c%cf_t*r%dlam_ds(1, 2) + kk_t
         r%tangent(1, 3) = 0.0_dp
         if (ntens == 2) then
            r%tangent(3, 1:2) = 0.0_dp
            r%tangent(2:3, 3) = 0.0_dp
         else
            r%tangent(3, 1) = c%cf_t*r%dlam_ds(2, 1)
            r%tangent(3, 2) = c%cf_t*r%dlam_ds(2, 2)
            r%tangent(2, 3) = c%cf_t*r%dlam_ds(1, 3)
            r%tangent(3, 3) = c%cf_t*r%dlam_ds(2, 3) + kk_t
         end if
      else
         ! stick
         slip = slip_old
         r%slip = slip
         r%regime = REGIME_STICK
         r%traction(2:3) = kk_t*st + c%cf_t*slip_old
         r%psi = closed_energy(c, d, s_n, st, ntens, r%traction, slip)
         call set_diagonal_tangent(kk_n, kk_t, ntens, r%tangent)
         r%dlam_ds = 0.0_dp
         if (.not. with_dd) then
            r%dlam_dd = 0.0_dp
            r%dtrac_dd(2:3) = 0.0_dp
         else if (present(dslip_dd)) then
            r%dlam_dd = dslip_dd
            r%dtrac_dd(2:3) = (dc%k_t + dc%kc_t)*st + dc%cf_t*slip_old + c%cf_t*dslip_dd
         else
            r%dlam_dd = 0.0_dp
            r%dtrac_dd(2:3) = (dc%k_t + dc%kc_t)*st + dc%cf_t*slip_old
         end if
      end if
   end subroutine respond

   !> The closed crack's stored energy psi = 1/2 t.s + 1/2 C^f_T lambda.s_T - 1/2 D T^f ufbar
   !> |lambda|^2 (N/mm; docs/theory.md), formed as interphase_block forms it.
   pure real(dp) function closed_energy(c, d, s_n, st, ntens, traction, slip) result(psi)
      type(coefficient_set_type), intent(in) :: c         !! coefficients at D
      real(dp), intent(in) :: d                           !! damage D (-)
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm)
      integer, intent(in) :: ntens
      real(dp), intent(in) :: traction(3)                 !! t (MPa)
      real(dp), intent(in) :: slip(2)                     !! lambda (mm)
      psi = 0.5_dp*(traction(1)*s_n + shear_work(traction, st, ntens)) &
         + 0.5_dp*c%cf_t*(slip(1)*st(1) + slip(2)*st(2)) &
         - 0.5_dp*d*c%tf*c%ufbar*(slip(1)**2 + slip(2)**2)
   end function closed_energy

   !> tangent = diag(a, b, b) in 3-D, diag(a, b, 0) in 2-D (zeros elsewhere).
   pure subroutine set_diagonal_tangent(a, b, ntens, tangent)
      real(dp), intent(in) :: a, b                        !! normal and shear stiffness (MPa/mm)
      integer, intent(in) :: ntens
      real(dp), intent(out) :: tangent(3, 3)              !! (MPa/mm)
      tangent(1, 1) = a
      tangent(2:3, 1) = 0.0_dp
      tangent(1, 2) = 0.0_dp
      tangent(2, 2) = b
      tangent(3, 2) = 0.0_dp
      tangent(1:2, 3) = 0.0_dp
      tangent(3, 3) = 0.0_dp
      if (ntens == 3) tangent(3, 3) = b
   end subroutine set_diagonal_tangent

   !> The shear part t_T.s_T of the work t.s (N/mm), formed as interphase_block forms it:
   !> t_T1 s_T1 + 0 in 2-D, t_T1 s_T1 + t_T2 s_T2 in 3-D (written out: a SUM over a run-time
   !> extent is a loop).
   pure real(dp) function shear_work(traction, st, ntens) result(w)
      real(dp), intent(in) :: traction(3)                 !! t (MPa)
      real(dp), intent(in) :: st(2)                       !! s_T (mm)
      integer, intent(in) :: ntens
      if (ntens == 3) then
         w = traction(2)*st(1) + traction(3)*st(2)
      else
         w = traction(2)*st(1) + 0.0_dp
      end if
   end function shear_work

   !> The contact band's shape (docs/theory.md, 'The contact band'): g = |s_T|^2 (1 - W(t)),
   !> t = s_N/(chi |s_T|), W(t) = 10 t^3 - 15 t^4 + 6 t^5, with its gradient and Hessian in
   !> s = (s_N, s_T[, s_T2]) (mm^2, mm, -; the Hessian only when asked for: the release rate
   !> needs none). inside = .false. (and g = 0) outside the band 0 < s_N < chi |s_T|.
   pure subroutine contact_band_shape(chi, s_n, st, ntens, inside, g, grad, hess)
      real(dp), intent(in) :: chi                         !! band width chi (-), > 0
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm)
      integer, intent(in) :: ntens
      logical, intent(out) :: inside
      real(dp), intent(out) :: g, grad(3)
      real(dp), intent(out), optional :: hess(3, 3)
      real(dp) :: rho, tb, w, w1, w2, a_t, h_nt, h_tt, e(2)
      integer :: nt, i, j
      nt = ntens - 1
      g = 0.0_dp
      grad = 0.0_dp
      if (present(hess)) hess = 0.0_dp
      rho = sqrt(st(1)**2 + st(2)**2)
      inside = s_n > 0.0_dp .and. s_n < chi*rho
      if (.not. inside) return
      tb = s_n/(chi*rho)                          ! in (0, 1)
      e = st/rho                                  ! shear direction (|e| = 1; rho > 0 here)
      w = tb**3*(10.0_dp + tb*(-15.0_dp + 6.0_dp*tb))
      w1 = 30.0_dp*(tb*(1.0_dp - tb))**2
      w2 = 60.0_dp*tb*(1.0_dp - tb)*(1.0_dp - 2.0_dp*tb)
      g = rho**2*(1.0_dp - w)
      a_t = 2.0_dp*(1.0_dp - w) + tb*w1
      grad(1) = -rho*w1/chi
      grad(2:ntens) = a_t*st(1:nt)
      if (.not. present(hess)) return
      ! (the Hessian's mixed and shear-shear parts written with e, not st/rho^k: no overflow
      ! for tiny |s_T|)
      h_nt = -(w1 - tb*w2)/chi
      h_tt = tb*(w1 - tb*w2)
      hess(1, 1) = -w2/chi**2
      do i = 1, nt
         hess(1, 1 + i) = h_nt*e(i)
         hess(1 + i, 1) = hess(1, 1 + i)
         do j = 1, nt
            hess(1 + i, 1 + j) = merge(a_t, 0.0_dp, i == j) + h_tt*e(i)*e(j)
         end do
      end do
   end subroutine contact_band_shape

   !> q = kc_T - C^f_T T^c_T/T^f (MPa/mm), the frictionless closed crack's shear stiffness over
   !> the open crack's, and its first and second derivatives in D (c, dc, d2c: the coefficients
   !> and their derivatives; d2c may be zero when q'' is not wanted). T^f < 0 is the caller's
   !> check.
   pure subroutine band_stiffness(c, dc, d2c, q, dq, d2q)
      type(coefficient_set_type), intent(in) :: c, dc, d2c
      real(dp), intent(out) :: q, dq, d2q
      real(dp) :: u, du, d2u
      ! q = kc_t - u/T^f with u = C^f_T T^c_T
      u = c%cf_t*c%tc_t
      du = dc%cf_t*c%tc_t + c%cf_t*dc%tc_t
      d2u = d2c%cf_t*c%tc_t + 2.0_dp*dc%cf_t*dc%tc_t + c%cf_t*d2c%tc_t
      q = c%kc_t - u/c%tf
      dq = dc%kc_t - du/c%tf + u*dc%tf/c%tf**2
      d2q = d2c%kc_t - d2u/c%tf + 2.0_dp*du*dc%tf/c%tf**2 + u*d2c%tf/c%tf**2 - 2.0_dp*u*dc%tf**2/c%tf**3
   end subroutine band_stiffness

   !> The contact band (option OPT_CONTACT_BAND, docs/theory.md 'The contact band'). At s_N = 0
   !> the closed crack slips without friction (mu sigma = 0), the bilateral crack, whose shear
   !> stiffness exceeds the open crack's by q (band_stiffness; the I coupling). On the opening
   !> side, 0 < s_N < chi |s_T|, that excess fades out with the open crack's energy
   !>   psi = 1/2 k_n s_N^2 + 1/2 k_t |s_T|^2 + 1/2 q g,  g = |s_T|^2 (1 - W(t))
   !> (contact_band_shape), so that t = d psi/ds is continuous where the crack opens (the
   !> tangent keeps the unilateral contact's kink there) and, with its tangent, at the band's
   !> upper edge; the law stays hyperelastic at fixed D. The closed crack (s_N <= 0) is the
   !> paper's. On entry `r` holds the open crack's response; outside the band it is left as it is.
   pure subroutine blend_contact_band(chi, c, dc, s_n, st, ntens, r, status)
      real(dp), intent(in) :: chi                         !! band width chi (-), > 0
      type(coefficient_set_type), intent(in) :: c, dc     !! coefficients at D and d/dD
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm), s_N > 0
      integer, intent(in) :: ntens
      type(response_type), intent(inout) :: r             !! open response in, banded out
      integer, intent(out) :: status

      real(dp) :: q, dq, unused_d2q, g, gq(3), hq(3, 3)
      logical :: inside

      status = STATUS_OK
      call contact_band_shape(chi, s_n, st, ntens, inside, g, gq, hq)
      if (.not. inside) return
      if (.not. (c%tf < 0.0_dp)) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      call band_stiffness(c, dc, NO_COEFFICIENTS, q, dq, unused_d2q)
      r%traction(1:ntens) = r%traction(1:ntens) + 0.5_dp*q*gq(1:ntens)
      r%tangent(1:ntens, 1:ntens) = r%tangent(1:ntens, 1:ntens) + 0.5_dp*q*hq(1:ntens, 1:ntens)
      r%dtrac_dd(1:ntens) = r%dtrac_dd(1:ntens) + 0.5_dp*dq*gq(1:ntens)
      r%psi = r%psi + 0.5_dp*q*g
   end subroutine blend_contact_band

end module interphase_response
