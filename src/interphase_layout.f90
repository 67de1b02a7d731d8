!> The Abaqus-facing layout of interphase: PROPS and STATEV slot numbers and the codes stored in
!> them. This module is the only place that knows which slot holds what; `docs/abaqus.md` is its
!> user-facing copy and must be kept in step with it.
module interphase_layout
   use interphase_kinds, only: dp
   ! the codes stored in the slots (interphase_enums), offered here too so that a user of the
   ! layout has the slot and its values from one module
   use interphase_enums, only: TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, &
      DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA, RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED, &
      REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, STIFFNESS_CONSISTENT, STIFFNESS_SYMMETRIC, &
      STIFFNESS_FIXED_DAMAGE, HOST_ABAQUS, HOST_CALCULIX
   implicit none
   private
   public :: TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, &
      DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA, RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED, &
      REGIME_INTACT, REGIME_OPEN, REGIME_STICK, REGIME_SLIP, STIFFNESS_CONSISTENT, STIFFNESS_SYMMETRIC, &
      STIFFNESS_FIXED_DAMAGE, HOST_ABAQUS, HOST_CALCULIX

   ! ---- PROPS (material constants, `*USER MATERIAL, CONSTANTS=...`) --------------------------
   !> Model selector: MODEL_SIMPLIFIED or MODEL_MICROMECHANICAL.
   integer, parameter, public :: PROP_MODEL = 1
   !> Damage-law selector: DAMAGE_DISPLACEMENT or DAMAGE_FRACTURE.
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
   !> Option offset: the viscosity eta (s) of the damage's viscous regularisation (Duvaut-Lions,
   !> as Abaqus offers for its cohesive elements): D_v = (D_v,n + (dt/eta) D)/(1 + dt/eta), the
   !> response and the tangent at D_v; 0 (the default) is off. Displacement-driven law only.
   integer, parameter, public :: OPT_VISCOSITY = 3
   !> Option offset: which stiffness DDSDDE is (STIFFNESS_*): the consistent tangent (0, the
   !> default), its symmetric part (1), or the tangent at fixed damage without the friction's
   !> normal coupling (2, symmetric, and positive semi-definite: with the contact band where chi >=
   !> chi_min(D), docs/theory.md). The traction is the same.
   integer, parameter, public :: OPT_STIFFNESS = 4
   !> Option offset: the thickness t (mm) of a thin continuum joint layer (the UMAT's layer
   !> mode, docs/abaqus.md 'Thin continuum layers'): the UMAT reads STRAN and DSTRAN as strains
   !> of a layer of thickness t and maps them to separations, s_N = t eps_nn and s_T = t gamma
   !> (engineering shears); STRESS = the tractions, DDSDDE = t dT/ds, SSE and SPD per unit
   !> volume of the layer. 0 (the default) is the cohesive element with constitutive
   !> thickness 1: STRAN and DSTRAN are the separations. UMAT only.
   integer, parameter, public :: OPT_LAYER_THICKNESS = 5
   !> Option offset: the layer's normal axis, 1, 2 or 3, the direct strain component that is the
   !> layer's through-thickness strain in a continuum element (NDI = 2 or 3); 0 (the default)
   !> for a cohesive element (NDI = 1), whose components are normal first. UMAT only.
   integer, parameter, public :: OPT_LAYER_NORMAL = 6
   !> Option offset: the host's conventions (HOST_*): Abaqus (0, the default: SSE and SPD are
   !> kept by the host between calls and accumulated) or CalculiX (1: SSE and SPD arrive
   !> uninitialised and are not kept, so the UMAT neither reads nor writes them). UMAT only.
   integer, parameter, public :: OPT_HOST = 7
   !> Number of option constants.
   integer, parameter, public :: NPROPS_OPTIONS = 7
   !> Admissible layer thicknesses: t = 0 or LAYER_THICKNESS_MIN <= t <= LAYER_THICKNESS_MAX (mm).
   real(dp), parameter, public :: LAYER_THICKNESS_MIN = 1.0e-6_dp
   real(dp), parameter, public :: LAYER_THICKNESS_MAX = 1.0e3_dp
   !> Admissible contact band widths: chi = 0 or CONTACT_BAND_MIN <= chi <= CONTACT_BAND_MAX (-).
   !> Below 0.1 the band's normal stiffness, ~ q max|W''|/(2 chi^2), could exceed the intact
   !> crack's (which the VUMAT's stable increment assumes), and its energy is far from convex.
   real(dp), parameter, public :: CONTACT_BAND_MIN = 0.1_dp
   real(dp), parameter, public :: CONTACT_BAND_MAX = 10.0_dp

   !> How an option constant is decoded: OPTION_SELECTOR, an integer code 0 .. upper given as
   !> exactly that real number; OPTION_SWITCHED_RANGE, 0 (off) or a finite value in
   !> [lower, upper].
   integer, parameter, public :: OPTION_SELECTOR = 1
   integer, parameter, public :: OPTION_SWITCHED_RANGE = 2
   !> What an option constant is: its symbol (in messages), how it is decoded, its default, its
   !> range and the rule a message states when a value breaks it.
   type, public :: option_spec_type
      character(len=24) :: symbol = ''
      integer :: kind = OPTION_SELECTOR
      real(dp) :: default = 0.0_dp
      real(dp) :: lower = 0.0_dp
      real(dp) :: upper = 0.0_dp
      character(len=160) :: rule = ''
   end type option_spec_type
   !> Everything a new option needs, in one place: its offset (OPT_*) is its index here, and
   !> interphase_params decodes, checks and encodes every entry from this table.
   type(option_spec_type), parameter, public :: OPTION_SPECS(NPROPS_OPTIONS) = [ &
      option_spec_type('growth slip', OPTION_SELECTOR, real(GROWTH_FIXED_PI, dp), 0.0_dp, &
         real(GROWTH_FIXED_LAMBDA, dp), 'use 0 (conserve the integrated slip pi = D ufbar lambda, the '// &
         'default) or 1 (hold lambda, the paper''s form)'), &
      option_spec_type('contact band chi', OPTION_SWITCHED_RANGE, 0.0_dp, CONTACT_BAND_MIN, CONTACT_BAND_MAX, &
         'must be 0 (the paper''s open/closed switch) or finite in [0.1, 10]'), &
      option_spec_type('viscosity eta', OPTION_SWITCHED_RANGE, 0.0_dp, 1.0e-20_dp, 1.0e20_dp, &
         'must be 0 (no viscous regularisation) or finite in [1e-20, 1e20] s'), &
      option_spec_type('stiffness', OPTION_SELECTOR, real(STIFFNESS_CONSISTENT, dp), 0.0_dp, &
         real(STIFFNESS_FIXED_DAMAGE, dp), 'use 0 (the consistent tangent), 1 (its symmetric part) or 2 '// &
         '(the tangent at fixed damage without the friction''s normal coupling)'), &
      option_spec_type('layer thickness t', OPTION_SWITCHED_RANGE, 0.0_dp, LAYER_THICKNESS_MIN, &
         LAYER_THICKNESS_MAX, 'must be 0 (a cohesive element: STRAN is the separation) or finite in '// &
         '[1e-6, 1e3] mm'), &
      option_spec_type('layer normal axis', OPTION_SELECTOR, 0.0_dp, 0.0_dp, 3.0_dp, &
         'use 0 (a cohesive element, normal first) or the axis 1, 2 or 3 of the layer''s normal '// &
         'in a continuum element'), &
      option_spec_type('host', OPTION_SELECTOR, real(HOST_ABAQUS, dp), 0.0_dp, real(HOST_CALCULIX, dp), &
         'use 0 (Abaqus: the host keeps SSE and SPD) or 1 (CalculiX: SSE and SPD are neither read '// &
         'nor written)')]
   !> The options' defaults, OPTION_SPECS%default as an array constant of its own (the update
   !> decodes PROPS at every call: a reference to a component of OPTION_SPECS there made the
   !> compiler build the whole table, strings included, each time).
   real(dp), parameter, public :: OPTION_DEFAULTS(NPROPS_OPTIONS) = OPTION_SPECS%default

   ! ---- STATEV (solution-dependent state, `*DEPVAR`) -----------------------------------------
   ! The slots the UMAT and the VUMAT share come first (1 .. NSTATV_SHARED), the VUMAT's own after
   ! them, so that a new shared slot never moves a shared one.
   !> Damage D = a/b (-), 0 <= D <= 1, the damage the response uses: the history maximum of the
   !> damage law's D, or with viscous regularisation (OPT_VISCOSITY) the regularised D_v.
   integer, parameter, public :: SV_DAMAGE = 1
   !> Frictional slip lambda, first tangential component (mm).
   integer, parameter, public :: SV_SLIP_1 = 2
   !> Frictional slip lambda, second tangential component (mm); stays 0 in 2-D.
   integer, parameter, public :: SV_SLIP_2 = 3
   !> Regime of the last converged update (output only): one of the REGIME_* codes.
   integer, parameter, public :: SV_REGIME = 4
   !> With viscous regularisation only: the damage law's own (inviscid) D, history maximum
   !> (-), D_v <= D <= 1. Not read nor written without it.
   integer, parameter, public :: SV_DAMAGE_INVISCID = 5
   !> Number of STATEV slots interphase uses without viscous regularisation (NSTATV must be at
   !> least this).
   integer, parameter, public :: NSTATV_REQUIRED = 4
   !> Number of STATEV slots with viscous regularisation (NSTATV must be at least this then).
   integer, parameter, public :: NSTATV_VISCOUS = 5
   !> Number of slots the UMAT and the VUMAT share.
   integer, parameter, public :: NSTATV_SHARED = 5

   ! ---- STATEV slots of the VUMAT only (Abaqus/Explicit passes increments, not totals) -------
   !> VUMAT: total normal separation s_N accumulated from the increments (mm).
   integer, parameter, public :: SV_SEP_N = NSTATV_SHARED + 1
   !> VUMAT: total tangential separation s_T1, first shear direction (mm).
   integer, parameter, public :: SV_SEP_T1 = NSTATV_SHARED + 2
   !> VUMAT: total tangential separation s_T2, second shear direction (mm); stays 0 in 2-D.
   integer, parameter, public :: SV_SEP_T2 = NSTATV_SHARED + 3
   !> VUMAT: failure flag, 0 = every update succeeded, 1 = an update at this point failed at
   !> some increment and its stress and state were held there (sticky; output only).
   integer, parameter, public :: SV_FAILED = NSTATV_SHARED + 4
   !> Number of STATEV slots the VUMAT uses (nstatev must be at least this).
   integer, parameter, public :: NSTATV_VUMAT = NSTATV_SHARED + 4

end module interphase_layout
