#!/usr/bin/env bash
# fgsg run/check --start-rule NAME: a .cga grammar's lots (or its default lot) derived by
# the named rule instead of the @StartRule, by both engines; a rule the file lacks or one
# with parameters is E803 naming it (and the rules that can start), and an fgsg grammar,
# which starts from its axiom, is E803 too.
#   cga_start_rule.sh FGSG
set -uo pipefail
fgsg=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cat >"$tmp/two.cga" <<'CGA'
version "2023.0"
@StartRule
Lot --> split(x) { 5 : A }*
Other --> split(x) { 10 : A }*
Param(n) --> A
A --> extrude(3) Mass
CGA
# Two lots 20 m along x: Lot makes 4 pieces of each, Other 2 (a box is 12 triangles).
cat >"$tmp/lots.geojson" <<'JSON'
{"type": "FeatureCollection", "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},
 "features": [
  {"type": "Feature", "id": "a", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [20, 0], [20, 10], [0, 10], [0, 0]]]}},
  {"type": "Feature", "id": "b", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[30, 0], [50, 0], [50, 10], [30, 10], [30, 0]]]}}]}
JSON

counts() {  # FILE ARGS...: "instances N triangles M" of a run
  "$fgsg" run "$@" --stats -q -o "$tmp/out.obj" 2>"$tmp/err.txt" | grep -E '^(instances|triangles) ' | tr '\n' ' ' |
    sed 's/ $//'
}
expect() {  # WANT ARGS...
  local want=$1
  shift
  local got
  got=$(counts "$@")
  [ "$got" = "$want" ] || { cat "$tmp/err.txt"; fail "$* gives '$got', expected '$want'"; }
}
for engine in jit interp; do
  expect "instances 8 triangles 96" "$tmp/two.cga" --lots "$tmp/lots.geojson" --engine $engine
  expect "instances 8 triangles 96" "$tmp/two.cga" --lots "$tmp/lots.geojson" --engine $engine --start-rule Lot
  expect "instances 4 triangles 48" "$tmp/two.cga" --lots "$tmp/lots.geojson" --engine $engine --start-rule Other
  # The default lot, 20 m a side.
  expect "instances 4 triangles 48" "$tmp/two.cga" --engine $engine
  expect "instances 2 triangles 24" "$tmp/two.cga" --engine $engine --start-rule Other
done
"$fgsg" check "$tmp/two.cga" --start-rule Other >"$tmp/check.txt" 2>&1 || { cat "$tmp/check.txt"; fail "check --start-rule Other"; }
grep -q "two.cga: ok" "$tmp/check.txt" || { cat "$tmp/check.txt"; fail "check does not say ok"; }

# Another start rule is no dead code (#43/#44): with --start-rule Other, the @StartRule Lot
# (and what only it reaches, Mid) gets no W002 in check or run; Param, which no start rule
# reaches, still does.
cat >"$tmp/three.cga" <<'CGA'
version "2023.0"
@StartRule
Lot --> split(x) { 5 : Mid }*
Mid --> A
Other --> split(x) { 10 : A }*
Param(n) --> A
A --> extrude(3) Mass
CGA
for cmd in check run; do
  [ $cmd = run ] && extra=(-o "$tmp/three.obj") || extra=()
  "$fgsg" $cmd "$tmp/three.cga" --start-rule Other "${extra[@]}" >"$tmp/w.txt" 2>&1 || { cat "$tmp/w.txt"; fail "$cmd --start-rule Other"; }
  ! grep -E "W002.*'(Lot|Mid)'" "$tmp/w.txt" || fail "$cmd --start-rule Other warns W002 on the @StartRule's rules"
  grep -qF "three.cga:6:1: warning[W002]: the rules for 'Param' can never apply" "$tmp/w.txt" ||
    { cat "$tmp/w.txt"; fail "$cmd --start-rule Other: no W002 for Param, which nothing reaches"; }
done
# A rule the file lacks: E803 naming it, with the rules that could start (the @StartRule first).
"$fgsg" run "$tmp/two.cga" --lots "$tmp/lots.geojson" --start-rule Nope -o "$tmp/x.obj" >"$tmp/nope.txt" 2>&1
rc=$?
[ $rc = 1 ] || { cat "$tmp/nope.txt"; fail "--start-rule Nope exits $rc, expected 1"; }
grep -qF "two.cga:1:1: error[E803]: --start-rule Nope: the start rule 'Nope' is not a rule of this file; rules that can start: Lot (@StartRule), A, Other" \
  "$tmp/nope.txt" || { cat "$tmp/nope.txt"; fail "no E803 for a missing rule"; }
[ ! -e "$tmp/x.obj" ] || fail "a mesh written despite the error"
"$fgsg" check "$tmp/two.cga" --start-rule Nope >"$tmp/nope2.txt" 2>&1 && fail "check passes --start-rule Nope"
grep -qF "error[E803]: --start-rule Nope" "$tmp/nope2.txt" || { cat "$tmp/nope2.txt"; fail "check: no E803"; }
# A rule with parameters cannot start.
"$fgsg" run "$tmp/two.cga" --start-rule Param -o "$tmp/x.obj" >"$tmp/param.txt" 2>&1 && fail "--start-rule Param runs"
grep -qF "error[E803]: --start-rule Param: the start rule 'Param' takes parameters: a start shape has none to give" \
  "$tmp/param.txt" || { cat "$tmp/param.txt"; fail "no E803 for a rule with parameters"; }
# An fgsg grammar starts from its axiom: --start-rule is an error there.
printf 'axiom: A;\nA -> B;\n' >"$tmp/g.fgsg"
"$fgsg" run "$tmp/g.fgsg" --start-rule A -o "$tmp/x.obj" >"$tmp/fgsg.txt" 2>&1 && fail "--start-rule runs an fgsg grammar"
grep -qF "g.fgsg:1:1: error[E803]: --start-rule A: only a .cga grammar (CityEngine CGA) has a start rule to choose" \
  "$tmp/fgsg.txt" || { cat "$tmp/fgsg.txt"; fail "no E803 for an fgsg grammar"; }
# The flag needs its value: a usage error.
"$fgsg" run "$tmp/two.cga" --start-rule >"$tmp/usage.txt" 2>&1
rc=$?
[ $rc = 2 ] || { cat "$tmp/usage.txt"; fail "--start-rule without a name exits $rc, expected 2"; }
echo "cga start rule: ok"
