!> The table grid: an RVE table's interpolant (the cubic spline of interphase_rve_table's columns in
!> the interpolation variable) resampled onto cells indexed by the bits of the damage D, so that a
!> lookup needs neither the variable's logarithm and division nor a search among the knots
!> (docs/theory.md, 'The table grid'; docs/performance.md, issue 18).
!>
!> **Cells.** Below D = 1/2 the cells lie in the binades of D, [2^-j, 2^-j+1) for j = 2 ... 100
!> (D_MIN_CRACK = 1e-30 lies in the last), above it in the binades of y = 1 - D, which is exact
!> there, for j = 2 ... 53 (y = 2^-53 is the largest D < 1). A binade holds M = 2^m equal cells,
!> the cell of a number given by its leading m mantissa bits. Three cells of their own: D below
!> 2^-100 (D = 0: the intact state), D = 1/2 and D = 1 (the broken state).
!>
!> **Cubics.** On each cell every column is the cubic Hermite interpolant of the spline: the
!> spline's value and first derivative in D at both ends of the cell. So the grid is the spline at
!> every cell end, continuous with a continuous first derivative on (0, 1) (C1; the spline is C2;
!> but for a round-off step at D = 2^-19, where the short cracks' cells below meet the others),
!> and between the ends it differs from the spline by O(h^4) in value and O(h^3) in slope. Each
!> cubic is written in s = D - D_0, D_0 the cell's end nearest to the binade's origin (D_cell for
!> D < 1/2, 1 - y_cell above), so that s is exact. The cells of their own hold the spline's
!> Taylor terms at D = 0, at D = 1/2 (where only s = 0 is used) and the value at D = 1 with zero
!> derivatives (the log-ligament variable's convention there: dw/dD is infinite at D = 1; a table
!> in D gets them too, which no caller reads).
!>
!> **Short cracks.** Below D = 2^-19 (1.9e-6) each binade of D is one cell holding the spline's
!> Taylor terms at D = 0 (value, slope, curvature): the spline takes its variable w from 1 - D,
!> which keeps about 1e-16/D of D's digits, so that its values there are those of D = 0 with
!> round-off added, and columns that vanish with D (K^c, Dbar) come out 0 or of either sign below
!> D ~ 1e-16. The Taylor terms give them their slope there; the third-order term they leave out is
!> below 1e-17 of the columns' scale. (The spline's slope and curvature at D = 0 are exact: w = 1
!> there.)
!>
!> **How many cells.** For each binade `grid_build` takes the smallest M = 1, 2, 4, ..., 256 whose
!> cubics meet the spline at 15 points inside every cell within 0.9 GRID_VALUE_TOL of the column's
!> largest value and, in the first derivative, within 0.9 GRID_SLOPE_TOL relative (of the larger of
!> |dX/dD| and a floor: GRID_SLOPE_SHARE (1e-2) of the binade's largest |dX/dD| at 65 equally
!> spaced points, and
!> GRID_SLOPE_FLOOR X_max / v, v
!> the binade's lower end: the slope of a column that is constant, or nearly so, there is not
!> asked to match the spline's round-off). Where no M meets both (the spline's round-off at the smallest D,
!> where it takes w from 1 - D), the M with the smallest excess is taken. In the binades of y,
!> M is at most 2^(53 - j): there a finer cell would hold no binary64 D.
!>
!> Set-up code (`grid_build` runs once, when a table is loaded or when the built-in one is
!> generated at build time); the evaluation is the hot path's (interphase_grid_cell.inc and the
!> Horner loops of interphase_micro_coefficients).
module interphase_table_grid
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_finite, only: HIGH_HALF, LOW_HALF, LOW_HALF_MASK
   use interphase_status, only: STATUS_OK, STATUS_SPLINE_OUT_OF_RANGE
   use interphase_spline, only: cubic_locate, cubic_eval
   use interphase_rve_table, only: crack_variable, N_COEFFICIENTS, VARIABLE_DAMAGE
   implicit none
   private
   public :: grid_build, grid_columns, grid_cell_count, grid_sample_damages, grid_state_columns, GRID_INDEX_SIZE, &
      GRID_E_D_FIRST, GRID_E_Y_FIRST, &
      GRID_Y_OFFSET, GRID_MANTISSA_MASK, GRID_VALUE_TOL, GRID_SLOPE_TOL, GRID_SLOPE_FLOOR, GRID_SLOPE_SHARE, &
      GRID_MAX_CELL_BITS

   !> Biased binary64 exponents: D with an exponent up to GRID_E_D_FIRST (D < 2^-100, D = 0) takes
   !> the first cell; D < 1/2 has an exponent up to 1021. y = 1 - D with an exponent up to
   !> GRID_E_Y_FIRST is y = 0 (D = 1); y <= 1/2 has an exponent up to 1022.
   integer, parameter :: GRID_E_D_FIRST = 922, GRID_E_Y_FIRST = 969
   !> Entries of grid_index: 100 for D < 1/2 (the first for D < 2^-100), then 54 for y (the first
   !> for y = 0).
   integer, parameter :: GRID_Y_OFFSET = 1021 - GRID_E_D_FIRST + 1
   integer, parameter :: GRID_INDEX_SIZE = GRID_Y_OFFSET + 1022 - GRID_E_Y_FIRST + 1
   !> The mantissa bits of a binary64 number.
   integer(int64), parameter :: GRID_MANTISSA_MASK = int(z'000FFFFFFFFFFFFF', int64)
   !> At most 2^GRID_MAX_CELL_BITS cells a binade.
   integer, parameter :: GRID_MAX_CELL_BITS = 8
   !> The binades of D from [2^-GRID_TAYLOR_BINADE, 2^-GRID_TAYLOR_BINADE+1) down take the spline's
   !> Taylor terms at D = 0, one cell each (module header).
   integer, parameter :: GRID_TAYLOR_BINADE = 20
   !> The fit's tolerances (module header): the value, against the column's largest value, and the
   !> slope, relative.
   real(dp), parameter :: GRID_VALUE_TOL = 1.0e-6_dp, GRID_SLOPE_TOL = 2.0e-5_dp
   !> The slope below which a column counts as constant in a binade [v, 2v): GRID_SLOPE_FLOOR of
   !> the column's largest value over v (a change of 1e-8 of the scale over the binade). The
   !> tables' constant columns (T^c_T, S^c_N) have slopes of round-off, which a Hermite cubic on
   !> cells of width h turns into slope errors of round-off / h.
   real(dp), parameter :: GRID_SLOPE_FLOOR = 1.0e-8_dp
   !> ... and the slope below which the slope's relative error is not asked: GRID_SLOPE_SHARE of
   !> the column's largest slope in the binade (where a column's slope passes through 0, its
   !> relative error has no meaning, and the column's share of G there is small).
   real(dp), parameter :: GRID_SLOPE_SHARE = 1.0e-2_dp
   !> Points inside a cell at which the fit is measured: (1 ... 15)/16 of the cell; there the fit
   !> must be within FIT_MARGIN of the tolerances, so that it stays within them between the points
   !> (a smooth error curve's largest value lies within 1 % of its largest sample).
   integer, parameter :: FIT_SAMPLES = 15
   real(dp), parameter :: FIT_MARGIN = 0.9_dp
   !> Most cells a grid can have.
   integer, parameter :: MAX_CELLS = GRID_INDEX_SIZE*2**GRID_MAX_CELL_BITS

contains

   include 'interphase_binary64_bits.inc'
   include 'interphase_binary64_value.inc'

   !> The grid of a table's spline (module header): grid(column, power, cell), the cubics'
   !> coefficients of s^0 ... s^3, and grid_index, each binade's first cell and mantissa shift
   !> packed as first*64 + shift. status: STATUS_OK, or a failure of the spline's evaluation,
   !> passed on (not expected for a spline that spline_build accepted: its evaluation here is
   !> clamped to the knots).
   subroutine grid_build(variable, knots, values, coef, grid, grid_index, domain, status)
      integer, intent(in) :: variable                        !! VARIABLE_* of the knots
      real(dp), intent(in) :: knots(:)                       !! the spline's knots, ascending
      !> the interpolation data at the knots (interphase_rve_table's interpolation_data: knot, column)
      real(dp), intent(in) :: values(:, :)
      real(dp), intent(in) :: coef(:, 0:, :)                 !! its cubics (column, power, interval)
      real(dp), allocatable, intent(out) :: grid(:, :, :)    !! (N_COEFFICIENTS, 0:3, cells)
      integer, intent(out) :: grid_index(GRID_INDEX_SIZE)
      !> the damages [D_first, D_last] of the table's first and last rows, where its spline ends:
      !> [0, 1] but for a table whose end rows the loader takes within 1e-12 of a = 0 and a = b
      real(dp), intent(out) :: domain(2)
      integer, intent(out) :: status
      real(dp), allocatable :: work(:, :, :)
      real(dp) :: scale(N_COEFFICIENTS), f(N_COEFFICIENTS), g(N_COEFFICIENTS), h2(N_COEFFICIENTS)
      real(dp) :: best_excess, excess
      integer :: idx, ncell, m, m_max, best_m, j
      logical :: d_side, special

      allocate (work(N_COEFFICIENTS, 0:3, MAX_CELLS))
      grid_index = 0
      ! the spline's ends as damages (x = D, or x = w = 1/(1 - ln(1 - D)): w = 1 at D = 0, w = 0
      ! at D = 1, and D = 1 - exp(1 - 1/w) between)
      if (variable == VARIABLE_DAMAGE) then
         domain = [knots(1), knots(size(knots))]
      else
         ! (w decreases with D: the first D whose w is at most the last knot, and the last D whose
         ! w is at least the first, as the spline's own lookup decided: domain_end)
         domain(1) = 0.0_dp
         if (knots(size(knots)) < 1.0_dp) domain(1) = domain_end(1.0_dp - exp(1.0_dp - 1.0_dp/knots(size(knots))), &
            knots(size(knots)), -1.0_dp)
         domain(2) = 1.0_dp
         if (knots(1) > 0.0_dp) domain(2) = domain_end(1.0_dp - exp(1.0_dp - 1.0_dp/knots(1)), knots(1), 1.0_dp)
      end if
      ! the columns' scales: their largest magnitudes at the rows and at D = 0 and 1
      do j = 1, N_COEFFICIENTS
         scale(j) = maxval(abs(coef(j, 0, :)))
      end do
      call spline_at(0.0_dp, f, g, h2, status)
      if (status /= STATUS_OK) return
      scale = max(scale, abs(f))
      call spline_at(1.0_dp, f, g, h2, status)
      if (status /= STATUS_OK) return
      scale = max(scale, abs(f), tiny(1.0_dp))
      ncell = 0
      do idx = 1, GRID_INDEX_SIZE
         d_side = idx <= GRID_Y_OFFSET
         special = idx == 1 .or. idx == GRID_Y_OFFSET + 1 .or. idx == GRID_INDEX_SIZE
         j = 0
         if (.not. special) j = binade_of(idx)
         if (special .or. (d_side .and. j >= GRID_TAYLOR_BINADE)) then
            ! one cell for the whole entry: the cells of their own, D < 2^-100 (D = 0), y = 0
            ! (D = 1) and y in [1/2, 1) (D = 1/2); or a short crack's binade, the spline's Taylor
            ! terms at D = 0
            if (special) then
               call special_cell(idx, ncell + 1, status)
            else
               call taylor_cell(j, ncell + 1, status)
            end if
            if (status /= STATUS_OK) return
            grid_index(idx) = (ncell + 1)*64 + 52
            ncell = ncell + 1
            cycle
         end if
         m_max = GRID_MAX_CELL_BITS
         if (.not. d_side) m_max = min(m_max, 53 - j)
         best_m = 0
         best_excess = huge(1.0_dp)
         do m = 0, m_max
            call fit_binade(idx, j, m, ncell + 1, status)
            if (status /= STATUS_OK) return
            grid_index(idx) = (ncell + 1)*64 + 52 - m
            call binade_excess(idx, j, m, ncell + 1, excess, status)
            if (status /= STATUS_OK) return
            if (excess < best_excess) then
               best_excess = excess
               best_m = m
            end if
            if (excess <= FIT_MARGIN) exit
         end do
         if (best_m /= m) then
            ! none met both tolerances (the loop ran to its end): the least excess
            call fit_binade(idx, j, best_m, ncell + 1, status)
            if (status /= STATUS_OK) return
         end if
         grid_index(idx) = (ncell + 1)*64 + 52 - best_m
         ncell = ncell + 2**best_m
      end do
      grid = work(:, :, 1:ncell)

   contains


      !> Where the spline's log-ligament variable w(D) (crack_variable) passes the knot w_end, as
      !> the spline's lookup decides it (w decreases with D): with toward = -1 the smallest D with
      !> w(D) <= w_end, with +1 the largest D with w(D) >= w_end. By bisection between 0 or 1 and
      !> a D on the knot's side near the estimate d_guess = 1 - exp(1 - 1/w_end), to adjacent
      !> binary64 numbers (many D share one w near D = 0, where 1 - D rounds).
      pure real(dp) function domain_end(d_guess, w_end, toward) result(d_end)
         real(dp), intent(in) :: d_guess, w_end, toward
         real(dp) :: d_in, d_out, d_mid, gap
         integer :: k
         ! d_out: the far end of [0, 1] (outside the knots); d_in: a D inside, near the estimate
         d_out = merge(0.0_dp, 1.0_dp, toward < 0.0_dp)
         gap = 1.0e-12_dp
         d_in = min(max(d_guess - toward*gap, 0.0_dp), 1.0_dp)
         do k = 1, 40
            if (inside_of(d_in, w_end, toward)) exit
            gap = 2.0_dp*gap
            d_in = min(max(d_guess - toward*gap, 0.0_dp), 1.0_dp)
         end do
         do k = 1, 200
            d_mid = d_in + 0.5_dp*(d_out - d_in)
            if (binary64_bits(d_mid) == binary64_bits(d_in) .or. binary64_bits(d_mid) == binary64_bits(d_out)) exit
            if (inside_of(d_mid, w_end, toward)) then
               d_in = d_mid
            else
               d_out = d_mid
            end if
         end do
         d_end = d_in
      end function domain_end

      !> Whether D's w lies on the knots' side of w_end (domain_end's).
      pure logical function inside_of(d, w_end, toward) result(yes)
         real(dp), intent(in) :: d, w_end, toward
         real(dp) :: x, dx_dd, d2x_dd2
         call crack_variable(variable, d, x, dx_dd, d2x_dd2)
         if (toward < 0.0_dp) then
            yes = x <= w_end
         else
            yes = x >= w_end
         end if
      end function inside_of

      !> The spline's columns, dX/dD and d2X/dD2 at D (interphase_rve_table's crack variable); at a
      !> knot the columns are the data there (the spline's cubic gives them only to its round-off:
      !> Dbar_NN = -2.8e-17 for the 0 of the a = 0 row of tables/paper-resolution.dat). A D beyond
      !> the spline's ends (a table whose end rows lie within 1e-12 of D = 0 and 1, where a lookup
      !> fails: `domain`) takes the end interval's cubic.
      pure subroutine spline_at(d, v, dv, d2v, st)
         real(dp), intent(in) :: d
         real(dp), intent(out) :: v(N_COEFFICIENTS), dv(N_COEFFICIENTS), d2v(N_COEFFICIENTS)
         integer, intent(out) :: st
         real(dp) :: x, dx_dd, d2x_dd2, dv_x(N_COEFFICIENTS), d2v_x(N_COEFFICIENTS)
         integer :: interval
         call crack_variable(variable, d, x, dx_dd, d2x_dd2)
         call cubic_locate(knots, min(max(x, knots(1)), knots(size(knots))), interval, st)
         if (st /= STATUS_OK) then
            v = 0.0_dp
            dv = 0.0_dp
            d2v = 0.0_dp
            return
         end if
         call cubic_eval(knots, coef, interval, x, v, dv_x, d2v_x)
         if (binary64_bits(x) == binary64_bits(knots(interval))) then
            v = values(interval, :)
         else if (binary64_bits(x) == binary64_bits(knots(interval + 1))) then
            v = values(interval + 1, :)
         end if
         dv = dv_x*dx_dd
         d2v = d2v_x*dx_dd*dx_dd + dv_x*d2x_dd2
      end subroutine spline_at

      !> A cell of its own: the spline's Taylor terms at D = 0 and D = 1/2 (s = D - D_0), the value
      !> alone at D = 1.
      subroutine special_cell(idx, cell, st)
         integer, intent(in) :: idx, cell
         integer, intent(out) :: st
         real(dp) :: d0, v(N_COEFFICIENTS), dv(N_COEFFICIENTS), d2v(N_COEFFICIENTS)
         if (idx == 1) then
            d0 = 0.0_dp
         else if (idx == GRID_Y_OFFSET + 1) then
            d0 = 1.0_dp
         else
            d0 = 0.5_dp
         end if
         call spline_at(d0, v, dv, d2v, st)
         if (st /= STATUS_OK) return
         work(:, 0, cell) = v
         if (idx == GRID_Y_OFFSET + 1) then
            work(:, 1, cell) = 0.0_dp
            work(:, 2, cell) = 0.0_dp
         else
            work(:, 1, cell) = dv
            work(:, 2, cell) = 0.5_dp*d2v
         end if
         work(:, 3, cell) = 0.0_dp
      end subroutine special_cell

      !> The one cell of a binade [2^-j, 2^-j+1) of D with j >= GRID_TAYLOR_BINADE: the spline's
      !> value, slope and curvature at D = 0 as the quadratic in s = D - 2^-j.
      subroutine taylor_cell(jj, cell, st)
         integer, intent(in) :: jj, cell
         integer, intent(out) :: st
         real(dp) :: lo, v(N_COEFFICIENTS), dv(N_COEFFICIENTS), d2v(N_COEFFICIENTS)
         call spline_at(0.0_dp, v, dv, d2v, st)
         if (st /= STATUS_OK) return
         lo = 2.0_dp**(-jj)
         work(:, 0, cell) = v + lo*(dv + lo*0.5_dp*d2v)
         work(:, 1, cell) = dv + lo*d2v
         work(:, 2, cell) = 0.5_dp*d2v
         work(:, 3, cell) = 0.0_dp
      end subroutine taylor_cell

      !> The Hermite cubics of binade j with 2^m cells, into work(:, :, first ...).
      subroutine fit_binade(idx, jj, m, first, st)
         integer, intent(in) :: idx, jj, m, first
         integer, intent(out) :: st
         real(dp) :: lo, h, f0(N_COEFFICIENTS), g0(N_COEFFICIENTS), f1(N_COEFFICIENTS), g1(N_COEFFICIENTS)
         real(dp) :: unused(N_COEFFICIENTS), slope(N_COEFFICIENTS)
         integer :: k
         h = 2.0_dp**(-jj - m)
         st = STATUS_OK
         do k = 0, 2**m - 1
            lo = 2.0_dp**(-jj) + real(k, dp)*h
            if (idx <= GRID_Y_OFFSET) then
               ! s = D - lo on [0, h]
               call spline_at(lo, f0, g0, unused, st)
               if (st /= STATUS_OK) return
               call spline_at(lo + h, f1, g1, unused, st)
               if (st /= STATUS_OK) return
               slope = (f1 - f0)/h
               work(:, 0, first + k) = f0
               work(:, 1, first + k) = g0
               work(:, 2, first + k) = (3.0_dp*slope - 2.0_dp*g0 - g1)/h
               work(:, 3, first + k) = (g0 + g1 - 2.0_dp*slope)/(h*h)
            else
               ! y in [lo, lo + h): s = D - (1 - lo) on [-h, 0]; with r = -s on [0, h] the
               ! Hermite cubic q(r) from D = 1 - lo (r = 0) to D = 1 - lo - h (r = h), then
               ! p(s) = q(-s): the odd powers change sign
               call spline_at(1.0_dp - lo, f0, g0, unused, st)
               if (st /= STATUS_OK) return
               call spline_at(1.0_dp - (lo + h), f1, g1, unused, st)
               if (st /= STATUS_OK) return
               g0 = -g0
               g1 = -g1
               slope = (f1 - f0)/h
               work(:, 0, first + k) = f0
               work(:, 1, first + k) = -g0
               work(:, 2, first + k) = (3.0_dp*slope - 2.0_dp*g0 - g1)/h
               work(:, 3, first + k) = -(g0 + g1 - 2.0_dp*slope)/(h*h)
            end if
         end do
      end subroutine fit_binade

      !> How far binade j's fit with 2^m cells (already in work, with its grid_index entry set) is
      !> from the spline at FIT_SAMPLES points inside each cell: the largest of (value error /
      !> GRID_VALUE_TOL) and (slope error / GRID_SLOPE_TOL), relative as in the module header.
      pure subroutine binade_excess(idx, jj, m, first, worst, st)
         integer, intent(in) :: idx, jj, m, first
         real(dp), intent(out) :: worst
         integer, intent(out) :: st
         real(dp) :: lo, h, d, y, v(N_COEFFICIENTS), dv(N_COEFFICIENTS), gv(N_COEFFICIENTS), gdv(N_COEFFICIENTS)
         real(dp) :: unused(N_COEFFICIENTS), gmax(N_COEFFICIENTS), slope_floor(N_COEFFICIENTS)
         integer :: k, q, cells, fine, local_index(GRID_INDEX_SIZE)
         worst = 0.0_dp
         ! grid_index with this binade's entry pointing at the first of its cells, passed alone
         local_index = grid_index
         local_index(idx) = 1*64 + 52 - m
         st = STATUS_OK
         cells = 2**m
         ! the binade's largest slopes, at 65 points from its lower to its upper end (fewer deep in
         ! the binades of y, where no more binary64 D lie in it)
         fine = 64
         if (idx > GRID_Y_OFFSET .and. 53 - jj < 6) fine = 2**(53 - jj)
         gmax = 0.0_dp
         do k = 0, fine
            lo = 2.0_dp**(-jj)*(1.0_dp + real(k, dp)/real(fine, dp))
            d = lo
            if (idx > GRID_Y_OFFSET) d = 1.0_dp - lo
            call spline_at(d, v, dv, unused, st)
            if (st /= STATUS_OK) return
            gmax = max(gmax, abs(dv))
         end do
         slope_floor = max(GRID_SLOPE_SHARE*gmax, GRID_SLOPE_FLOOR*scale/2.0_dp**(-jj))
         h = 2.0_dp**(-jj - m)
         do k = 0, cells - 1
            lo = 2.0_dp**(-jj) + real(k, dp)*h
            do q = 1, FIT_SAMPLES
               if (idx <= GRID_Y_OFFSET) then
                  d = lo + h*real(q, dp)/real(FIT_SAMPLES + 1, dp)
               else
                  y = lo + h*real(q, dp)/real(FIT_SAMPLES + 1, dp)
                  d = 1.0_dp - y
                  ! (deep in the binades of y a point inside the cell may have no binary64 D)
                  if (binary64_bits(1.0_dp - d) /= binary64_bits(y)) cycle
               end if
               call spline_at(d, v, dv, unused, st)
               if (st /= STATUS_OK) return
               call grid_columns(work(:, :, first:first + cells - 1), local_index, d, gv, gdv)
               worst = max(worst, maxval(abs(gv - v)/scale)/GRID_VALUE_TOL, &
                  maxval(abs(gdv - dv)/max(abs(dv), slope_floor))/GRID_SLOPE_TOL)
            end do
         end do
      end subroutine binade_excess

   end subroutine grid_build

   !> The binade j of a regular entry idx of grid_index: [2^-j, 2^-j+1) of D (idx <= GRID_Y_OFFSET)
   !> or of y = 1 - D.
   pure integer function binade_of(idx) result(j)
      integer, intent(in) :: idx
      if (idx <= GRID_Y_OFFSET) then
         j = 1023 - (GRID_E_D_FIRST + idx - 1)
      else
         j = 1023 - (GRID_E_Y_FIRST + idx - 1 - GRID_Y_OFFSET)
      end if
   end function binade_of

   !> Damages at which to look at a grid (its checks, the tests), in ascending order: the ends of
   !> every cell and per_cell points equally spaced inside each, from D = 2^-100 to the largest
   !> D < 1 (a point of a cell of y that no binary64 D has is left out; cell ends repeat).
   pure subroutine grid_sample_damages(grid_index, per_cell, damages)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)
      integer, intent(in) :: per_cell                        !! points inside each cell (>= 0)
      real(dp), allocatable, intent(out) :: damages(:)
      real(dp), allocatable :: list(:)
      real(dp) :: h, y, d
      integer :: idx, j, k, q, cells, n
      allocate (list((grid_cell_count(grid_index) + 1)*(per_cell + 2) + 1))
      n = 0
      do idx = 2, GRID_Y_OFFSET
         j = binade_of(idx)
         cells = 2**(52 - iand(grid_index(idx), 63))
         h = 2.0_dp**(-j)/real(cells, dp)
         do k = 0, cells - 1
            do q = 0, per_cell + 1
               n = n + 1
               list(n) = 2.0_dp**(-j) + (real(k, dp) + real(q, dp)/real(per_cell + 1, dp))*h
            end do
         end do
      end do
      n = n + 1
      list(n) = 0.5_dp
      do idx = GRID_INDEX_SIZE - 1, GRID_Y_OFFSET + 2, -1
         j = binade_of(idx)
         cells = 2**(52 - iand(grid_index(idx), 63))
         h = 2.0_dp**(-j)/real(cells, dp)
         do k = cells - 1, 0, -1
            do q = per_cell + 1, 0, -1
               y = 2.0_dp**(-j) + (real(k, dp) + real(q, dp)/real(per_cell + 1, dp))*h
               d = 1.0_dp - y
               if (binary64_bits(1.0_dp - d) /= binary64_bits(y)) cycle
               n = n + 1
               list(n) = d
            end do
         end do
      end do
      allocate (damages(n))
      damages(:) = list(1:n)
   end subroutine grid_sample_damages

   !> The grid's columns and their first derivatives dX/dD at D (finite in [0, 1]): the cubics of
   !> D's cell (interphase_grid_cell.inc) in Horner form, the same operations as the providers'.
   pure subroutine grid_columns(grid, grid_index, d, values, derivatives)
      real(dp), intent(in) :: grid(:, 0:, :)                 !! (N_COEFFICIENTS, 0:3, cells)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)
      real(dp), intent(in) :: d                              !! damage D (-)
      real(dp), intent(out) :: values(N_COEFFICIENTS), derivatives(N_COEFFICIENTS)
      logical :: d_side
      real(dp) :: v, vc, s
      integer(int64) :: bits
      integer :: e, idx, packed, sh, cell, j
      include 'interphase_grid_cell.inc'
      do j = 1, N_COEFFICIENTS
         values(j) = grid(j, 0, cell) + s*(grid(j, 1, cell) + s*(grid(j, 2, cell) + s*grid(j, 3, cell)))
         derivatives(j) = grid(j, 1, cell) + s*(2.0_dp*grid(j, 2, cell) + 3.0_dp*s*grid(j, 3, cell))
      end do
   end subroutine grid_columns

   !> The columns at the intact (D = +0) and the broken state (D = 1): the values of the grid's
   !> cells of their own there (the table's rows at a = 0 and a = b), and the status of a lookup
   !> there: STATUS_OK, or STATUS_SPLINE_OUT_OF_RANGE outside the table's domain (a table whose
   !> end rows lie within 1e-12 of them). For the updates' shortcut at these damages.
   pure subroutine grid_state_columns(grid, grid_index, domain, columns, status)
      real(dp), intent(in) :: grid(:, 0:, :)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)
      real(dp), intent(in) :: domain(2)
      real(dp), intent(out) :: columns(N_COEFFICIENTS, 2)    !! at D = +0 and at D = 1
      integer, intent(out) :: status(2)
      columns(:, 1) = grid(:, 0, ishft(grid_index(1), -6))
      columns(:, 2) = grid(:, 0, ishft(grid_index(GRID_Y_OFFSET + 1), -6))
      status = STATUS_OK
      if (domain(1) > 0.0_dp) status(1) = STATUS_SPLINE_OUT_OF_RANGE
      if (domain(2) < 1.0_dp) status(2) = STATUS_SPLINE_OUT_OF_RANGE
   end subroutine grid_state_columns

   !> The number of cells a grid_index addresses (the size of its grid's last dimension).
   pure integer function grid_cell_count(grid_index) result(n)
      integer, intent(in) :: grid_index(GRID_INDEX_SIZE)
      integer :: k
      n = 0
      do k = 1, GRID_INDEX_SIZE
         n = max(n, ishft(grid_index(k), -6) - 1 + 2**(52 - iand(grid_index(k), 63)))
      end do
   end function grid_cell_count

end module interphase_table_grid
