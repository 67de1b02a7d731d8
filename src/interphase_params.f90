!> Material parameters of the interface law and their one decoder from an Abaqus PROPS array.
!> Every value is range-checked here, once, with a message that names the PROPS index, the
!> symbol, the value and the admissible range; nothing is clamped.
module interphase_params
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_finite, only: EXPONENT_MASK, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, PROPS_VALUE_MIN, PROPS_VALUE_MAX, &
      D_MIN_CRACK
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text
   use interphase_layout, only: PROP_MODEL, PROP_DAMAGE_LAW, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, &
      PROP_SF_T, PROP_K_N, PROP_K_T, NPROPS_SIMPLIFIED, PROP_TABLE, NPROPS_MICROMECHANICAL, LFM_D0, &
      LFM_RCURVE, LFM_GC_I, LFM_GC_II, NPROPS_FRACTURE_EXTRA, OPT_GROWTH_SLIP, NPROPS_OPTIONS, &
      OPT_CONTACT_BAND, OPT_VISCOSITY, OPT_STIFFNESS, OPTION_SPECS, OPTION_DEFAULTS, OPTION_SELECTOR, &
      OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, OPT_HOST
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, &
      TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, DAMAGE_FRACTURE, RCURVE_CONSTANT, RCURVE_EQUIVALENT, &
      RCURVE_TABULATED, GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA
   use interphase_status, only: STATUS_OK, STATUS_BAD_NPROPS, STATUS_BAD_MODEL, &
      STATUS_BAD_DAMAGE_LAW, STATUS_BAD_MU, STATUS_BAD_S0_N, STATUS_BAD_SF_N, STATUS_BAD_S0_T, &
      STATUS_BAD_SF_T, STATUS_BAD_K_N, STATUS_BAD_K_T, STATUS_BAD_TABLE_SELECTOR, MESSAGE_LEN, &
      STATUS_BAD_D0, STATUS_BAD_RCURVE, STATUS_BAD_GC_I, STATUS_BAD_GC_II, STATUS_BAD_OPTION
   implicit none
   private
   public :: law_params_type, from_props, decode_props, params_from_values, set_fracture_params, set_options, to_props, &
      refuse_umat_options, constants_count
   ! (for the UMAT, which includes decode_props' source: interphase_decode_props.inc)
   public :: check_constants, decode_options, DEFAULT_PARAMS, WINDOW_MIN_BITS, WINDOW_MAX_BITS, TWO_BITS, THREE_BITS, &
      D0_MIN_BITS

   ! PROPS_VALUE_MIN, PROPS_VALUE_MAX: the admissible magnitudes of the dimensional PROPS
   ! (interphase_finite, where the table readers, built before this module, take them too)
   public :: PROPS_VALUE_MIN, PROPS_VALUE_MAX
   !> Largest admissible separation component |s_i| (mm) at the end of an increment; larger
   !> ones are STATUS_SEPARATION_OUT_OF_RANGE (the increment is cut back).
   real(dp), parameter, public :: SEPARATION_MAX = 1.0e20_dp
   !> Largest admissible slip component |lambda_i| (mm) in an incoming state (STATEV(2:3)):
   !> the slip the law itself produces stays of the order of the separations.
   real(dp), parameter, public :: SLIP_MAX = 1.0e30_dp
   !> Relative size of the round-off in the Coulomb function phi = mu sigma + |tau_trial| (eq 43):
   !> a closed crack slips where phi > SLIP_ONSET_ROUNDOFF (|mu sigma| + |T^c_T s_T|_1). Below it
   !> the sign of phi is round-off: at an increment without change after a slip, phi, returned to
   !> 0, is formed again (the return mapping's second step keeps the slip's own rounding at the
   !> size of the new slip), and where a crack closes at the slip lambda = s_T the terms of
   !> tau_trial cancel; |T^f lambda| <= |tau| + |T^c_T s_T| is covered where phi is near 0. The
   !> sign then decided between slip and stick, and so the tangent, by chance (docs/theory.md,
   !> 'Slip onset').
   real(dp), parameter, public :: SLIP_ONSET_ROUNDOFF = 64.0_dp*epsilon(1.0_dp)
   !> Largest admissible magnitudes of what a host passes in besides the separation (adapters):
   !> HOST_VALUE_MAX for the UMAT's incoming STRESS (MPa), SSE and SPD (N/mm) and the VUMAT's
   !> stressOld, enerInternOld and enerInelasOld (per unit mass); HOST_INCREMENT_MAX for the
   !> UMAT's STRAN and DSTRAN and the VUMAT's separation increments (mm). With the density in
   !> [DENSITY_MIN, DENSITY_MAX] every term of the energy updates then stays below 1e260, and what
   !> the adapters return from admissible separations (tractions up to 1e40 MPa, energies up to
   !> 1e60 N/mm, 1e110 per unit mass) lies inside the bounds again. Outside: STATUS_BAD_HOST_INPUT
   !> (STRAN, DSTRAN: STATUS_NONFINITE_SEPARATION or STATUS_SEPARATION_OUT_OF_RANGE, as for the
   !> separation itself).
   real(dp), parameter, public :: HOST_VALUE_MAX = 1.0e150_dp
   real(dp), parameter, public :: HOST_INCREMENT_MAX = 1.0e50_dp
   !> Admissible density of the VUMAT (*Density, tonne/mm^3 in N-mm-s units).
   real(dp), parameter, public :: DENSITY_MIN = 1.0e-50_dp, DENSITY_MAX = 1.0e50_dp
   !> The window [PROPS_VALUE_MIN, PROPS_VALUE_MAX] and its upper end as the messages show them.
   character(len=*), parameter :: WINDOW_TEXT = '[1e-20, 1e20]', RANGE_MAX_TEXT = '1e20'
   !> The window's ends as bit patterns: positive reals are ordered like their bit patterns read
   !> as signed integers, negative ones (sign bit set) lie below every positive one, +Inf and NaN
   !> above every finite one; so a test on the bits is a range test raising no FP exception.
   integer(int64), parameter :: WINDOW_MIN_BITS = transfer(PROPS_VALUE_MIN, 0_int64)
   !> the fracture law's smallest initial crack D0, D_MIN_CRACK, as bits (accept_constants)
   integer(int64), parameter :: D0_MIN_BITS = transfer(D_MIN_CRACK, 0_int64)
   integer(int64), parameter :: WINDOW_MAX_BITS = transfer(PROPS_VALUE_MAX, 0_int64)
   !> The largest selector code (PROPS values that select a model, a law, a table, an option)
   !> and its bit pattern.
   integer, parameter :: MAX_SELECTOR = 9
   integer(int64), parameter :: MAX_SELECTOR_BITS = transfer(real(MAX_SELECTOR, dp), 0_int64)
   !> The bit patterns of the selector values 1, 2 and 3 (and of 1 as D0's upper end).
   integer(int64), parameter :: ONE_BITS = transfer(1.0_dp, 0_int64), TWO_BITS = transfer(2.0_dp, 0_int64), &
      THREE_BITS = transfer(3.0_dp, 0_int64)

   !> Parameters of one interface material (immutable once decoded).
   type :: law_params_type
      integer :: model = MODEL_SIMPLIFIED            !! MODEL_* selector
      integer :: damage_law = DAMAGE_DISPLACEMENT    !! DAMAGE_* selector
      real(dp) :: mu = 0.0_dp                        !! Coulomb friction coefficient (-)
      real(dp) :: s0_n = 0.0_dp                      !! first-cracking normal separation (mm)
      real(dp) :: sf_n = 0.0_dp                      !! full-crack normal separation (mm)
      real(dp) :: s0_t = 0.0_dp                      !! first-cracking tangential separation (mm)
      real(dp) :: sf_t = 0.0_dp                      !! full-crack tangential separation (mm)
      real(dp) :: k_n = 0.0_dp                       !! simplified model: K_N = C^_NN/h (MPa/mm)
      real(dp) :: k_t = 0.0_dp                       !! simplified model: K_T = C^_TT/h (MPa/mm)
      integer :: table = TABLE_DEFAULT_CODE          !! micromechanical model: TABLE_*_CODE
      real(dp) :: d0 = 0.0_dp                        !! fracture law: initial crack D0 = a0/b (-)
      integer :: rcurve = 0                          !! fracture law: RCURVE_*
      real(dp) :: gc_i = 0.0_dp                      !! fracture law, constant R-curve: G_cI (N/mm per unit crack area)
      real(dp) :: gc_ii = 0.0_dp                     !! fracture law, constant R-curve: G_cII (N/mm per unit crack area)
      integer :: growth_slip = GROWTH_FIXED_PI       !! option: the crack faces' slip while the crack grows, GROWTH_*
      real(dp) :: contact_band = 0.0_dp              !! option: contact band width chi (-), 0 = the paper's two-state law
      real(dp) :: viscosity = 0.0_dp                 !! option: viscosity eta of the damage (s), 0 = none
      integer :: stiffness = 0                       !! option: which stiffness DDSDDE is, STIFFNESS_*
      real(dp) :: layer_thickness = 0.0_dp           !! UMAT option: thin-layer thickness t (mm), 0 = cohesive
      integer :: layer_normal = 0                    !! UMAT option: the layer's normal axis (1-3), 0 = cohesive
      integer :: host = 0                            !! UMAT option: the host's conventions, HOST_*
      real(dp) :: eta_n = 0.0_dp                     !! eta_N = s0_N/sf_N (-), eq 13
      real(dp) :: eta_t = 0.0_dp                     !! eta_T = s0_T/sf_T (-), eq 13
      real(dp) :: inv_s0_n = 0.0_dp                  !! 1/s0_N (1/mm), for the damage law
      real(dp) :: inv_s0_t_sq = 0.0_dp               !! 1/s0_T^2 (1/mm^2), for the damage law
   end type law_params_type

   !> The type's default components (those decode_props writes for a law that does not set them).
   type(law_params_type), parameter :: DEFAULT_PARAMS = law_params_type()

contains

   !> Decode and validate an Abaqus PROPS array. On failure `params` is undefined, `status`
   !> names the first bad value and `message` says which PROPS index, its value and the range.
   pure subroutine from_props(props, params, status, message)
      real(dp), intent(in) :: props(:)                  !! PROPS as given by the host
      type(law_params_type), intent(out) :: params      !! decoded parameters
      integer, intent(out) :: status                    !! STATUS_OK or a STATUS_BAD_* code
      character(len=MESSAGE_LEN), intent(out) :: message   !! set only on failure
      call decode_props(size(props), props, params, status, message)
   end subroutine from_props

   include 'interphase_decode_props.inc'
   include 'interphase_props_stores.inc'

   !> The checks of decode_props, each of which names the first bad value: NPROPS, the
   !> selectors, then every constant (`check_values`, `check_fracture`). Sets model, damage_law
   !> and nprops_needed on success; the option constants are checked by decode_options.
   pure subroutine check_constants(nprops, props, model, damage_law, nprops_needed, status, message)
      integer, intent(in) :: nprops
      real(dp), intent(in) :: props(nprops)
      integer, intent(out) :: model, damage_law, nprops_needed
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      integer :: table, nm

      status = STATUS_OK
      model = 0
      damage_law = 0
      nprops_needed = 0
      if (nprops < PROP_DAMAGE_LAW) then
         status = STATUS_BAD_NPROPS
         write (message, '(a,i0,a)') 'NPROPS = ', nprops, &
            ' is too small: PROPS(1) selects the model, PROPS(2) the damage law'
         return
      end if
      model = selector_code(props(PROP_MODEL))
      if (model /= MODEL_SIMPLIFIED .and. model /= MODEL_MICROMECHANICAL) then
         status = STATUS_BAD_MODEL
         write (message, '(a,i0,a,a,a)') 'PROPS(', PROP_MODEL, ') model = ', real_text(props(PROP_MODEL)), &
            ' is not a model: use 1 (simplified spring model) or 2 (micromechanical)'
         return
      end if
      damage_law = selector_code(props(PROP_DAMAGE_LAW))
      if (damage_law /= DAMAGE_DISPLACEMENT .and. damage_law /= DAMAGE_FRACTURE) then
         status = STATUS_BAD_DAMAGE_LAW
         write (message, '(a,i0,a,a,a)') 'PROPS(', PROP_DAMAGE_LAW, ') damage law = ', &
            real_text(props(PROP_DAMAGE_LAW)), ' is not a damage law: use 1 (displacement-driven, eqs 13-18) '// &
            'or 2 (fracture mechanics, eqs 20-24)'
         return
      end if
      call constants_count(model, damage_law, nm, nprops_needed)
      if (nprops < nprops_needed .or. nprops > nprops_needed + NPROPS_OPTIONS) then
         status = STATUS_BAD_NPROPS
         write (message, '(a,i0,a,a,a,a,a,i0,a,i0,a)') 'NPROPS = ', nprops, ' but the ', &
            trim(merge('simplified     ', 'micromechanical', model == MODEL_SIMPLIFIED)), &
            ' model with the ', &
            trim(merge('displacement-driven', 'fracture-mechanics ', damage_law == DAMAGE_DISPLACEMENT)), &
            ' damage law takes ', nprops_needed, ' constants, followed by at most ', NPROPS_OPTIONS, &
            ' option constant(s)'
         return
      end if

      if (model == MODEL_SIMPLIFIED) then
         call check_values(model, props(PROP_MU), props(PROP_S0_N), props(PROP_SF_N), props(PROP_S0_T), &
            props(PROP_SF_T), props(PROP_K_N), props(PROP_K_T), status, message)
      else
         table = selector_code(props(PROP_TABLE))
         if (table /= TABLE_DEFAULT_CODE .and. table /= TABLE_CUSTOM_CODE) then
            status = STATUS_BAD_TABLE_SELECTOR
            write (message, '(a,i0,a,a,a)') 'PROPS(', PROP_TABLE, ') table = ', real_text(props(PROP_TABLE)), &
               ' is not a table selector: use 0 (built-in table) or 1 (custom table loaded at start-up); the '// &
               'micromechanical model takes no K_N, K_T (its RVE table gives them)'
            return
         end if
         call check_values(model, props(PROP_MU), props(PROP_S0_N), props(PROP_SF_N), props(PROP_S0_T), &
            props(PROP_SF_T), 0.0_dp, 0.0_dp, status, message)
      end if
      if (status /= STATUS_OK) return
      if (damage_law == DAMAGE_FRACTURE) then
         call check_fracture(props(nm + LFM_D0), selector_code(props(nm + LFM_RCURVE)), props(nm + LFM_RCURVE), &
            props(nm + LFM_GC_I), props(nm + LFM_GC_II), nm, status, message)
      end if
   end subroutine check_constants

   !> Decode and validate the optional trailing option constants (PROPS(base + OPT_*)); the
   !> options not given keep their defaults. `base` is the PROPS index before them.
   pure subroutine set_options(params, options, base, status, message)
      type(law_params_type), intent(inout) :: params
      real(dp), intent(in) :: options(:)     !! the option constants given (0 to NPROPS_OPTIONS)
      integer, intent(in) :: base            !! PROPS index before the options (for messages)
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      if (size(options) > NPROPS_OPTIONS) then
         status = STATUS_BAD_NPROPS
         write (message, '(a,i0,a,i0)') 'too many option constants: ', size(options), ' given, at most ', &
            NPROPS_OPTIONS
      else
         call decode_options(params, size(options), options, base, status, message)
      end if
   end subroutine set_options

   !> `set_options` for NOPTIONS (0 to NPROPS_OPTIONS) option constants in an explicit-shape
   !> array (no descriptor at the UMAT's call).
   pure subroutine decode_options(params, noptions, options, base, status, message)
      type(law_params_type), intent(inout) :: params
      integer, intent(in) :: noptions        !! the number of option constants given, <= NPROPS_OPTIONS
      real(dp), intent(in) :: options(*)     !! the option constants given (noptions of them)
      integer, intent(in) :: base            !! PROPS index before the options (for messages)
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      real(dp) :: values(NPROPS_OPTIONS)
      logical :: valid
      integer :: k

      status = STATUS_OK
      ! every option from its entry in OPTION_SPECS: the default, or the value given when it
      ! passes the entry's check (with no option constants, the defaults; decode_props stores
      ! those itself)
      values = OPTION_DEFAULTS
      do k = 1, noptions
         ! (the table's components read in place: a local copy of an entry, a derived type with
         ! default initialisation, was blank-filled at every call, options given or not)
         if (OPTION_SPECS(k)%kind == OPTION_SELECTOR) then
            valid = selector_code(options(k)) >= nint(OPTION_SPECS(k)%lower) .and. &
               selector_code(options(k)) <= nint(OPTION_SPECS(k)%upper)
         else
            valid = finite_at_least(options(k), 0.0_dp)
            if (valid) valid = .not. (options(k) > 0.0_dp) .or. &
               (options(k) >= OPTION_SPECS(k)%lower .and. options(k) <= OPTION_SPECS(k)%upper)
         end if
         if (.not. valid) then
            call reject(STATUS_BAD_OPTION, base + k, trim(OPTION_SPECS(k)%symbol), options(k), &
               trim(OPTION_SPECS(k)%rule), status, message)
            return
         end if
         values(k) = options(k)
      end do
      if (values(OPT_VISCOSITY) > 0.0_dp .and. params%damage_law == DAMAGE_FRACTURE) then
         call reject(STATUS_BAD_OPTION, base + OPT_VISCOSITY, trim(OPTION_SPECS(OPT_VISCOSITY)%symbol), &
            values(OPT_VISCOSITY), 'viscous regularisation is for the displacement-driven law (PROPS(2) = 1); '// &
            'the fracture law''s damage is a root of g(D) = 0 (docs/theory.md): set it to 0', status, message)
         return
      end if
      call store_options(values, params)
   end subroutine decode_options

   !> Entry points that take separations (the VUMAT, the C API) refuse a material that sets the
   !> UMAT's own options, the thin-layer mode (OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL) and the
   !> host conventions (OPT_HOST), rather than ignoring them: STATUS_BAD_OPTION naming the first.
   !> `entry` names the caller in the message.
   pure subroutine refuse_umat_options(params, entry, status, message)
      type(law_params_type), intent(in) :: params
      character(len=*), intent(in) :: entry
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      integer :: k, base, nm
      status = STATUS_OK
      k = 0
      if (params%layer_thickness > 0.0_dp) then
         k = OPT_LAYER_THICKNESS
      else if (params%layer_normal /= 0) then
         k = OPT_LAYER_NORMAL
      else if (params%host /= 0) then
         k = OPT_HOST
      end if
      if (k == 0) return
      call constants_count(params%model, params%damage_law, nm, base)
      status = STATUS_BAD_OPTION
      write (message, '(a,i0,a,a,a,a,a)') 'PROPS(', base + k, ') ', trim(OPTION_SPECS(k)%symbol), &
         ' is an option of the UMAT only (thin continuum layers, host conventions); ', entry, &
         ' takes separations: leave it 0'
   end subroutine refuse_umat_options

   !> The PROPS array (docs/abaqus.md) of a parameter set: the one encoder of PROPS, the inverse
   !> of `from_props` for every set it accepts. The option constants are written up to the last
   !> one that is not at its default (none when all are), so that a material without options has
   !> the short deck it always had.
   pure function to_props(params) result(props)
      type(law_params_type), intent(in) :: params
      real(dp), allocatable :: props(:)
      real(dp) :: values(NPROPS_OPTIONS)
      integer :: nm, nlast, k
      nm = NPROPS_SIMPLIFIED
      if (params%model == MODEL_MICROMECHANICAL) nm = NPROPS_MICROMECHANICAL
      allocate (props(nm))
      props(PROP_MODEL) = real(params%model, dp)
      props(PROP_DAMAGE_LAW) = real(params%damage_law, dp)
      props(PROP_MU) = params%mu
      props(PROP_S0_N) = params%s0_n
      props(PROP_SF_N) = params%sf_n
      props(PROP_S0_T) = params%s0_t
      props(PROP_SF_T) = params%sf_t
      if (params%model == MODEL_MICROMECHANICAL) then
         props(PROP_TABLE) = real(params%table, dp)
      else
         props(PROP_K_N) = params%k_n
         props(PROP_K_T) = params%k_t
      end if
      if (params%damage_law == DAMAGE_FRACTURE) then
         props = [props, [params%d0, real(params%rcurve, dp), params%gc_i, params%gc_ii]]
      end if
      values(OPT_GROWTH_SLIP) = real(params%growth_slip, dp)
      values(OPT_CONTACT_BAND) = params%contact_band
      values(OPT_VISCOSITY) = params%viscosity
      values(OPT_STIFFNESS) = real(params%stiffness, dp)
      values(OPT_LAYER_THICKNESS) = params%layer_thickness
      values(OPT_LAYER_NORMAL) = real(params%layer_normal, dp)
      values(OPT_HOST) = real(params%host, dp)
      nlast = 0
      do k = 1, NPROPS_OPTIONS
         if (.not. same_bits(values(k), OPTION_DEFAULTS(k))) nlast = k
      end do
      props = [props, values(1:nlast)]
   contains
      pure logical function same_bits(a, b)
         real(dp), intent(in) :: a, b
         same_bits = transfer(a, 0_int64) == transfer(b, 0_int64)
      end function same_bits
   end function to_props

   !> Build and validate parameters from named values (the same checks as `from_props`; the
   !> messages cite the PROPS index each value occupies). The simplified model needs k_n and
   !> k_t; the micromechanical model takes `table` (default: the built-in table).
   pure subroutine params_from_values(model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, &
         params, status, message, k_n, k_t, table)
      integer, intent(in) :: model                 !! MODEL_* selector
      integer, intent(in) :: damage_law            !! DAMAGE_* selector
      real(dp), intent(in) :: mu                   !! friction coefficient (-)
      real(dp), intent(in) :: s0_n, sf_n           !! normal first-cracking / full-crack separations (mm)
      real(dp), intent(in) :: s0_t, sf_t           !! tangential first-cracking / full-crack separations (mm)
      type(law_params_type), intent(out) :: params
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      real(dp), intent(in), optional :: k_n, k_t   !! simplified model: spring stiffnesses (MPa/mm)
      integer, intent(in), optional :: table       !! micromechanical model: TABLE_*_CODE

      real(dp) :: k_n_used, k_t_used
      integer :: table_used

      k_n_used = 0.0_dp
      k_t_used = 0.0_dp
      if (model == MODEL_SIMPLIFIED) then
         k_n_used = -1.0_dp
         k_t_used = -1.0_dp
         if (present(k_n)) k_n_used = k_n
         if (present(k_t)) k_t_used = k_t
      end if
      table_used = TABLE_DEFAULT_CODE
      if (present(table)) table_used = table
      call decode_values(model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n_used, k_t_used, table_used, &
         params, status, message)
   end subroutine params_from_values

   !> params_from_values' checks and assignments, filling `params` in place (its components
   !> other than these keep what they hold): k_n, k_t are the simplified model's (ignored by the
   !> micromechanical model, and stored as given), table the micromechanical model's.
   pure subroutine decode_values(model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n_used, k_t_used, table, &
         params, status, message)
      integer, intent(in) :: model, damage_law
      real(dp), intent(in) :: mu, s0_n, sf_n, s0_t, sf_t
      real(dp), intent(in) :: k_n_used, k_t_used   !! (MPa/mm)
      integer, intent(in) :: table
      type(law_params_type), intent(inout) :: params
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      call check_values(model, mu, s0_n, sf_n, s0_t, sf_t, k_n_used, k_t_used, status, message)
      if (status /= STATUS_OK) return
      call store_values(model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n_used, k_t_used, table, params)
   end subroutine decode_values

   !> The checks of the law's constants (PROPS(3:9)): the first bad value named, with its PROPS
   !> index, in `message`. k_n, k_t are checked for the simplified model only.
   pure subroutine check_values(model, mu, s0_n, sf_n, s0_t, sf_t, k_n_used, k_t_used, status, message)
      integer, intent(in) :: model
      real(dp), intent(in) :: mu, s0_n, sf_n, s0_t, sf_t
      real(dp), intent(in) :: k_n_used, k_t_used   !! (MPa/mm)
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      status = STATUS_OK
      ! Each test fails for NaN and Inf without comparing them (no FP exception is raised).
      if (.not. (finite_at_least(mu, 0.0_dp) .and. finite_at_most(mu, PROPS_VALUE_MAX))) then
         call reject(STATUS_BAD_MU, PROP_MU, 'mu', mu, 'must lie in [0, '//RANGE_MAX_TEXT//']', status, message)
      else if (.not. in_window(s0_n)) then
         call reject(STATUS_BAD_S0_N, PROP_S0_N, 's0_N', s0_n, 'must lie in '//WINDOW_TEXT//' mm', status, message)
      else if (.not. (finite_above(sf_n, s0_n) .and. in_window(sf_n))) then
         call reject(STATUS_BAD_SF_N, PROP_SF_N, 'sf_N', sf_n, 'must be > s0_N = PROPS(4) = '//real_text(s0_n)// &
            ' mm and lie in '//WINDOW_TEXT//' mm', status, message)
      else if (.not. in_window(s0_t)) then
         call reject(STATUS_BAD_S0_T, PROP_S0_T, 's0_T', s0_t, 'must lie in '//WINDOW_TEXT//' mm', status, message)
      else if (.not. (finite_above(sf_t, s0_t) .and. in_window(sf_t))) then
         call reject(STATUS_BAD_SF_T, PROP_SF_T, 'sf_T', sf_t, 'must be > s0_T = PROPS(6) = '//real_text(s0_t)// &
            ' mm and lie in '//WINDOW_TEXT//' mm', status, message)
      else if (model == MODEL_SIMPLIFIED .and. .not. in_window(k_n_used)) then
         call reject(STATUS_BAD_K_N, PROP_K_N, 'K_N', k_n_used, 'must lie in '//WINDOW_TEXT//' MPa/mm', status, message)
      else if (model == MODEL_SIMPLIFIED .and. .not. in_window(k_t_used)) then
         call reject(STATUS_BAD_K_T, PROP_K_T, 'K_T', k_t_used, 'must lie in '//WINDOW_TEXT//' MPa/mm', status, message)
      end if
   end subroutine check_values

   !> Add and validate the fracture-mechanics law's constants; `base` is the PROPS index before
   !> them (for the messages: D0 is PROPS(base + 1), ...).
   pure subroutine set_fracture_params(params, d0, rcurve, rcurve_value, gc_i, gc_ii, base, status, message)
      type(law_params_type), intent(inout) :: params
      real(dp), intent(in) :: d0             !! initial crack D0 = a0/b (-)
      integer, intent(in) :: rcurve          !! RCURVE_* (or -1: not a selector)
      real(dp), intent(in) :: rcurve_value   !! the PROPS value of the selector (for messages)
      real(dp), intent(in) :: gc_i, gc_ii    !! constant toughnesses (N/mm), 0 unless RCURVE_CONSTANT
      integer, intent(in) :: base            !! PROPS index before the law's constants
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      call check_fracture(d0, rcurve, rcurve_value, gc_i, gc_ii, base, status, message)
      if (status /= STATUS_OK) return
      call store_fracture(d0, rcurve, gc_i, gc_ii, params)
   end subroutine set_fracture_params

   !> The checks of the fracture law's constants (set_fracture_params' arguments), the first bad
   !> value named in `message`.
   pure subroutine check_fracture(d0, rcurve, rcurve_value, gc_i, gc_ii, base, status, message)
      real(dp), intent(in) :: d0, rcurve_value, gc_i, gc_ii
      integer, intent(in) :: rcurve, base
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      logical :: valid

      status = STATUS_OK
      ! (d0 compared with 1 only once it is known finite: a NaN D0 raises no invalid-operation
      ! exception, which a build trapping them would stop on)
      valid = finite_at_least(d0, D_MIN_CRACK)
      if (valid) valid = d0 < 1.0_dp
      if (.not. valid) then
         ! (below D_MIN_CRACK, 1e-30, the coefficients' and the release rates' D-slopes of so short
         ! a crack would overflow: interphase_finite)
         call reject(STATUS_BAD_D0, base + LFM_D0, 'D0 = a0/b', d0, &
            'must lie in [1e-30, 1): the fracture-mechanics law needs an initial crack', status, message)
         return
      end if
      if (rcurve /= RCURVE_CONSTANT .and. rcurve /= RCURVE_EQUIVALENT .and. rcurve /= RCURVE_TABULATED) then
         call reject(STATUS_BAD_RCURVE, base + LFM_RCURVE, 'R-curve', rcurve_value, &
            'use 1 (constant G_c), 2 (equivalent to the displacement law) or 3 (tabulated, from a file)', &
            status, message)
         return
      end if
      if (rcurve == RCURVE_CONSTANT) then
         if (.not. in_window(gc_i)) then
            call reject(STATUS_BAD_GC_I, base + LFM_GC_I, 'G_cI', gc_i, 'must lie in '//WINDOW_TEXT//' N/mm', &
               status, message)
         else if (.not. in_window(gc_ii)) then
            call reject(STATUS_BAD_GC_II, base + LFM_GC_II, 'G_cII', gc_ii, 'must lie in '//WINDOW_TEXT//' N/mm', &
               status, message)
         end if
      else
         if (finite_above(gc_i, 0.0_dp) .or. .not. finite_at_least(gc_i, 0.0_dp)) then
            call reject(STATUS_BAD_GC_I, base + LFM_GC_I, 'G_cI', gc_i, &
               'must be 0 (only the constant R-curve takes a toughness from PROPS)', status, message)
         else if (finite_above(gc_ii, 0.0_dp) .or. .not. finite_at_least(gc_ii, 0.0_dp)) then
            call reject(STATUS_BAD_GC_II, base + LFM_GC_II, 'G_cII', gc_ii, &
               'must be 0 (only the constant R-curve takes a toughness from PROPS)', status, message)
         end if
      end if
   end subroutine check_fracture

   !> Set a rejection status and its message: PROPS(index) symbol = value is out of range: rule.
   pure subroutine reject(code, index, symbol, value, rule, status, message)
      integer, intent(in) :: code, index
      character(len=*), intent(in) :: symbol, rule
      real(dp), intent(in) :: value
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      status = code
      ! (the value as real_text writes it, as the model and damage-law messages do: -0.75, 0.1E-3,
      ! NaN, the fewest digits that read back as the same number)
      write (message, '(a,i0,a,a,a,a,a,a)') 'PROPS(', index, ') ', symbol, ' = ', real_text(value), &
         ' is out of range: ', rule
   end subroutine reject

   !> The selector code held by a PROPS value: c when `x` is exactly the real number c for a code
   !> 0 <= c <= MAX_SELECTOR, else -1 (which no selector uses); -0 is the code 0, as +0 (a deck's
   !> `-0.` is the number 0). The range is tested on the bit pattern first (+0 <= x <=
   !> MAX_SELECTOR: false for NaN and Inf), so the conversion and the comparison of bit patterns
   !> only ever see a finite x in that range: no floating-point exception.
   pure integer function selector_code(x) result(code)
      real(dp), intent(in) :: x
      integer(int64) :: b
      integer :: k
      code = -1
      b = binary64_bits(x)
      if (b == ibset(0_int64, 63)) b = 0_int64
      if (b >= 0_int64 .and. b <= MAX_SELECTOR_BITS) then
         k = int(x)
         if (binary64_bits(real(k, dp)) == b) code = k
      end if
   end function selector_code

   !> x lies in [PROPS_VALUE_MIN, PROPS_VALUE_MAX] (false for NaN and Inf, without an exception).
   pure logical function in_window(x)
      real(dp), intent(in) :: x
      integer(int64) :: b
      b = binary64_bits(x)
      in_window = b >= WINDOW_MIN_BITS .and. b <= WINDOW_MAX_BITS
   end function in_window

   include 'interphase_binary64_bits.inc'

   !> x is neither NaN nor Inf (interphase_finite's test, here where the decoder's checks can
   !> inline it).
   pure logical function finite(x)
      real(dp), intent(in) :: x
      finite = iand(binary64_bits(x), EXPONENT_MASK) /= EXPONENT_MASK
   end function finite

   !> x is finite and x > lower (false for NaN and Inf, without an invalid-operation exception).
   pure logical function finite_above(x, lower)
      real(dp), intent(in) :: x, lower
      finite_above = .false.
      if (finite(x)) finite_above = x > lower
   end function finite_above

   !> x is finite and x <= upper.
   pure logical function finite_at_most(x, upper)
      real(dp), intent(in) :: x, upper
      finite_at_most = .false.
      if (finite(x)) finite_at_most = x <= upper
   end function finite_at_most

   !> x is finite and x >= lower.
   pure logical function finite_at_least(x, lower)
      real(dp), intent(in) :: x, lower
      finite_at_least = .false.
      if (finite(x)) finite_at_least = x >= lower
   end function finite_at_least

end module interphase_params
