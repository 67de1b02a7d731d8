# Run a command that must fail: exit status non-zero AND output (stdout + stderr) matching EXPECT.
#   cmake -DPROGRAM=<exe> -DARGS="arg1|arg2|..." -DEXPECT=<regex> [-DWORKDIR=<dir>] -P expect_failure.cmake
# -DMERGED=ON: standard output and error as one stream, in the order written.
# -DREJECT=<regex>: the output must NOT match it either (a line that must not be printed).
# ARGS is '|'-separated (a ';' would be split by add_test). Fails (message(FATAL_ERROR)) if the
# command exits with status 0 or its output does not match EXPECT.
foreach(var IN ITEMS PROGRAM EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "expect_failure.cmake: ${var} is not set")
  endif()
endforeach()
string(REPLACE "|" ";" arguments "${ARGS}")
if(NOT DEFINED WORKDIR)
  set(WORKDIR ${CMAKE_CURRENT_BINARY_DIR})
endif()
file(MAKE_DIRECTORY ${WORKDIR})
if(MERGED)
  # standard output and error in one stream, in the order written (as a pipe 2>&1 shows them)
  execute_process(COMMAND ${PROGRAM} ${arguments}
    WORKING_DIRECTORY ${WORKDIR}
    RESULT_VARIABLE status
    OUTPUT_VARIABLE all
    ERROR_VARIABLE all)
else()
  execute_process(COMMAND ${PROGRAM} ${arguments}
    WORKING_DIRECTORY ${WORKDIR}
    RESULT_VARIABLE status
    OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
  set(all "${out}${err}")
endif()
message(STATUS "command: ${PROGRAM} ${arguments}\nexit status: ${status}\noutput:\n${all}")
if(status STREQUAL "0")
  message(FATAL_ERROR "expected a non-zero exit status, got 0")
elseif(NOT status MATCHES "^[0-9]+$")
  message(FATAL_ERROR "the command did not run to an exit status: ${status}")
endif()
if(NOT all MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match the expected message: ${EXPECT}")
endif()
if(DEFINED REJECT AND all MATCHES "${REJECT}")
  message(FATAL_ERROR "output matches what it must not: ${REJECT}")
endif()
message(STATUS "ok: exit status ${status} and the expected message")
