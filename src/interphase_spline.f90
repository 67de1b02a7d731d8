!> Piecewise-cubic interpolation of m tabulated functions that share one set of knots, with
!> first derivatives: the RVE coefficient functions C(a) of the micromechanical model.
!>
!> Build once (`spline_build`, not pure, no I/O, returns a status), then evaluate from pure code:
!> `spline_locate` finds the knot interval (hint, its neighbours, then binary search) and
!> `spline_eval` evaluates all m columns and their derivatives in it; `spline_value` does both.
!> An argument outside [x(1), x(n)] is a status, never an extrapolation; the end knots are
!> inside. The caller owns the hint (its previous interval): no module state, re-entrant.
!>
!> Every method computes the slopes s_i = S'(x_i) and stores, per interval i and column j, the
!> Hermite cubic in the local variable t = x - x_i (0 <= t <= h_i = x_(i+1) - x_i):
!>   S(x) = c0 + t (c1 + t (c2 + t c3)),  c0 = y_i, c1 = s_i,
!>   c2 = (3 d_i - 2 s_i - s_(i+1))/h_i,  c3 = (s_i + s_(i+1) - 2 d_i)/h_i**2,
!> with the secant slope d_i = (y_(i+1) - y_i)/h_i.
!>
!> Methods:
!> - SPLINE_NATURAL, SPLINE_NOT_A_KNOT (C2 cubic splines): slope (first-derivative) formulation,
!>   continuity of S'' at the interior knots,
!>     h_i s_(i-1) + 2 (h_(i-1) + h_i) s_i + h_(i-1) s_(i+1) = 3 (h_i d_(i-1) + h_(i-1) d_i),
!>   with the end rows  natural: 2 s_1 + s_2 = 3 d_1,  s_(n-1) + 2 s_n = 3 d_(n-1)  (S'' = 0);
!>   not-a-knot (S''' continuous at x_2 and x_(n-1)): the jump condition couples s_1, s_2, s_3;
!>   eliminating s_3 with the row of x_2 leaves the two-term row (as in de Boor, and SciPy's
!>   CubicSpline)
!>     h_2 s_1 + (h_1 + h_2) s_2 = ((h_1 + 2 (h_1 + h_2)) h_2 d_1 + h_1**2 d_2)/(h_1 + h_2),
!>   and its mirror image at x_n, so the system stays tridiagonal. It is solved for all m
!>   columns at once by LAPACK `dgtsv` (partial pivoting: the not-a-knot end rows are not
!>   diagonally dominant).
!> - SPLINE_MONOTONE: Fritsch-Carlson (SIAM J. Numer. Anal. 17, 1980) monotone piecewise cubic
!>   Hermite interpolation, C1. Initial slopes: the three-point (parabola) derivative at interior
!>   knots, zero where the secant slopes change sign or one of them is zero; at the ends the
!>   one-sided three-point derivative, set to zero if its sign differs from d_1 (d_(n-1)) and
!>   limited to 3 d_1 when the data turns at x_2 (as PCHIP does). Then, interval by interval,
!>   d_i = 0 sets s_i = s_(i+1) = 0, and (alpha, beta) = (s_i, s_(i+1))/d_i is pulled back onto
!>   the circle alpha**2 + beta**2 <= 9. Limiting only shrinks slopes, so intervals already
!>   treated stay monotone: the interpolant is monotone on every interval where the data is.
!>
!> Storage: `coef(m, 0:3, n-1)`. Evaluating all m columns at one x reads one contiguous block of
!> 4m reals, and each power's coefficients are contiguous in j, so the column loop vectorises.
module interphase_spline
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_status, only: STATUS_OK, STATUS_SPLINE_TOO_FEW_POINTS, STATUS_SPLINE_BAD_SHAPE, &
      STATUS_SPLINE_BAD_METHOD, STATUS_SPLINE_NONFINITE_DATA, STATUS_SPLINE_BAD_KNOTS, &
      STATUS_SPLINE_SOLVER_FAILED, STATUS_SPLINE_NOT_BUILT, STATUS_SPLINE_OUT_OF_RANGE, &
      STATUS_SPLINE_NONFINITE_ARGUMENT
   implicit none
   private
   public :: spline_type, spline_build, spline_locate, spline_eval, spline_value
   public :: spline_points, spline_columns, spline_domain
   public :: cubic_locate, cubic_eval, spline_export

   !> C2 cubic spline, natural ends (S'' = 0 at x(1) and x(n)); needs n >= 2.
   integer, parameter, public :: SPLINE_NATURAL = 1
   !> C2 cubic spline, not-a-knot ends (S''' continuous at x(2) and x(n-1)); needs n >= 4.
   integer, parameter, public :: SPLINE_NOT_A_KNOT = 2
   !> C1 monotone piecewise cubic Hermite (Fritsch-Carlson); needs n >= 2.
   integer, parameter, public :: SPLINE_MONOTONE = 3



   !> m interpolated columns on n shared knots. Set by `spline_build` only (the components are
   !> private); an unbuilt or failed spline has n = 0 and every locate reports
   !> STATUS_SPLINE_NOT_BUILT.
   type :: spline_type
      private
      integer :: n = 0                          !! number of knots
      integer :: m = 0                          !! number of columns
      integer :: method = 0                     !! SPLINE_* used to build it
      real(dp), allocatable :: x(:)             !! knots x(n), strictly increasing
      real(dp), allocatable :: coef(:, :, :)    !! coef(j, k, i): t**k coefficient of column j on interval i
   end type spline_type

   interface
      !> LAPACK: solve a general tridiagonal system A X = B by Gaussian elimination with partial
      !> pivoting (dl, d, du and b are overwritten).
      subroutine dgtsv(n, nrhs, dl, d, du, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, nrhs, ldb
         real(dp), intent(inout) :: dl(*), d(*), du(*)
         real(dp), intent(inout) :: b(ldb, *)
         integer, intent(out) :: info
      end subroutine dgtsv
   end interface

contains

   !> Build the interpolant of the columns of y on the knots x. On failure `spline` is left
   !> unbuilt (n = 0) and `status` says why.
   subroutine spline_build(x, y, method, spline, status)
      real(dp), intent(in) :: x(:)                  !! knots, strictly increasing, finite
      real(dp), intent(in) :: y(:, :)               !! y(i, j): column j at knot i, finite
      integer, intent(in) :: method                 !! SPLINE_NATURAL, SPLINE_NOT_A_KNOT or SPLINE_MONOTONE
      type(spline_type), intent(out) :: spline      !! the interpolant
      integer, intent(out) :: status                !! STATUS_OK or a STATUS_SPLINE_* code

      real(dp), allocatable :: h(:), d(:, :), s(:, :)
      integer :: n, m, i

      n = size(x)
      m = size(y, 2)
      status = check_data(x, y, method)
      if (status /= STATUS_OK) return

      allocate (h(n - 1), d(n - 1, m), s(n, m))
      h = x(2:n) - x(1:n - 1)
      do i = 1, n - 1
         d(i, :) = (y(i + 1, :) - y(i, :))/h(i)
      end do

      select case (method)
      case (SPLINE_NATURAL, SPLINE_NOT_A_KNOT)
         call c2_slopes(method, h, d, s, status)
         if (status /= STATUS_OK) return
      case (SPLINE_MONOTONE)
         call monotone_slopes(h, d, s)
      end select

      allocate (spline%x(n), spline%coef(m, 0:3, n - 1))
      spline%x = x
      do i = 1, n - 1
         spline%coef(:, 0, i) = y(i, :)
         spline%coef(:, 1, i) = s(i, :)
         spline%coef(:, 2, i) = (3.0_dp*d(i, :) - 2.0_dp*s(i, :) - s(i + 1, :))/h(i)
         spline%coef(:, 3, i) = (s(i, :) + s(i + 1, :) - 2.0_dp*d(i, :))/h(i)**2
      end do
      if (.not. all(is_finite(spline%coef))) then
         ! finite data can still overflow (e.g. huge values on very close knots)
         deallocate (spline%x, spline%coef)
         status = STATUS_SPLINE_NONFINITE_DATA
         return
      end if
      spline%n = n
      spline%m = m
      spline%method = method
   end subroutine spline_build

   !> Validate the construction data; the first failed check wins.
   pure integer function check_data(x, y, method) result(status)
      real(dp), intent(in) :: x(:)
      real(dp), intent(in) :: y(:, :)
      integer, intent(in) :: method

      integer :: n

      n = size(x)
      if (method /= SPLINE_NATURAL .and. method /= SPLINE_NOT_A_KNOT .and. method /= SPLINE_MONOTONE) then
         status = STATUS_SPLINE_BAD_METHOD
      else if (size(y, 1) /= n .or. size(y, 2) < 1) then
         status = STATUS_SPLINE_BAD_SHAPE
      else if (n < 2 .or. (method == SPLINE_NOT_A_KNOT .and. n < 4)) then
         status = STATUS_SPLINE_TOO_FEW_POINTS
      else if (.not. (all(is_finite(x)) .and. all(is_finite(y)))) then
         status = STATUS_SPLINE_NONFINITE_DATA
      else if (any(x(2:n) <= x(1:n - 1))) then
         status = STATUS_SPLINE_BAD_KNOTS
      else
         status = STATUS_OK
      end if
   end function check_data

   !> Slopes of the C2 cubic spline (natural or not-a-knot ends) from the tridiagonal system of
   !> the module header, all columns at once.
   subroutine c2_slopes(method, h, d, s, status)
      integer, intent(in) :: method
      real(dp), intent(in) :: h(:)            !! interval lengths h(n-1)
      real(dp), intent(in) :: d(:, :)         !! secant slopes d(n-1, m)
      real(dp), intent(out) :: s(:, :)        !! knot slopes s(n, m)
      integer, intent(out) :: status

      real(dp), allocatable :: lower(:), diag(:), upper(:)
      real(dp) :: w
      integer :: n, i, info

      n = size(s, 1)
      allocate (lower(n - 1), diag(n), upper(n - 1))
      ! interior rows i = 2..n-1: lower(i-1) s(i-1) + diag(i) s(i) + upper(i) s(i+1)
      do i = 2, n - 1
         lower(i - 1) = h(i)
         diag(i) = 2.0_dp*(h(i - 1) + h(i))
         upper(i) = h(i - 1)
         s(i, :) = 3.0_dp*(h(i)*d(i - 1, :) + h(i - 1)*d(i, :))
      end do
      if (method == SPLINE_NATURAL) then
         diag(1) = 2.0_dp
         upper(1) = 1.0_dp
         s(1, :) = 3.0_dp*d(1, :)
         lower(n - 1) = 1.0_dp
         diag(n) = 2.0_dp
         s(n, :) = 3.0_dp*d(n - 1, :)
      else
         w = h(1) + h(2)
         diag(1) = h(2)
         upper(1) = w
         s(1, :) = ((h(1) + 2.0_dp*w)*h(2)*d(1, :) + h(1)**2*d(2, :))/w
         w = h(n - 2) + h(n - 1)
         lower(n - 1) = w
         diag(n) = h(n - 2)
         s(n, :) = (h(n - 1)**2*d(n - 2, :) + (h(n - 1) + 2.0_dp*w)*h(n - 2)*d(n - 1, :))/w
      end if
      call dgtsv(n, size(s, 2), lower, diag, upper, s, n, info)
      if (info /= 0) then
         status = STATUS_SPLINE_SOLVER_FAILED
      else
         status = STATUS_OK
      end if
   end subroutine c2_slopes

   !> Fritsch-Carlson monotone slopes (module header), column by column.
   pure subroutine monotone_slopes(h, d, s)
      real(dp), intent(in) :: h(:)            !! interval lengths h(n-1)
      real(dp), intent(in) :: d(:, :)         !! secant slopes d(n-1, m)
      real(dp), intent(out) :: s(:, :)        !! knot slopes s(n, m)

      real(dp) :: r
      integer :: n, i, j

      n = size(s, 1)
      do j = 1, size(s, 2)
         if (n == 2) then
            s(:, j) = d(1, j)
            cycle
         end if
         do i = 2, n - 1
            if (sign_of(d(i - 1, j))*sign_of(d(i, j)) > 0) then
               s(i, j) = (h(i)*d(i - 1, j) + h(i - 1)*d(i, j))/(h(i - 1) + h(i))
            else
               s(i, j) = 0.0_dp
            end if
         end do
         s(1, j) = end_slope(h(1), h(2), d(1, j), d(2, j))
         s(n, j) = end_slope(h(n - 1), h(n - 2), d(n - 1, j), d(n - 2, j))
         do i = 1, n - 1
            if (sign_of(d(i, j)) == 0) then
               s(i, j) = 0.0_dp
               s(i + 1, j) = 0.0_dp
            else
               r = hypot(s(i, j), s(i + 1, j))
               if (r > 3.0_dp*abs(d(i, j))) then
                  r = 3.0_dp*abs(d(i, j))/r
                  s(i, j) = r*s(i, j)
                  s(i + 1, j) = r*s(i + 1, j)
               end if
            end if
         end do
      end do
   end subroutine monotone_slopes

   !> One-sided three-point end slope at the end of interval 1 (h1, d1) next to interval 2
   !> (h2, d2), limited as in PCHIP so that it does not spoil monotonicity.
   pure real(dp) function end_slope(h1, h2, d1, d2) result(slope)
      real(dp), intent(in) :: h1, h2, d1, d2

      slope = ((2.0_dp*h1 + h2)*d1 - h1*d2)/(h1 + h2)
      if (sign_of(slope)*sign_of(d1) <= 0) then
         slope = 0.0_dp
      else if (sign_of(d1) /= sign_of(d2) .and. abs(slope) > 3.0_dp*abs(d1)) then
         slope = 3.0_dp*d1
      end if
   end function end_slope

   !> -1, 0 or 1 as v < 0, v = 0 (either sign of zero) or v > 0; v finite.
   elemental integer function sign_of(v)
      real(dp), intent(in) :: v
      if (v > 0.0_dp) then
         sign_of = 1
      else if (v < 0.0_dp) then
         sign_of = -1
      else
         sign_of = 0
      end if
   end function sign_of

   !> Interval i of x: x(i) <= x < x(i+1), or i = n-1 at x = x(n). A hint (the caller's previous
   !> interval) is checked first, then its neighbours, then a binary search runs. On failure
   !> `interval` = 0.
   pure subroutine spline_locate(spline, x, interval, status, hint)
      type(spline_type), intent(in) :: spline   !! a built spline
      real(dp), intent(in) :: x                 !! argument, x(1) <= x <= x(n)
      integer, intent(out) :: interval          !! 1 <= interval <= n-1
      integer, intent(out) :: status            !! STATUS_OK, STATUS_SPLINE_OUT_OF_RANGE,
                                                !! STATUS_SPLINE_NONFINITE_ARGUMENT or STATUS_SPLINE_NOT_BUILT
      integer, intent(in), optional :: hint     !! previous interval; ignored when not in 1..n-1

      if (spline%n < 2) then
         interval = 0
         status = STATUS_SPLINE_NOT_BUILT
         return
      end if
      call cubic_locate(spline%x, x, interval, status, hint)
   end subroutine spline_locate

   !> `spline_locate` on bare knots (for interpolants stored as parameter data, e.g. the
   !> compiled-in RVE table): the interval of x among knots(1:n), n >= 2, strictly increasing.
   pure subroutine cubic_locate(knots, x, interval, status, hint)
      real(dp), intent(in) :: knots(:)          !! knots, strictly increasing, size >= 2
      real(dp), intent(in) :: x                 !! argument, knots(1) <= x <= knots(n)
      integer, intent(out) :: interval          !! 1 <= interval <= n-1; 0 on failure
      integer, intent(out) :: status            !! STATUS_OK, STATUS_SPLINE_OUT_OF_RANGE or
                                                !! STATUS_SPLINE_NONFINITE_ARGUMENT
      integer, intent(in), optional :: hint     !! previous interval; ignored when not in 1..n-1

      integer :: n, lo, hi, mid

      interval = 0
      n = size(knots)
      if (.not. is_finite(x)) then
         status = STATUS_SPLINE_NONFINITE_ARGUMENT
         return
      end if
      if (x < knots(1) .or. x > knots(n)) then
         status = STATUS_SPLINE_OUT_OF_RANGE
         return
      end if
      status = STATUS_OK
      if (.not. (x < knots(n))) then     ! x = x(n)
         interval = n - 1
         return
      end if
      lo = 1
      hi = n
      if (present(hint)) then
         if (hint >= 1 .and. hint <= n - 1) then
            if (x >= knots(hint)) then
               if (x < knots(hint + 1)) then
                  interval = hint
                  return
               end if
               lo = hint + 1
               if (lo + 1 <= n) then
                  if (x < knots(lo + 1)) then
                     interval = lo
                     return
                  end if
               end if
            else
               hi = hint
               if (hint > 1) then
                  if (x >= knots(hint - 1)) then
                     interval = hint - 1
                     return
                  end if
               end if
            end if
         end if
      end if
      ! invariant: x(lo) <= x < x(hi); branch-free steps (conditional moves, no mispredictions)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         lo = merge(mid, lo, x >= knots(mid))
         hi = merge(hi, mid, x >= knots(mid))
      end do
      interval = lo
   end subroutine cubic_locate

   !> All m columns and their first derivatives at x in a located interval. `interval` must come
   !> from `spline_locate` with STATUS_OK for this x (not checked here: this is the hot path).
   pure subroutine spline_eval(spline, interval, x, values, derivatives)
      type(spline_type), intent(in) :: spline   !! a built spline
      integer, intent(in) :: interval           !! from spline_locate
      real(dp), intent(in) :: x                 !! argument
      real(dp), intent(out) :: values(:)        !! values(m): the columns at x
      real(dp), intent(out) :: derivatives(:)   !! derivatives(m): their d/dx at x
      call cubic_eval(spline%x, spline%coef, interval, x, values, derivatives)
   end subroutine spline_eval

   !> `spline_eval` on bare knots and coefficients coef(m, 0:3, n-1) (see the module header),
   !> optionally with the second derivatives.
   pure subroutine cubic_eval(knots, coef, interval, x, values, derivatives, second_derivatives)
      real(dp), intent(in) :: knots(:)          !! knots(n)
      real(dp), intent(in) :: coef(:, 0:, :)    !! coef(j, k, i): t**k coefficient of column j on interval i
      integer, intent(in) :: interval           !! from cubic_locate
      real(dp), intent(in) :: x                 !! argument
      real(dp), intent(out) :: values(:)        !! values(m)
      real(dp), intent(out) :: derivatives(:)   !! derivatives(m)
      real(dp), intent(out), optional :: second_derivatives(:)   !! second derivatives(m)

      real(dp) :: t
      integer :: j

      t = x - knots(interval)
      if (present(second_derivatives)) then
         do j = 1, size(coef, 1)
            values(j) = coef(j, 0, interval) + t*(coef(j, 1, interval) &
               + t*(coef(j, 2, interval) + t*coef(j, 3, interval)))
            derivatives(j) = coef(j, 1, interval) + t*(2.0_dp*coef(j, 2, interval) &
               + 3.0_dp*t*coef(j, 3, interval))
            second_derivatives(j) = 2.0_dp*coef(j, 2, interval) + 6.0_dp*t*coef(j, 3, interval)
         end do
      else
         do j = 1, size(coef, 1)
            values(j) = coef(j, 0, interval) + t*(coef(j, 1, interval) &
               + t*(coef(j, 2, interval) + t*coef(j, 3, interval)))
            derivatives(j) = coef(j, 1, interval) + t*(2.0_dp*coef(j, 2, interval) &
               + 3.0_dp*t*coef(j, 3, interval))
         end do
      end if
   end subroutine cubic_eval

   !> The knots x(n) and cubic coefficients coef(m, 0:3, n-1) of a built spline (both empty
   !> when it is not built), for storing the interpolant elsewhere (cubic_locate, cubic_eval).
   pure subroutine spline_export(spline, knots, coef)
      type(spline_type), intent(in) :: spline
      real(dp), allocatable, intent(out) :: knots(:)
      real(dp), allocatable, intent(out) :: coef(:, :, :)
      if (spline%n < 2) then
         allocate (knots(0), coef(0, 0:3, 0))
      else
         allocate (knots(spline%n), coef(spline%m, 0:3, spline%n - 1))
         knots(:) = spline%x
         coef(:, :, :) = spline%coef
      end if
   end subroutine spline_export

   !> Locate and evaluate: all m columns and their first derivatives at x. With `hint`, the
   !> search starts at the caller's previous interval and `hint` returns the new one (unchanged
   !> on failure). On failure values and derivatives are zero.
   pure subroutine spline_value(spline, x, values, derivatives, status, hint)
      type(spline_type), intent(in) :: spline   !! a built spline
      real(dp), intent(in) :: x                 !! argument, x(1) <= x <= x(n)
      real(dp), intent(out) :: values(:)        !! values(m): the columns at x
      real(dp), intent(out) :: derivatives(:)   !! derivatives(m): their d/dx at x
      integer, intent(out) :: status            !! STATUS_OK or a spline_locate failure
      integer, intent(inout), optional :: hint  !! in: previous interval (any value); out: interval of x

      integer :: interval

      call spline_locate(spline, x, interval, status, hint)
      if (status /= STATUS_OK) then
         values = 0.0_dp
         derivatives = 0.0_dp
         return
      end if
      if (present(hint)) hint = interval
      call spline_eval(spline, interval, x, values, derivatives)
   end subroutine spline_value

   !> Number of knots n (0 when not built).
   pure integer function spline_points(spline)
      type(spline_type), intent(in) :: spline   !! the spline
      spline_points = spline%n
   end function spline_points

   !> Number of columns m (0 when not built).
   pure integer function spline_columns(spline)
      type(spline_type), intent(in) :: spline   !! the spline
      spline_columns = spline%m
   end function spline_columns

   !> The interpolation range [x(1), x(n)] of a built spline (0, 0 when not built).
   pure subroutine spline_domain(spline, lower, upper)
      type(spline_type), intent(in) :: spline   !! the spline
      real(dp), intent(out) :: lower            !! x(1)
      real(dp), intent(out) :: upper            !! x(n)
      if (spline%n < 2) then
         lower = 0.0_dp
         upper = 0.0_dp
      else
         lower = spline%x(1)
         upper = spline%x(spline%n)
      end if
   end subroutine spline_domain

end module interphase_spline
