#!/bin/bash
# Packs what tools/device/run.sh needs on a lent GPU machine (the `device` tool: bare, no package
# registry) into .device/, from this Debian 12 machine: a retroaa built without OpenImageIO, the
# shared libraries it needs beyond glibc and libstdc++, and the GL loader packages (libglvnd's EGL)
# that the NVIDIA driver there plugs into. Then call the device tool with
#   command: tools/device/run.sh    carry: [".device"]    timeout_s: 480
# and read the figures with tools/device/summary.py on the JSON it returns.
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${BUILD_DEVICE:-build-device}
cmake -S . -B "$build" -DRETROAA_WITH_OPENIMAGEIO=OFF -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target retroaa_cli
rm -rf .device && mkdir -p .device/bin .device/lib .device/gl
cp "$build/app/retroaa" .device/bin/
# Libraries a CUDA image lacks; glibc, libstdc++, libgcc and zlib come from the machine itself.
ldd .device/bin/retroaa | awk '/=> \//{print $1, $3}' | while read -r soname path; do
  case "$soname" in
    libc.so.* | libm.so.* | libdl.so.* | librt.so.* | libpthread.so.* | ld-linux* | libstdc++.so.* | libgcc_s.so.* | libz.so.*) ;;
    *) cp -L "$path" ".device/lib/$soname" ;;
  esac
done
# libepoxy opens libEGL.so.1 at run time; the device README's recipe: libglvnd's loaders as packages.
(cd .device/gl && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
du -sh .device
ls .device/lib .device/gl
