#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang-19 with ASan + UBSan) into build-fuzz/ and runs
# each for its share of MINUTES (default 10), then prints executions, speed, coverage and
# findings per target. Findings (crash-*, timeout-*, oom-*, leak-* inputs) are kept in
# build-fuzz/findings/<target>/, the growing corpora in build-fuzz/corpus/<target>/.
#
#   scripts/fuzz.sh [MINUTES]
#   FUZZ_TARGETS="fuzz_frontend" scripts/fuzz.sh 60      # one target for the whole hour
#   FUZZ_SANITIZE=0 scripts/fuzz.sh 60                   # coverage only (build-fuzz-fast/):
#                                                        # more executions, no memory checks
#   FUZZ_RUNS=1000000 FUZZ_TARGETS="fuzz_lots fuzz_image" scripts/fuzz.sh 120
#                                     # each target until 10^6 executions (or its share of time)
#   FUZZ_BUILD=0 FUZZ_TAG=b FUZZ_TARGETS=fuzz_imports scripts/fuzz.sh 60
#                                     # no configure/build (another run did it): a second run
#                                     # beside the first, its summary in fuzz-summary-b.txt
# FUZZ_RSS_MB and FUZZ_MALLOC_MB (default 2048 each) bound each process's resident memory
# and any single allocation: a reader must refuse what would need more.
#
# A target that stops on a finding is restarted for the rest of its time, so one run can
# report several. docs/testing.md describes the targets and their oracles.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-fuzz"
sanitize=ON
if [ "${FUZZ_SANITIZE:-1}" = 0 ]; then build="$root/build-fuzz-fast" sanitize=OFF; fi
minutes=${1:-10}
targets=(${FUZZ_TARGETS:-fuzz_frontend fuzz_run fuzz_mesh fuzz_assimp fuzz_lots fuzz_image fuzz_evolve_tiles
          fuzz_synthesis_example fuzz_imports fuzz_view_message})
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
cxx=${FUZZ_CXX:-clang++-19}
cc=${FUZZ_CC:-clang-19}

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
if [ "${FUZZ_BUILD:-1}" != 0 ]; then
cmake -S "$root" -B "$build" -G Ninja -DFGSG_FUZZ=ON -DFGSG_FUZZ_SANITIZE=$sanitize -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" >/dev/null
cmake --build "$build" -j "$jobs" --target "${targets[@]}"
fi

