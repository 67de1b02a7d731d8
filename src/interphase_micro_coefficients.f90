!> The micromechanical model's coefficient provider: the coefficient set at damage D
!> interpolated from an RVE table (paper section 5.1: "spline regression" of the FE results),
!> with its derivatives d/dD for the consistent tangent.
!>
!> Two tables can serve: the default one, compiled in as generated `parameter` data
!> (`interphase_default_table`, from tables/paper.dat), and one custom table per process,
!> loaded once at start-up by `load_custom_table` (Abaqus: UEXTERNALDB; the driver: its case
!> file) into `protected` data that the pure update only reads.
module interphase_micro_coefficients
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_real_text, only: es_field
   use interphase_logarithm, only: ln_positive_block
   use interphase_enums, only: TABLE_CUSTOM_CODE
   use interphase_status, only: STATUS_OK, STATUS_TABLE_NOT_LOADED, STATUS_BAD_COEFFICIENTS, MESSAGE_LEN, &
      STATUS_TABLE_INTERPOLANT, status_message, message_path, STATUS_SPLINE_OUT_OF_RANGE, &
      STATUS_SPLINE_NONFINITE_ARGUMENT, STATUS_SPLINE_TOO_FEW_POINTS
   use interphase_coefficients, only: coefficient_set_type, NO_COEFFICIENTS
   use interphase_finite, only: EXPONENT_MASK, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, D_MIN_CRACK
   use interphase_spline, only: spline_type, spline_build, spline_export, &
      cubic_locate, cubic_eval, guide_build
   use interphase_rve_table, only: rve_table_type, read_rve_table, check_rve_table, &
      interpolation_data, N_COEFFICIENTS, TABLE_SPLINE_METHOD, VARIABLE_DAMAGE, IC_K_N, IC_K_T, &
      IC_KC_N, IC_KC_T, IC_DBAR_N, IC_DBAR_T, IC_TC_T, IC_SC_N, IC_DTF, IC_UFBAR, state_columns
   use interphase_default_table, only: DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, DEFAULT_TABLE_SOURCE, &
      DEFAULT_TABLE_VARIABLE, DEFAULT_TABLE_GUIDE, DEFAULT_TABLE_GUIDE_SCALE, DEFAULT_TABLE_GUIDE_STEPS, &
      DEFAULT_TABLE_STATE_COLUMNS, DEFAULT_TABLE_STATE_STATUS
   implicit none
   private
   public :: micro_coefficients, micro_values, micro_ufbar, load_custom_table, custom_table_source, table_coefficients, &
      custom_table_loaded, check_interpolant, default_table_data, micro_block_coefficients, table_curvature_type, &
      micro_second_derivatives, micro_block_ufbar

   !> What a table evaluation with derivatives keeps so that the second derivatives d2/dD2 of its
   !> set can be formed later, and only where they are used (`micro_second_derivatives`): the
   !> fracture law's search needs them at a damage where the crack grows, which it knows only
   !> after g there is formed. No default initialisation (hot path): table_coefficients sets every
   !> member where it returns STATUS_OK.
   type :: table_curvature_type
      real(dp) :: d2v_x(N_COEFFICIENTS)  !! the interpolated columns' second derivatives in the crack variable x
      real(dp) :: dv_x(N_COEFFICIENTS)   !! their first derivatives in x
      real(dp) :: dx_dd                  !! dx/dD (-)
      real(dp) :: d2x_dd2                !! d2x/dD2 (-)
   end type table_curvature_type

   !> Points per chunk of the block evaluations (fixed-size working arrays: a run-time-sized
   !> automatic array would be allocated on the heap at every call).
   integer, parameter :: BLOCK_CHUNK = 64

   !> Points per interval between two rows at which `check_interpolant` evaluates the interpolant.
   integer, parameter :: INTERPOLANT_SAMPLES = 16

   !> Smallest positive damage at which the tables' coefficients are evaluated (-): interphase_finite's
   public :: D_MIN_CRACK

   !> The bit pattern of D = 1, the broken state (the intact state D = +0 is the pattern 0).
   integer(int64), parameter :: BROKEN_BITS = int(z'3FF0000000000000', int64)

   !> The custom table: written once by `load_custom_table` before any update, then read only.
   integer, protected :: custom_variable = 0
   real(dp), allocatable, protected :: custom_knots(:)
   real(dp), allocatable, protected :: custom_coef(:, :, :)
   !> its knots' interval guide (interphase_spline's guide_build)
   integer, allocatable, protected :: custom_guide(:)
   real(dp), protected :: custom_guide_scale = 0.0_dp
   integer, protected :: custom_guide_steps = 0
   !> its interpolated columns at D = +0 and D = 1, and the status of each (interphase_rve_table's
   !> state_columns; STATUS_TABLE_NOT_LOADED until a table is loaded)
   real(dp), protected :: custom_state_columns(N_COEFFICIENTS, 2) = 0.0_dp
   integer, protected :: custom_state_status(2) = STATUS_TABLE_NOT_LOADED
   character(len=:), allocatable, protected :: custom_source

