#!/usr/bin/env bash
# Builds SuperTuxKart 1.4 with retroaa: unpacks the source tarball, applies patches/ in order, and
# builds it against the retroaa installed from BUILD, through ccache (its cache outside the clone, so a
# later clone or CI run on this machine reuses it).   usage: build.sh BUILD [TARBALL]
# Prints the path of the built binary last. Stops with what to install when something is missing.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=$(mkdir -p "$1" && cd "$1" && pwd)
tarball=${2:-$root/../shared/third_party/stk-code-1.4-src.tar.xz}
data=/usr/share/games/supertuxkart/data
stk=$build/stk
source=$stk/stk-code-1.4

[ -f "$tarball" ] || { echo "make stk: the SuperTuxKart 1.4 source tarball is missing: $tarball" >&2; exit 2; }
[ -f "$data/stk_config.xml" ] || {
  echo "make stk: SuperTuxKart's data is missing ($data): apt-get install supertuxkart-data" >&2; exit 2; }
for tool in ccache patch xvfb-run; do
  command -v "$tool" >/dev/null || { echo "make stk: '$tool' is missing (make stk-deps installs it)" >&2; exit 2; }
done
lib=/usr/lib/$(gcc -dumpmachine)
for file in libshaderc.so libglslang.a libSPIRV.a libSPIRV-Tools-opt.a; do
  [ -f "$lib/$file" ] || { echo "make stk: $lib/$file is missing: apt-get install libshaderc-dev" >&2; exit 2; }
done

# The library, installed where STK's find_package(retroaa) finds it.
cmake --install "$build" --prefix "$stk/retroaa" >/dev/null

# A fresh source tree whenever the tarball or a patch changed; otherwise the tree as it is (ccache and
# make then rebuild only what changed).
stamp=$(cat "$tarball" "$here"/patches/*.patch | sha256sum | cut -c1-16)
if [ "$(cat "$stk/source.stamp" 2>/dev/null)" != "$stamp" ]; then
  rm -rf "$source"
  mkdir -p "$stk"
  tar -xf "$tarball" -C "$stk"
  for p in "$here"/patches/*.patch; do
    patch -d "$source" -p1 --quiet --forward < "$p" || { echo "make stk: $(basename "$p") does not apply" >&2; exit 1; }
  done
  ln -sfn "$data" "$source/data"   # STK's CMake wants data/ beside its sources
  echo "$stamp" > "$stk/source.stamp"
fi

# Paths relative to the clone (CCACHE_BASEDIR, no directory hash) let another clone hit the same cache.
export CCACHE_DIR=${RETROAA_STK_CCACHE:-/var/cache/retroaa/ccache-stk} CCACHE_BASEDIR=$root CCACHE_NOHASHDIR=1
export CCACHE_MAXSIZE=5G
mkdir -p "$CCACHE_DIR"
# Debian's libshaderc leaves glslang and SPIRV-Tools unresolved: name them, in this order (a STRING: as
# a FILEPATH, CMake would make -lpthread a path).
shaderc="$lib/libshaderc.so;$lib/libglslang.a;$lib/libSPIRV.a;$lib/libMachineIndependent.a;$lib/libGenericCodeGen.a"
shaderc="$shaderc;$lib/libOSDependent.a;$lib/libOGLCompiler.a;$lib/libSPIRV-Tools-opt.a;$lib/libSPIRV-Tools.a;-lpthread"
cmake -S "$source" -B "$stk/stk-build" -DCMAKE_BUILD_TYPE=Release -DCHECK_ASSETS=OFF -DBUILD_RECORDER=OFF \
  -DUSE_WIIUSE=OFF -DUSE_SQLITE3=OFF -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DCMAKE_PREFIX_PATH="$stk/retroaa" -DSHADERC_LIBRARY:STRING="$shaderc" >"$stk/configure.log" 2>&1 ||
  { tail -20 "$stk/configure.log" >&2; echo "make stk: STK's configure failed ($stk/configure.log)" >&2; exit 1; }
echo "building SuperTuxKart (~800 files: 40-60 min on 2 cores the first time, minutes through ccache after): $stk/build.log" >&2
cmake --build "$stk/stk-build" -j"$(nproc)" >"$stk/build.log" 2>&1 ||
  { grep -E "error" "$stk/build.log" | head -20 >&2; echo "make stk: the build failed ($stk/build.log)" >&2; exit 1; }
echo "$stk/stk-build/bin/supertuxkart"
