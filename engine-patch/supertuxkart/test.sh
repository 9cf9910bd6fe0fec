#!/usr/bin/env bash
# The real-engine check on one track: capture METHODS at 320x240, STK's stock render at 1280x960 as the
# reference, score, then check.py's assertions (CHECKS: --edges and/or --sky).
#   usage: test.sh STK_BINARY RETROAA TRACK FRAME "METHODS" OUT CHECKS...
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
binary=$1 retroaa=$2 track=$3 frame=$4 methods=$5 out=$6
shift 6
bash "$here/capture.sh" "$binary" "$track" 320x240 "$frame" "$methods" "$out" 1
bash "$here/capture.sh" "$binary" "$track" 1280x960 "$frame" off "$out/reference" 1
"$retroaa" score "$out" --reference "$out/reference/off.png" --factor 4
python3 "$here/check.py" "$out" "$here/patches" "$@"
