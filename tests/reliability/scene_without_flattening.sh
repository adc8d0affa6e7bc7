#!/usr/bin/env bash
# A run that writes only scenes assembles no flattened mesh (#45): 65 535 tori, whose
# flattened mesh alone needs about 3 GB (65 535 x 1 536 triangles x 12 bytes of indices,
# 1.2 GB, and the vertices' positions, normals and colours, 36 bytes each, more), are
# written as the default glTF scene (one torus placed 65 535 times), as a .gltf and as
# per-lot files under an address-space limit of 1.5 GB that the flattened mesh cannot
# fit: were it assembled again, the run would end with R020 (out of memory assembling
# 65535 instances into one mesh), exit 1. What needs the flattened mesh (a flattened -o,
# --stats) still assembles it and runs out there, as before. Memory, not time.
. "$(dirname "$0")/lib.sh"
skip_under_asan "it runs under ulimit -v (AddressSanitizer reserves terabytes)"
export FGSG_CACHE_DIR=off
# One malloc arena per thread reserves 64 MB of address space: a many-core machine would
# spend the limit on arenas, not on the mesh.
export MALLOC_ARENA_MAX=2
g="$inputs/scene_only_tori.fgsg"
limited=(bash -c 'ulimit -v 1500000 && exec "$0" "$@"' "$fgsg")
# --max-memory far above what the machine has: the derivation's budget (which counts the
# flattened mesh to come, 4 x 3 GB) would otherwise stop it before the assembly.
flags=(--engine interp --max-memory 1T)

# 65 535 instances; 65 535 x 1 536 = 100 661 760 triangles, each torus drawn whole.
wrote='wrote [^ ]+ \(65535 instances, 100661760 triangles\)'
expect 0 "$wrote" -- "${limited[@]}" run "$g" "${flags[@]}" -o "$tmp/tori.glb"
size=$(stat -c %s "$tmp/tori.glb")
declared=$(od -An -tu4 -j8 -N4 "$tmp/tori.glb" | tr -d ' ')
[ "$size" = "$declared" ] || fail "tori.glb has $size bytes, its header declares $declared"
# The scene instances the torus: far below the flattened file's 1.2 GB of indices alone.
[ "$size" -lt 10000000 ] || fail "tori.glb has $size bytes: the torus was not instanced"
expect 0 'wrote [^ ]+/ \(65535 instances, 100661760 triangles\)' -- \
  "${limited[@]}" run "$g" "${flags[@]}" --split-output "$tmp/split"
[ -s "$tmp/split/manifest.json" ] || fail "--split-output wrote no manifest"
expect 0 "$wrote" -- "${limited[@]}" run "$g" "${flags[@]}" -o "$tmp/tori.gltf" --instances "$tmp/tori.json"
[ "$(grep -o '"asset"' "$tmp/tori.json" | wc -l)" -eq 65535 ] || fail "--instances does not list the 65535 tori"

# What needs the flattened mesh still assembles it, and under the same limit runs out.
oom='error\[R020\]: out of memory assembling 65535 instances into one mesh'
expect 1 "$oom" -- "${limited[@]}" run "$g" "${flags[@]}" -o "$tmp/flat.glb" --instancing off --group-by none
expect 1 "$oom" -- "${limited[@]}" run "$g" "${flags[@]}" -o "$tmp/stats.glb" --stats
[ ! -e "$tmp/stats.glb" ] || fail "a run out of memory wrote stats.glb"
exit 0
