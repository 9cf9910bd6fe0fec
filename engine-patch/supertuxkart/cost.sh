#!/usr/bin/env bash
# What the plugin's own passes cost in SuperTuxKart, against the bytes they must move: each track at
# SIZE with particles on (forward passes), METHODS with measure_pass_floors (each pass beside a floor pass
# of its shape, timed in the same run) and TIMED timed frames, and `resolve` and `edge` without the floors,
# then scored against STK's own render at 4x the size. Writes OUT/<track>/report.md (quality, wall and own
# passes against off, the floors table) and OUT/cost.md (the targets of docs/results.md#what-the-passes-cost,
# met or not, per track).
#   usage: cost.sh STK_BINARY RETROAA OUT [SIZE] [TIMED] [TRACK...]
set -euo pipefail
binary=$1 retroaa=$2 out=$3
size=${4:-320x240} timed=${5:-10}
shift $(($# < 5 ? $# : 5))
tracks=("$@")
[ ${#tracks[@]} -gt 0 ] || tracks=(cornfield_crossing olivermath black_forest)
here=$(cd "$(dirname "$0")" && pwd)
width=${size%x*} height=${size#*x}
# `resolve` and `edge` as a player runs them give the walls: a floor's replay adds its own time to the
# frame, and `resolve` is the host's multisampled geometry with one pass of ours.
methods="off resolve edge edge@measure_pass_floors=on per-sample@measure_pass_floors=on aggregate@measure_pass_floors=on"
mkdir -p "$out"
for track in "${tracks[@]}"; do
  bash "$here/capture.sh" "$binary" "$track" "$size" 40 "$methods" "$out/$track" "$timed" --particles
  bash "$here/capture.sh" "$binary" "$track" "$((width * 4))x$((height * 4))" 40 off "$out/$track/reference" 1 --particles
  "$retroaa" score "$out/$track" --reference "$out/$track/reference/off.png" --factor 4 >/dev/null  # report.md, .json
done
python3 "$here/cost_targets.py" "$out" "${tracks[@]}" | tee "$out/cost.md"
