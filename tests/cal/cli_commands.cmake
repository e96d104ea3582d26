# The calstation commands end to end (run by CTest, host only):
#   cmake -DTOOL=<calstation> -DWORKDIR=<dir> -P cli_commands.cmake
# A hand-placed six-face session simulated as a sample CSV in m/s^2 (2 deg placement errors):
# fit (no record without --out; the coefficients printed), fit --out, show, apply (the firmware
# on every sample) with the face-mean residual asserted against the per-axis pair method; and
# every bad argument and output: strict numbers, placeholder temperatures, a directory as a
# record, outputs that are an input, a symlink, or a full device (/dev/full).
if(NOT TOOL OR NOT WORKDIR)
  message(FATAL_ERROR "TOOL and WORKDIR are required")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/calstation_run.cmake)
file(REMOVE_RECURSE ${WORKDIR})
file(MAKE_DIRECTORY ${WORKDIR})
set(W ${WORKDIR})

# The value of key in the summary line of out.
function(key_of out key var)
  string(REGEX MATCH "summary: [^\n]*" line "${out}")
  string(REGEX MATCH " ${key}=([^ \n]*)" m "${line}")
  set(${var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

# ---- the hand-placed session ----
run(simulate 0 "status=ok;samples=[0-9]+" simulate --schedule hand --placement-deg 2
    --placement-seed 3 --noise-seed 3 --samples 1024 --rate 102.4 --format samples-notemp
    --units m/s2 --out ${W}/hand.csv)
run(fit_no_out 0 "status=ok;command=fit;input=samples;units=m/s2;g=9.80665;fit=magnitude;tmodel=none;faces=6;gyro=not-calibrated;record=none;warnings=[1-9]"
    fit ${W}/hand.csv --units m/s2)
if(NOT out MATCHES "acc x: offset" OR NOT out MATCHES "gyro: not calibrated")
  message(SEND_ERROR "fit does not print the coefficients / the gyro state\n${out}")
endif()
if(EXISTS ${W}/hand.bin)
  message(SEND_ERROR "fit without --out wrote a record")
endif()
run(fit 0 "status=ok;fit=magnitude;record_bytes=656;format=2" fit ${W}/hand.csv --units m/s2 --out ${W}/hand.bin)
key_of("${out}" face_rms_mg fit_face)
key_of("${out}" face_max_mg fit_max)
key_of("${out}" pair_face_rms_mg pair_face)
key_of("${out}" face_rms_before_mg before)
message(STATUS "hand-placed, 2 deg: face-mean rms ${fit_face} mg, max ${fit_max} mg (before ${before}, per-axis pair ${pair_face})")
if(NOT fit_max LESS_EQUAL 0.05 OR NOT fit_face LESS_EQUAL pair_face OR NOT before GREATER 10)
  message(SEND_ERROR "face-mean residual ${fit_face} / ${fit_max} mg (limit 0.05, pair ${pair_face}, before ${before})")
endif()
run(show 0 "status=ok;command=show;format=2;family=4;product=1;gyro=not-calibrated;tmodel=none" show ${W}/hand.bin)
run(apply 0 "status=ok;command=apply;units=m/s2;faces=6;range=0" apply ${W}/hand.bin ${W}/hand.csv -o ${W}/hand_out.csv --units m/s2)
key_of("${out}" face_max_mg apply_max)
if(NOT apply_max LESS_EQUAL 0.05)
  message(SEND_ERROR "apply: face-mean max ${apply_max} mg")
endif()
file(STRINGS ${W}/hand.csv in_lines)
file(STRINGS ${W}/hand_out.csv out_lines)
list(LENGTH in_lines n_in)
list(LENGTH out_lines n_out)
if(NOT n_in EQUAL n_out)
  message(SEND_ERROR "apply: ${n_out} lines written for ${n_in}")
endif()
# Applying the output again through a record of the identity is not needed: the fit on the
# corrected samples must find them calibrated (placement-free residual ~0 before).
run(refit 0 "status=ok" fit ${W}/hand_out.csv --units m/s2)
key_of("${out}" face_rms_before_mg again)
if(NOT again LESS_EQUAL 0.05)
  message(SEND_ERROR "the corrected samples still miss 1 g by ${again} mg")
endif()
# The same session in g: the same residuals (units only change the scale).
run(simulate_g 0 "status=ok" simulate --schedule hand --placement-deg 2 --placement-seed 3
    --noise-seed 3 --samples 1024 --rate 102.4 --format samples --out ${W}/hand_g.csv)
run(fit_g 0 "status=ok;units=g;fit=magnitude" fit ${W}/hand_g.csv)
key_of("${out}" face_max_mg g_max)
if(NOT g_max LESS_EQUAL 0.05)
  message(SEND_ERROR "in g: face-mean max ${g_max} mg")
endif()
run(fit_g_local 0 "status=ok;units=m/s2;g=9.81" fit ${W}/hand.csv --units m/s2 --g 9.81)

# ---- bad arguments: exit 2, nothing written ----
run(cycles_octal 2 "status=error;error=usage;problem=bad-argument;option=cycles" simulate --cycles 010 --out ${W}/x.csv)
run(seed_negative 2 "status=error;problem=bad-argument;option=noise-seed" simulate --noise-seed -1 --out ${W}/x.csv)
run(seed_overflow 2 "status=error;problem=bad-argument;option=noise-seed" simulate --noise-seed 18446744073709551616 --out ${W}/x.csv)
run(part_seed_sign 2 "status=error;problem=bad-argument;option=part" simulate --part +5 --out ${W}/x.csv)
run(units_bad 2 "status=error;problem=bad-argument;option=units" fit ${W}/hand.csv --units furlong)
run(g_bad 2 "status=error;problem=bad-argument;option=g" fit ${W}/hand.csv --units m/s2 --g 0)
run(g_nan 2 "status=error;problem=bad-argument;option=g" fit ${W}/hand.csv --units m/s2 --g nan)
run(seq_bad 2 "status=error;problem=bad-argument;option=seq" fit ${W}/hand.csv --seq 4294967296)
run(fit_method_bad 2 "status=error;problem=bad-argument;option=fit" fit ${W}/hand.csv --fit best)
if(EXISTS ${W}/x.csv)
  message(SEND_ERROR "a refused simulate wrote its output")
endif()

# ---- bad inputs: exit 1 ----
run(show_dir 1 "status=error;error=ERR_IO;problem=cannot-open" show ${W})
run(show_csv 1 "status=error;error=ERR_[A-Z]+;problem=record-refused" show ${W}/hand.csv)
file(WRITE ${W}/short.bin "ICAL")
run(show_short 1 "status=error;error=ERR_FORMAT;problem=not-a-record" show ${W}/short.bin)
run(apply_dir 1 "status=error;error=ERR_IO;problem=cannot-open" apply ${W}/hand.bin ${W} -o ${W}/o.csv)
# Without --units, samples that read 9.8 at rest are taken as m/s^2 (said); --units g refuses.
run(fit_detect_units 0 "status=ok;units=m/s2;units_detected=1;fit=magnitude" fit ${W}/hand.csv)
key_of("${out}" face_max_mg det_max)
if(NOT det_max LESS_EQUAL 0.05)
  message(SEND_ERROR "units detected: face-mean max ${det_max} mg")
endif()
run(fit_wrong_units 1 "status=error" fit ${W}/hand.csv --units g)
file(WRITE ${W}/noacc.csv "t,foo,bar\n0,1,2\n")
run(no_acc 1 "status=error;error=ERR_FORMAT;problem=no-acc-column" fit ${W}/noacc.csv)

# ---- outputs ----
# An input is never the output.
file(SHA256 ${W}/hand.csv h0)
run(out_is_input 1 "status=error;error=ERR_IO;problem=cannot-write" apply ${W}/hand.bin ${W}/hand.csv -o ${W}/hand.csv --units m/s2)
file(SHA256 ${W}/hand.csv h1)
if(NOT h0 STREQUAL h1)
  message(SEND_ERROR "apply -o IN changed its input")
endif()
run(record_is_output 1 "status=error;problem=cannot-write" apply ${W}/hand.bin ${W}/hand.csv -o ${W}/hand.bin --units m/s2)
# A symlink stays a symlink; its target gets the data.
file(WRITE ${W}/target.csv "old\n")
file(CREATE_LINK ${W}/target.csv ${W}/link.csv SYMBOLIC)
run(out_symlink 0 "status=ok" apply ${W}/hand.bin ${W}/hand.csv -o ${W}/link.csv --units m/s2)
if(NOT IS_SYMLINK ${W}/link.csv)
  message(SEND_ERROR "the output symlink was replaced")
endif()
file(SIZE ${W}/target.csv tsize)
if(tsize LESS 1000)
  message(SEND_ERROR "the symlink's target was not written (${tsize} bytes)")
endif()
# A full device: the write error is reported, exit 1 (the device is written in place, never
# replaced).
if(EXISTS /dev/full)
  run(apply_full 1 "status=error;error=ERR_IO;problem=cannot-write" apply ${W}/hand.bin ${W}/hand.csv -o /dev/full --units m/s2)
  run(fit_full 1 "status=error;error=ERR_IO;problem=cannot-write" fit ${W}/hand.csv --units m/s2 --out /dev/full)
  run(simulate_full 1 "status=error;error=ERR_IO;problem=cannot-write" simulate --schedule hand --out /dev/full)
  if(NOT EXISTS /dev/full)
    message(SEND_ERROR "/dev/full is gone")
  endif()
else()
  message(SEND_ERROR "/dev/full is missing: the full-disk case cannot run")
endif()
# A directory as the output.
run(out_dir 1 "status=error;problem=cannot-write" apply ${W}/hand.bin ${W}/hand.csv -o ${W} --units m/s2)
# No temporary file is left behind by any refusal.
file(GLOB leftovers ${W}/*.tmp-*)
if(leftovers)
  message(SEND_ERROR "temporary files left: ${leftovers}")
endif()
