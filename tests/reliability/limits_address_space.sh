#!/usr/bin/env bash
# Under a tight address-space limit (ulimit -v) every example that starts either runs or
# fails with "out of memory" and exit 1, whatever ran out: a worker thread TBB could not
# start (was "internal error: pthread_create has failed"), FCL's collision trees (an
# unchecked failed build crashed the first query), the derivation, the assembly. The
# limits span the first that lets the libraries load to well past what each example needs.
. "$(dirname "$0")/lib.sh"
export FGSG_CACHE_DIR=off
if grep -qa __asan_init "$fgsg"; then
  echo "limits_address_space: skipped (AddressSanitizer reserves terabytes of address space)"
  exit 0
fi
failures=0 successes=0
for example in stem_leaf ivy_fig10b_forbidden fig10_line_merging; do
  for kib in $(seq 280000 10000 400000); do
    bash -c "ulimit -v $kib; exec \"\$0\" run \"\$1\" -q -o \"\$2\"" "$fgsg" "$root/examples/$example.fgsg" \
      "$tmp/out.glb" >/dev/null 2>"$tmp/err"
    status=$?
    grep -q "error while loading shared libraries" "$tmp/err" && continue  # too little to start at all
    if [ "$status" -eq 0 ]; then
      successes=$((successes + 1))
      continue
    fi
    [ "$status" -eq 1 ] || { cat "$tmp/err" >&2; fail "$example under ulimit -v $kib: exit $status, expected 1"; }
    grep -qE "R020|out of memory" "$tmp/err" || { cat "$tmp/err" >&2; fail "$example under ulimit -v $kib: no out-of-memory message"; }
    ! grep -q "internal error" "$tmp/err" || { cat "$tmp/err" >&2; fail "$example under ulimit -v $kib: blamed on an internal error"; }
    failures=$((failures + 1))
  done
done
[ "$failures" -gt 0 ] || fail "no limit made a run fail (try lower limits)"
[ "$successes" -gt 0 ] || fail "no limit let a run succeed (try higher limits)"
echo "limits_address_space: $failures out-of-memory failures, $successes runs written"
exit 0
