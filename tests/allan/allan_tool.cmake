# End-to-end run of the `allan` host tool: a simulated run with every output, a CSV run, and the
# exit codes for bad usage and bad input, judged on the tool's summary line
# (docs/tool-summary.md). Invoked by CTest with -DALLAN=<tool> -DWORKDIR=<dir>.
if(NOT ALLAN OR NOT WORKDIR)
  message(FATAL_ERROR "allan_tool.cmake: ALLAN and WORKDIR are required")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/../../cmake/scripts/tool_summary.cmake)
set(out ${WORKDIR}/allan_tool)
file(MAKE_DIRECTORY ${out})
file(REMOVE ${out}/curve.csv ${out}/plot.svg ${out}/plot.gp)

# 1. simulated ADIS gyro, 300 s: CSV, SVG and gnuplot outputs, read-offs printed.
execute_process(COMMAND ${ALLAN} --sim adis --seconds 300 --seed 5 --theory --quiet
                        --out ${out}/curve.csv --svg ${out}/plot.svg --gnuplot ${out}/plot.gp
                        --png ${out}/plot.png
                RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "simulated run failed (${rc}): ${so} ${se}")
endif()
set(num "[0-9.]+(e[-+][0-9]+)?")
tool_summary_check("${so}" "tool=allan;status=ok;unit=deg/s;arw=0[.]0[0-9]+;bias_instability=${num};model_adev_1s=${num};samples=245760" "simulated run")
foreach(f curve.csv plot.svg plot.gp)
  if(NOT EXISTS ${out}/${f})
    message(FATAL_ERROR "simulated run did not write ${f}")
  endif()
endforeach()
file(READ ${out}/curve.csv csv)
if(NOT csv MATCHES "^tau_s,adev,err,theory\n")
  message(FATAL_ERROR "curve.csv has no header")
endif()

# 2. the curve it wrote, read back as a CSV (tau column as data, no time column) must parse.
execute_process(COMMAND ${ALLAN} --csv ${out}/curve.csv --col 1 --rate-hz 1 --quiet
                        --min-rel-err 0.9
                RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "CSV run failed (${rc}): ${so} ${se}")
endif()
tool_summary_check("${so}" "status=ok;samples=[1-9][0-9]*;points=[1-9][0-9]*" "CSV run")

# 3. bad usage -> 1; malformed CSV -> 2 with the line number; missing file -> 2.
execute_process(COMMAND ${ALLAN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_QUIET)
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "no arguments: exit ${rc}, want 1")
endif()
tool_summary_check("${so}" "status=error;error=usage" "no arguments")
file(WRITE ${out}/bad.csv "t,x\n0,1\n1,2\n2,oops\n")
execute_process(COMMAND ${ALLAN} --csv ${out}/bad.csv --col 1 --time-col 0
                RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "malformed CSV: exit ${rc}, stderr '${se}'")
endif()
tool_summary_check("${so}" "status=error;error=ERR_FORMAT;line=4" "malformed CSV")
execute_process(COMMAND ${ALLAN} --csv ${out}/does-not-exist.csv --rate-hz 10
                RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_QUIET)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "missing file: exit ${rc}, want 2")
endif()
tool_summary_check("${so}" "status=error;error=cannot-open" "missing file")
