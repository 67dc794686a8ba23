# Runs one golden case and compares its standard output, byte for byte, with the golden file.
#
#   cmake -DPROGRAM=... -DARGS="a;b;c" -DGOLDEN=file.out -DEXPECT_STATUS=0 -DWORKDIR=dir
#         -P run_golden.cmake
#
# When golden/NAME.err exists (written by the refresh when the program printed anything on
# stderr), standard error is compared with it too: that is how error messages are pinned.
#
# Lines "wall_time_ms: N" are the one thing that differs between runs; they are written as
# "wall_time_ms: (elided)" before comparing. With the environment variable
# MAZE_MAPPER_UPDATE_GOLDEN=1 the golden file is rewritten instead (scripts/refresh-goldens.sh);
# review `git diff tests/golden` after that.

cmake_minimum_required(VERSION 3.25)

if(NOT DEFINED EXPECT_STATUS)
  set(EXPECT_STATUS 0)
endif()
string(RANDOM LENGTH 8 _tag)
# add_golden_test passes the arguments as one list with its ';' escaped; make it a list again.
string(REPLACE "\\;" ";" ARGS "${ARGS}")
set(_actual "${GOLDEN}.actual")
string(REGEX REPLACE "\\.out$" ".err" _golden_err "${GOLDEN}")

execute_process(
  COMMAND ${PROGRAM} ${ARGS}
  WORKING_DIRECTORY "${WORKDIR}"
  OUTPUT_VARIABLE _stdout
  ERROR_VARIABLE _stderr
  RESULT_VARIABLE _status)

string(REGEX REPLACE "wall_time_ms: [0-9.]+" "wall_time_ms: (elided)" _stdout "${_stdout}")

if(NOT "${_status}" STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "exit status ${_status}, expected ${EXPECT_STATUS}\nstderr:\n${_stderr}")
endif()

if("$ENV{MAZE_MAPPER_UPDATE_GOLDEN}" STREQUAL "1")
  file(WRITE "${GOLDEN}" "${_stdout}")
  message(STATUS "updated ${GOLDEN}")
  if(NOT "${_stderr}" STREQUAL "")
    file(WRITE "${_golden_err}" "${_stderr}")
    message(STATUS "updated ${_golden_err}")
  endif()
  return()
endif()

if(NOT EXISTS "${GOLDEN}")
  message(FATAL_ERROR "no golden file ${GOLDEN}; create it with scripts/refresh-goldens.sh")
endif()

file(READ "${GOLDEN}" _expected)
if(NOT _stdout STREQUAL _expected)
  file(WRITE "${_actual}" "${_stdout}")
  execute_process(COMMAND diff -u "${GOLDEN}" "${_actual}" OUTPUT_VARIABLE _diff)
  file(REMOVE "${_actual}")
  message(FATAL_ERROR "output differs from ${GOLDEN}:\n${_diff}")
endif()

if(EXISTS "${_golden_err}")
  file(READ "${_golden_err}" _expected_err)
  if(NOT _stderr STREQUAL _expected_err)
    message(FATAL_ERROR "standard error differs from ${_golden_err}:\nexpected: ${_expected_err}\nactual:   ${_stderr}")
  endif()
endif()
