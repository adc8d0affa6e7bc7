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

# fuzz_image (2026-12-06): a JPEG Huffman table (DHT) declaring more than 256 codes made
# stb_image 2.27 write past its 257-entry tables (UBSan: stb_image.h:1990, index 257; the
# code values follow 4 KB further), already while reading the header; the second one
# reaches its table past bytes that are no marker (stb_image skips them as padding). Both
# engines read them as an image field, and synth as an example.
cp "$inputs/fuzz_jpeg_huffman_overflow.jpg" "$inputs/fuzz_jpeg_huffman_after_padding.jpg" "$tmp/"
for input in fuzz_jpeg_huffman_overflow fuzz_jpeg_huffman_after_padding; do
  at=6 codes=679
  [ $input = fuzz_jpeg_huffman_after_padding ] && at=21 codes=645
  message="$input\\.jpg: (error\\[[A-Z0-9]+\\]: )?.*the JPEG file is damaged: its Huffman table at byte $at declares $codes codes \\(at most 256\\)"
  printf 'surface plane(8, 8);\nfield P = image("%s.jpg");\naxiom: A(0);\nA(n) : n < 4 ~> S(0.1, 0.1, 0.1 + P.intensity) I("cube") T(0.13, 0, 0) A(n + 1);\n' \
    "$input" >"$tmp/$input.fgsg"
  for engine in interp jit; do
    expect 1 "$message" -- "$fgsg" run "$tmp/$input.fgsg" --engine=$engine -o "$tmp/x.obj"
  done
  cp "$tmp/$input.jpg" "$tmp/$input.png"  # synth reads .png examples, by content
  expect 1 "${message//jpg/png}" -- "$fgsg" synth "$tmp/$input.png" --size 4 4 1 --labels "$tmp/labels.txt"
done

# fuzz_evolve_tiles (2026-12-06): a number too large for a double in a tile file threw
# nlohmann's out_of_range out of the reader: fgsg evolve ended in std::terminate.
expect 1 "fuzz_tiles_number_overflow\\.json:1:1: not valid JSON: the number '5555555555555555500000000000133e625086406' is too large" -- \
  "$fgsg" evolve "$inputs/fuzz_tiles_number_overflow.json" --max-generations 1 --json "$tmp/e.json"

# fuzz_assimp (2026-12-06): a COLLADA <float_array count="0"> that an <accessor> of 4
# elements reads: assimp reads the elements without comparing them with the array's size
# (an empty array: a null pointer) and fgsg died of SIGSEGV in both engines.
for engine in interp jit; do
  expect 1 "fuzz_dae_accessor_empty_array\\.dae:6: an <accessor> of 4 elements \\(stride 3, offset 0, 3 params\\) reads 12 values of <float_array> 'pa', which holds 0" -- \
    "$fgsg" run "$surface_grammar" --surface "$inputs/fuzz_dae_accessor_empty_array.dae" --engine=$engine -o "$tmp/x.obj"
done

# fuzz_image (2026-12-06): a 512 x 512 one-bit PNG whose image data uses the distance code
# 30, which deflate does not define: stb_image took it for a distance of 0 and copied
# output bytes not yet written, so the picture differed from run to run (the fuzzer's
# oracle decodes twice). zlib inflates the data first now.
cp "$inputs/fuzz_png_distance_code_30.png" "$tmp/"
printf 'surface plane(8, 8);\nfield P = image("fuzz_png_distance_code_30.png");\naxiom: A(0);\nA(n) : n < 4 ~> S(0.1, 0.1, 0.1 + P.intensity) I("cube") T(0.13, 0, 0) A(n + 1);\n' \
  >"$tmp/png_field.fgsg"
for engine in interp jit; do
  expect 1 "fuzz_png_distance_code_30\\.png: the PNG file is damaged: its image data does not inflate \\(zlib: invalid distance code\\)" -- \
    "$fgsg" run "$tmp/png_field.fgsg" --engine=$engine -o "$tmp/x.obj"
done
expect 1 "fuzz_png_distance_code_30\\.png.*does not inflate" -- \
  "$fgsg" synth "$tmp/fuzz_png_distance_code_30.png" --size 4 4 1 --labels "$tmp/labels.txt"

# fuzz_assimp (2026-12-06): a byte that is not part of a number (here 0xd8) in a COLLADA
# <p> index list: assimp's reader does not advance past it and appends indices until
# memory runs out (38 s and 1.5 GB under a 4 GB limit, then std::bad_alloc; without a
# limit, the machine's memory). Refused before assimp reads the file, with its line; under
# a 4 GB address-space limit (not under ASan, which reserves terabytes of shadow).
limit=(bash -c 'ulimit -v 4000000 && exec "$0" "$@"')
grep -qa __asan_init "$fgsg" && limit=()
for engine in interp jit; do
  expect 1 "fuzz_dae_index_not_a_number\\.dae:8: <p> holds the byte 0xd8, which is not part of a whole number" -- \
    "${limit[@]}" "$fgsg" run "$surface_grammar" --surface "$inputs/fuzz_dae_index_not_a_number.dae" \
    --engine=$engine -o "$tmp/x.obj"
done

# fuzz_assimp (2026-12-06): a NUL byte in a word of an ASCII FBX file stopped the FBX
# pre-check's scanner without advancing (strchr finds its own set's terminator for NUL):
# fgsg hung before assimp saw the file. Now assimp reads it, and refuses it.
for engine in interp jit; do
  expect 1 "fuzz_fbx_nul_in_word\\.fbx: " -- \
    "$fgsg" run "$surface_grammar" --surface "$inputs/fuzz_fbx_nul_in_word.fbx" --engine=$engine -o "$tmp/x.obj"
done
