#!/usr/bin/env bash
# The run set-up's build as a new user meets it (#47): a fresh clone of HEAD built with
# `scripts/build.sh fgsg` (what scripts/setup-and-run.sh builds; the installs are not
# timed: this machine already has them). Reports wall time and processor time; on a
# shared machine the wall time depends on the load, so the processor time over the number
# of cores is the figure to compare with the 8-minute goal (a cold build of 300+ files on
# two cores keeps both busy). Also the ten slowest compile steps, from ninja's log.
#   bench/setup_build_time.sh [SCRATCH_DIR]      (default: a temporary folder, removed after)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
scratch="${1:-$(mktemp -d "${TMPDIR:-/tmp}/fgsg-setup-bench.XXXXXX")}"
[ $# -gt 0 ] || trap 'rm -rf "$scratch"' EXIT
clone="$scratch/fgsg"
rm -rf "$clone"
git clone -q "$root" "$clone"
cores=$(nproc)
load_before=$(cut -d' ' -f1 /proc/loadavg)
/usr/bin/time -o "$scratch/time.txt" -f "%e %U %S" "$clone/scripts/build.sh" fgsg >"$scratch/build.log" 2>&1 || {
  echo "setup_build_time: the build failed; the last lines of its log:" >&2
  tail -20 "$scratch/build.log" >&2
  exit 1
}
read -r wall user sys <"$scratch/time.txt"
steps=$(awk 'NR > 1' "$clone/build/.ninja_log" | wc -l)
printf '{"bench":"setup_build","commit":"%s","cores":%d,"load_before":%s,"load_after":%s,"steps":%d,' \
  "$(git -C "$clone" rev-parse --short HEAD)" "$cores" "$load_before" "$(cut -d' ' -f1 /proc/loadavg)" "$steps"
awk -v w="$wall" -v u="$user" -v s="$sys" -v c="$cores" \
  'BEGIN { printf "\"wall_s\":%.0f,\"cpu_s\":%.0f,\"cpu_over_cores_min\":%.1f,\"goal_min\":8}\n", w, u + s, (u + s) / c / 60 }'
echo "slowest compile steps (wall seconds under the load above):"
awk 'NR > 1 { printf "%8.1f %s\n", ($2 - $1) / 1000, $4 }' "$clone/build/.ninja_log" | sort -rn | head -10
