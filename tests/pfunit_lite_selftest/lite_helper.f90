!> Helper module given to add_pfunit_ctest as OTHER_SOURCES by the pfunit_lite self-test.
module lite_helper
   use, intrinsic :: iso_fortran_env, only: dp => real64
   implicit none
   private
   public :: dp, twice

contains

   pure real(dp) function twice(x)
      real(dp), intent(in) :: x
      twice = 2 * x
   end function twice

end module lite_helper
