!> Case files of the single-point driver: the namelist groups `&material` and `&loading`.
!>
!>     &material
!>       model = 'simplified', damage_law = 'displacement',
!>       mu = 0.75, s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06,   ! (-), mm
!>       k_n = 482.69742679680568, k_t = 198.75776397515528                      ! MPa/mm
!>     /
!>     &loading
!>       history = 'h1I.txt', increments = 200, output = 'h1I.csv', plot = .true.
!>     /
!>
!> The material may be given as the UMAT's PROPS instead (`props = 1, 1, 0.75, ...`: 1 to 20
!> values; drivers/README.md, 'The material as PROPS'), with `table` and `rcurve_file` only where
!> PROPS select those files.
!>
!> Every `&material` entry is required; `&loading` needs `history`, `increments` and `output`
!> (`plot` defaults to true). The driver only packs the material data into PROPS: range checks
!> are the UMAT's. Nothing is stopped here: errors come back as a message.
module interphase_driver_case
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use interphase_kinds, only: dp
   use interphase_enums, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED, TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, &
      GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA, STIFFNESS_CONSISTENT, STIFFNESS_SYMMETRIC, STIFFNESS_FIXED_DAMAGE
   use interphase_params, only: law_params_type, to_props, from_props, refuse_umat_options
   use interphase_driver_text, only: int_to_string, real_to_string, to_lower, directory_of, stem_of, join_path, &
      same_file
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_rcurve, only: load_rcurve
   use interphase_provider, only: check_run_time_data
   use interphase_mixed_control, only: TRACTION_TOLERANCE_MAX
   use interphase_status, only: STATUS_OK, MESSAGE_LEN, status_message, STATUS_BAD_MU, STATUS_BAD_S0_N, &
      STATUS_BAD_SF_N, STATUS_BAD_S0_T, STATUS_BAD_SF_T, STATUS_BAD_K_N, STATUS_BAD_K_T, STATUS_BAD_D0, &
      STATUS_BAD_RCURVE, STATUS_BAD_GC_I, STATUS_BAD_GC_II, STATUS_BAD_OPTION, STATUS_RCURVE_OUT_OF_RANGE
   use interphase_layout, only: OPTION_SPECS, OPT_CONTACT_BAND, OPT_VISCOSITY, NPROPS_SIMPLIFIED, NPROPS_FRACTURE_EXTRA, &
      NPROPS_OPTIONS, NPROPS_MICROMECHANICAL, LFM_RCURVE
   use interphase_text_input, only: tried_path
   use interphase_driver_namelist, only: check_namelist_file, entry_kind_type, entry_line_type, with_entry_line, given_values, &
      KIND_REAL, KIND_INTEGER, KIND_LOGICAL, KIND_STRING, open_namelist_file
   implicit none
   private
   public :: case_type, read_case, material_entries_type, material_props, unpack_entries, writes_an_input, &
      load_start_up_data, ENTRY_LEN, UNSET_REAL, is_unset, precheck_case_file, material_entry_kinds, &
      check_material_props, material_summary, data_files_summary, d0_entry_of, STIFFNESS_WORDS

   !> The words of the `stiffness` entry, by their STIFFNESS_* codes (0, 1, 2): the entry's reader,
   !> the console's material summary and interphase-point's tangent-check note name them alike.
   character(len=12), parameter :: STIFFNESS_WORDS(STIFFNESS_CONSISTENT:STIFFNESS_FIXED_DAMAGE) = &
      [character(len=12) :: 'consistent', 'symmetric', 'fixed-damage']

   !> Length of the character entries of the namelists (model names, paths).
   integer, parameter :: ENTRY_LEN = 1024
   !> Marks a real entry the case file did not set.
   real(dp), parameter :: UNSET_REAL = -huge(1.0_dp)
   !> Marks an integer entry the case file did not set.
   integer, parameter :: UNSET_INTEGER = -huge(1)
   !> The most values the `props` entry of a material group takes: the longest PROPS the UMAT
   !> decodes (the simplified model with the fracture law and every option constant).
   integer, parameter, public :: PROPS_ENTRY_MAX = NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA + NPROPS_OPTIONS
   !> Default of `traction_tolerance` (MPa): a few units in the last place of tractions of order
   !> 1 MPa, so that an imposed traction is met to round-off.
   real(dp), parameter, public :: DEFAULT_TRACTION_TOLERANCE = 1.0e-12_dp
   !> Default of `tangent_step` (mm): small against s0 (4.4e-4 mm in the paper's data), large
   !> against the round-off of the separation.
   real(dp), parameter, public :: DEFAULT_TANGENT_STEP = 1.0e-8_dp

   !> The entries of a material group (`&material` of interphase-point, `&joint` of
   !> interphase-fe2d) as read, before `material_props` checks them and packs PROPS.
   type :: material_entries_type
      character(len=ENTRY_LEN) :: model = ''         !! 'simplified' or 'micromechanical'
      character(len=ENTRY_LEN) :: damage_law = ''    !! 'displacement' or 'fracture'
      character(len=ENTRY_LEN) :: table = ''         !! custom RVE table (micromechanical)
      character(len=ENTRY_LEN) :: rcurve = ''        !! 'constant', 'equivalent', 'tabulated'
      character(len=ENTRY_LEN) :: rcurve_file = ''   !! tabulated R-curve file
      real(dp) :: mu = UNSET_REAL                    !! friction coefficient (-)
      real(dp) :: s0_n = UNSET_REAL, sf_n = UNSET_REAL   !! mm
      real(dp) :: s0_t = UNSET_REAL, sf_t = UNSET_REAL   !! mm
      real(dp) :: k_n = UNSET_REAL, k_t = UNSET_REAL     !! MPa/mm (simplified)
      real(dp) :: d0 = UNSET_REAL                    !! initial crack a0/b (fracture law)
      real(dp) :: g_ci = UNSET_REAL, g_cii = UNSET_REAL  !! N/mm per unit crack area (constant R-curve)
      !> option: the crack faces' slip while the crack grows, 'fixed-pi' (the default) or
      !> 'fixed-lambda' (the paper's form); '' leaves the option constant out of PROPS
      character(len=ENTRY_LEN) :: growth_slip = ''
      !> option: the contact band width chi (-), the continuous variant of the open/closed switch
      !> at s_N = 0 (0: the paper's two-state law, the default); unset leaves it out of PROPS
      real(dp) :: contact_band = UNSET_REAL
      !> option: the viscosity eta (s) of the damage's viscous regularisation (0: none, the
      !> default); unset leaves it out of PROPS
      real(dp) :: viscosity = UNSET_REAL
      !> option: which stiffness DDSDDE is, 'consistent' (the default), 'symmetric' (its
      !> symmetric part) or 'fixed-damage' (symmetric, positive semi-definite)
      character(len=ENTRY_LEN) :: stiffness = ''
      !> the material as the UMAT's PROPS (docs/abaqus.md), in place of the entries above but
      !> `table` and `rcurve_file`: its first props_count values (the pre-check's count of the
      !> values given: a value is never taken for a marker of one left out)
      real(dp) :: props(PROPS_ENTRY_MAX) = 0.0_dp
      integer :: props_count = 0
   end type material_entries_type

   !> Everything the driver needs from one case file.
   type :: case_type
      !> The case file as given on the command line.
      character(len=:), allocatable :: path
      !> Case name: the case file's name without directory and extension (plot title).
      character(len=:), allocatable :: name
      !> Material constants in the UMAT's PROPS layout (`interphase_layout`).
      real(dp), allocatable :: props(:)
      !> History file, resolved against the case file's directory.
      character(len=:), allocatable :: history_path
      !> 'path:line: &loading: history: ' (the entry's line where the file gives it), to begin the
      !> message of a history file that cannot be opened
      character(len=:), allocatable :: history_entry
      !> CSV output path as written in the case file (resolved later against --output-dir).
      character(len=:), allocatable :: output
      !> 'path:line: &loading: output = '...'' (the entry's line where the file gives it), to
      !> begin the messages that refuse the output
      character(len=:), allocatable :: output_entry
      !> Number of equal sub-increments per history segment (>= 1).
      integer :: increments = 0
      !> Whether a PNG of the traction-separation curves is wanted.
      logical :: plot = .true.
      !> Custom RVE table of the micromechanical model, resolved against the case file's
      !> directory; empty for the built-in table.
      character(len=:), allocatable :: table_path
      !> Tabulated R-curve of the fracture-mechanics law, resolved against the case file's
      !> directory; empty when not used.
      character(len=:), allocatable :: rcurve_path
      !> Mixed control: an increment has converged when every traction-controlled component is
      !> within this of its imposed value (MPa).
      real(dp) :: traction_tolerance = DEFAULT_TRACTION_TOLERANCE
      !> Write every k-th converged step (and the end of every history segment).
      integer :: output_every = 1
      !> Tangent check: the largest relative error of DDSDDE against the central finite
      !> difference allowed (0: no check).
      real(dp) :: tangent_check = 0.0_dp
      !> Tangent check: the finite-difference step on each separation component (mm).
      real(dp) :: tangent_step = DEFAULT_TANGENT_STEP
      !> Where each entry was given (the pre-check's lines): the messages about the files the
      !> case names (`with_entry_line`) name the entry's line.
      type(entry_line_type), allocatable :: lines(:)
   end type case_type

   !> The entries of interphase-point's `&loading` group and their kinds (checked before the
   !> namelist read, with those of `material_entry_kinds('material')`).
   type(entry_kind_type), parameter :: LOADING_ENTRIES(8) = [ &
      entry_kind_type('loading.history', KIND_STRING, ENTRY_LEN), &
      entry_kind_type('loading.output', KIND_STRING, ENTRY_LEN), &
      entry_kind_type('loading.increments', KIND_INTEGER), entry_kind_type('loading.plot', KIND_LOGICAL), &
      entry_kind_type('loading.traction_tolerance', KIND_REAL), entry_kind_type('loading.output_every', KIND_INTEGER), &
      entry_kind_type('loading.tangent_check', KIND_REAL), entry_kind_type('loading.tangent_step', KIND_REAL)]

contains

   !> The pre-check of every case file of the drivers (interphase-point, interphase-fe2d), before
   !> Fortran's namelist read: bounded lines and file size, one group of each name, each entry
   !> once and of its kind (`check_namelist_file`); a file that cannot be opened is named as the
   !> path tried.
   subroutine precheck_case_file(path, known, ok, message, lines, expected_groups)
      character(len=*), intent(in) :: path                 !! case file
      type(entry_kind_type), intent(in) :: known(:)        !! 'group.entry' names and kinds
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message  !! 'file:line: &group: ...' when not ok
      !> the entries' lines, for the messages of the checks after the namelist read
      type(entry_line_type), allocatable, intent(out), optional :: lines(:)
      !> the groups a file without any needs (default: every group of `known`)
      character(len=*), intent(in), optional :: expected_groups
      call check_namelist_file(path, known, ok, message, lines, expected_groups=expected_groups)
      if (.not. ok) then
         if (index(message, path//': cannot open') == 1) message = tried_path(path)//message(len(path) + 1:)
      end if
   end subroutine precheck_case_file

   !> The entries of the interface material's group (`&material` of interphase-point, `&joint`
   !> of interphase-fe2d: the same entries, packed by `material_props`) and their kinds.
   pure function material_entry_kinds(group) result(kinds)
      character(len=*), intent(in) :: group                !! the group's name, lower case
      character(len=*), parameter :: STRINGS(7) = [character(len=11) :: 'model', 'damage_law', 'table', &
         'rcurve', 'rcurve_file', 'growth_slip', 'stiffness']
      character(len=*), parameter :: REALS(12) = [character(len=12) :: 'mu', 's0_n', 'sf_n', 's0_t', 'sf_t', &
         'k_n', 'k_t', 'd0', 'g_ci', 'g_cii', 'contact_band', 'viscosity']
      !> (the strings, the reals, and props)
      type(entry_kind_type) :: kinds(size(STRINGS) + size(REALS) + 1)
      integer :: i
      do i = 1, size(STRINGS)
         kinds(i) = entry_kind_type(group//'.'//trim(STRINGS(i)), KIND_STRING, ENTRY_LEN)
      end do
      do i = 1, size(REALS)
         kinds(size(STRINGS) + i) = entry_kind_type(group//'.'//trim(REALS(i)), KIND_REAL)
      end do
      kinds(size(kinds)) = entry_kind_type(group//'.props', KIND_REAL, count=PROPS_ENTRY_MAX)
   end function material_entry_kinds

   !> Read and check a case file. On failure `ok` is false and `message` says what and where,
   !> always naming the case file. With `material_only` (interphase-calibrate) the `&loading` group
   !> may be left out (run's loading components then keep their defaults); where given it is read
   !> and checked as always.
   subroutine read_case(path, run, ok, message, material_only)
      character(len=*), intent(in) :: path        !! case file path
      type(case_type), intent(out) :: run        !! the case, valid when ok
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      logical, intent(in), optional :: material_only   !! read &material alone (default false)
      integer :: unit, ios
      character(len=512) :: iomsg
      type(entry_line_type), allocatable :: lines(:)
      logical :: with_loading
      character(len=:), allocatable :: groups

      ok = .false.
      run%path = path
      run%name = stem_of(path)
      groups = '&material and &loading'
      if (present(material_only)) then
         if (material_only) groups = '&material'   ! (interphase-calibrate: &loading is optional)
      end if
      ! bounded lines, one group of each name, each entry once and of its kind (and a group at all)
      call precheck_case_file(path, [material_entry_kinds('material'), LOADING_ENTRIES], ok, message, lines, &
         expected_groups=groups)
      if (.not. ok) return
      run%lines = lines
      ok = .false.
      call open_namelist_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = tried_path(path)//': cannot open the case file: '//trim(iomsg)
         return
      end if
      call read_material(unit, run, ok, message)
      ! (material_only: a &loading group that is given is still read, so that its history is known
      ! to writes_an_input; the pre-check's lines name each entry 'group.entry')
      with_loading = .true.
      if (present(material_only)) then
         if (material_only) with_loading = any(index(lines%name, 'loading.') == 1)
      end if
      if (ok .and. with_loading) then
         rewind (unit)
         call read_loading(unit, run, ok, message)
      end if
      close (unit)
      if (.not. ok) then
         message = with_entry_line(message, path, lines)
         return
      end if
      call check_material_props(path, 'material', run%props, ok, message, lines)
      if (allocated(run%output)) &
         run%output_entry = with_entry_line(path//': &loading: output = '''//run%output//'''', path, lines)
      if (allocated(run%history_path)) run%history_entry = with_entry_line(path//': &loading: history: ', path, lines)
   end subroutine read_case

   !> The material's constants as the UMAT decodes them, checked when a case file is read (so that
   !> the drivers refuse them once, in one message naming the case and the group, before any
   !> update or output file): ok false with 'path: &group: why' otherwise, or, where the
   !> constant refused is a case-file entry, 'path:line: &group: entry: why' (the entry's line from
   !> `lines`, the pre-check's).
   subroutine check_material_props(path, group, props, ok, message, lines)
      character(len=*), intent(in) :: path                 !! case file
      character(len=*), intent(in) :: group                !! its material group (material, joint)
      real(dp), intent(in) :: props(:)                     !! PROPS packed from the group
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message
      type(entry_line_type), intent(in), optional :: lines(:)   !! where each entry was given
      type(law_params_type) :: params
      integer :: status
      character(len=MESSAGE_LEN) :: why
      character(len=:), allocatable :: entry
      call from_props(props, params, status, why)
      ok = status == STATUS_OK
      if (ok) return
      entry = props_entry(status, why)
      if (len(entry) == 0) then
         message = path//': &'//group//': '//trim(why)
      else
         message = path//': &'//group//': '//entry//': '//trim(why)
         if (present(lines)) message = with_entry_line(message, path, lines)
      end if
   end subroutine check_material_props

   !> The case-file entry that holds the constant a decoder status refuses (the material group's
   !> names), or '' where none does (the selectors, which the drivers set from their words).
   pure function props_entry(status, why) result(entry)
      integer, intent(in) :: status              !! the decoder's STATUS_BAD_*
      character(len=*), intent(in) :: why        !! its message: 'PROPS(i) symbol = ...'
      character(len=:), allocatable :: entry
      select case (status)
      case (STATUS_BAD_MU);     entry = 'mu'
      case (STATUS_BAD_S0_N);   entry = 's0_n'
      case (STATUS_BAD_SF_N);   entry = 'sf_n'
      case (STATUS_BAD_S0_T);   entry = 's0_t'
      case (STATUS_BAD_SF_T);   entry = 'sf_t'
      case (STATUS_BAD_K_N);    entry = 'k_n'
      case (STATUS_BAD_K_T);    entry = 'k_t'
      case (STATUS_BAD_D0);     entry = 'd0'
      case (STATUS_BAD_RCURVE); entry = 'rcurve'
      case (STATUS_BAD_GC_I);   entry = 'g_ci'
      case (STATUS_BAD_GC_II);  entry = 'g_cii'
      case (STATUS_BAD_OPTION)
         ! (the real options; the selectors are set from the drivers' words)
         if (index(why, ') '//trim(OPTION_SPECS(OPT_CONTACT_BAND)%symbol)//' =') > 0) then
            entry = 'contact_band'
         else if (index(why, ') '//trim(OPTION_SPECS(OPT_VISCOSITY)%symbol)//' =') > 0) then
            entry = 'viscosity'
         else
            entry = ''
         end if
      case default
         entry = ''
      end select
   end function props_entry

   !> Read the `&material` group and pack it into PROPS.
   subroutine read_material(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(case_type), intent(inout) :: run      !! receives props, table_path, rcurve_path
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      type(material_entries_type) :: e
      character(len=ENTRY_LEN) :: model, damage_law, table, rcurve, rcurve_file, growth_slip
      real(dp) :: mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t, d0, g_ci, g_cii, contact_band, viscosity
      character(len=ENTRY_LEN) :: stiffness
      real(dp) :: props(PROPS_ENTRY_MAX)
      namelist /material/ model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t, table, d0, rcurve, &
         rcurve_file, g_ci, g_cii, growth_slip, contact_band, viscosity, stiffness, props
      character(len=:), allocatable :: where
      integer :: ios
      character(len=512) :: iomsg

      ok = .false.
      where = run%path//': &material: '
      call unpack_entries(e, model, damage_law, table, rcurve, rcurve_file, mu, s0_n, sf_n, s0_t, sf_t, &
         k_n, k_t, d0, g_ci, g_cii)
      growth_slip = e%growth_slip
      contact_band = e%contact_band
      viscosity = e%viscosity
      stiffness = e%stiffness
      props = e%props
      read (unit, nml=material, iostat=ios, iomsg=iomsg)
      if (ios == iostat_end) then
         message = where//'group not found (expected "&material ... /")'
         return
      else if (ios /= 0) then
         message = where//'cannot read the group: '//trim(iomsg)
         return
      end if
      e = material_entries_type(model, damage_law, table, rcurve, rcurve_file, mu, s0_n, sf_n, s0_t, &
         sf_t, k_n, k_t, d0, g_ci, g_cii)
      e%growth_slip = growth_slip
      e%contact_band = contact_band
      e%viscosity = viscosity
      e%stiffness = stiffness
      e%props = props
      e%props_count = given_values(run%lines, 'material.props')
      call material_props(e, where, directory_of(run%path), run%props, run%table_path, run%rcurve_path, &
         ok, message)
   end subroutine read_material

   !> Copy the defaults of `e` into the variables of a material namelist (before the read).
   pure subroutine unpack_entries(e, model, damage_law, table, rcurve, rcurve_file, mu, s0_n, sf_n, &
         s0_t, sf_t, k_n, k_t, d0, g_ci, g_cii)
      type(material_entries_type), intent(in) :: e
      character(len=ENTRY_LEN), intent(out) :: model, damage_law, table, rcurve, rcurve_file
      real(dp), intent(out) :: mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t, d0, g_ci, g_cii
      model = e%model
      damage_law = e%damage_law
      table = e%table
      rcurve = e%rcurve
      rcurve_file = e%rcurve_file
      mu = e%mu
      s0_n = e%s0_n
      sf_n = e%sf_n
      s0_t = e%s0_t
      sf_t = e%sf_t
      k_n = e%k_n
      k_t = e%k_t
      d0 = e%d0
      g_ci = e%g_ci
      g_cii = e%g_cii
   end subroutine unpack_entries

   !> Check the entries of a material group and pack them into PROPS (interphase_layout): the
   !> one decoder of interphase-point's `&material` and interphase-fe2d's `&joint`. Paths of a
   !> custom RVE table and of a tabulated R-curve are resolved against `base_dir`.
   subroutine material_props(e, where, base_dir, props, table_path, rcurve_path, ok, message)
      type(material_entries_type), intent(in) :: e   !! the entries as read
      character(len=*), intent(in) :: where          !! message prefix: 'file: &group: '
      character(len=*), intent(in) :: base_dir       !! folder of the case file
      real(dp), allocatable, intent(out) :: props(:)
      character(len=:), allocatable, intent(out) :: table_path, rcurve_path   !! '' when unused
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message

      character(len=:), allocatable :: missing, model, law, rcurve
      type(law_params_type) :: p

      ok = .false.
      message = ''
      table_path = ''
      rcurve_path = ''
      if (e%props_count > 0) then
         call props_material(e, where, base_dir, props, table_path, rcurve_path, ok, message)
         return
      end if
      model = to_lower(trim(adjustl(e%model)))
      law = to_lower(trim(adjustl(e%damage_law)))
      rcurve = to_lower(trim(adjustl(e%rcurve)))
      missing = ''
      if (len(model) == 0) call add_name(missing, 'model')
      if (len(law) == 0) call add_name(missing, 'damage_law')
      if (is_unset(e%mu)) call add_name(missing, 'mu')
      if (is_unset(e%s0_n)) call add_name(missing, 's0_n')
      if (is_unset(e%sf_n)) call add_name(missing, 'sf_n')
      if (is_unset(e%s0_t)) call add_name(missing, 's0_t')
      if (is_unset(e%sf_t)) call add_name(missing, 'sf_t')
      if (model == 'simplified') then
         if (is_unset(e%k_n)) call add_name(missing, 'k_n')
         if (is_unset(e%k_t)) call add_name(missing, 'k_t')
      end if
      if (len(missing) > 0) then
         if (index(missing, ',') > 0) then
            message = where//'missing entries '//missing
         else
            message = where//'missing entry '//missing
         end if
         return
      end if

      select case (model)
      case ('simplified')
         if (len_trim(e%table) > 0) then
            message = where//"table is an entry of model = 'micromechanical' only"
            return
         end if
         p%model = MODEL_SIMPLIFIED
         if (.not. finite_entry('k_n', e%k_n)) return
         if (.not. finite_entry('k_t', e%k_t)) return
         p%k_n = e%k_n
         p%k_t = e%k_t
      case ('micromechanical')
         if (.not. (is_unset(e%k_n) .and. is_unset(e%k_t))) then
            message = where//"k_n and k_t are entries of model = 'simplified' only (the "// &
               "micromechanical model takes its stiffness from the RVE table)"
            return
         end if
         p%model = MODEL_MICROMECHANICAL
         if (len_trim(e%table) == 0) then
            p%table = TABLE_DEFAULT_CODE
         else
            p%table = TABLE_CUSTOM_CODE
            table_path = join_path(base_dir, trim(adjustl(e%table)))
         end if
      case default
         ! (the entry's name first: the message then gets its line)
         message = where//"model '"//trim(adjustl(e%model))// &
            "' is unknown (available: 'simplified', 'micromechanical')"
         return
      end select
      select case (law)
      case ('displacement')
         p%damage_law = DAMAGE_DISPLACEMENT
         if (.not. (is_unset(e%d0) .and. is_unset(e%g_ci) .and. is_unset(e%g_cii)) .or. &
            len(rcurve) > 0 .or. len_trim(e%rcurve_file) > 0) then
            ! (the first of them given named first: the message then gets its line)
            message = where//first_given()//" is an entry of damage_law = 'fracture' only (as are d0, rcurve, "// &
               "rcurve_file, g_ci and g_cii)"
            return
         end if
      case ('fracture')
         p%damage_law = DAMAGE_FRACTURE
         if (is_unset(e%d0)) then
            message = where//"missing entry d0 (initial crack a0/b, needed by damage_law = 'fracture')"
            return
         end if
         if (.not. finite_entry('d0', e%d0)) return
         p%d0 = e%d0
         p%gc_i = 0.0_dp
         p%gc_ii = 0.0_dp
         if (len(rcurve) == 0) then
            message = where//"missing entry rcurve ('constant', 'equivalent' or 'tabulated', needed by "// &
               "damage_law = 'fracture')"
            return
         end if
         select case (rcurve)
         case ('constant')
            ! (the toughnesses left out named, not both when one is given)
            if (is_unset(e%g_ci) .and. is_unset(e%g_cii)) then
               message = where//"rcurve = 'constant' needs the entries g_ci and g_cii (N/mm)"
               return
            else if (is_unset(e%g_ci)) then
               message = where//"rcurve = 'constant' needs the entry g_ci (N/mm; g_cii is given)"
               return
            else if (is_unset(e%g_cii)) then
               message = where//"rcurve = 'constant' needs the entry g_cii (N/mm; g_ci is given)"
               return
            end if
            if (.not. finite_entry('g_ci', e%g_ci)) return
            if (.not. finite_entry('g_cii', e%g_cii)) return
            p%rcurve = RCURVE_CONSTANT
            p%gc_i = e%g_ci
            p%gc_ii = e%g_cii
         case ('equivalent')
            p%rcurve = RCURVE_EQUIVALENT
         case ('tabulated')
            if (len_trim(e%rcurve_file) == 0) then
               message = where//"rcurve = 'tabulated' needs the entry rcurve_file"
               return
            end if
            p%rcurve = RCURVE_TABULATED
            rcurve_path = join_path(base_dir, trim(adjustl(e%rcurve_file)))
         case default
            message = where//"rcurve must be 'constant', 'equivalent' or 'tabulated', got '"// &
               trim(adjustl(e%rcurve))//"'"
            return
         end select
         if (rcurve /= 'constant' .and. .not. (is_unset(e%g_ci) .and. is_unset(e%g_cii))) then
            message = where//"g_ci and g_cii are entries of rcurve = 'constant' only"
            return
         end if
         if (rcurve /= 'tabulated' .and. len_trim(e%rcurve_file) > 0) then
            message = where//"rcurve_file is an entry of rcurve = 'tabulated' only (rcurve = '"//rcurve// &
               "' would not read '"//trim(adjustl(e%rcurve_file))//"')"
            return
         end if
      case default
         message = where//"damage_law '"//trim(adjustl(e%damage_law))// &
            "' is unknown (available: 'displacement', 'fracture')"
         return
      end select

      if (.not. finite_entry('mu', e%mu)) return
      if (.not. finite_entry('s0_n', e%s0_n)) return
      if (.not. finite_entry('sf_n', e%sf_n)) return
      if (.not. finite_entry('s0_t', e%s0_t)) return
      if (.not. finite_entry('sf_t', e%sf_t)) return
      p%mu = e%mu
      p%s0_n = e%s0_n
      p%sf_n = e%sf_n
      p%s0_t = e%s0_t
      p%sf_t = e%sf_t
      ! the option settings (their defaults unless given)
      if (.not. keyword_entry('growth_slip', e%growth_slip, [character(len=12) :: 'fixed-pi', 'fixed-lambda'], &
         [GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA], "'fixed-pi' (the default) or 'fixed-lambda' (the paper's form)", &
         p%growth_slip)) return
      if (.not. is_unset(e%contact_band)) then
         if (.not. finite_entry('contact_band', e%contact_band)) return
         p%contact_band = e%contact_band
      end if
      if (.not. is_unset(e%viscosity)) then
         if (.not. finite_entry('viscosity', e%viscosity)) return
         p%viscosity = e%viscosity
      end if
      if (.not. keyword_entry('stiffness', e%stiffness, STIFFNESS_WORDS, &
         [STIFFNESS_CONSISTENT, STIFFNESS_SYMMETRIC, STIFFNESS_FIXED_DAMAGE], &
         "'consistent' (the default), 'symmetric' or 'fixed-damage'", p%stiffness)) return
      ! PROPS from the one encoder (interphase_params); the values are checked by the UMAT's
      ! decoder, whose message names the PROPS index
      props = to_props(p)
      ok = .true.

   contains

      !> The code of an option entry given as one of `keywords` (any case; '' is the first, the
      !> default); false (and the message set, naming the entry and `choices`) for another word.
      logical function keyword_entry(name, value, keywords, codes, choices, code)
         character(len=*), intent(in) :: name, value    !! entry name, its value as read
         character(len=*), intent(in) :: keywords(:)    !! the words it takes
         integer, intent(in) :: codes(:)                !! their codes
         character(len=*), intent(in) :: choices        !! the words, for the message
         integer, intent(inout) :: code                 !! the code, set when found
         integer :: k
         character(len=:), allocatable :: word
         word = to_lower(trim(adjustl(value)))
         if (len(word) == 0) word = trim(keywords(1))
         keyword_entry = .false.
         do k = 1, size(keywords)
            if (word == trim(keywords(k))) then
               code = codes(k)
               keyword_entry = .true.
               return
            end if
         end do
         message = where//name//" must be "//choices//", got '"//trim(adjustl(value))//"'"
      end function keyword_entry

      !> The first of the fracture law's entries that is given (for the message that refuses them).
      function first_given() result(name)
         character(len=:), allocatable :: name
         if (.not. is_unset(e%d0)) then
            name = 'd0'
         else if (len(rcurve) > 0) then
            name = 'rcurve'
         else if (len_trim(e%rcurve_file) > 0) then
            name = 'rcurve_file'
         else if (.not. is_unset(e%g_ci)) then
            name = 'g_ci'
         else
            name = 'g_cii'
         end if
      end function first_given

      !> False (and the message set) when the entry is NaN or infinite.
      logical function finite_entry(name, value)
         character(len=*), intent(in) :: name     !! entry name
         real(dp), intent(in) :: value            !! its value

         finite_entry = ieee_is_finite(value)
         if (.not. finite_entry) message = where//name//' is not a finite number'
      end function finite_entry

   end subroutine material_props

   !> The material given as the UMAT's PROPS (the `props` entry of a material group): the values
   !> one after another from PROPS(1), as an Abaqus *USER MATERIAL lists them, decoded by the
   !> UMAT's own decoder (its message, naming the PROPS index, on failure). The other entries
   !> are left out but the files PROPS cannot hold: `table` where PROPS select a custom RVE table,
   !> `rcurve_file` where they select a tabulated R-curve (each needed there, and refused
   !> elsewhere), resolved against `base_dir`.
   subroutine props_material(e, where, base_dir, props, table_path, rcurve_path, ok, message)
      type(material_entries_type), intent(in) :: e   !! the entries as read, props given
      character(len=*), intent(in) :: where          !! message prefix: 'file: &group: '
      character(len=*), intent(in) :: base_dir       !! folder of the case file
      real(dp), allocatable, intent(out) :: props(:)
      character(len=:), allocatable, intent(inout) :: table_path, rcurve_path   !! '' when unused
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(inout) :: message
      type(law_params_type) :: p
      character(len=:), allocatable :: given
      character(len=MESSAGE_LEN) :: why
      integer :: n, status

      ok = .false.
      ! (the pre-check took the values as one list from PROPS(1), 1 to PROPS_ENTRY_MAX of them:
      ! `props(3) = ...` is not an entry)
      n = e%props_count
      given = ''
      if (len_trim(e%model) > 0) call add_name(given, 'model')
      if (len_trim(e%damage_law) > 0) call add_name(given, 'damage_law')
      if (.not. is_unset(e%mu)) call add_name(given, 'mu')
      if (.not. is_unset(e%s0_n)) call add_name(given, 's0_n')
      if (.not. is_unset(e%sf_n)) call add_name(given, 'sf_n')
      if (.not. is_unset(e%s0_t)) call add_name(given, 's0_t')
      if (.not. is_unset(e%sf_t)) call add_name(given, 'sf_t')
      if (.not. is_unset(e%k_n)) call add_name(given, 'k_n')
      if (.not. is_unset(e%k_t)) call add_name(given, 'k_t')
      if (.not. is_unset(e%d0)) call add_name(given, 'd0')
      if (len_trim(e%rcurve) > 0) call add_name(given, 'rcurve')
      if (.not. is_unset(e%g_ci)) call add_name(given, 'g_ci')
      if (.not. is_unset(e%g_cii)) call add_name(given, 'g_cii')
      if (len_trim(e%growth_slip) > 0) call add_name(given, 'growth_slip')
      if (.not. is_unset(e%contact_band)) call add_name(given, 'contact_band')
      if (.not. is_unset(e%viscosity)) call add_name(given, 'viscosity')
      if (len_trim(e%stiffness) > 0) call add_name(given, 'stiffness')
      if (len(given) > 0) then
         message = where//'props gives the whole material as the UMAT''s PROPS: leave out '//given// &
            ' (or give the material by its entries, without props)'
         return
      end if
      props = e%props(1:n)
      call from_props(props, p, status, why)
      ! (the thin-layer mode and the host conventions would read the history's separations as
      ! strains or change what the outputs mean: the drivers refuse them, as the C API does)
      if (status == STATUS_OK) call refuse_umat_options(p, 'this driver', status, why)
      if (status /= STATUS_OK) then
         message = where//'props: '//trim(why)
         return
      end if
      ! the files PROPS cannot name: each given exactly where PROPS select it
      if (.not. file_entry(p%model == MODEL_MICROMECHANICAL .and. p%table == TABLE_CUSTOM_CODE, e%table, &
         'props: PROPS(8) = 1 selects a custom RVE table: give its file as the entry table', &
         'table is read only where props select a custom RVE table (the micromechanical model with PROPS(8) = 1)', &
         table_path)) return
      if (.not. file_entry(p%damage_law == DAMAGE_FRACTURE .and. p%rcurve == RCURVE_TABULATED, e%rcurve_file, &
         'props: PROPS('//int_to_string(merge(NPROPS_MICROMECHANICAL, NPROPS_SIMPLIFIED, p%model == MODEL_MICROMECHANICAL) &
         + LFM_RCURVE)//') = 3 selects a tabulated R-curve: give its file as the entry rcurve_file', &
         'rcurve_file is read only where props select a tabulated R-curve (the fracture law with its R-curve code 3)', &
         rcurve_path)) return
      ok = .true.

   contains

      !> A file entry (`value`, '' when left out) where PROPS select its file (`selected`): needed
      !> there (else the message `missing`), its path resolved against base_dir; refused elsewhere
      !> (the message `refused`). False where the message is set.
      logical function file_entry(selected, value, missing, refused, path) result(good)
         logical, intent(in) :: selected
         character(len=*), intent(in) :: value, missing, refused
         character(len=:), allocatable, intent(inout) :: path
         good = .false.
         if (selected) then
            if (len_trim(value) == 0) then
               message = where//missing
               return
            end if
            path = join_path(base_dir, trim(adjustl(value)))
         else if (len_trim(value) > 0) then
            message = where//refused
            return
         end if
         good = .true.
      end function file_entry

   end subroutine props_material

   !> The entry of material group `group` that holds D0 in a case file whose pre-check found
   !> `lines`: 'props' where the material is given as PROPS, else 'd0'.
   pure function d0_entry_of(lines, group) result(entry)
      type(entry_line_type), intent(in) :: lines(:)
      character(len=*), intent(in) :: group                !! 'material' or 'joint'
      character(len=:), allocatable :: entry
      entry = 'd0'
      if (given_values(lines, group//'.props') > 0) entry = 'props'
   end function d0_entry_of

   !> Read the `&loading` group.
   subroutine read_loading(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(case_type), intent(inout) :: run      !! receives history_path, increments, output, plot
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      character(len=ENTRY_LEN) :: history, output
      integer :: increments, output_every
      logical :: plot
      real(dp) :: traction_tolerance, tangent_check, tangent_step
      namelist /loading/ history, increments, output, plot, traction_tolerance, output_every, tangent_check, &
         tangent_step
      character(len=:), allocatable :: missing, where
      integer :: ios
      character(len=512) :: iomsg

      ok = .false.
      where = run%path//': &loading: '
      history = ''
      output = ''
      increments = UNSET_INTEGER
      plot = .true.
      traction_tolerance = DEFAULT_TRACTION_TOLERANCE
      output_every = 1
      tangent_check = 0.0_dp
      tangent_step = UNSET_REAL
      read (unit, nml=loading, iostat=ios, iomsg=iomsg)
      if (ios == iostat_end) then
         message = where//'group not found (expected "&loading ... /")'
         return
      else if (ios /= 0) then
         message = where//'cannot read the group: '//trim(iomsg)
         return
      end if

      missing = ''
      if (len_trim(history) == 0) call add_name(missing, 'history')
      if (increments == UNSET_INTEGER) call add_name(missing, 'increments')
      if (len_trim(output) == 0) call add_name(missing, 'output')
      if (len(missing) > 0) then
         if (index(missing, ',') > 0) then
            message = where//'missing entries '//missing
         else
            message = where//'missing entry '//missing
         end if
         return
      end if
      if (increments < 1) then
         message = where//'increments must be at least 1, got '//int_to_string(increments)
         return
      end if

      if (.not. (traction_tolerance > 0.0_dp .and. traction_tolerance <= TRACTION_TOLERANCE_MAX)) then
         ! (1e-3: TRACTION_TOLERANCE_MAX)
         message = where//'traction_tolerance must be a finite number > 0 and at most 1e-3 (MPa), got '// &
            real_to_string(traction_tolerance)// &
            ': Newton meets an imposed traction only to within it (joints carry tractions of 0.01 to 10 MPa)'
         return
      end if
      if (output_every < 1) then
         message = where//'output_every must be at least 1, got '//int_to_string(output_every)
         return
      end if
      if (.not. (tangent_check >= 0.0_dp .and. ieee_is_finite(tangent_check))) then
         message = where//'tangent_check must be a finite number >= 0 (0: no check), got '//real_to_string(tangent_check)
         return
      end if
      if (tangent_check >= 1.0_dp) then
         ! (the relative error max|FD - DDSDDE|/max|DDSDDE| of a tangent off by its own size is 1)
         message = where//'tangent_check = '//real_to_string(tangent_check)//' would pass a tangent wrong by '// &
            'its own size or more (a relative error >= 1): it must be < 1 (e.g. 1e-5; 0: no check)'
         return
      end if
      if (is_unset(tangent_step)) then
         tangent_step = DEFAULT_TANGENT_STEP
      else if (.not. tangent_check > 0.0_dp) then
         ! (the step of a check that is not made: refused, not ignored)
         message = where//'tangent_step is an entry of the tangent check only: set tangent_check > 0 too, or '// &
            'drop tangent_step'
         return
      end if
      if (.not. (tangent_step > 0.0_dp .and. ieee_is_finite(tangent_step))) then
         message = where//'tangent_step must be a finite number > 0 (mm), got '//real_to_string(tangent_step)
         return
      end if
      run%traction_tolerance = traction_tolerance
      run%output_every = output_every
      run%tangent_check = tangent_check
      run%tangent_step = tangent_step
      run%history_path = join_path(directory_of(run%path), trim(adjustl(history)))
      run%output = trim(adjustl(output))
      run%increments = increments
      run%plot = plot
      ok = .true.
   end subroutine read_loading

   !> One line naming the material of PROPS for consoles and plot titles: model, damage law and
   !> key parameters, e.g. 'simplified model, displacement law: mu = 0.75, s0_N = 0.00044 mm,
   !> ..., K_N = 482.7 MPa/mm' (the fracture law: D0 and the R-curve; the options that are not
   !> their default). PROPS that do not decode give the model code only.
   function material_summary(props) result(text)
      real(dp), intent(in) :: props(:)            !! PROPS (interphase_layout)
      character(len=:), allocatable :: text
      type(law_params_type) :: p
      integer :: status
      character(len=MESSAGE_LEN) :: why

      call from_props(props, p, status, why)
      if (status /= STATUS_OK) then
         text = 'PROPS that do not decode ('//trim(why)//')'
         return
      end if
      if (p%model == MODEL_SIMPLIFIED) then
         text = 'simplified model'
      else
         text = 'micromechanical model'
         if (p%table == TABLE_CUSTOM_CODE) then
            text = text//' (custom RVE table)'
         else
            text = text//' (built-in RVE table)'
         end if
      end if
      if (p%damage_law == DAMAGE_FRACTURE) then
         text = text//', fracture law'
      else
         text = text//', displacement law'
      end if
      text = text//': mu = '//short(p%mu)//', s0_N = '//short(p%s0_n)//', sf_N = '//short(p%sf_n)// &
         ', s0_T = '//short(p%s0_t)//', sf_T = '//short(p%sf_t)//' mm'
      if (p%model == MODEL_SIMPLIFIED) text = text//', K_N = '//short(p%k_n)//', K_T = '//short(p%k_t)//' MPa/mm'
      if (p%damage_law == DAMAGE_FRACTURE) then
         text = text//', D0 = '//short(p%d0)
         select case (p%rcurve)
         case (RCURVE_CONSTANT)
            text = text//', G_cI = '//short(p%gc_i)//', G_cII = '//short(p%gc_ii)//' N/mm'
         case (RCURVE_EQUIVALENT)
            text = text//', equivalent R-curve'
         case (RCURVE_TABULATED)
            text = text//', tabulated R-curve'
         end select
      end if
      if (p%viscosity > 0.0_dp) text = text//', eta = '//short(p%viscosity)//' s'
      ! (the options that change the response, where they are not the default; the contact band
      ! changes nothing in the simplified model, which has no closing jump: named as such, that a
      ! band given to it is not taken for one at work)
      if (p%contact_band > 0.0_dp) then
         text = text//', chi = '//short(p%contact_band)
         if (p%model == MODEL_SIMPLIFIED) text = text//' (no effect: the simplified model has no closing jump)'
      end if
      if (p%growth_slip == GROWTH_FIXED_LAMBDA) text = text//', growth_slip fixed-lambda'
      if (p%stiffness /= STIFFNESS_CONSISTENT) text = text//', stiffness '//trim(STIFFNESS_WORDS(p%stiffness))
   contains
      !> Four significant digits, plain for 1e-5 <= |value| < 1e6 (0.00044, 482.7), else 1.234E-07.
      function short(value) result(t)
         real(dp), intent(in) :: value
         character(len=:), allocatable :: t
         character(len=32) :: buffer
         character(len=16) :: form
         integer :: decimals
         if (abs(value) >= 1.0e-5_dp .and. abs(value) < 1.0e6_dp) then
            decimals = max(0, 3 - floor(log10(abs(value))))
            write (form, '(a,i0,a)') '(f0.', decimals, ')'
            write (buffer, form) value
            t = trim(adjustl(buffer))
            if (index(t, '.') > 0) then
               do while (t(len(t):len(t)) == '0')
                  t = t(:len(t) - 1)
               end do
               if (t(len(t):len(t)) == '.') t = t(:len(t) - 1)
            end if
            if (t(1:1) == '.') t = '0'//t
            if (len(t) > 1) then
               if (t(1:2) == '-.') t = '-0'//t(2:)
            end if
         else if (.not. abs(value) > 0.0_dp) then
            t = '0'
         else
            write (buffer, '(es11.3e3)') value
            t = trim(adjustl(buffer))
         end if
      end function short
   end function material_summary

   !> The files a material's PROPS cannot name, for consoles and logs beside material_summary:
   !> 'custom RVE table PATH' and 'tabulated R-curve PATH' (the paths as resolved from the case
   !> file), joined by '; ', or '' when the material uses neither.
   function data_files_summary(table_path, rcurve_path) result(text)
      character(len=*), intent(in) :: table_path, rcurve_path   !! '' when unused
      character(len=:), allocatable :: text
      text = ''
      if (len_trim(table_path) > 0) text = 'custom RVE table '//trim(table_path)
      if (len_trim(rcurve_path) > 0) then
         if (len(text) > 0) text = text//'; '
         text = text//'tabulated R-curve '//trim(rcurve_path)
      end if
   end function data_files_summary

   !> Whether writing `path` would replace an input of the run: the case file, its history (when
   !> &loading was read), RVE table or R-curve file (the paths resolved: same_file). One comparison
   !> a statement: same_file is not pure, and GCC may skip an impure call in an .or. chain.
   logical function writes_an_input(run, path)
      type(case_type), intent(in) :: run
      character(len=*), intent(in) :: path
      writes_an_input = same_file(path, run%path)
      if (.not. writes_an_input .and. allocated(run%history_path)) writes_an_input = same_file(path, run%history_path)
      if (.not. writes_an_input .and. len(run%table_path) > 0) writes_an_input = same_file(path, run%table_path)
      if (.not. writes_an_input .and. len(run%rcurve_path) > 0) writes_an_input = same_file(path, run%rcurve_path)
   end function writes_an_input

   !> True when a real entry still holds UNSET_REAL (a NaN from the file is not "unset").
   elemental logical function is_unset(value)
      real(dp), intent(in) :: value               !! the entry after the namelist read

      if (ieee_is_nan(value)) then
         is_unset = .false.
      else
         is_unset = value >= UNSET_REAL .and. value <= UNSET_REAL
      end if
   end function is_unset

   !> Append a name to a comma-separated list.
   pure subroutine add_name(list, name)
      character(len=:), allocatable, intent(inout) :: list  !! 'a, b' or ''
      character(len=*), intent(in) :: name        !! name to append

      if (len(list) == 0) then
         list = name
      else
         list = list//', '//name
      end if
   end subroutine add_name

   !> Start-up, as UEXTERNALDB does in Abaqus: read the custom RVE table and the tabulated R-curve
   !> a case names (empty path: none), once, before any update. A refusal names where the file
   !> was given: `context` (the case file and group, e.g. 'case.nml: &material: '), then the entry
   !> (`with_entry_line` then adds the entry's line). With `props`, the material's data are checked
   !> as the UMAT checks them at its every call (check_run_time_data): a tabulated R-curve that
   !> does not cover the initial crack D0 is refused here, under the entry d0 (or `d0_entry`),
   !> with the file's D range and D0, rather than at the first update.
   subroutine load_start_up_data(table_path, rcurve_path, context, ok, message, rcurve_entry, props, d0_entry)
      character(len=*), intent(in) :: table_path   !! custom RVE table, or ''
      character(len=*), intent(in) :: rcurve_path  !! tabulated R-curve, or ''
      character(len=*), intent(in) :: context      !! the case file and group that name them
      logical, intent(out) :: ok                   !! true when everything named was read
      character(len=:), allocatable, intent(out) :: message  !! the reason when not ok
      !> the entry that names the R-curve file (default rcurve_file, as &material and &joint)
      character(len=*), intent(in), optional :: rcurve_entry
      !> the case's PROPS, to check the data loaded against (the R-curve's coverage of D0)
      real(dp), intent(in), optional :: props(:)
      !> the entry that holds D0 (default d0; props where the case gives the material as PROPS)
      character(len=*), intent(in), optional :: d0_entry
      integer :: status
      character(len=MESSAGE_LEN) :: text
      type(law_params_type) :: params

      ok = .true.
      message = ''
      status = STATUS_OK
      if (len(table_path) > 0) then
         call load_custom_table(table_path, status, text)
         message = context//'table: '
      end if
      if (status == STATUS_OK .and. len(rcurve_path) > 0) then
         call load_rcurve(rcurve_path, status, text)
         message = context//'rcurve_file: '
         if (present(rcurve_entry)) message = context//rcurve_entry//': '
      end if
      if (status == STATUS_OK .and. len(rcurve_path) > 0 .and. present(props)) then
         ! (the UMAT's own check and words; PROPS that do not decode were refused with the case)
         call from_props(props, params, status, text)
         if (status == STATUS_OK) then
            call check_run_time_data(params, status, text)
            ! (an R-curve that does not cover the initial crack is the entry d0's; any other
            ! refusal of the data loaded is named by the group alone)
            message = context
            if (status == STATUS_RCURVE_OUT_OF_RANGE) then
               message = context//'d0: '
               if (present(d0_entry)) message = context//d0_entry//': '
            end if
         else
            status = STATUS_OK
         end if
      end if
      ! (message holds where the last file read was named; it is kept only with its refusal)
      if (status == STATUS_OK) then
         message = ''
      else
         ok = .false.
         message = message//status_message(status)//': '//trim(text)
      end if
   end subroutine load_start_up_data

end module interphase_driver_case
