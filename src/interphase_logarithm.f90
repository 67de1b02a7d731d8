!> The natural logarithm of the micromechanical model's interpolation variable w = 1/(1 - ln(1 - D)),
!> in plain Fortran arithmetic, so that the spline of an RVE table (the table grid's source,
!> interphase_table_grid) is evaluated with the same operations in every build and by every
!> compiler, and a grid built at build time (the built-in table) and one built when a table is
!> loaded agree bit for bit. (The compiler's `log` is a libm call in scalar code but, in a
!> vectorised loop, a call of the vector math library, whose results differ in the last bit;
!> docs/performance.md.)
!>
!> Method: y = 2^e m with m in [sqrt(1/2), sqrt(2)) from the bits of y (exact), then
!> ln y = e ln 2 + ln m, ln m = 2 atanh(s) = 2 s + s z P(z), s = (m - 1)/(m + 1), z = s^2,
!> P(z) = sum_{k=1..10} 2 z^(k-1)/(2k + 1) (the Taylor series of atanh, evaluated in Estrin's
!> scheme; |s| <= 0.1716, z <= 0.0295, so the first neglected term is below 1e-18 relative).
!> m - 1 is exact (Sterbenz), the division rounds once: the result is within a few units in the
!> last place of ln y (tests/test_spline.pf compares it with the intrinsic over many decades).
module interphase_logarithm
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   implicit none
   private
   public :: ln_positive

contains

   ! ln_positive and its pieces (one source with interphase_micro_coefficients, which inlines it)
   include 'interphase_ln_positive.inc'

end module interphase_logarithm
