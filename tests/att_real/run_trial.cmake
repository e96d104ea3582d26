# run_trial.cmake - one real trial through imu_replay (defaults) and att_score, for
# tests/att_real. Writes <WORK>/att_<NAME>.score (att_score's key=value line) for
# att_real_overall and removes the estimate CSV afterwards.
#   cmake -DREPLAY=.. -DSCORE=.. -DINPUT=<trial.csv.gz> -DNAME=<id> -DWORK=<dir>
#         -DREQUIRE=<key<=v;...> -P run_trial.cmake
foreach(v REPLAY SCORE INPUT NAME WORK REQUIRE)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_trial.cmake: -D${v}= is required")
  endif()
endforeach()
set(est "${WORK}/att_${NAME}.csv")
set(score "${WORK}/att_${NAME}.score")
file(REMOVE "${score}")
execute_process(COMMAND "${REPLAY}" "${INPUT}" -o "${est}" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "imu_replay failed (${rc}):\n${err}")
endif()
string(REGEX MATCH "summary: [^\n]*" summary "${err}")
message(STATUS "${summary}")
set(args "")
foreach(r IN LISTS REQUIRE)
  list(APPEND args --require "${r}")
endforeach()
execute_process(COMMAND "${SCORE}" "${INPUT}" "${est}" --name "${NAME}" ${args}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(REMOVE "${est}")
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "att_score (${rc}): ${err}")
endif()
file(WRITE "${score}" "${out}")
