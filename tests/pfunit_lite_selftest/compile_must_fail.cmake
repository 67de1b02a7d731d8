# Preprocess a .pf file and compile it against pfunit_lite's funit module: the compilation must
# fail with a message matching EXPECT (a construct real pFUnit refuses at compile time must not
# compile here either). With -DWARNING_ONLY=ON it must compile, with a warning matching EXPECT (a
# construct that real pFUnit's funit makes a warning with this compiler: the same warning here).
#   cmake -DPREPROCESS=<pf_preprocess> -DPF=<file.pf> -DCOMPILER=<fc> -DMODULE_DIR=<funit mod dir>
#         -DWORK=<dir> -DEXPECT=<regex> [-DWARNING_ONLY=ON] -P compile_must_fail.cmake
cmake_minimum_required(VERSION 3.20)
foreach(var IN ITEMS PREPROCESS PF COMPILER MODULE_DIR WORK EXPECT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "compile_must_fail.cmake: ${var} is not set")
  endif()
endforeach()
file(MAKE_DIRECTORY "${WORK}")
get_filename_component(name "${PF}" NAME_WE)
execute_process(COMMAND "${PREPROCESS}" "${PF}" "${WORK}/${name}.F90" RESULT_VARIABLE status
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the preprocessor refused ${PF} (it must compile and fail):\n${out}${err}")
endif()
execute_process(COMMAND "${COMPILER}" -c "-I${MODULE_DIR}" "${WORK}/${name}.F90" -o "${WORK}/${name}.o"
  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("---- compiler output for ${PF}\n${out}${err}----")
if(WARNING_ONLY AND NOT status EQUAL 0)
  message(FATAL_ERROR "${PF} did not compile, but real pFUnit's funit gives this compiler a warning only")
elseif(NOT WARNING_ONLY AND status EQUAL 0)
  message(FATAL_ERROR "${PF} compiled, but real pFUnit refuses it")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "the compiler's output for ${PF} does not match: ${EXPECT}")
endif()
