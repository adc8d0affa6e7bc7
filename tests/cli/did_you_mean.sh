#!/usr/bin/env bash
# "did you mean ...?" for a near miss (frontend/did_you_mean.h): an unknown option names
# the command's nearest option, an unknown --set attribute the grammar's nearest attr, an
# unknown --start-rule the file's nearest rule that can start, a CGA leaf the symbol with
# rules one edit away; a name near nothing gets no guess. The exit codes stay those of the errors (2 usage, 1 grammar).
#   did_you_mean.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
export FGSG_CACHE_DIR="$work/cache"

expect() {  # CODE TEXT ARGS...: the run exits CODE and prints TEXT (within a line)
  local code="$1" line="$2"
  shift 2
  local out rc
  out="$("$fgsg" "$@" 2>&1 </dev/null)"
  rc=$?
  if [ "$rc" -ne "$code" ] || ! grep -qF -- "$line" <<<"$out"; then
    echo "FAIL: fgsg $* exited $rc (expected $code), printing:"; echo "$out"; echo "expected: $line"; fail=1
  fi
}
koch="$source/examples/koch.fgsg"
mueller="$source/examples/mueller_building.fgsg"

expect 2 "fgsg run: unknown option '--sed'; did you mean --seed? (see fgsg run --help)" run "$koch" --sed 3
expect 2 "fgsg run: unknown option '--sed=3'; did you mean --seed? (see fgsg run --help)" run "$koch" --sed=3
expect 2 "fgsg run: unknown option '--perview'; did you mean --preview? (see fgsg run --help)" run "$koch" --perview p.png
expect 2 "fgsg run: unknown option '--zzzzzz' (see fgsg run --help)" run "$koch" --zzzzzz
expect 2 "fgsg compile: unknown option '--heade'; did you mean --header? (see fgsg compile --help)" compile "$koch" --heade x
expect 2 "fgsg view: unknown option '--prot'; did you mean --port? (see fgsg view --help)" view "$koch" --prot 0

expect 1 "error[R010]: --set buildng_height: the grammar declares no attr 'buildng_height'; did you mean 'building_height'? (attrs: lot_width, lot_depth, building_height, roof_angle," \
  run "$mueller" --set buildng_height=12 -o "$work/m.glb"
[ ! -e "$work/m.glb" ] || { echo "FAIL: a mesh written despite the unknown attr"; fail=1; }

cat >"$work/two.cga" <<'CGA'
version "2023.0"
@StartRule
Lot --> split(x) { 5 : A }*
Other --> split(x) { 10 : A }*
Param(n) --> A
A --> extrude(3) Mass
CGA
expect 1 "$work/two.cga:1:1: error[E803]: --start-rule Otehr: the start rule 'Otehr' is not a rule of this file; did you mean 'Other'?; rules that can start: Lot (@StartRule), A, Other" \
  check "$work/two.cga" --start-rule Otehr
expect 1 "$work/two.cga:1:1: error[E803]: --start-rule Nope: the start rule 'Nope' is not a rule of this file; rules that can start: Lot (@StartRule), A, Other" \
  check "$work/two.cga" --start-rule Nope

# A leaf of a CGA-style grammar whose name is a slip for a symbol with rules (swapped letters).
printf 'axiom: S(10, 0, 10) Lot;\nLot ~> Extrude(3) Mass;\nMass ~> Comp("faces") { top: Gabel | side: Wall };\nGable ~> I("cube");\nWall ~> I("cube");\n' >"$work/slip.fgsg"
expect 0 "slip.fgsg:3:30: warning[W001]: 'Gabel' has no rule: it is a leaf and outputs its own geometry; did you mean 'Gable'?" \
  check "$work/slip.fgsg"

# A misspelt builtin function or operation (#47): the located error names the nearest
# builtin of the dialect; a shape with arguments and no rule, the nearest operation.
printf 'axiom: A;\nA -> S(1, sqr(4), 1) I("cube");\n' >"$work/fn.fgsg"
expect 1 "fn.fgsg:2:11: error[E011]: unknown function 'sqr'; did you mean 'sqrt'? (math: sin cos tan" check "$work/fn.fgsg"
printf 'axiom: A;\nA -> S(1, zzz(4), 1) I("cube");\n' >"$work/nofn.fgsg"
expect 1 "nofn.fgsg:2:11: error[E011]: unknown function 'zzz' (math: sin cos tan" check "$work/nofn.fgsg"
printf 'axiom: A;\nA -> S(1, 2, 1) Extrud(2) B Roofs;\nB -> I("cube");\n' >"$work/op.fgsg"
expect 0 "op.fgsg:2:17: warning[W001]: 'Extrud' has no rule: it stays a terminal shape and places no geometry; did you mean the operation 'Extrude'?" \
  check "$work/op.fgsg"
# Without arguments a shape may well be meant: no guess for Roofs (near Roof); nor for a
# name of one or two letters (B(3) is one edit from T).
grep -q "'Roofs' has no rule: it stays a terminal shape and places no geometry$" <<<"$("$fgsg" check "$work/op.fgsg" 2>&1)" ||
  { echo "FAIL: Roofs (no arguments) got a guess or no W001"; fail=1; }
printf 'axiom: B(3);\n' >"$work/short.fgsg"
grep -q "'B' has no rule: it stays a terminal shape and places no geometry$" <<<"$("$fgsg" check "$work/short.fgsg" 2>&1)" ||
  { echo "FAIL: B(3) got a guess or no W001"; fail=1; }
printf 'axiom: S(10, 0, 10) Lot;\nLot ~> Extrude(3) Mass;\nMass ~> Comp("faces") { top: Rof(30) | side: Wall };\nWall ~> I("cube");\n' >"$work/leaf.fgsg"
expect 0 "leaf.fgsg:3:30: warning[W001]: 'Rof' has no rule: it is a leaf and outputs its own geometry; did you mean the operation 'Roof'?" \
  check "$work/leaf.fgsg"
# A .cga file stops at its first error: one slip per file.
printf 'version "2023.0"\nattr h = 3\n@StartRule\nLot --> extrud(h) Mass\n' >"$work/op.cga"
expect 1 "op.cga:4:9: error[E800]: unknown operation 'extrud'; did you mean 'extrude'? (no rule of this file has that name)" check "$work/op.cga"
printf 'version "2023.0"\n@StartRule\nLot --> extrude(3) Mass\nMass --> comp(f) { top : Roof | side : wal(2) }\nwall(n) --> color("#ff0000")\n' >"$work/rule.cga"
expect 1 "rule.cga:4:40: error[E800]: unknown operation 'wal'; did you mean 'wall'? (no rule of this file has that name)" check "$work/rule.cga"
printf 'version "2023.0"\nLot --> extrude(sqr(4)) M\n' >"$work/fn.cga"
expect 1 "fn.cga:2:17: error[E011]: unknown function 'sqr'; did you mean 'sqrt'? (not a function of this file or of CityEngine CGA)" check "$work/fn.cga"
printf 'version "2023.0"\nheight(a) = a * 2\nLot --> extrude(heigth(2)) M\n' >"$work/own.cga"
expect 1 "own.cga:3:17: error[E011]: unknown function 'heigth'; did you mean 'height'? (not a function of this file or of CityEngine CGA)" check "$work/own.cga"
printf 'version "2023.0"\nLot --> extrude(zzz(4)) M\n' >"$work/nofn.cga"
expect 1 "nofn.cga:2:17: error[E011]: unknown function 'zzz' (not a function" check "$work/nofn.cga"
exit $fail
