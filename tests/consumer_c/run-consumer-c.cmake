# Install the interphase build tree into a scratch prefix, then build and run the C program
# tests/consumer_c/consumer.c against it twice: as a C-only CMake project (find_package) and by
# hand with pkg-config (interphase.pc), and, with OTHER_FORTRAN_COMPILER, as a project that enables
# Fortran with that compiler (not the one that built interphase). Fails on any step; pkg-config missing: a skip (SKIP_CODE 77) or a failure (strict CI).
foreach(var INTERPHASE_BUILD CONSUMER_SOURCE WORK C_COMPILER SKIP_CODE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run-consumer-c.cmake: ${var} not set")
  endif()
endforeach()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "C consumer test: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok\n${out}")
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${INTERPHASE_BUILD} --prefix ${prefix} --config ${BUILD_TYPE})
run_step("configure the C-only consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${WORK}/build
         -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_C_COMPILER=${C_COMPILER})
run_step("build the C-only consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
run_step("run the C-only consumer" ${WORK}/build/consumer_c)
# the same program in a project that enables Fortran with the other tested compiler
if(OTHER_FORTRAN_COMPILER)
  run_step("configure the consumer with Fortran enabled (${OTHER_FORTRAN_COMPILER})" ${CMAKE_COMMAND}
           -S ${CONSUMER_SOURCE} -B ${WORK}/build-other -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
           -DCMAKE_C_COMPILER=${C_COMPILER} -DCONSUMER_ENABLE_FORTRAN=ON -DCMAKE_Fortran_COMPILER=${OTHER_FORTRAN_COMPILER})
  run_step("build the consumer with Fortran enabled (${OTHER_FORTRAN_COMPILER})" ${CMAKE_COMMAND} --build ${WORK}/build-other)
  run_step("run the consumer with Fortran enabled (${OTHER_FORTRAN_COMPILER})" ${WORK}/build-other/consumer_c)
endif()

find_program(PKG_CONFIG_EXE NAMES pkg-config pkgconf)
if(NOT PKG_CONFIG_EXE)
  # the CMake part passed; ctest reads this line as a skip (SKIP_REGULAR_EXPRESSION), except
  # under strict CI, where it is a failure
  if(SKIP_CODE EQUAL 77)
    message(STATUS "INTERPHASE-SKIP: pkg-config not found: the interphase.pc part is skipped (install Debian package pkgconf)")
    return()
  endif()
  message(FATAL_ERROR "pkg-config not found (install Debian package pkgconf)")
endif()
set(ENV{PKG_CONFIG_PATH} ${prefix}/lib/pkgconfig:${prefix}/lib64/pkgconfig)
execute_process(COMMAND ${PKG_CONFIG_EXE} --cflags --libs interphase RESULT_VARIABLE rc OUTPUT_VARIABLE flags
  ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pkg-config --cflags --libs interphase failed: ${err}")
endif()
message(STATUS "pkg-config --cflags --libs interphase: ${flags}")
separate_arguments(flag_list UNIX_COMMAND "${flags}")
run_step("build with pkg-config" ${C_COMPILER} ${CONSUMER_SOURCE}/consumer.c -o ${WORK}/consumer_pc ${flag_list})
run_step("run the pkg-config build" ${WORK}/consumer_pc)
