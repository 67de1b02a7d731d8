!> interphase-check-deck: check an Abaqus input deck's use of interphase before running it.
!>
!>   interphase-check-deck deck.inp [more.inp ...]
!>
!> For every *COHESIVE SECTION, and every *SOLID SECTION whose material has a *USER MATERIAL (the
!> job's one UMAT, interphase's, takes continuum elements only in its thin-layer mode: a layer
!> thickness and normal axis are required; under Explicit such a section is refused; a material
!> named as CalculiX names one, ABAQUS... or @..., marks a CalculiX deck, which is not checked),
!> it checks what interphase requires (docs/abaqus.md):
!> RESPONSE=TRACTION SEPARATION (or CONTINUUM), THICKNESS=SPECIFIED with constitutive thickness 1,
!> or the material's layer thickness t when it sets one (a continuum response with THICKNESS=
!> GEOMETRY gets a note: the value comes from the nodes), the layer normal axis 0, a material
!> with *USER MATERIAL whose constants decode as interphase PROPS (the library's own decoder:
!> the same messages the UMAT would give at the first increment), *DEPVAR at least 4 (UMAT; 5 with
!> viscous regularisation) or 9 (VUMAT, when the deck has a *DYNAMIC, EXPLICIT step), UNSYMM for
!> Abaqus/Standard with the consistent tangent (stiffness option 0), a *DENSITY > 0 for
!> Abaqus/Explicit, and no *DEPVAR, DELETE= among interphase's slots (which hold 0 at every intact
!> point: Abaqus would delete it), none of the built-in cohesive law's keywords (*ELASTIC,
!> TYPE=TRACTION, *DAMAGE INITIATION, *DAMAGE EVOLUTION, *DAMAGE STABILIZATION) in the material
!> (a note for a *SECTION CONTROLS' VISCOSITY=, which is not interphase's), and the element sets'
!> initial state variables (*INITIAL CONDITIONS, TYPE=SOLUTION) as the UMAT's and VUMAT's STATEV reader checks them. It reads
!> keywords (a keyword line that ends in a comma continued on the next; keywords, parameters and
!> values abbreviated as Abaqus allows) and their data lines only, those of *INCLUDE files where
!> they stand (a relative INPUT= from the deck's folder, the job's working directory, in nested
!> files too; an *INCLUDE that cannot be read is a failed check; no parts/assemblies resolution;
!> *USER MATERIAL, TYPE=THERMAL, a UMATHT's, is not interphase's and is skipped) as Abaqus reads
!> them: an empty data field is 0 (not skipped), a label in double quotes is taken as written;
!> what Abaqus refuses in the lines it reads is a failed check (a line over 256
!> characters, more than 8 constants on a *USER MATERIAL data line, a parameter *USER MATERIAL
!> does not have, *MATERIAL without NAME=, *COHESIVE SECTION without ELSET= or MATERIAL=), and
!> a section whose own or material's lines fail is not said to be ok. It prints one line per
!> cohesive section, and a note when the material needs a file loaded at start-up (a custom RVE
!> table, a tabulated R-curve: the run then needs the environment variable and the
!> start-of-analysis hook, which a deck cannot show); the exit status is 0 when every check
!> passes, 1 otherwise, 2 when a file cannot be read.
program interphase_check_deck
   use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite
   use interphase_layout, only: NSTATV_REQUIRED, NSTATV_VUMAT, MODEL_SIMPLIFIED, DAMAGE_DISPLACEMENT, &
      MODEL_MICROMECHANICAL, TABLE_CUSTOM_CODE, TABLE_DEFAULT_CODE, DAMAGE_FRACTURE, RCURVE_TABULATED, PROP_TABLE, &
      RCURVE_EQUIVALENT, RCURVE_CONSTANT, NSTATV_VISCOUS, STIFFNESS_CONSISTENT, &
      GROWTH_FIXED_LAMBDA, HOST_CALCULIX, OPT_HOST, OPT_CONTACT_BAND, OPT_VISCOSITY, OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, &
      SV_DAMAGE, SV_SLIP_1, &
      SV_SLIP_2, SV_REGIME, SV_DAMAGE_INVISCID, &
      SV_FAILED, SV_SEP_N, SV_SEP_T1, SV_SEP_T2
   use interphase_status, only: STATUS_OK, STATUS_BAD_OPTION, MESSAGE_LEN
   use interphase_state, only: interface_state_type, unpack_statev
   use interphase_params, only: law_params_type, from_props, refuse_umat_options, constants_count
   use interphase_coefficients, only: coefficient_set_type
   use interphase_provider, only: coefficient_values_at
   use interphase_driver_cli, only: get_argument, exit_program, print_version
   use interphase_text_input, only: text_file_type, open_text_file, read_text_line, close_text_file, &
      tried_path, clip_text, parse_real, text_before, TEXT_LINE, TEXT_END
   use interphase_driver_text, only: int_to_string, real_to_string
   use interphase_real_text, only: real_text
   implicit none
   !> The smallest contact band width chi that keeps the stored energy convex at every D of the
   !> built-in table (docs/theory.md, 'The contact band').
   real(dp), parameter :: CHI_MIN_BUILT_IN = 0.55_dp

   !> Length of a keyword's or a parameter's name (upper case, blanks removed).
   integer, parameter :: NAME_LEN = 40
   !> Longest deck line read (a longer one is not read: exit status 2).
   integer, parameter :: LINE_LEN = 1024
   !> Longest keyword or data line Abaqus reads (its input syntax rules: 256 characters,
   !> blanks included); a longer one, up to LINE_LEN, is a failed check.
   integer, parameter :: ABAQUS_LINE_LEN = 256
   !> Most constants on one *USER MATERIAL data line (Abaqus Keywords Guide: eight per line).
   integer, parameter :: CONSTANTS_PER_LINE = 8
   !> The parameters of *USER MATERIAL (Abaqus Keywords Guide): any other one is refused.
   character(len=NAME_LEN), parameter :: USER_MATERIAL_PARAMETERS(5) = [character(len=NAME_LEN) :: 'CONSTANTS', &
      'EFFMOD', 'HYBRIDFORMULATION', 'TYPE', 'UNSYMM']
   !> The parameters of *COHESIVE SECTION (Abaqus Keywords Guide): another one is named in a note
   !> (a misspelt THICKNSS= would otherwise leave THICKNESS= to its default without a word).
   character(len=NAME_LEN), parameter :: COHESIVE_SECTION_PARAMETERS(9) = [character(len=NAME_LEN) :: 'CONTROLS', &
      'ELSET', 'HALF', 'MATERIAL', 'ORIENTATION', 'RESPONSE', 'STACKDIRECTION', 'SYMMETRIC', 'THICKNESS']
   !> Most constants of one *USER MATERIAL.
   integer, parameter :: MAX_CONSTANTS = 64
   !> Most *INCLUDE files open at once (one inside another): deeper is refused (a file that includes
   !> itself is refused by name; a loop the names do not show would otherwise be read without end).
   integer, parameter :: MAX_INCLUDE_DEPTH = 16

   !> A file that includes the one being read, as it was left at its *INCLUDE line: the file, its
   !> path, and the keyword line it had read ahead (after an *INCLUDE line that ends in a comma),
   !> which is read after the included file: its text, number and length.
   type :: include_frame_type
      type(text_file_type) :: file
      character(len=:), allocatable :: path
      logical :: have_held = .false.
      character(len=LINE_LEN) :: held = ''
      integer :: held_lineno = 0, held_length = 0
   end type include_frame_type

   !> The keywords this check reads (upper case, blanks removed, as Abaqus compares them). Abaqus
   !> takes a keyword, a parameter and most parameter values abbreviated to any start that no
   !> other one shares (its input syntax rules): `resolve_name` reads such an abbreviation as the
   !> name it abbreviates, against these and the Abaqus keywords beside them (KEYWORDS_BESIDE).
   character(len=NAME_LEN), parameter :: KEYWORDS_READ(22) = [character(len=NAME_LEN) :: 'MATERIAL', &
      'USERMATERIAL', 'DEPVAR', 'DENSITY', 'COHESIVESECTION', 'DYNAMIC', 'DYNAMICTEMPERATURE-DISPLACEMENT', &
      'INCLUDE', 'STEP', 'PART', 'ASSEMBLY', 'INSTANCE', 'NODE', 'ELEMENT', 'SOLIDSECTION', 'SHELLSECTION', &
      'INITIALCONDITIONS', 'ELASTIC', 'DAMAGEINITIATION', 'DAMAGEEVOLUTION', 'DAMAGESTABILIZATION', 'SECTIONCONTROLS']
   !> The keywords of Abaqus's built-in cohesive (traction-separation) law in a material: beside
   !> interphase's *USER MATERIAL they are a second law, left over from a deck that used the built-in
   !> one (*ELASTIC counts with TYPE=TRACTION or COUPLED TRACTION only).
   character(len=NAME_LEN), parameter :: BUILT_IN_LAW_KEYWORDS(4) = [character(len=NAME_LEN) :: 'ELASTIC', &
      'DAMAGEINITIATION', 'DAMAGEEVOLUTION', 'DAMAGESTABILIZATION']
   !> The values of *ELASTIC's TYPE= (Abaqus Keywords Guide), against which an abbreviation is read.
   character(len=NAME_LEN), parameter :: ELASTIC_TYPES(8) = [character(len=NAME_LEN) :: 'ANISOTROPIC', &
      'COUPLEDTRACTION', 'ENGINEERINGCONSTANTS', 'ISOTROPIC', 'LAMINA', 'ORTHOTROPIC', 'SHEAR', 'TRACTION']
   !> Material options (the Abaqus Keywords Guide's material data keywords and their suboptions,
   !> and *INCLUDE, whose lines continue the block): a keyword among them, after *MATERIAL, is still
   !> of that material; any other keyword ends the material's block (so that a *DAMAGE INITIATION
   !> of a *SURFACE INTERACTION is not taken for the material's). Abbreviations of them are read as
   !> those of KEYWORDS_READ are.
   character(len=NAME_LEN), parameter :: MATERIAL_OPTIONS(*) = [character(len=NAME_LEN) :: 'USERMATERIAL', &
      'DEPVAR', 'DENSITY', 'ELASTIC', 'DAMAGEINITIATION', 'DAMAGEEVOLUTION', 'DAMAGESTABILIZATION', 'EXPANSION', &
      'DAMPING', 'CONDUCTIVITY', 'SPECIFICHEAT', 'LATENTHEAT', 'PLASTIC', 'USERDEFINEDFIELD', &
      'USEROUTPUTVARIABLES', 'VISCOELASTIC', 'HYPERELASTIC', 'INELASTICHEATFRACTION', &
      'INCLUDE', 'ACOUSTICMEDIUM', 'ANNEALTEMPERATURE', 'KAPPA', 'DETONATIONPOINT', 'ANISOTROPICHYPERELASTIC', &
      'BIAXIALTESTDATA', 'BRITTLECRACKING', &
      'BRITTLEFAILURE', 'BRITTLESHEAR', 'CAPCREEP', 'CAPHARDENING', 'CAPPLASTICITY', &
      'CASTIRONCOMPRESSIONHARDENING', 'CASTIRONPLASTICITY', 'CASTIRONTENSIONHARDENING', 'CLAYHARDENING', &
      'CLAYPLASTICITY', 'COMBINEDTESTDATA', 'CONCRETE', 'CONCRETECOMPRESSIONDAMAGE', &
      'CONCRETECOMPRESSIONHARDENING', 'CONCRETEDAMAGEDPLASTICITY', 'CONCRETETENSIONDAMAGE', &
      'CONCRETETENSIONSTIFFENING', 'CREEP', 'CREEPSTRAINRATECONTROL', 'CRUSHABLEFOAM', 'CRUSHABLEFOAMHARDENING', &
      'CYCLEDPLASTIC', 'CYCLICHARDENING', 'DEFORMATIONPLASTICITY', 'DIELECTRIC', 'DIFFUSIVITY', 'DRUCKERPRAGER', &
      'DRUCKERPRAGERCREEP', 'DRUCKERPRAGERHARDENING', 'ELECTRICALCONDUCTIVITY', 'EOS', 'EOSCOMPACTION', &
      'FAILSTRAIN', 'FAILSTRESS', 'FAILURERATIOS', 'FLUIDLEAKOFF', 'GAPFLOW', 'GEL', 'HEATGENERATION', &
      'HYPERFOAM', 'HYPOELASTIC', 'JOULEHEATFRACTION', 'LOWDENSITYFOAM', 'MAGNETICPERMEABILITY', 'MOHRCOULOMB', &
      'MOHRCOULOMBHARDENING', 'MOISTURESWELLING', 'MULLINSEFFECT', 'ORNL', 'PERMEABILITY', 'PIEZOELECTRIC', &
      'PLANARTESTDATA', 'POROUSBULKMODULI', &
      'POROUSELASTIC', 'POROUSFAILURECRITERIA', 'POROUSMETALPLASTICITY', 'POTENTIAL', 'RATEDEPENDENT', 'RATIOS', &
      'SHEARFAILURE', 'SHEARRETENTION', 'SHEARTESTDATA', 'SOFTROCKHARDENING', 'SOFTROCKPLASTICITY', 'SOLUBILITY', &
      'SORPTION', 'SWELLING', 'TENSILEFAILURE', 'TENSIONSTIFFENING', 'TRS', 'UNIAXIALTESTDATA', 'VISCOSITY', &
      'VOLUMETRICTESTDATA', 'HYSTERESIS']
   !> The values of *INITIAL CONDITIONS' TYPE= (Abaqus Keywords Guide), against which an
   !> abbreviation is read: only TYPE=SOLUTION, the state variables, is checked.
   character(len=NAME_LEN), parameter :: INITIAL_CONDITION_TYPES(*) = [character(len=NAME_LEN) :: &
      'ACOUSTICSTATICPRESSURE', 'ACTIVATION', 'CONCENTRATION', 'CONTACT', 'CURE', 'DAMAGEINITIATION', 'ENRICHMENT', &
      'FIELD', 'FLUIDPRESSURE', 'HARDENING', 'INITIALGAP', 'IONCONCENTRATION', 'MASSFLOWRATE', &
      'NORMALIZEDCONCENTRATION', 'PLASTICSTRAIN', 'POREPRESSURE', 'POROSITY', 'PRESSURESTRESS', 'RATIO', &
      'REFCOORDINATE', 'RELATIVEDENSITY', 'ROTATINGVELOCITY', 'SATURATION', 'SOLUTION', 'SPECIFICENERGY', &
      'SPUDCANEMBEDMENT', 'STRESS', 'TEMPERATURE', 'VELOCITY', 'VOLUMEFRACTION']
   !> *INITIAL CONDITIONS, TYPE=SOLUTION: the values on an element set's first data line (its label
   !> takes the first of eight fields) and on each line after it (Abaqus Keywords Guide).
   integer, parameter :: SOLUTION_FIRST_LINE_VALUES = 7, SOLUTION_LINE_VALUES = 8
   !> Abaqus keywords that begin as a keyword of KEYWORDS_READ does: an abbreviation that could be
   !> one of them as well is ambiguous (Abaqus refuses it), not one this check reads. (The ones
   !> known here; a start shared with a keyword missing from this list is read as the keyword of
   !> KEYWORDS_READ, and Abaqus then refuses the deck itself.)
   character(len=NAME_LEN), parameter :: KEYWORDS_BESIDE(*) = [character(len=NAME_LEN) :: 'MATRIXASSEMBLE', &
      'MATRIXCHECK', 'MATRIXGENERATE', 'MATRIXINPUT', 'MATRIXOUTPUT', 'MASS', 'MASSDIFFUSION', 'MASSFLOWRATE', &
      'MAPSOLUTION', 'USERDEFINEDFIELD', 'USERELEMENT', 'USEROUTPUTVARIABLES', 'USERPROPERTY', 'DESIGNGRADIENT', &
      'DESIGNPARAMETER', 'DESIGNRESPONSE', 'DETONATIONPOINT', 'DEBOND', 'DEFORMATIONPLASTICITY', &
      'COHESIVEBEHAVIOR', 'INCIDENTWAVE', 'INCIDENTWAVEINTERACTION', 'INCIDENTWAVEINTERACTIONPROPERTY', &
      'INCIDENTWAVEPROPERTY', 'INCREMENTATIONOUTPUT', 'STEADYSTATECRITERIA', 'STEADYSTATEDETECTION', &
      'STEADYSTATEDYNAMICS', 'STEADYSTATENATURALFREQUENCYEXTRACTION', 'STEADYSTATETRANSPORT', 'PARAMETER', &
      'PARAMETERDEPENDENCE', 'PARAMETERSHAPEVARIATION', 'PARAMETERTABLE', 'PARAMETERTABLETYPE', &
      'PARTICLEGENERATOR', 'PARTICLEGENERATORFLOW', 'PARTICLEGENERATORINLET', 'PARTICLEGENERATORMIXTURE', &
      'ASSEMBLEDFASTENER', 'ASSEMBLEDFASTENERPROPERTY', 'NODEFILE', 'NODEOUTPUT', 'NODEPRINT', 'NODERESPONSE', &
      'NODALENERGYRATE', 'NODALTHICKNESS', 'ELEMENTMATRIXOUTPUT', 'ELEMENTOPERATOROUTPUT', 'ELEMENTOUTPUT', &
      'ELEMENTPROPERTIES', 'ELEMENTRECOVERYMATRIX', 'ELEMENTRESPONSE', 'ELFILE', 'ELPRINT', 'ELSET', &
      'SOLUTIONTECHNIQUE', 'SOLVERCONTROLS', 'SHELLGENERALSECTION', 'SHELLTOSOLIDCOUPLING', 'INITIALSTATE']

   !> What the deck says about one material.
   type :: material_type
      character(len=80) :: name = ''
      integer :: user_line = 0                 !! line of *USER MATERIAL (0: none)
      integer :: nconstants = -1               !! CONSTANTS= (-1: not given, or not a whole number)
      character(len=80) :: constants_text = '' !! CONSTANTS= as the deck gives it
      integer :: nread = 0                     !! constants read from the data lines
      logical :: bad_constant = .false.        !! a field of its *USER MATERIAL data is not a number
      character(len=512) :: bad_data = ''      !! the first such field of its data, as reported
      real(dp) :: constants(MAX_CONSTANTS) = 0.0_dp
      integer :: constant_line(MAX_CONSTANTS) = 0       !! the data line of each constant
      integer :: constant_field(MAX_CONSTANTS) = 0      !! its field on that line
      logical :: constant_empty(MAX_CONSTANTS) = .false. !! an empty field (Abaqus reads 0)
      logical :: line_overflow = .false.       !! a data line with more than 8 constants (reported)
      character(len=512) :: last_data_line = '' !! the last *USER MATERIAL data line read (file:line)
      integer :: last_data_fields = 0          !! and its fields
      !> the first *USER MATERIAL data line (file:line) with fewer than 8 fields that another data
      !> line follows ('': none), and its fields: whether Abaqus pads it to 8 is not known here (a note)
      character(len=512) :: short_line = ''
      integer :: short_fields = 0
      integer :: refused = 0                   !! failed checks on its own lines (reported as read)
      logical :: unsymm = .false.
      integer :: depvar = -1                   !! *DEPVAR (-1: none)
      integer :: depvar_line = 0               !! line of *DEPVAR's count (0: none)
      logical :: depvar_bad = .false.          !! *DEPVAR given, but not a count (reported)
      logical :: depvar_empty = .false.        !! *DEPVAR's count an empty field (Abaqus reads 0)
      character(len=80) :: delete_text = ''    !! *DEPVAR's DELETE= as written ('' when absent)
      integer :: delete_line = 0               !! line of the *DEPVAR keyword with DELETE=
      real(dp) :: density = -1.0_dp            !! *DENSITY (-1: none)
      integer :: density_line = 0              !! line of *DENSITY's value (0: none)
      logical :: density_empty = .false.       !! *DENSITY's value an empty field (Abaqus reads 0)
      integer :: line = 0                      !! line of *MATERIAL
      !> the first keyword of Abaqus's built-in cohesive law in its block ('' when none: the
      !> keyword as the deck writes it, with its file and line: file:line: *KEYWORD)
      character(len=512) :: built_in_law = ''
      !> its first *ELASTIC or *HYPERELASTIC, of any type (file:line: *KEYWORD; '' when none): a
      !> material of Abaqus's own whose cohesive sections are not interphase's when it has no
      !> *USER MATERIAL (a brick's potential crack with the built-in law, an adhesive layer)
      character(len=512) :: own_law = ''
      character(len=:), allocatable :: file    !! the file its lines are in (the deck or an *INCLUDE)
      character(len=16), allocatable :: options_seen(:)   !! *USER MATERIAL, *DEPVAR, *DENSITY so far
   end type material_type

   !> One *COHESIVE SECTION (or *SOLID SECTION of a *USER MATERIAL).
   type :: section_type
      integer :: line = 0
      character(len=:), allocatable :: file    !! the file its line is in (the deck or an *INCLUDE)
      !> a *SOLID SECTION (continuum elements) whose material has a *USER MATERIAL: the job's one
      !> UMAT, interphase's, serves it only in the thin-layer mode
      logical :: solid = .false.
      character(len=80) :: elset = '', material = '', response = '', thickness_mode = ''
      character(len=80) :: controls = ''       !! CONTROLS= (a *SECTION CONTROLS' NAME=; '' when none)
      !> that *SECTION CONTROLS' VISCOSITY= as written, with its file and line ('' when none or 0)
      character(len=512) :: viscosity = ''
      real(dp) :: thickness = -1.0_dp
      logical :: thickness_empty = .false.     !! the thickness an empty field (Abaqus reads 0)
      logical :: thickness_read = .false.      !! a thickness (or an empty field) on the data line
      character(len=512) :: bad_data = ''      !! a field of its data line that is not a number
      integer :: refused = 0                   !! failed checks on its own lines (reported as read)
   end type section_type

   !> A data line of *INITIAL CONDITIONS, TYPE=SOLUTION, kept until the deck is read: where one
   !> element set's values end depends on its material's *DEPVAR, which may come later.
   type :: solution_line_type
      character(len=:), allocatable :: file
      integer :: line = 0
      integer :: block = 0                     !! which *INITIAL CONDITIONS it belongs to
      character(len=:), allocatable :: text    !! the line, trailing blanks dropped
   end type solution_line_type

   !> The initial state variables one *INITIAL CONDITIONS, TYPE=SOLUTION gives an element set.
   type :: initial_state_type
      character(len=:), allocatable :: file
      integer :: line = 0                      !! its first data line
      character(len=80) :: elset = ''
      real(dp), allocatable :: values(:)       !! STATEV(1:*DEPVAR) (mm for the slips)
   end type initial_state_type

   character(len=:), allocatable :: path
   integer :: iarg, nfail, status

   if (command_argument_count() < 1) then
      write (error_unit, '(a)') 'interphase-check-deck: error: no deck given'
      call print_usage(error_unit)
      call exit_program(2)
   end if
   ! options first: --help and --version answer alone, anything else starting with '-' is refused
   do iarg = 1, command_argument_count()
      call get_argument(iarg, path)
      if (path == '-h' .or. path == '--help') then
         call print_usage(output_unit)
         call exit_program(0)
      else if (path == '--version') then
         call print_version('interphase-check-deck')
         call exit_program(0)
      else if (len(path) == 0) then
         write (error_unit, '(a,i0,a)') 'interphase-check-deck: error: argument ', iarg, ' is empty (an empty deck name)'
         call print_usage(error_unit)
         call exit_program(2)
      else if (len(path) > 0) then
         if (path(1:1) == '-') then
            write (error_unit, '(a)') 'interphase-check-deck: error: unknown option '//path
            call print_usage(error_unit)
            call exit_program(2)
         end if
      end if
   end do
   nfail = 0
   do iarg = 1, command_argument_count()
      call get_argument(iarg, path)
      call check_deck(path, nfail, status)
      if (status /= 0) call exit_program(2)
   end do
   if (nfail > 0) then
      write (output_unit, '(a,i0,a)') 'interphase-check-deck: ', nfail, ' check(s) failed'
      call exit_program(1)
   end if

contains

   !> Notes on values that PROPS admit but no masonry joint has, which is what a length in m, a
   !> stiffness in Pa/m or a toughness in J/m^2 look like in interphase's units (mm, MPa/mm, N/mm):
   !> the peak tractions K s0 outside 0.001 to 100 MPa (the intact stiffness of the simplified
   !> model's PROPS, or of the built-in table; a custom table's is not known before the run), mu
   !> above 2 (a friction angle in degrees?), and a constant toughness more than 100 times above or
   !> below 1/2 K s0 sf, the fracture energy of the displacement law with the same s0 and sf. Each
   !> '; note: ...', or '' when none applies.
   function units_notes(params) result(text)
      type(law_params_type), intent(in) :: params
      character(len=:), allocatable :: text
      real(dp), parameter :: PEAK_MIN = 1.0e-3_dp, PEAK_MAX = 100.0_dp   ! (MPa)
      real(dp), parameter :: MU_MAX = 2.0_dp, TOUGHNESS_RATIO = 100.0_dp
      character(len=2), parameter :: MODE(2) = ['_N', '_T']
      character(len=3), parameter :: ROMAN(2) = ['I  ', 'II ']
      type(coefficient_set_type) :: c, unused_dc
      real(dp) :: k(2), s0(2), sf(2), gc(2), peak, energy
      integer :: status, i
      text = ''
      s0 = [params%s0_n, params%s0_t]
      sf = [params%sf_n, params%sf_t]
      gc = [params%gc_i, params%gc_ii]
      call coefficient_values_at(params, 0.0_dp, c, unused_dc, status)
      if (status == STATUS_OK) then
         k = [c%k_n, c%k_t]
         do i = 1, 2
            peak = k(i)*s0(i)
            if (peak < PEAK_MIN .or. peak > PEAK_MAX) text = text//'; note: the peak traction K'//MODE(i)// &
               ' s0'//MODE(i)//' = '//real_text(peak, 3)//' MPa lies outside 0.001 to 100 MPa, where masonry '// &
               'joints are: check the units (mm, MPa/mm)'
            if (params%damage_law == DAMAGE_FRACTURE .and. params%rcurve == RCURVE_CONSTANT) then
               energy = 0.5_dp*k(i)*s0(i)*sf(i)
               if (gc(i) > TOUGHNESS_RATIO*energy .or. gc(i) < energy/TOUGHNESS_RATIO) text = text// &
                  '; note: G_c'//trim(ROMAN(i))//' = '//real_to_string(gc(i))//' N/mm is '// &
                  real_text(gc(i)/energy, 2)//' x (1/2) K'//MODE(i)//' s0'//MODE(i)//' sf'//MODE(i)//' = '// &
                  real_text(energy, 3)//' N/mm, the fracture energy of the displacement law with these s0 and sf: '// &
                  'check the units (N/mm, and 1 J/m^2 = 0.001 N/mm)'
            end if
         end do
      end if
      if (params%mu > MU_MAX) text = text//'; note: mu = '//real_to_string(params%mu)//' is above 2, beyond '// &
         'masonry joints (about 0.3 to 1.2): a friction angle in degrees? mu is its tangent'
   end function units_notes

   !> How to call the program.
   subroutine print_usage(unit)
      integer, intent(in) :: unit                 !! where to print
      write (unit, '(a)') 'usage: interphase-check-deck DECK.inp [MORE.inp ...]', &
         '       interphase-check-deck --help | --version', &
         '  Checks every *COHESIVE SECTION of an Abaqus deck that uses interphase (and every *SOLID SECTION', &
         '  of a *USER MATERIAL: the thin-layer mode): RESPONSE, THICKNESS,', &
         '  *USER MATERIAL constants decoded as interphase PROPS, *DEPVAR (and its DELETE=), UNSYMM,', &
         '  *DENSITY (Explicit), *INITIAL CONDITIONS, TYPE=SOLUTION (initial state variables), and no', &
         '  keyword of Abaqus''s built-in cohesive law (*ELASTIC, TYPE=TRACTION, *DAMAGE ...) beside it.', &
         '  *INCLUDE files are read where they stand (a relative INPUT= from the deck''s folder, as the job''s).', &
         '  Exit status: 0 all checks pass, 1 a check failed, 2 a file cannot be read.', &
         '  Documented in drivers/README.md and docs/abaqus.md.'
   end subroutine print_usage

   !> Read one deck (with its *INCLUDE files) and check its sections; nfail counts the failed checks.
   subroutine check_deck(deck, nfail, status)
      character(len=*), intent(in) :: deck
      integer, intent(inout) :: nfail
      integer, intent(out) :: status     !! 0, or 2 when the file cannot be read

      type(material_type), allocatable :: materials(:)
      type(section_type), allocatable :: sections(:)
      type(text_file_type) :: file
      !> the file being read (the deck, or an *INCLUDE file in it: messages name it) and the files
      !> that include it, outermost first, with their paths
      character(len=:), allocatable :: path
      type(include_frame_type) :: including(MAX_INCLUDE_DEPTH)
      integer :: depth
      character(len=LINE_LEN) :: line
      !> a line read ahead (after a keyword line that ends in a comma) and its number
      character(len=LINE_LEN) :: held
      integer :: held_lineno, held_length
      logical :: have_held
      character(len=MESSAGE_LEN) :: message
      character(len=80) :: keyword, field, repeated
      character(len=:), allocatable :: ambiguous     !! an ambiguous abbreviation's reading, or ''
      character(len=:), allocatable :: keyword_at    !! file:line: *KEYWORD of a keyword line
      character(len=80) :: keyword_text        !! the keyword as the deck writes it (for messages)
      !> the keyword before an *INCLUDE line, which the included data lines continue
      character(len=80) :: previous_keyword, previous_keyword_text
      integer :: previous_data_lines
      character(len=512) :: bad_text           !! a data field that is not a number, as reported
      character(len=LINE_LEN) :: bad_item      !! that field
      character(len=32) :: bad_why             !! why it is not (parse_real)
      character(len=80), allocatable :: parameter_names(:)
      character(len=LINE_LEN), allocatable :: parameter_values(:)
      real(dp) :: values(LINE_LEN + 1)
      logical :: empty(LINE_LEN + 1)           !! which of values are empty fields (read as 0)
      integer :: ios, lineno, nvalues, k, current, data_lines, i, bad_field, length
      integer :: nfail_line                    !! nfail before the line (its failures are attributed)
      character(len=:), allocatable :: label
      logical :: explicit, opened
      logical :: in_material                   !! the keyword lines read are a material's options
      !> the *SECTION CONTROLS with a VISCOSITY= other than 0: their names and, for each, the
      !> value as written with its file and line
      character(len=80), allocatable :: controls_names(:)
      character(len=512), allocatable :: controls_viscosity(:)
      real(dp) :: viscosity_value
      logical :: viscosity_ok
      logical :: already_open          !! an *INCLUDE's file open already (in a file that includes it)
      !> the first step procedure of each solver (line and keyword): one analysis runs one solver
      integer :: explicit_line, standard_line
      logical, allocatable :: keep(:)          !! the sections interphase serves
      logical, allocatable :: unused(:)        !! the materials with a *USER MATERIAL no section uses
      logical :: calculix                      !! a section of a CalculiX-named user material was seen
      !> a section keyword this check does not read (*SHELL SECTION, a composite *SOLID SECTION,
      !> ...) was seen, and the materials such sections name by MATERIAL=
      logical :: other_sections
      character(len=80), allocatable :: other_materials(:)
      integer :: keyword_lines                 !! keyword lines read
      character(len=:), allocatable :: explicit_file, standard_file
      character(len=:), allocatable :: include_input !! an *INCLUDE's INPUT= as written
      character(len=:), allocatable :: include_path  !! the file it names, as opened
      character(len=80) :: standard_keyword
      !> the data lines of *INITIAL CONDITIONS, TYPE=SOLUTION, the one being read (0: none) and
      !> the number read so far, and the element sets' values read from them
      type(solution_line_type), allocatable :: solution_lines(:), grown_lines(:)
      integer :: solution_block, solution_blocks, nsolution_lines, nstates
      type(initial_state_type), allocatable :: states(:)

      allocate (materials(0), sections(0), solution_lines(64), other_materials(0))
      allocate (controls_names(0), controls_viscosity(0))
      in_material = .false.
      keyword_at = ''
      other_sections = .false.
      calculix = .false.
      solution_block = 0
      solution_blocks = 0
      nsolution_lines = 0
      path = deck
      depth = 0
      explicit_file = ''
      standard_file = ''
      ! the readers' bounded line reader (interphase_text_input): lines and file size are limited,
      ! so that no file (/dev/zero, a line without end) is read forever
      call open_text_file(path, file, opened, message)
      if (.not. opened) then
         write (error_unit, '(a)') 'interphase-check-deck: '//tried_path(path)//': '//trim(message)
         status = 2
         return
      end if
      status = 0
      explicit = .false.
      explicit_line = 0
      standard_line = 0
      standard_keyword = ''
      keyword = ''
      keyword_text = ''
      ! (set before the loop: gcc -O3 reports their lengths as maybe uninitialised otherwise)
      label = ''
      include_input = ''
      include_path = ''
      current = 0
      data_lines = 0
      lineno = 0
      keyword_lines = 0
      have_held = .false.
      do
         if (have_held) then
            line = held
            lineno = held_lineno
            length = held_length
            have_held = .false.
         else
            if (.not. next_line(file, path, line, lineno, status, length)) then
               if (depth == 0) exit
               ! the end of an *INCLUDE file: back to the file that includes it, after its
               ! *INCLUDE line
               call close_text_file(file)
               file = including(depth)%file
               path = including(depth)%path
               have_held = including(depth)%have_held
               if (have_held) then
                  held = including(depth)%held
                  held_lineno = including(depth)%held_lineno
                  held_length = including(depth)%held_length
               end if
               depth = depth - 1
               cycle
            end if
         end if
         if (status /= 0) return
         if (len_trim(line) == 0 .or. line(1:min(2, len(line))) == '**') cycle
         ! the failed checks of this line (and its continuations), for its material or section
         nfail_line = nfail
         if (length > ABAQUS_LINE_LEN) call record_failure(too_long(path, lineno, length), nfail)
         if (line(1:1) == '*') then
            ! a keyword line that ends in a comma continues on the next line (Abaqus' input syntax
            ! rules): the continuation's parameters join this line's
            do while (line(len_trim(line):len_trim(line)) == ',')
               if (.not. next_line(file, path, held, held_lineno, status, held_length)) exit
               if (status /= 0) return
               if (len_trim(held) == 0) cycle
               if (held(1:min(2, len(held))) == '**') cycle
               if (held(1:1) == '*') then
                  ! a new keyword: the comma ended this line's parameters
                  have_held = .true.
                  exit
               end if
               if (held_length > ABAQUS_LINE_LEN) call record_failure(too_long(path, held_lineno, held_length), nfail)
               if (len_trim(line) + 1 + len_trim(held) > LINE_LEN) then
                  write (error_unit, '(a,i0,a,i0,a)') 'interphase-check-deck: '//tried_path(path)//':', held_lineno, &
                     ': keyword line with its continuations longer than ', LINE_LEN, ' characters'
                  call close_text_file(file)
                  status = 2
                  return
               end if
               line = trim(line)//' '//trim(held)
            end do
            keyword_lines = keyword_lines + 1
            previous_keyword = keyword
            previous_keyword_text = keyword_text
            previous_data_lines = data_lines
            keyword_text = adjustl(text_before(line(2:), ','))
            ! the keyword, an abbreviation read as the keyword it abbreviates
            keyword = resolve_name(upper_compact(text_before(line(2:), ',')), [KEYWORDS_READ, KEYWORDS_BESIDE, &
               MATERIAL_OPTIONS], ambiguous, '*')
            if (len(ambiguous) > 0) then
               call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' could be '// &
                  ambiguous//': Abaqus refuses an abbreviation that is not unique; spell the keyword out', nfail)
            end if
            data_lines = 0
            ! its parameters, abbreviations read as the names they abbreviate
            call keyword_parameters(line, keyword, parameter_names, parameter_values, repeated, ambiguous)
            if (len(ambiguous) > 0) then
               call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//': '//ambiguous// &
                  ': Abaqus refuses an abbreviation that is not unique; spell the parameter out', nfail)
            end if
            ! *USER MATERIAL takes its own parameters only: any other one Abaqus refuses
            if (trim(keyword) == 'USERMATERIAL') then
               do k = 1, size(parameter_names)
                  if (.not. any(USER_MATERIAL_PARAMETERS == parameter_names(k))) then
                     call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//': '// &
                        trim(parameter_names(k))//' is not a parameter of *USER MATERIAL (CONSTANTS, EFFMOD, '// &
                        'HYBRID FORMULATION, TYPE, UNSYMM): Abaqus refuses it', nfail)
                  end if
               end do
            end if
            ! a material's block: *MATERIAL and the material options after it (read before a
            ! thermal *USER MATERIAL is renamed below: it is a material option too)
            if (trim(keyword) == 'MATERIAL') then
               in_material = .true.
            else if (.not. any(MATERIAL_OPTIONS == keyword)) then
               in_material = .false.
            end if
            ! *USER MATERIAL, TYPE=THERMAL is a UMATHT's (heat transfer), not interphase's: its
            ! constants are neither decoded nor counted as the material's *USER MATERIAL
            if (trim(keyword) == 'USERMATERIAL') then
               if (parameter_choice(parameter_names, parameter_values, 'TYPE', &
                  [character(len=NAME_LEN) :: 'MECHANICAL', 'THERMAL']) == 'THERMAL') keyword = 'USERMATERIAL,THERMAL'
            end if
            ! a parameter given twice on a keyword line: which one counts is not for us to guess
            if (len_trim(repeated) > 0) then
               call record_failure(path//':'//int_to_string(lineno)//': *'//trim(text_before(line(2:), ','))//': parameter '// &
                  trim(repeated)//' given twice: "'//clip_text(trim(line))//'"', nfail)
            end if
            ! a law of Abaqus's own in a material (its first *ELASTIC or *HYPERELASTIC), and the
            ! built-in cohesive law's keywords there (checked with the sections of a material that has
            ! interphase's *USER MATERIAL): each the first one, as file:line: *KEYWORD[, TYPE=...]
            if (in_material .and. current > 0) then
               keyword_at = path//':'//int_to_string(lineno)//': *'//trim(clip_text(trim(text_before(line(2:), ','))))
               if (len_trim(materials(current)%own_law) == 0 .and. &
                   (trim(keyword) == 'ELASTIC' .or. trim(keyword) == 'HYPERELASTIC')) materials(current)%own_law = keyword_at
               if (len_trim(materials(current)%built_in_law) == 0 .and. any(BUILT_IN_LAW_KEYWORDS == keyword)) then
                  if (trim(keyword) /= 'ELASTIC') then
                     materials(current)%built_in_law = keyword_at
                  else if (any(parameter_choice(parameter_names, parameter_values, 'TYPE', ELASTIC_TYPES) == &
                           [character(len=NAME_LEN) :: 'TRACTION', 'COUPLEDTRACTION'])) then
                     materials(current)%built_in_law = keyword_at//', TYPE='// &
                        parameter_value(parameter_names, parameter_values, 'TYPE')
                  end if
               end if
            end if
            select case (trim(keyword))
            case ('SECTIONCONTROLS')
               ! Abaqus's viscous regularisation of its own damage models (VISCOSITY=)
               field = label_value(parameter_value(parameter_names, parameter_values, 'NAME'))
               if (len_trim(field) > 0 .and. len(parameter_value(parameter_names, parameter_values, 'VISCOSITY')) > 0) then
                  call parse_real(parameter_value(parameter_names, parameter_values, 'VISCOSITY'), viscosity_value, &
                     viscosity_ok, bad_why)
                  if (.not. viscosity_ok .or. abs(viscosity_value) > 0.0_dp) then
                     controls_names = [character(len=80) :: controls_names, field]
                     controls_viscosity = [character(len=512) :: controls_viscosity, &
                        'VISCOSITY='//parameter_value(parameter_names, parameter_values, 'VISCOSITY')// &
                        ' (*SECTION CONTROLS, NAME='//trim(field)//' at '//path//':'//int_to_string(lineno)//')']
                  end if
               end if
            case ('MATERIAL')
               label = label_value(parameter_value(parameter_names, parameter_values, 'NAME'))
               if (len(label) == 0) then
                  call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' without NAME=: '// &
                     'Abaqus requires the material''s name (a section refers to it by MATERIAL=)', nfail)
               else
                  do k = 1, size(materials)
                     if (materials(k)%name == label) then
                        call record_failure(path//':'//int_to_string(lineno)//': *MATERIAL, NAME='// &
                           trim(materials(k)%name)//' defined a second time (first at '// &
                           line_in(path, materials(k)%file, materials(k)%line)//')', nfail)
                     end if
                  end do
               end if
               ! (a material without a name is kept, that the options after it are not read as
               ! another material's; no section can refer to it)
               materials = [materials, material_type(name=label, line=lineno, file=path, &
                  options_seen=[character(len=16) ::])]
               current = size(materials)
            case ('USERMATERIAL', 'DEPVAR', 'DENSITY')
               if (current > 0) then
                  if (any(materials(current)%options_seen == trim(keyword))) then
                     call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword)//' given twice in '// &
                        '*MATERIAL, NAME='//trim(materials(current)%name), nfail)
                  end if
                  materials(current)%options_seen = [character(len=16) :: materials(current)%options_seen, &
                     trim(keyword)]
               end if
            end select
            ! (the data lines after an *INCLUDE line continue the keyword before it)
            if (trim(keyword) /= 'INCLUDE') solution_block = 0
            ! a section of other elements (*SHELL SECTION, *MEMBRANE SECTION, a composite *SOLID
            ! SECTION, whose materials are on its data lines, ...): its material is used, if not by
            ! interphase (the job's one UMAT would serve it)
            k = len_trim(keyword)
            if (k > 7) then
               if (keyword(k - 6:k) == 'SECTION' .and. trim(keyword) /= 'COHESIVESECTION' .and. &
                  (trim(keyword) /= 'SOLIDSECTION' .or. any(parameter_names == 'COMPOSITE'))) then
                  other_sections = .true.
                  field = label_value(parameter_value(parameter_names, parameter_values, 'MATERIAL'))
                  if (len_trim(field) > 0) other_materials = [character(len=80) :: other_materials, field]
               end if
            end if
            select case (trim(keyword))
            case ('INCLUDE')
               ! its lines are read where it stands, as Abaqus reads them; a relative INPUT= from
               ! the deck's folder, in an included file too (Abaqus takes it from the directory the
               ! job runs in, not from the including file's: the job runs in the deck's folder)
               include_input = parameter_value(parameter_names, parameter_values, 'INPUT')
               include_path = include_file(deck, include_input)
               ! (a file open already, in the deck or a file that includes this one, is a loop of
               ! *INCLUDEs whatever its name's spelling, ./deck.inp for deck.inp: where the
               ! run-time library tells, as gfortran's does, rather than 'cannot open: already opened')
               already_open = .false.
               ios = 0
               if (len(include_path) > 0) inquire (file=include_path, opened=already_open, iostat=ios)
               if (ios /= 0) already_open = .false.
               if (len(include_path) == 0) then
                  call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' without '// &
                     'INPUT=: Abaqus requires the file to include', nfail)
               else if (include_path == path .or. already_open .or. &
                  any([(including(k)%path == include_path, k = 1, depth)])) then
                  call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//', INPUT='// &
                     include_input//': the file includes itself (directly or through the files it includes): not read', &
                     nfail)
               else if (depth == MAX_INCLUDE_DEPTH) then
                  call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//', INPUT='// &
                     include_input//': *INCLUDE files nested more than '//int_to_string(MAX_INCLUDE_DEPTH)// &
                     ' deep: not read', nfail)
               else
                  including(depth + 1)%file = file
                  call open_text_file(include_path, file, opened, message)
                  if (opened) then
                     depth = depth + 1
                     including(depth)%path = path
                     path = include_path
                     ! (a keyword line read ahead of the included file's lines comes after them)
                     including(depth)%have_held = have_held
                     if (have_held) then
                        including(depth)%held = held
                        including(depth)%held_lineno = held_lineno
                        including(depth)%held_length = held_length
                        have_held = .false.
                     end if
                  else
                     file = including(depth + 1)%file
                     call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//', INPUT='// &
                        include_input//': cannot read '//tried_path(include_path)//': '//trim(message)// &
                        ' (Abaqus would stop here too)', nfail)
                  end if
               end if
               ! an *INCLUDE does not end the keyword before it: data lines in the file are its own
               ! (*USER MATERIAL, CONSTANTS=9 with its constants in a file of their own)
               keyword = previous_keyword
               keyword_text = previous_keyword_text
               data_lines = previous_data_lines
            case ('USERMATERIAL')
               if (current > 0) then
                  materials(current)%user_line = lineno
                  materials(current)%unsymm = any(parameter_names == 'UNSYMM')
                  field = parameter_value(parameter_names, parameter_values, 'CONSTANTS')
                  materials(current)%constants_text = field
                  ! a whole number: every character a digit (-1, reported later, otherwise)
                  materials(current)%nconstants = -1
                  if (len_trim(field) > 0 .and. len_trim(field) <= 9) then
                     if (verify(trim(field), '0123456789') == 0) then
                        read (field, '(i9)', iostat=ios) materials(current)%nconstants
                        if (ios /= 0) materials(current)%nconstants = -1
                     end if
                  end if
               end if
            case ('DEPVAR')
               ! the element deletion variable (checked with the section: interphase's slots hold 0)
               if (current > 0 .and. any(parameter_names == 'DELETE')) then
                  materials(current)%delete_text = parameter_value(parameter_names, parameter_values, 'DELETE')
                  materials(current)%delete_line = lineno
               end if
            case ('COHESIVESECTION')
               do k = 1, size(parameter_names)
                  if (.not. any(COHESIVE_SECTION_PARAMETERS == parameter_names(k))) &
                     write (output_unit, '(a)') path//':'//int_to_string(lineno)//': note: *'//trim(keyword_text)// &
                        ': '//trim(parameter_names(k))//' is not a parameter of *COHESIVE SECTION this check knows '// &
                        '(CONTROLS, ELSET, HALF, MATERIAL, ORIENTATION, RESPONSE, STACK DIRECTION, SYMMETRIC, THICKNESS): '// &
                        'Abaqus refuses a misspelt one'
               end do
               ! ELSET= and MATERIAL= are required (Abaqus Keywords Guide); RESPONSE= is checked
               ! with the section
               do k = 1, 2
                  field = trim(merge('ELSET   ', 'MATERIAL', k == 1))
                  if (len(label_value(parameter_value(parameter_names, parameter_values, trim(field)))) == 0) &
                     call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' without '// &
                        trim(field)//'=: Abaqus requires it', nfail)
               end do
               sections = [sections, section_type(line=lineno, file=path, &
                  elset=label_value(parameter_value(parameter_names, parameter_values, 'ELSET')), &
                  material=label_value(parameter_value(parameter_names, parameter_values, 'MATERIAL')), &
                  response=parameter_choice(parameter_names, parameter_values, 'RESPONSE', &
                     [character(len=NAME_LEN) :: 'TRACTIONSEPARATION', 'CONTINUUM', 'GASKET']), &
                  thickness_mode=parameter_choice(parameter_names, parameter_values, 'THICKNESS', &
                     [character(len=NAME_LEN) :: 'GEOMETRY', 'SPECIFIED']), &
                  controls=label_value(parameter_value(parameter_names, parameter_values, 'CONTROLS')))]
               ! (THICKNESS= left out: Abaqus's default, checked with the section)
               if (.not. any(parameter_names == 'THICKNESS')) sections(size(sections))%thickness_mode = 'DEFAULT'
            case ('INITIALCONDITIONS')
               ! the state variables' initial values: read after the deck (read_initial_states)
               field = parameter_choice(parameter_names, parameter_values, 'TYPE', INITIAL_CONDITION_TYPES)
               if (len_trim(field) > 0 .and. .not. any(INITIAL_CONDITION_TYPES == field)) then
                  ! (a type this check does not know, or a misspelt one: TYPE=SOLUTON would leave the
                  ! state variables unchecked without a word)
                  write (output_unit, '(a)') path//':'//int_to_string(lineno)//': note: *'//trim(keyword_text)// &
                     ', TYPE='//parameter_value(parameter_names, parameter_values, 'TYPE')//': not a type this check '// &
                     'knows (TYPE=SOLUTION gives the state variables, which it checks): not checked'
               else if (field == 'SOLUTION') then
                  if (any(parameter_names == 'USER')) then
                     write (output_unit, '(a)') path//':'//int_to_string(lineno)//': note: *'//trim(keyword_text)// &
                        ', TYPE=SOLUTION, USER: the user subroutine SDVINI gives the state variables, which this '// &
                        'check cannot see: interphase''s slots must start as docs/abaqus.md says (STATEV)'
                  else if (any(parameter_names == 'REBAR')) then
                     continue     ! rebars' state variables: not interphase's (a cohesive element has no rebar)
                  else if (len(parameter_value(parameter_names, parameter_values, 'INPUT')) > 0) then
                     write (output_unit, '(a)') path//':'//int_to_string(lineno)//': note: *'//trim(keyword_text)// &
                        ', TYPE=SOLUTION, INPUT='//parameter_value(parameter_names, parameter_values, 'INPUT')// &
                        ': the state variables in that file are not checked'
                  else
                     solution_blocks = solution_blocks + 1
                     solution_block = solution_blocks
                  end if
               end if
            case ('DYNAMIC', 'DYNAMICTEMPERATURE-DISPLACEMENT')
               ! (an explicit dynamic step, with or without the temperatures: Abaqus/Explicit)
               if (any(parameter_names == 'EXPLICIT')) then
                  explicit = .true.
                  if (explicit_line == 0) then
                     explicit_line = lineno
                     explicit_file = path
                  end if
               else if (standard_line == 0) then
                  standard_line = lineno
                  standard_file = path
                  standard_keyword = keyword_text
               end if
            case ('STATIC', 'VISCO', 'FREQUENCY', 'BUCKLE', 'GEOSTATIC', 'SOILS', 'HEATTRANSFER', &
               'COUPLEDTEMPERATURE-DISPLACEMENT', 'STEADYSTATEDYNAMICS', 'MODALDYNAMIC', 'RIKS')
               ! an Abaqus/Standard procedure
               if (standard_line == 0) then
                  standard_line = lineno
                  standard_file = path
                  standard_keyword = keyword_text
               end if
            case ('STEP', 'PART', 'ASSEMBLY', 'INSTANCE', 'NODE', 'ELEMENT', 'SOLIDSECTION', 'SHELLSECTION')
               current = 0
               ! a solid section is checked when its material turns out to have a *USER MATERIAL
               ! (with the failed checks of its line so far: it is then not said to be ok)
               if (trim(keyword) == 'SOLIDSECTION') then
                  if (len(label_value(parameter_value(parameter_names, parameter_values, 'MATERIAL'))) > 0) &
                     sections = [sections, section_type(line=lineno, file=path, solid=.true., &
                        elset=label_value(parameter_value(parameter_names, parameter_values, 'ELSET')), &
                        material=label_value(parameter_value(parameter_names, parameter_values, 'MATERIAL')), &
                        refused=nfail - nfail_line)]
               end if
            end select
            call attribute_failures(nfail - nfail_line, keyword, current, materials, sections)
            cycle
         end if
         ! a data line of the current keyword
         data_lines = data_lines + 1
         if (trim(keyword) == 'INITIALCONDITIONS' .and. solution_block > 0) then
            ! (the array doubled when full: a deck may give the state of thousands of elements)
            if (nsolution_lines == size(solution_lines)) then
               allocate (grown_lines(2*size(solution_lines)))
               grown_lines(1:nsolution_lines) = solution_lines(1:nsolution_lines)
               call move_alloc(grown_lines, solution_lines)
            end if
            nsolution_lines = nsolution_lines + 1
            solution_lines(nsolution_lines)%file = path
            solution_lines(nsolution_lines)%line = lineno
            solution_lines(nsolution_lines)%block = solution_block
            solution_lines(nsolution_lines)%text = trim(line)
            cycle
         end if
         call parse_numbers(line, values, empty, nvalues, bad_field, bad_item, bad_why)
         ! at most eight constants on one *USER MATERIAL data line (Abaqus Keywords Guide)
         if ((trim(keyword) == 'USERMATERIAL' .or. trim(keyword) == 'USERMATERIAL,THERMAL') .and. &
             bad_field == 0 .and. nvalues > CONSTANTS_PER_LINE) then
            call record_failure(path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' data line: '// &
               int_to_string(nvalues)//' constants on one line, but Abaqus reads at most '// &
               int_to_string(CONSTANTS_PER_LINE)//' per line: put the rest on the next line (fields are '// &
               'separated by commas: a decimal comma splits a number in two; write 0.75, not 0,75)', nfail)
            if (current > 0 .and. trim(keyword) == 'USERMATERIAL') materials(current)%line_overflow = .true.
         end if
         select case (trim(keyword))
         case ('USERMATERIAL', 'DEPVAR', 'DENSITY', 'COHESIVESECTION')
            ! the data read here are numbers (every line of *USER MATERIAL, the first line of the
            ! others): a field that is not one is named by the check of the sections that use it,
            ! and a material's constants are then not decoded (nor CONSTANTS= compared)
            if (bad_field > 0 .and. (trim(keyword) == 'USERMATERIAL' .or. data_lines == 1)) then
               bad_text = path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' data line: field '// &
                  int_to_string(bad_field)//" '"//clip_text(trim(adjustl(bad_item)))//"' is "//trim(bad_why)
               if (trim(keyword) == 'COHESIVESECTION') then
                  if (size(sections) > 0) then
                     if (len_trim(sections(size(sections))%bad_data) == 0) sections(size(sections))%bad_data = bad_text
                  end if
               else if (current > 0) then
                  if (len_trim(materials(current)%bad_data) == 0) materials(current)%bad_data = bad_text
                  if (trim(keyword) == 'USERMATERIAL') materials(current)%bad_constant = .true.
               end if
            end if
         end select
         select case (trim(keyword))
         case ('USERMATERIAL')
            if (current > 0) then
               associate (mat => materials(current))
                  ! a line of fewer than 8 constants with another after it
                  if (data_lines > 1 .and. len_trim(mat%short_line) == 0 .and. &
                      mat%last_data_fields < CONSTANTS_PER_LINE) then
                     mat%short_line = mat%last_data_line
                     mat%short_fields = mat%last_data_fields
                  end if
                  mat%last_data_line = path//':'//int_to_string(lineno)
                  mat%last_data_fields = nvalues
                  do k = 1, nvalues
                     mat%nread = mat%nread + 1
                     if (mat%nread <= MAX_CONSTANTS) then
                        mat%constants(mat%nread) = values(k)
                        mat%constant_line(mat%nread) = lineno
                        mat%constant_field(mat%nread) = k
                        mat%constant_empty(mat%nread) = empty(k)
                     end if
                  end do
               end associate
            end if
         case ('DEPVAR')
            if (current > 0 .and. data_lines == 1) then
               if (bad_field > 0) then
                  materials(current)%depvar_bad = .true.
               else if (nvalues >= 1) then
                  if (values(1) >= 0.0_dp .and. values(1) <= 1.0e9_dp .and. &
                      .not. abs(values(1) - aint(values(1))) > 0.0_dp) then
                     materials(current)%depvar = nint(values(1))
                     materials(current)%depvar_line = lineno
                     materials(current)%depvar_empty = empty(1)
                  else
                     materials(current)%depvar_bad = .true.
                     if (len_trim(materials(current)%bad_data) == 0) materials(current)%bad_data = &
                        path//':'//int_to_string(lineno)//': *'//trim(keyword_text)//' '// &
                        real_to_string(values(1))//' is not a count (a whole number >= 0)'
                  end if
               end if
            end if
         case ('DENSITY')
            if (current > 0 .and. data_lines == 1 .and. nvalues >= 1) then
               materials(current)%density = values(1)
               materials(current)%density_line = lineno
               materials(current)%density_empty = empty(1)
            end if
         case ('COHESIVESECTION')
            if (data_lines == 1 .and. nvalues >= 1) then
               sections(size(sections))%thickness = values(1)
               sections(size(sections))%thickness_empty = empty(1)
               sections(size(sections))%thickness_read = .true.
            end if
         end select
         call attribute_failures(nfail - nfail_line, keyword, current, materials, sections)
      end do
      call close_text_file(file)

      if (explicit_line > 0 .and. standard_line > 0) then
         call record_failure(deck//': the deck has an Abaqus/Explicit step (*DYNAMIC, EXPLICIT at '// &
            line_in(deck, explicit_file, explicit_line)//') and an Abaqus/Standard one (*'//trim(standard_keyword)// &
            ' at '//line_in(deck, standard_file, standard_line)//'): one analysis runs one solver (a Standard result '// &
            'goes to Explicit, or back, by an import between two decks)', nfail)
      end if
      ! a solid section is interphase's when its material has a (mechanical) *USER MATERIAL: one
      ! UMAT serves the job; the others (the bricks' *ELASTIC) are not
      allocate (keep(size(sections)))
      do i = 1, size(sections)
         keep(i) = .not. sections(i)%solid
         do k = 1, size(materials)
            if (materials(k)%name == sections(i)%material .and. materials(k)%user_line /= 0) keep(i) = .true.
         end do
         ! CalculiX names the material of an Abaqus-style UMAT ABAQUS... or @... (a library), and
         ! reads *USER MATERIAL otherwise (a temperature after the constants): not checked here
         if (keep(i) .and. sections(i)%solid) then
            if (index(sections(i)%material, 'ABAQUS') == 1 .or. index(sections(i)%material, '@') == 1) then
               keep(i) = .false.
               calculix = .true.
               write (output_unit, '(a)') sections(i)%file//':'//int_to_string(sections(i)%line)//': note: '// &
                  '*SOLID SECTION, ELSET='//trim(sections(i)%elset)//': material '//trim(sections(i)%material)// &
                  ' is named as CalculiX names a user material (ABAQUS..., @...): a CalculiX deck, not checked '// &
                  '(docs/calculix.md)'
            end if
         end if
      end do
      ! a *USER MATERIAL that no section uses (a misspelt section keyword leaves it so); none of it
      ! is checked
      allocate (unused(size(materials)))
      do k = 1, size(materials)
         unused(k) = materials(k)%user_line /= 0 .and. .not. any(sections%material == materials(k)%name) .and. &
            .not. any(other_materials == materials(k)%name)
      end do
      sections = pack(sections, keep)
      if (size(sections) == 0) then
         if (keyword_lines == 0) then
            call record_failure(deck//': no keyword line (*HEADING, *MATERIAL, ...): not an Abaqus input deck', nfail)
         else if (any(unused) .and. .not. (calculix .or. other_sections)) then
            do k = 1, size(materials)
               if (unused(k)) call record_failure(materials(k)%file//':'//int_to_string(materials(k)%user_line)// &
                  ': *USER MATERIAL of '//trim(materials(k)%name)//', but no *COHESIVE SECTION or *SOLID SECTION '// &
                  'uses it: nothing of interphase''s would run (a misspelt section keyword? a material library is '// &
                  'checked with the deck that includes it)', nfail)
            end do
         else
            write (output_unit, '(a)') deck//': no *COHESIVE SECTION, and no *SOLID SECTION of an Abaqus *USER '// &
               'MATERIAL: nothing for interphase to check (CalculiX decks are not checked: docs/abaqus.md)'
         end if
         return
      end if
      do k = 1, size(materials)
         if (unused(k)) write (output_unit, '(a)') materials(k)%file//':'//int_to_string(materials(k)%user_line)// &
            ': note: *USER MATERIAL of '//trim(materials(k)%name)//': no section uses it (not checked)'
      end do
      call read_initial_states(solution_lines, nsolution_lines, sections, materials, states, nstates, nfail)
      ! the section controls' viscosity of each cohesive section (a note: it is not interphase's)
      do i = 1, size(sections)
         if (len_trim(sections(i)%controls) == 0) cycle
         do k = 1, size(controls_names)
            if (controls_names(k) == sections(i)%controls) sections(i)%viscosity = controls_viscosity(k)
         end do
      end do
      do i = 1, size(sections)
         call check_section(deck, sections(i), materials, explicit, states(1:nstates), nfail)
      end do

   end subroutine check_deck

   !> The checks of one cohesive section and its material; one line of output, plus one line per
   !> failed check.
   subroutine check_section(path, section, materials, explicit, states, nfail)
      character(len=*), intent(in) :: path
      type(section_type), intent(in) :: section
      type(material_type), intent(in) :: materials(:)
      logical, intent(in) :: explicit
      type(initial_state_type), intent(in) :: states(:)   !! the deck's initial state variables
      integer, intent(inout) :: nfail

      type(law_params_type) :: params
      character(len=MESSAGE_LEN) :: message
      character(len=:), allocatable :: where, solver, summary, notes, hook, section_where, why, maker
      integer :: m, k, status, nfail_before, depvar_needed, normal, nm, nconstants, nempty
      logical :: decoded       !! the material's constants decode (params holds them)
      logical :: refused       !! its own or its material's lines have failed checks (named as read)
      real(dp) :: t_layer

      nfail_before = nfail
      status = -1
      solver = merge('Abaqus/Explicit (VUMAT)', 'Abaqus/Standard (UMAT) ', explicit)
      where = section%file//':'//int_to_string(section%line)//': *'// &
         trim(merge('SOLID SECTION   ', 'COHESIVE SECTION', section%solid))//', ELSET='//trim(section%elset)
      ! a cohesive section of a material with a law of Abaqus's own (*ELASTIC, of any type) and no
      ! *USER MATERIAL is not interphase's (the built-in cohesive law of a brick's potential crack,
      ! an adhesive layer): named, not checked
      ! (a material defined twice is named as such, and its section checked as interphase's)
      if (.not. section%solid .and. len_trim(section%material) > 0 .and. &
          count(materials%name == section%material) == 1) then
         ! (the material's index by a loop: findloc on the component materials%name would copy it)
         do k = 1, size(materials)
            if (materials(k)%name == section%material) exit
         end do
         if (materials(k)%user_line == 0 .and. len_trim(materials(k)%own_law) > 0) then
            ! (a field of its lines that is not one number is refused all the same: Abaqus would)
            if (len_trim(section%bad_data) > 0) call record_failure(trim(section%bad_data), nfail)
            write (output_unit, '(a)') where//': note: material '//trim(section%material)//' has no *USER '// &
               'MATERIAL but a law of Abaqus''s own ('//trim(materials(k)%own_law)//'): not interphase''s, not checked'
            return
         end if
      end if
      section_where = where
      if (len_trim(section%bad_data) > 0) call record_failure(trim(section%bad_data), nfail)
      if (.not. section%solid .and. len_trim(section%response) == 0) then
         call record_failure(where//': no RESPONSE= (Abaqus requires it): interphase is a traction-separation law: '// &
            'RESPONSE=TRACTION SEPARATION', nfail)
      else if (.not. section%solid .and. section%response /= 'TRACTIONSEPARATION' .and. section%response /= 'CONTINUUM') then
         call record_failure(where//': RESPONSE='//trim(section%response)//' but interphase is a traction-separation '// &
            'law: RESPONSE=TRACTION SEPARATION, or CONTINUUM (its strains are the separations over the constitutive '// &
            'thickness T0: give the layer thickness option t = T0, docs/abaqus.md)', nfail)
      end if
      m = 0
      ! (a section without MATERIAL= is named where it is read, and refers to no material)
      if (len_trim(section%material) > 0) then
         do k = 1, size(materials)
            if (materials(k)%name == section%material) m = k
         end do
      end if
      summary = ''
      notes = ''
      ! the constitutive thickness T0 turns separations into the strains the UMAT gets
      ! (eps = delta/T0): T0 = 1 with the layer thickness option 0, T0 = t with t > 0 (the
      ! material's options when its constants decode; its own checks follow)
      t_layer = 0.0_dp
      normal = 0
      if (m > 0) then
         if (materials(m)%user_line /= 0 .and. materials(m)%nconstants == materials(m)%nread .and. &
            .not. materials(m)%bad_constant .and. materials(m)%nread <= MAX_CONSTANTS) then
            call from_props(materials(m)%constants(1:materials(m)%nread), params, status, message)
            ! (the VUMAT takes separations, T0 = 1: its layer options are refused below)
            if (status == STATUS_OK .and. .not. explicit) then
               t_layer = params%layer_thickness
               normal = params%layer_normal
            end if
         end if
      end if
      if (.not. section%solid) then
         call check_thickness(section, section_where, t_layer, normal, notes, nfail)
      else if (explicit) then
         call record_failure(where//': continuum elements, but the VUMAT takes cohesive elements only (*COHESIVE '// &
            'SECTION, RESPONSE=TRACTION SEPARATION, constitutive thickness 1: docs/abaqus.md)', nfail)
      else if (status == STATUS_OK) then
         ! (the material's options as decoded; a material that does not decode is named below)
         call constants_count(params%model, params%damage_law, nm, nconstants)
         if (t_layer <= 0.0_dp) then
            call record_failure(where//': continuum elements with material '//trim(section%material)//', whose '// &
               'layer thickness PROPS('//int_to_string(nconstants + OPT_LAYER_THICKNESS)//') is 0: the UMAT takes a '// &
               'continuum element only in the thin-layer mode (it would refuse every call): set the layer thickness t > 0 '// &
               '(mm) in PROPS('//int_to_string(nconstants + OPT_LAYER_THICKNESS)//') and its normal axis in PROPS('// &
               int_to_string(nconstants + OPT_LAYER_NORMAL)//'), or mesh the joint with cohesive elements under '// &
               '*COHESIVE SECTION (docs/abaqus.md, ''Thin continuum layers'')', nfail)
         else if (normal == 0) then
            call record_failure(where//': continuum elements with material '//trim(section%material)//', whose '// &
               'layer normal axis PROPS('//int_to_string(nconstants + OPT_LAYER_NORMAL)//') is 0 (a cohesive '// &
               'element''s): give the axis of the layer''s normal, 1, 2 or 3 (1 or 2 in 2-D)', nfail)
         else
            notes = notes//'; note: *SOLID SECTION: thin continuum layer, t = '//real_to_string(t_layer)// &
               ' mm, normal axis '//int_to_string(normal)//' (the element type is not checked: a 2-D element takes '// &
               'axis 1 or 2)'
         end if
      end if
      hook = trim(merge('VEXTERNALDB', 'UEXTERNALDB', explicit))
      ! (the one-file source with that hook: --explicit makes the VUMAT's, with VEXTERNALDB)
      maker = trim(merge('make-user-file.sh --explicit --uexternaldb', 'make-user-file.sh --uexternaldb           ', explicit))
      if (len_trim(section%material) == 0) then
         continue     ! named where the section is read
      else if (m == 0) then
         call record_failure(where//': material '//trim(section%material)//' is not defined in this deck', nfail)
      else if (materials(m)%user_line == 0) then
         call record_failure(where//': material '//trim(section%material)//' has no *USER MATERIAL', nfail)
      else
         associate (mat => materials(m))
            where = mat%file//':'//int_to_string(mat%user_line)//': *USER MATERIAL of '//trim(mat%name)
            status = -1
            decoded = .false.
            if (len_trim(mat%bad_data) > 0) call record_failure(trim(mat%bad_data), nfail)
            if (mat%bad_constant) then
               continue     ! its constants are not decoded: the field that is not a number is named above
            else if (mat%line_overflow) then
               continue     ! nor when a data line holds more than Abaqus reads (named where it is read)
            else if (mat%nconstants < 0 .and. len_trim(mat%constants_text) == 0) then
               if (mat%nread > 0) then
                  call record_failure(where//': no CONSTANTS= (Abaqus then takes 0) but '// &
                     int_to_string(mat%nread)//' values follow: give CONSTANTS= the number of PROPS', nfail)
               else
                  call record_failure(where//': no CONSTANTS= and no constants: interphase needs its PROPS '// &
                     '(docs/abaqus.md)', nfail)
               end if
            else if (mat%nconstants < 0) then
               call record_failure(where//': CONSTANTS='//trim(mat%constants_text)//' is not a whole number '// &
                  '(CONSTANTS= is the number of PROPS)', nfail)
            else if (mat%nconstants /= mat%nread) then
               nempty = count(mat%constant_empty(1:min(mat%nread, MAX_CONSTANTS)))
               if (nempty > 0) then
                  why = ' (an empty field is a value, 0 for Abaqus: '//empty_fields(mat, .false.)//')'
               else if (mat%nread > mat%nconstants) then
                  why = ' (fields are separated by commas: a decimal comma splits a number in two; write 0.75, not 0,75)'
               else
                  why = ''
               end if
               call record_failure(where//': CONSTANTS='//int_to_string(mat%nconstants)//' but '// &
                  int_to_string(mat%nread)//' values follow'//why, nfail)
               ! the first CONSTANTS= values, which would be the PROPS: what the UMAT would say of
               ! them when one is an empty field (read as 0)
               if (nempty > 0 .and. mat%nread > mat%nconstants .and. mat%nconstants <= MAX_CONSTANTS) then
                  call from_props(mat%constants(1:mat%nconstants), params, status, message)
                  if (status /= STATUS_OK) call record_failure(where//': the first '//int_to_string(mat%nconstants)// &
                     ' values as PROPS: '//trim(message)//empty_constants_note(mat), nfail)
                  status = -1
               end if
            else if (mat%nread > MAX_CONSTANTS) then
               call record_failure(where//': '//int_to_string(mat%nread)//' constants: interphase takes far fewer '// &
                  '(docs/abaqus.md, PROPS)', nfail)
            else
               call from_props(mat%constants(1:mat%nread), params, status, message)
               decoded = status == STATUS_OK
               if (status == STATUS_OK) then
                  ! what the VUMAT refuses at its first call: the UMAT's layer and host options
                  if (explicit) call refuse_umat_options(params, 'the VUMAT', status, message)
                  if (status == STATUS_OK .and. .not. explicit .and. params%host == HOST_CALCULIX) then
                     status = STATUS_BAD_OPTION
                     call constants_count(params%model, params%damage_law, nm, nconstants)
                     message = 'PROPS('//int_to_string(nconstants + OPT_HOST)//') host = '// &
                        int_to_string(HOST_CALCULIX)//' (CalculiX conventions) in an Abaqus deck: the UMAT would '// &
                        'neither read nor write SSE and SPD, and the energies would be lost: leave it 0'
                  end if
               end if
               if (status /= STATUS_OK) then
                  call record_failure(where//': '//trim(message)//empty_constants_note(mat), nfail)
               else
                  summary = trim(merge('simplified     ', 'micromechanical', params%model == MODEL_SIMPLIFIED))// &
                     ' model, '//trim(merge('displacement-driven', 'fracture-mechanics ', &
                     params%damage_law == DAMAGE_DISPLACEMENT))//' damage law'
                  ! files the run must load at start-up (docs/abaqus.md, 'RVE tables')
                  if (params%model == MODEL_MICROMECHANICAL .and. params%table == TABLE_CUSTOM_CODE) &
                     notes = notes//'; note: PROPS('//int_to_string(PROP_TABLE)//') = 1 (custom RVE table): '// &
                     'the run needs INTERPHASE_TABLE set to the table file (an absolute path: a relative one '// &
                     'opens from the analysis'' working directory) and '//hook//' linked ('//maker//')'
                  if (params%damage_law == DAMAGE_FRACTURE .and. params%rcurve /= RCURVE_EQUIVALENT) &
                     notes = notes//'; note: the toughness (PROPS or R-curve file) is energy per unit crack '// &
                     'area, as measured (interphase before 2026-12 read it per unit '// &
                     'advance of a: the same number now means twice the energy)'
                  if (params%growth_slip == GROWTH_FIXED_LAMBDA) &
                     notes = notes//'; note: growth slip 1 (the paper''s form, lambda held while the crack grows) '// &
                     'can return energy in a closed crack (docs/theory.md)'
                  if (params%model == MODEL_MICROMECHANICAL .and. params%table == TABLE_DEFAULT_CODE .and. &
                     params%contact_band > 0.0_dp .and. params%contact_band < CHI_MIN_BUILT_IN) &
                     notes = notes//'; note: contact band chi = '//real_to_string(params%contact_band)// &
                     ' is below 0.55, the width that keeps the stored energy convex up to D = 1 - 1e-7 on the '// &
                     'built-in table (docs/theory.md, ''The contact band'')'
                  if (params%model == MODEL_MICROMECHANICAL .and. .not. (params%contact_band > 0.0_dp)) then
                     ! (the paper's two-state law, the default: what a structural run should know)
                     call constants_count(params%model, params%damage_law, nm, nconstants)
                     notes = notes//'; note: contact band 0, the paper''s two-state law: the shear traction '// &
                        'jumps where a crack closes under shear, and a cycle through s_N = 0 returns work that no '// &
                        'friction pays for (docs/theory.md, ''Open and closed at s_N = 0''): the contact band '// &
                        'PROPS('//int_to_string(nconstants + OPT_CONTACT_BAND)//') = 0.6 makes the traction '// &
                        'continuous and the law hyperelastic at fixed damage'
                  end if
                  if (params%damage_law == DAMAGE_FRACTURE .and. params%rcurve == RCURVE_TABULATED) &
                     notes = notes//'; note: tabulated R-curve: the run needs INTERPHASE_RCURVE set to the '// &
                     'R-curve file (an absolute path) and '//hook//' linked ('//maker//')'
                  notes = notes//units_notes(params)
               end if
            end if
            depvar_needed = merge(NSTATV_VUMAT, NSTATV_REQUIRED, explicit)
            ! (params is the decoded material when from_props succeeded above, whatever the
            ! host-option checks after it said)
            if (decoded .and. .not. explicit) then
               if (params%viscosity > 0.0_dp) depvar_needed = NSTATV_VISCOUS
            end if
            if (mat%depvar_bad) then
               continue     ! named above
            else if (mat%depvar < 0) then
               call record_failure(where//': no *DEPVAR: '//trim(solver)//' needs at least '//int_to_string(depvar_needed), nfail)
            else if (mat%depvar < depvar_needed) then
               why = ''
               if (depvar_needed == NSTATV_VISCOUS .and. .not. explicit) why = ' (the viscous damage takes STATEV(5))'
               ! (the VUMAT's own message says the same)
               if (explicit) why = ' (since 2026-12 slots 6-9 hold the separations and the failure flag, '// &
                  'docs/abaqus.md)'
               call record_failure(mat%file//':'//int_to_string(mat%depvar_line)//': *DEPVAR of '//trim(mat%name)//': '// &
                  int_to_string(mat%depvar)//empty_field_note(mat%depvar_empty)//' but '//trim(solver)// &
                  ' needs at least '//int_to_string(depvar_needed)//why, nfail)
            end if
            if (mat%delete_line > 0) call check_delete(mat%file, mat, explicit, depvar_needed, notes, nfail)
            ! a second law beside interphase's: the built-in one's keywords, left from a deck that used it
            if (len_trim(mat%built_in_law) > 0) call record_failure(trim(mat%built_in_law)//' in *MATERIAL, NAME='// &
               trim(mat%name)//', beside interphase''s *USER MATERIAL: a keyword of Abaqus''s built-in cohesive '// &
               'law (*ELASTIC, TYPE=TRACTION, *DAMAGE INITIATION, *DAMAGE EVOLUTION, *DAMAGE STABILIZATION), which '// &
               'interphase''s PROPS replace (stiffness, strengths, fracture energies, viscosity: docs/abaqus.md, '// &
               '''Coming from the built-in cohesive law''): remove it', nfail)
            if (len_trim(section%viscosity) > 0) then
               why = 'nb + 3'
               if (decoded) then
                  call constants_count(params%model, params%damage_law, nm, nconstants)
                  why = int_to_string(nconstants + OPT_VISCOSITY)
               end if
               notes = notes//'; note: '//trim(section%viscosity)//': Abaqus''s viscous regularisation of its own '// &
                  'damage models, which does not reach the damage inside a user material: interphase''s is the '// &
                  'viscosity option PROPS('//why//') (docs/abaqus.md, PROPS)'
            end if
            if (.not. explicit .and. .not. mat%unsymm) then
               if (.not. decoded) then
                  call record_failure(where//': no UNSYMM: the tangent DDSDDE is unsymmetric (friction, damage)', nfail)
               else if (params%stiffness == STIFFNESS_CONSISTENT) then
                  call record_failure(where//': no UNSYMM: the consistent tangent DDSDDE is unsymmetric (friction, '// &
                     'damage) and Abaqus would use its symmetric part, with which Newton fails where damage grows; '// &
                     'add UNSYMM, or choose the stiffness option 2 (docs/abaqus.md)', nfail)
               end if
            end if
            if (explicit .and. .not. (is_finite(mat%density) .and. mat%density > 0.0_dp)) then
               if (mat%density_line == 0) then
                  call record_failure(where//': no *DENSITY > 0: the VUMAT energies are per unit mass', nfail)
               else
                  call record_failure(mat%file//':'//int_to_string(mat%density_line)//': *DENSITY of '//trim(mat%name)// &
                     ': '//real_to_string(mat%density)//empty_field_note(mat%density_empty)// &
                     ' but the VUMAT needs a density > 0: its energies are per unit mass', nfail)
               end if
            end if
            if (len_trim(mat%short_line) > 0) notes = notes//'; note: '//trim(mat%short_line)//': this '// &
               '*USER MATERIAL data line holds '//int_to_string(mat%short_fields)//' constants and another line follows: '// &
               'this check reads the constants one after the other, but Abaqus''s data lines of eight values may '// &
               'read a shorter line as padded with zeros to 8, shifting every PROPS after it: write 8 on every line '// &
               'but the last'
            if (decoded .and. any(mat%constant_empty(1:min(mat%nread, MAX_CONSTANTS)))) &
               notes = notes//'; note: '//empty_fields(mat, .true.)//' read as 0, as Abaqus reads an empty data field'
            if (decoded .and. mat%depvar >= depvar_needed) &
               call check_initial_states(section%elset, states, params, explicit, notes, nfail)
         end associate
      end if
      ! failed checks on the section's or its material's own lines are named where they are read
      refused = section%refused > 0
      if (m > 0) refused = refused .or. materials(m)%refused > 0
      if (nfail == nfail_before .and. .not. refused) then
         write (output_unit, '(a)') path//': ELSET='//trim(section%elset)//', material '// &
            trim(section%material)//', '//trim(solver)//': '//summary//': ok'//notes
      end if
   end subroutine check_section

   !> The element sets' initial state variables from the data lines of *INITIAL CONDITIONS,
   !> TYPE=SOLUTION (Abaqus Keywords Guide): an element set's label and the values of its first
   !> seven state variables on one line, eight more on each line after it, for as many state
   !> variables as its material's *DEPVAR count: so many lines, whatever each holds (a field left
   !> out, or empty, is 0, as Abaqus reads data lines). An element set is known here by the ELSET=
   !> of a section interphase serves (a label qualified by an instance, Part-1-1.JOINT, by the
   !> part after its last point): where a line names an element (by number) or another set, where
   !> its values end is not known, and the reading goes on at the next line that names a set (a
   !> label: value lines hold numbers only), with a note. A field that is not a number, a line with
   !> more values than Abaqus reads there, and a set's line where its values go on are failed
   !> checks; data that end before a set's last line leave the rest 0, with a note.
   subroutine read_initial_states(lines, nlines, sections, materials, states, nstates, nfail)
      type(solution_line_type), intent(in) :: lines(:)
      integer, intent(in) :: nlines                 !! the lines read (the first nlines of `lines`)
      !> the sections interphase serves (a failed check of an element set's values is its section's)
      type(section_type), intent(inout) :: sections(:)
      type(material_type), intent(in) :: materials(:)
      type(initial_state_type), allocatable, intent(out) :: states(:)
      integer, intent(out) :: nstates               !! the element sets' values read (states(1:nstates))
      integer, intent(inout) :: nfail
      type(initial_state_type), allocatable :: grown(:)
      real(dp), allocatable :: got(:)
      integer :: i, i0, s

      allocate (states(8))
      nstates = 0
      i = 1
      ! (one set at a time in a procedure of its own: its messages' temporaries end with it, where a
      ! compiler that keeps them on the stack would otherwise pile them up over thousands of sets)
      do while (i <= nlines)
         i0 = i
         call read_set_values(lines, nlines, i, sections, materials, nfail, s, got)
         if (s == 0) cycle
         ! (doubled when full: a deck may give thousands of sets)
         if (nstates == size(states)) then
            allocate (grown(2*size(states)))
            grown(1:nstates) = states(1:nstates)
            call move_alloc(grown, states)
         end if
         nstates = nstates + 1
         states(nstates)%file = lines(i0)%file
         states(nstates)%line = lines(i0)%line
         states(nstates)%elset = sections(s)%elset
         call move_alloc(got, states(nstates)%values)
      end do
   end subroutine read_initial_states

   !> One record of read_initial_states, from line i: the values of the set it names (s its section,
   !> `got` its *DEPVAR values), or s = 0 when it names an element, an unknown set, or fails (a note
   !> or a failed check said so); i is left at the next record's first line.
   subroutine read_set_values(lines, nlines, i, sections, materials, nfail, s, got)
      type(solution_line_type), intent(in) :: lines(:)
      integer, intent(in) :: nlines
      integer, intent(inout) :: i
      type(section_type), intent(inout) :: sections(:)
      type(material_type), intent(in) :: materials(:)
      integer, intent(inout) :: nfail
      integer, intent(out) :: s
      real(dp), allocatable, intent(out) :: got(:)
      real(dp) :: buffer(LINE_LEN + 1)
      logical :: empty(LINE_LEN + 1)
      character(len=LINE_LEN) :: first, rest, bad_item
      character(len=32) :: why
      character(len=:), allocatable :: where, label, line_where
      integer :: i0, m, n, nvalues, nfields, bad_field, limit, nfail_before, record_lines, j, given, last

      i0 = i
      where = lines(i0)%file//':'//int_to_string(lines(i0)%line)//': *INITIAL CONDITIONS, TYPE=SOLUTION'
      call split_label(lines(i0)%text, first, rest)
      s = 0
      if (is_number(first)) then
         write (output_unit, '(a)') where//': note: element '//trim(adjustl(first))//': the state variables '// &
            'of single elements are not checked (this check knows elements by their section''s ELSET=), nor the '// &
            'lines after them up to the next that names an element set'
         call next_set_line(lines, nlines, i)
         return
      end if
      label = label_value(first)
      call section_of(label, sections, materials, s, m)
      if (s == 0) then
         write (output_unit, '(a)') where//': note: ELSET='//label//' is not the ELSET= of a section interphase '// &
            'serves (a set of other elements, or one this check cannot resolve: it reads no *ELSET): not checked, '// &
            'nor the lines after it up to the next that names an element set'
         call next_set_line(lines, nlines, i)
         return
      else if (m == 0) then
         s = 0
         call next_set_line(lines, nlines, i)     ! (the section's missing material is its own failed check)
         return
      else if (materials(m)%depvar < 1) then
         s = 0
         call next_set_line(lines, nlines, i)     ! (no *DEPVAR count: the material's own failed check)
         return
      end if
      n = materials(m)%depvar
      record_lines = 1 + (max(0, n - SOLUTION_FIRST_LINE_VALUES) + SOLUTION_LINE_VALUES - 1)/SOLUTION_LINE_VALUES
      where = where//' of ELSET='//label
      nfail_before = nfail
      allocate (got(n))
      got = 0.0_dp
      given = 0
      do j = 1, record_lines
         i = i0 + j - 1
         if (j > 1) then
            if (i > nlines) exit
            if (lines(i)%block /= lines(i0)%block) exit
         end if
         line_where = lines(i)%file//':'//int_to_string(lines(i)%line)//': *INITIAL CONDITIONS, TYPE=SOLUTION '// &
            'data line of ELSET='//label
         if (j == 1) then
            call parse_numbers(rest, buffer, empty, nvalues, bad_field, bad_item, why)
            if (bad_field > 0) bad_field = bad_field + 1   ! (the label is the line's first field)
            nfields = field_count(rest)
            limit = SOLUTION_FIRST_LINE_VALUES
         else
            call parse_numbers(lines(i)%text, buffer, empty, nvalues, bad_field, bad_item, why)
            nfields = field_count(lines(i)%text)
            limit = SOLUTION_LINE_VALUES
            if (bad_field == 1) then
               ! a line that names the next set where this set's values go on: Abaqus reads its
               ! label as a number
               call record_failure(line_where//': its '//int_to_string(n)//' state variables (*DEPVAR of '// &
                  trim(materials(m)%name)//') take '//int_to_string(record_lines)//' lines, '// &
                  int_to_string(SOLUTION_FIRST_LINE_VALUES)//' values on the line of the set and '// &
                  int_to_string(SOLUTION_LINE_VALUES)//' on each line after it, but line '// &
                  int_to_string(lines(i)%line)//" ('"//clip_text(trim(adjustl(bad_item)))//"') is not one of them", &
                  nfail)
               exit
            end if
         end if
         if (bad_field > 0) then
            call record_failure(line_where//': field '//int_to_string(bad_field)//" '"// &
               clip_text(trim(adjustl(bad_item)))//"' is "//trim(why), nfail)
            exit
         end if
         if (nfields > limit) then
            call record_failure(line_where//': '//int_to_string(nfields)//' values, but Abaqus reads '// &
               int_to_string(SOLUTION_FIRST_LINE_VALUES)//' on the line of the element set and '// &
               int_to_string(SOLUTION_LINE_VALUES)//' on each line after it', nfail)
            exit
         end if
         ! (the line's values in their slots; fields left out or empty are 0)
         nvalues = min(nvalues, n - given)
         got(given + 1:given + nvalues) = buffer(1:nvalues)
         given = given + limit
      end do
      ! (the lines the set's values took: i0 to i0 + j - 2)
      last = i0 + j - 2
      if (nfail > nfail_before) then
         sections(s)%refused = sections(s)%refused + (nfail - nfail_before)
         i = max(last, i0)
         call next_set_line(lines, nlines, i)
         s = 0
         return
      end if
      if (j <= record_lines) write (output_unit, '(a)') where//': note: the data end after '// &
         int_to_string(j - 1)//' of the '//int_to_string(record_lines)//' lines its '//int_to_string(n)// &
         ' state variables take (*DEPVAR of '//trim(materials(m)%name)//'): STATEV('// &
         int_to_string(min(n, given) + 1)//':'//int_to_string(n)//') taken as 0'
      ! (the set's values read: the next record starts after the lines they took)
      i = last + 1
   end subroutine read_set_values

   !> Move i to the next of the first nlines `lines`, of any *INITIAL CONDITIONS, that names an
   !> element set (its first field a label, not a number), or past the last line.
   subroutine next_set_line(lines, nlines, i)
      type(solution_line_type), intent(in) :: lines(:)
      integer, intent(in) :: nlines
      integer, intent(inout) :: i
      character(len=LINE_LEN) :: head, tail
      do
         i = i + 1
         if (i > nlines) return
         call split_label(lines(i)%text, head, tail)
         if (.not. is_number(head)) return
      end do
   end subroutine next_set_line

   !> The section (s) whose ELSET= is `label`, or the part of it after its last point (an
   !> instance's set, Part-1-1.JOINT), and its material (m); 0 when none.
   subroutine section_of(label, sections, materials, s, m)
      character(len=*), intent(in) :: label
      type(section_type), intent(in) :: sections(:)
      type(material_type), intent(in) :: materials(:)
      integer, intent(out) :: s, m
      integer :: k, dot
      s = 0
      m = 0
      dot = index(label, '.', back=.true.)
      do k = 1, size(sections)
         if (sections(k)%elset == label) then
            s = k
            exit
         end if
      end do
      if (s == 0 .and. dot > 0) then
         do k = 1, size(sections)
            if (sections(k)%elset == label(dot + 1:)) then
               s = k
               exit
            end if
         end do
      end if
      if (s == 0) return
      do k = 1, size(materials)
         if (materials(k)%name == sections(s)%material) m = k
      end do
   end subroutine section_of

   !> A data line's first field (before its first comma outside quotes) and the rest after it.
   pure subroutine split_label(text, first, rest)
      character(len=*), intent(in) :: text
      character(len=*), intent(out) :: first, rest
      integer :: c
      c = comma_outside_quotes(text)
      if (c > 0) then
         first = text(1:c - 1)
         rest = text(c + 1:)
      else
         first = text
         rest = ''
      end if
   end subroutine split_label

   !> The field is one number (an element's label, or a value), not a set's label.
   !> (The result has a name of its own: passed as the function's name, gfortran took the internal
   !> function itself and built a trampoline, which put the program's stack in executable memory.)
   logical function is_number(field) result(number)
      character(len=*), intent(in) :: field
      real(dp) :: x
      character(len=32) :: why
      call parse_real(field, x, number, why)
   end function is_number

   !> The fields of a comma-separated data line as Abaqus counts them: every field, empty ones
   !> too, but for one comma that ends the line.
   pure integer function field_count(text) result(n)
      character(len=*), intent(in) :: text
      integer :: k, last
      n = 0
      last = len_trim(text)
      if (last == 0) return
      n = 1
      do k = 1, last
         if (text(k:k) == ',') n = n + 1
      end do
      if (text(last:last) == ',') n = n - 1
   end function field_count

   !> The initial state variables the deck gives the section's element set, checked as the UMAT's
   !> and VUMAT's STATEV reader checks them at the first call (unpack_statev: the same messages),
   !> as a 2-D point reads them; what only a 3-D point refuses (STATEV(3), the second slip) is a
   !> note. For the VUMAT (explicit), STATEV(6:8) are the total separations it adds each increment
   !> to: an element starts at rest, so they must start at 0.
   subroutine check_initial_states(elset, states, params, explicit, notes, nfail)
      character(len=*), intent(in) :: elset
      type(initial_state_type), intent(in) :: states(:)
      type(law_params_type), intent(in) :: params         !! the section's material, decoded
      logical, intent(in) :: explicit
      character(len=:), allocatable, intent(inout) :: notes
      integer, intent(inout) :: nfail
      character(len=:), allocatable :: note_3d
      integer :: k, first_checked, nnotes_3d
      logical :: passed

      first_checked = 0
      nnotes_3d = 0
      ! (one state at a time in a procedure of its own: its messages' temporaries end with it)
      do k = 1, size(states)
         if (states(k)%elset /= elset) cycle
         call check_one_state(states(k), params%viscosity > 0.0_dp, explicit, nfail, passed, note_3d)
         if (len(note_3d) > 0) then
            nnotes_3d = nnotes_3d + 1
            if (nnotes_3d == 1) notes = notes//'; note: '//note_3d
         end if
         if (passed .and. first_checked == 0) first_checked = k
      end do
      if (nnotes_3d > 1) notes = notes//' (and '//int_to_string(nnotes_3d - 1)//' more such line(s))'
      if (first_checked > 0) notes = notes//'; note: initial state variables (*INITIAL CONDITIONS at '// &
         states(first_checked)%file//':'//int_to_string(states(first_checked)%line)//') checked'
   end subroutine check_initial_states

   !> check_initial_states on one element set's values: `passed` false when a failed check was
   !> recorded; `note_3d` what only a 3-D point refuses ('' when nothing).
   subroutine check_one_state(given, viscous, explicit, nfail, passed, note_3d)
      type(initial_state_type), intent(in) :: given
      logical, intent(in) :: viscous                      !! the material's viscous regularisation
      logical, intent(in) :: explicit
      integer, intent(inout) :: nfail
      logical, intent(out) :: passed
      character(len=:), allocatable, intent(out) :: note_3d
      type(interface_state_type) :: state
      character(len=MESSAGE_LEN) :: message
      character(len=:), allocatable :: where
      integer :: status

      note_3d = ''
      passed = .false.
      associate (v => given%values)
         where = given%file//':'//int_to_string(given%line)//': *INITIAL CONDITIONS, TYPE=SOLUTION of '// &
            'ELSET='//trim(given%elset)
         call unpack_statev(size(v), v, 2, viscous, state, status, message)
         if (status /= STATUS_OK) then
            call record_failure(where//': '//trim(message)//' (the '//trim(merge('VUMAT', 'UMAT ', explicit))// &
               ' refuses it at the first increment: docs/abaqus.md, STATEV)', nfail)
            return
         end if
         call unpack_statev(size(v), v, 3, viscous, state, status, message)
         if (status /= STATUS_OK) note_3d = where//': '//trim(message)//' in a 3-D element (a 2-D one does not '// &
            'read STATEV(3))'
         if (explicit .and. size(v) >= SV_SEP_T2) then
            if (.not. all(abs(v(SV_SEP_N:SV_SEP_T2)) <= 0.0_dp)) then
               call record_failure(where//': STATEV(6:8) = '//real_to_string(v(SV_SEP_N))//', '// &
                  real_to_string(v(SV_SEP_T1))//', '//real_to_string(v(SV_SEP_T2))//' mm, but these are the '// &
                  'VUMAT''s total separations, to which it adds each increment''s: an element at rest starts from 0 '// &
                  '(another value would offset its traction; docs/abaqus.md, VUMAT)', nfail)
               return
            end if
         end if
         if (explicit .and. size(v) >= SV_FAILED) then
            if (.not. abs(v(SV_FAILED)) <= 0.0_dp) then
               call record_failure(where//': STATEV('//int_to_string(SV_FAILED)//') = '// &
                  real_to_string(v(SV_FAILED))//', but it is the VUMAT''s failure flag (1 where a point''s '// &
                  'update failed and was held), which the VUMAT carries over without reading it: a point starts '// &
                  'from 0 (docs/abaqus.md, VUMAT)', nfail)
               return
            end if
         end if
      end associate
      passed = .true.
   end subroutine check_one_state

   !> `*DEPVAR, DELETE=n` of a material: Abaqus deletes a material point whose state variable n is
   !> 0 (1: active). interphase's own slots (1 to depvar_needed) start from zeros and hold 0 at an
   !> intact point (or at one that has not failed: the VUMAT's flag), so a DELETE= among them would
   !> delete every intact point: a failed check. A slot beyond them is the user's (the VUMAT
   !> carries it over, the UMAT leaves it alone): a note that interphase never flags a point for
   !> deletion. DELETE= that is not a whole number, or beyond *DEPVAR's count, is a failed check.
   subroutine check_delete(path, mat, explicit, depvar_needed, notes, nfail)
      character(len=*), intent(in) :: path
      type(material_type), intent(in) :: mat
      logical, intent(in) :: explicit
      integer, intent(in) :: depvar_needed       !! interphase's slots for this material and solver
      character(len=:), allocatable, intent(inout) :: notes
      integer, intent(inout) :: nfail
      character(len=:), allocatable :: where, slot
      integer :: n, ios
      where = path//':'//int_to_string(mat%delete_line)//': *DEPVAR of '//trim(mat%name)//', DELETE='// &
         trim(mat%delete_text)
      n = -1
      if (len_trim(mat%delete_text) > 0 .and. len_trim(mat%delete_text) <= 9) then
         if (verify(trim(mat%delete_text), '0123456789') == 0) then
            read (mat%delete_text, '(i9)', iostat=ios) n
            if (ios /= 0) n = -1
         end if
      end if
      if (n < 1) then
         call record_failure(where//': not a state variable number (a whole number >= 1)', nfail)
      else if (mat%depvar >= 0 .and. n > mat%depvar) then
         call record_failure(where//': beyond the '//int_to_string(mat%depvar)//' state variables of *DEPVAR', nfail)
      else if (n <= depvar_needed) then
         select case (n)
         case (SV_DAMAGE)
            slot = 'the damage D, 0 at every intact point'
         case (SV_SLIP_1, SV_SLIP_2)
            slot = 'a frictional slip, 0 until the crack slides'
         case (SV_REGIME)
            slot = 'the regime, 0 at every intact point'
         case (SV_DAMAGE_INVISCID)
            slot = 'with viscous regularisation the damage law''s own D, 0 at every intact point'
         case (SV_FAILED)
            slot = 'the failure flag, 0 at every point whose update has not failed'
         case default
            slot = 'a separation, 0 at the start'
         end select
         call record_failure(where//': STATEV('//int_to_string(n)//') is interphase''s ('//trim(slot)// &
            '; every point starts from zeros), and Abaqus deletes a point whose deletion variable is 0: every '// &
            'point would be deleted at the start. interphase does not flag points for deletion (a fully cracked joint '// &
            'still carries contact and friction, docs/abaqus.md): drop DELETE=', nfail)
      else
         slot = ''
         if (explicit) slot = ' (the VUMAT carries it over)'
         notes = notes//'; note: *DEPVAR, DELETE='//int_to_string(n)//': interphase never writes STATEV('// &
            int_to_string(n)//')'//slot//', so a point is deleted only if that slot starts at 0'
      end if
   end subroutine check_delete

   !> ' (the empty field f of line L (PROPS(i)), ... read as 0, as Abaqus reads an empty data
   !> field)' after a decoder's message when some of the material's constants were empty fields;
   !> '' when none was.
   function empty_constants_note(mat) result(note)
      type(material_type), intent(in) :: mat
      character(len=:), allocatable :: note
      note = ''
      if (any(mat%constant_empty(1:min(mat%nread, MAX_CONSTANTS)))) &
         note = ' ('//empty_fields(mat, .true.)//' read as 0, as Abaqus reads an empty data field)'
   end function empty_constants_note

   !> ' (an empty field: Abaqus reads it as 0)' for a value read from an empty field; '' otherwise.
   pure function empty_field_note(empty) result(note)
      logical, intent(in) :: empty
      character(len=:), allocatable :: note
      note = ''
      if (empty) note = ' (an empty field: Abaqus reads it as 0)'
   end function empty_field_note

   !> The material's constants given as empty fields: 'the empty field 4 of line 88' ('the empty
   !> fields 3 of line 88 (PROPS(3)), 1 of line 89 (PROPS(9))' with `props`).
   function empty_fields(mat, props) result(text)
      type(material_type), intent(in) :: mat
      logical, intent(in) :: props                   !! name the PROPS index of each
      character(len=:), allocatable :: text
      integer :: i, n
      text = ''
      n = 0
      do i = 1, min(mat%nread, MAX_CONSTANTS)
         if (.not. mat%constant_empty(i)) cycle
         n = n + 1
         if (n > 1) text = text//', '
         text = text//int_to_string(mat%constant_field(i))//' of line '//int_to_string(mat%constant_line(i))
         if (props) text = text//' (PROPS('//int_to_string(i)//'))'
      end do
      if (n > 1) then
         text = 'the empty fields '//text
      else
         text = 'the empty field '//text
      end if
   end function empty_fields

   !> A cohesive section's constitutive thickness against its material's layer options (t = 0:
   !> the separation itself, T0 = 1; t > 0: T0 = t) and normal axis (0 on a cohesive element).
   subroutine check_thickness(section, where, t_layer, normal, notes, nfail)
      type(section_type), intent(in) :: section
      character(len=*), intent(in) :: where
      real(dp), intent(in) :: t_layer
      integer, intent(in) :: normal
      character(len=:), allocatable, intent(inout) :: notes
      integer, intent(inout) :: nfail
      real(dp) :: t0
      character(len=:), allocatable :: rule, mode, default_note
      t0 = 1.0_dp
      rule = 'constitutive thickness 1 (strain = separation in mm)'
      if (t_layer > 0.0_dp) then
         t0 = t_layer
         rule = 'the constitutive thickness '//real_to_string(t_layer)//' mm of the material''s layer thickness '// &
            'option (strain = separation/t)'
      end if
      if (normal /= 0) call record_failure(where//': the material''s layer normal axis is '// &
         int_to_string(normal)//' but a cohesive element is normal first: set it to 0', nfail)
      ! THICKNESS= left out: Abaqus takes GEOMETRY for a continuum response, SPECIFIED otherwise
      ! (Abaqus Keywords Guide, *COHESIVE SECTION)
      mode = trim(section%thickness_mode)
      default_note = ''
      if (mode == 'DEFAULT') then
         mode = trim(merge('GEOMETRY ', 'SPECIFIED', section%response == 'CONTINUUM'))
         default_note = ' (THICKNESS= left out: Abaqus''s default for RESPONSE='//trim(section%response)//')'
      end if
      if (mode /= 'SPECIFIED') then
         if (section%response == 'CONTINUUM' .and. mode == 'GEOMETRY' .and. t_layer > 0.0_dp) then
            notes = notes//'; note: THICKNESS=GEOMETRY'//default_note//': the constitutive thickness comes from the '// &
               'nodes and must equal the layer thickness option '//real_to_string(t_layer)//' mm (not checked)'
         else
            call record_failure(where//': THICKNESS='//mode//default_note//' but interphase needs '// &
               'THICKNESS=SPECIFIED with '//rule, nfail)
         end if
      else if (len_trim(section%bad_data) > 0) then
         continue     ! its field is not a number: named with the section
      else if ((section%thickness_empty .or. .not. section%thickness_read) .and. &
         section%response == 'TRACTIONSEPARATION' .and. t_layer <= 0.0_dp) then
         ! the field has a default, 1.0 for a traction-separation response (Abaqus Analysis User's
         ! Guide, 'Defining the constitutive thickness'): an empty field takes it
         notes = notes//'; note: the constitutive thickness is '//trim(merge('an empty field', 'not given     ', &
            section%thickness_read))//': Abaqus takes its default, 1.0, for a traction-separation response (write 1. '// &
            'to make it plain)'
      else if (.not. section%thickness_read) then
         call record_failure(where//': no constitutive thickness (the section''s data line) but interphase needs '// &
            rule, nfail)
      else if (.not. is_finite(section%thickness) .or. abs(section%thickness - t0) > 1.0e-12_dp*t0) then
         call record_failure(where//': constitutive thickness '//real_to_string(section%thickness)// &
            empty_field_note(section%thickness_empty)//' but interphase needs '//rule, nfail)
      end if
   end subroutine check_thickness

   !> The file an *INCLUDE's INPUT= names ('' when none): its double quotes dropped, and a relative
   !> path taken from the folder of `from`, the deck (the job's working directory, where Abaqus
   !> resolves every relative INPUT=, an included file's too).
   function include_file(from, input) result(name)
      character(len=*), intent(in) :: from          !! the deck
      character(len=*), intent(in) :: input         !! INPUT= as written
      character(len=:), allocatable :: name
      integer :: slash
      name = trim(adjustl(input))
      if (len(name) >= 2) then
         if (name(1:1) == '"' .and. name(len(name):len(name)) == '"') name = name(2:len(name) - 1)
      end if
      if (len(name) == 0) return
      if (name(1:1) == '/') return
      slash = index(from, '/', back=.true.)
      if (slash > 0) name = from(1:slash)//name
   end function include_file

   !> 'line N' of the deck, or 'FILE:N' for a line of an *INCLUDE file.
   function line_in(deck, file, number) result(text)
      character(len=*), intent(in) :: deck, file
      integer, intent(in) :: number
      character(len=:), allocatable :: text
      if (file == deck) then
         text = 'line '//int_to_string(number)
      else
         text = file//':'//int_to_string(number)
      end if
   end function line_in

   !> The next line of the deck, left-adjusted, its number and its length as written (trailing
   !> blanks not counted); false at the end of the file. A line that cannot be read, or is longer
   !> than LINE_LEN, is reported: status = 2, the file closed, and the result true (the caller
   !> stops on the status).
   logical function next_line(file, path, text, number, status, length)
      type(text_file_type), intent(inout) :: file
      character(len=*), intent(in) :: path
      character(len=LINE_LEN), intent(out) :: text
      integer, intent(out) :: number
      integer, intent(inout) :: status
      integer, intent(out) :: length
      character(len=MESSAGE_LEN) :: message
      integer :: outcome
      next_line = .false.
      text = ''
      length = 0
      call read_text_line(file, outcome, message)
      number = file%line_number
      if (outcome == TEXT_END) return
      next_line = .true.
      if (outcome /= TEXT_LINE) then
         write (error_unit, '(a,i0,a)') 'interphase-check-deck: '//tried_path(path)//':', number, ': '//trim(message)
         call close_text_file(file)
         status = 2
         return
      end if
      if (file%length > LINE_LEN) then
         write (error_unit, '(a,i0,a,i0,a)') 'interphase-check-deck: '//tried_path(path)//':', number, &
            ': line longer than ', LINE_LEN, ' characters (Abaqus reads at most 256)'
         call close_text_file(file)
         status = 2
         return
      end if
      text = adjustl(file%buffer(1:file%length))
      length = len_trim(file%buffer(1:file%length))
   end function next_line

   !> The failed check of a keyword or data line longer than Abaqus reads.
   function too_long(path, number, length) result(text)
      character(len=*), intent(in) :: path
      integer, intent(in) :: number              !! the line's number
      integer, intent(in) :: length              !! its length (trailing blanks not counted)
      character(len=:), allocatable :: text
      text = path//':'//int_to_string(number)//': line of '//int_to_string(length)//' characters, but Abaqus '// &
         'reads at most '//int_to_string(ABAQUS_LINE_LEN)//' (blanks included): split it (a keyword line after a '// &
         'comma, a data line as its keyword allows)'
   end function too_long

   !> Count `n` failed checks of a line against what the line belongs to: the current material
   !> (its *MATERIAL, *USER MATERIAL, *DEPVAR, *DENSITY lines) or the last cohesive section (its
   !> keyword and data lines), whose line then says no 'ok'.
   subroutine attribute_failures(n, keyword, current, materials, sections)
      integer, intent(in) :: n
      character(len=*), intent(in) :: keyword          !! the line's keyword, resolved
      integer, intent(in) :: current                   !! the current material (0: none)
      type(material_type), intent(inout) :: materials(:)
      type(section_type), intent(inout) :: sections(:)
      if (n <= 0) return
      select case (trim(keyword))
      case ('MATERIAL', 'USERMATERIAL', 'USERMATERIAL,THERMAL', 'DEPVAR', 'DENSITY')
         if (current > 0) materials(current)%refused = materials(current)%refused + n
      case ('COHESIVESECTION')
         if (size(sections) > 0) sections(size(sections))%refused = sections(size(sections))%refused + n
      end select
   end subroutine attribute_failures

   !> A label as Abaqus reads it (its input syntax rules): in double quotes, the text between
   !> them, case and blanks kept; otherwise upper case, blanks removed.
   pure function label_value(text) result(label)
      character(len=*), intent(in) :: text           !! the parameter's value as written
      character(len=:), allocatable :: label
      integer :: n
      label = trim(adjustl(text))
      n = len(label)
      if (n >= 2) then
         if (label(1:1) == '"' .and. label(n:n) == '"') then
            label = label(2:n - 1)
            return
         end if
      end if
      label = trim(upper_compact(label))
   end function label_value

   !> The position of the first comma of `text` outside double quotes (0: none).
   pure integer function comma_outside_quotes(text) result(at)
      character(len=*), intent(in) :: text
      logical :: quoted
      integer :: i
      quoted = .false.
      at = 0
      do i = 1, len_trim(text)
         if (text(i:i) == '"') then
            quoted = .not. quoted
         else if (text(i:i) == ',' .and. .not. quoted) then
            at = i
            return
         end if
      end do
   end function comma_outside_quotes

   !> Print a failed check and count it.
   subroutine record_failure(text, nfail)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: nfail
      write (output_unit, '(a)') text
      nfail = nfail + 1
   end subroutine record_failure

   !> Upper case without blanks (Abaqus ignores blanks and case in keywords and parameters).
   pure function upper_compact(s) result(t)
      character(len=*), intent(in) :: s
      character(len=len(s)) :: t
      integer :: i, n, c
      t = ''
      n = 0
      do i = 1, len_trim(s)
         if (s(i:i) == ' ') cycle
         c = iachar(s(i:i))
         n = n + 1
         t(n:n) = s(i:i)
         if (c >= iachar('a') .and. c <= iachar('z')) t(n:n) = achar(c - 32)
      end do
   end function upper_compact

   !> The parameters of a keyword line, "*KEYWORD, NAME=value, FLAG, ...": their names (upper
   !> case, blanks removed, as Abaqus compares them; an abbreviation of one of `keyword`'s
   !> parameters read as the parameter, `parameters_of`), their values as written ('' for a flag),
   !> the first name given twice ('' when none) and an ambiguous abbreviation's reading ('' when
   !> none: 'E could be ELEMENT BY ELEMENT or EXPLICIT').
   subroutine keyword_parameters(line, keyword, names, values, repeated, ambiguous)
      character(len=*), intent(in) :: line
      character(len=*), intent(in) :: keyword          !! the keyword, resolved
      character(len=80), allocatable, intent(out) :: names(:)
      character(len=len(line)), allocatable, intent(out) :: values(:)
      character(len=80), intent(out) :: repeated
      character(len=:), allocatable, intent(out) :: ambiguous
      character(len=len(line)) :: rest, item
      character(len=80) :: name
      character(len=:), allocatable :: readings
      integer :: i, eq
      allocate (names(0), values(0))
      repeated = ''
      ambiguous = ''
      rest = line
      i = comma_outside_quotes(rest)
      do while (i > 0)
         rest = rest(i + 1:)
         i = comma_outside_quotes(rest)
         if (i > 0) then
            item = rest(1:i - 1)
         else
            item = rest
         end if
         eq = index(item, '=')
         if (eq == 0) eq = len_trim(item) + 1
         if (len_trim(item(1:eq - 1)) == 0) cycle
         name = resolve_name(upper_compact(item(1:eq - 1)), parameters_of(keyword), readings)
         if (len(readings) > 0 .and. len(ambiguous) == 0) &
            ambiguous = trim(upper_compact(item(1:eq - 1)))//' could be '//readings
         if (len_trim(repeated) == 0 .and. any(names == name)) repeated = name
         names = [character(len=80) :: names, name]
         values = [character(len=len(line)) :: values, adjustl(item(min(eq + 1, len(item) + 1):))]
      end do
   end subroutine keyword_parameters

   !> The parameters of a keyword of KEYWORDS_READ that this check reads, with the others of the
   !> keyword that begin as they do (Abaqus Keywords Guide), against which an abbreviation is read.
   pure function parameters_of(keyword) result(names)
      character(len=*), intent(in) :: keyword          !! resolved
      character(len=NAME_LEN), allocatable :: names(:)
      select case (trim(keyword))
      case ('MATERIAL')
         names = [character(len=NAME_LEN) :: 'NAME', 'RTEMP', 'SRATE']
      case ('USERMATERIAL')
         names = USER_MATERIAL_PARAMETERS
      case ('COHESIVESECTION')
         names = COHESIVE_SECTION_PARAMETERS
      case ('DYNAMIC', 'DYNAMICTEMPERATURE-DISPLACEMENT')
         names = [character(len=NAME_LEN) :: 'ALLSDTOL', 'ALPHA', 'APPLICATION', 'DIRECT', 'ELEMENTBYELEMENT', &
            'EXPLICIT', 'FIXEDTIMEINCREMENTATION', 'HAFTOL', 'HALFINC', 'IMPROVEDDTMETHOD', 'INITIAL', 'NOHAF', &
            'SCALEFACTOR']
      case ('DEPVAR')
         names = [character(len=NAME_LEN) :: 'DELETE']
      case ('ELASTIC')
         names = [character(len=NAME_LEN) :: 'DEPENDENCIES', 'MODULI', 'POREFLUID', 'REGULARIZE', 'RTOL', 'TYPE']
      case ('SECTIONCONTROLS')
         names = [character(len=NAME_LEN) :: 'DISTORTIONCONTROL', 'ELEMENTCONVERSION', 'ELEMENTDELETION', &
            'HOURGLASS', 'INITIALGAPOPENING', 'KINEMATICSPLIT', 'LENGTHRATIO', 'MAXDEGRADATION', 'NAME', &
            'SECONDORDERACCURACY', 'VISCOSITY', 'WEIGHTFACTOR']
      case ('INCLUDE')
         names = [character(len=NAME_LEN) :: 'INPUT', 'PASSWORD']
      case ('INITIALCONDITIONS')
         names = [character(len=NAME_LEN) :: 'CRITERION', 'DEFINITION', 'FILE', 'INC', 'INPUT', 'INTERPOLATE', &
            'MIDSIDE', 'NORMAL', 'REBAR', 'SECTIONPOINTS', 'STEP', 'TYPE', 'UNBALANCEDSTRESS', 'USER', 'VARIABLE']
      case ('SOLIDSECTION')
         names = [character(len=NAME_LEN) :: 'COMPOSITE', 'CONTROLS', 'ELSET', 'LAYUP', 'MATERIAL', 'ORIENTATION', &
            'REFNODE', 'STACKDIRECTION', 'SYMMETRIC']
      case default
         allocate (names(0))
      end select
   end function parameters_of

   !> The name of `known` that `word` (upper case, blanks removed) is, or abbreviates: `word`
   !> itself when it is one of them, else the only one it is the start of (Abaqus' abbreviation
   !> rule); `word` unchanged when it starts none. When it starts several, `ambiguous` lists them
   !> ('A, B or C', each name after `mark` when given) and `word` is returned unchanged; ''
   !> otherwise.
   function resolve_name(word, known, ambiguous, mark) result(name)
      character(len=*), intent(in) :: word
      character(len=*), intent(in) :: known(:)
      character(len=:), allocatable, intent(out) :: ambiguous
      character(len=*), intent(in), optional :: mark   !! written before each name listed ('*')
      character(len=80) :: name
      character(len=:), allocatable :: before
      integer :: k, n, found, m
      before = ''
      if (present(mark)) before = mark
      name = word
      ambiguous = ''
      n = len_trim(word)
      if (n == 0) return
      if (any(known == word)) return
      found = 0
      m = 0
      do k = 1, size(known)
         if (len_trim(known(k)) > n) then
            if (known(k)(1:n) == word(1:n)) then
               ! (a name that two of the lists hold counts once)
               if (any(known(1:k - 1) == known(k))) cycle
               found = found + 1
               m = k
               if (found == 1) then
                  ambiguous = before//trim(known(k))
               else
                  ambiguous = ambiguous//', '//before//trim(known(k))
               end if
            end if
         end if
      end do
      if (found == 1) then
         name = known(m)
         ambiguous = ''
      else if (found > 1) then
         k = index(ambiguous, ', ', back=.true.)
         ambiguous = ambiguous(:k - 1)//' or '//ambiguous(k + 2:)
      end if
   end function resolve_name

   !> The value of parameter `name` as written ('' when absent; the first when repeated).
   pure function parameter_value(names, values, name) result(value)
      character(len=*), intent(in) :: names(:), values(:), name
      character(len=:), allocatable :: value
      integer :: i
      value = ''
      do i = 1, size(names)
         if (trim(names(i)) == name) then
            value = trim(values(i))
            return
         end if
      end do
   end function parameter_value

   !> The value of parameter `name` among `choices` (upper case, blanks removed), an
   !> abbreviation read as the choice it abbreviates; an unknown or ambiguous value as written
   !> (upper case, blanks removed), '' when the parameter is absent.
   function parameter_choice(names, values, name, choices) result(choice)
      character(len=*), intent(in) :: names(:), values(:), name
      character(len=*), intent(in) :: choices(:)
      character(len=80) :: choice
      character(len=:), allocatable :: ambiguous
      choice = resolve_name(upper_compact(parameter_value(names, values, name)), choices, ambiguous)
   end function parameter_choice

   !> The numbers of a comma-separated data line as Abaqus reads them: an empty field is 0
   !> (flagged in `empty`); empty fields after the last one that is not are no values (a line
   !> may end in a comma); a field that is not a number stops the values there.
   subroutine parse_numbers(line, values, empty, n, bad_field, bad_item, why)
      character(len=*), intent(in) :: line
      real(dp), intent(out) :: values(:)       !! at least len(line) + 1: one per field
      logical, intent(out) :: empty(:)         !! (size(values)) the field is empty: its value is 0
      integer, intent(out) :: n                !! the values read
      !> the first comma-separated field (1-based, empty fields counted) that is not one finite
      !> real literal (interphase_text_input's parse_real); 0 when all are (the values stop there)
      integer, intent(out) :: bad_field
      character(len=*), intent(out) :: bad_item  !! that field's text ('' when bad_field = 0)
      character(len=32), intent(out) :: why    !! parse_real's reason for bad_field
      character(len=len(line)) :: rest, item, tail
      integer :: k
      real(dp) :: x
      logical :: ok
      n = 0
      bad_field = 0
      bad_item = ''
      why = ''
      values = 0.0_dp
      empty = .false.
      rest = line
      k = 0
      do while (len_trim(rest) > 0 .and. k < size(values))
         ! (the field before the first comma: a number holds no double quote, so split_label's
         ! comma outside quotes is the first comma)
         call split_label(rest, item, tail)
         rest = tail
         k = k + 1
         if (len_trim(item) == 0) then
            ! 0, as Abaqus reads it; a value only when a field that is not empty follows
            empty(k) = .true.
            cycle
         end if
         call parse_real(item, x, ok, why)
         if (.not. ok) then
            bad_field = k
            bad_item = item
            n = k - 1
            exit
         end if
         values(k) = x
         n = k
      end do
   end subroutine parse_numbers

end program interphase_check_deck
