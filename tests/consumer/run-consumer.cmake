# Install the interphase build tree into a scratch prefix, build the consumer project against
# it with find_package(interphase), and run it. Fails on any step.
foreach(var INTERPHASE_BUILD CONSUMER_SOURCE WORK)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run-consumer.cmake: ${var} not set")
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
    message(FATAL_ERROR "consumer test: ${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok\n${out}")
endfunction()

run_step("install" ${CMAKE_COMMAND} --install ${INTERPHASE_BUILD} --prefix ${prefix} --config ${BUILD_TYPE})
run_step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE} -B ${WORK}/build
         -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE})
run_step("build consumer" ${CMAKE_COMMAND} --build ${WORK}/build)
run_step("run consumer" ${WORK}/build/consumer)
