#!/bin/sh
# The crops of docs/methods/temporal.md, rendered at 160x120 and enlarged 4x (nearest). A method with a
# history is played up to the frame. Usage: sh docs/results/temporal/crops.sh [RETROAA] (default: the build's)
set -eu
root=$(cd "$(dirname "$0")/../../.." && pwd)
retroaa=${1:-$root/build/app/retroaa}
images=$root/docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
render() {  # output, scene, frame ('' for the scene camera), method
  image=$1 scene=$2 at=$3 method=$4
  "$retroaa" render --scene "$scene" ${at:+--frame "$at"} --method "$method" --width 160 --height 120 \
    --gt-samples 6 --out "$image" >/dev/null
}
row() {  # output, geometry, then pairs of scene and method
  out=$1 geometry=$2 frame=$3
  shift 3
  i=0 tiles=""
  while [ $# -ge 2 ]; do
    render "$tmp/$i.png" "$1" "$frame" "$2"
    oiiotool "$tmp/$i.png" --ch R,G,B --cut "$geometry" -o "$tmp/c$i.png"
    tiles="$tiles $tmp/c$i.png" i=$((i + 1))
    shift 2
  done
  # shellcheck disable=SC2086
  oiiotool $tiles --mosaic "${i}x1" --resize:filter=box 400% -o "$out"
}
scenes=$root/integration-tests/scenes
methods="off temporal reconstruct+temporal ssaa@supersample=2 ground-truth"
row "$tmp/still.png" 48x36+60+45 "" $(for m in $methods; do echo default "$m"; done)
row "$tmp/fence.png" 48x36+0+45 8 $(for m in $methods; do echo "$scenes/fence.json" "$m"; done)
oiiotool "$tmp/still.png" "$tmp/fence.png" --mosaic 1x2 -o "$images/temporal-crops.png"
# The moving crate: off; temporal by the camera alone (the scene without its velocity attachment);
# temporal and reconstruct+temporal following the attachment; the ground truth.
sed '0,/{/s//{"velocity_attachment": false,/' "$scenes/moving_object.json" >"$tmp/no_velocity.json"
crate=$scenes/moving_object.json
row "$images/temporal-moving-object.png" 56x42+54+38 15 "$crate" off "$tmp/no_velocity.json" temporal \
  "$crate" temporal "$crate" reconstruct+temporal "$crate" ground-truth
