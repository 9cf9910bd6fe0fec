#!/usr/bin/env bash
# Configures, builds and installs the library alone (-DRETROAA_BUILD_TOOLS=OFF) in a mount namespace
# where every tool and test dependency is hidden: their CMake packages, their headers, and every
# pkg-config file except libepoxy's and what libepoxy-dev itself pulls in (egl, gl, x11 and x11's).
# What a machine with only `cmake g++ pkg-config libepoxy-dev` sees. Needs root (unshare -m).
#   usage: library-only-isolated.sh SOURCE
set -euo pipefail
source=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/pkgconfig"
for module in epoxy $(pkg-config --print-requires-private epoxy | awk '{print $1}') x11 xproto kbproto xcb xau xdmcp; do
  cp "$(pkg-config --variable=pcfiledir "$module")/$module.pc" "$work/pkgconfig/"
done
hide=""
for dir in /usr/lib/x86_64-linux-gnu/cmake /usr/share/cmake /usr/include/assimp /usr/include/gtest /usr/include/glm \
           /usr/include/nlohmann /usr/include/CLI /usr/include/OpenImageIO /usr/include/GLFW /usr/include/imgui; do
  [ -d "$dir" ] && hide="$hide mount -t tmpfs none $dir &&"
done
unshare -m bash -c "$hide PKG_CONFIG_LIBDIR='$work/pkgconfig' cmake -S '$source' -B '$work/build' -DRETROAA_BUILD_TOOLS=OFF \
  && cmake --build '$work/build' -j2 && cmake --install '$work/build' --prefix '$work/prefix'" > "$work/log" 2>&1 \
  || { cat "$work/log"; echo "library-only: FAILED"; exit 1; }
grep -E "Found|Installing: .*(libretroaa|retroaa.pc|retroaaConfig.cmake)" "$work/log"
echo "library-only: configured, built and installed with only libepoxy's packages visible"
