!> The natural logarithm of the micromechanical model's interpolation variable w = 1/(1 - ln(1 - D)),
!> in plain Fortran arithmetic, so that the point update and the vectorised block update compute
!> it with the same operations and agree bit for bit. (The compiler's `log` is a libm call in
!> scalar code but, in a vectorised loop, a call of the vector math library, whose results
!> differ in the last bit; docs/performance.md.)
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
   public :: ln_positive, ln_positive_block

contains

   ! ln_positive and its pieces (one source with interphase_micro_coefficients, which inlines it)
   include 'interphase_ln_positive.inc'

   !> ln_y(i) = ln_positive(y(i)), i = 1..n, in one call: the same operations on each element
   !> (so the same bits), in loops the compiler vectorises where a caller's own loop could not
   !> inline a function of another translation unit, a chunk at a time on the stack.
   pure subroutine ln_positive_block(n, y, ln_y)
      integer, intent(in) :: n
      real(dp), intent(in) :: y(n)        !! positive, finite, normal
      real(dp), intent(out) :: ln_y(n)
      integer, parameter :: CHUNK = 128
      integer(int64) :: bits(CHUNK), m_bits(CHUNK), up(CHUNK)
      real(dp) :: m(CHUNK)
      integer :: i, first, k
      do first = 1, n, CHUNK
         k = min(CHUNK, n - first + 1)
         ! (element by element, vectorised by gfortran 12: a section's transfer of run-time length
         ! is built in a heap temporary, with a malloc, a copy and a free per chunk)
         do i = 1, k
            bits(i) = transfer(y(first + i - 1), 0_int64)
            up(i) = above_sqrt2(bits(i))
            m_bits(i) = reduced_mantissa(bits(i), up(i))
            m(i) = transfer(m_bits(i), 0.0_dp)
         end do
         do i = 1, k
            ln_y(first + i - 1) = ln_series(real(int(ishft(bits(i), -52)) - 1023 + int(up(i)), dp), m(i))
         end do
      end do
   end subroutine ln_positive_block

end module interphase_logarithm
