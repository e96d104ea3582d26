# Test data from outside the repository: the BROAD trials (docs/data.md). Included from
# cmake/inclino.cmake.
#
# INCLINO_BROAD_DIR, the directory holding <trial>.csv.gz for every trial in
# tools/broad/CSV-SHA256SUMS, is the first of:
#   1. the cache variable INCLINO_BROAD_DIR (-DINCLINO_BROAD_DIR=<dir>), if not empty;
#   2. the environment variable INCLINO_BROAD_DIR at configure time, if not empty;
#   3. ${INCLINO_ROOT}/../shared/data/broad-dev, if it exists (developer machines and CI, where
#      the repository sits beside shared/);
#   4. empty.
# Give an absolute path; a relative one in the environment is taken relative to the repository
# root (a relative -D value CMake makes relative to the current directory).
#
#   inclino_require_broad(<test> [<test>...])
#       for tests that read the trials. Sets INCLINO_BROAD_OK in the caller's scope: TRUE when
#       INCLINO_BROAD_DIR holds every trial file, and the caller then adds its tests; FALSE
#       otherwise, and then each <test> is added here as a test that fails with the one step
#       that gets the data (tools/broad/fetch-broad.sh <dir>, then -DINCLINO_BROAD_DIR=<dir>).
#       Missing data never skips a test. Only the presence of the files is checked here; the
#       test broad_data (tests/broad) checks their content against the committed hashes.
#
# Also set: INCLINO_BROAD_TRIALS (the trial names), INCLINO_BROAD_SUMS (that list's path),
# INCLINO_BROAD_MISSING (the files not found), INCLINO_BROAD_HOWTO (the instruction, one line).

include_guard(GLOBAL)

string(REGEX REPLACE "/+$" "" _inclino_root "${INCLINO_ROOT}")

set(INCLINO_BROAD_DIR "" CACHE PATH
  "Directory of the BROAD trials <trial>.csv.gz (tools/broad/fetch-broad.sh; docs/data.md)")
set(INCLINO_BROAD_SUMS "${_inclino_root}/tools/broad/CSV-SHA256SUMS")
set(INCLINO_BROAD_FETCH "${_inclino_root}/tools/broad/fetch-broad.sh")

function(_inclino_broad_resolve)
  set(dir "$CACHE{INCLINO_BROAD_DIR}")
  set(from "-DINCLINO_BROAD_DIR")
  if(dir STREQUAL "" AND NOT "$ENV{INCLINO_BROAD_DIR}" STREQUAL "")
    set(dir "$ENV{INCLINO_BROAD_DIR}")
    set(from "the environment variable INCLINO_BROAD_DIR")
  endif()
  if(dir STREQUAL "" AND IS_DIRECTORY "${_inclino_root}/../shared/data/broad-dev")
    set(dir "${_inclino_root}/../shared/data/broad-dev")
    set(from "the default ../shared/data/broad-dev")
  endif()
  if(NOT dir STREQUAL "")
    cmake_path(ABSOLUTE_PATH dir BASE_DIRECTORY "${_inclino_root}" NORMALIZE)
  else()
    set(from "nothing (no -DINCLINO_BROAD_DIR, no environment variable, no ../shared/data/broad-dev)")
  endif()

  # The trials are the entries of the committed list of CSV hashes.
  file(STRINGS "${INCLINO_BROAD_SUMS}" lines REGEX "^[0-9a-f]+  .+\\.csv$")
  set(trials "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[0-9a-f]+  (.+)\\.csv$" "\\1" trial "${line}")
    list(APPEND trials "${trial}")
  endforeach()
  list(LENGTH trials n)
  if(n EQUAL 0)
    message(FATAL_ERROR "${INCLINO_BROAD_SUMS} lists no trial")
  endif()

  set(missing "")
  foreach(trial IN LISTS trials)
    if(dir STREQUAL "" OR NOT EXISTS "${dir}/${trial}.csv.gz")
      list(APPEND missing "${trial}.csv.gz")
    endif()
  endforeach()

  set(INCLINO_BROAD_DIR "${dir}" PARENT_SCOPE)
  set(INCLINO_BROAD_TRIALS "${trials}" PARENT_SCOPE)
  set(INCLINO_BROAD_MISSING "${missing}" PARENT_SCOPE)
  set(_INCLINO_BROAD_FROM "${from}" PARENT_SCOPE)
endfunction()

_inclino_broad_resolve()

# The instruction, one line (it is passed on a command line).
if(INCLINO_BROAD_DIR STREQUAL "")
  set(_inclino_broad_where "no BROAD data directory found")
  set(_inclino_broad_dest "<dir>")
else()
  list(LENGTH INCLINO_BROAD_MISSING _n)
  list(JOIN INCLINO_BROAD_MISSING ", " _m)
  set(_inclino_broad_where "${INCLINO_BROAD_DIR} (from ${_INCLINO_BROAD_FROM}) lacks ${_n} BROAD file(s): ${_m}")
  set(_inclino_broad_dest "${INCLINO_BROAD_DIR}")
endif()
string(CONCAT INCLINO_BROAD_HOWTO
  "Get the data with one step: ${INCLINO_BROAD_FETCH} ${_inclino_broad_dest} "
  "(downloads github.com/dlaidig/broad at commit 7e2f818, checks every file's SHA-256, converts), "
  "then configure with -DINCLINO_BROAD_DIR=${_inclino_broad_dest} "
  "(or export INCLINO_BROAD_DIR before configuring). See docs/data.md.")

if(INCLINO_BROAD_MISSING)
  message(STATUS "BROAD data: ${_inclino_broad_where}; the tests that read it will fail. ${INCLINO_BROAD_HOWTO}")
else()
  message(STATUS "BROAD data: ${INCLINO_BROAD_DIR} (from ${_INCLINO_BROAD_FROM})")
endif()

function(inclino_require_broad)
  if(NOT ARGN)
    message(FATAL_ERROR "inclino_require_broad: name the test(s) that need the data")
  endif()
  if(NOT INCLINO_BROAD_MISSING)
    set(INCLINO_BROAD_OK TRUE PARENT_SCOPE)
    return()
  endif()
  set(INCLINO_BROAD_OK FALSE PARENT_SCOPE)
  foreach(name IN LISTS ARGN)
    add_test(NAME ${name}
      COMMAND ${CMAKE_COMMAND} "-DMESSAGE=${name}: ${_inclino_broad_where}. ${INCLINO_BROAD_HOWTO}"
        -P ${_inclino_root}/cmake/scripts/fail_with_message.cmake)
    set_tests_properties(${name} PROPERTIES LABELS "${INCLINO_TARGET};broad" TIMEOUT 60)
  endforeach()
endfunction()
