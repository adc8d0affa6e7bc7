#!/usr/bin/env bash
# fgsg run --lines: the line graph (FGSG §4.4, Fig. 10) as JSON — every segment the
# derivation counted, each line with its symbol, width and merge flag; a joined line
# ends on another's centreline; no lines, an empty list; a wrong name is a usage error.
. "$(dirname "$0")/../reliability/lib.sh"

"$fgsg" run "$root/examples/fig10_line_merging.fgsg" -o "$tmp/l.glb" --lines "$tmp/lines.json" --stats \
  >"$tmp/stats" 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "fgsg run --lines failed"; }
segments=$(awk '$1 == "line.segments" { print $2 }' "$tmp/stats")
python3 - "$tmp/lines.json" "$segments" <<'PY' || fail "the line graph is not what was derived"
import json, math, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "fgsg-lines" and d["version"] == 1
lines = d["lines"]
assert sum(len(l["points"]) - 1 for l in lines) == int(sys.argv[2]), "segment count"
assert all(l["symbol"] and l["width"] > 0 and len(l["points"]) >= 2 for l in lines)
# A merged line that ended on another one: its last point lies on that one's centreline.
def dist_to_segment(p, a, b):
    ab = [y - x for x, y in zip(a, b)]; ap = [y - x for x, y in zip(a, p)]
    t = max(0.0, min(1.0, sum(u * v for u, v in zip(ab, ap)) / max(sum(u * u for u in ab), 1e-300)))
    return math.dist(p, [x + t * u for x, u in zip(a, ab)])
on_other = 0
for i, l in enumerate(lines):
    end = l["points"][-1]
    for j, m in enumerate(lines):
        if j != i and any(dist_to_segment(end, m["points"][k], m["points"][k + 1]) < 1e-9
                          for k in range(len(m["points"]) - 1)):
            on_other += 1
            break
assert on_other > 0, "no line ends on another"
PY
"$fgsg" run "$root/examples/koch.fgsg" -o "$tmp/k.glb" --lines "$tmp/none.json" 2>/dev/null || fail "a grammar without lines failed"
python3 -c "import json,sys; assert json.load(open(sys.argv[1]))['lines'] == []" "$tmp/none.json" || fail "no lines: not an empty list"
expect 2 "written as JSON" -- "$fgsg" run "$root/examples/koch.fgsg" -o "$tmp/k.glb" --lines "$tmp/lines.txt"
echo "ok: lines export"
