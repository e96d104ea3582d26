#!/bin/sh
# att_vehicle.sh - the attitude estimator on the vehicle scenarios (docs/vehicle-scenarios.md):
# each scenario from tools/vehicle_sim through imu_replay (the ADIS16405 part, estimator att) with
# and without vehicle aiding, scored by att_score; one markdown row per scenario and mode.
#   benches/att_vehicle/att_vehicle.sh BUILD_DIR [ACCEL_BIAS_MG] [SEED] [SCENARIO...]
# ACCEL_BIAS_MG: the part's residual accelerometer bias, 1 sigma (default 1: after end-of-line
# calibration; 5 is the simulator's factory-calibrated part). Writes into a temporary folder.
set -eu
build="${1:?usage: att_vehicle.sh BUILD_DIR [ACCEL_BIAS_MG] [SEED] [SCENARIO...]}"
bias="${2:-1}"
seed="${3:-1}"
shift $(( $# < 3 ? $# : 3 ))
scenarios="${*:-cornering braking acceleration lane_change banked_slope rough_road speed_bumps parking idle_slope drive_20min}"
sim="$build/tools/vehicle_sim/vehicle_sim"
replay="$build/tools/imu_replay/imu_replay"
score="$build/tools/att_score/att_score"
for t in "$sim" "$replay" "$score"; do
    [ -x "$t" ] || { echo "att_vehicle.sh: $t not built" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| scenario | aiding | roll RMS / max | pitch RMS / max | inclination RMS / max | valid | over bound | max err/bound | median bound |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|"
for sc in $scenarios; do
    "$sim" --scenario "$sc" --seed "$seed" --accel-bias-mg "$bias" --out "$tmp/in.csv" >/dev/null
    for aid in yes no; do
        opt=""
        [ "$aid" = no ] && opt="--no-aiding"
        # shellcheck disable=SC2086
        "$replay" --part adis16405 $opt "$tmp/in.csv" -o "$tmp/est.csv" 2>/dev/null
        "$score" "$tmp/in.csv" "$tmp/est.csv" --name "$sc" | awk -v aid="$aid" '{
            for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
            printf "| %s | %s | %.2f / %.2f | %.2f / %.2f | %.2f / %.2f | %.3f | %.5f | %.2f | %.2f |\n",
                v["name"], aid, v["roll_rms_deg"], v["roll_max_deg"], v["pitch_rms_deg"],
                v["pitch_max_deg"], v["rms_deg"], v["max_deg"], v["valid_frac"],
                v["over_bound_frac"], v["max_err_over_bound"], v["median_bound_deg"] }'
    done
done
