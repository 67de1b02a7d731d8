# The status-code check (check_status_codes.cmake) must be able to fail: it passes on the real
# files and fails on copies with one planted difference each (a changed value, a missing code,
# an extra macro, a new Fortran code, a Fortran value that is not a plain integer).
#
#   cmake -DFORTRAN=... -DHEADER=... -DCHECKER=check_status_codes.cmake -DWORK=<dir> -P this file
cmake_minimum_required(VERSION 3.20)

file(MAKE_DIRECTORY "${WORK}")
file(READ "${HEADER}" header)
file(READ "${FORTRAN}" fortran)

set(failures "")

function(run_check label fortran_file header_file expect_ok)
  execute_process(COMMAND ${CMAKE_COMMAND} -DFORTRAN=${fortran_file} -DHEADER=${header_file}
                          -P ${CHECKER}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect_ok AND NOT rc EQUAL 0)
    set(failures "${failures}  ${label}: the check failed on the real files:\n${err}\n" PARENT_SCOPE)
  elseif(NOT expect_ok AND rc EQUAL 0)
    set(failures "${failures}  ${label}: the check passed but must fail\n" PARENT_SCOPE)
  else()
    message(STATUS "${label}: exit ${rc} as expected")
  endif()
endfunction()

# a mutation that does not change the text would test nothing
function(must_differ label original mutated)
  if(original STREQUAL mutated)
    message(FATAL_ERROR "${label}: the mutation did not apply (has the file's format changed?)")
  endif()
endfunction()

run_check("real files" "${FORTRAN}" "${HEADER}" TRUE)

# 1. one header value changed (the last code, 63 -> 64)
string(REGEX REPLACE "(#define INTERPHASE_STATUS_RCURVE_BAD_RANGE[ \t]+)63" "\\164" mutated "${header}")
must_differ("changed value" "${header}" "${mutated}")
file(WRITE "${WORK}/changed_value.h" "${mutated}")
run_check("header value 63 -> 64" "${FORTRAN}" "${WORK}/changed_value.h" FALSE)

# 2. one header code missing
string(REGEX REPLACE "#define INTERPHASE_STATUS_TABLE_NOT_LOADED[^\n]*\n" "" mutated "${header}")
must_differ("missing code" "${header}" "${mutated}")
file(WRITE "${WORK}/missing_code.h" "${mutated}")
run_check("header without TABLE_NOT_LOADED" "${FORTRAN}" "${WORK}/missing_code.h" FALSE)

# 3. an extra header macro that the module does not have
file(WRITE "${WORK}/extra_code.h" "${header}\n#define INTERPHASE_STATUS_PLANTED 99 /**< planted */\n")
run_check("extra header macro" "${FORTRAN}" "${WORK}/extra_code.h" FALSE)

# 4. a new Fortran code (two on one continued statement) that the header lacks
string(REPLACE "contains" "integer, parameter, public :: STATUS_PLANTED_A = 98, &\n      STATUS_PLANTED_B = 99\ncontains"
       mutated "${fortran}")
must_differ("new Fortran code" "${fortran}" "${mutated}")
file(WRITE "${WORK}/new_code.f90" "${mutated}")
run_check("new Fortran codes" "${WORK}/new_code.f90" "${HEADER}" FALSE)

# 5. a Fortran value the check cannot read must fail, not be skipped
string(REGEX REPLACE "(STATUS_TABLE_NOT_LOADED = )59" "\\1STATUS_TABLE_IDENTITY + 1" mutated "${fortran}")
must_differ("unreadable value" "${fortran}" "${mutated}")
file(WRITE "${WORK}/unreadable.f90" "${mutated}")
run_check("Fortran value not an integer" "${WORK}/unreadable.f90" "${HEADER}" FALSE)

if(failures)
  message(FATAL_ERROR "the status-code check is broken:\n${failures}")
endif()
message(STATUS "the status-code check passes on the real files and fails on all 5 planted differences")
