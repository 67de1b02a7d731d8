# pfunit_lite: fallback for machines without pFUnit 4.x (tests/CMakeLists.txt includes this file
# when find_package(PFUNIT) fails). It needs only CMake and a Fortran compiler:
#   - tests/pfunit_lite/pf_preprocess.f90: translates a .pf file into Fortran (host executable),
#   - tests/pfunit_lite/funit.f90: module `funit`, the assertions and the test runner.
#
# add_pfunit_ctest(<name>
#                  TEST_SOURCES <file.pf>...          (relative paths: to CMAKE_CURRENT_SOURCE_DIR)
#                  [OTHER_SOURCES <source>...]
#                  [LINK_LIBRARIES <library>...]
#                  [LABELS <label>...]
#                  [MAX_PES <n>]                      (accepted; the tests run serially)
#                  [WORKING_DIRECTORY <dir>])         (default: CMAKE_CURRENT_BINARY_DIR)
#
# Same meaning as pFUnit's function: one executable <name> from all the .pf files (each translated
# to ${CMAKE_CURRENT_BINARY_DIR}/<file>.F90) plus a generated driver, and one ctest test <name>.
# Unlike pFUnit's, the executable exits with status 1 when a test fails; its last line is
# "N passed, N failed", and the ctest test passes only when that line reports 0 failed (a program
# that stops early, even with status 0, fails). Run `<name> -h` for its options (filter by test name, verbose).
# pFUnit's REGISTRY, EXTRA_USE, EXTRA_INITIALIZE and EXTRA_FINALIZE are not supported (error).
#
# INTERPHASE_PFUNIT_CHECK_FLAGS (cache) holds the run-time checks the test code is compiled with.
include_guard(GLOBAL)

set(_PFUNIT_LITE_SOURCE_DIR "${CMAKE_CURRENT_LIST_DIR}/../tests/pfunit_lite")
get_filename_component(_PFUNIT_LITE_SOURCE_DIR "${_PFUNIT_LITE_SOURCE_DIR}" ABSOLUTE)
set(_PFUNIT_LITE_BINARY_DIR "${CMAKE_CURRENT_BINARY_DIR}/pfunit_lite")

