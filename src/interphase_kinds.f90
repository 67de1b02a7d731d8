!> Working precision of interphase: every real is `real(dp)`.
module interphase_kinds
   use, intrinsic :: iso_fortran_env, only: real64
   implicit none
   private

   !> Double precision, used for every real quantity in the library.
   integer, parameter, public :: dp = real64

end module interphase_kinds
