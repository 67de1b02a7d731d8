!> The update of a whole block of interface points at once, for hosts that pass many points per
!> call (Abaqus/Explicit's VUMAT, a vectorised FE assembly): the simplified model with the
!> displacement-driven damage law, written so that the compiler vectorises the loop over the
!> points (SIMD). The points are stored component by component (structure of arrays), as
!> Abaqus/Explicit lays out its block arrays, so every column is read and written contiguously.
!>
!> Same law, same arithmetic, same results as `interface_update` (`interphase_kernel`) point by
!> point, bit for bit (tests/test_vumat.pf checks 4237 points over histories that reach every
!> regime, in 2-D and 3-D): every branch of the scalar update becomes a selection (`merge`)
!> between the branches, both evaluated on guarded operands so that no branch can raise a
!> floating-point exception. No tangent is formed (explicit hosts do not use one).
!> The one branch kept is per group of 64 points: D^ (a square root and a division, the costliest
!> operations of the update) is evaluated only for a group in which some point can grow.
!>
!> Compiler notes (gfortran 12; docs/performance.md): the file needs -fno-trapping-math to
!> vectorise (CMakeLists.txt sets it); `merge` is evaluated lazily, so a load inside one is a
!> branch (every value is loaded first); a local name must not repeat a use-associated one in
!> another case (Fortran names are case-insensitive: a local `regime_open` silently took the
!> place of REGIME_OPEN).
!>
!> Also here: the check of a block's densities, and whether it has just one, as branch-free
!> counts (the incoming states are counted by `count_invalid_states` of interphase_state, beside
!> the STATEV decoder), so that a host can validate a block in one vectorised pass and look for
!> the culprit only on error.
module interphase_block
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_finite, only: MAGNITUDE_MASK
   use interphase_params, only: law_params_type, SEPARATION_MAX, DENSITY_MIN, DENSITY_MAX, HOST_VALUE_MAX, &
      HOST_INCREMENT_MAX, SLIP_ONSET_ROUNDOFF
   use interphase_enums, only: REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, GROWTH_FIXED_PI, &
      MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT
   use interphase_micro_coefficients, only: micro_block_coefficients, micro_block_ufbar
   implicit none
   private
   public :: block_update, simplified_block_update, micromechanical_block_update, density_counts, block_supports, &
      block_energies

   !> Bit patterns of DENSITY_MIN and DENSITY_MAX (positive numbers are ordered like their bits).
   integer(int64), parameter :: DENSITY_MIN_BITS = transfer(DENSITY_MIN, 0_int64)
   integer(int64), parameter :: DENSITY_MAX_BITS = transfer(DENSITY_MAX, 0_int64)
   !> Bit pattern of SEPARATION_MAX: |x| <= SEPARATION_MAX exactly when the bits of |x| are at most these.
   integer(int64), parameter :: SEPARATION_MAX_BITS = transfer(SEPARATION_MAX, 0_int64)
   !> Bit patterns of HOST_VALUE_MAX and HOST_INCREMENT_MAX (the same test on |x|).
   integer(int64), parameter :: HOST_VALUE_MAX_BITS = transfer(HOST_VALUE_MAX, 0_int64)
   integer(int64), parameter :: HOST_INCREMENT_MAX_BITS = transfer(HOST_INCREMENT_MAX, 0_int64)

contains

   !> Whether the points of a material may take a block update: the displacement-driven damage
   !> law without viscous regularisation, with the simplified model (`simplified_block_update`;
   !> any mu, eta_N, eta_T, K_N, K_T and options that from_props accepts; the contact band acts
   !> on the micromechanical model only) or the micromechanical model without the contact band
   !> (`micromechanical_block_update`, either table). The others (the fracture-mechanics law,
   !> viscous regularisation, the micromechanical contact band) take the point update. Hosts ask
   !> here, never decide themselves, so that the block update's coverage is stated in one place.
   pure logical function block_supports(params)
      type(law_params_type), intent(in) :: params    !! decoded by from_props
      block_supports = params%damage_law == DAMAGE_DISPLACEMENT .and. .not. (params%viscosity > 0.0_dp) &
         .and. (params%model == MODEL_SIMPLIFIED .or. &
         (params%model == MODEL_MICROMECHANICAL .and. .not. (params%contact_band > 0.0_dp)))
   end function block_supports

   !> Update n points of a material that `block_supports` admits: `simplified_block_update` or
   !> `micromechanical_block_update` by the model (the same arguments).
   pure subroutine block_update(params, n, nt, s_n, s_t1, s_t2, d_old, lam1_old, lam2_old, t_n, t_t1, t_t2, &
         d, lam1, lam2, regime, psi, ok, nfailed)
      type(law_params_type), intent(in) :: params
      integer, intent(in) :: n, nt
      real(dp), intent(in) :: s_n(n), s_t1(n), s_t2(n), d_old(n), lam1_old(n), lam2_old(n)
      real(dp), intent(out) :: t_n(n), t_t1(n), t_t2(n), d(n), lam1(n), lam2(n), regime(n), psi(n)
      logical, intent(out) :: ok(n)
      integer, intent(out) :: nfailed
      if (params%model == MODEL_SIMPLIFIED) then
         call simplified_block_update(params, n, nt, s_n, s_t1, s_t2, d_old, lam1_old, lam2_old, t_n, t_t1, t_t2, &
            d, lam1, lam2, regime, psi, ok, nfailed)
      else
         call micromechanical_block_update(params, n, nt, s_n, s_t1, s_t2, d_old, lam1_old, lam2_old, t_n, t_t1, &
            t_t2, d, lam1, lam2, regime, psi, ok, nfailed)
      end if
   end subroutine block_update

   !> Update n points of the simplified model (displacement-driven damage law) from their
   !> separations at the end of the increment and their state at its start.
   !>
   !> A point whose separation is not finite or exceeds SEPARATION_MAX gets ok = .false.; its outputs are then finite but
   !> meaningless (the caller holds the point at its old values). The other points are updated
   !> exactly as `interface_update` does. In 2-D (nt = 1) the values of s_t2 and lam2_old are
   !> not used (the arrays must exist) and t_t2 = lam2 = 0 on return.
   pure subroutine simplified_block_update(params, n, nt, s_n, s_t1, s_t2, d_old, lam1_old, &
         lam2_old, t_n, t_t1, t_t2, d, lam1, lam2, regime, psi, ok, nfailed)
      type(law_params_type), intent(in) :: params    !! the simplified model, displacement law
      integer, intent(in) :: n                       !! number of points
      integer, intent(in) :: nt                      !! tangential components: 1 (2-D) or 2 (3-D)
      real(dp), intent(in) :: s_n(n)                 !! normal separation at the end (mm)
      real(dp), intent(in) :: s_t1(n), s_t2(n)       !! tangential separations at the end (mm)
      real(dp), intent(in) :: d_old(n)               !! damage D at the start (-), in [0, 1]
      real(dp), intent(in) :: lam1_old(n), lam2_old(n)  !! slip lambda at the start (mm)
      real(dp), intent(out) :: t_n(n)                !! normal traction (MPa)
      real(dp), intent(out) :: t_t1(n), t_t2(n)      !! tangential tractions (MPa)
      real(dp), intent(out) :: d(n)                  !! damage D at the end (-)
      real(dp), intent(out) :: lam1(n), lam2(n)      !! slip lambda at the end (mm)
      real(dp), intent(out) :: regime(n)             !! REGIME_* code, as a real (STATEV form)
      real(dp), intent(out) :: psi(n)                !! stored energy per unit area (N/mm)
      logical, intent(out) :: ok(n)                  !! the separation was finite, |s_i| <= SEPARATION_MAX
      integer, intent(out) :: nfailed                !! number of points with ok = .false.

      !> Points per pass: the passes' working arrays stay in the L1 cache.
      integer, parameter :: SUB = 64
      real(dp) :: sn_w(SUB), st1_w(SUB), st2_w(SUB), lam1_w(SUB), lam2_w(SUB), t_sq_w(SUB), d_w(SUB)
      real(dp) :: ratio_w(SUB)
      logical :: ok_w(SUB)
      real(dp) :: inv_kf, s_n_k, st1, st2, lam1_k, lam2_k, t_sq, sn_pos, x, r, alpha2, weighted
      real(dp) :: d_hat, d_k, num, den, kn_open, kt_open, kk_n, kk_t, cf_t, sigma, tau1, tau2
      real(dp) :: lam1_step, lam2_step, tau1_end, tau2_end
      real(dp) :: phi_roundoff, tau_norm, phi, inv_norm, dir1, dir2, dgamma, lam1_closed, lam2_closed
      real(dp) :: psi_open, psi_closed, tn_open, tn_closed, tt1_open, tt1_closed, tt2_open, tt2_closed
      real(dp) :: lam1_open, lam2_open, regime_if_open, regime_if_closed
      integer(int64) :: nfailed_count
      logical :: ok_k, growing, open, slipping, conserve
      integer(int64) :: ngrow
      integer :: c0, m, i, k

      ! Two passes over SUB points at a time, each a loop without control flow (every input
      ! loaded unconditionally, every branch computed and then selected) so that it vectorises;
      ! every operand is guarded so that no lane can raise a floating-point exception, whatever
      ! the compiler evaluates speculatively (hosts may run with traps enabled):
      ! pass 1, one loop for 2-D and one for 3-D: finiteness and |s_T|^2;
      ! between them the damage (its square root and division only where a point can grow), and
      ! where a point's crack grew, its trial slip lambda_n D_n/D (pi = D lambda conserved,
      ! GROWTH_FIXED_PI);
      ! pass 2, one loop for 2-D (no arithmetic on the zero second tangential components: |tau|
      ! and its sign, no square root or division) and one for 3-D: the trial crack shear stress
      ! from the trial slip, the simplified coefficients, open/stick/slip, energy.
      ! the return mapping divides by kf = -T^f = K_T (the scalar update forms the same 1/kf)
      inv_kf = 1.0_dp/params%k_t
      conserve = params%growth_slip == GROWTH_FIXED_PI
      nfailed_count = 0
      do c0 = 1, n, SUB
         m = min(SUB, n - c0 + 1)

         ! ---- pass 1: a point with a non-finite separation, or one beyond SEPARATION_MAX (the
         ! kernel's two checks; the magnitude bits of NaN and Inf exceed those of every finite
         ! number), computes on zeros (its results are not used); bit masks, not branches
         if (nt == 1) then
            do i = 1, m
               k = c0 + i - 1
               s_n_k = s_n(k)
               st1 = s_t1(k)
               ok_k = max(iand(transfer(s_n_k, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st1, 0_int64), MAGNITUDE_MASK)) <= SEPARATION_MAX_BITS
               s_n_k = merge(s_n_k, 0.0_dp, ok_k)
               st1 = merge(st1, 0.0_dp, ok_k)
               ok_w(i) = ok_k
               nfailed_count = nfailed_count + merge(0_int64, 1_int64, ok_k)
               sn_w(i) = s_n_k
               st1_w(i) = st1
               lam1_w(i) = lam1_old(k)
               t_sq_w(i) = st1**2
            end do
         else
            do i = 1, m
               k = c0 + i - 1
               s_n_k = s_n(k)
               st1 = s_t1(k)
               st2 = s_t2(k)
               ok_k = max(iand(transfer(s_n_k, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st1, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st2, 0_int64), MAGNITUDE_MASK)) <= SEPARATION_MAX_BITS
               s_n_k = merge(s_n_k, 0.0_dp, ok_k)
               st1 = merge(st1, 0.0_dp, ok_k)
               st2 = merge(st2, 0.0_dp, ok_k)
               ok_w(i) = ok_k
               nfailed_count = nfailed_count + merge(0_int64, 1_int64, ok_k)
               sn_w(i) = s_n_k
               st1_w(i) = st1
               st2_w(i) = st2
               lam1_w(i) = lam1_old(k)
               lam2_w(i) = lam2_old(k)
               t_sq_w(i) = st1**2 + st2**2
            end do
         end if

         ! ---- damage, eqs 13-18 (interphase_damage): D^ = beta/(eta (1 + beta)), r = 1 + beta.
         ! Its square root and division are the costliest operations of the update, and in most
         ! increments no point of a pass is on its damage surface (r > 1 with D < 1): such a pass
         ! skips them (D^ = 0 then, as in the formula).
         ngrow = 0
         do i = 1, m
            k = c0 + i - 1
            d_k = d_old(k)
            x = max(sn_w(i), 0.0_dp)*params%inv_s0_n
            ngrow = ngrow + merge(1_int64, 0_int64, x*x + t_sq_w(i)*params%inv_s0_t_sq > 1.0_dp .and. d_k < 1.0_dp)
         end do
         if (ngrow > 0) then
            do i = 1, m
               k = c0 + i - 1
               d_k = d_old(k)
               t_sq = t_sq_w(i)
               sn_pos = max(sn_w(i), 0.0_dp)
               x = sn_pos*params%inv_s0_n
               r = sqrt(x*x + t_sq*params%inv_s0_t_sq)
               growing = r > 1.0_dp
               alpha2 = sn_pos*sn_pos + t_sq
               weighted = params%eta_n*sn_pos*sn_pos + params%eta_t*t_sq
               num = (r - 1.0_dp)*alpha2
               den = r*(alpha2 - weighted)
               ! the guard keeps 0/0 (s = 0) out of the lanes that are not growing: the compiler may
               ! divide first and select afterwards; where D grows den >= r alpha^2 (1 - max(eta)) is
               ! far above tiny (unless sf = s0 to round-off), so it changes no result
               d_hat = merge(num/max(den, tiny(1.0_dp)), 0.0_dp, growing)
               ! + 0: an incoming D = -0 leaves as +0 whichever operand max picks (as in the kernel)
               d_w(i) = max(d_k, min(1.0_dp, d_hat)) + 0.0_dp
            end do
            ! where the crack grew: the trial slip lambda_n (D_n/D), the quotient the point update
            ! forms (growth_trial_slip, m = D ufbar = D); elsewhere lambda_n x 1, lambda_n itself.
            ! m(D_n) is +0 where D_n <= 0, as slip_measure gives it: from an incoming D_n = -0 the
            ! slip is lambda_n x +0, not lambda_n x -0 (the sign of a zero slip)
            do i = 1, m
               k = c0 + i - 1
               d_k = d_w(i)
               ratio_w(i) = merge(merge(d_old(k), 0.0_dp, d_old(k) > 0.0_dp)*(1.0_dp/max(d_k, tiny(1.0_dp))), 1.0_dp, &
                  conserve .and. d_k > d_old(k))
               lam1_w(i) = lam1_w(i)*ratio_w(i)
            end do
            if (nt == 2) lam2_w(1:m) = lam2_w(1:m)*ratio_w(1:m)
         else
            do i = 1, m
               k = c0 + i - 1
               d_w(i) = max(d_old(k), min(1.0_dp, 0.0_dp)) + 0.0_dp
            end do
         end if

         ! ---- pass 2, in 2-D: the general form below with s_T2 = lambda_2 = 0, written out so
         ! that no arithmetic is spent on those zeros. Bit for bit the same numbers: there
         ! t_T2 = +0 and lambda_2 = +0 in every regime (k_T (1 - D) +0 = +0, and
         ! +0 + (-D K_T) (+0) = +0), so each product with s_T2 or lambda_2 is +0 and the sums
         ! keep a "+ 0" (which turns a -0 into +0, as the general form does)
         if (nt == 1) then
            do i = 1, m
               k = c0 + i - 1
               s_n_k = sn_w(i)
               st1 = st1_w(i)
               lam1_k = lam1_w(i)
               d_k = d_w(i)
               ! trial crack shear stress (eq 43) from the trial slip: |tau| and its sign
               tau1 = params%k_t*st1 + (-params%k_t)*lam1_k
               tau_norm = abs(tau1)
               dir1 = sign(1.0_dp, tau1)

               kn_open = (1.0_dp - d_k)*params%k_n
               kt_open = (1.0_dp - d_k)*params%k_t
               kk_n = kn_open + d_k*params%k_n
               kk_t = kt_open + d_k*params%k_t
               cf_t = -d_k*params%k_t

               tn_open = kn_open*s_n_k
               tt1_open = kt_open*st1
               psi_open = 0.5_dp*(tn_open*s_n_k + (tt1_open*st1 + 0.0_dp))
               lam1_open = merge(lam1_k, st1, d_k <= 0.0_dp)
               regime_if_open = merge(real(REGIME_INTACT, dp), real(REGIME_OPEN, dp), d_k <= 0.0_dp)

               sigma = params%k_n*s_n_k
               phi = params%mu*sigma + tau_norm
               ! (respond's round-off of phi, with T^c_T = K_T)
               phi_roundoff = SLIP_ONSET_ROUNDOFF*(abs(params%mu*sigma) + abs(params%k_t*st1))
               slipping = phi > phi_roundoff .and. tau_norm > 0.0_dp
               dgamma = phi*inv_kf
               ! (respond's second step, from tau at the first step's slip)
               lam1_step = lam1_k + dgamma*dir1
               tau1_end = params%k_t*st1 + (-params%k_t)*lam1_step
               lam1_closed = merge(lam1_step + (tau1_end + (params%mu*sigma)*dir1)*inv_kf, lam1_k, slipping)
               tn_closed = kk_n*s_n_k
               tt1_closed = kk_t*st1 + cf_t*lam1_closed
               psi_closed = 0.5_dp*(tn_closed*s_n_k + (tt1_closed*st1 + 0.0_dp)) &
                  + 0.5_dp*cf_t*(lam1_closed*st1 + 0.0_dp) &
                  - 0.5_dp*d_k*(-params%k_t)*lam1_closed**2
               regime_if_closed = merge(real(REGIME_SLIP, dp), real(REGIME_STICK, dp), slipping)

               open = d_k <= 0.0_dp .or. s_n_k > 0.0_dp
               ok(k) = ok_w(i)
               d(k) = d_k
               t_n(k) = merge(tn_open, tn_closed, open)
               t_t1(k) = merge(tt1_open, tt1_closed, open)
               t_t2(k) = 0.0_dp
               lam1(k) = merge(lam1_open, lam1_closed, open)
               lam2(k) = 0.0_dp
               psi(k) = merge(psi_open, psi_closed, open)
               regime(k) = merge(regime_if_open, regime_if_closed, open)
            end do
         else
            ! ---- pass 2 (3-D)
            do i = 1, m
               k = c0 + i - 1
               s_n_k = sn_w(i)
               st1 = st1_w(i)
               st2 = st2_w(i)
               lam1_k = lam1_w(i)
               lam2_k = lam2_w(i)
               t_sq = t_sq_w(i)
               ! trial crack shear stress (eq 43) from the trial slip: its norm and direction
               tau1 = params%k_t*st1 + (-params%k_t)*lam1_k
               tau2 = params%k_t*st2 + (-params%k_t)*lam2_k
               tau_norm = sqrt(tau1**2 + tau2**2)
               inv_norm = 1.0_dp/max(tau_norm, tiny(1.0_dp))
               dir1 = tau1*inv_norm
               dir2 = tau2*inv_norm

               d_k = d_w(i)

               ! the simplified model's coefficients at D (eqs 31-35)
               kn_open = (1.0_dp - d_k)*params%k_n
               kt_open = (1.0_dp - d_k)*params%k_t
               kk_n = kn_open + d_k*params%k_n
               kk_t = kt_open + d_k*params%k_t
               cf_t = -d_k*params%k_t

               ! intact or open crack: t = k s, crack faces free, slip = mean sliding = s_T
               tn_open = kn_open*s_n_k
               tt1_open = kt_open*st1
               tt2_open = kt_open*st2
               psi_open = 0.5_dp*(tn_open*s_n_k + (tt1_open*st1 + tt2_open*st2))
               lam1_open = merge(lam1_k, st1, d_k <= 0.0_dp)
               lam2_open = merge(lam2_k, st2, d_k <= 0.0_dp)
               regime_if_open = merge(real(REGIME_INTACT, dp), real(REGIME_OPEN, dp), d_k <= 0.0_dp)

               ! closed crack: trial stick state (eq 43), return mapping (eqs 44-48)
               sigma = params%k_n*s_n_k
               phi = params%mu*sigma + tau_norm
               phi_roundoff = SLIP_ONSET_ROUNDOFF*(abs(params%mu*sigma) + (abs(params%k_t*st1) + abs(params%k_t*st2)))
               slipping = phi > phi_roundoff .and. tau_norm > 0.0_dp
               dgamma = phi*inv_kf
               ! (respond's second step, from tau at the first step's slip)
               lam1_step = lam1_k + dgamma*dir1
               lam2_step = lam2_k + dgamma*dir2
               tau1_end = params%k_t*st1 + (-params%k_t)*lam1_step
               tau2_end = params%k_t*st2 + (-params%k_t)*lam2_step
               lam1_closed = merge(lam1_step + (tau1_end + (params%mu*sigma)*dir1)*inv_kf, lam1_k, slipping)
               lam2_closed = merge(lam2_step + (tau2_end + (params%mu*sigma)*dir2)*inv_kf, lam2_k, slipping)
               tn_closed = kk_n*s_n_k
               tt1_closed = kk_t*st1 + cf_t*lam1_closed
               tt2_closed = kk_t*st2 + cf_t*lam2_closed
               psi_closed = 0.5_dp*(tn_closed*s_n_k + (tt1_closed*st1 + tt2_closed*st2)) &
                  + 0.5_dp*cf_t*(lam1_closed*st1 + lam2_closed*st2) &
                  - 0.5_dp*d_k*(-params%k_t)*(lam1_closed**2 + lam2_closed**2)
               regime_if_closed = merge(real(REGIME_SLIP, dp), real(REGIME_STICK, dp), slipping)

               ! select the regime's values
               open = d_k <= 0.0_dp .or. s_n_k > 0.0_dp
               ok(k) = ok_w(i)
               d(k) = d_k
               t_n(k) = merge(tn_open, tn_closed, open)
               t_t1(k) = merge(tt1_open, tt1_closed, open)
               t_t2(k) = merge(tt2_open, tt2_closed, open)
               lam1(k) = merge(lam1_open, lam1_closed, open)
               lam2(k) = merge(lam2_open, lam2_closed, open)
               psi(k) = merge(psi_open, psi_closed, open)
               regime(k) = merge(regime_if_open, regime_if_closed, open)
            end do
         end if
      end do
      nfailed = int(nfailed_count)
   end subroutine simplified_block_update

   !> Update n points of the micromechanical model (displacement-driven damage law, either RVE
   !> table, no contact band) from their separations at the end of the increment and their
   !> state at its start: `simplified_block_update` with the table's coefficients at each
   !> point's D (`micro_block_coefficients`, values only) in place of the spring model's. The
   !> same arguments and conventions; exactly the numbers of `interface_update`, bit for bit.
   !> ok = .false. also where the point update fails on the table (a D in (0, D_MIN_CRACK), a D
   !> outside a custom table's rows, a closed crack slipping with T^f >= 0).
   pure subroutine micromechanical_block_update(params, n, nt, s_n, s_t1, s_t2, d_old, lam1_old, &
         lam2_old, t_n, t_t1, t_t2, d, lam1, lam2, regime, psi, ok, nfailed)
      type(law_params_type), intent(in) :: params    !! the micromechanical model, displacement law
      integer, intent(in) :: n                       !! number of points
      integer, intent(in) :: nt                      !! tangential components: 1 (2-D) or 2 (3-D)
      real(dp), intent(in) :: s_n(n)                 !! normal separation at the end (mm)
      real(dp), intent(in) :: s_t1(n), s_t2(n)       !! tangential separations at the end (mm)
      real(dp), intent(in) :: d_old(n)               !! damage D at the start (-), in [0, 1]
      real(dp), intent(in) :: lam1_old(n), lam2_old(n)  !! slip lambda at the start (mm)
      real(dp), intent(out) :: t_n(n)                !! normal traction (MPa)
      real(dp), intent(out) :: t_t1(n), t_t2(n)      !! tangential tractions (MPa)
      real(dp), intent(out) :: d(n)                  !! damage D at the end (-)
      real(dp), intent(out) :: lam1(n), lam2(n)      !! slip lambda at the end (mm)
      real(dp), intent(out) :: regime(n)             !! REGIME_* code, as a real (STATEV form)
      real(dp), intent(out) :: psi(n)                !! stored energy per unit area (N/mm)
      logical, intent(out) :: ok(n)                  !! the point update would succeed
      integer, intent(out) :: nfailed                !! number of points with ok = .false.

      !> Points per group: the groups' working arrays stay in the L1 cache.
      integer, parameter :: SUB = 64
      real(dp) :: sn_w(SUB), st1_w(SUB), st2_w(SUB), lam1_w(SUB), lam2_w(SUB), t_sq_w(SUB), d_w(SUB)
      real(dp) :: m_w(SUB), fail_w(SUB), failc(SUB)
      real(dp), dimension(SUB) :: ck_n, ck_t, ckc_n, ckc_t, cdbar_n, cdbar_t, ctc_t, csc_n, ccf_t, ctf, cufbar
      real(dp) :: s_n_k, st1, st2, lam1_k, lam2_k, t_sq, sn_pos, x, r, alpha2, weighted
      real(dp) :: d_hat, d_k, num, den, kk_n, kk_t, cf_t, tf_k, kf, inv_kf, ufbar_k, sigma, tau1, tau2
      real(dp) :: lam1_step, lam2_step, tau1_end, tau2_end
      real(dp) :: phi_roundoff, tau_norm, phi, inv_norm, dir1, dir2, dgamma, lam1_closed, lam2_closed, ratio
      real(dp) :: psi_open, psi_closed, tn_open, tn_closed, tt1_open, tt1_closed, tt2_open, tt2_closed
      real(dp) :: lam1_open, lam2_open, regime_if_open, regime_if_closed
      integer(int64) :: nfailed_count, ngrow, nup
      logical :: ok_k, growing, open, slipping, conserve, grown, slipped
      integer :: c0, m, i, k

      ! The passes of simplified_block_update (see there), with the coefficients of each point
      ! from the table between the damage and the response; every operand guarded (no lane can
      ! raise a floating-point exception: at D = 0 the table's T^f is -huge, and the closed
      ! crack's arithmetic, not selected there, runs on T^f = -1 instead). Divisors are guarded
      ! by max(., tiny), never by a selection (under -fno-trapping-math the compiler may divide
      ! by both operands of a selection): ufbar > 0 and -T^f > 0 wherever the point update
      ! divides by them (interphase_micro_coefficients checks the interpolant's signs), so the
      ! guards change no result the point update can return.
      conserve = params%growth_slip == GROWTH_FIXED_PI
      nfailed_count = 0
      do c0 = 1, n, SUB
         m = min(SUB, n - c0 + 1)

         ! ---- pass 1: finiteness and range of the separation (bit masks), |s_T|^2
         if (nt == 1) then
            do i = 1, m
               k = c0 + i - 1
               s_n_k = s_n(k)
               st1 = s_t1(k)
               ok_k = max(iand(transfer(s_n_k, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st1, 0_int64), MAGNITUDE_MASK)) <= SEPARATION_MAX_BITS
               s_n_k = merge(s_n_k, 0.0_dp, ok_k)
               st1 = merge(st1, 0.0_dp, ok_k)
               fail_w(i) = merge(0.0_dp, 1.0_dp, ok_k)
               sn_w(i) = s_n_k
               st1_w(i) = st1
               lam1_w(i) = lam1_old(k)
               lam2_w(i) = 0.0_dp
               t_sq_w(i) = st1**2
            end do
         else
            do i = 1, m
               k = c0 + i - 1
               s_n_k = s_n(k)
               st1 = s_t1(k)
               st2 = s_t2(k)
               ok_k = max(iand(transfer(s_n_k, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st1, 0_int64), MAGNITUDE_MASK), &
                  iand(transfer(st2, 0_int64), MAGNITUDE_MASK)) <= SEPARATION_MAX_BITS
               s_n_k = merge(s_n_k, 0.0_dp, ok_k)
               st1 = merge(st1, 0.0_dp, ok_k)
               st2 = merge(st2, 0.0_dp, ok_k)
               fail_w(i) = merge(0.0_dp, 1.0_dp, ok_k)
               sn_w(i) = s_n_k
               st1_w(i) = st1
               st2_w(i) = st2
               lam1_w(i) = lam1_old(k)
               lam2_w(i) = lam2_old(k)
               t_sq_w(i) = st1**2 + st2**2
            end do
         end if

         ! ---- damage, eqs 13-18: as in simplified_block_update (the law does not depend on the model)
         ngrow = 0
         do i = 1, m
            k = c0 + i - 1
            d_k = d_old(k)
            x = max(sn_w(i), 0.0_dp)*params%inv_s0_n
            ngrow = ngrow + merge(1_int64, 0_int64, x*x + t_sq_w(i)*params%inv_s0_t_sq > 1.0_dp .and. d_k < 1.0_dp)
         end do
         nup = 0
         if (ngrow > 0) then
            do i = 1, m
               k = c0 + i - 1
               d_k = d_old(k)
               t_sq = t_sq_w(i)
               sn_pos = max(sn_w(i), 0.0_dp)
               x = sn_pos*params%inv_s0_n
               r = sqrt(x*x + t_sq*params%inv_s0_t_sq)
               growing = r > 1.0_dp
               alpha2 = sn_pos*sn_pos + t_sq
               weighted = params%eta_n*sn_pos*sn_pos + params%eta_t*t_sq
               num = (r - 1.0_dp)*alpha2
               den = r*(alpha2 - weighted)
               d_hat = merge(num/max(den, tiny(1.0_dp)), 0.0_dp, growing)
               d_w(i) = max(d_k, min(1.0_dp, d_hat)) + 0.0_dp
               nup = nup + merge(1_int64, 0_int64, d_w(i) > d_k)
            end do
         else
            do i = 1, m
               k = c0 + i - 1
               d_w(i) = max(d_old(k), min(1.0_dp, 0.0_dp)) + 0.0_dp
            end do
         end if

         ! ---- where the crack grew under slip (GROWTH_FIXED_PI): m(D_n) = D_n ufbar(D_n) from the
         ! table at the old damage (slip_measure; ufbar alone), for the trial slip lambda_n m(D_n)/m(D)
         if (conserve .and. nup > 0) then
            call micro_block_ufbar(params%table, m, d_old(c0:c0 + m - 1), cufbar, failc)
            do i = 1, m
               k = c0 + i - 1
               grown = d_w(i) > d_old(k)
               slipped = abs(lam1_w(i)) > 0.0_dp .or. abs(lam2_w(i)) > 0.0_dp
               m_w(i) = merge(d_old(k)*cufbar(i), 0.0_dp, d_old(k) > 0.0_dp)
               fail_w(i) = max(fail_w(i), merge(failc(i), 0.0_dp, grown .and. slipped .and. d_old(k) > 0.0_dp))
            end do
         end if

         ! ---- the coefficients at D
         call micro_block_coefficients(params%table, m, d_w(1:m), ck_n, ck_t, ckc_n, ckc_t, cdbar_n, cdbar_t, &
            ctc_t, csc_n, ccf_t, ctf, cufbar, failc)
         if (conserve .and. nup > 0) then
            ! the quotient growth_trial_slip forms; elsewhere lambda_n x 1, lambda_n itself
            do i = 1, m
               k = c0 + i - 1
               ratio = merge(m_w(i)*(1.0_dp/max(d_w(i)*cufbar(i), tiny(1.0_dp))), 1.0_dp, d_w(i) > d_old(k))
               lam1_w(i) = lam1_w(i)*ratio
               lam2_w(i) = lam2_w(i)*ratio
            end do
         end if

         ! ---- pass 2, in 2-D: respond (interphase_response) with s_T2 = lambda_2 = 0 written out,
         ! as in simplified_block_update (the same bits: each dropped product is +0)
         if (nt == 1) then
            do i = 1, m
               k = c0 + i - 1
               s_n_k = sn_w(i)
               st1 = st1_w(i)
               lam1_k = lam1_w(i)
               d_k = d_w(i)
               tf_k = merge(ctf(i), -1.0_dp, d_k > 0.0_dp)
               ufbar_k = max(cufbar(i), tiny(1.0_dp))
               kf = -tf_k
               kk_n = ck_n(i) + ckc_n(i)
               kk_t = ck_t(i) + ckc_t(i)
               cf_t = ccf_t(i)

               tn_open = ck_n(i)*s_n_k
               tt1_open = ck_t(i)*st1
               psi_open = 0.5_dp*(tn_open*s_n_k + (tt1_open*st1 + 0.0_dp))
               lam1_open = merge(lam1_k, cdbar_t(i)*st1/ufbar_k, d_k <= 0.0_dp)
               regime_if_open = merge(real(REGIME_INTACT, dp), real(REGIME_OPEN, dp), d_k <= 0.0_dp)

               tau1 = ctc_t(i)*st1 + tf_k*lam1_k
               tau_norm = abs(tau1)
               dir1 = sign(1.0_dp, tau1)
               sigma = csc_n(i)*s_n_k
               phi = params%mu*sigma + tau_norm
               phi_roundoff = SLIP_ONSET_ROUNDOFF*(abs(params%mu*sigma) + abs(ctc_t(i)*st1))
               slipping = phi > phi_roundoff .and. tau_norm > 0.0_dp
               inv_kf = 1.0_dp/max(kf, tiny(1.0_dp))
               dgamma = phi*inv_kf
               ! (respond's second step, from tau at the first step's slip)
               lam1_step = lam1_k + dgamma*dir1
               tau1_end = ctc_t(i)*st1 + tf_k*lam1_step
               lam1_closed = merge(lam1_step + (tau1_end + (params%mu*sigma)*dir1)*inv_kf, lam1_k, slipping)
               tn_closed = kk_n*s_n_k
               tt1_closed = kk_t*st1 + cf_t*lam1_closed
               psi_closed = 0.5_dp*(tn_closed*s_n_k + (tt1_closed*st1 + 0.0_dp)) &
                  + 0.5_dp*cf_t*(lam1_closed*st1 + 0.0_dp) &
                  - 0.5_dp*d_k*tf_k*cufbar(i)*lam1_closed**2
               regime_if_closed = merge(real(REGIME_SLIP, dp), real(REGIME_STICK, dp), slipping)

               open = d_k <= 0.0_dp .or. s_n_k > 0.0_dp
               fail_w(i) = max(fail_w(i), merge(1.0_dp, failc(i), .not. open .and. slipping .and. .not. (kf > 0.0_dp)))
               d(k) = d_k
               t_n(k) = merge(tn_open, tn_closed, open)
               t_t1(k) = merge(tt1_open, tt1_closed, open)
               t_t2(k) = 0.0_dp
               lam1(k) = merge(lam1_open, lam1_closed, open)
               lam2(k) = 0.0_dp
               psi(k) = merge(psi_open, psi_closed, open)
               regime(k) = merge(regime_if_open, regime_if_closed, open)
            end do
         else
            ! ---- pass 2 (3-D)
            do i = 1, m
               k = c0 + i - 1
               s_n_k = sn_w(i)
               st1 = st1_w(i)
               st2 = st2_w(i)
               lam1_k = lam1_w(i)
               lam2_k = lam2_w(i)
               d_k = d_w(i)
               tf_k = merge(ctf(i), -1.0_dp, d_k > 0.0_dp)
               ufbar_k = max(cufbar(i), tiny(1.0_dp))
               kf = -tf_k
               kk_n = ck_n(i) + ckc_n(i)
               kk_t = ck_t(i) + ckc_t(i)
               cf_t = ccf_t(i)

               ! intact or open crack: t = k s, crack faces free, slip = Dbar_TT s_T/ufbar
               tn_open = ck_n(i)*s_n_k
               tt1_open = ck_t(i)*st1
               tt2_open = ck_t(i)*st2
               psi_open = 0.5_dp*(tn_open*s_n_k + (tt1_open*st1 + tt2_open*st2))
               lam1_open = merge(lam1_k, cdbar_t(i)*st1/ufbar_k, d_k <= 0.0_dp)
               lam2_open = merge(lam2_k, cdbar_t(i)*st2/ufbar_k, d_k <= 0.0_dp)
               regime_if_open = merge(real(REGIME_INTACT, dp), real(REGIME_OPEN, dp), d_k <= 0.0_dp)

               ! closed crack: trial stick state (eq 43), return mapping (eqs 44-48)
               tau1 = ctc_t(i)*st1 + tf_k*lam1_k
               tau2 = ctc_t(i)*st2 + tf_k*lam2_k
               tau_norm = sqrt(tau1**2 + tau2**2)
               inv_norm = 1.0_dp/max(tau_norm, tiny(1.0_dp))
               dir1 = tau1*inv_norm
               dir2 = tau2*inv_norm
               sigma = csc_n(i)*s_n_k
               phi = params%mu*sigma + tau_norm
               phi_roundoff = SLIP_ONSET_ROUNDOFF*(abs(params%mu*sigma) + (abs(ctc_t(i)*st1) + abs(ctc_t(i)*st2)))
               slipping = phi > phi_roundoff .and. tau_norm > 0.0_dp
               inv_kf = 1.0_dp/max(kf, tiny(1.0_dp))
               dgamma = phi*inv_kf
               ! (respond's second step, from tau at the first step's slip)
               lam1_step = lam1_k + dgamma*dir1
               lam2_step = lam2_k + dgamma*dir2
               tau1_end = ctc_t(i)*st1 + tf_k*lam1_step
               tau2_end = ctc_t(i)*st2 + tf_k*lam2_step
               lam1_closed = merge(lam1_step + (tau1_end + (params%mu*sigma)*dir1)*inv_kf, lam1_k, slipping)
               lam2_closed = merge(lam2_step + (tau2_end + (params%mu*sigma)*dir2)*inv_kf, lam2_k, slipping)
               tn_closed = kk_n*s_n_k
               tt1_closed = kk_t*st1 + cf_t*lam1_closed
               tt2_closed = kk_t*st2 + cf_t*lam2_closed
               psi_closed = 0.5_dp*(tn_closed*s_n_k + (tt1_closed*st1 + tt2_closed*st2)) &
                  + 0.5_dp*cf_t*(lam1_closed*st1 + lam2_closed*st2) &
                  - 0.5_dp*d_k*tf_k*cufbar(i)*(lam1_closed**2 + lam2_closed**2)
               regime_if_closed = merge(real(REGIME_SLIP, dp), real(REGIME_STICK, dp), slipping)

               open = d_k <= 0.0_dp .or. s_n_k > 0.0_dp
               fail_w(i) = max(fail_w(i), merge(1.0_dp, failc(i), .not. open .and. slipping .and. .not. (kf > 0.0_dp)))
               d(k) = d_k
               t_n(k) = merge(tn_open, tn_closed, open)
               t_t1(k) = merge(tt1_open, tt1_closed, open)
               t_t2(k) = merge(tt2_open, tt2_closed, open)
               lam1(k) = merge(lam1_open, lam1_closed, open)
               lam2(k) = merge(lam2_open, lam2_closed, open)
               psi(k) = merge(psi_open, psi_closed, open)
               regime(k) = merge(regime_if_open, regime_if_closed, open)
            end do
         end if
         ! ok: the separation and the table at D (and D_n), and the return mapping's -T^f > 0
         ! (respond's check): one real flag a point, 1 where any pass failed it (max), so that no
         ! pass has logical arrays to vectorise and this one no branches
         do i = 1, m
            k = c0 + i - 1
            ok(k) = fail_w(i) < 0.5_dp
            nfailed_count = nfailed_count + merge(1_int64, 0_int64, fail_w(i) >= 0.5_dp)
         end do
      end do
      nfailed = int(nfailed_count)
   end subroutine micromechanical_block_update

   !> The densities of a block in one branch-free pass: nbad values outside [DENSITY_MIN,
   !> DENSITY_MAX] (bit patterns: no exception for NaN; negative numbers have the sign bit and
   !> lie below; the window keeps the energies per unit mass and their products with the density
   !> finite).
   pure subroutine density_counts(n, rho, nbad)
      integer, intent(in) :: n
      real(dp), intent(in) :: rho(n)
      integer, intent(out) :: nbad
      integer(int64) :: b, nbad_bits
      integer :: k
      nbad_bits = 0
      do k = 1, n
         b = transfer(rho(k), 0_int64)
         nbad_bits = nbad_bits + merge(0_int64, 1_int64, b >= DENSITY_MIN_BITS .and. b <= DENSITY_MAX_BITS)
      end do
      nbad = int(nbad_bits)
   end subroutine density_counts

   !> The energies per unit mass at the end of the increment of a block's points (Abaqus/Explicit's
   !> enerInternNew and enerInelasNew), in one vectorised pass, and the count of points whose host
   !> values lie out of range. With the layer's mass per unit area rho t:
   !>   psi_n = (e_int,n - e_inel,n) rho t,
   !>   e_inel = e_inel,n + (1/2 (sigma_n + sigma).ds - (psi - psi_n))/(rho t),
   !>   e_int = e_inel + psi/(rho t).
   !> A point is out of range (counted in nbad, its energies finite but meaningless, computed from
   !> zeros) where its incoming stress, e_int,n or e_inel,n exceeds HOST_VALUE_MAX in magnitude,
   !> or a separation increment HOST_INCREMENT_MAX (bit patterns: NaN and Inf count, without an
   !> exception). In 2-D (nt = 1) the third columns are checked but do not enter the energies
   !> (pass the second columns again: the pass reads them either way). rho t and 1/(rho t) are formed
   !> at every point: with one division for a block of one density (a branch on it, or a selection,
   !> kept gfortran 12 from vectorising the loop: docs/performance.md) the loop ran scalar.
   pure subroutine block_energies(n, nt, thickness, rho, so_n, so_t1, so_t2, ds_n, ds_t1, ds_t2, &
         t_n, t_t1, t_t2, psi, ei_old, ep_old, ei_new, ep_new, nbad)
      integer, intent(in) :: n                       !! number of points
      integer, intent(in) :: nt                      !! tangential components: 1 (2-D) or 2 (3-D)
      real(dp), intent(in) :: thickness              !! constitutive thickness t (mm)
      real(dp), intent(in) :: rho(n)                 !! density (tonne/mm^3), within [DENSITY_MIN, DENSITY_MAX]
      real(dp), intent(in) :: so_n(n), so_t1(n), so_t2(n)   !! tractions at the start (MPa)
      real(dp), intent(in) :: ds_n(n), ds_t1(n), ds_t2(n)   !! separation increments (mm)
      real(dp), intent(in) :: t_n(n), t_t1(n), t_t2(n)      !! tractions at the end (MPa)
      real(dp), intent(in) :: psi(n)                 !! stored energy at the end (N/mm)
      real(dp), intent(in) :: ei_old(n), ep_old(n)   !! e_int,n and e_inel,n (per unit mass)
      real(dp), intent(out) :: ei_new(n), ep_new(n)  !! e_int and e_inel (per unit mass)
      integer, intent(out) :: nbad                   !! points with host values out of range

      real(dp) :: so1, so2, so3, ds1, ds2, ds3, ei, ep, work, rho_t, inv_rho
      real(dp) :: psi_old, energy_inelas
      integer(int64) :: nbad_count, big_value, big_increment
      logical :: ok
      integer :: k

      nbad_count = 0
      do k = 1, n
         so1 = so_n(k)
         so2 = so_t1(k)
         ds1 = ds_n(k)
         ds2 = ds_t1(k)
         ei = ei_old(k)
         ep = ep_old(k)
         so3 = so_t2(k)
         ds3 = ds_t2(k)
         ! the largest magnitudes' bits, a value's and an increment's (the third columns in 2-D too)
         big_value = max(magnitude_bits(so1), magnitude_bits(so2), magnitude_bits(so3), magnitude_bits(ei), &
            magnitude_bits(ep))
         big_increment = max(magnitude_bits(ds1), magnitude_bits(ds2), magnitude_bits(ds3))
         ok = big_value <= HOST_VALUE_MAX_BITS .and. big_increment <= HOST_INCREMENT_MAX_BITS
         nbad_count = nbad_count + merge(0_int64, 1_int64, ok)
         so1 = merge(so1, 0.0_dp, ok)
         so2 = merge(so2, 0.0_dp, ok)
         ds1 = merge(ds1, 0.0_dp, ok)
         ds2 = merge(ds2, 0.0_dp, ok)
         ei = merge(ei, 0.0_dp, ok)
         ep = merge(ep, 0.0_dp, ok)
         so3 = merge(so3, 0.0_dp, ok)
         ds3 = merge(ds3, 0.0_dp, ok)
         ! (the third term selected, not branched on: a branch stops the vectorisation)
         work = (so1 + t_n(k))*ds1 + (so2 + t_t1(k))*ds2
         work = merge(work + (so3 + t_t2(k))*ds3, work, nt == 2)
         rho_t = rho(k)*thickness
         inv_rho = 1.0_dp/rho_t
         psi_old = (ei - ep)*rho_t
         energy_inelas = ep + (0.5_dp*work - (psi(k) - psi_old))*inv_rho
         ep_new(k) = energy_inelas
         ei_new(k) = energy_inelas + psi(k)*inv_rho
      end do
      nbad = int(nbad_count)
   end subroutine block_energies

   !> The bit pattern of |x| (positive numbers, +Inf and NaN are ordered like their bits).
   elemental integer(int64) function magnitude_bits(x)
      real(dp), intent(in) :: x
      magnitude_bits = iand(transfer(x, 0_int64), MAGNITUDE_MASK)
   end function magnitude_bits

end module interphase_block
