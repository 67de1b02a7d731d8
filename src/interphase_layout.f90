!> The Abaqus-facing layout of interphase: PROPS and STATEV slot numbers and the codes stored in
!> them. This module is the only place that knows which slot holds what; `docs/abaqus.md` is its
!> user-facing copy and must be kept in step with it.
module interphase_layout
   use interphase_kinds, only: dp
   implicit none
   private

   ! ---- PROPS (material constants, `*USER MATERIAL, CONSTANTS=...`) --------------------------
   !> Model selector: MODEL_SIMPLIFIED or MODEL_MICROMECHANICAL.
   integer, parameter, public :: PROP_MODEL = 1
   !> Damage-law selector: DAMAGE_DISPLACEMENT.
   integer, parameter, public :: PROP_DAMAGE_LAW = 2
   !> Coulomb friction coefficient mu on the crack faces (-), mu >= 0.
   integer, parameter, public :: PROP_MU = 3
   !> First-cracking normal separation s0_N (mm), > 0.
   integer, parameter, public :: PROP_S0_N = 4
   !> Full-crack normal separation sf_N (mm), > s0_N.
   integer, parameter, public :: PROP_SF_N = 5
   !> First-cracking tangential separation s0_T (mm), > 0.
   integer, parameter, public :: PROP_S0_T = 6
   !> Full-crack tangential separation sf_T (mm), > s0_T.
   integer, parameter, public :: PROP_SF_T = 7
   !> Simplified model: normal spring stiffness K_N = C^_NN/h (MPa/mm), > 0.
   integer, parameter, public :: PROP_K_N = 8
   !> Simplified model: tangential spring stiffness K_T = C^_TT/h (MPa/mm), > 0.
   integer, parameter, public :: PROP_K_T = 9
   !> Number of PROPS the simplified model takes.
   integer, parameter, public :: NPROPS_SIMPLIFIED = 9
   !> Micromechanical model: table selector, TABLE_DEFAULT_CODE (the built-in table of the
   !> paper's RVE) or TABLE_CUSTOM_CODE (the table loaded at start-up: UEXTERNALDB with the
   !> environment variable INTERPHASE_TABLE, or the driver's case file).
   integer, parameter, public :: PROP_TABLE = 8
   !> Number of PROPS the micromechanical model takes.
   integer, parameter, public :: NPROPS_MICROMECHANICAL = 8
   !> PROPS(PROP_TABLE) value: the built-in table (tables/paper.dat).
   integer, parameter, public :: TABLE_DEFAULT_CODE = 0
   !> PROPS(PROP_TABLE) value: the custom table loaded at start-up.
   integer, parameter, public :: TABLE_CUSTOM_CODE = 1

   !> PROPS(PROP_MODEL) value: the simplified spring model of the paper's section 3.4.
   integer, parameter, public :: MODEL_SIMPLIFIED = 1
   !> PROPS(PROP_MODEL) value: the micromechanical model on RVE tables.
   integer, parameter, public :: MODEL_MICROMECHANICAL = 2
   !> PROPS(PROP_DAMAGE_LAW) value: the displacement-driven damage law, eqs 13-18.
   integer, parameter, public :: DAMAGE_DISPLACEMENT = 1
   !> PROPS(PROP_DAMAGE_LAW) value: the fracture-mechanics law (Griffith criterion with R-curves,
   !> eqs 20-24, 40-42, 49-50). Its four constants follow the model's block:
   !> PROPS(nm + LFM_*) with nm = NPROPS_SIMPLIFIED or NPROPS_MICROMECHANICAL.
   integer, parameter, public :: DAMAGE_FRACTURE = 2
   !> Fracture-mechanics law, offset of the initial crack D0 = a0/b (-), 0 < D0 < 1.
   integer, parameter, public :: LFM_D0 = 1
   !> Fracture-mechanics law, offset of the R-curve selector: RCURVE_*.
   integer, parameter, public :: LFM_RCURVE = 2
   !> Fracture-mechanics law, offset of the constant mode-I toughness G_cI (N/mm, energy per
   !> unit crack area, as tests measure it); 0 unless RCURVE_CONSTANT.
   integer, parameter, public :: LFM_GC_I = 3
   !> Fracture-mechanics law, offset of the constant mode-II toughness G_cII (N/mm); 0 unless
   !> RCURVE_CONSTANT.
   integer, parameter, public :: LFM_GC_II = 4
   !> Number of PROPS the fracture-mechanics law adds to the model's.
   integer, parameter, public :: NPROPS_FRACTURE_EXTRA = 4
   !> Optional trailing option constants: PROPS(nb + OPT_*), nb = the count the model and the
   !> damage law take (9 or 8, plus 4 for the fracture law). A deck may stop before any of them;
   !> each one left out takes its default. NPROPS may exceed nb by at most NPROPS_OPTIONS.
   !> Option offset: the slip of the crack faces while the crack grows (GROWTH_*).
   integer, parameter, public :: OPT_GROWTH_SLIP = 1
   !> Option offset: the width chi (-) of the contact band, the continuous variant of the
   !> open/closed switch at s_N = 0 (docs/theory.md, 'The contact band'): 0 (the default) is
   !> the paper's two-state law; chi > 0 fades the frictionless closed crack's extra shear
   !> stiffness out over 0 < s_N < chi |s_T|, so that the traction is continuous where the
   !> crack opens. Micromechanical model (the simplified one has no jump), both damage laws.
   integer, parameter, public :: OPT_CONTACT_BAND = 2
   !> Number of option constants.
   integer, parameter, public :: NPROPS_OPTIONS = 2
   !> Admissible contact band widths: chi = 0 or CONTACT_BAND_MIN <= chi <= CONTACT_BAND_MAX (-).
   !> Below 0.1 the band's normal stiffness, ~ q max|W''|/(2 chi^2), could exceed the intact
   !> crack's (which the VUMAT's stable increment assumes), and its energy is far from convex.
   real(dp), parameter, public :: CONTACT_BAND_MIN = 0.1_dp
   real(dp), parameter, public :: CONTACT_BAND_MAX = 10.0_dp
   !> PROPS(nb + OPT_GROWTH_SLIP) value, the default: the crack faces' integrated slip
   !> pi = D ufbar lambda is conserved while the crack grows (the faces made by the growth start
   !> with zero slip), so that the damage driving force is >= 0 (docs/theory.md).
   integer, parameter, public :: GROWTH_FIXED_PI = 0
   !> PROPS(nb + OPT_GROWTH_SLIP) value: the paper's form, the mean slip lambda is held fixed
   !> while the crack grows (the driving force can be negative in a closed crack).
   integer, parameter, public :: GROWTH_FIXED_LAMBDA = 1
   !> R-curve: constant G_cI, G_cII.
   integer, parameter, public :: RCURVE_CONSTANT = 1
   !> R-curve: the one equivalent to the displacement-driven law in pure mode I and mode II,
   !> built from s0_N, sf_N, s0_T, sf_T (PROPS 4-7) and the provider's dC/dD.
   integer, parameter, public :: RCURVE_EQUIVALENT = 2
   !> R-curve: tabulated G_cI(D), G_cII(D), read from a file at start-up (UEXTERNALDB with the
   !> environment variable INTERPHASE_RCURVE, or the driver's case file).
   integer, parameter, public :: RCURVE_TABULATED = 3

   ! ---- STATEV (solution-dependent state, `*DEPVAR`) -----------------------------------------
   !> Damage D = a/b (-), history maximum, 0 <= D <= 1.
   integer, parameter, public :: SV_DAMAGE = 1
   !> Frictional slip lambda, first tangential component (mm).
   integer, parameter, public :: SV_SLIP_1 = 2
   !> Frictional slip lambda, second tangential component (mm); stays 0 in 2-D.
   integer, parameter, public :: SV_SLIP_2 = 3
   !> Regime of the last converged update (output only): one of the REGIME_* codes.
   integer, parameter, public :: SV_REGIME = 4
   !> Number of STATEV slots interphase uses (NSTATV must be at least this).
   integer, parameter, public :: NSTATV_REQUIRED = 4

   ! ---- STATEV slots of the VUMAT only (Abaqus/Explicit passes increments, not totals) -------
   !> VUMAT: total normal separation s_N accumulated from the increments (mm).
   integer, parameter, public :: SV_SEP_N = 5
   !> VUMAT: total tangential separation s_T1, first shear direction (mm).
   integer, parameter, public :: SV_SEP_T1 = 6
   !> VUMAT: total tangential separation s_T2, second shear direction (mm); stays 0 in 2-D.
   integer, parameter, public :: SV_SEP_T2 = 7
   !> VUMAT: failure flag, 0 = every update succeeded, 1 = an update at this point failed at
   !> some increment and its stress and state were held there (sticky; output only).
   integer, parameter, public :: SV_FAILED = 8
   !> Number of STATEV slots the VUMAT uses (nstatev must be at least this).
   integer, parameter, public :: NSTATV_VUMAT = 8

   !> Regime codes (STATEV(SV_REGIME)): no crack yet.
   integer, parameter, public :: REGIME_INTACT = 0
   !> Regime code: crack open, crack faces traction-free.
   integer, parameter, public :: REGIME_OPEN = 1
   !> Regime code: crack closed, faces stick.
   integer, parameter, public :: REGIME_STICK = 2
   !> Regime code: crack closed, faces slip (Coulomb).
   integer, parameter, public :: REGIME_SLIP = 3

end module interphase_layout
