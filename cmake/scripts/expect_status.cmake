# expect_status.cmake - run a command and pass only if it exits with exactly EXPECT_STATUS.
#
#   cmake -DEXPECT_STATUS=<n> -P expect_status.cmake <command> [args...]
#
# CTest's WILL_FAIL accepts any non-zero status, so a test that must fail in one particular way
# (one failed check: status 1; a fault caught by the QEMU board: status 126) is run through this
# script. A crash, a hang (TIMEOUT_S, default 60 s) or any other status fails.
if(NOT DEFINED EXPECT_STATUS)
  message(FATAL_ERROR "expect_status.cmake: -DEXPECT_STATUS=<n> is required")
endif()
if(NOT DEFINED TIMEOUT_S)
  set(TIMEOUT_S 60)
endif()

# Everything after the script's own path is the command.
include(${CMAKE_CURRENT_LIST_DIR}/script_command.cmake)
if(cmd STREQUAL "") # not if(NOT cmd): a command named "false", "off", "0"... reads as false
  message(FATAL_ERROR "expect_status.cmake: no command given")
endif()

execute_process(COMMAND ${cmd} RESULT_VARIABLE status TIMEOUT ${TIMEOUT_S})
if(NOT "${status}" STREQUAL "${EXPECT_STATUS}")
  message(FATAL_ERROR "expected exit status ${EXPECT_STATUS}, got '${status}' from: ${cmd}")
endif()
message(STATUS "exit status ${status}, as expected")
