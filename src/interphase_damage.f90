!> The displacement-driven damage law of the paper, eqs 13-18 (stated in docs/theory.md): the
!> damage D^ reached by a separation, and its derivatives for the tangent.
module interphase_damage
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   implicit none
   private
   public :: displacement_damage, damage_slopes

   !> What D^(s) is formed from, for its derivatives (`damage_slopes`). No default
   !> initialisation (the update's hot path).
   type, public :: damage_terms_type
      real(dp) :: sn_pos                !! <s_N>, the positive part of s_N (mm)
      real(dp) :: r                     !! r = 1 + beta, eq 18 (-)
      real(dp) :: alpha2                !! alpha^2 = <s_N>^2 + |s_T|^2, eq 15 (mm^2)
      real(dp) :: weighted              !! eta_N <s_N>^2 + eta_T |s_T|^2 (mm^2)
   end type damage_terms_type

contains

   !> D^(s) of eq 17. s_N enters through its positive part and the tangential separation through
   !> its norm t = |s_T| (isotropic in the interface plane). Below first cracking (beta <= 0)
   !> D^ = 0. The history maximum and the cap at 1 (eqs 16, 39) are the caller's, and so are the
   !> derivatives (`damage_slopes`, from `terms`, wherever D^ > 0: the update asks for them only
   !> where the damage grows).
   pure subroutine displacement_damage(params, s_n, t_sq, d_hat, terms)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: s_n       !! normal separation (mm)
      real(dp), intent(in) :: t_sq      !! |s_T|^2, squared norm of the tangential separation (mm^2)
      real(dp), intent(out) :: d_hat    !! D^ of eq 17 (-), may exceed 1
      type(damage_terms_type), intent(out) :: terms   !! defined where d_hat > 0

      ! D^ itself needs only t^2 (no square root); interphase_block evaluates the same expressions
      terms%sn_pos = max(s_n, 0.0_dp)
      associate (sn_pos => terms%sn_pos, r => terms%r, alpha2 => terms%alpha2, weighted => terms%weighted)
         r = sqrt((sn_pos*params%inv_s0_n)**2 + t_sq*params%inv_s0_t_sq)  ! r = 1 + beta, eq 18
         if (r <= 1.0_dp) then
            d_hat = 0.0_dp
            return
         end if
         alpha2 = sn_pos*sn_pos + t_sq             ! alpha^2, eq 15
         weighted = params%eta_n*sn_pos*sn_pos + params%eta_t*t_sq
         ! eq 17: D^ = beta/(eta (1 + beta)) = (r - 1) alpha^2/(r (alpha^2 - weighted)), one division
         d_hat = (r - 1.0_dp)*alpha2/(r*(alpha2 - weighted))
      end associate
   end subroutine displacement_damage

   !> The partial derivatives of D^(s) where D^ > 0 (`displacement_damage`'s d_hat and terms).
   pure subroutine damage_slopes(params, t_sq, d_hat, terms, dd_dsn, dd_dt)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: t_sq      !! |s_T|^2 (mm^2)
      real(dp), intent(in) :: d_hat     !! D^ (-), > 0
      type(damage_terms_type), intent(in) :: terms   !! from displacement_damage at the same s
      real(dp), intent(out) :: dd_dsn   !! dD^/ds_N (1/mm)
      real(dp), intent(out) :: dd_dt    !! dD^/dt with t = |s_T| (1/mm)

      real(dp) :: t, eta, dd_dr, dd_deta, deta_scale

      associate (sn_pos => terms%sn_pos, r => terms%r, alpha2 => terms%alpha2, weighted => terms%weighted)
         t = sqrt(t_sq)
         eta = 1.0_dp - weighted/alpha2            ! eq 14
         dd_dr = 1.0_dp/(eta*r*r)
         dd_deta = -d_hat/eta
         ! d eta/d s_N = -2 s_N t^2 (eta_N - eta_T)/alpha^4, d eta/d t = -2 t s_N^2 (eta_T - eta_N)/alpha^4
         deta_scale = 2.0_dp*(params%eta_n - params%eta_t)/(alpha2*alpha2)
         dd_dsn = dd_dr*sn_pos/(params%s0_n**2*r) - dd_deta*deta_scale*sn_pos*t_sq
         dd_dt = dd_dr*t/(params%s0_t**2*r) + dd_deta*deta_scale*t*sn_pos*sn_pos
      end associate
   end subroutine damage_slopes

end module interphase_damage
