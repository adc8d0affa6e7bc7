#!/usr/bin/env bash
# The examples' painted masks live in their meshes' generated atlases: repainted now, they
# must be the committed bytes, or a changed atlas builder has left them stale (repaint
# with scripts/paint-example-masks.sh and look at the examples again).
. "$(dirname "$0")/lib.sh"
export FGSG_CACHE_DIR="$tmp/cache"
"$root/scripts/paint-example-masks.sh" "$fgsg" "$tmp" || fail "painting the masks failed"
for mask in fig10b_bunny_forbidden.png fig10c_elephant_path.png; do
  cmp -s "$tmp/$mask" "$root/examples/assets/$mask" ||
    fail "examples/assets/$mask is stale: the atlas of its mesh changed; run scripts/paint-example-masks.sh"
done
echo "ok: $test_name"
