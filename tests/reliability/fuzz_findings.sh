#!/usr/bin/env bash
# Inputs the fuzzers (fuzz/, scripts/fuzz.sh) found, minimized: each must end with a
# located error, never a crash or a hang.
. "$(dirname "$0")/lib.sh"
surface_grammar="$root/examples/fig4_on_surface.fgsg"

# fuzz_mesh: a PLY header without 'end_header' (a truncated file) made OpenMesh's PLY
# reader loop forever at the end of the file, printing "Unsupported entry type".
# (The truncated one also holds a NUL byte in its header, which is reported first.)
for input in fuzz_ply_no_end_header.ply fuzz_ply_truncated_header.ply; do
  message="$input: the PLY header has no 'end_header' line"
  [ $input = fuzz_ply_truncated_header.ply ] && message="$input:4: the PLY header holds the control byte 0x00"
  for engine in interp jit; do
    expect 1 "$message" -- \
      "$fgsg" run "$surface_grammar" --surface "$inputs/$input" --engine=$engine -o "$tmp/x.obj"
  done
  same_message "$fgsg" run "$surface_grammar" --surface "$inputs/$input" --engine=interp -o "$tmp/x.obj"
done

# fuzz_mesh on main after the PLY header check (runtime/io/check_ply.cpp) landed: a format
# line without a readable version ("format ascii", "format ascii \xef1.0") passes the
# check, and OpenMesh's PLY reader then loops forever reading the header.
for input in fuzz_ply_format_without_version.ply fuzz_ply_format_bad_version.ply; do
  expect 1 "$input:2: .*format" -- \
    "$fgsg" run "$surface_grammar" --surface "$inputs/$input" --engine=interp -o "$tmp/x.obj"
done

# fuzz_mesh (2026-12-02, the filters gone): a control byte in a PLY header line (here a
# form feed inside an element name) splits words for OpenMesh's reader but not for the
# header check, and OpenMesh then loops forever on the header.
for engine in interp jit; do
  expect 1 "fuzz_ply_form_feed_in_header.ply:7: the PLY header holds the control byte 0x0c, which is not text" -- \
    "$fgsg" run "$surface_grammar" --surface "$inputs/fuzz_ply_form_feed_in_header.ply" --engine=$engine -o "$tmp/x.obj"
done

# fuzz_synthesis_example (2026-12-02): a grid cell named `layer` became a label of that
# name, and the grid written back as fgsg-labels could not be read again (E703 there).
expect 1 "fuzz_grid_cell_named_layer.txt:4:3: error\[E703\]: .layer. is a keyword, not a label name" -- \
  "$fgsg" synth "$inputs/fuzz_grid_cell_named_layer.txt" --size 4 4 1 --labels "$tmp/labels.txt"

# fuzz_mesh: an OBJ face whose corners name no vertex ("f /1 /2 /3", texture indices only)
# trips an assertion in OpenMesh's OBJ reader (OBJReader.cc:633, !vhandles.empty()): the
# whole process aborts (exit 134) in both engines.
for engine in interp jit; do
  expect 1 "fuzz_obj_face_without_vertex.obj:4: " -- \
    "$fgsg" run "$surface_grammar" --surface "$inputs/fuzz_obj_face_without_vertex.obj" --engine=$engine -o "$tmp/x.obj"
done
