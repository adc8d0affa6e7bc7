#!/usr/bin/env bash
# ThreadSanitizer on fgsg's threaded paths (issue 52): builds, with g++ -fsanitize=thread,
# only what those paths need into build-tsan/, then runs a fixed list of tests, path by
# path, and prints per path the tests run and the TSan reports (docs/testing.md).
#
#   scripts/tsan.sh              build, then run every path
#   scripts/tsan.sh --no-build   run only (build-tsan/ is already built)
#   scripts/tsan.sh rewriter c_api ...   only these paths (also after --no-build)
#
# Paths: rewriter (L-system strings rewritten in chunks on all cores), seeds (per-seed
# plants and marches, derived in parallel), assembly (TBB assembly, the writers from many
# threads), python (the package from 16 threads), c_api (libfgsg.so from 8 threads).
#
# TBB: Debian's libtbb is not instrumented, so TSan cannot see a tbb::parallel_for hand its
# work to the workers or take it back, and reports every loop as a race. Instead of
# suppressing every stack through TBB (which would hide real races between workers too),
# the script builds libtbb itself from Debian's source of the same version (onetbb
# 2021.8.0, `apt-get source`, fetched once into build-tsan/tbb-src) with TBB's own
# TBB_SANITIZE=thread, and runs everything with it first on LD_LIBRARY_PATH. Same soname,
# same ABI: nothing of fgsg is rebuilt for it.
#
# Reports do not stop a test (halt_on_error=0): they land in build-tsan/tsan-logs/<path>/
# (one file per process, fgsg compile's and python3's too), and are counted at the end.
# Exit status: 0 when every test passed and no path has a report.
#
# FGSG_TSAN_SOURCE=DIR builds and tests another tree into the same build-tsan/: on a shared
# checkout whose uncommitted edits do not build, a `git worktree add --detach DIR HEAD`
# (link this checkout's tests/data/meshes into it: git ignores that folder).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build-tsan"
src="${FGSG_TSAN_SOURCE:-$root}"
jobs=${JOBS:-2}
do_build=1
if [ "${1:-}" = "--no-build" ]; then
  do_build=0
  shift
