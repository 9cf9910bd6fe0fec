#!/usr/bin/env bash
# Renders one SuperTuxKart frame with each anti-aliasing method in one process, headless (Xvfb,
# llvmpipe): the race starts at once with one kart and no opponents, the world advances by a fixed step
# to frame FRAME, then holds still while each method renders it (2 frames to settle, TIMED frames timed,
# the last one written). Writes OUT/<method>.png and OUT/capture.jsonl.
#   usage: capture.sh STK_BINARY TRACK WIDTHxHEIGHT FRAME "METHODS" OUT [TIMED] [--race=K [--karts=N]] [--effects]
#          [--no-ssao] [--particles]
# METHODS: retroaa method specs (off, fxaa, edge, resolve/fso+fxaa, ...), `stk-mlaa` (STK's own MLAA) and
# `chosen` (the choice saved in STK's config.xml; see RETROAA_STK_HOME).
# --race=K: a race in motion instead: STK's AI drives (its profile mode), the world never holds, the one
#   method renders from the start, and frames FRAME-K+1 .. FRAME are written (<method>.<frame>.png).
#   --karts=N: N karts in the race, the player's and N-1 AI opponents (default 1).
# --effects: the effects STK's high preset turns on (shadows, SSAO, glow, bloom, light shafts, image-based
#   lighting, particles) instead of off. --no-ssao then leaves SSAO off: its sample pattern and depth mips are
#   in pixels, so a 4x reference does not match it (olivermath at 320x240, SSAO alone: interior PSNR 21.5 dB
#   against 40.1 without; each other effect alone within 0.2 dB): scored tables use it.
# --particles: STK's particles (exhaust smoke, the track's emitters) on without the other effects: forward
#   passes drawn between beginForward() and endForward().
set -euo pipefail
binary=$1 track=$2 size=$3 frame=$4 methods=$5 out=$6
shift 6
timed=3 mode=(--race-now --numkarts=1 --laps=1) race=0 karts=1 no_ssao=0 particles=0
effects=(--disable-light-shaft --disable-ssao --disable-glow --disable-bloom --disable-ibl --disable-particles --shadows=0)
for option in "$@"; do
  case $option in
    --race=*) race=${option#--race=} ;;
    --karts=*) karts=${option#--karts=} ;;
    --effects) effects=(--enable-light-shaft --enable-ssao --enable-glow --enable-bloom --enable-ibl --enable-particles
                        --shadows=1024) ;;
    --no-ssao) no_ssao=1 ;;
    --particles) particles=1 ;;
    *[!0-9]* | '') echo "capture: unknown option '$option'" >&2; exit 2 ;;
    *) timed=$option ;;
  esac
done
[ "$no_ssao" = 0 ] || effects=("${effects[@]/--enable-ssao/--disable-ssao}")   # STK: --enable-ssao wins
[ "$particles" = 0 ] || effects=("${effects[@]/--disable-particles/--enable-particles}")
case $karts in '' | *[!0-9]* | 0) echo "capture: --karts needs a count of at least 1, got '$karts'" >&2; exit 2 ;; esac
[ "$race" = 0 ] || mode=("--numkarts=$karts" --profile-time=100000 "--aa-race=$race")
width=${size%x*} height=${size#*x}
data=/usr/share/games/supertuxkart
[ -d "$data/data/tracks/$track" ] || { echo "capture: no track '$track' in $data/data/tracks" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out/capture.jsonl"
# A private home: STK's config, its first-run screens and its caches stay out of the user's.
# RETROAA_STK_HOME keeps one across runs (a choice saved in its config.xml).
if [ -n "${RETROAA_STK_HOME:-}" ]; then
  home=$(mkdir -p "$RETROAA_STK_HOME" && cd "$RETROAA_STK_HOME" && pwd)
else
  home=$(mktemp -d)
  trap 'rm -rf "$home"' EXIT
fi
# Mesa's shader cache outside the clone: STK's ~200 shaders compile once per machine, not per run.
export MESA_SHADER_CACHE_DIR=${RETROAA_STK_SHADER_CACHE:-/var/cache/retroaa/mesa-shader-cache}
mkdir -p "$MESA_SHADER_CACHE_DIR"
export HOME=$home XDG_CONFIG_HOME=$home/config XDG_DATA_HOME=$home/data XDG_CACHE_HOME=$home/cache
export SUPERTUXKART_DATADIR=$data LP_NUM_THREADS=${LP_NUM_THREADS:-2}
# The effects that blur or move the image (depth of field, motion blur) off, and without --effects those
# llvmpipe pays most for; MLAA is its own row (stk-mlaa), so its target exists from the start when asked for.
mlaa=--disable-mlaa
case " $methods " in *" stk-mlaa "*) mlaa=--enable-mlaa ;; esac
status=0
# The timeout runs inside xvfb-run, on STK itself: STK ignores SIGTERM, so it is killed 15 s later, and
# xvfb-run then takes its X server down (a timeout around xvfb-run would leave STK running).
xvfb-run -a -s "-screen 0 ${width}x${height}x24" \
  timeout --kill-after=15 "${RETROAA_STK_TIMEOUT:-1800}" "$binary" --screensize="${width}x${height}" --windowed --no-sound --no-start-screen \
  --track="$track" "${mode[@]}" --seed=1 --enable-dynamic-lights --disable-dof --disable-motion-blur \
  "${effects[@]}" "$mlaa" --anisotropic=0 \
  --aa-capture="$out" --aa-capture-frame="$frame" --aa-methods="$methods" --aa-fixed-dt=0.0166667 \
  --aa-timed-frames="$timed" >"$out/stk.log" 2>&1 || status=$?
if [ "$status" = 124 ] || [ "$status" = 137 ]; then
  reached=$(grep -o 'AaCapture: .*' "$out/stk.log" | tail -1 || true)
  echo "capture: SuperTuxKart did not finish in ${RETROAA_STK_TIMEOUT:-1800} s on $track (its last word: ${reached:-none}; $out/stk.log)" >&2
  exit 1
fi
captured=$(grep -c '"image"' "$out/capture.jsonl" 2>/dev/null || true)
wanted=$(echo "$methods" | wc -w)
[ "$race" = 0 ] || wanted=$race
if [ "${captured:-0}" != "$wanted" ]; then
  tail -20 "$out/stk.log" >&2
  echo "capture: $captured of $wanted methods captured on $track (exit $status; $out/stk.log)" >&2
  exit 1
fi
echo "capture: $track, $wanted methods at ${size} -> $out"
