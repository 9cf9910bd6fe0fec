#!/usr/bin/env bash
# tools/device/run.sh on this machine, tiny, with this build's retroaa and the machine's own GL: every
# bench it makes runs, and summary.py finds every figure the open GPU targets need in their JSON, so a
# lent GPU's few minutes are not lost to a renamed field.   usage: device_dry_run.sh RETROAA SOURCE
set -euo pipefail
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log=$(RETROAA="$1" OUT="$work" DEVICE_SKIP_GL=1 WIDTH=64 HEIGHT=48 GT_SAMPLES=1 REPEATS=1 WALL_FRAMES=2 \
  "$2/tools/device/run.sh" 2>&1)
echo "$log"
for run in samples4 samples8 samples16; do
  [ -s "$work/$run.json" ] || { echo "dry run: $run.json was not written"; exit 1; }
  grep -qF -- "$work/$run.json: " <<<"$log" || { echo "dry run: no summary of $run.json"; exit 1; }
done
for expected in "[19] reconstruct: wall" "[19] reconstruct holds" "[22] resolve pass" \
  "[22] resolve@resolve_compute=on pass" "[22] edge lighting" "[22] edge@resolve_compute=on lighting" \
  "[22] edge plugin_overhead_ms"; do
  grep -qF -- "$expected" <<<"$log" || { echo "dry run: no line with '$expected'"; exit 1; }
done
if grep -q -e "Traceback" -e "missing (" <<<"$log"; then echo "dry run: summary.py failed"; exit 1; fi
echo "device dry run: passed"
