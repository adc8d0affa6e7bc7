#!/usr/bin/env bash
# Outputs cut short by the file-size limit (ulimit -f) or out of memory (ulimit -v) are
# errors naming the file, exit 1, the old file untouched; non-finite coordinates never
# reach a file (R005 naming the op, both engines).
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
g="$inputs/outputs_spheres.fgsg"

# ulimit -f 64: 64 KiB, far below the flattened mesh (about 10 MB as OBJ, 3.5 MB as GLB).
for out in big.obj big.glb big.ply; do
  echo "old" > "$out"
  expect 1 "cannot write '$out': File too large" -- bash -c "ulimit -f 64; exec \"\$0\" run \"\$1\" -q --instancing off --group-by none -o \"\$2\"" "$fgsg" "$g" "$out"
  [ "$(cat "$out")" = "old" ] || fail "ulimit -f: $out was replaced"
done
# The default glTF scene instances the spheres (about 24 KB): ulimit -f 8 cuts it.
echo "old" > scene.glb
expect 1 "cannot write 'scene.glb': File too large" -- bash -c "ulimit -f 8; exec \"\$0\" run \"\$1\" -q -o \"\$2\"" "$fgsg" "$g" scene.glb
[ "$(cat scene.glb)" = "old" ] || fail "ulimit -f: scene.glb was replaced"
! ls -a | grep -q '\.tmp\.' || fail "temporaries left: $(ls -a)"

# ulimit -v: under any memory limit the run either writes a whole file (a GLB as long
# as its header declares) or fails and keeps the old one; never a cut file with exit 0
# (before: exit 0 and a GLB cut at a power of two). The limits span failing and success
# for the flattened GLB: the writers stream the mesh to the file through a few MiB, so
# the memory runs out while deriving or assembling (before the streaming writers, also
# while encoding about 60 MB of GLB for 2 million triangles). The default glTF scene
# assembles no flattened mesh (#45) and instances the spheres: it fits under all or
# nearly all of these limits (here from about 90 MB on); each result is checked alike.
g2="$inputs/outputs_many_spheres.fgsg"
failures=0 successes=0
# AddressSanitizer reserves terabytes of address space for its shadow memory, so a build
# with it (scripts/sanitize.sh) cannot start under any ulimit -v: that part is skipped.
# (Since the JIT is a plugin, a run with the interpreter maps no LLVM: it needs less.)
limits="100000 150000 200000 250000 280000 300000 $(seq 350000 50000 1000000)"
if grep -qa __asan_init "$fgsg"; then
  echo "outputs_limits: ulimit -v skipped (an AddressSanitizer build)"
  limits="" failures=1 successes=1
fi
scene_successes=0
for layout in flattened scene; do
  flags=(--instancing off --group-by none)
  [ "$layout" = scene ] && flags=()
  for kib in $limits; do
    echo "old" > mem.glb
    bash -c "ulimit -v $kib; exec \"\$0\" run \"\$1\" -q --engine=interp -o mem.glb \"\${@:2}\"" "$fgsg" "$g2" "${flags[@]}" 2>err
    status=$?
    if [ "$status" -eq 0 ]; then
      size=$(stat -c %s mem.glb)
      declared=$(od -An -tu4 -j8 -N4 mem.glb | tr -d ' ')
      [ "$size" = "$declared" ] || fail "ulimit -v $kib ($layout): exit 0 with $size bytes, header declares $declared"
      if [ "$layout" = flattened ]; then successes=$((successes + 1)); else scene_successes=$((scene_successes + 1)); fi
    else
      [ "$(cat mem.glb)" = "old" ] || fail "ulimit -v $kib ($layout): exit $status but mem.glb was replaced"
      # Out of memory anywhere (deriving, assembling, encoding) is a message and exit 1,
      # never an abort.
      [ "$status" -eq 1 ] || { cat err >&2; fail "ulimit -v $kib ($layout): exit $status, expected 1"; }
      grep -qE "R020|out of memory|cannot write 'mem.glb'" err || { cat err >&2; fail "ulimit -v $kib ($layout): no message"; }
      [ "$layout" = flattened ] && failures=$((failures + 1))
    fi
  done
done
[ "$failures" -gt 0 ] || fail "ulimit -v: no limit made the flattened run fail (try other limits)"
[ "$successes" -gt 0 ] || fail "ulimit -v: no limit let the flattened run succeed"
[ -z "$limits" ] || [ "$scene_successes" -gt 0 ] || fail "ulimit -v: no limit let the scene run succeed"
! ls -a | grep -q '\.tmp\.' || fail "temporaries left: $(ls -a)"

# Coordinates past a 32-bit float's range: a located R005 at the op that placed them.
for engine in interp jit; do
  for input in outputs_scale_huge outputs_extrude_huge; do
    for out in x.obj x.glb; do
      expect 1 "$input.fgsg:1:[0-9]+: error\[R005\]: this instance of 'axiom' reaches coordinate 1e\+308" -- \
        "$fgsg" run "$inputs/$input.fgsg" --engine=$engine -o $out
      [ ! -e $out ] || fail "$input --engine=$engine: $out was written"
    done
  done
done
exit 0