contains

   ! the crack variable's finiteness test, here where the compiler inlines it (interphase_finite's,
   ! from the same source)
   include 'interphase_binary64_bits.inc'
   include 'interphase_is_finite.inc'
   ! the logarithm of the interpolation variable, here where the compiler inlines it (interphase_logarithm's
   ! ln_positive, from the same source: the same operations as ln_positive_block's)
   include 'interphase_ln_positive.inc'
   ! (the interpolation variable, from interphase_rve_table's source)
   include 'interphase_crack_variable.inc'

   !> Coefficients at D from the selected table (TABLE_DEFAULT_CODE or TABLE_CUSTOM_CODE).
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
      ! (the guided lookup called directly, on arrays of explicit shape, with or without what the
      ! second derivatives are formed from: no optional argument reaches the hot path, which
      ! a compiler that does not inline table_coefficients would test at every call)
      if (table == TABLE_CUSTOM_CODE) then
         if (.not. allocated(custom_coef)) then
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         if (present(curvature)) then
            call guided_coefficients(custom_variable, size(custom_knots), custom_knots, custom_coef, size(custom_guide), &
               custom_guide, custom_guide_scale, custom_guide_steps, d, .true., coef, dcoef_dd, curvature, status)
         else
            call guided_coefficients(custom_variable, size(custom_knots), custom_knots, custom_coef, size(custom_guide), &
               custom_guide, custom_guide_scale, custom_guide_steps, d, .false., coef, dcoef_dd, unused_curvature, status)
         end if
      else if (present(curvature)) then
         call guided_coefficients(DEFAULT_TABLE_VARIABLE, size(DEFAULT_TABLE_KNOTS), DEFAULT_TABLE_KNOTS, &
            DEFAULT_TABLE_COEF, size(DEFAULT_TABLE_GUIDE), DEFAULT_TABLE_GUIDE, DEFAULT_TABLE_GUIDE_SCALE, &
            DEFAULT_TABLE_GUIDE_STEPS, d, .true., coef, dcoef_dd, curvature, status)
      else
         call guided_coefficients(DEFAULT_TABLE_VARIABLE, size(DEFAULT_TABLE_KNOTS), DEFAULT_TABLE_KNOTS, &
            DEFAULT_TABLE_COEF, size(DEFAULT_TABLE_GUIDE), DEFAULT_TABLE_GUIDE, DEFAULT_TABLE_GUIDE_SCALE, &
            DEFAULT_TABLE_GUIDE_STEPS, d, .false., coef, dcoef_dd, unused_curvature, status)
      end if
   end subroutine micro_coefficients

   !> Coefficients at D from interpolation data (docs/theory.md). The data hold D T^f
   !> (IC_DTF), smooth down to D = 0; T^f = (D T^f)/D. At D = 0 (no crack) T^f has no finite
   !> value: the set holds -huge(1.0_dp) there, which no regime uses (D = 0 is intact), and
   !> zero derivatives. Below D = D_MIN_CRACK (> 0) T^f ~ 1/D and its derivatives ~ 1/D^2,
   !> 1/D^3 would come close to overflow: STATUS_BAD_COEFFICIENTS (no update reaches such a D:
   !> the displacement law's first damage is above 1e-16, and D0 is the fracture law's start).
   pure subroutine table_coefficients(variable, knots, coef_table, d, coef, dcoef_dd, status, curvature, &
         guide, guide_scale, guide_steps)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      real(dp), contiguous, intent(in) :: knots(:)           !! knots, ascending
      !> cubic coefficients (column, power, interval), the columns IC_* (N_COEFFICIENTS of them)
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)
      real(dp), intent(in) :: d
      type(coefficient_set_type), intent(out) :: coef
      !> first derivatives d/dD (absent: not formed; curvature, which needs them, must then be
      !> absent too: it would be left undefined)
      type(coefficient_set_type), intent(out), optional :: dcoef_dd
      integer, intent(out) :: status
      !> what `micro_second_derivatives` needs for the second derivatives d2/dD2 at D
      type(table_curvature_type), intent(out), optional :: curvature
      !> the knots' interval guide (guide_build), all three or none: the interval from x's cell
      !> (the same interval as cubic_locate's binary search, in fewer steps)
      integer, intent(in), optional :: guide(:)
      real(dp), intent(in), optional :: guide_scale
      integer, intent(in), optional :: guide_steps

      real(dp) :: x, dx_dd, d2x_dd2, v(N_COEFFICIENTS), dv(N_COEFFICIENTS)
      type(coefficient_set_type) :: unused_dcoef
      type(table_curvature_type) :: unused_curvature
      integer :: interval

      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      if (present(guide)) then
         if (.not. present(dcoef_dd)) then
            ! the values alone: table_values (the same guide, the same Horner form, so the same
            ! numbers)
            call table_values(variable, size(knots), knots, coef_table, size(guide), guide, guide_scale, &
               guide_steps, d, coef, status)
         else if (present(curvature)) then
            call guided_coefficients(variable, size(knots), knots, coef_table, size(guide), guide, guide_scale, &
               guide_steps, d, .true., coef, dcoef_dd, curvature, status)
         else
            call guided_coefficients(variable, size(knots), knots, coef_table, size(guide), guide, guide_scale, &
               guide_steps, d, .false., coef, dcoef_dd, unused_curvature, status)
         end if
         return
      end if
      ! without a guide: cubic_locate's binary search, then cubic_eval's Horner form (the same
      ! numbers as the guided lookup's)
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
      if (present(dcoef_dd)) then
         call form_sets(d, v, dv, coef, dcoef_dd)
      else
         call form_sets(d, v, dv, coef, unused_dcoef)
      end if
   end subroutine table_coefficients

   !> table_coefficients' guided lookup with first derivatives, on arrays of explicit shape (no
   !> descriptors, no optional arguments): the interval from the knots' guide, every column's
   !> cubic with its derivative in x (guided_cubics), the sets at D (form_sets) and, with
   !> `with_curvature`, what micro_second_derivatives forms the second derivatives from (else
   !> `curvature` is left undefined).
   pure subroutine guided_coefficients(variable, n_knots, knots, coef_table, n_guide, guide, guide_scale, guide_steps, &
         d, with_curvature, coef, dcoef_dd, curvature, status)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      integer, intent(in) :: n_knots                         !! knots (>= 2)
      real(dp), intent(in) :: knots(n_knots)                 !! knots, ascending
      real(dp), intent(in) :: coef_table(N_COEFFICIENTS, 0:3, n_knots - 1)   !! as table_coefficients'
      integer, intent(in) :: n_guide                         !! cells of the guide
      integer, intent(in) :: guide(n_guide)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      real(dp), intent(in) :: d                              !! damage D = a/b
      logical, intent(in) :: with_curvature
      type(coefficient_set_type), intent(out) :: coef, dcoef_dd
      type(table_curvature_type), intent(out) :: curvature
      integer, intent(out) :: status
      real(dp) :: x, dx_dd, d2x_dd2, v(N_COEFFICIENTS), dv(N_COEFFICIENTS)
      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      call crack_variable(variable, d, x, dx_dd, d2x_dd2)
      ! the columns' values v, and their derivatives in x (kept), then in D (dv)
      call guided_cubics(n_knots, knots, coef_table, n_guide, guide, guide_scale, guide_steps, x, with_curvature, v, &
         curvature%dv_x, curvature%d2v_x, status)
      if (status /= STATUS_OK) return
      if (with_curvature) then
         curvature%dx_dd = dx_dd
         curvature%d2x_dd2 = d2x_dd2
      end if
      dv = curvature%dv_x*dx_dd
      call form_sets(d, v, dv, coef, dcoef_dd)
   end subroutine guided_coefficients

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
      real(dp) :: tf, dtf, dcf
      tf = -huge(1.0_dp)
      if (d > 0.0_dp) tf = v(IC_DTF)/d
      coef = as_set(v, tf, reciprocal_cf(v(IC_TC_T), d, v(IC_UFBAR)))
      dtf = 0.0_dp
      if (d > 0.0_dp) dtf = (dv(IC_DTF) - tf)/d
      dcf = -(dv(IC_TC_T)*(d*v(IC_UFBAR)) + v(IC_TC_T)*(v(IC_UFBAR) + d*dv(IC_UFBAR)))
      dcoef_dd = as_set(dv, dtf, dcf)
   end subroutine form_sets

   ! the second derivatives from what table_coefficients kept (one source, included in
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
   !> (table_coefficients, table_values, block_values) forms it so, in this order of operations
   !> (the same bits).
   elemental real(dp) function reciprocal_cf(tc_t, d, ufbar) result(cf_t)
      real(dp), intent(in) :: tc_t               !! tc_t = T^c_T/h at D (MPa/mm)
      real(dp), intent(in) :: d                  !! D (-)
      real(dp), intent(in) :: ufbar              !! ufbar at D (-)
      cf_t = -tc_t*(d*ufbar)
   end function reciprocal_cf

   !> The guided path of table_coefficients: the interval of x from the knots' guide, and every
   !> column's cubic in cubic_eval's Horner form with its first derivative in x (and the second,
   !> `second`), here where the loop knows its columns and the data's unit strides (arrays of
   !> explicit shape: no descriptors).
   pure subroutine guided_cubics(n_knots, knots, coef_table, n_guide, guide, guide_scale, guide_steps, x, second, &
         v, dv, d2v, status)
      integer, intent(in) :: n_knots                         !! knots (>= 2)
      real(dp), intent(in) :: knots(n_knots)                 !! knots, ascending
      real(dp), intent(in) :: coef_table(N_COEFFICIENTS, 0:3, n_knots - 1)   !! as table_coefficients'
      integer, intent(in) :: n_guide                         !! cells of the guide
      integer, intent(in) :: guide(n_guide)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      real(dp), intent(in) :: x                              !! the crack variable
      logical, intent(in) :: second                          !! d2v too (else left undefined)
      real(dp), intent(out) :: v(N_COEFFICIENTS), dv(N_COEFFICIENTS), d2v(N_COEFFICIENTS)  !! in x
      integer, intent(out) :: status
      real(dp) :: t
      integer :: interval, candidate, j, k
      include 'interphase_guided_interval.inc'
      do j = 1, N_COEFFICIENTS
         v(j) = coef_table(j, 0, interval) + t*(coef_table(j, 1, interval) &
            + t*(coef_table(j, 2, interval) + t*coef_table(j, 3, interval)))
         dv(j) = coef_table(j, 1, interval) + t*(2.0_dp*coef_table(j, 2, interval) &
            + 3.0_dp*t*coef_table(j, 3, interval))
         if (second) d2v(j) = 2.0_dp*coef_table(j, 2, interval) + 6.0_dp*t*coef_table(j, 3, interval)
      end do
   end subroutine guided_cubics

   !> The coefficients at D from the selected table, values only (`micro_coefficients` without
   !> derivatives, the entry of the updates that need none: the same numbers bit for bit, the
   !> same statuses; a procedure of its own, so that its code does not depend on how the compiler
   !> specialises the optional arguments of table_coefficients).
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
         ! points are: the table's columns there, evaluated once (state_columns, with the operations
         ! of table_values: the same bits, the same status), without the logarithm, the crack
         ! variable's division or the interval search
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
         if (.not. allocated(custom_coef)) then
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         call table_values(custom_variable, size(custom_knots), custom_knots, custom_coef, size(custom_guide), &
            custom_guide, custom_guide_scale, custom_guide_steps, d, coef, status)
      else
         call table_values(DEFAULT_TABLE_VARIABLE, size(DEFAULT_TABLE_KNOTS), DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, &
            size(DEFAULT_TABLE_GUIDE), DEFAULT_TABLE_GUIDE, DEFAULT_TABLE_GUIDE_SCALE, DEFAULT_TABLE_GUIDE_STEPS, d, &
            coef, status)
      end if
   end subroutine micro_values

   !> table_coefficients' values without derivatives (its guided path): the interval from the
   !> guide, every column's cubic in Horner form, T^f = (D T^f)/D (-huge at D = 0). (Arrays of
   !> explicit shape: no descriptors, and the column stride a constant, whichever table it is.)
   pure subroutine table_values(variable, n_knots, knots, coef_table, n_guide, guide, guide_scale, guide_steps, d, &
         coef, status)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      integer, intent(in) :: n_knots                         !! knots (>= 2)
      real(dp), intent(in) :: knots(n_knots)                 !! knots, ascending
      real(dp), intent(in) :: coef_table(N_COEFFICIENTS, 0:3, n_knots - 1)   !! as table_coefficients'
      integer, intent(in) :: n_guide                         !! cells of the guide
      integer, intent(in) :: guide(n_guide)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      real(dp), intent(in) :: d
      type(coefficient_set_type), intent(out) :: coef
      integer, intent(out) :: status
      real(dp) :: x, dx_dd, d2x_dd2, t, v(N_COEFFICIENTS)
      integer :: interval, candidate, j, k
      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      call crack_variable(variable, d, x, dx_dd, d2x_dd2)
      include 'interphase_guided_interval.inc'
      do j = 1, N_COEFFICIENTS
         v(j) = coef_table(j, 0, interval) + t*(coef_table(j, 1, interval) &
            + t*(coef_table(j, 2, interval) + t*coef_table(j, 3, interval)))
      end do
      call columns_set(v, d, coef)
   end subroutine table_values

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
   !> of micro_coefficients' set, at the same interval in the same Horner form, so the same
   !> number bit for bit, and the same statuses; one cubic instead of the set.
   pure subroutine micro_ufbar(table, d, ufbar, status)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      real(dp), intent(in) :: d                              !! damage D = a/b
      real(dp), intent(out) :: ufbar                         !! ufbar(D) (-)
      integer, intent(out) :: status
      if (table == TABLE_CUSTOM_CODE) then
         if (.not. allocated(custom_coef)) then
            ufbar = 0.0_dp
            status = STATUS_TABLE_NOT_LOADED
            return
         end if
         call table_ufbar(custom_variable, custom_knots, custom_coef, custom_guide, custom_guide_scale, &
            custom_guide_steps, d, ufbar, status)
      else
         call table_ufbar(DEFAULT_TABLE_VARIABLE, DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, DEFAULT_TABLE_GUIDE, &
            DEFAULT_TABLE_GUIDE_SCALE, DEFAULT_TABLE_GUIDE_STEPS, d, ufbar, status)
      end if
   end subroutine micro_ufbar

   !> table_coefficients' value of the column IC_UFBAR (its guided path).
   pure subroutine table_ufbar(variable, knots, coef_table, guide, guide_scale, guide_steps, d, ufbar, status)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      real(dp), contiguous, intent(in) :: knots(:)           !! knots, ascending
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)
      integer, intent(in) :: guide(:)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      real(dp), intent(in) :: d
      real(dp), intent(out) :: ufbar
      integer, intent(out) :: status
      real(dp) :: x, dx_dd, d2x_dd2, t
      integer :: interval, candidate, k
      ! (ufbar defined on the failure paths too, 0 there: with the callers inlined, for the
      ! compiler's uninitialised-use analysis)
      ufbar = 0.0_dp
      if (d > 0.0_dp .and. d < D_MIN_CRACK) then
         status = STATUS_BAD_COEFFICIENTS
         return
      end if
      call crack_variable(variable, d, x, dx_dd, d2x_dd2)
      include 'interphase_guided_interval.inc'
      ufbar = coef_table(IC_UFBAR, 0, interval) + t*(coef_table(IC_UFBAR, 1, interval) &
         + t*(coef_table(IC_UFBAR, 2, interval) + t*coef_table(IC_UFBAR, 3, interval)))
   end subroutine table_ufbar

   !> The coefficients at n damages D(1:n) from the selected table, values only (no derivatives):
   !> the vectorised block update's provider (interphase_block). Each value is bit for bit what
   !> `table_coefficients` returns at that D: the same interpolation variable, the same interval
   !> (from the knots' interval guide, which ends where the search of `cubic_locate` does), the
   !> same Horner form, the same T^f = (D T^f)/D. fail(i) = 1 where `table_coefficients` would
   !> fail (0 < D < D_MIN_CRACK, the variable outside the knots, no custom table loaded), else 0
   !> (a real flag, so that the caller's loops that combine it vectorise); the values there are
   !> finite but meaningless. D must be finite in [0, 1] (the block update's damages are).
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
      if (table == TABLE_CUSTOM_CODE .and. .not. allocated(custom_coef)) then
         fail = 1.0_dp
         k_n = 0.0_dp; k_t = 0.0_dp; kc_n = 0.0_dp; kc_t = 0.0_dp; dbar_n = 0.0_dp; dbar_t = 0.0_dp
         tc_t = 0.0_dp; sc_n = 0.0_dp; cf_t = 0.0_dp; tf = -huge(1.0_dp); ufbar = 1.0_dp
         return
      end if
      n_eval = merge(1, n, one_damage(n, d))
      if (table == TABLE_CUSTOM_CODE) then
         call block_values(custom_variable, custom_knots, custom_coef, custom_guide, custom_guide_scale, &
            custom_guide_steps, n_eval, d, k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar, fail)
      else
         call block_values(DEFAULT_TABLE_VARIABLE, DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, DEFAULT_TABLE_GUIDE, &
            DEFAULT_TABLE_GUIDE_SCALE, DEFAULT_TABLE_GUIDE_STEPS, n_eval, d, k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, &
            tc_t, sc_n, cf_t, tf, ufbar, fail)
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

   !> `micro_block_coefficients` on given interpolation data, BLOCK_CHUNK points at a time.
   pure subroutine block_values(variable, knots, coef_table, guide, guide_scale, guide_steps, n, d, k_n, k_t, &
         kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar, fail)
      integer, intent(in) :: variable
      real(dp), contiguous, intent(in) :: knots(:)
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)
      integer, intent(in) :: guide(:)                        !! the knots' interval guide (guide_build)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      real(dp), intent(out), dimension(n) :: k_n, k_t, kc_n, kc_t, dbar_n, dbar_t, tc_t, sc_n, cf_t, tf, ufbar
      real(dp), intent(out) :: fail(n)
      real(dp) :: x(BLOCK_CHUNK), t(BLOCK_CHUNK), v(N_COEFFICIENTS, BLOCK_CHUNK), t_i
      integer :: lo(BLOCK_CHUNK), i, j, k, c0, m
      do c0 = 1, n, BLOCK_CHUNK
         m = min(BLOCK_CHUNK, n - c0 + 1)
         call block_locate(variable, knots, guide, guide_scale, guide_steps, m, d(c0:c0 + m - 1), x, lo, &
            fail(c0:c0 + m - 1))
         ! the columns of one point together (cubic_eval's Horner form): a point's coefficients on
         ! its interval are contiguous in the data (column fastest), so the compiler evaluates the
         ! columns as a few short vectors each power, where a loop over the points would gather
         ! every coefficient of every column; then the columns copied out point by point
         do i = 1, m
            t_i = x(i) - knots(lo(i))
            do j = 1, N_COEFFICIENTS
               v(j, i) = coef_table(j, 0, lo(i)) + t_i*(coef_table(j, 1, lo(i)) &
                  + t_i*(coef_table(j, 2, lo(i)) + t_i*coef_table(j, 3, lo(i))))
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
         ! T^f = (D T^f)/D; -huge at D = 0 (table_coefficients). The divisor is guarded by max, not
         ! by a selection (which the compiler may turn into two divisions under -fno-trapping-math):
         ! below D_MIN_CRACK (a failing point) the quotient could overflow
         do i = 1, m
            k = c0 + i - 1
            tf(k) = merge(t(i)/max(d(k), D_MIN_CRACK), -huge(1.0_dp), d(k) > 0.0_dp)
         end do
      end do
   end subroutine block_values

   !> ufbar(D) alone at n damages D(1:n), with the failure flags of `micro_block_coefficients`:
   !> each value bit for bit what `micro_ufbar` returns at that D (the same interval and Horner
   !> form), fail(i) = 1 where it fails. For the block update's trial slip of a growing crack
   !> (m(D_n) = D_n ufbar(D_n)), which needs this one column at the old damage. A block of one
   !> damage is evaluated once, as in `micro_block_coefficients`.
   pure subroutine micro_block_ufbar(table, n, d, ufbar, fail)
      integer, intent(in) :: table                           !! TABLE_*_CODE of interphase_layout
      integer, intent(in) :: n                               !! number of points (>= 1)
      real(dp), intent(in) :: d(n)                           !! damage D = a/b (-), finite in [0, 1]
      real(dp), intent(out) :: ufbar(n)                      !! ufbar(D) (-)
      real(dp), intent(out) :: fail(n)                       !! 1 where micro_ufbar fails, else 0
      integer :: n_eval
      if (table == TABLE_CUSTOM_CODE .and. .not. allocated(custom_coef)) then
         fail = 1.0_dp
         ufbar = 1.0_dp
         return
      end if
      n_eval = merge(1, n, one_damage(n, d))
      if (table == TABLE_CUSTOM_CODE) then
         call block_ufbar(custom_variable, custom_knots, custom_coef, custom_guide, custom_guide_scale, &
            custom_guide_steps, n_eval, d, ufbar, fail)
      else
         call block_ufbar(DEFAULT_TABLE_VARIABLE, DEFAULT_TABLE_KNOTS, DEFAULT_TABLE_COEF, DEFAULT_TABLE_GUIDE, &
            DEFAULT_TABLE_GUIDE_SCALE, DEFAULT_TABLE_GUIDE_STEPS, n_eval, d, ufbar, fail)
      end if
      if (n_eval < n) then
         ufbar(2:n) = ufbar(1)
         fail(2:n) = fail(1)
      end if
   end subroutine micro_block_ufbar

   !> `micro_block_ufbar` on given interpolation data, BLOCK_CHUNK points at a time.
   pure subroutine block_ufbar(variable, knots, coef_table, guide, guide_scale, guide_steps, n, d, ufbar, fail)
      integer, intent(in) :: variable
      real(dp), contiguous, intent(in) :: knots(:)
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)
      integer, intent(in) :: guide(:)                        !! the knots' interval guide (guide_build)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      real(dp), intent(out) :: ufbar(n), fail(n)
      real(dp) :: x(BLOCK_CHUNK), t_i
      integer :: lo(BLOCK_CHUNK), i, c0, m
      do c0 = 1, n, BLOCK_CHUNK
         m = min(BLOCK_CHUNK, n - c0 + 1)
         call block_locate(variable, knots, guide, guide_scale, guide_steps, m, d(c0:c0 + m - 1), x, lo, &
            fail(c0:c0 + m - 1))
         ! (table_ufbar's Horner form)
         do i = 1, m
            t_i = x(i) - knots(lo(i))
            ufbar(c0 + i - 1) = coef_table(IC_UFBAR, 0, lo(i)) + t_i*(coef_table(IC_UFBAR, 1, lo(i)) &
               + t_i*(coef_table(IC_UFBAR, 2, lo(i)) + t_i*coef_table(IC_UFBAR, 3, lo(i))))
         end do
      end do
   end subroutine block_ufbar

   !> For m <= BLOCK_CHUNK damages D(1:m): the interpolation variable x (crack_variable: x = D, or
   !> w = 1/(1 - ln(1 - D)), 0 at D = 1, with crack_variable's logarithm: ln_positive gives the
   !> same bits in scalar and vector code), the interval lo of x among the knots (the guided
   !> interval of interphase_guided_interval.inc, which ends where cubic_locate's search does),
   !> and fail = 1 where the point evaluation fails (0 < D < D_MIN_CRACK, x outside the knots),
   !> else 0. One source for the block evaluations of the set and of ufbar alone.
   pure subroutine block_locate(variable, knots, guide, guide_scale, guide_steps, m, d, x, lo, fail)
      integer, intent(in) :: variable
      real(dp), contiguous, intent(in) :: knots(:)
      integer, intent(in) :: guide(:)
      real(dp), intent(in) :: guide_scale
      integer, intent(in) :: guide_steps
      integer, intent(in) :: m
      real(dp), intent(in) :: d(m)
      real(dp), intent(out) :: x(BLOCK_CHUNK)
      integer, intent(out) :: lo(BLOCK_CHUNK)
      real(dp), intent(out) :: fail(m)
      real(dp) :: y(BLOCK_CHUNK), x_k, x_lo, x_hi
      integer :: nk, step, cand, i, ncells
      logical :: inside
      nk = size(knots)
      ncells = size(guide)
      x_lo = knots(1)
      x_hi = knots(nk)
      if (variable == VARIABLE_DAMAGE) then
         x(1:m) = d
      else
         ! (the argument is 1 - D for every D < 1; at D = 1, where x = 0, it stays > 0)
         do i = 1, m
            y(i) = 1.0_dp - min(d(i), 1.0_dp - 0.5_dp*epsilon(1.0_dp))
         end do
         call ln_positive_block(m, y, x)
         do i = 1, m
            x(i) = merge(1.0_dp/(1.0_dp - x(i)), 0.0_dp, d(i) < 1.0_dp)
         end do
      end if
      ! (x compared at every point, the two conditions combined after: written as one short-circuit
      ! condition, gfortran loaded x only where D passed its test and compared the lanes of the
      ! others unloaded, which can raise an exception under -fno-trapping-math)
      do i = 1, m
         x_k = x(i)
         inside = x_k >= x_lo .and. x_k <= x_hi
         fail(i) = merge(0.0_dp, 1.0_dp, inside .and. .not. (d(i) > 0.0_dp .and. d(i) < D_MIN_CRACK))
      end do
      ! the interval: the largest lo in 1..nk-1 with knots(lo) <= x (cubic_locate's interval; at
      ! x = knots(nk), nk - 1), from the interval guide: the guide's interval of x's cell
      ! (guide_cell, of x clamped to the knots: where the point fails x may lie outside), then
      ! guide_steps forward comparisons (guide_locate)
      do i = 1, m
         x_k = min(max(x(i), x_lo), x_hi)
         lo(i) = guide(min(ncells, max(1, int((x_k - x_lo)*guide_scale) + 1)))
      end do
      do step = 1, guide_steps
         do i = 1, m
            cand = min(lo(i) + 1, nk - 1)
            lo(i) = merge(cand, lo(i), x(i) >= knots(cand))
         end do
      end do
   end subroutine block_locate

   !> Whether the n damages D(1:n) are one value bit for bit (equal numbers of the same sign, NaN
   !> counted as different): then a block evaluation of the table is made once and copied, which
   !> gives the same bits, since each value depends on D alone.
   pure logical function one_damage(n, d)
      integer, intent(in) :: n
      real(dp), intent(in) :: d(n)
      integer(int64) :: ndiff
      real(dp) :: d1, sign1
      integer :: i
      d1 = d(1)
      sign1 = sign(1.0_dp, d1)
      ndiff = 0
      do i = 1, n
         ndiff = ndiff + merge(0_int64, 1_int64, abs(d(i) - d1) <= 0.0_dp .and. sign(1.0_dp, d(i)) >= sign1 &
            .and. sign(1.0_dp, d(i)) <= sign1)
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

   !> The interpolant between a table's rows must be a law where the update uses it (0 < D < 1):
   !> at INTERPOLANT_SAMPLES points inside every interval of the interpolation variable it checks
   !> the signs the update's structure rests on: k_N > 0, k_T > 0 (open crack), Dbar_NN > 0 (the
   !> open/closed switch Dbar_NN s_N > 0), ufbar > 0, T^f < 0 (the friction step), S^c_N > 0 and
   !> T^c_T > 0 (the closed crack's stresses). Rows that pass their own checks can still have an
   !> interpolant that breaks these where the rows are far apart (tables/paper-small-d.dat, short
   !> cracks only and then the a = b row, has Dbar_NN < 0 from D = 0.30). Dbar_TT is not among
   !> them: it only sets the slip an open crack's faces keep for when they close again, and the
   !> paper-resolution table's spline undershoots it (Dbar_TT >= -4.7e-3 for D < 0.014, between
   !> its rows at a = 0 and 1 mm; tables/README.md). On failure: STATUS_TABLE_INTERPOLANT, the
   !> first D, the coefficient's name and its value.
   pure subroutine check_interpolant(variable, knots, coef_table, status, bad_d, bad_name, bad_value)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      ! (contiguous, as table_coefficients takes them: no copy at each of its calls)
      real(dp), contiguous, intent(in) :: knots(:)           !! knots, ascending
      real(dp), contiguous, intent(in) :: coef_table(:, 0:, :)   !! cubic coefficients
      integer, intent(out) :: status
      real(dp), intent(out) :: bad_d                         !! where (-), when status /= STATUS_OK
      character(len=*), intent(out) :: bad_name              !! which coefficient
      real(dp), intent(out) :: bad_value                     !! its value there
      type(coefficient_set_type) :: c, dc
      real(dp) :: x, d, values(7)
      integer :: i, j, k
      character(len=8), parameter :: NAMES(7) = [character(len=8) :: 'k_N', 'k_T', 'Dbar_NN', &
         'ufbar', '-T^f', 'S^c_N', 'T^c_T']
      status = STATUS_OK
      c = NO_COEFFICIENTS    ! (set by every successful table_coefficients: for the compiler's flow analysis)
      bad_d = 0.0_dp
      bad_name = ''
      bad_value = 0.0_dp
      do i = 1, size(knots) - 1
         do j = 1, INTERPOLANT_SAMPLES
            x = knots(i) + (knots(i + 1) - knots(i))*real(j, dp)/real(INTERPOLANT_SAMPLES + 1, dp)
            ! D from the interpolation variable: x = D, or x = w = 1/(1 - ln(1 - D))
            if (variable == VARIABLE_DAMAGE) then
               d = x
            else
               d = 1.0_dp - exp(1.0_dp - 1.0_dp/x)
            end if
            if (.not. (d > D_MIN_CRACK .and. d < 1.0_dp)) cycle
            call table_coefficients(variable, knots, coef_table, d, c, dc, status)
            if (status /= STATUS_OK) return
            values = [c%k_n, c%k_t, c%dbar_n, c%ufbar, -c%tf, c%sc_n, c%tc_t]
            do k = 1, size(values)
               if (.not. (values(k) > 0.0_dp)) then
                  status = STATUS_TABLE_INTERPOLANT
                  bad_d = d
                  bad_name = NAMES(k)
                  bad_value = values(k)
                  return
               end if
            end do
         end do
      end do
   end subroutine check_interpolant

   !> The built-in table's interpolation data (for tests of `check_interpolant`).
   pure subroutine default_table_data(variable, knots, coef_table)
      integer, intent(out) :: variable
      real(dp), allocatable, intent(out) :: knots(:), coef_table(:, :, :)
      variable = DEFAULT_TABLE_VARIABLE
      knots = DEFAULT_TABLE_KNOTS
      coef_table = DEFAULT_TABLE_COEF
   end subroutine default_table_data

   !> Read, check and interpolate a custom table; call once at start-up, before any update
   !> and from one thread (UEXTERNALDB at LOP = 0 does). A second call replaces the table and
   !> is only safe while no update runs.
   subroutine load_custom_table(path, status, message)
      character(len=*), intent(in) :: path                   !! table file (tables/README.md format)
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      type(rve_table_type) :: table
      type(spline_type) :: spline
      real(dp), allocatable :: x(:), y(:, :)
      integer :: n
      real(dp) :: bad_d, bad_value
      real(dp), allocatable :: knots(:), coef(:, :, :)
      integer, allocatable :: guide(:)
      real(dp) :: guide_scale
      integer :: guide_steps
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
      ! the interpolant between the rows must be a law too (signs the update relies on)
      call check_interpolant(table%variable, knots, coef, status, bad_d, bad_name, bad_value)
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
      call guide_build(knots, guide, guide_scale, guide_steps)
      call state_columns(table%variable, knots, coef, custom_state_columns, custom_state_status)
      call move_alloc(knots, custom_knots)
      call move_alloc(coef, custom_coef)
      call move_alloc(guide, custom_guide)
      custom_guide_scale = guide_scale
      custom_guide_steps = guide_steps
      custom_variable = table%variable
      ! the file as it was tried (a relative path resolved against the current directory)
      custom_source = table%source
   end subroutine load_custom_table

   !> Whether a custom table has been loaded (the micromechanical model with PROPS(8) = 1 needs one).
   pure logical function custom_table_loaded()
      custom_table_loaded = allocated(custom_coef)
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
