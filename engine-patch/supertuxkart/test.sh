#!/usr/bin/env bash
# The real-engine check on one track: capture METHODS at 320x240, STK's stock render at 1280x960 as the
# reference, score, then check.py's assertions (CHECKS: --edges and/or --sky).
# --effects among the CHECKS: the capture and its reference with the effects of STK's high preset on
# (--no-ssao: but SSAO, which a 4x reference cannot match).
#   usage: test.sh STK_BINARY RETROAA TRACK FRAME "METHODS" OUT CHECKS...
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=$1 retroaa=$2 track=$3 frame=$4 methods=$5 out=$6
shift 6
effects=() checks=()
for check in "$@"; do
  case $check in --effects | --no-ssao) effects+=("$check") ;; *) checks+=("$check") ;; esac
done
bash "$here/capture.sh" "$binary" "$track" 320x240 "$frame" "$methods" "$out" 1 "${effects[@]}"
bash "$here/capture.sh" "$binary" "$track" 1280x960 "$frame" off "$out/reference" 1 "${effects[@]}"
"$retroaa" score "$out" --reference "$out/reference/off.png" --factor 4
python3 "$here/check.py" "$out" "$here/patches" "${checks[@]}"
