#!/bin/sh
# The crops of results.md's textured-content section, from `retroaa bench --images DIR` on the demo
# (default) and engine scenes at 240x180. Usage: sh docs/results/textures/crops.sh DEMO_DIR ENGINE_DIR
set -eu
here=$(dirname "$0")
crop() {  # dir, geometry, output
  dir=$1 geometry=$2 out=$3 tmp=$(mktemp -d)
  i=0
  for name in ground-truth off fxaa smaa resolve edge "ssaa@supersample=2"; do
    cp "$dir/$name.png" "$tmp/$i.png"  # oiiotool reads '@' and '=' as its own syntax
    oiiotool "$tmp/$i.png" --ch R,G,B --cut "$geometry" -o "$tmp/c$i.png"
    i=$((i + 1))
  done
  oiiotool "$tmp"/c0.png "$tmp"/c1.png "$tmp"/c2.png "$tmp"/c3.png "$tmp"/c4.png "$tmp"/c5.png "$tmp"/c6.png \
    --mosaic:pad=2 7x1 --resize:filter=box 300% -o "$out"
  rm -rf "$tmp"
}
crop "$1" 64x56+44+62 "$here/crops-default.png"
crop "$2" 64x56+88+60 "$here/crops-engine.png"
