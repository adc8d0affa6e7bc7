#!/usr/bin/env bash
# Where fgsg run says R020 (memory ran out assembling the instances into one mesh), the
# Python package raised a bare MemoryError('std::bad_alloc') (issue 42): it now carries
# the CLI's R020 message and names the limit that was met (here ulimit -v). 16 383 tori,
# 25 M triangles, under address-space limits from one that lets Python and fgsg load to
# one past what the mesh needs.
. "$(dirname "$0")/lib.sh"
export FGSG_CACHE_DIR=off
build=${3:?binary dir}
export PYTHONPATH="$build/python"
if grep -qa __asan_init "$fgsg"; then
  echo "limits_memory_python: skipped (AddressSanitizer reserves terabytes of address space)"
  exit 0
fi
if ! python3 -c 'import fgsg' 2>/dev/null; then
  echo "limits_memory_python: skipped (the fgsg Python package is not built in $build/python)"
  exit 0
fi
cat >"$tmp/run.py" <<'P'
import sys, fgsg
grammar = fgsg.Grammar.from_file(sys.argv[1])
try:
    result = grammar.generate(seed=1)
    print("ok", result)
except MemoryError as e:
    print("MemoryError:", e)
P
memory_errors=0 written=0
for kib in $(seq 400000 100000 1300000); do
  bash -c "ulimit -v $kib; exec python3 \"\$0\" \"\$1\"" "$tmp/run.py" "$inputs/limits_assembly_tori.fgsg" \
    >"$tmp/py" 2>"$tmp/err"
  grep -q "^ok" "$tmp/py" && { written=$((written + 1)); continue; }
  grep -q "^MemoryError:" "$tmp/py" || continue  # too little to start Python at all
  grep -qE '^MemoryError: R020: out of memory assembling 16383 instances into one mesh \(the address-space limit \(ulimit -v\) of [0-9.]+M; [0-9.]+[MG] in use\); nothing was kept$' "$tmp/py" ||
    { cat "$tmp/py" "$tmp/err" >&2; fail "under ulimit -v $kib: a MemoryError without R020 and its limit"; }
  memory_errors=$((memory_errors + 1))
done
[ "$memory_errors" -gt 0 ] || fail "no limit made the assembly run out of memory (try lower limits)"
echo "limits_memory_python: $memory_errors MemoryErrors with their limit, $written results"
exit 0
