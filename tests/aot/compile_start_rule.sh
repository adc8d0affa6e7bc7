#!/usr/bin/env bash
# fgsg compile --start-rule [Style$]Rule (#43): the library derives in the chosen style and
# rule, byte for byte as fgsg run --start-rule does, not in the Default style a library
# compiled without the flag derives in; an unknown style or rule is a located error and
# writes no library.
#   compile_start_rule.sh FGSG RUN_LIBRARY SOURCE_ROOT
set -uo pipefail
fgsg=$1
runlib=$2
root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL [compile_start_rule]: $*" >&2; exit 1; }
cd "$root" || fail "no root $root"
grammar=tests/cga/corpus/155_style_rules.cga
lots=(--lots tests/cga/corpus/lots/rect20x10.geojson)
flat=(--instancing off --group-by none)

# run NAME ARGS...: fgsg run's mesh in $tmp/NAME.glb
run() {
  local name=$1
  shift
  "$fgsg" run "$grammar" -q -o "$tmp/$name.glb" "${flat[@]}" "${lots[@]}" "$@" 2>"$tmp/err.txt" ||
    { cat "$tmp/err.txt"; fail "fgsg run $*"; }
}
# library NAME ARGS...: compiled with ARGS, run by the C API into $tmp/NAME.glb
library() {
  local name=$1
  shift
  "$fgsg" compile "$grammar" -q -o "$tmp/lib$name.so" "$@" 2>"$tmp/err.txt" || { cat "$tmp/err.txt"; fail "fgsg compile $*"; }
  "$runlib" "$tmp/lib$name.so" -o "$tmp/$name.glb" --quiet "${lots[@]}" 2>"$tmp/err.txt" ||
    { cat "$tmp/err.txt"; fail "run_library lib$name.so"; }
}
run default_run
run glass_run --start-rule 'Glass$Lot'
run wide_run --start-rule 'Glass_Wide$Lot'
library default
library glass --start-rule 'Glass$Lot'
library wide --start-rule 'Glass_Wide$Lot'
for style in default glass wide; do
  [ -s "$tmp/${style}_run.glb" ] || fail "fgsg run wrote no mesh for $style"
  cmp -s "$tmp/$style.glb" "$tmp/${style}_run.glb" || fail "the $style library's mesh differs from fgsg run's"
done
# The styles' meshes differ from each other (20 blue Panes or 8 wide ones, not 10 red Bricks).
cmp -s "$tmp/default.glb" "$tmp/glass.glb" && fail "the Glass library derives the Default style"
cmp -s "$tmp/glass.glb" "$tmp/wide.glb" && fail "the Glass_Wide library derives the Glass style"

# A style or rule the file lacks: fgsg run's E803, no library.
expect_error() {  # MESSAGE START_RULE
  "$fgsg" compile "$grammar" -q -o "$tmp/libbad.so" --start-rule "$2" >"$tmp/err.txt" 2>&1 &&
    fail "fgsg compile --start-rule $2 succeeds"
  grep -qF -- "$1" "$tmp/err.txt" || { cat "$tmp/err.txt"; fail "--start-rule $2: no '$1'"; }
  [ ! -e "$tmp/libbad.so" ] || fail "--start-rule $2 wrote a library"
}
expect_error "155_style_rules.cga:1:1: error[E803]: --start-rule Metal\$Lot: this file has no style 'Metal'" 'Metal$Lot'
expect_error "155_style_rules.cga:1:1: error[E803]: --start-rule Lott:" 'Lott'
"$fgsg" compile "$grammar" -q -o "$tmp/libbad.so" --start-rule >"$tmp/err.txt" 2>&1
[ $? -eq 2 ] || fail "--start-rule without a name is not a usage error"
echo "PASS: compile --start-rule: Default, Glass and Glass_Wide libraries = fgsg run's bytes"
