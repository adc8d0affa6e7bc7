#!/usr/bin/env bash
# Broken and forged mesh files given as --surface end at once, with both engines, in one
# located message that is the same on every run (they used to abort on bad_alloc, hang, or
# read uninitialised memory); a valid OFF with a comment after the counts loads.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
grammar="$inputs/readers_surface_grammar.fgsg"

# One triangle repeated 200 000 times (duplicate handling was quadratic: a hang).
{ echo OFF; echo "4 200004 0"; echo "0 0 0"; echo "1 0 0"; echo "0 1 0"; echo "0 0 1"
  awk 'BEGIN { for (i = 0; i < 200000; i++) print "3 0 1 2"
               print "3 0 2 3"; print "3 0 3 1"; print "3 1 3 2"; print "3 0 2 1" }'
} >"$tmp/repeated.off"

check() {  # FILE REGEX: exit 1 with REGEX for both engines, the same message each run
  local file=$1 pattern=$2
  for engine in interp jit; do
    expect 1 "$pattern" -- "$fgsg" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
    same_message "$fgsg" run "$grammar" --surface "$file" --engine=$engine -o "$tmp/x.obj"
  done
}
check "$inputs/readers_05_off_header_only.off" \
  'readers_05_off_header_only\.off: the file ends before the vertex and face counts$'
check "$inputs/readers_06_off_counts_negative.off" \
  'readers_06_off_counts_negative\.off:2: the vertex count -1 is negative$'
check "$inputs/readers_07_off_counts_huge.off" \
  'readers_07_off_counts_huge\.off:2: the header declares 1000000000 vertices and 0 faces, more than the 0 bytes after it can hold$'
check "$inputs/readers_08_ply_huge_vertex_count.ply" \
  'readers_08_ply_huge_vertex_count\.ply:3: the header declares 2000000000 vertex elements, more than the 0 bytes after the header can hold$'
check "$inputs/readers_09_off_face_negative_corner_count.off" \
  'readers_09_off_face_negative_corner_count\.off:6: face 0 has -3 corners \(a face needs at least 3\)$'
check "$tmp/repeated.off" \
  'repeated\.off: and 199990 more: 199990 duplicate faces$'

# The repeated triangle is repaired (a sort, not pairwise comparison) well within the limit.
start=$(date +%s%N)
expect 0 'wrote' -- "$fgsg" run "$grammar" --surface "$tmp/repeated.off" --repair-surface -o "$tmp/x.obj"
ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$ms" -lt 20000 ] || fail "repairing 200 000 repeated faces took $ms ms"

# A comment line after the counts (as in CGAL's cube_poly.off) is skipped: the triangle loads.
for engine in interp jit; do
  expect 0 'wrote .*x\.obj' -- "$fgsg" run "$grammar" --surface "$inputs/readers_13_off_comment_in_body.off" \
    --engine=$engine -o "$tmp/x.obj"
done

# A mesh name that is a device, a FIFO or a directory is refused by what it is.
mkfifo "$tmp/fifo.off"
ln -s /dev/zero "$tmp/zero.off"
expect 1 'fifo\.off: is a FIFO \(named pipe\), not a mesh file' -- \
  "$fgsg" run "$grammar" --surface "$tmp/fifo.off" -o "$tmp/x.obj"
expect 1 "zero\.off: is a symbolic link to '/dev/zero', a character device, not a mesh file" -- \
  "$fgsg" run "$grammar" --surface "$tmp/zero.off" -o "$tmp/x.obj"
mkdir "$tmp/dir.off"
expect 1 'dir\.off: is a directory, not a mesh file' -- \
  "$fgsg" run "$grammar" --surface "$tmp/dir.off" -o "$tmp/x.obj"
exit 0
