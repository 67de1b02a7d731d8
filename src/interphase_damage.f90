!> The displacement-driven damage law of the paper, eqs 13-18 (reconstructed in MODEL-NOTES
!> section 2): the damage D^ reached by a separation, and its derivatives for the tangent.
module interphase_damage
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   implicit none
   private
   public :: displacement_damage

contains

   !> D^(s) of eq 17 with its partial derivatives. s_N enters through its positive part and the
   !> tangential separation through its norm t = |s_T| (isotropic in the interface plane).
   !> Below first cracking (beta <= 0) D^ = 0. The history maximum and the cap at 1 (eqs 16, 39)
   !> are the caller's.
   pure subroutine displacement_damage(params, s_n, t, d_hat, dd_dsn, dd_dt)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: s_n       !! normal separation (mm)
      real(dp), intent(in) :: t         !! norm of the tangential separation (mm), >= 0
      real(dp), intent(out) :: d_hat    !! D^ of eq 17 (-), may exceed 1
      real(dp), intent(out) :: dd_dsn   !! dD^/ds_N (1/mm)
      real(dp), intent(out) :: dd_dt    !! dD^/dt (1/mm)

      real(dp) :: sn_pos, x, y, r, alpha2, weighted, eta, dd_dr, dd_deta, deta_scale

      sn_pos = max(s_n, 0.0_dp)
      x = sn_pos/params%s0_n
      y = t/params%s0_t
      r = sqrt(x*x + y*y)                       ! r = 1 + beta, eq 18
      if (r <= 1.0_dp) then
         d_hat = 0.0_dp
         dd_dsn = 0.0_dp
         dd_dt = 0.0_dp
         return
      end if
      alpha2 = sn_pos*sn_pos + t*t              ! alpha^2, eq 15
      weighted = params%eta_n*sn_pos*sn_pos + params%eta_t*t*t
      eta = 1.0_dp - weighted/alpha2            ! eq 14
      d_hat = (1.0_dp - 1.0_dp/r)/eta           ! eq 17: beta/(eta (1 + beta))

      dd_dr = 1.0_dp/(eta*r*r)
      dd_deta = -d_hat/eta
      ! d eta/d s_N = -2 s_N t^2 (eta_N - eta_T)/alpha^4, d eta/d t = -2 t s_N^2 (eta_T - eta_N)/alpha^4
      deta_scale = 2.0_dp*(params%eta_n - params%eta_t)/(alpha2*alpha2)
      dd_dsn = dd_dr*sn_pos/(params%s0_n**2*r) - dd_deta*deta_scale*sn_pos*t*t
      dd_dt = dd_dr*t/(params%s0_t**2*r) + dd_deta*deta_scale*t*sn_pos*sn_pos
   end subroutine displacement_damage

end module interphase_damage
