!> The coefficient set of the paper's section 4 at one crack length, in interface units, and its
!> providers. The update (`interphase_kernel`) is written once against this set; each model is a
!> provider of it: the simplified spring model (section 3.4) here, the micromechanical RVE
!> tables later.
!>
!> Interface units: the paper's RVE coefficients are per unit mean strain E = s/h; here they are
!> divided by h so that the update works on the separation s (mm) directly:
!> k = C/h, kc = C^c/h, dbar = Dbar/h, tc_t = T^c_T/h, sc_n = S^c_N/h; C^f, T^f are per unit
!> slip lambda (mm) already. The symmetric RVE (crack centred, periodic sides) makes every
!> cross term vanish (C_TN = C_NT = 0, Dbar_TN = Dbar_NT = 0, T^c_N = S^c_T = 0, C^f_N = 0,
!> S^f = 0; docs/rve.md, 'Exact identities'); providers guarantee it and the set holds the non-zero
!> members only, which is also what in-plane isotropy requires in 3-D.
module interphase_coefficients
   use interphase_kinds, only: dp
   implicit none
   private
   public :: coefficient_set_type, NO_COEFFICIENTS, SIMPLIFIED_UFBAR, simplified_coefficients

   !> Coefficients at one damage D = a/b (or their derivatives d/dD, in the same type). No default
   !> initialisation: providers set every member (LLVM flang 19 initialises a variable of a type
   !> with default initialisation, and an intent(out) argument of one, by a run-time library call
   !> at every entry, the largest cost of its update; docs/compilers.md). NO_COEFFICIENTS is the set
   !> of zeros.
   type :: coefficient_set_type
      real(dp) :: k_n              !! C_NN/h: open-crack normal stiffness (MPa/mm)
      real(dp) :: k_t              !! C_TT/h: open-crack tangential stiffness (MPa/mm)
      real(dp) :: kc_n             !! C^c_NN/h: contact stiffness added when closed (MPa/mm)
      real(dp) :: kc_t             !! C^c_TT/h (MPa/mm)
      real(dp) :: dbar_n           !! Dbar_NN/h: mean crack opening per unit s_N (-)
      real(dp) :: dbar_t           !! Dbar_TT/h: mean crack sliding per unit s_T (-)
      real(dp) :: tc_t             !! T^c_T/h: mean crack shear stress per unit s_T, closed (MPa/mm)
      real(dp) :: sc_n             !! S^c_N/h: mean crack normal stress per unit s_N, closed (MPa/mm)
      real(dp) :: cf_t             !! C^f_T: interface shear traction per unit slip (MPa/mm)
      real(dp) :: tf               !! T^f: mean crack shear stress per unit slip, < 0 (MPa/mm)
      real(dp) :: ufbar            !! mean over the crack of the slip shape u^f, max|u^f| = 1 (-)
   end type coefficient_set_type

   type(coefficient_set_type), parameter :: NO_COEFFICIENTS = coefficient_set_type(0.0_dp, 0.0_dp, 0.0_dp, &
      0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp)

   !> The simplified model's mean slip shape ufbar (-): u^f = 1 over the whole crack.
   real(dp), parameter :: SIMPLIFIED_UFBAR = 1.0_dp

contains

   include 'interphase_simplified.inc'

end module interphase_coefficients
