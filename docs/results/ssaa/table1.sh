#!/bin/sh
# Regenerates adaptive.md's Table 1: adaptive against ssaa at m = 2, 3, 4 on three scenes, 320x240.
# Usage (from the repository root, after `make build`): sh docs/results/ssaa/table1.sh [OUT_DIR]
# Writes one bench JSON per scene and settings here and prints one Markdown row per m; the PSNR and MSE
# are over RGB of the two 8-bit images (idiff), wall times from the bench's own back-to-back frames.
set -eu
retroaa=build/app/retroaa
out=${1:-out/table1}
here=$(dirname "$0")
quality="@adaptive_shading_scale=4@adaptive_threshold_min=0.004@adaptive_threshold_edge=0.02@adaptive_depth_scale=4@adaptive_normal_scale=8"
for scene in default fence space_battle; do
  file=$scene
  [ "$scene" = default ] || file=integration-tests/scenes/$scene.json
  for settings in defaults quality; do
    extra=""
    [ "$settings" = quality ] && extra=$quality
    methods=""
    for m in 2 3 4; do methods="$methods,ssaa@supersample=$m,adaptive@supersample=$m$extra"; done
    dir=$out/$scene-$settings
    rm -rf "$dir"
    "$retroaa" bench --scene "$file" --width 320 --height 240 --methods "${methods#,}" --repeats 1 \
      --wall-frames 10 --gt-samples 2 --images "$dir" --json "$here/llvmpipe-$scene-320x240-$settings.json" >/dev/null
    for m in 2 3 4; do
      # oiiotool reads '@' and '=' in names as its own syntax: copy to plain names first.
      cp "$dir/ssaa@supersample=$m.png" "$dir/ssaa$m.png"
      cp "$dir/adaptive@supersample=$m$extra.png" "$dir/adaptive$m.png"
      oiiotool "$dir/ssaa$m.png" --ch R,G,B -o "$dir/ssaa${m}_rgb.png"
      oiiotool "$dir/adaptive$m.png" --ch R,G,B -o "$dir/adaptive${m}_rgb.png"
      idiff -a "$dir/ssaa${m}_rgb.png" "$dir/adaptive${m}_rgb.png" >"$dir/idiff$m.txt" || true
      python3 - "$here/llvmpipe-$scene-320x240-$settings.json" "$m" "$extra" "$dir/idiff$m.txt" "$scene" "$settings" <<'PY'
import json, re, sys
rows = {r["method"]: r for r in json.load(open(sys.argv[1]))["rows"]}
m, extra, text = sys.argv[2], sys.argv[3], open(sys.argv[4]).read()
ssaa, adaptive = rows[f"ssaa@supersample={m}"], rows[f"adaptive@supersample={m}{extra}"]
psnr = re.search(r"Peak SNR = ([0-9.inf]+)", text)
rms = float(re.search(r"RMS error = ([0-9.e+-]+)", text).group(1))
share = adaptive["lighting_evaluations"] / ssaa["lighting_evaluations"]
print(f"| {sys.argv[5]} | {m}x{m} | {sys.argv[6]} | {adaptive['wall_ms']:.1f} / {ssaa['wall_ms']:.1f} | "
      f"{100 * share:.1f} % | {psnr.group(1) if psnr else 'inf'} | {rms * rms:.1e} |")
PY
    done
  done
done
