#!/bin/bash
# Runs on a lent GPU machine, from the repository root, with .device/ carried (tools/device/pack.sh):
# the benchmark runs that the open GPU targets need, one JSON each into $OUT, the bench tables on
# stdout. Sized to fit one call of the device tool (a few minutes on an H100); every run has its own
# time limit so one slow run cannot take the others with it.
#   issue 19: `reconstruct` vs `off` in wall clock at 1280×720 4× (≤ 1.5×) and 16× (≤ 2×), its full-screen
#             and its compute pass (reconstruct_compute); plugin B/px at 8× and 16× against `resolve`'s
#   issue 22: the resolve pass against its traffic bound, edge's lighting against its ideal, edge's
#             plugin_overhead_ms against `off`'s frame (4×); each also with the compute resolve
#             (resolve_compute), whose passes do not wait on the small graphics partition
# Environment: OUT (default out/device), WIDTH, HEIGHT, GT_SAMPLES, REPEATS, WALL_FRAMES, STEP_TIMEOUT;
# DEVICE_SKIP_GL=1 leaves the machine's own GL loader alone and RETROAA names another binary (a dry run
# on a machine that has both: integration-tests/device_dry_run.sh).
set -u
cd "$(dirname "$0")/../.." || exit 2
if [ "${DEVICE_SKIP_GL:-0}" != 1 ]; then
  for f in .device/gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  [ -f "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor
fi
export LD_LIBRARY_PATH=$PWD/.device/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
out=${OUT:-out/device}
mkdir -p "$out"
retroaa=${RETROAA:-.device/bin/retroaa}
nvidia-smi -L 2>/dev/null || true

bench() {  # bench NAME ARGS...: one bench run into $out/NAME.json
  local name=$1
  shift
  echo "== $name: $*"
  timeout "${STEP_TIMEOUT:-150}" "$retroaa" bench --scene default --width "${WIDTH:-1280}" --height "${HEIGHT:-720}" \
    --gt-samples "${GT_SAMPLES:-8}" --repeats "${REPEATS:-7}" --wall-frames "${WALL_FRAMES:-60}" \
    --json "$out/$name.json" "$@" 2>&1 | grep -v '^bench: ' | tail -20
  echo "   exit ${PIPESTATUS[0]}"
}
bench samples4 --samples 4 --methods off,fxaa,coverage,reconstruct,reconstruct@reconstruct_compute=on,reconstruct@reconstruct_search_radius=1,resolve,resolve@resolve_compute=on,resolve+reconstruct,edge,edge@resolve_compute=on,adaptive,aggregate,per-sample
bench samples8 --samples 8 --methods off,coverage,reconstruct,reconstruct@reconstruct_compute=on,resolve,edge
bench samples16 --samples 16 --methods off,coverage,reconstruct,reconstruct@reconstruct_compute=on,resolve,resolve@resolve_compute=on,edge
python3 tools/device/summary.py "$out/samples4.json" "$out/samples8.json" "$out/samples16.json" || true
