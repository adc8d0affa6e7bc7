#!/usr/bin/env bash
# Imports are bounded (#42 M1): 26 modules, each importing the next under two names, are
# 2^25 copies (each alias path has names and attrs of its own); `check` and `run` (both
# engines) stop at once with a located E065 that names the module copied most, instead
# of copying for hours. A diamond inside the bound still imports every copy.
. "$(dirname "$0")/lib.sh"

# ok COMMAND...: COMMAND ends (within 60 s) with exit code 0; stdout in $tmp/out.
ok() {
  timeout 60 "$@" >"$tmp/out" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "'$*': exit $?"; }
}

mkdir -p "$tmp/diamond"
for k in $(seq 0 24); do
  printf 'import "m%d" as a;\nimport "m%d" as b;\nattr v%d = 1;\nX%d ~> I("cube");\n' \
    $((k + 1)) $((k + 1)) "$k" "$k" >"$tmp/diamond/m$k.fgsg"
done
printf 'attr leaf = 1;\nL ~> I("cube");\n' >"$tmp/diamond/m25.fgsg"
printf 'axiom: a.X1;\n' >>"$tmp/diamond/m0.fgsg"

start=$(date +%s)
expect 1 "m0\.fgsg:1:8: error\[E065\].*'m25\.fgsg' is copied 16777216 times" -- "$fgsg" check "$tmp/diamond/m0.fgsg"
grep -q '\^' "$tmp/err" || fail "E065 without a caret"
for engine in jit interp; do
  expect 1 "m0\.fgsg:1:8: error\[E065\]" -- "$fgsg" run "$tmp/diamond/m0.fgsg" --engine=$engine -o "$tmp/d.obj"
done
[ $(( $(date +%s) - start )) -le 20 ] || fail "the three commands took $(( $(date +%s) - start )) s"
[ ! -e "$tmp/d.obj" ] || fail "an output was written"

# Six levels (2^6 copies of the leaf) are fine: every alias path is a copy of its own,
# with its own attrs.
mkdir -p "$tmp/small"
for k in $(seq 0 5); do
  printf 'import "m%d" as a;\nimport "m%d" as b;\nX%d ~> T(1, 0, 0) a.X%d T(0, 1, 0) b.X%d;\n' \
    $((k + 1)) $((k + 1)) "$k" $((k + 1)) $((k + 1)) >"$tmp/small/m$k.fgsg"
done
printf 'attr leaf = 0.5;\nX6 ~> S(leaf, leaf, leaf) I("cube");\n' >"$tmp/small/m6.fgsg"
printf 'axiom: X0;\n' >>"$tmp/small/m0.fgsg"
ok "$fgsg" check "$tmp/small/m0.fgsg"
grep -q "ok" "$tmp/out" || fail "check of the small diamond did not say ok"
for engine in jit interp; do
  ok "$fgsg" run "$tmp/small/m0.fgsg" --engine=$engine --set b.a.b.a.b.a.leaf=2 -q --stats \
    -o "$tmp/s.$engine.obj"
  grep -qx "instances 64" "$tmp/out" || { cat "$tmp/out" >&2; fail "small diamond ($engine): not 64 instances"; }
done
cmp -s "$tmp/s.jit.obj" "$tmp/s.interp.obj" || fail "the engines wrote other bytes"
exit 0
