#!/usr/bin/env bash
# --max-seconds 1 on a mesh ran over by seconds in the phases that read no clock (issue
# 42): laying the ivy's surface out for marching (charts, flattening, packing, the
# geometry image: 7.7 s for the bunny at --atlas-resolution 4096) and, for the
# ornaments, the polycube and the offset surface's first search for intersections. The
# layout and the polycube now run on a worker the limit abandons, and the search asks
# the limit from every thread. A procedural surface made with CGAL's booleans and
# remeshing (FGSG Fig. 17's three tori: about 2 s) is made on such a worker too. Both engines; the derivation ends within a loaded
# machine's margin of the limit and the surface is written.
. "$(dirname "$0")/lib.sh"
skip_under_asan "it times --max-seconds"
export FGSG_CACHE_DIR=off
meshes="$root/tests/data/meshes"
stopped='warning\[R004\]: derivation stopped after 1\.0+ s \(--max-seconds\); the shapes derived so far are kept'

# run_within SECONDS NAME -- COMMAND...: R004, exit 0, the whole command within SECONDS
# and its time.derive under 1.6 s for --max-seconds 1 (unloaded: about 1.1).
run_within() {
  local limit=$1 name=$2 t0 took derive
  shift 3
  t0=$(date +%s.%N)
  expect 0 "$stopped" -- "$@" --max-seconds 1 --stats -o "$tmp/$name.glb"
  took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  awk -v t="$took" -v l="$limit" 'BEGIN { exit !(t < l) }' || fail "$name took $took s, more than $limit s"
  derive=$(awk '$1 == "time.derive" { print $2 }' "$tmp/out")
  awk -v d="$derive" 'BEGIN { exit !(d >= 1.0 && d < 1.6) }' || fail "$name: time.derive $derive for --max-seconds 1"
  [ -s "$tmp/$name.glb" ] || fail "$name: the kept result was not written"
}

for engine in interp jit; do
  run_within 5 "ivy_$engine" -- "$fgsg" run "$root/examples/ivy.fgsg" --engine "$engine" \
    --surface "$meshes/bunny00.off" --surface-size 2 --seed-points 0,1,0.3 --atlas-resolution 4096
  run_within 5 "ornaments_$engine" -- "$fgsg" run "$root/examples/evolve_ornaments.fgsg" --engine "$engine" \
    --surface "$meshes/refined_elephant.off"
  run_within 5 "three_tori_$engine" -- "$fgsg" run "$root/examples/fig17_three_tori.fgsg" --engine "$engine"
done
exit 0
