# Runs one command and checks its exit status and output (used by the pfunit_lite self-test).
#   cmake -DSPEC=<file> -P check_run.cmake
# SPEC (written by pfunit_lite_check() in CMakeLists.txt) sets CHECK_COMMAND (list), CHECK_EXIT
# (expected exit status), CHECK_EXPECT (regular expressions the output must match) and
# CHECK_REJECT (regular expressions it must not match); output = standard output + standard error.
cmake_minimum_required(VERSION 3.20)
if(NOT SPEC)
  message(FATAL_ERROR "usage: cmake -DSPEC=<check spec> -P check_run.cmake")
endif()
include("${SPEC}")

execute_process(COMMAND ${CHECK_COMMAND}
  RESULT_VARIABLE exit_status OUTPUT_VARIABLE standard_output ERROR_VARIABLE standard_error)
set(output "${standard_output}${standard_error}")
message("---- output of: ${CHECK_COMMAND}\n${output}----")

set(problems "")
if(NOT exit_status STREQUAL CHECK_EXIT)
  string(APPEND problems "  exit status is '${exit_status}', expected ${CHECK_EXIT}\n")
endif()
foreach(pattern IN LISTS CHECK_EXPECT)
  if(NOT output MATCHES "${pattern}")
    string(APPEND problems "  output does not match: ${pattern}\n")
  endif()
endforeach()
foreach(pattern IN LISTS CHECK_REJECT)
  if(output MATCHES "${pattern}")
    string(APPEND problems "  output matches (and must not): ${pattern}\n")
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "check failed:\n${problems}")
endif()
