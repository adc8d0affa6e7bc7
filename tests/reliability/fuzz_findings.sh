#!/usr/bin/env bash
# Inputs the fuzzers (fuzz/, scripts/fuzz.sh) found, minimized: each must end with a
# located error, never a crash or a hang.
. "$(dirname "$0")/lib.sh"
surface_grammar="$root/examples/fig4_on_surface.fgsg"

# fuzz_mesh: a PLY header without 'end_header' (a truncated file) made OpenMesh's PLY
# reader loop forever at the end of the file, printing "Unsupported entry type".
for input in fuzz_ply_no_end_header.ply fuzz_ply_truncated_header.ply; do
  for engine in interp jit; do
    expect 1 "$input: the PLY header has no 'end_header' line" -- \
      "$fgsg" run "$surface_grammar" --surface "$inputs/$input" --engine=$engine -o "$tmp/x.obj"
  done
  same_message "$fgsg" run "$surface_grammar" --surface "$inputs/$input" --engine=interp -o "$tmp/x.obj"
done
