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

   !> ln 2 rounded to binary64.
   real(dp), parameter :: LN2 = 0.693147180559945309417232121458176568_dp
   !> The mantissa field and the bits of 1.0.
   integer(int64), parameter :: MANTISSA_MASK = int(z'000FFFFFFFFFFFFF', int64)
   integer(int64), parameter :: ONE_BITS = int(z'3FF0000000000000', int64)
   !> The mantissa field of sqrt(2): a mantissa above it is halved (and the exponent raised).
   integer(int64), parameter :: SQRT2_MANTISSA = iand(transfer(sqrt(2.0_dp), 0_int64), MANTISSA_MASK)
   !> 2/(2k + 1), k = 1..10.
   real(dp), parameter :: C1 = 2.0_dp/3.0_dp, C2 = 2.0_dp/5.0_dp, C3 = 2.0_dp/7.0_dp, C4 = 2.0_dp/9.0_dp, &
      C5 = 2.0_dp/11.0_dp, C6 = 2.0_dp/13.0_dp, C7 = 2.0_dp/15.0_dp, C8 = 2.0_dp/17.0_dp, C9 = 2.0_dp/19.0_dp, &
      C10 = 2.0_dp/21.0_dp

contains

   !> ln y for a positive, normal, finite y (others are the caller's business: no check here, this
   !> is the hot path; no floating-point exception for such y).
   elemental real(dp) function ln_positive(y) result(ln_y)
      real(dp), intent(in) :: y
      integer(int64) :: bits, up
      bits = transfer(y, 0_int64)
      up = above_sqrt2(bits)
      ln_y = ln_series(real(int(ishft(bits, -52)) - 1023 + int(up), dp), &
         transfer(reduced_mantissa(bits, up), 0.0_dp))
   end function ln_positive

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

   !> 1 when the mantissa of the number with bit pattern b lies above sqrt(2), else 0.
   elemental integer(int64) function above_sqrt2(b)
      integer(int64), intent(in) :: b
      above_sqrt2 = merge(1_int64, 0_int64, iand(b, MANTISSA_MASK) > SQRT2_MANTISSA)
   end function above_sqrt2

   !> The bit pattern of m: the mantissa in [1, 2), halved (exponent field 1022) when above
   !> sqrt(2) (up = 1).
   elemental integer(int64) function reduced_mantissa(b, up)
      integer(int64), intent(in) :: b, up
      reduced_mantissa = ior(iand(b, MANTISSA_MASK), ONE_BITS - ishft(up, 52))
   end function reduced_mantissa

   !> ln y = e ln 2 + ln m, m in [1/sqrt(2), sqrt(2)]: ln m = 2 atanh(s), s = (m - 1)/(m + 1),
   !> as its series to s^21. P(z) in Estrin's scheme: the pairs C_k + z C_(k+1), combined with
   !> z^2, then z^4, so that the chain of dependent multiply-and-add stages after z is 4 deep,
   !> where Horner's form is 9 (no contraction: -ffp-contract=off). The point update waits for
   !> this logarithm before the table lookup can start; the scheme makes the micromechanical
   !> UMAT call about 6 ns faster (docs/performance.md). The same operations, in the same order,
   !> in the scalar and the block form.
   elemental real(dp) function ln_series(e, m) result(ln_y)
      real(dp), intent(in) :: e, m
      real(dp) :: f, s, z, z2, z4
      f = m - 1.0_dp
      s = f/(2.0_dp + f)
      z = s*s
      z2 = z*z
      z4 = z2*z2
      ln_y = e*LN2 + (2.0_dp*s + s*(z*(((C1 + z*C2) + z2*(C3 + z*C4)) &
         + z4*(((C5 + z*C6) + z2*(C7 + z*C8)) + z4*(C9 + z*C10)))))
   end function ln_series

end module interphase_logarithm
