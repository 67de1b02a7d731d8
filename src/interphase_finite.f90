!> Finiteness test for real(dp) values without `ieee_arithmetic`: with gfortran, every
!> procedure that uses that module saves and restores the floating-point environment on entry
!> and exit, which costs more than the whole interface update. Checking the exponent bits is
!> exact for IEEE binary64 and raises no floating-point exception for NaN or Inf.
module interphase_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   implicit none
   private
   public :: is_finite, is_within, all_within, EXPONENT_MASK, MAGNITUDE_MASK

   !> Exponent field of an IEEE binary64 number; all ones means Inf or NaN.
   integer(int64), parameter :: EXPONENT_MASK = int(z'7FF0000000000000', int64)
   !> All bits but the sign: iand(bits of x, MAGNITUDE_MASK) are the bits of |x|.
   integer(int64), parameter :: MAGNITUDE_MASK = int(z'7FFFFFFFFFFFFFFF', int64)

contains

   !> True when x is neither NaN nor +-Inf.
   elemental logical function is_finite(x)
      real(dp), intent(in) :: x
      is_finite = iand(transfer(x, 0_int64), EXPONENT_MASK) /= EXPONENT_MASK
   end function is_finite

   !> True when x is finite and |x| <= bound (bound finite, >= 0). Compares the bit patterns of |x|
   !> and bound (ordered like the numbers; NaN and Inf lie above every finite number), so it
   !> raises no floating-point exception for NaN or Inf.
   elemental logical function is_within(x, bound)
      real(dp), intent(in) :: x, bound
      is_within = iand(transfer(x, 0_int64), MAGNITUDE_MASK) <= transfer(bound, 0_int64)
   end function is_within

   !> all(is_within(x(1:n), bound)) in one call (a call per element costs more than the test where
   !> the caller is in another translation unit and cannot inline it). A scalar loop that stops
   !> at the first value out of range: the arrays are a host's 2 to 6 components.
   pure logical function all_within(n, x, bound)
      integer, intent(in) :: n            !! number of values
      real(dp), intent(in) :: x(n), bound
      integer :: i
      all_within = .false.
      do i = 1, n
         if (.not. is_within(x(i), bound)) return
      end do
      all_within = .true.
   end function all_within

end module interphase_finite
