#!/usr/bin/env bash
# Continuous synthesis reads its example's vertex figures (the inside/outside just off
# every edge and vertex) before the assignment; that was a solid-angle sum over every
# face for every point, before any limit was asked (issue 42, S1): 4 000 coplanar quads
# took 7.3 s with --time-limit 2, 25 000 more than two minutes. The figures now come
# from a ray test through a grid and ask the limit as they go, as does the arrangement
# of the output's planes (houses.obj in 200 x 200 x 40 took 4.3 s with --time-limit 1).
# Bounds are loose (a loaded 2-core machine) but far below what the examples took.
. "$(dirname "$0")/lib.sh"
skip_under_asan "it times --max-seconds"
export FGSG_CACHE_DIR=off

# cube N FILE: the unit cube, each side cut into N x N quads (6 N^2 coplanar quads).
cube() {
  python3 - "$1" "$2" <<'P'
import sys
n, path = int(sys.argv[1]), sys.argv[2]
index, lines, faces = {}, [], []
def v(p):
    if p not in index:
        index[p] = len(index) + 1
        lines.append("v %g %g %g" % tuple(c / n for c in p))
    return index[p]
for axis in range(3):
    for side in (0, n):
        for i in range(n):
            for j in range(n):
                def at(a, b):
                    p = [0, 0, 0]
                    p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = side, a, b
                    return tuple(p)
                quad = [v(at(i, j)), v(at(i + 1, j)), v(at(i + 1, j + 1)), v(at(i, j + 1))]
                faces.append(quad if side else quad[::-1])
with open(path, "w") as f:
    f.write("\n".join(lines) + "\n")
    for q in faces:
        f.write("f %d %d %d %d\n" % tuple(q))
P
}

within() {  # within SECONDS CODE PATTERN -- COMMAND...
  local limit=$1 code=$2 pattern=$3 t0 took
  shift 4
  t0=$(date +%s.%N)
  expect "$code" "$pattern" -- "$@"
  took=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  awk -v t="$took" -v l="$limit" 'BEGIN { exit !(t < l) }' || fail "'$*' took $took s, more than $limit s"
}

cube 26 "$tmp/cube26.obj"    # 4 056 quads: was 7 s
cube 65 "$tmp/cube65.obj"    # 25 350: was minutes
cube 150 "$tmp/cube150.obj"  # 135 000: the figures alone take most of a second
# These finish, with the figures of the plain cube (a box has 28).
for n in 26 65; do
  within 10 0 'wrote .* 28 labels\)' -- "$fgsg" synth "$tmp/cube$n.obj" --size 8 8 8 --time-limit 2 -o "$tmp/s$n.obj"
done
# Past the limit while the figures are read: the time limit's error, soon after it (the
# limit counts from the start: reading the file is part of the run).
within 6 1 'error\[E751\]: continuous synthesis failed: stopped by the time limit \(0\.30* s\)' -- \
  "$fgsg" synth "$tmp/cube150.obj" --size 8 8 8 --time-limit 0.3 -o "$tmp/s150.obj"
[ ! -e "$tmp/s150.obj" ] || fail "a synthesis stopped by its limit wrote a mesh"
# Past the limit while the output's planes are arranged (200 x 200 x 40: seconds).
within 4 1 'stopped by the time limit \(1\.0+ s\)' -- \
  "$fgsg" synth "$root/examples/synthesis/continuous/houses.obj" --size 200 200 40 --time-limit 1 -o "$tmp/h.obj"
exit 0
