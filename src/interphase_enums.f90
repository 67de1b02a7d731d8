!> The codes of interphase: the values PROPS selectors take (model, damage law, RVE table,
!> R-curve, option settings) and the regime codes of STATEV(SV_REGIME). Where each code is stored
!> is interphase_layout's business (the slot map); this module only names the values.
module interphase_enums
   implicit none
   private

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
   !> Regime codes (STATEV(SV_REGIME)): no crack yet.
   integer, parameter, public :: REGIME_INTACT = 0
   !> Regime code: crack open, crack faces traction-free.
   integer, parameter, public :: REGIME_OPEN = 1
   !> Regime code: crack closed, faces stick.
   integer, parameter, public :: REGIME_STICK = 2
   !> Regime code: crack closed, faces slip (Coulomb).
   integer, parameter, public :: REGIME_SLIP = 3
   !> PROPS(nb + OPT_STIFFNESS) value, the default: DDSDDE is the consistent tangent (unsymmetric
   !> while damage grows or the crack slips: Abaqus needs UNSYMM).
   integer, parameter, public :: STIFFNESS_CONSISTENT = 0
   !> PROPS(nb + OPT_STIFFNESS) value: DDSDDE is the consistent tangent's symmetric part.
   integer, parameter, public :: STIFFNESS_SYMMETRIC = 1
   !> PROPS(nb + OPT_STIFFNESS) value: DDSDDE is the tangent at fixed damage, without the
   !> friction's coupling of the shear traction to s_N: symmetric, and positive semi-definite
   !> (with the contact band only where chi >= chi_min(D), docs/theory.md 'The contact band')
   !> (for hosts that assemble only a symmetric stiffness; Newton then converges linearly).
   integer, parameter, public :: STIFFNESS_FIXED_DAMAGE = 2
   !> PROPS(nb + OPT_HOST) value, the default: Abaqus's conventions (SSE and SPD are the values
   !> the UMAT returned last, kept by the host; PNEWDT arrives large).
   integer, parameter, public :: HOST_ABAQUS = 0
   !> PROPS(nb + OPT_HOST) value: CalculiX's conventions (SSE and SPD arrive uninitialised and
   !> are not kept between calls; PNEWDT arrives as -1, and any value > 0 is a cut-back factor).
   integer, parameter, public :: HOST_CALCULIX = 1

end module interphase_enums
