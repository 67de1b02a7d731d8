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

   include 'interphase_damage.inc'

end module interphase_damage
