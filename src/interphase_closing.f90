!> A crack that closes within the increment: the slip its friction step starts from, and that
!> slip's share of the tangent (docs/theory.md, 'An increment across which the crack closes').
!> The decision is `closes_within` (interphase_closes_within.inc, inlined where the update runs);
!> these procedures run only where it holds, and live in their own module so that the update's
!> hot path does not carry them (a compiler that inlined them there grew the UMAT's paths past
!> their own inlining: docs/performance.md).
!>
!> An increment that starts open (s_N,n > 0) and ends closed (s_N <= 0) passes, on its straight
!> path s_n + t (s - s_n), through s_N = 0 at t_c = s_N,n/(s_N,n - s_N), where the faces meet. There
!> the closed crack carries no normal stress (sigma = S^c_N s_N = 0), so no friction: its faces
!> slip to tau = 0, lambda_c = (T^c_T/kf) s_T(t_c), kf = -T^f, with the coefficients at D_c (the
!> closed branch of the response at s_N = 0; a refined path reaches the same slip, whichever side
!> of s_N = 0 its increments end on). The friction step then starts from lambda_c, not from lambda_n,
!> and the closed state no longer depends on where the increment began (with the displacement law
!> the crack's growth on the way to the crossing included, D_c; the fracture law and viscous
!> regularisation form lambda_c at D_n: docs/theory.md, 'An
!> increment across which the crack closes'). For the simplified model lambda_c = s_T(t_c), the
!> open crack's slip there; for the micromechanical model the table's open slip dbar_t s_T/ufbar
!> lies within 0.2 % of it (at D = 0.9; the same docs).
module interphase_closing
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_state, only: interface_state_type
   use interphase_enums, only: REGIME_STICK, REGIME_SLIP, GROWTH_FIXED_PI, DAMAGE_DISPLACEMENT
   use interphase_damage, only: damage_terms_type, displacement_damage, damage_slopes
   use interphase_status, only: STATUS_OK, STATUS_BAD_COEFFICIENTS
   use interphase_coefficients, only: coefficient_set_type
   use interphase_provider, only: coefficients_at, coefficient_values_at
   use interphase_response, only: response_type, growth_trial_slip
   implicit none
   private
   public :: closing_slip, add_closing_share

contains

   !> For a crack that closes within the increment (update_point decides: closes_within), the
   !> damage D_c and the slip lambda_c where its faces met, and their derivatives with respect to
   !> the separation at the end (columns 1:ntens; zeros beyond). With the displacement-driven law
   !> (without viscous regularisation) the open crack grows on the way to the crossing: D_c =
   !> max(D_n, min(1, D^(s(t_c)))), a function of s(t_c) (where s_N = 0: of |s_T(t_c)| alone); with
   !> the fracture-mechanics law or viscous regularisation D_c = D_n (docs/theory.md, 'What it
   !> leaves out'). lambda_c = (T^c_T/kf)(D_c) s_T(t_c).
   pure subroutine closing_slip(params, old, s_start, s_n, st1, st2, ntens, slip_from, dfrom_ds, d_c, dd_c_ds, &
         dm_c, status)
      type(law_params_type), intent(in) :: params
      type(interface_state_type), intent(in) :: old      !! state at the start of the increment
      real(dp), intent(in) :: s_start(3)                 !! separation at the start, s_N,n > 0 (mm)
      !> separation at the end (mm), s_N <= 0 (by value: the caller's array is not passed, so that
      !> its compiler keeps it where it likes)
      real(dp), value :: s_n, st1, st2
      integer, intent(in) :: ntens
      real(dp), intent(out) :: slip_from(2)              !! lambda_c (mm)
      real(dp), intent(out) :: dfrom_ds(2, 3)            !! d lambda_c/ds (-)
      real(dp), intent(out) :: d_c                       !! D_c, the damage where the faces met (-)
      real(dp), intent(out) :: dd_c_ds(3)                !! dD_c/ds (1/mm)
      real(dp), intent(out) :: dm_c                      !! m'(D_c) = ufbar + D ufbar' at D_c (-)
      integer, intent(out) :: status

      type(coefficient_set_type) :: c_c, dc_c
      type(damage_terms_type) :: terms
      real(dp) :: t_c, dt_dsn, ratio, dratio, st_start(2), st_c(2), st(2), t_sq, t_norm, d_hat, dd_dsn, dd_dt
      real(dp) :: dst_c(2, 3)   ! d s_T(t_c)/ds
      logical :: grows_c
      integer :: j

      dfrom_ds = 0.0_dp
      dd_c_ds = 0.0_dp
      dm_c = 0.0_dp
      slip_from = old%slip
      st = [st1, st2]
      ! t_c in (0, 1]: s_N,n - s_N >= s_N,n > 1e-200 mm (closes_within)
      t_c = s_start(1)/(s_start(1) - s_n)
      dt_dsn = t_c/(s_start(1) - s_n)
      st_start(1) = s_start(2)
      st_start(2) = 0.0_dp
      if (ntens == 3) st_start(2) = s_start(3)
      st_c = st_start + t_c*(st - st_start)
      ! d s_T(t_c)/ds_N = (s_T - s_T,n) dt_c/ds_N, d s_T(t_c)/ds_T = t_c I
      dst_c = 0.0_dp
      dst_c(:, 1) = (st - st_start)*dt_dsn
      dst_c(1, 2) = t_c
      if (ntens == 3) dst_c(2, 3) = t_c
      if (ntens == 2) dst_c(2, :) = 0.0_dp
      ! D_c: the displacement law's damage at s(t_c), where s_N = 0 (so D^ of |s_T(t_c)| alone)
      d_c = old%d
      grows_c = .false.
      if (params%damage_law == DAMAGE_DISPLACEMENT .and. .not. (params%viscosity > 0.0_dp) .and. old%d < 1.0_dp) then
         t_sq = st_c(1)**2 + st_c(2)**2
         call displacement_damage(params, 0.0_dp, t_sq, d_hat, terms)
         d_c = max(old%d, min(1.0_dp, d_hat)) + 0.0_dp
         grows_c = d_hat > old%d .and. d_hat < 1.0_dp
         if (grows_c) then
            call damage_slopes(params, t_sq, d_hat, terms, dd_dsn, dd_dt)
            t_norm = sqrt(t_sq)
            if (t_norm > 0.0_dp) then
               do j = 1, ntens
                  dd_c_ds(j) = dd_dt*(st_c(1)*dst_c(1, j) + st_c(2)*dst_c(2, j))/t_norm
               end do
            end if
         end if
      end if
      if (grows_c) then
         call coefficients_at(params, d_c, c_c, dc_c, status)
      else
         call coefficient_values_at(params, d_c, c_c, dc_c, status)
      end if
      if (status /= STATUS_OK) return
      if (.not. (-c_c%tf > 0.0_dp)) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      dm_c = c_c%ufbar + d_c*dc_c%ufbar
      ! the frictionless slip at s_N = 0, formed as the response's mu = 0 branch forms its slope
      ratio = c_c%tc_t*(1.0_dp/(-c_c%tf))
      slip_from(1) = ratio*st_c(1)
      slip_from(2) = 0.0_dp
      if (ntens == 3) slip_from(2) = ratio*st_c(2)
      ! d lambda_c/ds = (T^c_T/kf) d s_T(t_c)/ds + s_T(t_c) d(T^c_T/kf)/dD dD_c/ds
      dratio = (dc_c%tc_t*(-c_c%tf) + c_c%tc_t*dc_c%tf)/c_c%tf**2
      do j = 1, ntens
         dfrom_ds(1:ntens - 1, j) = ratio*dst_c(1:ntens - 1, j) + st_c(1:ntens - 1)*dratio*dd_c_ds(j)
      end do
   end subroutine closing_slip

   !> Adds to the response r at D (formed by `respond` from the trial slip `slip_trial`, which the
   !> growth rule made from lambda_c: growth_trial_slip with D_from, m_from) the share of the
   !> start slip's dependence on s: d lambda/ds and the tangent gain (d lambda/d lambda_trial)
   !> (d lambda_trial/d lambda_c) d lambda_c/ds, and C^f_T times it. In stick d lambda/d lambda_trial
   !> = I; in slip -(mu sigma/|tau|)(I - n n) (zero in 2-D); with mu = 0 the crack that sticks
   !> carries the frictionless slip T^c_T s_T/kf, which does not depend on the start.
   pure subroutine add_closing_share(params, d_from, m_from, d, c, dc, s_n, st, ntens, slip_trial, dfrom_ds, r, &
         slip_from, dd_from_ds, dm_from)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d_from, m_from              !! D_n (or D_c) and m of it, as growth_trial_slip takes them
      real(dp), intent(in) :: d                           !! damage D of the response (-)
      type(coefficient_set_type), intent(in) :: c, dc     !! coefficients at D (and d/dD)
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm)
      integer, intent(in) :: ntens
      real(dp), intent(in) :: slip_trial(2)               !! the trial slip the response started from (mm)
      real(dp), intent(in) :: dfrom_ds(2, 3)              !! d lambda_c/ds (-)
      type(response_type), intent(inout) :: r
      !> where the start damage D_from itself depends on s (D_c of closing_slip): lambda_c, dD_c/ds
      !> and m'(D_c), for the growth rule's dependence on it (lambda_trial = lambda_c m(D_c)/m(D))
      real(dp), intent(in), optional :: slip_from(2), dd_from_ds(3), dm_from

      real(dp) :: dtrial_ds(2, 3), share(2, 3), column(2), unused(2), tau(2), tau_norm, nvec(2), ratio
      integer :: j, nt

      nt = ntens - 1
      ! d lambda_trial/ds: the growth rule is linear in the slip it scales
      do j = 1, 3
         call growth_trial_slip(params%growth_slip, d_from, m_from, d, c, dc, dfrom_ds(:, j), column, unused)
         dtrial_ds(:, j) = column
      end do
      if (present(dd_from_ds) .and. params%growth_slip == GROWTH_FIXED_PI .and. d > d_from) then
         ! d(m(D_c))/ds = m'(D_c) dD_c/ds: lambda_c m'(D_c)/m(D) dD_c/ds (m(D) > 0 where D > D_c >= 0)
         do j = 1, 3
            dtrial_ds(:, j) = dtrial_ds(:, j) + slip_from*(dm_from*dd_from_ds(j)/(d*c%ufbar))
         end do
      end if
      if (r%regime == REGIME_STICK) then
         if (.not. (params%mu > 0.0_dp) .and. -c%tf > 0.0_dp) return
         share = dtrial_ds
      else if (r%regime == REGIME_SLIP .and. ntens == 3) then
         tau = c%tc_t*st + c%tf*slip_trial
         tau_norm = sqrt(tau(1)**2 + tau(2)**2)
         nvec = tau*(1.0_dp/max(tau_norm, tiny(1.0_dp)))
         ratio = params%mu*c%sc_n*s_n/tau_norm
         do j = 1, 3
            share(:, j) = -ratio*(dtrial_ds(:, j) - (nvec(1)*dtrial_ds(1, j) + nvec(2)*dtrial_ds(2, j))*nvec)
         end do
      else
         return
      end if
      r%dlam_ds(1:nt, 1:ntens) = r%dlam_ds(1:nt, 1:ntens) + share(1:nt, 1:ntens)
      r%tangent(2:ntens, 1:ntens) = r%tangent(2:ntens, 1:ntens) + c%cf_t*share(1:nt, 1:ntens)
   end subroutine add_closing_share

end module interphase_closing
