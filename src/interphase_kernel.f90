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
!>   mean crack opening dbar_n s_N > 0: open crack, t = k s, crack faces free, the slip
!>   follows the mean tangential jump: lambda = dbar_t s_T / ufbar.
!>   otherwise closed: trial crack stresses sigma = sc_n s_N, tau = tc_t s_T + T^f lambda_n,
!>   phi = mu sigma + |tau| (eq 43); phi <= 0: stick; phi > 0: slip, return mapping along
!>   tau_trial (eqs 44-48): lambda = lambda_n + (phi/(-T^f)) tau/|tau|.
!>   t_N = (k_n + kc_n) s_N, t_T = (k_t + kc_t) s_T + C^f_T lambda.
!> The damage:
!>   displacement-driven law (eqs 13-18, 39): D = max(D_n, min(1, D^(s))), independent of
!>   contact and friction, so it comes first;
!>   fracture-mechanics law (eqs 20-24, 40-42, 49-50): D from g(D) = 0 (interphase_fracture);
!>   open crack: predictor D_n, corrector by a bracketed root; closed crack: the staggered
!>   scheme of section 4.2 (damage with lambda frozen, friction with D frozen) to STAGGER_TOL.
!> The consistent tangent adds (dt/dD)(dD/ds) while the crack grows (for the fracture law with
!> dD/ds from the implicit function g = 0, including the slip's dependence on s and D).
!> Stored energy: open or intact psi = 1/2 t.s; closed psi = 1/2 t.s + 1/2 C^f lambda.s_T
!> - 1/2 D T^f ufbar |lambda|^2 (docs/theory.md).
module interphase_kernel
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_layout, only: REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, &
      DAMAGE_DISPLACEMENT
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_NONFINITE_SEPARATION, &
      STATUS_BAD_COEFFICIENTS, STATUS_STAGGER_NOT_CONVERGED
   use interphase_coefficients, only: coefficient_set_type
   use interphase_provider, only: coefficients_at
   use interphase_damage, only: displacement_damage
   use interphase_fracture, only: crack_load_type, growth_function, grow_crack
   use interphase_state, only: interface_state_type
   implicit none
   private
   public :: interface_update

   !> Staggered damage-friction iteration (fracture law, closed crack): tolerance on D and the
   !> largest number of passes.
   real(dp), parameter :: STAGGER_TOL = 1.0e-13_dp
   integer, parameter :: STAGGER_MAX = 100

   !> The response at fixed D (internal).
   type :: response_type
      real(dp) :: traction(3) = 0.0_dp         !! t (MPa)
      real(dp) :: tangent(3, 3) = 0.0_dp       !! dt/ds at fixed D (MPa/mm)
      real(dp) :: dtrac_dd(3) = 0.0_dp         !! dt/dD at fixed s (MPa)
      real(dp) :: slip(2) = 0.0_dp             !! lambda (mm)
      real(dp) :: dlam_ds(2, 3) = 0.0_dp       !! d lambda/ds at fixed D (slip regime)
      real(dp) :: dlam_dd(2) = 0.0_dp          !! d lambda/dD at fixed s (slip regime)
      real(dp) :: psi = 0.0_dp                 !! stored energy (N/mm)
      integer :: regime = REGIME_INTACT
      logical :: closed = .false.
   end type response_type

contains

   !> Update one interface point from the old state and the separation at the end of the
   !> increment. On a non-zero status the outputs are undefined and must not be used.
   pure subroutine interface_update(params, old, s, traction, tangent, new, psi, status)
      type(law_params_type), intent(in) :: params        !! material parameters
      type(interface_state_type), intent(in) :: old      !! state at the start of the increment
      real(dp), intent(in) :: s(:)                       !! separation (s_N, s_T[, s_T2]) (mm)
      real(dp), intent(out) :: traction(:)               !! traction, same order (MPa)
      real(dp), intent(out) :: tangent(:, :)             !! dtraction/ds (MPa/mm), unsymmetric
      type(interface_state_type), intent(out) :: new     !! state at the end of the increment
      real(dp), intent(out) :: psi                       !! stored energy per unit area (N/mm)
      integer, intent(out) :: status                     !! STATUS_OK or a failure code

      type(coefficient_set_type) :: c, dc
      type(response_type) :: r
      real(dp) :: s_n, st(2), t, d_hat, dd_dsn, dd_dt, d, dd_ds(3)
      integer :: ntens, nt, j

      ntens = size(s)
      nt = ntens - 1
      if (ntens /= 2 .and. ntens /= 3) then
         status = STATUS_BAD_NTENS
         return
      end if
      if (.not. all(is_finite(s))) then
         status = STATUS_NONFINITE_SEPARATION
         return
      end if
      s_n = s(1)
      st = 0.0_dp
      st(1:nt) = s(2:ntens)

      if (params%damage_law == DAMAGE_DISPLACEMENT) then
         ! damage first (eq 39), then the response at that damage
         t = sqrt(st(1)**2 + st(2)**2)
         call displacement_damage(params, s_n, t, d_hat, dd_dsn, dd_dt)
         d = max(old%d, min(1.0_dp, d_hat))
         dd_ds = 0.0_dp
         if (d_hat > old%d .and. d_hat < 1.0_dp) then
            dd_ds(1) = dd_dsn
            if (t > 0.0_dp) dd_ds(2:ntens) = dd_dt*st(1:nt)/t
         end if
         call coefficients_at(params, d, c, dc, status)
         if (status /= STATUS_OK) return
         call respond(params, c, dc, d, old%slip, s_n, st, ntens, r, status)
         if (status /= STATUS_OK) return
      else
         call fracture_update(params, old, s_n, st, ntens, d, r, dd_ds, status)
         if (status /= STATUS_OK) return
      end if

      new%d = d
      new%slip = r%slip
      new%regime = r%regime
      traction(1:ntens) = r%traction(1:ntens)
      do j = 1, ntens
         tangent(1:ntens, j) = r%tangent(1:ntens, j) + r%dtrac_dd(1:ntens)*dd_ds(j)
      end do
      psi = r%psi
   end subroutine interface_update

   !> The fracture-mechanics law: D from g = 0, the response at that D, and dD/ds.
   pure subroutine fracture_update(params, old, s_n, st, ntens, d, r, dd_ds, status)
      type(law_params_type), intent(in) :: params
      type(interface_state_type), intent(in) :: old
      real(dp), intent(in) :: s_n, st(2)
      integer, intent(in) :: ntens
      real(dp), intent(out) :: d                      !! damage at the end of the increment
      type(response_type), intent(out) :: r           !! response at d
      real(dp), intent(out) :: dd_ds(3)               !! dD/ds (0 unless the crack grows)
      integer, intent(out) :: status

      type(coefficient_set_type) :: c, dc
      type(crack_load_type) :: load
      real(dp) :: d_n, d_next, g, g_s(3), g_lam(2), g_d, denominator, numerator(3)
      integer :: iter, j, nt

      nt = ntens - 1
      d_n = max(old%d, params%d0)                     ! the initial crack a0 = D0 b
      d = d_n
      load%s_n = s_n
      load%st = st
      dd_ds = 0.0_dp
      do iter = 1, STAGGER_MAX
         ! friction with D frozen
         call coefficients_at(params, d, c, dc, status)
         if (status /= STATUS_OK) return
         call respond(params, c, dc, d, old%slip, s_n, st, ntens, r, status)
         if (status /= STATUS_OK) return
         ! damage with lambda frozen
         load%closed = r%closed
         load%slip = r%slip
         call grow_crack(params, d_n, load, ntens, d_next, status)
         if (status /= STATUS_OK) return
         if (abs(d_next - d) <= STAGGER_TOL) exit
         d = d_next
         if (iter == STAGGER_MAX) then
            status = STATUS_STAGGER_NOT_CONVERGED
            return
         end if
      end do
      if (abs(d_next - d) > 0.0_dp) then
         d = d_next
         call coefficients_at(params, d, c, dc, status)
         if (status /= STATUS_OK) return
         call respond(params, c, dc, d, old%slip, s_n, st, ntens, r, status)
         if (status /= STATUS_OK) return
      end if

      ! dD/ds from g(D, s, lambda(s, D)) = 0 while the crack grows
      if (d > d_n .and. d < 1.0_dp) then
         load%closed = r%closed
         load%slip = r%slip
         call growth_function(params, d, load, ntens, g, status, .true., g_s, g_lam, g_d)
         if (status /= STATUS_OK) return
         numerator = g_s
         denominator = g_d
         do j = 1, nt
            numerator = numerator + g_lam(j)*r%dlam_ds(j, :)
            denominator = denominator + g_lam(j)*r%dlam_dd(j)
         end do
         if (abs(denominator) > 0.0_dp) dd_ds(1:ntens) = -numerator(1:ntens)/denominator
      end if
   end subroutine fracture_update

   !> The response at a fixed damage D: regime, traction, tangent at fixed D, dt/dD, slip and
   !> its sensitivities, stored energy.
   pure subroutine respond(params, c, dc, d, slip_old, s_n, st, ntens, r, status)
      type(law_params_type), intent(in) :: params
      type(coefficient_set_type), intent(in) :: c, dc     !! coefficients at D and d/dD
      real(dp), intent(in) :: d                           !! damage D
      real(dp), intent(in) :: slip_old(2)                 !! slip at the start of the increment (mm)
      real(dp), intent(in) :: s_n, st(2)                  !! separation (mm)
      integer, intent(in) :: ntens
      type(response_type), intent(out) :: r
      integer, intent(out) :: status

      real(dp) :: kk_n, kk_t, sigma, tau(2), tau_norm, phi, kf, nvec(2), dgamma, ratio
      real(dp) :: dtau_dd(2), dphi_dd, proj_dtau(2), n_dot
      integer :: nt, i, j

      status = STATUS_OK
      nt = ntens - 1
      if (d <= 0.0_dp .or. c%dbar_n*s_n > 0.0_dp) then
         ! intact, or open crack: Sigma = C E, crack faces traction-free
         r%traction(1) = c%k_n*s_n
         r%traction(2:ntens) = c%k_t*st(1:nt)
         r%tangent(1, 1) = c%k_n
         do i = 2, ntens
            r%tangent(i, i) = c%k_t
         end do
         r%dtrac_dd(1) = dc%k_n*s_n
         r%dtrac_dd(2:ntens) = dc%k_t*st(1:nt)
         if (d <= 0.0_dp) then
            r%slip = slip_old
            r%regime = REGIME_INTACT
         else
            r%slip = 0.0_dp
            r%slip(1:nt) = c%dbar_t*st(1:nt)/c%ufbar
            r%regime = REGIME_OPEN
         end if
         r%psi = 0.5_dp*sum(r%traction(1:ntens)*[s_n, st(1:nt)])
         return
      end if

      ! closed crack: trial stick state, eq 43
      r%closed = .true.
      kk_n = c%k_n + c%kc_n
      kk_t = c%k_t + c%kc_t
      sigma = c%sc_n*s_n
      tau = c%tc_t*st + c%tf*slip_old
      tau_norm = sqrt(tau(1)**2 + tau(2)**2)
      phi = params%mu*sigma + tau_norm
      r%traction(1) = kk_n*s_n
      r%tangent(1, 1) = kk_n
      r%dtrac_dd(1) = (dc%k_n + dc%kc_n)*s_n
      if (phi > 0.0_dp .and. tau_norm > 0.0_dp) then
         ! slip: return mapping along the trial crack shear stress, eqs 44-48
         kf = -c%tf
         if (.not. (kf > 0.0_dp)) then
            status = STATUS_BAD_COEFFICIENTS
            return
         end if
         nvec = tau/tau_norm
         dgamma = phi/kf
         r%slip = slip_old + dgamma*nvec
         r%regime = REGIME_SLIP
         ! d lambda/d s_T = (T^c_T/kf) [I + (mu sigma/|tau|)(I - n n)], d lambda/d s_N = (mu S^c_N/kf) n
         ratio = params%mu*sigma/tau_norm
         do j = 1, nt
            do i = 1, nt
               r%dlam_ds(i, 1 + j) = (c%tc_t/kf)*(merge(1.0_dp, 0.0_dp, i == j)*(1.0_dp + ratio) &
                  - ratio*nvec(i)*nvec(j))
            end do
            r%dlam_ds(j, 1) = params%mu*c%sc_n/kf*nvec(j)
         end do
         ! d lambda/dD at fixed s
         dtau_dd = dc%tc_t*st + dc%tf*slip_old
         n_dot = nvec(1)*dtau_dd(1) + nvec(2)*dtau_dd(2)
         dphi_dd = params%mu*dc%sc_n*s_n + n_dot
         proj_dtau = dtau_dd - n_dot*nvec
         r%dlam_dd = (nvec*dphi_dd + (phi/tau_norm)*proj_dtau)/kf + dgamma*nvec*dc%tf/kf
         r%traction(2:ntens) = kk_t*st(1:nt) + c%cf_t*r%slip(1:nt)
         do j = 1, ntens
            r%tangent(2:ntens, j) = c%cf_t*r%dlam_ds(1:nt, j)
         end do
         do i = 2, ntens
            r%tangent(i, i) = r%tangent(i, i) + kk_t
         end do
         r%dtrac_dd(2:ntens) = (dc%k_t + dc%kc_t)*st(1:nt) + dc%cf_t*r%slip(1:nt) + c%cf_t*r%dlam_dd(1:nt)
      else
         ! stick
         r%slip = slip_old
         r%regime = REGIME_STICK
         r%traction(2:ntens) = kk_t*st(1:nt) + c%cf_t*slip_old(1:nt)
         do i = 2, ntens
            r%tangent(i, i) = kk_t
         end do
         r%dtrac_dd(2:ntens) = (dc%k_t + dc%kc_t)*st(1:nt) + dc%cf_t*slip_old(1:nt)
      end if
      r%psi = 0.5_dp*sum(r%traction(1:ntens)*[s_n, st(1:nt)]) &
         + 0.5_dp*c%cf_t*(r%slip(1)*st(1) + r%slip(2)*st(2)) &
         - 0.5_dp*d*c%tf*c%ufbar*(r%slip(1)**2 + r%slip(2)**2)
   end subroutine respond

end module interphase_kernel
