# script_command.cmake - for scripts run as `cmake [-D...] -P <script> <command> [args...]`:
# sets `cmd` to the list of every argument after the script's own path (the command to run).
# Empty when none was given; the including script reports that.
set(cmd "")
set(_sc_after_script OFF)
math(EXPR _sc_last "${CMAKE_ARGC} - 1")
foreach(_sc_i RANGE 1 ${_sc_last})
  if(_sc_after_script)
    list(APPEND cmd "${CMAKE_ARGV${_sc_i}}")
  elseif(CMAKE_ARGV${_sc_i} STREQUAL "-P")
    math(EXPR _sc_skip "${_sc_i} + 1")
  endif()
  if(DEFINED _sc_skip AND _sc_i EQUAL _sc_skip)
    set(_sc_after_script ON)
  endif()
endforeach()
