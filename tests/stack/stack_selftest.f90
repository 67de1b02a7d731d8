!> The self-test of tests/check_stack.cmake (ctest no_executable_stack_selftest): a library whose
!> object asks for an executable stack on purpose, and a program that links it. `scaled_apply`'s
!> internal function uses a variable of its host and is passed as an actual argument, for which
!> gfortran and flang build a trampoline on the stack. Nothing of interphase uses this.
module stack_selftest
   implicit none
   private
   public :: scaled_apply

   abstract interface
      real function unary(x)
         real, intent(in) :: x
      end function unary
   end interface

contains

   real function scaled_apply(scale, x) result(y)
      real, intent(in) :: scale, x
      y = apply(scaled, x)
   contains
      real function scaled(v)
         real, intent(in) :: v
         scaled = scale*v
      end function scaled
   end function scaled_apply

   real function apply(f, x)
      procedure(unary) :: f
      real, intent(in) :: x
      apply = f(x)
   end function apply

end module stack_selftest
