# run_libfuzzer.cmake - one bounded libFuzzer run of a target (CTest libfuzzer_<name>,
# cmake/inclino_fuzz.cmake; docs/fuzzing.md).
#
#   cmake -DFUZZER=<lf_x> -DCORPUS=<tests/fuzz/corpus/x> -DWORK=<dir> -DRUNS=<n> -DMAX_LEN=<n>
#         [-DDICT=<file>] -P run_libfuzzer.cmake
#
# New inputs go to a scratch corpus WORK/new (emptied first, so every run starts from the kept
# corpus alone and costs the same); crash, leak and timeout files to WORK/artifacts. Fails
# unless libFuzzer exits 0 having done its RUNS executions, with no sanitizer or libFuzzer error
# report in its output.
foreach(v FUZZER CORPUS WORK RUNS MAX_LEN)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_libfuzzer.cmake: -D${v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK}/new ${WORK}/artifacts)
file(MAKE_DIRECTORY ${WORK}/new ${WORK}/artifacts)
set(args -runs=${RUNS} -seed=1 -max_len=${MAX_LEN} -timeout=10 -rss_limit_mb=2048
         -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/)
if(DICT)
  list(APPEND args -dict=${DICT})
endif()
execute_process(COMMAND ${FUZZER} ${args} ${WORK}/new ${CORPUS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se TIMEOUT 280)
set(all "${so}${se}")
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" execs "${all}")
string(REGEX MATCH "cov: [0-9]+ ft: [0-9]+" cov "${all}")
file(GLOB artifacts ${WORK}/artifacts/*)
if(NOT rc EQUAL 0 OR all MATCHES "ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|libFuzzer)"
   OR all MATCHES "runtime error:" OR artifacts)
  string(LENGTH "${all}" len)
  if(len GREATER 6000)
    math(EXPR from "${len} - 6000")
    string(SUBSTRING "${all}" ${from} 6000 all)
  endif()
  message(FATAL_ERROR "libFuzzer run failed (exit ${rc}; artifacts: ${artifacts}); reproduce with\n"
    "  ${FUZZER} <artifact>\n${all}")
endif()
if(NOT execs MATCHES "${RUNS}$")
  message(FATAL_ERROR "libFuzzer did not do ${RUNS} executions (${execs}):\n${all}")
endif()
message(STATUS "${FUZZER}: ${execs}, ${cov}, no crash")