# Seed corpora: every grammar and synthesis example in the tree, the small test meshes,
# images, tile files and lots, and the hand-made ones in fuzz/seeds/ (large files are past
# the targets' size cap).
seed() {  # only for the targets of this run: another run beside it may be reading its own
  [[ " ${targets[*]} " == *" $1 "* ]] || return 0
  local dir="$build/seeds/$1"; shift
  rm -rf "$dir"; mkdir -p "$dir"
  local f
  for f in "$@"; do
    [ -f "$f" ] && [ "$(stat -c %s "$f")" -le 16384 ] && cp "$f" "$dir/$(echo "${f#"$root"/}" | tr / _)"
  done
  return 0
}
shopt -s nullglob
grammars=("$root"/examples/*.fgsg "$root"/tests/cases/*/*.fgsg "$root"/tests/reliability/inputs/*.fgsg
          "$root"/tests/repl/*.script "$root"/bench/*.fgsg "$root"/bench/*/*.fgsg)
seed fuzz_frontend "${grammars[@]}"
seed fuzz_run "${grammars[@]}"
seed fuzz_mesh "$root"/fuzz/seeds/mesh/* "$root"/tests/data/meshes/*.{off,ply,stl,obj} "$root"/tests/reliability/inputs/*.{off,ply,stl,obj}
seed fuzz_synthesis_example "$root"/examples/synthesis/*.{txt,json} "$root"/tests/reliability/inputs/*.json \
  "$root"/tests/unit/synthesis/data/*
seed fuzz_assimp "$root"/fuzz/seeds/assimp/* "$root"/tests/reliability/inputs/*.{gltf,glb,dae,fbx}
seed fuzz_lots "$root"/fuzz/seeds/lots/* "$root"/tests/reliability/inputs/*.geojson
# The city's first lots (the whole file is past the size cap).
[[ " ${targets[*]} " == *" fuzz_lots "* ]] && [ -f "$root/examples/city/lots.geojson" ] && python3 - "$root/examples/city/lots.geojson" "$build/seeds/fuzz_lots/city_head.geojson" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["features"] = d["features"][:6]
open(sys.argv[2], "w").write(json.dumps(d))
PY
seed fuzz_image "$root"/fuzz/seeds/image/* "$root"/examples/*/*.png "$root"/examples/textures/* "$root"/stdlib/*/*.png \
  "$root"/tests/cases/*/*.png "$root"/tests/reliability/inputs/*.png
seed fuzz_evolve_tiles "$root"/fuzz/seeds/evolve_tiles/* "$root"/examples/assets/*tiles*.json "$root"/tests/data/evolve/*.json
seed fuzz_imports "$root"/fuzz/seeds/imports/* "$root"/examples/stdlib_*.fgsg "$root"/tests/cases/*import*/*.fgsg
seed fuzz_view_message "$root"/fuzz/seeds/view_message/*

# allocator_may_return_null=1: an absurd allocation throws std::bad_alloc as in Release,
# which the code must turn into a located error, instead of ending the run.
# malloc_context_size=0: no allocation stacks (a third of the time went to collecting
# them); a finding replayed with the default options shows them.
export ASAN_OPTIONS="allocator_may_return_null=1:max_allocation_size_mb=2048:detect_stack_use_after_return=0:malloc_context_size=0:${ASAN_OPTIONS_EXTRA:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The JIT keeps process-lifetime LLVM state; leak checks there only report LLVM.
declare -A extra=([fuzz_run]="-detect_leaks=0" [fuzz_frontend]="-dict=$root/fuzz/fgsg.dict"
                  [fuzz_imports]="-dict=$root/fuzz/fgsg.dict")
extra[fuzz_run]+=" -dict=$root/fuzz/fgsg.dict"

share=$((minutes * 60 / ${#targets[@]}))
runs_cap=${FUZZ_RUNS:-}
summary="$build/fuzz-summary${FUZZ_TAG:+-$FUZZ_TAG}.txt"
printf '%-24s %12s %9s %8s %8s %8s %9s\n' target executions exec/s seconds cov features findings >"$summary"
for t in "${targets[@]}"; do
  corpus="$build/corpus/$t" findings="$build/findings/$t" log="$build/logs/$t.log"
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  : >"$log"
  start=$SECONDS end=$((SECONDS + share))
  while [ $((end - SECONDS)) -gt 5 ]; do
    # Totals over the restarts: each libFuzzer run ends with "stat::number_of_executed_units".
    runs=$(awk '/stat::number_of_executed_units/ {s += $2} END {print s + 0}' "$log")
    left=""
    if [ -n "$runs_cap" ]; then
      [ "$runs" -lt "$runs_cap" ] || break
      left="-runs=$((runs_cap - runs))"
    fi
    # shellcheck disable=SC2086
    "$build/bin/$t" -max_total_time=$((end - SECONDS)) $left -timeout=10 -rss_limit_mb="${FUZZ_RSS_MB:-2048}" \
      -malloc_limit_mb="${FUZZ_MALLOC_MB:-2048}" -max_len=8192 -print_final_stats=1 -artifact_prefix="$findings/" \
      ${extra[$t]:-} "$corpus" "$build/seeds/$t" >>"$log" 2>&1 || true
  done
  runs=$(awk '/stat::number_of_executed_units/ {s += $2} END {print s + 0}' "$log")
  secs=$((SECONDS - start))
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | awk '{print $2}')
  found=$(find "$findings" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' -o -name 'slow-unit-*' \) | wc -l)
  printf '%-24s %12s %9s %8s %8s %8s %9s\n' "$t" "$runs" "$((runs / (secs > 0 ? secs : 1)))" "$secs" "${cov:-0}" "${ft:-0}" "$found" >>"$summary"
done
cat "$summary"
echo "findings: $build/findings/<target>/ (reproduce: build-fuzz/bin/<target> FILE); logs: $build/logs/"