if(CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
  # The project's Debug checks, in every build type. Not -std=f2008/-pedantic: the .pf code is
  # also compiled by real pFUnit, which does not use them.
  set(INTERPHASE_PFUNIT_CHECK_FLAGS "-g;-fcheck=all;-fbacktrace;-ffpe-trap=invalid,zero,overflow;-fimplicit-none;-Wall"
      CACHE STRING "Compiler flags of the pfunit_lite test executables")
  set(_PFUNIT_LITE_OWN_FLAGS -std=f2008 -fimplicit-none -Wall -Wextra -Wimplicit-interface -pedantic)
elseif(CMAKE_Fortran_COMPILER_ID STREQUAL "LLVMFlang")
  # flang has no run-time checks to add (no -fcheck, no -ffpe-trap): debug information only.
  set(INTERPHASE_PFUNIT_CHECK_FLAGS "-g;-fimplicit-none"
      CACHE STRING "Compiler flags of the pfunit_lite test executables")
  set(_PFUNIT_LITE_OWN_FLAGS -std=f2018 -pedantic -fimplicit-none)
else()
  set(INTERPHASE_PFUNIT_CHECK_FLAGS "" CACHE STRING "Compiler flags of the pfunit_lite test executables")
  set(_PFUNIT_LITE_OWN_FLAGS "")
endif()

# OpenMP, as real pFUnit compiles its test programs (without it the `!$` lines stay comments)
find_package(OpenMP COMPONENTS Fortran QUIET)
if(OpenMP_Fortran_FOUND)
  set(_PFUNIT_LITE_OPENMP TRUE)
else()
  set(_PFUNIT_LITE_OPENMP FALSE)
  message(STATUS "pfunit_lite: OpenMP for Fortran not found: the test programs are compiled without it "
                 "(real pFUnit's are compiled with it: an !$ line is not checked here)")
endif()

if(NOT TARGET pfunit_lite_preprocessor)
  add_executable(pfunit_lite_preprocessor "${_PFUNIT_LITE_SOURCE_DIR}/pf_preprocess.f90")
  set_target_properties(pfunit_lite_preprocessor PROPERTIES
    RUNTIME_OUTPUT_DIRECTORY "${_PFUNIT_LITE_BINARY_DIR}"
    Fortran_MODULE_DIRECTORY "${_PFUNIT_LITE_BINARY_DIR}/preprocessor_mod")
  target_compile_options(pfunit_lite_preprocessor PRIVATE ${_PFUNIT_LITE_OWN_FLAGS})
endif()

if(NOT TARGET pfunit_lite_funit)
  add_library(pfunit_lite_funit STATIC "${_PFUNIT_LITE_SOURCE_DIR}/funit.f90")
  set_target_properties(pfunit_lite_funit PROPERTIES
    ARCHIVE_OUTPUT_DIRECTORY "${_PFUNIT_LITE_BINARY_DIR}"
    Fortran_MODULE_DIRECTORY "${_PFUNIT_LITE_BINARY_DIR}/mod")
  target_include_directories(pfunit_lite_funit PUBLIC "${_PFUNIT_LITE_BINARY_DIR}/mod")
  target_compile_options(pfunit_lite_funit PRIVATE ${_PFUNIT_LITE_OWN_FLAGS})
endif()

function(add_pfunit_ctest test_name)
  cmake_parse_arguments(PARSE_ARGV 1 PF ""
    "MAX_PES;WORKING_DIRECTORY;REGISTRY;EXTRA_USE;EXTRA_INITIALIZE;EXTRA_FINALIZE"
    "TEST_SOURCES;OTHER_SOURCES;LINK_LIBRARIES;LABELS")
  if(PF_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "add_pfunit_ctest(${test_name}): unexpected arguments: ${PF_UNPARSED_ARGUMENTS}")
  endif()
  foreach(option IN ITEMS REGISTRY EXTRA_USE EXTRA_INITIALIZE EXTRA_FINALIZE)
    if(DEFINED PF_${option})
      message(FATAL_ERROR "add_pfunit_ctest(${test_name}): ${option} is not supported by pfunit_lite")
    endif()
  endforeach()
  if(NOT PF_TEST_SOURCES)
    message(FATAL_ERROR "add_pfunit_ctest(${test_name}): TEST_SOURCES is required")
  endif()
  if(DEFINED PF_MAX_PES AND NOT PF_MAX_PES MATCHES "^[1-9][0-9]*$")
    message(FATAL_ERROR "add_pfunit_ctest(${test_name}): MAX_PES must be a positive integer, not '${PF_MAX_PES}'")
  endif()

  # One custom command per generated file in this directory, even if two tests share a .pf.
  get_property(generated_here DIRECTORY PROPERTY _PFUNIT_LITE_GENERATED)
  set(generated_sources "")
  set(suite_uses "")
  set(suite_calls "")
  set(suite_index 0)
  foreach(pf_file IN LISTS PF_TEST_SOURCES)
    get_filename_component(pf_path "${pf_file}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(module_name "${pf_path}" NAME_WLE)
    if(NOT module_name MATCHES "^[A-Za-z][A-Za-z0-9_]*$")
      message(FATAL_ERROR "add_pfunit_ctest(${test_name}): '${pf_file}' must be named like the Fortran module it holds")
    endif()
    set(f90_file "${CMAKE_CURRENT_BINARY_DIR}/${module_name}.F90")
    if(f90_file IN_LIST generated_sources)
      message(FATAL_ERROR "add_pfunit_ctest(${test_name}): two TEST_SOURCES named ${module_name}")
    endif()
    if(NOT "${f90_file}<-${pf_path}" IN_LIST generated_here)
      if("${f90_file}" IN_LIST generated_here)
        message(FATAL_ERROR "add_pfunit_ctest(${test_name}): ${module_name}.F90 is already generated from "
                            "another .pf file in ${CMAKE_CURRENT_SOURCE_DIR}")
      endif()
      add_custom_command(OUTPUT "${f90_file}"
        COMMAND pfunit_lite_preprocessor "${pf_path}" "${f90_file}"
        DEPENDS "${pf_path}" pfunit_lite_preprocessor
        COMMENT "pfunit_lite: preprocessing ${pf_file}"
        VERBATIM)
      list(APPEND generated_here "${f90_file}" "${f90_file}<-${pf_path}")
    endif()
    list(APPEND generated_sources "${f90_file}")
    math(EXPR suite_index "${suite_index} + 1")
    string(APPEND suite_uses "   use wrap_${module_name}, only: suite_${suite_index} => ${module_name}_suite\n")
    string(APPEND suite_calls "   call suite_${suite_index}()\n")
  endforeach()
  set_property(DIRECTORY PROPERTY _PFUNIT_LITE_GENERATED "${generated_here}")

  set(driver "${CMAKE_CURRENT_BINARY_DIR}/${test_name}_driver.f90")
  file(CONFIGURE OUTPUT "${driver}" @ONLY CONTENT [=[
! Generated by cmake/InterphasePfunit.cmake for test @test_name@: runs every test of its .pf files.
program funit_driver
   use funit, only: funit_initialize, funit_finalize, FUNIT_RUN, FUNIT_HELP_SHOWN
@suite_uses@   implicit none
   integer :: status
   logical :: all_passed

   call funit_initialize(status)
   if (status == FUNIT_HELP_SHOWN) stop
   if (status /= FUNIT_RUN) stop 2
@suite_calls@   call funit_finalize(all_passed)
   if (.not. all_passed) stop 1
end program funit_driver
]=])

  add_executable(${test_name} ${generated_sources} ${PF_OTHER_SOURCES} "${driver}")
  set(module_dir "${CMAKE_CURRENT_BINARY_DIR}/mod/${test_name}")
  set_target_properties(${test_name} PROPERTIES Fortran_MODULE_DIRECTORY "${module_dir}")
  target_include_directories(${test_name} PRIVATE "${module_dir}")
  target_compile_options(${test_name} PRIVATE ${INTERPHASE_PFUNIT_CHECK_FLAGS})
  # warnings are errors in the test code too when they are in the library's (INTERPHASE_WERROR)
  if(INTERPHASE_WERROR AND CMAKE_Fortran_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${test_name} PRIVATE -Werror)
  endif()
  # Plain signature, as pFUnit's add_pfunit_ctest: callers may add libraries the same way.
  target_link_libraries(${test_name} pfunit_lite_funit ${PF_LINK_LIBRARIES})
  # Real pFUnit's test programs are compiled with OpenMP (../shared/PFUNIT.md): an `!$` line must
  # compile here too, so the same flag where the compiler has it.
  if(_PFUNIT_LITE_OPENMP)
    target_link_libraries(${test_name} OpenMP::OpenMP_Fortran)
  endif()

  if(PF_WORKING_DIRECTORY)
    set(working_directory "${PF_WORKING_DIRECTORY}")
  else()
    set(working_directory "${CMAKE_CURRENT_BINARY_DIR}")
  endif()
  add_test(NAME ${test_name} COMMAND ${test_name} WORKING_DIRECTORY "${working_directory}")
  # Passed only with the closing line of a run without failures: a test that ends the program
  # with a plain `stop` (exit status 0) after a failed assertion, or before the last test ran,
  # prints no closing line and fails here. (ctest then ignores the exit status, which is 0
  # exactly when that line is printed.)
  set_property(TEST ${test_name} PROPERTY PASS_REGULAR_EXPRESSION "(^|\n)[0-9]+ passed, 0 failed\n")
  if(PF_LABELS)
    set_property(TEST ${test_name} PROPERTY LABELS ${PF_LABELS})
  endif()
endfunction()
