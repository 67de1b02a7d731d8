!> Case files of the structural host `interphase-fe2d`: the namelist groups `&geometry`,
!> `&mesh`, `&brick`, `&joint` and `&loading` (drivers/fe2d/README.md lists every entry).
!> The interface material of `&joint` is packed into the UMAT's PROPS exactly as
!> docs/abaqus.md documents; its ranges are checked by `umat` itself. Nothing is stopped here:
!> errors come back as a message naming the case file and the group.
module interphase_fe2d_case
   use, intrinsic :: iso_fortran_env, only: iostat_end
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use interphase_kinds, only: dp
   use interphase_params, only: PROPS_VALUE_MIN, PROPS_VALUE_MAX
   use interphase_finite, only: difference_is_finite
   use interphase_text_input, only: tried_path, clip_text
   use interphase_driver_case, only: material_entries_type, material_props, unpack_entries, &
      ENTRY_LEN, precheck_case_file, material_entry_kinds, check_material_props, PROPS_ENTRY_MAX
   use interphase_driver_namelist, only: entry_kind_type, entry_line_type, with_entry_line, given_values, KIND_REAL, KIND_INTEGER, &
      KIND_LOGICAL, KIND_STRING, open_namelist_file
   use interphase_driver_history, only: carriage_return_message, parse_number, separator_hint, foreign_length_unit_after
   use interphase_driver_text, only: int_to_string, count_text, real_to_string, to_lower, directory_of, &
      stem_of, join_path, read_line, split_words, text_file_type, open_line_file, close_text_file
   implicit none
   private
   public :: fe2d_case_type, read_fe2d_case, read_shear_history, SIDES_FREE, SIDES_PERIODIC, &
      INTEGRATION_LOBATTO, INTEGRATION_GAUSS

   !> Lateral faces of the bricks: traction-free (the laboratory test).
   integer, parameter :: SIDES_FREE = 1
   !> Lateral faces tied periodically (left and right node at the same height share their
   !> displacements): uniform states are then exact solutions (patch checks).
   integer, parameter :: SIDES_PERIODIC = 2
   !> Interface-element integration at the nodes (2-point Lobatto / Newton-Cotes).
   integer, parameter :: INTEGRATION_LOBATTO = 1
   !> Interface-element integration at the 2 Gauss points.
   integer, parameter :: INTEGRATION_GAUSS = 2

   !> Everything one analysis needs.
   type :: fe2d_case_type
      character(len=:), allocatable :: path            !! case file
      character(len=:), allocatable :: name            !! case file stem
      ! &geometry
      integer :: bricks = 2                            !! 2 (couplet) or 3 (triplet)
      real(dp) :: brick_length = 200.0_dp              !! L (mm), along the joint (x)
      real(dp) :: brick_height = 50.0_dp               !! H (mm), across the joint (y)
      real(dp) :: thickness = 100.0_dp                 !! out-of-plane thickness (mm)
      integer :: sides = SIDES_FREE                    !! SIDES_FREE or SIDES_PERIODIC
      ! &mesh
      integer :: nx = 8                                !! elements per brick along x
      integer :: ny = 2                                !! elements per brick along y
      integer :: integration = INTEGRATION_LOBATTO     !! interface-element rule
      ! &brick
      real(dp) :: young = 16000.0_dp                   !! E_b (MPa)
      real(dp) :: poisson = 0.15_dp                    !! nu_b (-)
      ! &joint
      real(dp), allocatable :: props(:)                !! UMAT PROPS (docs/abaqus.md)
      character(len=:), allocatable :: table_path      !! custom RVE table or ''
      character(len=:), allocatable :: rcurve_path     !! tabulated R-curve or ''
      ! &loading
      real(dp) :: precompression = 0.0_dp              !! normal pressure on the top face (MPa)
      integer :: precompression_increments = 1         !! increments of the precompression step
      character(len=:), allocatable :: history_path    !! t / u_shear table
      real(dp), allocatable :: history_t(:)            !! history times
      real(dp), allocatable :: history_u(:)            !! prescribed shear displacement (mm)
      integer :: increments = 10                       !! nominal increments per history segment
      real(dp) :: tolerance = 1.0e-8_dp                !! relative residual norm
      real(dp) :: displacement_tolerance = 1.0e-6_dp   !! relative correction norm
      integer :: max_iterations = 15                   !! Newton iterations before a cut-back
      real(dp) :: min_increment = 1.0e-6_dp            !! smallest increment / nominal one
      character(len=:), allocatable :: output          !! CSV path (relative to --output-dir)
      !> 'path:line: &loading: output = '...'' (the entry's line where the file gives it), to
      !> begin the messages that refuse the output
      character(len=:), allocatable :: output_entry
      logical :: plot = .true.                         !! PNG wanted
      !> assemble only the symmetric part of DDSDDE (as CalculiX does, and Abaqus without
      !> UNSYMM): `&loading assembly = 'symmetric'`; default 'unsymmetric'
      logical :: symmetric_assembly = .false.
      !> Where each entry was given (the pre-check's lines): the messages about the files the
      !> case names (`with_entry_line`) name the entry's line.
      type(entry_line_type), allocatable :: lines(:)
   end type fe2d_case_type

   !> The entries of the groups other than `&joint` (whose entries are the point driver's
   !> `&material` ones, `material_entry_kinds`) and their kinds, for the pre-check.
   type(entry_kind_type), parameter :: FE2D_ENTRIES(21) = [ &
      entry_kind_type('geometry.bricks', KIND_INTEGER), entry_kind_type('geometry.brick_length', KIND_REAL), &
      entry_kind_type('geometry.brick_height', KIND_REAL), entry_kind_type('geometry.thickness', KIND_REAL), &
      entry_kind_type('geometry.sides', KIND_STRING, ENTRY_LEN), entry_kind_type('mesh.nx', KIND_INTEGER), &
      entry_kind_type('mesh.ny', KIND_INTEGER), entry_kind_type('mesh.integration', KIND_STRING, ENTRY_LEN), &
      entry_kind_type('brick.e', KIND_REAL), entry_kind_type('brick.nu', KIND_REAL), &
      entry_kind_type('loading.precompression', KIND_REAL), &
      entry_kind_type('loading.precompression_increments', KIND_INTEGER), &
      entry_kind_type('loading.history', KIND_STRING, ENTRY_LEN), entry_kind_type('loading.increments', KIND_INTEGER), &
      entry_kind_type('loading.tolerance', KIND_REAL), entry_kind_type('loading.displacement_tolerance', KIND_REAL), &
      entry_kind_type('loading.max_iterations', KIND_INTEGER), entry_kind_type('loading.min_increment', KIND_REAL), &
      entry_kind_type('loading.output', KIND_STRING, ENTRY_LEN), entry_kind_type('loading.plot', KIND_LOGICAL), &
      entry_kind_type('loading.assembly', KIND_STRING, ENTRY_LEN)]

contains

   !> Read and check a case file and its shear history.
   subroutine read_fe2d_case(path, run, ok, message)
      character(len=*), intent(in) :: path        !! case file
      type(fe2d_case_type), intent(out) :: run    !! the case, valid when ok
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      integer :: unit, ios
      character(len=512) :: iomsg
      type(entry_line_type), allocatable :: lines(:)

      ok = .false.
      run%path = path
      run%name = stem_of(path)
      ! the drivers' one pre-check: bounded lines and size, one group of each name, each entry
      ! once and of its kind
      call precheck_case_file(path, [FE2D_ENTRIES, material_entry_kinds('joint')], ok, message, lines)
      if (.not. ok) return
      ! (the entries' lines, kept before the groups are read: read_joint counts props' values)
      run%lines = lines
      ok = .false.
      call open_namelist_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         message = path//': cannot open the case file: '//trim(iomsg)
         return
      end if
      call read_geometry(unit, run, ok, message)
      if (ok) call read_mesh(unit, run, ok, message)
      if (ok) call read_brick(unit, run, ok, message)
      if (ok) call read_joint(unit, run, ok, message)
      if (ok) call read_loading(unit, run, ok, message)
      close (unit)
      ! a check after the namelist read names its entry's line too
      if (.not. ok) message = with_entry_line(message, path, lines)
      if (ok) call check_material_props(path, 'joint', run%props, ok, message, lines)
      if (ok) run%output_entry = with_entry_line(path//': &loading: output = '''//run%output//'''', path, lines)
      if (ok) call read_shear_history(run%history_path, run%history_t, run%history_u, ok, message, &
         named_by=with_entry_line(path//': &loading: history: ', path, lines))
   end subroutine read_fe2d_case

   subroutine read_geometry(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(fe2d_case_type), intent(inout) :: run  !! receives the geometry
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      integer :: bricks
      real(dp) :: brick_length, brick_height, thickness
      character(len=ENTRY_LEN) :: sides
      namelist /geometry/ bricks, brick_length, brick_height, thickness, sides
      character(len=:), allocatable :: where

      where = run%path//': &geometry: '
      bricks = run%bricks
      brick_length = run%brick_length
      brick_height = run%brick_height
      thickness = run%thickness
      sides = 'free'
      call read_group(unit, 'geometry', ok, message)
      if (.not. ok) return
      ok = .false.
      if (bricks /= 2 .and. bricks /= 3) then
         message = where//'bricks must be 2 (couplet) or 3 (triplet), got '//int_to_string(bricks)
         return
      end if
      if (.not. in_window(brick_length, 'brick_length')) return
      if (.not. in_window(brick_height, 'brick_height')) return
      if (.not. in_window(thickness, 'thickness')) return
      select case (to_lower(trim(adjustl(sides))))
      case ('free')
         run%sides = SIDES_FREE
      case ('periodic')
         run%sides = SIDES_PERIODIC
      case default
         ! (the entry's name first: the message then gets its line)
         message = where//"sides must be 'free' or 'periodic', got '"//trim(adjustl(sides))//"'"
         return
      end select
      run%bricks = bricks
      run%brick_length = brick_length
      run%brick_height = brick_height
      run%thickness = thickness
      ok = .true.
   contains
      subroutine read_group(unit, group, ok, message)
         integer, intent(in) :: unit
         character(len=*), intent(in) :: group
         logical, intent(out) :: ok
         character(len=:), allocatable, intent(out) :: message
         integer :: ios
         character(len=512) :: iomsg
         rewind (unit)
         read (unit, nml=geometry, iostat=ios, iomsg=iomsg)
         call group_status(run%path, group, ios, iomsg, ok, message)
      end subroutine read_group
      logical function in_window(value, name)
         real(dp), intent(in) :: value
         character(len=*), intent(in) :: name
         in_window = check_window(where, name, value, message)
      end function in_window
   end subroutine read_geometry

   subroutine read_mesh(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(fe2d_case_type), intent(inout) :: run  !! receives the mesh density
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      integer :: nx, ny, ios
      character(len=ENTRY_LEN) :: integration
      character(len=512) :: iomsg
      namelist /mesh/ nx, ny, integration
      character(len=:), allocatable :: where

      where = run%path//': &mesh: '
      nx = run%nx
      ny = run%ny
      integration = 'lobatto'
      rewind (unit)
      read (unit, nml=mesh, iostat=ios, iomsg=iomsg)
      call group_status(run%path, 'mesh', ios, iomsg, ok, message)
      if (.not. ok) return
      ok = .false.
      if (nx < 1 .or. ny < 1) then
         message = where//'nx and ny must be at least 1, got nx = '//int_to_string(nx)// &
            ', ny = '//int_to_string(ny)
         return
      end if
      if (nx > 400 .or. ny > 200) then
         message = where//'nx <= 400 and ny <= 200 (dense enough for this host), got nx = '// &
            int_to_string(nx)//', ny = '//int_to_string(ny)
         return
      end if
      select case (to_lower(trim(adjustl(integration))))
      case ('lobatto', 'newton-cotes')
         run%integration = INTEGRATION_LOBATTO
      case ('gauss')
         run%integration = INTEGRATION_GAUSS
      case default
         message = where//"integration must be 'lobatto' or 'gauss', got '"//trim(adjustl(integration))//"'"
         return
      end select
      run%nx = nx
      run%ny = ny
      ok = .true.
   end subroutine read_mesh

   subroutine read_brick(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(fe2d_case_type), intent(inout) :: run  !! receives E and nu
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      real(dp) :: e, nu
      integer :: ios
      character(len=512) :: iomsg
      namelist /brick/ e, nu
      character(len=:), allocatable :: where

      where = run%path//': &brick: '
      e = run%young
      nu = run%poisson
      rewind (unit)
      read (unit, nml=brick, iostat=ios, iomsg=iomsg)
      call group_status(run%path, 'brick', ios, iomsg, ok, message)
      if (.not. ok) return
      ok = check_window(where, 'e', e, message)
      if (.not. ok) return
      ok = .false.
      if (.not. ieee_is_finite(nu)) then
         message = where//'nu must be finite'
         return
      end if
      if (.not. (nu > -1.0_dp .and. nu < 0.5_dp)) then
         message = where//'nu must be in (-1, 0.5), got '//real_to_string(nu)
         return
      end if
      run%young = e
      run%poisson = nu
      ok = .true.
   end subroutine read_brick

   !> `&joint`: the interface material, as the `&material` group of interphase-point (the same
   !> entries and the same decoder, `material_props`); damage_law defaults to 'displacement' where
   !> the joint is given by its entries (not by props, the UMAT's PROPS).
   subroutine read_joint(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(fe2d_case_type), intent(inout) :: run  !! receives props, table_path, rcurve_path
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      type(material_entries_type) :: e
      character(len=ENTRY_LEN) :: model, damage_law, table, rcurve, rcurve_file, growth_slip
      real(dp) :: mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t, d0, g_ci, g_cii, contact_band, viscosity
      character(len=ENTRY_LEN) :: stiffness
      real(dp) :: props(PROPS_ENTRY_MAX)
      namelist /joint/ model, damage_law, mu, s0_n, sf_n, s0_t, sf_t, k_n, k_t, table, d0, rcurve, &
         rcurve_file, g_ci, g_cii, growth_slip, contact_band, viscosity, stiffness, props
      integer :: ios
      character(len=512) :: iomsg

      call unpack_entries(e, model, damage_law, table, rcurve, rcurve_file, mu, s0_n, sf_n, s0_t, sf_t, &
         k_n, k_t, d0, g_ci, g_cii)
      growth_slip = e%growth_slip
      contact_band = e%contact_band
      viscosity = e%viscosity
      stiffness = e%stiffness
      props = e%props
      rewind (unit)
      read (unit, nml=joint, iostat=ios, iomsg=iomsg)
      call group_status(run%path, 'joint', ios, iomsg, ok, message)
      if (.not. ok) return
      ! (damage_law's default where the joint is given by its entries, also for damage_law = '',
      ! an entry left out; with props, PROPS(2) is it)
      if (len_trim(damage_law) == 0 .and. given_values(run%lines, 'joint.props') == 0) damage_law = 'displacement'
      e = material_entries_type(model, damage_law, table, rcurve, rcurve_file, mu, s0_n, sf_n, s0_t, &
         sf_t, k_n, k_t, d0, g_ci, g_cii)
      e%growth_slip = growth_slip
      e%contact_band = contact_band
      e%viscosity = viscosity
      e%stiffness = stiffness
      e%props = props
      e%props_count = given_values(run%lines, 'joint.props')
      call material_props(e, run%path//': &joint: ', directory_of(run%path), run%props, run%table_path, &
         run%rcurve_path, ok, message)
   end subroutine read_joint

   subroutine read_loading(unit, run, ok, message)
      integer, intent(in) :: unit                 !! open case file
      type(fe2d_case_type), intent(inout) :: run  !! receives the loading and solver controls
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      real(dp) :: precompression, tolerance, displacement_tolerance, min_increment
      integer :: precompression_increments, increments, max_iterations, ios
      character(len=ENTRY_LEN) :: history, output, assembly
      logical :: plot
      character(len=512) :: iomsg
      namelist /loading/ precompression, precompression_increments, history, increments, &
         tolerance, displacement_tolerance, max_iterations, min_increment, output, plot, assembly
      character(len=:), allocatable :: where

      where = run%path//': &loading: '
      precompression = run%precompression
      precompression_increments = run%precompression_increments
      history = ''
      output = ''
      increments = run%increments
      tolerance = run%tolerance
      displacement_tolerance = run%displacement_tolerance
      max_iterations = run%max_iterations
      min_increment = run%min_increment
      plot = run%plot
      assembly = 'unsymmetric'
      rewind (unit)
      read (unit, nml=loading, iostat=ios, iomsg=iomsg)
      call group_status(run%path, 'loading', ios, iomsg, ok, message)
      if (.not. ok) return
      ok = .false.
      if (len_trim(history) == 0) then
         message = where//'missing entry history'
         return
      end if
      if (.not. ieee_is_finite(precompression)) then
         message = where//'precompression must be finite'
         return
      end if
      if (precompression < 0.0_dp .or. precompression > PROPS_VALUE_MAX) then
         message = where//'precompression is a compressive pressure and must lie in [0, 1e20] MPa, got '// &
            real_to_string(precompression)
         return
      end if
      if (precompression_increments < 1) then
         message = where//'precompression_increments must be at least 1, got '// &
            int_to_string(precompression_increments)
         return
      end if
      if (increments < 1) then
         message = where//'increments must be at least 1, got '//int_to_string(increments)
         return
      end if
      if (max_iterations < 1 .or. max_iterations > 50) then
         message = where//'max_iterations must be in 1..50, got '//int_to_string(max_iterations)
         return
      end if
      if (.not. check_relative(where, 'tolerance', tolerance, message)) return
      if (.not. check_relative(where, 'displacement_tolerance', displacement_tolerance, message)) return
      ! (one range, one message: the window's [1e-20, 1e20] would name a range that 5 lies in)
      if (.not. (min_increment >= PROPS_VALUE_MIN .and. min_increment <= 1.0_dp)) then
         message = where//'min_increment is a fraction of the nominal increment and must lie in [1e-20, 1], got '// &
            real_to_string(min_increment)
         return
      end if
      run%precompression = precompression
      run%precompression_increments = precompression_increments
      run%history_path = join_path(directory_of(run%path), trim(adjustl(history)))
      run%increments = increments
      run%tolerance = tolerance
      run%displacement_tolerance = displacement_tolerance
      run%max_iterations = max_iterations
      run%min_increment = min_increment
      if (len_trim(output) == 0) then
         run%output = run%name//'.csv'
      else
         run%output = trim(adjustl(output))
      end if
      run%plot = plot
      select case (to_lower(trim(adjustl(assembly))))   ! (any case, as the other words)
      case ('unsymmetric')
         run%symmetric_assembly = .false.
      case ('symmetric')
         run%symmetric_assembly = .true.
      case default
         message = where//"assembly must be 'unsymmetric' (the default) or 'symmetric', got '"// &
            trim(adjustl(assembly))//"'"
         return
      end select
      ok = .true.
   end subroutine read_loading

   !> Turn the iostat of a namelist read into ok/message. A missing group is an error.
   subroutine group_status(path, group, ios, iomsg, ok, message)
      character(len=*), intent(in) :: path, group, iomsg
      integer, intent(in) :: ios
      logical, intent(out) :: ok
      character(len=:), allocatable, intent(out) :: message

      ok = .false.
      if (ios == iostat_end) then
         message = path//': &'//group//': group not found (expected "&'//group//' ... /")'
      else if (ios /= 0) then
         message = path//': &'//group//': cannot read the group: '//trim(iomsg)
      else
         ok = .true.
      end if
   end subroutine group_status

   !> True when value is finite and in the window of the PROPS' magnitudes, [1e-20, 1e20] (beyond
   !> it the assembly's products and the solver's norms can overflow or lose every digit); else
   !> false with a message.
   logical function check_window(where, name, value, message)
      character(len=*), intent(in) :: where, name
      real(dp), intent(in) :: value
      character(len=:), allocatable, intent(inout) :: message

      check_window = .false.
      if (.not. ieee_is_finite(value)) then
         message = where//name//' must be finite'
      else if (.not. (value >= PROPS_VALUE_MIN .and. value <= PROPS_VALUE_MAX)) then
         message = where//name//' must lie in [1e-20, 1e20], got '//real_to_string(value)
      else
         check_window = .true.
      end if
   end function check_window

   !> True when value is a relative tolerance: finite, in [1e-20, 1) (a tolerance of 1 or more
   !> accepts any iterate); else false with a message.
   logical function check_relative(where, name, value, message)
      character(len=*), intent(in) :: where, name
      real(dp), intent(in) :: value
      character(len=:), allocatable, intent(inout) :: message

      check_relative = .false.
      if (.not. ieee_is_finite(value)) then
         message = where//name//' must be finite'
      else if (.not. (value >= PROPS_VALUE_MIN .and. value < 1.0_dp)) then
         message = where//name//' is a relative tolerance and must lie in [1e-20, 1), got '//real_to_string(value)
      else
         check_relative = .true.
      end if
   end function check_relative

   !> Read a shear history: two columns `t u_shear` (mm), `#` comments and blank lines allowed,
   !> time strictly increasing, at least two rows, first u_shear 0 (the precompression step
   !> ends at u = 0). Each field is one real literal as a whole (interphase-point's parse_number,
   !> its messages clipping the field to 60 characters with control characters masked); a
   !> carriage return inside a line is refused as interphase-point refuses it. A `# columns:` line (interphase-point's
   !> mixed control, which this host does not have) is refused rather than read as a comment.
   !> Errors name the file (as tried) and line; a file that cannot be opened is named after
   !> `named_by`, where the path came from ('case.nml:20: &loading: history: ').
   subroutine read_shear_history(path, t, u, ok, message, named_by)
      character(len=*), intent(in) :: path        !! history file
      real(dp), allocatable, intent(out) :: t(:)  !! times
      real(dp), allocatable, intent(out) :: u(:)  !! shear displacements (mm)
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      character(len=*), intent(in), optional :: named_by   !! where the path was given
      character(len=:), allocatable :: line
      integer, allocatable :: starts(:), ends(:)
      integer :: ios, line_number, n, k
      type(text_file_type) :: unit
      character(len=512) :: iomsg
      character(len=:), allocatable :: shown, comment, where
      real(dp) :: values(2)
      real(dp), allocatable :: grow(:)
      integer :: first_line
      logical :: parsed

      ok = .false.
      allocate (t(0), u(0))
      shown = tried_path(path)
      first_line = 0
      call open_line_file(path, unit, ios, iomsg)
      if (ios /= 0) then
         if (present(named_by)) then
            message = named_by//tried_path(path)//': cannot open the shear history: '//trim(iomsg)
         else
            message = tried_path(path)//': cannot open the shear history (&loading: history): '//trim(iomsg)
         end if
         return
      end if
      line_number = 0
      n = 0
      do
         call read_line(unit, line, ios, iomsg)
         if (ios == iostat_end) exit
         line_number = line_number + 1
         where = shown//':'//int_to_string(line_number)//': '
         if (ios /= 0) then
            message = where//'cannot read the line: '//trim(iomsg)
            call close_text_file(unit)
            return
         end if
         ! (interphase-point's history reader's check and message)
         message = carriage_return_message(line)
         if (len(message) > 0) then
            message = where//message
            call close_text_file(unit)
            return
         end if
         k = index(line, '#')
         if (k > 0) then
            ! a "# columns:" line (or one spelt like it) names interphase-point's mixed-control
            ! columns: here every value is a displacement, so it is refused, not skipped
            comment = to_lower(adjustl(line(k + 1:)))
            do while (index(comment, char(9)) > 0)
               comment(index(comment, char(9)):index(comment, char(9))) = ' '
            end do
            comment = adjustl(comment)
            if (len(comment) >= 6) then
               if (comment(1:6) == 'column' .and. index(comment, ':') > 0 .and. &
                  verify(comment(7:index(comment, ':') - 1), 's ') == 0) then
                  message = where//'"#'//clip_text(line(k + 1:))//'": interphase-fe2d''s '// &
                     'history has the two columns t u_shear (mm, a displacement) and no "# columns:" line '// &
                     '(imposed tractions are interphase-point''s mixed control)'
                  call close_text_file(unit)
                  return
               end if
            end if
            ! a caption that gives u_shear another length unit (`# t u_shear (m)`): the rows are
            ! read in mm whatever it says, so metres would run as millimetres
            comment = foreign_shear_unit(line(k + 1:))
            if (len(comment) > 0) then
               message = where//'"#'//clip_text(line(k + 1:))//'" gives '//comment//', but interphase-fe2d '// &
                  'reads u_shear in mm: convert the column, and write (mm) or no unit'
               call close_text_file(unit)
               return
            end if
            line = line(1:k - 1)
         end if
         call split_words(line, starts, ends)
         if (size(starts) == 0) cycle
         if (size(starts) /= 2) then
            message = shown//':'//int_to_string(line_number)//': found '// &
               count_text(size(starts), 'column')//'; expected 2 (t u_shear)'//separator_hint(line)
            call close_text_file(unit)
            return
         end if
         do k = 1, 2
            ! (interphase-point's parser and messages: the field clipped, control characters masked)
            call parse_number(line(starts(k):ends(k)), values(k), parsed, message)
            if (.not. parsed) then
               message = where//'column '//int_to_string(k)//': '//message
               call close_text_file(unit)
               return
            end if
         end do
         if (n == 0) first_line = line_number
         if (abs(values(2)) > PROPS_VALUE_MAX) then
            ! (the window of the case's lengths: beyond it the assembly's products overflow)
            message = shown//':'//int_to_string(line_number)//': column 2: u_shear '//real_to_string(values(2))// &
               ' mm is beyond |u_shear| <= 1e20 mm'
            call close_text_file(unit)
            return
         end if
         if (n > 0) then
            if (.not. (values(1) > t(n))) then
               message = shown//':'//int_to_string(line_number)//': time '// &
                  real_to_string(values(1))//' is not greater than the previous time '// &
                  real_to_string(t(n))
               call close_text_file(unit)
               return
            end if
            ! (the replay interpolates within the step: the step must be a number)
            if (.not. difference_is_finite(values(1), t(n))) then
               message = shown//':'//int_to_string(line_number)//': time '//real_to_string(values(1))// &
                  ': the time step from the previous time '//real_to_string(t(n))//' is not finite (beyond '// &
                  'the largest double)'
               call close_text_file(unit)
               return
            end if
         end if
         n = n + 1
         grow = [t, values(1)]
         call move_alloc(grow, t)
         grow = [u, values(2)]
         call move_alloc(grow, u)
      end do
      call close_text_file(unit)
      if (n < 2) then
         message = shown//': needs at least 2 data rows, found '//int_to_string(n)
         return
      end if
      if (abs(u(1)) > 0.0_dp) then
         message = shown//':'//int_to_string(first_line)//': the first row must have u_shear = 0 (the shear step starts '// &
            'from the precompressed state), got '//real_to_string(u(1))
         return
      end if
      ok = .true.
   end subroutine read_shear_history

   !> '' when no group in parentheses right after the word `u_shear` or `u` (any case) of a
   !> history's comment (`comment`, the text after '#') is a length unit other than mm
   !> (LENGTH_UNIT_WORDS); else that word and unit as written (`u_shear the unit (m)`). Other
   !> words in parentheses are a remark (`t (s)`, `u_shear (2 segments)`).
   pure function foreign_shear_unit(comment) result(found)
      character(len=*), intent(in) :: comment
      character(len=:), allocatable :: found
      found = foreign_length_unit_after(comment, [character(len=7) :: 'u_shear', 'u'])
   end function foreign_shear_unit

end module interphase_fe2d_case
