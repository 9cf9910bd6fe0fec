#!/usr/bin/env bash
# A race in motion, per method: STK's AI drives the kart (its profile mode) with each method active from
# the start, one STK process a method, and frames FRAME-K+1 .. FRAME written; the same frames at 4x width
# and height are the reference. `off` runs twice: the fixed step and the fixed item seeds must make the two
# runs byte-identical. Then `retroaa score` over the frames (its extra arguments after OUT: crops, regions).
#   usage: race.sh STK_BINARY RETROAA TRACK WIDTHxHEIGHT FRAME K "METHODS" OUT [--karts=N] [score options...]
# --karts=N: N karts, the player's and N-1 AI opponents (default 1).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=$1 retroaa=$2 track=$3 size=$4 frame=$5 frames=$6 methods=$7 out=$8
shift 8
karts=()
case ${1:-} in --karts=*) karts=("$1"); shift ;; esac
width=${size%x*} height=${size#*x}
rm -rf "$out"
mkdir -p "$out/runs"
: >"$out/capture.jsonl"
capture() {  # METHOD FOLDER
  bash "$here/capture.sh" "$binary" "$track" "$size" "$frame" "$1" "$out/runs/$2" --race="$frames" "${karts[@]}" >/dev/null
}
for method in off $(echo " $methods " | sed 's/ off / /g'); do
  run=$(echo "$method" | tr '/@=' '___')
  capture "$method" "$run"
  sed "s|\"image\": \"|\"image\": \"runs/$run/|" "$out/runs/$run/capture.jsonl" >>"$out/capture.jsonl"
done
capture off off.again
for png in "$out"/runs/off/*.png; do
  cmp -s "$png" "$out/runs/off.again/$(basename "$png")" ||
    { echo "race: two runs of off differ at $(basename "$png"): the race is not reproducible" >&2; exit 1; }
done
echo "race: two runs of off are byte-identical ($(ls "$out"/runs/off/off.*.png | wc -l) frames)"
bash "$here/capture.sh" "$binary" "$track" "$((width * 4))x$((height * 4))" "$frame" off "$out/reference" --race="$frames" "${karts[@]}" >/dev/null
"$retroaa" score "$out" --reference "$out/reference" --factor 4 "$@"
