#!/usr/bin/env bash
# Installs the library built in BUILD into a temporary prefix and builds and runs a tiny third-party
# project against it three ways: find_package, pkg-config and add_subdirectory(plugin). Then
# configures the library alone with every tool package hidden.   usage: run.sh BUILD SOURCE
set -euo pipefail
build=$(cd "$1" && pwd) source=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
consumer="$source/integration-tests/consumer"

cmake --install "$build" --prefix "$work/prefix" | tee "$work/install.log"
for file in lib/libretroaa.a include/retroaa/plugin.h include/retroaa/config.h include/retroaa/types.h \
            include/retroaa/result.h include/retroaa/export.h include/retroaa/version.h \
            lib/cmake/retroaa/retroaaConfig.cmake lib/cmake/retroaa/retroaaConfigVersion.cmake \
            lib/cmake/retroaa/retroaaTargets.cmake lib/pkgconfig/retroaa.pc; do
  [ -f "$work/prefix/$file" ] || { echo "install: $file is missing"; exit 1; }
done

echo "== each installed header compiles alone, pedantic, and brings in no GL header"
for header in "$work"/prefix/include/retroaa/*.h; do
  printf '#include <retroaa/%s>\n#if defined(GL_VERSION_1_0) || defined(__gl_h_) || defined(EGL_VERSION_1_0)\n#error GL leaked\n#endif\n' \
    "$(basename "$header")" | c++ -std=c++17 -Wall -Wextra -pedantic -Werror -fsyntax-only -I"$work/prefix/include" -x c++ - \
    || { echo "header: $(basename "$header") does not compile alone"; exit 1; }
done
echo "headers: $(ls "$work/prefix/include/retroaa" | tr '\n' ' ')"

echo "== find_package(retroaa CONFIG REQUIRED)"
cmake -S "$consumer" -B "$work/package" -DCONSUME=package -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/package" >/dev/null
"$work/package/consumer"

echo "== a window-lit renderer with retroaa put in: at most 70 lines, as docs/integration.md shows them"
block() { sed -n "/retroaa $1: begin/,/retroaa $1: end/p" "$2" | sed 's/^ *//'; }
for part in "call sites" glue; do
  diff <(block "$part" "$consumer/window_lit.cpp") <(block "$part" "$source/docs/integration.md") >/dev/null \
    || { echo "window_lit: the docs' $part differ from window_lit.cpp's"; exit 1; }
done
glue=$(block glue "$consumer/window_lit.cpp" | grep -v '^//' | grep -cv '^$')
sites=$(grep -c '// retroaa$' "$consumer/window_lit.cpp")
echo "window_lit: $glue lines of glue + $sites changed lines in the renderer = $((glue + sites))"
[ $((glue + sites)) -le 70 ] || { echo "window_lit: over 70 lines"; exit 1; }
"$work/package/window_lit"
"$work/package/window_lit" resolve+temporal reconstruct+temporal resolve+fxaa edge+coverage ssaa@supersample=3

echo "== pkg-config --cflags --libs retroaa"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
echo "pkg-config: $(pkg-config --modversion retroaa): $(pkg-config --cflags --libs retroaa)"
c++ -std=c++17 "$consumer/main.cpp" $(pkg-config --cflags --libs retroaa) -o "$work/pkgconfig-consumer"
"$work/pkgconfig-consumer"

echo "== add_subdirectory(<repo>/plugin)"
cmake -S "$consumer" -B "$work/subdirectory" -DCONSUME=subdirectory -DRETROAA_PLUGIN_DIR="$source/plugin" \
  -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/subdirectory" -j2 >/dev/null
"$work/subdirectory/consumer"

echo "== the library alone: -DRETROAA_BUILD_TOOLS=OFF with the tools' packages hidden"
cmake -S "$source" -B "$work/library-only" -DRETROAA_BUILD_TOOLS=OFF -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_glm=ON -DCMAKE_DISABLE_FIND_PACKAGE_assimp=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON -DCMAKE_DISABLE_FIND_PACKAGE_glfw3=ON >/dev/null
[ -f "$work/library-only/plugin/Makefile" ] && [ ! -d "$work/library-only/engine-patch" ] && [ ! -d "$work/library-only/app" ] || { echo "library-only: unexpected tree"; exit 1; }
echo "library-only: configured (plugin only)"
# With GoogleTest installed, -DRETROAA_BUILD_TOOLS=OFF still builds no test.
cmake -S "$source" -B "$work/library-with-gtest" -DRETROAA_BUILD_TOOLS=OFF >/dev/null
[ ! -d "$work/library-with-gtest/plugin/tests" ] || { echo "library-only: builds the unit tests"; exit 1; }
echo "library-only: no tests where GoogleTest is installed"
echo "== a shared library (BUILD_SHARED_LIBS=ON): the public API exported, nothing else of retroaa's"
cmake -S "$source" -B "$work/shared" -DRETROAA_BUILD_TOOLS=OFF -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/shared" -j2 >/dev/null
cmake --install "$work/shared" --prefix "$work/shared-prefix" >/dev/null
exported=$(nm -DC --defined-only "$work/shared-prefix/lib/libretroaa.so" | grep -o ' retroaa::[A-Za-z_:~]*' | sort -u)
echo "exported:" $exported
for public in retroaa::Plugin::create retroaa::Plugin::shade retroaa::applySetting retroaa::validateConfig retroaa::version; do
  grep -qx " $public" <<<"$exported" || { echo "shared: $public is not exported"; exit 1; }
done
internal=$(grep -Ev '^ retroaa::(Plugin::|applyConfigFile|applyConfigText|applyFsoFlag|applyMethodSpec|applySetting|applySettingsList|configKeys|findMethod|historyFrames|methodTable|readSetting|settingValues|toConfigText|toString|usesMsaa|validateConfig|version)' <<<"$exported" || true)
[ -z "$internal" ] || { echo "shared: internal symbols exported:" $internal; exit 1; }
cmake -S "$consumer" -B "$work/shared-consumer" -DCONSUME=package -DCMAKE_PREFIX_PATH="$work/shared-prefix" >/dev/null
cmake --build "$work/shared-consumer" >/dev/null
# ldd's output is read whole first: `ldd | grep -q` under pipefail fails when grep, having matched, exits
# before ldd finishes writing (SIGPIPE) — the flake this test showed under load.
libraries=$(ldd "$work/shared-consumer/consumer")
grep -q "$work/shared-prefix/lib/libretroaa.so" <<<"$libraries" || { echo "shared: the consumer does not load the installed libretroaa.so"; exit 1; }
"$work/shared-consumer/consumer"
echo "consumers: passed"
