# run_demo.cmake - run the EPB demo (or any tool) and judge its exit status and output.
#
#   cmake -DEXPECT_STATUS=<n> [-DKEYS=<key=re~key!=re...>] [-DMATCH=<re~re...>]
#         [-DNOMATCH=<re~...>] [-DVCD=<file> -DVCD2TRACE=<exe> -DMIN_BURSTS=<n>]
#         -P run_demo.cmake <command> [args...]
#
# Passes only when the command exits with exactly EXPECT_STATUS, its summary line meets every
# KEYS expectation (cmake/scripts/tool_summary.cmake, docs/tool-summary.md), every MATCH regular
# expression is found in its output (standard output and error) and no NOMATCH one is. With VCD: the VCD
# the command wrote is decoded by vcd2trace (mode 3, 16-bit frames on cs0) and must hold at
# least MIN_BURSTS ADIS burst reads (MOSI 3E00 followed by the output words).
if(NOT DEFINED EXPECT_STATUS)
  message(FATAL_ERROR "run_demo.cmake: -DEXPECT_STATUS=<n> is required")
endif()
string(REPLACE "~" ";" MATCH "${MATCH}")
string(REPLACE "~" ";" NOMATCH "${NOMATCH}")
string(REPLACE "~" ";" KEYS "${KEYS}")
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/scripts/script_command.cmake)
if(cmd STREQUAL "") # not if(NOT cmd): a command named "false", "off", "0"... reads as false
  message(FATAL_ERROR "run_demo.cmake: no command given")
endif()
execute_process(COMMAND ${cmd} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 300)
set(stdout "${out}")
set(out "${out}${err}") # MATCH / NOMATCH look at both streams
message("${out}")
if(NOT "${status}" STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "expected exit status ${EXPECT_STATUS}, got '${status}'")
endif()
if(KEYS)
  include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/scripts/tool_summary.cmake)
  tool_summary_check("${stdout}" "${KEYS}" "summary")
endif()
foreach(re IN LISTS MATCH)
  if(NOT out MATCHES "${re}")
    message(FATAL_ERROR "the output does not contain /${re}/")
  endif()
endforeach()
foreach(re IN LISTS NOMATCH)
  if(out MATCHES "${re}")
    message(FATAL_ERROR "the output contains /${re}/")
  endif()
endforeach()
if(DEFINED VCD)
  set(trace "${VCD}.trace")
  execute_process(COMMAND "${VCD2TRACE}" "${VCD}" "${trace}" RESULT_VARIABLE st2 OUTPUT_VARIABLE o2
                  ERROR_VARIABLE e2)
  if(NOT st2 EQUAL 0)
    message(FATAL_ERROR "vcd2trace failed on ${VCD}: ${e2}")
  endif()
  include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/scripts/tool_summary.cmake)
  tool_summary_check("${o2}" "tool=vcd2trace;status=ok;frames=[1-9][0-9]*;mode=3;bits=16" "vcd2trace")
  file(STRINGS "${trace}" bursts REGEX "mosi=3E00,0000")
  list(LENGTH bursts n)
  if(n LESS MIN_BURSTS)
    message(FATAL_ERROR "the VCD decodes to ${n} burst reads, expected at least ${MIN_BURSTS}")
  endif()
  message(STATUS "VCD: ${n} burst reads decoded")
endif()
message(STATUS "exit status ${status}, output as expected")
