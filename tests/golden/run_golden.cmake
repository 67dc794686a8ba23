# Runs one golden case and compares its standard output, byte for byte, with the golden file
# (and, when GOLDEN_STDERR is given, its standard error with that file).
#
#   cmake -DPROGRAM=... -DARGC=3 -DARG0=a -DARG1=b -DARG2=c -DGOLDEN=file.out
#         [-DGOLDEN_STDERR=file.err] -DEXPECT_STATUS=0 -DWORKDIR=dir -P run_golden.cmake
#
# One definition an argument (not one list in -DARGS=): ctest's escaping of a semicolon
# list reaches this script as "a\;b\;c", which became a single argument.
#
# Lines "wall_time_ms: N" are the one thing that differs between runs; they are written as
# "wall_time_ms: (elided)" before comparing. With the environment variable
# MAZE_MAPPER_UPDATE_GOLDEN=1 the golden files are rewritten instead
# (scripts/refresh-goldens.sh); review `git diff tests/golden` after that.

cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED EXPECT_STATUS)
  set(EXPECT_STATUS 0)
endif()
if(NOT DEFINED ARGC)
  set(ARGC 0)
endif()

set(_command "${PROGRAM}")
if(ARGC GREATER 0)
  math(EXPR _last "${ARGC} - 1")
  foreach(_i RANGE ${_last})
    list(APPEND _command "${ARG${_i}}")
  endforeach()
endif()

execute_process(
  COMMAND ${_command}
  WORKING_DIRECTORY "${WORKDIR}"
  OUTPUT_VARIABLE _stdout
  ERROR_VARIABLE _stderr
  RESULT_VARIABLE _status)

string(REGEX REPLACE "wall_time_ms: [0-9.]+" "wall_time_ms: (elided)" _stdout "${_stdout}")

if(NOT "${_status}" STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${_status}, expected ${EXPECT_STATUS}\nstderr:\n${_stderr}")
endif()

# Rewrites `golden` with `text` (update mode), or fails with a diff when they differ.
function(compare_with_golden golden text)
  if("$ENV{MAZE_MAPPER_UPDATE_GOLDEN}" STREQUAL "1")
    file(WRITE "${golden}" "${text}")
    message(STATUS "updated ${golden}")
    return()
  endif()
  if(NOT EXISTS "${golden}")
    message(FATAL_ERROR "no golden file ${golden}; create it with scripts/refresh-goldens.sh")
  endif()
  file(READ "${golden}" _expected)
  if(NOT text STREQUAL _expected)
    set(_actual "${golden}.actual")
    file(WRITE "${_actual}" "${text}")
    execute_process(COMMAND diff -u "${golden}" "${_actual}" OUTPUT_VARIABLE _diff)
    file(REMOVE "${_actual}")
    message(FATAL_ERROR "output differs from ${golden}:\n${_diff}")
  endif()
endfunction()

compare_with_golden("${GOLDEN}" "${_stdout}")
if(DEFINED GOLDEN_STDERR)
  compare_with_golden("${GOLDEN_STDERR}" "${_stderr}")
endif()
