# tool_summary.cmake - check the summary line of an end-to-end tool (docs/tool-summary.md).
#
#   include(<root>/cmake/scripts/tool_summary.cmake)
#   tool_summary_check("<stdout of the tool>" "<expectations>" <context>)
#
# The tool's stdout must end with one line "summary: tool=<name> status=<...> key=value ...".
# Each expectation is "key=REGEX" (the key is present and its whole value matches REGEX) or
# "key!=REGEX" (the key is absent, or its value does not match REGEX); a list, ';'-separated.
# A failure stops the script (FATAL_ERROR) naming the key, the expectation and the line.
include_guard(GLOBAL)

# The summary line of `stdout`, or "" when its last non-empty line is not one.
function(tool_summary_line stdout out)
  string(REGEX REPLACE "[\r\n]+$" "" text "${stdout}")
  string(REGEX MATCH "[^\n]*$" last "${text}")
  if(last MATCHES "^summary: ")
    set(${out} "${last}" PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

# The value of `key` in a summary line, and whether it is there.
function(tool_summary_get line key value found)
  set(${found} FALSE PARENT_SCOPE)
  set(${value} "" PARENT_SCOPE)
  string(REGEX REPLACE "^summary: " "" rest "${line}")
  string(REPLACE " " ";" fields "${rest}")
  foreach(f IN LISTS fields)
    if(f MATCHES "^([a-z0-9_]+)=(.*)$")
      # string(COMPARE), not if(STREQUAL): in script mode a quoted key such as "status" would be
      # read as the name of a variable of the caller (policy CMP0054).
      string(COMPARE EQUAL "${CMAKE_MATCH_1}" "${key}" same)
      if(same)
        set(${value} "${CMAKE_MATCH_2}" PARENT_SCOPE)
        set(${found} TRUE PARENT_SCOPE)
      endif()
    endif()
  endforeach()
endfunction()

function(tool_summary_check stdout expectations context)
  tool_summary_line("${stdout}" line)
  if(line STREQUAL "")
    message(FATAL_ERROR "${context}: stdout does not end with a 'summary:' line:\n${stdout}")
  endif()
  foreach(e IN LISTS expectations)
    if(e MATCHES "^([a-z0-9_]+)!=(.*)$")
      tool_summary_get("${line}" "${CMAKE_MATCH_1}" v found)
      set(re "${CMAKE_MATCH_2}")
      if(found AND v MATCHES "^(${re})$")
        message(FATAL_ERROR "${context}: summary key ${CMAKE_MATCH_1}=${v} must not match /${re}/:\n${line}")
      endif()
    elseif(e MATCHES "^([a-z0-9_]+)=(.*)$")
      set(k "${CMAKE_MATCH_1}")
      set(re "${CMAKE_MATCH_2}")
      tool_summary_get("${line}" "${k}" v found)
      if(NOT found)
        message(FATAL_ERROR "${context}: summary key '${k}' missing:\n${line}")
      endif()
      if(NOT v MATCHES "^(${re})$")
        message(FATAL_ERROR "${context}: summary key ${k}=${v} does not match /${re}/:\n${line}")
      endif()
    else()
      message(FATAL_ERROR "tool_summary_check: bad expectation '${e}' (key=REGEX or key!=REGEX)")
    endif()
  endforeach()
  message(STATUS "${context}: ${line}")
endfunction()
