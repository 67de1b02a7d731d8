!> The program of the self-test of tests/check_stack.cmake (tests/stack/stack_selftest.f90).
program stack_selftest_main
   use stack_selftest, only: scaled_apply
   implicit none
   print '(f4.1)', scaled_apply(2.0, 3.0)
end program stack_selftest_main
