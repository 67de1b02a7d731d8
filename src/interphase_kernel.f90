!> The update of one interface point (the paper's section 4), written once against the
!> coefficient set of `interphase_coefficients`, for every coefficient provider, in 2-D
!> (s_N, s_T) and 3-D (s_N, s_T1, s_T2; isotropic in the interface plane, vector slip).
!>
!> Component order everywhere is Abaqus's for cohesive elements: normal first, then the
!> shear(s). Separations in mm, tractions in MPa, tangent in MPa/mm, energy in N/mm.
!>
!> The algorithm, for the displacement-driven damage law (damage does not depend on contact or
!> friction, so it is evaluated first, eq 39):
!>   1. D = max(D_n, min(1, D^(s)))                                  (eqs 13-18, 39)
!>   2. coefficients at D from the provider (and their D-derivatives)
!>   3. D = 0: intact, t = k s.
!>      mean crack opening dbar_n s_N > 0: open crack, t = k s, crack faces free, the slip
!>      follows the mean tangential jump: lambda = dbar_t s_T / ufbar.
!>      otherwise closed: trial crack stresses sigma = sc_n s_N, tau = tc_t s_T + T^f lambda_n,
!>      phi = mu sigma + |tau| (eq 43); phi <= 0: stick; phi > 0: slip, return mapping along
!>      tau_trial (eqs 44-48): lambda = lambda_n + (phi/(-T^f)) tau/|tau|.
!>      t_N = (k_n + kc_n) s_N, t_T = (k_t + kc_t) s_T + C^f_T lambda.
!>   4. consistent tangent dt/ds, with the damage term (dt/dD)(dD/ds) while damage grows.
!>   5. stored energy psi = 1/2 t.s - 1/2 D T^f (ufbar |lambda|^2 - dbar_t lambda.s_T)
!>      (derivation in docs/theory.md).
module interphase_kernel
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_layout, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, REGIME_INTACT, REGIME_OPEN, REGIME_STICK, &
      REGIME_SLIP
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_NONFINITE_SEPARATION, &
      STATUS_BAD_COEFFICIENTS, STATUS_MODEL_UNAVAILABLE
   use interphase_coefficients, only: coefficient_set_type, simplified_coefficients
   use interphase_micro_coefficients, only: micro_coefficients
   use interphase_damage, only: displacement_damage
   use interphase_state, only: interface_state_type
   implicit none
   private
   public :: interface_update

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
      real(dp) :: s_n, st(2), t, d_hat, dd_dsn, dd_dt, d, dd_ds(3), dtrac_dd(3)
      real(dp) :: kk_n, kk_t, sigma, tau(2), tau_norm, phi, kf, nvec(2), dgamma, ratio
      real(dp) :: dtau_dd(2), dphi_dd, dlam_dd(2), proj_dtau(2), n_dot
      integer :: ntens, nt, i, j
      logical :: growing

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
      status = STATUS_OK

      s_n = s(1)
      st = 0.0_dp
      st(1:nt) = s(2:ntens)
      t = sqrt(st(1)**2 + st(2)**2)

      ! 1. damage, eq 39
      call displacement_damage(params, s_n, t, d_hat, dd_dsn, dd_dt)
      growing = d_hat > old%d .and. d_hat < 1.0_dp
      d = max(old%d, min(1.0_dp, d_hat))
      dd_ds = 0.0_dp
      if (growing) then
         dd_ds(1) = dd_dsn
         if (t > 0.0_dp) dd_ds(2:ntens) = dd_dt*st(1:nt)/t
      end if

      ! 2. coefficients at D
      select case (params%model)
      case (MODEL_SIMPLIFIED)
         call simplified_coefficients(params%k_n, params%k_t, d, c, dc)
      case (MODEL_MICROMECHANICAL)
         call micro_coefficients(params%table, d, c, dc, status)
         if (status /= STATUS_OK) return
      case default
         status = STATUS_MODEL_UNAVAILABLE
         return
      end select

      ! 3. regime
      new%d = d
      tangent(1:ntens, 1:ntens) = 0.0_dp
      dtrac_dd = 0.0_dp
      if (d <= 0.0_dp .or. c%dbar_n*s_n > 0.0_dp) then
         ! intact, or open crack: Sigma = C E, crack faces traction-free
         traction(1) = c%k_n*s_n
         traction(2:ntens) = c%k_t*st(1:nt)
         tangent(1, 1) = c%k_n
         do i = 2, ntens
            tangent(i, i) = c%k_t
         end do
         dtrac_dd(1) = dc%k_n*s_n
         dtrac_dd(2:ntens) = dc%k_t*st(1:nt)
         if (d <= 0.0_dp) then
            new%slip = old%slip
            new%regime = REGIME_INTACT
         else
            new%slip = 0.0_dp
            new%slip(1:nt) = c%dbar_t*st(1:nt)/c%ufbar
            new%regime = REGIME_OPEN
         end if
      else
         ! closed crack: trial stick state, eq 43
         kk_n = c%k_n + c%kc_n
         kk_t = c%k_t + c%kc_t
         sigma = c%sc_n*s_n
         tau = c%tc_t*st + c%tf*old%slip
         tau_norm = sqrt(tau(1)**2 + tau(2)**2)
         phi = params%mu*sigma + tau_norm
         traction(1) = kk_n*s_n
         tangent(1, 1) = kk_n
         dtrac_dd(1) = (dc%k_n + dc%kc_n)*s_n
         if (phi > 0.0_dp .and. tau_norm > 0.0_dp) then
            ! slip: return mapping along the trial crack shear stress, eqs 44-48
            kf = -c%tf
            if (.not. (kf > 0.0_dp)) then
               status = STATUS_BAD_COEFFICIENTS
               return
            end if
            nvec = tau/tau_norm
            dgamma = phi/kf
            new%slip = old%slip + dgamma*nvec
            new%regime = REGIME_SLIP
            traction(2:ntens) = kk_t*st(1:nt) + c%cf_t*new%slip(1:nt)
            ! d lambda/d s_T = (T^c_T/kf) [I + (mu sigma/|tau|)(I - n n)]
            ratio = params%mu*sigma/tau_norm
            do j = 1, nt
               do i = 1, nt
                  tangent(1 + i, 1 + j) = c%cf_t*(c%tc_t/kf)*(merge(1.0_dp, 0.0_dp, i == j)*(1.0_dp + ratio) &
                     - ratio*nvec(i)*nvec(j))
               end do
               tangent(1 + j, 1 + j) = tangent(1 + j, 1 + j) + kk_t
               ! d lambda/d s_N = (mu S^c_N/kf) n
               tangent(1 + j, 1) = c%cf_t*params%mu*c%sc_n/kf*nvec(j)
            end do
            ! d lambda/dD at fixed s
            dtau_dd = dc%tc_t*st + dc%tf*old%slip
            n_dot = nvec(1)*dtau_dd(1) + nvec(2)*dtau_dd(2)
            dphi_dd = params%mu*dc%sc_n*s_n + n_dot
            proj_dtau = dtau_dd - n_dot*nvec
            dlam_dd = (nvec*dphi_dd + (phi/tau_norm)*proj_dtau)/kf + dgamma*nvec*dc%tf/kf
            dtrac_dd(2:ntens) = (dc%k_t + dc%kc_t)*st(1:nt) + dc%cf_t*new%slip(1:nt) &
               + c%cf_t*dlam_dd(1:nt)
         else
            ! stick
            new%slip = old%slip
            new%regime = REGIME_STICK
            traction(2:ntens) = kk_t*st(1:nt) + c%cf_t*old%slip(1:nt)
            do i = 2, ntens
               tangent(i, i) = kk_t
            end do
            dtrac_dd(2:ntens) = (dc%k_t + dc%kc_t)*st(1:nt) + dc%cf_t*old%slip(1:nt)
         end if
      end if

      ! 4. damage term of the consistent tangent
      if (growing) then
         do j = 1, ntens
            tangent(1:ntens, j) = tangent(1:ntens, j) + dtrac_dd(1:ntens)*dd_ds(j)
         end do
      end if

      ! 5. stored energy
      psi = 0.5_dp*sum(traction(1:ntens)*s(1:ntens)) &
         - 0.5_dp*d*c%tf*(c%ufbar*(new%slip(1)**2 + new%slip(2)**2) &
         - c%dbar_t*(new%slip(1)*st(1) + new%slip(2)*st(2)))
   end subroutine interface_update

end module interphase_kernel
