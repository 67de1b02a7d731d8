!> The micromechanical model's coefficient provider: the coefficient set at damage D
!> interpolated from an RVE table (paper section 5.1: "spline regression" of the FE results),
!> with its derivatives d/dD for the consistent tangent.
!>
!> The interpolant the updates use is the table grid (interphase_table_grid): the table's cubic
!> spline in its interpolation variable, resampled onto cells indexed by the bits of D (and of
!> 1 - D above D = 1/2), a cubic in D on each cell, C1 across the cells and within the grid's
!> tolerances of the spline wherever 256 cells a binade reach them (docs/theory.md, 'The table
!> grid'). A lookup is a subtraction, shifts and masks, one cell's cubics: no logarithm, no
!> division for the interpolation variable, no search. The spline itself
!> (`table_coefficients`) is the grid's source and the reference of the tests.
!>
!> Two tables can serve: the default one, compiled in as generated `parameter` data
!> (`interphase_default_table`, from tables/paper.dat: its spline, its grid and its columns at
!> D = 0 and 1), and one custom table per process, loaded once at start-up by `load_custom_table`
!> (Abaqus: UEXTERNALDB; the driver: its case file) into `protected` data that the pure update
!> only reads.
module interphase_micro_coefficients
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_real_text, only: es_field
   use interphase_enums, only: TABLE_CUSTOM_CODE
   use interphase_status, only: STATUS_OK, STATUS_TABLE_NOT_LOADED, STATUS_BAD_COEFFICIENTS, MESSAGE_LEN, &
      STATUS_TABLE_INTERPOLANT, status_message, message_path, STATUS_SPLINE_OUT_OF_RANGE, &
      STATUS_SPLINE_NONFINITE_ARGUMENT, STATUS_SPLINE_TOO_FEW_POINTS
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS
   use interphase_finite, only: EXPONENT_MASK, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, D_MIN_CRACK
   use interphase_spline, only: spline_type, spline_build, spline_export, cubic_locate, cubic_eval
   use interphase_rve_table, only: rve_table_type, read_rve_table, check_rve_table, &
      interpolation_data, N_COEFFICIENTS, TABLE_SPLINE_METHOD, VARIABLE_DAMAGE, IC_K_N, IC_K_T, &
      IC_KC_N, IC_KC_T, IC_DBAR_N, IC_DBAR_T, IC_TC_T, IC_SC_N, IC_DTF, IC_UFBAR
   use interphase_table_grid, only: grid_build, grid_sample_damages, grid_state_columns, GRID_INDEX_SIZE, GRID_E_D_FIRST, &
      GRID_E_Y_FIRST, GRID_Y_OFFSET, GRID_MANTISSA_MASK
   use interphase_default_table, only: DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, DEFAULT_TABLE_SOURCE, &
      DEFAULT_TABLE_VARIABLE, DEFAULT_TABLE_GRID, DEFAULT_TABLE_GRID_INDEX, DEFAULT_TABLE_DOMAIN, &
      DEFAULT_TABLE_STATE_COLUMNS, &
      DEFAULT_TABLE_STATE_STATUS
   implicit none
   private
   public :: micro_coefficients, micro_values, micro_ufbar, load_custom_table, custom_table_source, &
      table_coefficients, &
      custom_table_loaded, check_interpolant, default_table_data, micro_block_coefficients, table_curvature_type, &
      micro_second_derivatives, micro_block_ufbar

   !> What a table evaluation with derivatives keeps so that the second derivatives d2/dD2 of its
   !> set can be formed later, and only where they are used (`micro_second_derivatives`): the
   !> fracture law's search needs them at a damage where the crack grows, which it knows only
   !> after g there is formed. No default initialisation (hot path): the providers set every
   !> member where they return STATUS_OK. (The grid's cubics are in D itself: x = D, dx/dD = 1,
   !> d2x/dD2 = 0; the spline's, table_coefficients', are in its interpolation variable x.)
   type :: table_curvature_type
      real(dp) :: d2v_x(N_COEFFICIENTS)  !! the interpolated columns' second derivatives in the crack variable x
      real(dp) :: dv_x(N_COEFFICIENTS)   !! their first derivatives in x
      real(dp) :: dx_dd                  !! dx/dD (-)
      real(dp) :: d2x_dd2                !! d2x/dD2 (-)
   end type table_curvature_type

   !> Points per chunk of the block evaluations (fixed-size working arrays: a run-time-sized
   !> automatic array would be allocated on the heap at every call).
   integer, parameter :: BLOCK_CHUNK = 64

   !> Points inside every cell of the grid at which `check_interpolant` evaluates it (its ends too).
   integer, parameter :: INTERPOLANT_SAMPLES = 3

   !> Smallest positive damage at which the tables' coefficients are evaluated (-): interphase_finite's
   public :: D_MIN_CRACK

   !> The bit pattern of D = 1, the broken state (the intact state D = +0 is the pattern 0).
   integer(int64), parameter :: BROKEN_BITS = int(z'3FF0000000000000', int64)

   !> The built-in table grid's index in 64-bit integers, as the block providers read it
   !> (`custom_grid_index64` below).
   integer(int64), parameter :: DEFAULT_GRID_INDEX64(GRID_INDEX_SIZE) = int(DEFAULT_TABLE_GRID_INDEX, int64)

   !> The custom table: written once by `load_custom_table` before any update, then read only:
   !> its grid (interphase_table_grid's grid_build) and the grid's index
   real(dp), allocatable, protected :: custom_grid(:, :, :)
   integer, protected :: custom_grid_index(GRID_INDEX_SIZE) = 0
   !> the same index in 64-bit integers, as the block providers read it (block_cells: their loop
   !> vectorises only in 64-bit integers, and a conversion at every call costs more than the
   !> lookup of a point)
   integer(int64), protected :: custom_grid_index64(GRID_INDEX_SIZE) = 0
   !> the damages of its first and last rows (grid_build's domain)
   real(dp), protected :: custom_domain(2) = [0.0_dp, 1.0_dp]
   !> its columns at D = +0 and D = 1, and the status of each (interphase_table_grid's
   !> grid_state_columns; STATUS_TABLE_NOT_LOADED until a table is loaded)
   real(dp), protected :: custom_state_columns(N_COEFFICIENTS, 2) = 0.0_dp
   integer, protected :: custom_state_status(2) = STATUS_TABLE_NOT_LOADED
   character(len=:), allocatable, protected :: custom_source

contains

   ! the crack variable's finiteness test, here where the compiler inlines it (interphase_finite's,
   ! from the same source), and the bit patterns the grid's cells are found from
   include 'interphase_binary64_bits.inc'
   include 'interphase_binary64_value.inc'
   include 'interphase_is_finite.inc'
   ! the logarithm of the interpolation variable (interphase_logarithm's ln_positive, from the same
   ! source), for the spline's evaluation (table_coefficients)
   include 'interphase_ln_positive.inc'
   ! (the interpolation variable, from interphase_rve_table's source)
   include 'interphase_crack_variable.inc'

   !> Coefficients at D from the selected table (TABLE_DEFAULT_CODE or TABLE_CUSTOM_CODE): the
   !> table grid's values and, with dcoef_dd, their derivatives d/dD (and with curvature what the
   !> second derivatives are formed from).
   pure subroutine micro_coefficients(table, d, coef, dcoef_dd, status, curvature)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      real(dp), intent(in) :: d                              !! damage D = a/b
      type(coefficient_set_type), intent(out) :: coef        !! coefficients at D
      !> their derivatives d/dD (absent: not formed; then curvature must be absent too)
      type(coefficient_set_type), intent(out), optional :: dcoef_dd
      integer, intent(out) :: status
      !> what `micro_second_derivatives` needs for the second derivatives at D
      type(table_curvature_type), intent(out), optional :: curvature
      type(table_curvature_type) :: unused_curvature
      if (.not. present(dcoef_dd)) then
         ! the values alone (the same numbers, the same statuses)
         call micro_values(table, d, coef, status)
         return
      end if
      ! (the grid's lookup called directly, on arrays of explicit shape, with or without what the
      ! second derivatives are formed from: no optional argument reaches the hot path, which
      ! a compiler that does not inline grid_coefficients would test at every call)
      if (table == TABLE_CUSTOM_CODE) then
         if (.not. allocated(custom_grid)) then
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         if (present(curvature)) then
            call grid_coefficients(size(custom_grid, 3), custom_grid, custom_grid_index, custom_domain, d, &
               .true., coef, dcoef_dd, &
               curvature, status)
         else
            call grid_coefficients(size(custom_grid, 3), custom_grid, custom_grid_index, custom_domain, d, &
               .false., coef, dcoef_dd, &
               unused_curvature, status)
         end if
      else if (present(curvature)) then
         call grid_coefficients(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_TABLE_GRID_INDEX, &
            DEFAULT_TABLE_DOMAIN, d, .true., &
            coef, dcoef_dd, curvature, status)
      else
         call grid_coefficients(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_TABLE_GRID_INDEX, &
            DEFAULT_TABLE_DOMAIN, d, .false., &
            coef, dcoef_dd, unused_curvature, status)
      end if
   end subroutine micro_coefficients

   !> The checks every lookup makes before the grid's cell is found: STATUS_BAD_COEFFICIENTS for
   !> 0 < D < D_MIN_CRACK (T^f ~ 1/D and its derivatives ~ 1/D^2, 1/D^3 would come close to
   !> overflow there; no update reaches such a D: the displacement law's first damage is above
   !> 1e-16, and D0 is the fracture law's start), STATUS_SPLINE_NONFINITE_ARGUMENT for a NaN or an
   !> infinite D, STATUS_SPLINE_OUT_OF_RANGE outside the table's domain (its first and last rows'
   !> damages: [0, 1] but for a table whose end rows lie within 1e-12 of them; -0 is D = 0), else
   !> STATUS_OK.
   pure integer function damage_status(d, domain) result(status)
      real(dp), intent(in) :: d                              !! damage D = a/b
      real(dp), intent(in) :: domain(2)                      !! the table's [D_first, D_last]
      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
      else if (d >= domain(1) .and. d <= domain(2)) then
         status = STATUS_OK
      else if (.not. is_finite(d)) then
         status = STATUS_SPLINE_NONFINITE_ARGUMENT
      else
         status = STATUS_SPLINE_OUT_OF_RANGE
      end if
   end function damage_status

   !> The spline's coefficient set at D (the table grid's source: interpolation data as
   !> interphase_rve_table's interpolation_data gives them, spline_export's knots and cubics),
   !> with its derivatives d/dD and, with curvature, what micro_second_derivatives forms the second
   !> derivatives from (in the spline's variable x). For the grid's construction and checks and for
   !> the tests; the updates use the grid. The data hold D T^f (IC_DTF), smooth down to D = 0;
   !> T^f = (D T^f)/D. At D = 0 (no crack) T^f has no finite value: the set holds -huge(1.0_dp)
   !> there, which no regime uses (D = 0 is intact), and zero derivatives. Statuses as the grid's
   !> (damage_status), and cubic_locate's where x lies outside the knots.
   pure subroutine table_coefficients(variable, knots, coef_table, d, coef, dcoef_dd, status, curvature)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      real(dp), contiguous, intent(in) :: knots(:)           !! knots, ascending
      !> cubic coefficients (column, power, interval), the columns IC_* (N_COEFFICIENTS of them)
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)
      real(dp), intent(in) :: d
      type(coefficient_set_type), intent(out) :: coef
      type(coefficient_set_type), intent(out) :: dcoef_dd    !! first derivatives d/dD
      integer, intent(out) :: status
      !> what `micro_second_derivatives` needs for the second derivatives d2/dD2 at D
      type(table_curvature_type), intent(out), optional :: curvature
      real(dp) :: x, dx_dd, d2x_dd2, v(N_COEFFICIENTS), dv(N_COEFFICIENTS)
      integer :: interval

      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      call crack_variable(variable, d, x, dx_dd, d2x_dd2)
      call cubic_locate(knots, x, interval, status)
      if (status /= STATUS_OK) return
      if (present(curvature)) then
         call cubic_eval(knots, coef_table, interval, x, v, curvature%dv_x, curvature%d2v_x)
         curvature%dx_dd = dx_dd
         curvature%d2x_dd2 = d2x_dd2
         dv = curvature%dv_x*dx_dd
      else
         call cubic_eval(knots, coef_table, interval, x, v, dv)
         dv = dv*dx_dd
      end if
      call form_sets(d, v, dv, coef, dcoef_dd)
   end subroutine table_coefficients

   !> The grid's lookup with first derivatives, on arrays of explicit shape (no descriptors, no
   !> optional arguments): D's cell (interphase_grid_cell.inc), every column's cubic in Horner form
   !> with its derivative in D, the sets at D (form_sets) and, with `with_curvature`, what
   !> micro_second_derivatives forms the second derivatives from (else `curvature` is left
   !> undefined).
   pure subroutine grid_coefficients(n_cells, grid, grid_index, domain, d, with_curvature, coef, dcoef_dd, &
      curvature, status)
      integer, intent(in) :: n_cells                         !! cells of the grid
      real(dp), intent(in) :: grid(N_COEFFICIENTS, 0:3, n_cells)   !! the cubics (column, power, cell)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)     !! each binade's first cell and shift
      real(dp), intent(in) :: domain(2)                      !! the table's [D_first, D_last]
      real(dp), intent(in) :: d                              !! damage D = a/b
      logical, intent(in) :: with_curvature
      type(coefficient_set_type), intent(out) :: coef, dcoef_dd
      type(table_curvature_type), intent(out) :: curvature
      integer, intent(out) :: status
      real(dp) :: columns(N_COEFFICIENTS), slopes(N_COEFFICIENTS), v, vc, s
      integer(int64) :: bits
      integer :: e, idx, packed, sh, cell, j
      logical :: d_side
      status = damage_status(d, domain)
      if (status /= STATUS_OK) return
      include 'interphase_grid_cell.inc'
      do j = 1, N_COEFFICIENTS
         columns(j) = grid(j, 0, cell) + s*(grid(j, 1, cell) + s*(grid(j, 2, cell) + s*grid(j, 3, cell)))
         slopes(j) = grid(j, 1, cell) + s*(2.0_dp*grid(j, 2, cell) + 3.0_dp*s*grid(j, 3, cell))
      end do
      if (with_curvature) then
         do j = 1, N_COEFFICIENTS
            curvature%d2v_x(j) = 2.0_dp*grid(j, 2, cell) + 6.0_dp*s*grid(j, 3, cell)
         end do
         curvature%dv_x = slopes
         curvature%dx_dd = 1.0_dp
         curvature%d2x_dd2 = 0.0_dp
      end if
      call form_sets(d, columns, slopes, coef, dcoef_dd)
   end subroutine grid_coefficients

   !> The coefficient set at D and its D-derivatives from the interpolated columns' values v and
   !> D-derivatives dv: T^f = v/D, T^f' = (v' - T^f)/D with v = D T^f (-huge and 0 at D = 0;
   !> T^f'': micro_second_derivatives), C^f_T from the reciprocity relation (reciprocal_cf) and
   !> C^f_T' = -(K' m + K m') for C^f_T = -K m, K = tc_t, m = D ufbar (at D = 1, where the other
   !> columns' derivatives are 0 by convention, the product rule's -K ufbar: no caller asks for
   !> derivatives there).
   pure subroutine form_sets(d, v, dv, coef, dcoef_dd)
      real(dp), intent(in) :: d
      real(dp), intent(in) :: v(N_COEFFICIENTS), dv(N_COEFFICIENTS)
      type(coefficient_set_type), intent(out) :: coef, dcoef_dd
      real(dp) :: dtf, dcf
      ! (the values as every provider forms them)
      call columns_set(v, d, coef)
      dtf = 0.0_dp
      if (d > 0.0_dp) dtf = (dv(IC_DTF) - coef%tf)/d
      dcf = -(dv(IC_TC_T)*(d*v(IC_UFBAR)) + v(IC_TC_T)*(v(IC_UFBAR) + d*dv(IC_UFBAR)))
      dcoef_dd = as_set(dv, dtf, dcf)
   end subroutine form_sets

   ! the second derivatives from what the providers kept (one source, included in
   ! interphase_fracture too, where the search's evaluation inlines it)
   include 'interphase_second_derivatives.inc'

   !> C^f_T at D from the reciprocity relation of the RVE problems, C^f_T = -(C_TT(0)/h) D ufbar
   !> (docs/rve.md; the tables meet it at their rows to 5e-15), with C_TT(0)/h = tc_t = T^c_T/h
   !> (the p2 crack stress, constant in the tables, so that its spline is too), instead of the column's
   !> own spline: D ufbar is not a cubic of the interpolation variable, and two separate splines
   !> drift apart between the rows (1e-6 to 1e-4 relative for D < 0.9999 of tables/paper.dat,
   !> 3.8e-4 in its last interval). The closed crack's stored energy is the potential of its
   !> traction and of the crack stress tau = tc_t s_T + T^f lambda that the friction step uses
   !> only when C^f/m = -tc_t (m = D ufbar; docs/theory.md, 'Crack growth under slip'): with
   !> the drift the dissipation fell on histories near D = 1, without converging under
   !> refinement. (tc_t, not k_T + k^c_T, which eq 52 makes equal to it: a table that meets
   !> eq 52 only to the loader's 1e-8 would leave a residue there.) Every provider of the tables
   !> (grid_coefficients, grid_values, block_values, and the spline's table_coefficients) forms it
   !> so, in this order of operations (the same bits).
   elemental real(dp) function reciprocal_cf(tc_t, d, ufbar) result(cf_t)
      real(dp), intent(in) :: tc_t               !! tc_t = T^c_T/h at D (MPa/mm)
      real(dp), intent(in) :: d                  !! D (-)
      real(dp), intent(in) :: ufbar              !! ufbar at D (-)
      cf_t = -tc_t*(d*ufbar)
   end function reciprocal_cf

   !> The coefficients at D from the selected table, values only (`micro_coefficients` without
   !> derivatives, the entry of the updates that need none: the same numbers bit for bit, the
   !> same statuses; a procedure of its own, so that its code does not depend on how the compiler
   !> specialises the optional arguments of micro_coefficients).
   pure subroutine micro_values(table, d, coef, status)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      real(dp), intent(in) :: d                              !! damage D = a/b
      type(coefficient_set_type), intent(out) :: coef        !! coefficients at D
      integer, intent(out) :: status
      integer(int64) :: d_bits
      integer :: state
      d_bits = binary64_bits(d)
      if (d_bits == 0_int64 .or. d_bits == BROKEN_BITS) then
         ! the intact (D = +0) or the broken state (D = 1), where most of a structure's interface
         ! points are: the table's columns there (grid_state_columns: the values of the grid's
         ! cells of their own at D = 0 and 1, which grid_values returns there as they are: the
         ! same bits, the same status)
         state = merge(1, 2, d_bits == 0_int64)
         if (table == TABLE_CUSTOM_CODE) then
            ! (STATUS_TABLE_NOT_LOADED before a custom table is loaded)
            status = custom_state_status(state)
            if (status == STATUS_OK) call columns_set(custom_state_columns(:, state), d, coef)
         else
            status = DEFAULT_TABLE_STATE_STATUS(state)
            if (status == STATUS_OK) call columns_set(DEFAULT_TABLE_STATE_COLUMNS(:, state), d, coef)
         end if
         return
      end if
      if (table == TABLE_CUSTOM_CODE) then
         if (.not. allocated(custom_grid)) then
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         call grid_values(size(custom_grid, 3), custom_grid, custom_grid_index, custom_domain, d, coef, status)
      else
         call grid_values(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_TABLE_GRID_INDEX, &
            DEFAULT_TABLE_DOMAIN, d, coef, status)
      end if
   end subroutine micro_values

   !> grid_coefficients' values without derivatives: D's cell, every column's cubic in Horner
   !> form, T^f = (D T^f)/D (-huge at D = 0). (Arrays of explicit shape: no descriptors, and the
   !> column stride a constant, whichever table it is.)
   pure subroutine grid_values(n_cells, grid, grid_index, domain, d, coef, status)
      integer, intent(in) :: n_cells                         !! cells of the grid
      real(dp), intent(in) :: grid(N_COEFFICIENTS, 0:3, n_cells)   !! the cubics (column, power, cell)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)     !! each binade's first cell and shift
      real(dp), intent(in) :: domain(2)                      !! the table's [D_first, D_last]
      real(dp), intent(in) :: d
      type(coefficient_set_type), intent(out) :: coef
      integer, intent(out) :: status
      real(dp) :: columns(N_COEFFICIENTS), v, vc, s
      integer(int64) :: bits
      integer :: e, idx, packed, sh, cell, j
      logical :: d_side
      status = damage_status(d, domain)
      if (status /= STATUS_OK) return
      include 'interphase_grid_cell.inc'
      do j = 1, N_COEFFICIENTS
         columns(j) = grid(j, 0, cell) + s*(grid(j, 1, cell) + s*(grid(j, 2, cell) + s*grid(j, 3, cell)))
      end do
      call columns_set(columns, d, coef)
   end subroutine grid_values

   !> The coefficient set at D from the interpolated columns v there (IC_* order): T^f = (D T^f)/D
   !> (-huge at D = 0, where it has no finite value) and C^f_T from the reciprocity relation
   !> (reciprocal_cf), the values of form_sets.
   pure subroutine columns_set(v, d, coef)
      real(dp), intent(in) :: v(N_COEFFICIENTS)              !! the columns at D
      real(dp), intent(in) :: d                              !! damage D = a/b (-)
      type(coefficient_set_type), intent(out) :: coef
      real(dp) :: tf
      tf = -huge(1.0_dp)
      if (d > 0.0_dp) tf = v(IC_DTF)/d
      coef = as_set(v, tf, reciprocal_cf(v(IC_TC_T), d, v(IC_UFBAR)))
   end subroutine columns_set

   !> ufbar(D) alone, for the slip measure m = D ufbar (interphase_response): the column IC_UFBAR
   !> of micro_coefficients' set, from the same cell in the same Horner form, so the same number
   !> bit for bit, and the same statuses; one cubic instead of the set.
   pure subroutine micro_ufbar(table, d, ufbar, status)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      real(dp), intent(in) :: d                              !! damage D = a/b
      real(dp), intent(out) :: ufbar                         !! ufbar(D) (-)
      integer, intent(out) :: status
      if (table == TABLE_CUSTOM_CODE) then
         if (.not. allocated(custom_grid)) then
            ufbar = 0.0_dp
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         call grid_ufbar(size(custom_grid, 3), custom_grid, custom_grid_index, custom_domain, d, ufbar, status)
      else
         call grid_ufbar(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_TABLE_GRID_INDEX, &
            DEFAULT_TABLE_DOMAIN, d, ufbar, status)
      end if
   end subroutine micro_ufbar

   !> grid_values' value of the column IC_UFBAR.
   pure subroutine grid_ufbar(n_cells, grid, grid_index, domain, d, ufbar, status)
      integer, intent(in) :: n_cells
      real(dp), intent(in) :: grid(N_COEFFICIENTS, 0:3, n_cells)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)
      real(dp), intent(in) :: domain(2)
      real(dp), intent(in) :: d
      real(dp), intent(out) :: ufbar
      integer, intent(out) :: status
      real(dp) :: v, vc, s
      integer(int64) :: bits
      integer :: e, idx, packed, sh, cell
      logical :: d_side
      ! (ufbar defined on the failure paths too, 0 there: with the callers inlined, for the
      ! compiler's uninitialised-use analysis)
      ufbar = 0.0_dp
      status = damage_status(d, domain)
      if (status /= STATUS_OK) return
      include 'interphase_grid_cell.inc'
      ufbar = grid(IC_UFBAR, 0, cell) + s*(grid(IC_UFBAR, 1, cell) + s*(grid(IC_UFBAR, 2, cell) &
         + s*grid(IC_UFBAR, 3, cell)))
   end subroutine grid_ufbar

   !> The coefficients at n damages D(1:n) from the selected table, values only (no derivatives):
   !> the vectorised block update's provider (interphase_block). Each value is bit for bit what
   !> `micro_coefficients` returns at that D: the same cell (block_cells: the operations of
   !> interphase_grid_cell.inc), the same Horner form, the same T^f = (D T^f)/D. fail(i) = 1 where
   !> `micro_coefficients` would fail (0 < D < D_MIN_CRACK, D outside the table's domain, no custom
   !> table loaded), else 0 (a real
   !> flag, so that the caller's loops that combine it vectorise); the values there are finite but
   !> meaningless. D must be finite in [0, 1] (the block update's damages are).
   !> Where all n damages are the same number with the same sign (a block of intact points, or
   !> of broken ones), the table is evaluated once and its values copied: the same bits, since
   !> each value depends on D alone. Compiled with -fno-trapping-math (CMakeLists.txt): every
   !> operand is guarded, so no lane can raise an exception.
   pure subroutine micro_block_coefficients(table, n, d, k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, &
         cf_t, tf, ufbar, fail)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      integer, intent(in) :: n                               !! number of points (>= 1)
      real(dp), intent(in) :: d(n)                           !! damage D = a/b (-)
      real(dp), intent(out), dimension(n) :: k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar
      real(dp), intent(out) :: fail(n)                       !! 1 where the point update fails on the table, else 0
      integer :: n_eval
      if (table == TABLE_CUSTOM_CODE .and. .not. allocated(custom_grid)) then
         fail = 1.0_dp
         k_n = 0.0_dp; k_t = 0.0_dp; kc_n = 0.0_dp; kc_t = 0.0_dp; dbar_n = 0.0_dp; dbar_t = 0.0_dp
         tc_t = 0.0_dp; sc_n = 0.0_dp; cf_t = 0.0_dp; tf = -huge(1.0_dp); ufbar = 1.0_dp
         return
      end if
      n_eval = merge(1, n, one_damage(n, d))
      if (table == TABLE_CUSTOM_CODE) then
         call block_values(size(custom_grid, 3), custom_grid, custom_grid_index64, custom_domain, n_eval, d, &
            k_n, k_t, kc_n, kc_t, &
            dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar, fail)
      else
         call block_values(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_GRID_INDEX64, &
            DEFAULT_TABLE_DOMAIN, n_eval, d, k_n, &
            k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar, fail)
      end if
      if (n_eval < n) then
         k_n(2:n) = k_n(1)
         k_t(2:n) = k_t(1)
         kc_n(2:n) = kc_n(1)
         kc_t(2:n) = kc_t(1)
         dbar_n(2:n) = dbar_n(1)
         dbar_t(2:n) = dbar_t(1)
         tc_t(2:n) = tc_t(1)
         sc_n(2:n) = sc_n(1)
         cf_t(2:n) = cf_t(1)
         tf(2:n) = tf(1)
         ufbar(2:n) = ufbar(1)
         fail(2:n) = fail(1)
      end if
   end subroutine micro_block_coefficients

   !> `micro_block_coefficients` on a given grid, BLOCK_CHUNK points at a time.
   pure subroutine block_values(n_cells, grid, grid_index, domain, n, d, k_n, k_t, kc_n, kc_t, dbar_n, &
      dbar_t, tc_t, sc_n, &
         cf_t, tf, ufbar, fail)
      integer, intent(in) :: n_cells
      real(dp), intent(in) :: grid(N_COEFFICIENTS, 0:3, n_cells)
      integer(int64), intent(in) :: grid_index(GRID_INDEX_SIZE)   !! the index in 64-bit integers
      real(dp), intent(in) :: domain(2)
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      real(dp), intent(out), dimension(n) :: k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar
      real(dp), intent(out) :: fail(n)
      real(dp) :: s(BLOCK_CHUNK), t(BLOCK_CHUNK), v(N_COEFFICIENTS, BLOCK_CHUNK), s_i
      integer(int64) :: cell(BLOCK_CHUNK)
      integer :: i, j, k, c0, m
      do c0 = 1, n, BLOCK_CHUNK
         m = min(BLOCK_CHUNK, n - c0 + 1)
         call block_cells(grid_index, domain, m, d(c0:c0 + m - 1), cell, s, fail(c0:c0 + m - 1))
         ! the columns of one point together (the point providers' Horner form): a point's cubics
         ! on its cell are contiguous in the grid (column fastest), so the compiler evaluates the
         ! columns as a few short vectors each power, where a loop over the points would gather
         ! every coefficient of every column; then the columns copied out point by point
         do i = 1, m
            s_i = s(i)
            do j = 1, N_COEFFICIENTS
               v(j, i) = grid(j, 0, cell(i)) + s_i*(grid(j, 1, cell(i)) + s_i*(grid(j, 2, cell(i)) &
                  + s_i*grid(j, 3, cell(i))))
            end do
         end do
         do i = 1, m
            k = c0 + i - 1
            k_n(k) = v(IC_K_N, i)
            k_t(k) = v(IC_K_T, i)
            kc_n(k) = v(IC_KC_N, i)
            kc_t(k) = v(IC_KC_T, i)
            dbar_n(k) = v(IC_DBAR_N, i)
            dbar_t(k) = v(IC_DBAR_T, i)
            tc_t(k) = v(IC_TC_T, i)
            sc_n(k) = v(IC_SC_N, i)
            cf_t(k) = reciprocal_cf(v(IC_TC_T, i), d(k), v(IC_UFBAR, i))
            t(i) = v(IC_DTF, i)
            ufbar(k) = v(IC_UFBAR, i)
         end do
         ! T^f = (D T^f)/D; -huge at D = 0 (columns_set). The divisor is guarded by max, not by a
         ! selection (which the compiler may turn into two divisions under -fno-trapping-math):
         ! below D_MIN_CRACK (a failing point) the quotient could overflow
         do i = 1, m
            k = c0 + i - 1
            tf(k) = merge(t(i)/max(d(k), D_MIN_CRACK), -huge(1.0_dp), d(k) > 0.0_dp)
         end do
      end do
   end subroutine block_values

   !> ufbar(D) alone at n damages D(1:n), with the failure flags of `micro_block_coefficients`:
   !> each value bit for bit what `micro_ufbar` returns at that D (the same cell and Horner form),
   !> fail(i) = 1 where it fails. For the block update's trial slip of a growing crack
   !> (m(D_n) = D_n ufbar(D_n)), which needs this one column at the old damage. A block of one
   !> damage is evaluated once, as in `micro_block_coefficients`.
   pure subroutine micro_block_ufbar(table, n, d, ufbar, fail)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      integer, intent(in) :: n                               !! number of points (>= 1)
      real(dp), intent(in) :: d(n)                           !! damage D = a/b (-), finite in [0, 1]
      real(dp), intent(out) :: ufbar(n)                      !! ufbar(D) (-)
      real(dp), intent(out) :: fail(n)                       !! 1 where micro_ufbar fails, else 0
      integer :: n_eval
      if (table == TABLE_CUSTOM_CODE .and. .not. allocated(custom_grid)) then
         fail = 1.0_dp
         ufbar = 1.0_dp
         return
      end if
      n_eval = merge(1, n, one_damage(n, d))
      if (table == TABLE_CUSTOM_CODE) then
         call block_ufbar(size(custom_grid, 3), custom_grid, custom_grid_index64, custom_domain, n_eval, d, ufbar, fail)
      else
         call block_ufbar(size(DEFAULT_TABLE_GRID, 3), DEFAULT_TABLE_GRID, DEFAULT_GRID_INDEX64, &
            DEFAULT_TABLE_DOMAIN, n_eval, d, ufbar, &
            fail)
      end if
      if (n_eval < n) then
         ufbar(2:n) = ufbar(1)
         fail(2:n) = fail(1)
      end if
   end subroutine micro_block_ufbar

   !> `micro_block_ufbar` on a given grid, BLOCK_CHUNK points at a time.
   pure subroutine block_ufbar(n_cells, grid, grid_index, domain, n, d, ufbar, fail)
      integer, intent(in) :: n_cells
      real(dp), intent(in) :: grid(N_COEFFICIENTS, 0:3, n_cells)
      integer(int64), intent(in) :: grid_index(GRID_INDEX_SIZE)   !! the index in 64-bit integers
      real(dp), intent(in) :: domain(2)
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      real(dp), intent(out) :: ufbar(n), fail(n)
      real(dp) :: s(BLOCK_CHUNK), s_i
      integer(int64) :: cell(BLOCK_CHUNK)
      integer :: i, c0, m
      do c0 = 1, n, BLOCK_CHUNK
         m = min(BLOCK_CHUNK, n - c0 + 1)
         call block_cells(grid_index, domain, m, d(c0:c0 + m - 1), cell, s, fail(c0:c0 + m - 1))
         ! (grid_ufbar's Horner form)
         do i = 1, m
            s_i = s(i)
            ufbar(c0 + i - 1) = grid(IC_UFBAR, 0, cell(i)) + s_i*(grid(IC_UFBAR, 1, cell(i)) &
               + s_i*(grid(IC_UFBAR, 2, cell(i)) + s_i*grid(IC_UFBAR, 3, cell(i))))
         end do
      end do
   end subroutine block_ufbar

   !> For m <= BLOCK_CHUNK damages D(1:m): each one's grid cell and the argument s of its cubics
   !> (the operations of interphase_grid_cell.inc, point by point in a loop the compiler
   !> vectorises: the bit patterns by an element's `transfer`, the same bits as binary64_bits and
   !> binary64_value), and fail = 1 where the point evaluation fails (0 < D < D_MIN_CRACK, D outside
   !> the table's domain), else 0.
   !> One source for the block evaluations of the set and of ufbar alone.
   pure subroutine block_cells(grid_index, domain, m, d, cell, s, fail)
      !> the grid's index in 64-bit integers (with 32-bit ones beside the 64-bit bit patterns
      !> gfortran 12 does not vectorise the loop; a copy made here would cost more than a lookup)
      integer(int64), intent(in) :: grid_index(GRID_INDEX_SIZE)
      real(dp), intent(in) :: domain(2)                      !! the table's [D_first, D_last]
      integer, intent(in) :: m
      real(dp), intent(in) :: d(m)
      integer(int64), intent(out) :: cell(BLOCK_CHUNK)
      real(dp), intent(out) :: s(BLOCK_CHUNK)
      real(dp), intent(out) :: fail(m)
      real(dp) :: v(BLOCK_CHUNK), vc
      integer(int64) :: bits, e, idx, packed, sh
      integer :: i
      do i = 1, m
         v(i) = abs(merge(d(i), 1.0_dp - d(i), d(i) < 0.5_dp))
      end do
      do i = 1, m
         bits = transfer(v(i), 0_int64)
         e = ishft(bits, -52)
         idx = min(int(GRID_INDEX_SIZE, int64), merge(max(e, int(GRID_E_D_FIRST, int64)) - GRID_E_D_FIRST, &
            max(e, int(GRID_E_Y_FIRST, int64)) - GRID_E_Y_FIRST + GRID_Y_OFFSET, d(i) < 0.5_dp) + 1)
         packed = grid_index(idx)
         sh = iand(packed, 63_int64)
         cell(i) = ishft(packed, -6) + ishft(iand(bits, GRID_MANTISSA_MASK), -sh)
         vc = transfer(iand(bits, ishft(-1_int64, sh)), 0.0_dp)
         s(i) = merge(v(i) - vc, vc - v(i), d(i) < 0.5_dp)
      end do
      do i = 1, m
         fail(i) = merge(1.0_dp, 0.0_dp, (d(i) > 0.0_dp .and. d(i) < D_MIN_CRACK) .or. &
            .not. (d(i) >= domain(1) .and. d(i) <= domain(2)))
      end do
   end subroutine block_cells

   !> Whether the n damages D(1:n) have one bit pattern: then a block evaluation of the table is
   !> made once and copied, which gives the same bits, since each value depends on the bits of D
   !> alone. (Compared as 64-bit integers: a vectorised compare a point.)
   pure logical function one_damage(n, d)
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      integer(int64) :: ndiff, bits1
      integer :: i
      bits1 = transfer(d(1), 0_int64)
      ndiff = 0
      do i = 1, n
         ndiff = ndiff + merge(1_int64, 0_int64, transfer(d(i), 0_int64) /= bits1)
      end do
      one_damage = ndiff == 0
   end function one_damage

   !> The interpolated columns (IC_* order) as a coefficient set, with T^f and C^f_T given apart.
   pure function as_set(v, tf, cf_t) result(c)
      real(dp), intent(in) :: v(N_COEFFICIENTS)
      real(dp), intent(in) :: tf, cf_t           !! T^f and C^f_T (or their derivatives), formed apart
      type(coefficient_set_type) :: c
      c = coefficient_set_type(k_n=v(IC_K_N), k_t=v(IC_K_T), kc_n=v(IC_KC_N), kc_t=v(IC_KC_T), &
         dbar_n=v(IC_DBAR_N), dbar_t=v(IC_DBAR_T), tc_t=v(IC_TC_T), sc_n=v(IC_SC_N), &
         cf_t=cf_t, tf=tf, ufbar=v(IC_UFBAR))
   end function as_set

   !> The interpolant must be a law where the update uses it (0 < D < 1): at the ends of every
   !> cell of the table grid and INTERPOLANT_SAMPLES points inside each (interphase_table_grid's
   !> grid_sample_damages, D ascending) it checks the signs the update's structure rests on:
   !> k_N > 0, k_T > 0 (open crack), Dbar_NN > 0 (the open/closed switch Dbar_NN s_N > 0),
   !> ufbar > 0, T^f < 0 (the friction step), S^c_N > 0 and T^c_T > 0 (the closed crack's
   !> stresses). Rows that pass their own checks can still have an interpolant that breaks these
   !> where the rows are far apart (tables/paper-small-d.dat, short cracks only and then the a = b
   !> row, has Dbar_NN < 0 from D = 0.30). Dbar_TT is not among them: it only sets the slip an open
   !> crack's faces keep for when they close again, and the paper-resolution table's spline
   !> undershoots it (Dbar_TT >= -4.7e-3 for D < 0.014, between its rows at a = 0 and 1 mm;
   !> tables/README.md). On failure: STATUS_TABLE_INTERPOLANT, the first D, the coefficient's name
   !> and its value.
   pure subroutine check_interpolant(grid, grid_index, domain, status, bad_d, bad_name, bad_value)
      real(dp), contiguous, intent(in) :: grid(:, 0:, :)     !! the table grid (column, power, cell)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)     !! its index
      real(dp), intent(in) :: domain(2)                      !! the table's [D_first, D_last]
      integer, intent(out) :: status
      real(dp), intent(out) :: bad_d                         !! where (-), when status /= STATUS_OK
      character(len=*), intent(out) :: bad_name              !! which coefficient
      real(dp), intent(out) :: bad_value                     !! its value there
      type(coefficient_set_type) :: c
      real(dp), allocatable :: damages(:)
      real(dp) :: values(7)
      integer :: i, k
      character(len=8), parameter :: NAMES(7) = [character(len=8) :: 'k_N', 'k_T', 'Dbar_NN', &
         'ufbar', '-T^f', 'S^c_N', 'T^c_T']
      status = STATUS_OK
      c = NO_COEFFICIENTS    ! (set by every successful grid_values: for the compiler's flow analysis)
      bad_d = 0.0_dp
      bad_name = ''
      bad_value = 0.0_dp
      call grid_sample_damages(grid_index, INTERPOLANT_SAMPLES, damages)
      do i = 1, size(damages)
         if (.not. (damages(i) > max(D_MIN_CRACK, domain(1)) .and. damages(i) < min(1.0_dp, domain(2)))) cycle
         call grid_values(size(grid, 3), grid, grid_index, domain, damages(i), c, status)
         if (status /= STATUS_OK) return
         values = [c%k_n, c%k_t, c%dbar_n, c%ufbar, -c%tf, c%sc_n, c%tc_t]
         do k = 1, size(values)
            if (.not. (values(k) > 0.0_dp)) then
               status = STATUS_TABLE_INTERPOLANT
               bad_d = damages(i)
               bad_name = NAMES(k)
               bad_value = values(k)
               return
            end if
         end do
      end do
   end subroutine check_interpolant

   !> The built-in table's spline: its interpolation variable, knots and cubics (the grid's source,
   !> for the tests).
   pure subroutine default_table_data(variable, knots, coef_table)
      integer, intent(out) :: variable
      real(dp), allocatable, intent(out) :: knots(:), coef_table(:, :, :)
      variable = DEFAULT_TABLE_VARIABLE
      knots = DEFAULT_TABLE_KNOTS
      coef_table = DEFAULT_TABLE_COEF
   end subroutine default_table_data

   !> Read, check and interpolate a custom table: its spline, then the spline's grid (the
   !> interpolant the updates use), checked; call once at start-up, before any update and from one
   !> thread (UEXTERNALDB at LOP = 0 does). A second call replaces the table and is only safe while
   !> no update runs.
   subroutine load_custom_table(path, status, message)
      character(len=*), intent(in) :: path                   !! table file (tables/README.md format)
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      type(rve_table_type) :: table
      type(spline_type) :: spline
      real(dp), allocatable :: x(:), y(:, :)
      integer :: n
      real(dp) :: bad_d, bad_value
      real(dp), allocatable :: knots(:), coef(:, :, :), grid(:, :, :)
      integer :: grid_index(GRID_INDEX_SIZE)
      real(dp) :: domain(2)
      character(len=32) :: bad_name

      call read_rve_table(path, table, status, message)
      if (status /= STATUS_OK) return
      call check_rve_table(table, status, message)
      if (status /= STATUS_OK) return
      n = size(table%rows, 1)
      allocate (x(n), y(n, N_COEFFICIENTS))
      call interpolation_data(table, x, y)
      call spline_build(x, y, TABLE_SPLINE_METHOD, spline, status)
      if (status == STATUS_SPLINE_TOO_FEW_POINTS) then
         write (message, '(a,a,i0,a)') message_path(table%source), ': ', n, ' rows, but the interpolant '// &
            '(a not-a-knot cubic spline) needs at least 4: add rows between a = 0 and a = b'
         return
      else if (status /= STATUS_OK) then
         message = message_path(table%source)//': '//status_message(status)
         return
      end if
      call spline_export(spline, knots, coef)
      call grid_build(table%variable, knots, y, coef, grid, grid_index, domain, status)
      if (status /= STATUS_OK) then
         message = message_path(table%source)//': the table grid: '//status_message(status)
         return
      end if
      ! the interpolant between the rows must be a law too (signs the update relies on)
      call check_interpolant(grid, grid_index, domain, status, bad_d, bad_name, bad_value)
      if (status /= STATUS_OK) then
         ! (the path as tried: a relative one resolved; D with its ligament 1 - D, which four
         ! digits of D near a = b would hide)
         ! (the path shortened to leave the rest of the message its 145 characters)
         ! (es_field: a three-digit exponent keeps its E, -1.205E+273, not -1.205+273)
         message = message_path(table%source, MESSAGE_LEN - 145)// &
            ': interpolant between rows: '//trim(bad_name)//' = '//trim(adjustl(es_field(bad_value, 11, 3)))// &
            ' at 1 - D = '//trim(adjustl(es_field(1.0_dp - bad_d, 11, 3)))// &
            ' (a = b - '//trim(adjustl(es_field((1.0_dp - bad_d)*table%b, 11, 3)))//' mm, b = '// &
            trim(adjustl(es_field(table%b, 11, 3)))//' mm), not > 0: add rows there'
         return
      end if
      call grid_state_columns(grid, grid_index, domain, custom_state_columns, custom_state_status)
      call move_alloc(grid, custom_grid)
      custom_grid_index = grid_index
      custom_grid_index64 = int(grid_index, int64)
      custom_domain = domain
      ! the file as it was tried (a relative path resolved against the current directory)
      custom_source = table%source
   end subroutine load_custom_table

   !> Whether a custom table has been loaded (the micromechanical model with PROPS(8) = 1 needs one).
   pure logical function custom_table_loaded()
      custom_table_loaded = allocated(custom_grid)
   end function custom_table_loaded

   !> Where the table selected by `table` came from (for messages and output headers).
   function custom_table_source(table) result(source)
      integer, intent(in) :: table
      character(len=:), allocatable :: source
      if (table == TABLE_CUSTOM_CODE) then
         if (allocated(custom_source)) then
            source = custom_source
         else
            source = '(no custom table loaded)'
         end if
      else
         source = 'built-in '//DEFAULT_TABLE_SOURCE
      end if
   end function custom_table_source

end module interphase_micro_coefficients
