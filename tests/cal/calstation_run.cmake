# calstation_run.cmake - run calstation from a CTest script and check its exit status and
# summary (docs/tool-summary.md); included by the scripts that drive the tool.
#   run(<name> <expected status> <summary expectations> args...)
# TOOL is the calstation binary; `out` receives the tool's stdout in the caller's scope.
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/scripts/tool_summary.cmake)

function(run name status keys)
  execute_process(COMMAND ${TOOL} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc STREQUAL "${status}")
    message(SEND_ERROR "${name}: exit status ${rc}, expected ${status}\n${out}${err}")
  endif()
  tool_summary_check("${out}" "tool=calstation;${keys}" "${name}")
  set(out "${out}" PARENT_SCOPE)
endfunction()
