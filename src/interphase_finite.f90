!> Finiteness test for real(dp) values without `ieee_arithmetic`: with gfortran, every
!> procedure that uses that module saves and restores the floating-point environment on entry
!> and exit, which costs more than the whole interface update. Checking the exponent bits is
!> exact for IEEE binary64 and raises no floating-point exception for NaN or Inf.
!>
!> The bits are read through storage association (`binary64_bits`), not `transfer`: LLVM flang 19
!> compiles a `transfer` evaluated at run time to a call of its run-time library with a heap
!> allocation (some 100 ns), the equivalence to a load; gfortran compiles both to a load
!> (docs/compilers.md).
module interphase_finite
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   implicit none
   private
   public :: is_finite, is_finite_nonnegative, is_within, all_within, difference_is_finite, binary64_bits, EXPONENT_MASK, &
      MAGNITUDE_MASK, HIGH_HALF, LOW_HALF, LOW_HALF_MASK

   !> Admissible magnitudes of the dimensional PROPS (s0, sf in mm; K in MPa/mm; G_c in N/mm) and
   !> the largest friction coefficient (interphase_params): every product the update forms of up
   !> to eight such factors (the squares of s/s0 in the damage law, alpha^4 in its derivatives,
   !> energies K s^2, g = G/(2 G_c)) then stays between 1e-160 and 1e160, normal numbers far from
   !> overflow and underflow, so that no build and no adapter can round a result differently
   !> into Inf, NaN or zero (docs/abaqus.md, 'Admissible ranges'). The table and R-curve readers
   !> bound their lengths, moduli and toughnesses by the same window.
   real(dp), parameter, public :: PROPS_VALUE_MIN = 1.0e-20_dp
   real(dp), parameter, public :: PROPS_VALUE_MAX = 1.0e20_dp

   !> Smallest positive damage D = a/b at which a crack's coefficients and release rates are
   !> formed (-): the micromechanical tables' T^f ~ 1/D and its D-derivatives ~ 1/D^2, 1/D^3 stay
   !> far from overflow (interphase_micro_coefficients fails below it), and so do the fracture
   !> law's release-rate slopes, which hold (m'/m)^2 ~ 1/D^2 with m = D ufbar (both models;
   !> interphase_fracture). The fracture law's initial crack D0 must be at least this
   !> (interphase_params): 1e-30 b is no physical length for any brick, and such a crack's release
   !> rates, which scale with D, could not make it grow.
   real(dp), parameter, public :: D_MIN_CRACK = 1.0e-30_dp

   !> Exponent field of an IEEE binary64 number; all ones means Inf or NaN.
   integer(int64), parameter :: EXPONENT_MASK = int(z'7FF0000000000000', int64)
   !> All bits but the sign: iand(bits of x, MAGNITUDE_MASK) are the bits of |x|.
   integer(int64), parameter :: MAGNITUDE_MASK = int(z'7FFFFFFFFFFFFFFF', int64)
   !> The two default integers (32 bits each) that share a binary64 number's storage, and which of
   !> them holds the sign and exponent (2 on a little-endian machine): from the bits of 1.0,
   !> whose low half is zero (constant expressions, folded at compile time).
   integer, parameter :: ONE_HALVES(2) = transfer(1.0_dp, [0, 0], 2)
   integer, parameter :: HIGH_HALF = merge(2, 1, ONE_HALVES(1) == 0), LOW_HALF = 3 - HIGH_HALF
   integer(int64), parameter :: LOW_HALF_MASK = int(z'00000000FFFFFFFF', int64)

contains

   include 'interphase_binary64_bits.inc'

   include 'interphase_is_finite.inc'

   include 'interphase_within.inc'

   !> True when x is a finite number >= 0 (a time increment): finiteness first, so that no
   !> ordered comparison meets a NaN (it raises the invalid flag, and a host with floating-point
   !> traps stops there).
   elemental logical function is_finite_nonnegative(x)
      real(dp), intent(in) :: x
      is_finite_nonnegative = is_finite(x)
      if (is_finite_nonnegative) is_finite_nonnegative = x >= 0.0_dp
   end function is_finite_nonnegative

   !> True when a - b is a finite number (a and b finite: a time step of a history), tested
   !> without forming it: a difference beyond huge() raises the overflow flag, and a host with
   !> floating-point traps stops there. a/2 - b/2 is the difference halved, rounded alike (no
   !> halving of a number that large is inexact), and never overflows.
   elemental logical function difference_is_finite(a, b)
      real(dp), intent(in) :: a, b
      difference_is_finite = abs(0.5_dp*a - 0.5_dp*b) <= 0.5_dp*huge(1.0_dp)
   end function difference_is_finite

end module interphase_finite
