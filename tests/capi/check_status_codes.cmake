# Check that include/interphase.h defines every status code of src/interphase_status.f90, with the
# same name and value, and nothing else:
#
#   cmake -DFORTRAN=src/interphase_status.f90 -DHEADER=include/interphase.h -P check_status_codes.cmake
#
# Fortran `integer, parameter ... :: STATUS_<NAME> = <integer>` (any case, several per statement,
# continuation lines) must match C `#define INTERPHASE_STATUS_<NAME> <integer>` one for one.
# A STATUS_* parameter or INTERPHASE_STATUS_* macro whose value is not a plain integer is an error
# (the check must never skip a code it cannot read). Exits non-zero, listing every difference.
cmake_minimum_required(VERSION 3.20)

foreach(var IN ITEMS FORTRAN HEADER)
  if(NOT DEFINED ${var} OR NOT EXISTS "${${var}}")
    message(FATAL_ERROR "check_status_codes: -D${var}=<file> not given or missing: '${${var}}'")
  endif()
endforeach()

set(errors "")

# ---- Fortran: statements of the module, comments stripped, continuations joined -------------
file(STRINGS "${FORTRAN}" flines)
set(statement "")
set(statements "")
foreach(line IN LISTS flines)
  string(REGEX REPLACE "!.*$" "" line "${line}")          # comments (no '!' in the declarations)
  string(STRIP "${line}" line)
  string(REGEX REPLACE "^&" "" line "${line}")
  if(line MATCHES "&$")
    string(REGEX REPLACE "&$" "" line "${line}")
    string(APPEND statement " ${line}")
  else()
    string(APPEND statement " ${line}")
    string(TOUPPER "${statement}" statement)
    list(APPEND statements "${statement}")
    set(statement "")
  endif()
endforeach()

set(f_names "")
foreach(st IN LISTS statements)
  if(NOT st MATCHES "PARAMETER" OR NOT st MATCHES "::")
    continue()
  endif()
  string(REGEX REPLACE "^.*::" "" entities "${st}")
  string(REPLACE "," ";" entities "${entities}")
  foreach(entity IN LISTS entities)
    string(STRIP "${entity}" entity)
    if(NOT entity MATCHES "^STATUS_[A-Z0-9_]+ *=")      # a declaration, not a use in a value
      continue()
    endif()
    if(entity MATCHES "^(STATUS_[A-Z0-9_]+) *= *([0-9]+)$")
      set(name "${CMAKE_MATCH_1}")
      set(value "${CMAKE_MATCH_2}")
      if(DEFINED f_${name})
        string(APPEND errors "  ${FORTRAN}: ${name} declared twice\n")
      endif()
      set(f_${name} "${value}")
      list(APPEND f_names "${name}")
    else()
      string(APPEND errors "  ${FORTRAN}: cannot read the status parameter '${entity}' (not NAME = integer)\n")
    endif()
  endforeach()
endforeach()

# ---- C header: #define INTERPHASE_STATUS_<NAME> <value> ------------------------------------
file(STRINGS "${HEADER}" hlines)
set(c_names "")
foreach(line IN LISTS hlines)
  if(NOT line MATCHES "^[ \t]*#[ \t]*define[ \t]+INTERPHASE_STATUS_")
    continue()
  endif()
  if(line MATCHES "^[ \t]*#[ \t]*define[ \t]+INTERPHASE_(STATUS_[A-Z0-9_]+)[ \t]+\\(?([0-9]+)\\)?[ \t]*(/\\*.*)?$")
    set(name "${CMAKE_MATCH_1}")
    set(value "${CMAKE_MATCH_2}")
    if(DEFINED c_${name})
      string(APPEND errors "  ${HEADER}: INTERPHASE_${name} defined twice\n")
    endif()
    set(c_${name} "${value}")
    list(APPEND c_names "${name}")
  else()
    string(APPEND errors "  ${HEADER}: cannot read the status macro '${line}' (not #define NAME integer)\n")
  endif()
endforeach()

# ---- compare, both ways ------------------------------------------------------------------
if(NOT "STATUS_OK" IN_LIST f_names)
  string(APPEND errors "  ${FORTRAN}: no STATUS_OK found: the parser read nothing\n")
endif()
foreach(name IN LISTS f_names)
  if(NOT DEFINED c_${name})
    string(APPEND errors "  INTERPHASE_${name} (= ${f_${name}} in ${FORTRAN}) is missing from ${HEADER}\n")
  elseif(NOT c_${name} EQUAL f_${name})
    string(APPEND errors
      "  INTERPHASE_${name} = ${c_${name}} in ${HEADER} but ${name} = ${f_${name}} in ${FORTRAN}\n")
  endif()
endforeach()
foreach(name IN LISTS c_names)
  if(NOT DEFINED f_${name})
    string(APPEND errors "  INTERPHASE_${name} (= ${c_${name}}) in ${HEADER} is not a status of ${FORTRAN}\n")
  endif()
endforeach()

list(LENGTH f_names nf)
list(LENGTH c_names nc)
if(errors)
  message(FATAL_ERROR "status codes of the C header and the Fortran module differ "
                      "(${nc} in the header, ${nf} in the module):\n${errors}")
endif()
message(STATUS "status codes match: ${nf} STATUS_* codes of ${FORTRAN} = ${nc} INTERPHASE_STATUS_* of ${HEADER}")
