!> Finiteness test for real(dp) values without `ieee_arithmetic`: with gfortran, every
!> procedure that uses that module saves and restores the floating-point environment on entry
!> and exit, which costs more than the whole interface update. Checking the exponent bits is
!> exact for IEEE binary64 and raises no floating-point exception for NaN or Inf.
module interphase_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   implicit none
   private
   public :: is_finite, EXPONENT_MASK

   !> Exponent field of an IEEE binary64 number; all ones means Inf or NaN.
   integer(int64), parameter :: EXPONENT_MASK = int(z'7FF0000000000000', int64)

contains

   !> True when x is neither NaN nor +-Inf.
   elemental logical function is_finite(x)
      real(dp), intent(in) :: x
      is_finite = iand(transfer(x, 0_int64), EXPONENT_MASK) /= EXPONENT_MASK
   end function is_finite

end module interphase_finite
