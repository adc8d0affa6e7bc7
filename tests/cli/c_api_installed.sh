#!/usr/bin/env bash
# A C program built against an installed fgsg, as its users build one: `cmake --install`
# into a temporary prefix (it installs what is built, it builds nothing), the installed
# fgsg compiles examples/stem_leaf.fgsg, and examples/c_api/generate.c is built with
# find_package(fgsg) (a tiny CMake project) and with pkg-config. Each program writes the
# same bytes as `fgsg run --seed 7` with a flattened mesh (the C API writes one). usage: c_api_installed.sh SOURCE_DIR BINARY_DIR
set -u
source="$1" build="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
if ! cmake --install "$build" --prefix "$prefix" >/dev/null; then
  echo "FAIL: cmake --install"; exit 1
fi
for f in include/fgsg/fgsg_api.h lib/libfgsg.so lib/cmake/fgsg/fgsgConfig.cmake \
         lib/cmake/fgsg/fgsgConfigVersion.cmake lib/pkgconfig/fgsg.pc share/doc/fgsg/LICENSE; do
  [ -f "$prefix/$f" ] || { echo "FAIL: $f not installed"; fail=1; }
done
head -1 "$prefix/include/fgsg/fgsg_api.h" | grep -qx '// SPDX-License-Identifier: MIT' \
  || { echo "FAIL: the installed header has no SPDX line"; fail=1; }
[ "$fail" -eq 0 ] || exit 1

# The prefix is moved before use: both packages must find it from where they lie.
mv "$prefix" "$work/moved"
prefix="$work/moved"
export FGSG_CACHE_DIR="$work/cache"
mkdir -p "$work/lib"
"$prefix/bin/fgsg" compile "$source/examples/stem_leaf.fgsg" -o "$work/lib/libstem_leaf.so" --quiet \
  || { echo "FAIL: the installed fgsg cannot compile examples/stem_leaf.fgsg"; exit 1; }
(cd "$work" && "$prefix/bin/fgsg" run "$source/examples/stem_leaf.fgsg" --seed 7 --instancing off --group-by none \
   -o "$work/expected.glb" --quiet) \
  || { echo "FAIL: the installed fgsg cannot run examples/stem_leaf.fgsg"; exit 1; }

# A second source that includes only the installed header: <fgsg/fgsg_api.h> resolves.
cat > "$work/uses_header.c" <<'C'
#include <fgsg/fgsg_api.h>
int fgsg_header_is_usable(void) { fgsg_generator_free(NULL); return 0; }
C

# 1. find_package(fgsg) and the imported target fgsg::fgsg.
mkdir -p "$work/cmake_user"
cat > "$work/cmake_user/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(fgsg_c_api_user C)
find_package(fgsg 0.1 REQUIRED CONFIG)
add_executable(generate $source/examples/c_api/generate.c $work/uses_header.c)
target_include_directories(generate PRIVATE $work/lib)
target_link_libraries(generate PRIVATE fgsg::fgsg $work/lib/libstem_leaf.so)
set_target_properties(generate PROPERTIES BUILD_RPATH "$work/lib;$prefix/lib")
CMAKE
if cmake -S "$work/cmake_user" -B "$work/cmake_user/build" -DCMAKE_PREFIX_PATH="$prefix" >"$work/cmake.log" 2>&1 &&
   cmake --build "$work/cmake_user/build" >>"$work/cmake.log" 2>&1; then
  grep -q "$prefix/lib/libfgsg.so" "$work/cmake_user/build/CMakeCache.txt" "$work/cmake_user/build"/*.ninja \
    "$work/cmake_user/build/CMakeFiles/generate.dir/link.txt" 2>/dev/null \
    || { echo "FAIL: find_package(fgsg) did not link the installed libfgsg.so"; fail=1; }
  (cd "$work" && "$work/cmake_user/build/generate" 7 "$work/cmake.glb" >/dev/null) \
    || { echo "FAIL: the find_package(fgsg) program failed"; fail=1; }
  cmp -s "$work/expected.glb" "$work/cmake.glb" \
    || { echo "FAIL: the find_package(fgsg) program wrote other bytes than fgsg run --seed 7"; fail=1; }
else
  echo "FAIL: the find_package(fgsg) project does not build:"; cat "$work/cmake.log"; fail=1
fi

# 2. pkg-config.
flags="$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs fgsg)" \
  || { echo "FAIL: pkg-config does not know fgsg"; exit 1; }
# shellcheck disable=SC2086  # the flags are words
set -- $flags
# pkg-config does not normalise ${pcfiledir}/../..: compare the folders themselves.
{ [ $# -eq 3 ] && [ "$(realpath "${1#-I}")" = "$prefix/include" ] && [ "$(realpath "${2#-L}")" = "$prefix/lib" ] &&
  [ "$3" = "-lfgsg" ]; } || { echo "FAIL: pkg-config --cflags --libs fgsg gave '$flags'"; fail=1; }
# shellcheck disable=SC2086  # the flags are words
if cc -std=c99 -Wall -Werror -I "$work/lib" "$source/examples/c_api/generate.c" "$work/uses_header.c" \
      -o "$work/generate_pc" -L "$work/lib" -lstem_leaf $flags \
      -Wl,-rpath,"$work/lib" -Wl,-rpath,"$prefix/lib" 2>"$work/cc.log"; then
  (cd "$work" && "$work/generate_pc" 7 "$work/pc.glb" >/dev/null) || { echo "FAIL: the pkg-config program failed"; fail=1; }
  cmp -s "$work/expected.glb" "$work/pc.glb" \
    || { echo "FAIL: the pkg-config program wrote other bytes than fgsg run --seed 7"; fail=1; }
else
  echo "FAIL: generate.c does not build with pkg-config's flags:"; cat "$work/cc.log"; fail=1
fi
exit $fail
