# run_layering.cmake - configure the layering test project (tests/build/layering) with one CASE
# and check the outcome: EXPECT "ok" (configure succeeds) or a regular expression the failing
# configure's output must match.
#   cmake -DCASE=up -DEXPECT=<regex|ok> -DROOT=<repo> -DWORK=<dir> -P run_layering.cmake
foreach(v CASE EXPECT ROOT WORK)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_layering.cmake: -D${v}= is required")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${ROOT}/tests/build/layering -B ${WORK} -DCASE=${CASE}
          -DINCLINO_ROOT=${ROOT}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \t\r\n]+" " " text "${out} ${err}")
if(EXPECT STREQUAL "ok")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "case ${CASE}: configure failed but should pass:\n${err}")
  endif()
  message(STATUS "case ${CASE}: configured, as expected")
else()
  if(rc EQUAL 0)
    message(FATAL_ERROR "case ${CASE}: configure passed but must fail matching '${EXPECT}'")
  endif()
  if(NOT text MATCHES "${EXPECT}")
    message(FATAL_ERROR "case ${CASE}: configure failed, but its message does not match "
      "'${EXPECT}':\n${err}")
  endif()
  message(STATUS "case ${CASE}: refused with the expected message")
endif()
