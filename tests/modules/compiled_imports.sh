#!/usr/bin/env bash
# A grammar importing three modules (two from the standard library's search rules, one
# beside it, one through another) compiles to one library that runs without the module
# files, with fgsg run's bytes; --set reaches a module's attr by its qualified name.
#   usage: compiled_imports.sh FGSG RUN_LIBRARY
set -uo pipefail
fgsg=$1 run_library=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [compiled_imports]: $*" >&2; exit 1; }
mkdir -p "$tmp/src/parts" "$tmp/std/shapes"
cat > "$tmp/std/shapes/ring.fgsg" <<'G'
attr radius = 1;
Ring ~> S(radius, 0.2, radius) I("torus");
G
cat > "$tmp/src/parts/box.fgsg" <<'G'
import "std/shapes/ring" as ring;
attr size = 2;
Axiom ~> Box(3);
Box(n) : n > 0 ~> S(size, 0.5, 1) I("cube") T(size + 1, 0, 0) Box(n - 1);
Box(n) ~> ring.Ring;
G
cat > "$tmp/src/parts/dot.fgsg" <<'G'
Dot ~> S(0.3, 0.3, 0.3) I("sphere");
G
cat > "$tmp/src/g.fgsg" <<'G'
import "parts/box" as box (size = 1.5);
import "parts/dot" as dot;
axiom: box.Box(2) T(0, 3, 0) dot.Dot;
G
cd "$tmp/src" || fail "no folder"
export FGSG_STDLIB="$tmp/std" FGSG_CACHE_DIR="$tmp/cache"
"$fgsg" run g.fgsg -o "$tmp/run.obj" --set box.ring.radius=2 -q || fail "fgsg run failed"
"$fgsg" run g.fgsg -o "$tmp/interp.obj" --set box.ring.radius=2 -q --engine interp || fail "fgsg run --engine interp failed"
cmp -s "$tmp/run.obj" "$tmp/interp.obj" || fail "the JIT and the interpreter differ"
"$fgsg" run g.fgsg -o "$tmp/default.obj" -q || fail "fgsg run without --set failed"
cmp -s "$tmp/run.obj" "$tmp/default.obj" && fail "--set box.ring.radius=2 changed nothing"
"$fgsg" compile g.fgsg -o "$tmp/libg.so" -q || fail "fgsg compile failed"
rm -rf "$tmp/src/parts" "$tmp/std"  # the library needs none of them
"$run_library" "$tmp/libg.so" -o "$tmp/lib.obj" --set box.ring.radius=2 || fail "the library did not run without its modules"
cmp -s "$tmp/run.obj" "$tmp/lib.obj" || fail "the library's output differs from fgsg run's"
echo "ok: three modules in one library, run without them"
