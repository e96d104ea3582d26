# End-to-end run of the vehicle_sim tool: the list, a short run at each rate with the CSV header
# and summary line, and the exit status for bad arguments (1) and write errors (2).
# Invoked by CTest with -DTOOL=<vehicle_sim> -DWORKDIR=<dir>.
if(NOT TOOL OR NOT WORKDIR)
  message(FATAL_ERROR "vehicle_sim_tool.cmake: TOOL and WORKDIR are required")
endif()
set(out ${WORKDIR}/vehicle_sim_tool)
file(MAKE_DIRECTORY ${out})

function(run want)
  execute_process(COMMAND ${TOOL} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE so ERROR_VARIABLE se)
  if(NOT "${rc}" STREQUAL "${want}")
    message(FATAL_ERROR "vehicle_sim ${ARGN}: exit '${rc}', want ${want}\n${so}${se}")
  endif()
  set(so "${so}" PARENT_SCOPE)
  set(se "${se}" PARENT_SCOPE)
endfunction()

# 1. the list names every preset
run(0 --scenario list)
foreach(name cornering braking acceleration lane_change banked_slope rough_road speed_bumps
             parking idle_slope drive_20min)
  if(NOT so MATCHES "${name} ")
    message(FATAL_ERROR "list: no ${name} in:\n${so}")
  endif()
endforeach()

# 2. short runs: header, rows, summary line
run(0 --scenario braking --duration 2 --seed 7 --out ${out}/b.csv)
if(NOT so MATCHES "^scenario=braking samples=1639 duration_s=2\\.001 max_lat_g=[0-9.]+ max_lon_g=[0-9.]+ max_roll_deg=[0-9.]+ max_pitch_deg=[0-9.]+\n$")
  message(FATAL_ERROR "summary line: '${so}'")
endif()
file(STRINGS ${out}/b.csv lines)
list(LENGTH lines n)
list(GET lines 0 head)
if(NOT n EQUAL 1640 OR NOT head STREQUAL "t_s,gyr_x_dps,gyr_y_dps,gyr_z_dps,acc_x_g,acc_y_g,acc_z_g,truth_qw,truth_qx,truth_qy,truth_qz,movement,speed_mps,yaw_rate_dps,temp_c")
  message(FATAL_ERROR "b.csv: ${n} lines, header '${head}'")
endif()
list(GET lines 1 row)
string(REPEAT "-?[0-9]+\\.[0-9]+," 10 ten) # CMake regular expressions have no {n}
if(NOT row MATCHES "^0\\.000000,${ten}0,0\\.0000,-?[0-9.]+,[0-9.]+$")
  message(FATAL_ERROR "b.csv first row: '${row}'")
endif()
# the same seed writes the same file; the low rate and a misalignment work
run(0 --scenario braking --duration 2 --seed 7 --out ${out}/b2.csv)
file(SHA256 ${out}/b.csv h1)
file(SHA256 ${out}/b2.csv h2)
if(NOT h1 STREQUAL h2)
  message(FATAL_ERROR "the same seed wrote two different files")
endif()
run(0 --scenario parking --rate 285.714 --duration 1.5 --mount-deg 0.5,-1,2 --ideal --out ${out}/p.csv)
if(NOT so MATCHES "samples=429 ")
  message(FATAL_ERROR "285.714 Hz: '${so}'")
endif()

# 3. bad arguments: exit 1 with a message naming the option
foreach(bad "--rate;abc" "--rate;819.2x" "--rate;;" "--rate; 819.2" "--rate;0" "--rate;1e6"
            "--rate;nan" "--rate;inf" "--seed;-1" "--seed;1.5" "--seed;99999999999999999999"
            "--seed;0x10" "--duration;0" "--duration;-3" "--duration;1e9" "--mount-deg;1,2"
            "--mount-deg;1,2,3,4" "--mount-deg;1,,3" "--mount-deg;11,0,0" "--scenario;nope"
            "--frobnicate;1" "--rate" "--out;")
  if(bad MATCHES "^--scenario")
    run(1 ${bad})
  else()
    run(1 --scenario braking ${bad})
  endif()
  if(NOT se MATCHES "vehicle_sim: ")
    message(FATAL_ERROR "'${bad}': no message: '${se}'")
  endif()
endforeach()
run(1)
if(NOT se MATCHES "usage: vehicle_sim")
  message(FATAL_ERROR "no arguments: no usage: '${se}'")
endif()

# 4. write errors: exit 2
run(2 --scenario braking --duration 1 --out ${out}/no/such/dir/x.csv)
if(EXISTS /dev/full)
  # a device is refused before anything is written (tools/lib/cli's safe writer)
  run(2 --scenario braking --duration 1 --out /dev/full)
  if(NOT se MATCHES "is a character device; refusing")
    message(FATAL_ERROR "/dev/full: '${se}'")
  endif()
endif()
message(STATUS "vehicle_sim: every case as expected")