fi
all_paths=(rewriter seeds assembly python c_api)
paths=("$@")
[ ${#paths[@]} = 0 ] && paths=("${all_paths[@]}")

tbb_lib="$build/tbb/lib"
build_tbb() {
  [ -e "$tbb_lib/libtbb.so.12" ] && return 0
  local tsrc="$build/tbb-src"
  if [ ! -d "$tsrc" ]; then
    # Debian's source package of the libtbb12 installed (bookworm: 2021.8.0-2+deb12u1),
    # with a private source list, so the system's apt configuration is left alone.
    local version apt="$build/tbb-apt"
    version=$(dpkg-query -W -f='${Version}' libtbb12)
    mkdir -p "$apt/lists/partial" "$apt/archives/partial"
    printf 'deb-src http://deb.debian.org/debian bookworm main\ndeb-src http://deb.debian.org/debian-security bookworm-security main\n' \
      >"$apt/sources.list"
    local opts=(-o Dir::Etc::SourceList="$apt/sources.list" -o Dir::Etc::SourceParts=/dev/null
                -o Dir::State::Lists="$apt/lists" -o Dir::Cache::Archives="$apt/archives" -o Debug::NoLocking=1)
    apt-get "${opts[@]}" update >/dev/null
    (cd "$apt" && apt-get "${opts[@]}" source --download-only "onetbb=$version" >/dev/null)
    dpkg-source -x "$apt"/onetbb_*.dsc "$tsrc" >/dev/null
  fi
  cmake -S "$tsrc" -B "$build/tbb-build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ "${launcher[@]}" \
    -DTBB_SANITIZE=thread -DTBB_TEST=OFF -DTBB_EXAMPLES=OFF -DTBBMALLOC_BUILD=OFF -DTBB_STRICT=OFF \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" >/dev/null
  # Its log is long with GCC's "atomic_thread_fence is not supported with -fsanitize=thread".
  nice -n 15 cmake --build "$build/tbb-build" -j "$jobs" --target tbb >"$build/tbb-build.log" 2>&1 ||
    { tail -20 "$build/tbb-build.log" >&2; exit 1; }
  mkdir -p "$tbb_lib"
  cp -a "$build/tbb-build"/*/libtbb.so* "$tbb_lib"/
}

# The build: flags as scripts/sanitize.sh's, but -fsanitize=thread; only these targets.
flags="-fsanitize=thread -fno-omit-frame-pointer -g1"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
targets=(test_backend test_runtime test_marching test_c_api fgsg fgsg_shared fgsg_python fgsg_llvm_plugin
         fgsg_fcl_plugin run_library)
if [ "$do_build" = 1 ]; then
  start=$(date +%s)
  build_tbb
  cmake -S "$src" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER=gcc -DCMAKE_CXX_COMPILER=g++ "${launcher[@]}" \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_C_FLAGS_RELEASE="-O1 -DNDEBUG" \
    -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=thread" >/dev/null
  # nice: the machine is shared; the build takes spare cycles.
  nice -n 15 cmake --build "$build" -j "$jobs" --target "${targets[@]}"
  echo "tsan: build took $(( $(date +%s) - start )) s"
fi
[ -e "$tbb_lib/libtbb.so.12" ] || { echo "tsan: no instrumented libtbb in $tbb_lib (run without --no-build)" >&2; exit 2; }

libtsan=$(g++ -print-file-name=libtsan.so)
logs="$build/tsan-logs"
bin="$build/bin"
export LD_LIBRARY_PATH="$tbb_lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export FGSG_SOURCE="$src" FGSG_BINARY="$bin/fgsg"
# The examples' assets are found from the source tree; keep the JIT cache out of $HOME.
export XDG_CACHE_HOME="$build/tsan-cache"

# run PATH COMMAND...: one test command of a path, under TSan, its output in
# $logs/PATH.out and every process's reports in $logs/PATH/tsan.<pid>.
run() {
  local path=$1
  shift
  mkdir -p "$logs/$path"
  export TSAN_OPTIONS="suppressions=$root/scripts/tsan.supp halt_on_error=0 second_deadlock_stack=1 \
print_suppressions=1 exitcode=66 log_path=$logs/$path/tsan"
  echo "\$ $*" >>"$logs/$path.out"
  local rc=0
  timeout 3600 "$@" >>"$logs/$path.out" 2>&1 || rc=$?
  # 66: reports were made (counted below); anything else non-zero is a failed test.
  if [ "$rc" != 0 ] && [ "$rc" != 66 ]; then
    echo "tsan: [$path] FAILED (exit $rc): $*" >&2
    failed[$path]=1
  fi
}

declare -A failed
mkdir -p "$logs"
for path in "${paths[@]}"; do
  rm -rf "${logs:?}/$path" "$logs/$path.out"  # this path's last run; the others' stay
  t0=$(date +%s)
  case "$path" in
    rewriter)  # the chunked rewrite on 1, 2 and 4 threads against the one-thread loop, and every L-system test
      run rewriter "$bin/test_backend" '[parallel],[lsystem]' ;;
    seeds)  # plants per seed on the TBB pool, marches from many threads, geometry images built in parallel
      run seeds "$bin/test_backend" '[seeds],[marching]'
      run seeds "$bin/test_marching" 'marches from many threads at once give the answers of one thread,[image],[atlas]' ;;
    assembly)  # TBB assembly (counted, then written in place), bent assembly, writers and readers from many threads
      run assembly "$bin/test_runtime" '[assemble],threads writing the same path all succeed and leave one whole result,OBJ files read from many threads at once'
      run assembly "$bin/test_marching" '[assemble]' ;;
    python)  # python3 is not instrumented: the TSan runtime is preloaded, as libasan is under ASan
      run python env LD_PRELOAD="$libtsan" PYTHONPATH="$build/python" /usr/bin/python3 -m pytest -q -p no:cacheprovider \
        "$src/tests/python/test_threads.py" \
        "$src/tests/python/test_fgsg.py::test_threads_derive_concurrently_with_the_sequential_results" ;;
    c_api)  # the unit tests' thread cases, then a C program: 8 threads generate, then write one path
      run c_api "$bin/test_c_api" '[threads],two generators in two threads give the bytes of one generator run twice,a deep grammar derives on a host thread with a 256 KiB stack*'
      work="$build/tsan-c-api"
      rm -rf "$work" && mkdir -p "$work"
      gcc -fsanitize=thread -O1 -g1 -std=gnu11 -I"$src" "$src/tests/aot/c_api_threads.c" -o "$work/c_api_threads" \
        -L"$build/lib" -lfgsg -ldl -lpthread -Wl,-rpath,"$build/lib"
      run c_api "$bin/fgsg" compile "$src/examples/stem_leaf.fgsg" -o "$work/libstem_leaf.so" --quiet
      run c_api env -C "$work" ./c_api_threads "$work/libstem_leaf.so" fgsg_program_stem_leaf 8 1 ;;
    *) echo "tsan: unknown path '$path' (${all_paths[*]})" >&2; exit 2 ;;
  esac
  secs=$(( $(date +%s) - t0 ))
  # Catch2 ends "All tests passed (A assertions in N test cases)" or "test cases: N | ...";
  # pytest "N passed"; the C program "mismatches 0".
  cases=$(grep -hoE 'in [0-9]+ test cases?|test cases: +[0-9]+|[0-9]+ passed in|mismatches [0-9]+' "$logs/$path.out" |
          sed -E 's/in ([0-9]+) test cases?/\1 Catch2 cases/; s/test cases: +([0-9]+)/\1 Catch2 cases/; s/([0-9]+) passed in/\1 pytest/; s/mismatches ([0-9]+)/C program: \1 mismatches/' |
          paste -sd+ | sed 's/+/, /g' || true)
  reports=$(cat "$logs/$path"/tsan.* 2>/dev/null | grep -c '^WARNING: ThreadSanitizer' || true)
  suppressed=$( (cat "$logs/$path"/tsan.* 2>/dev/null | grep -oE 'Matched [0-9]+ suppressions' || true) |
               awk '{ s += $2 } END { print s + 0 }')
  echo "tsan: [$path] ${cases:-no tests counted}; $reports TSan reports, $suppressed suppressed matches; ${failed[$path]:+FAILED; }$secs s"
done
status=0
for path in "${paths[@]}"; do
  [ -n "${failed[$path]:-}" ] && status=1
  [ "$(cat "$logs/$path"/tsan.* 2>/dev/null | grep -c '^WARNING: ThreadSanitizer' || true)" = 0 ] || status=1
done
echo "tsan: reports in $logs/<path>/tsan.*; $([ $status = 0 ] && echo 'clean' || echo 'NOT CLEAN')"
exit $status
