#!/usr/bin/env bash
# Numbers out of range: a grammar constant that does not fit where it goes is a located
# E error with the allowed range; a command-line integer out of range is a usage error
# (exit 2) naming the flag and the range, never wrapped (--max-depth 4294967297 was 1).
. "$(dirname "$0")/lib.sh"
expect 1 'inputs_parallel_int_overflow.fgsg:1:17: error\[E029\]: `derive parallel N;` needs a whole number of steps N from 0 to 2147483647 \(a constant or an attr\), got 4294967297' \
  -- "$fgsg" check "$inputs/inputs_parallel_int_overflow.fgsg"
grep -q 'E999' "$tmp/err" && fail "derive parallel 4294967297 is an internal error"
printf 'derive parallel 2147483647;\naxiom: F(1);\nF(l) -> F(l);\n' > "$tmp/max.fgsg"
timeout 60 "$fgsg" check "$tmp/max.fgsg" >/dev/null 2>"$tmp/err" || { cat "$tmp/err" >&2; fail "the largest step count is refused"; }
printf 'derive parallel 1 / 0;\naxiom: F(1);\nF(l) -> F(l);\n' > "$tmp/zero.fgsg"
expect 1 'zero.fgsg:1:21: error\[E027\]: division by zero' -- "$fgsg" check "$tmp/zero.fgsg"
printf 'surface sphere(1);\nfield F = design tensor { wedge at vertex 0; smooth 3000000000; };\nAxiom ~> S(1, 1, 1) I("cube");\n' > "$tmp/smooth.fgsg"
expect 1 'error\[E040\]: the number of smoothing iterations is a whole number from 0 to 2147483647, got 3e\+09' -- "$fgsg" check "$tmp/smooth.fgsg"

g="$tmp/box.fgsg"
printf 'Axiom ~> S(1, 1, 1) I("cube");\n' > "$g"
run_flag() {  # FLAG VALUE RANGE-TEXT
  expect 2 "$1 expects a whole number from $3, got '$2'" -- "$fgsg" run "$g" "$1" "$2" -o "$tmp/x.obj"
  [ ! -e "$tmp/x.obj" ] || fail "run $1 $2 wrote an output"
}
run_flag --max-depth 4294967297 '0 to 4294967295'
run_flag --max-depth 4294967296 '0 to 4294967295'
run_flag --max-depth -1 '0 to 4294967295'
run_flag --max-depth ' 5' '0 to 4294967295'
run_flag --seed 18446744073709551616 '0 to 18446744073709551615'
run_flag --seed -1 '0 to 18446744073709551615'
run_flag --seed 3.5 '0 to 18446744073709551615'
run_flag --max-shapes 99999999999999999999 '0 to 18446744073709551615'
run_flag --max-shapes 1e6 '0 to 18446744073709551615'

json="$tmp/t.json"
echo '{"tiles": [{"name": "a"}], "neighbors": [{"left": "a", "right": "a"}]}' > "$json"
synth_usage() {  # PATTERN ARGS...
  local pattern=$1; shift
  expect 2 "fgsg synth: error: $pattern" -- "$fgsg" synth "$json" "$@"
}
synth_usage '--size needs X Y \[Z\]: whole numbers from 1 to 1048576' --size 4294967297 4 1
synth_usage '--size needs X Y \[Z\]: whole numbers from 1 to 1048576' --size 4 0 1
synth_usage '--size needs X Y \[Z\]: whole numbers from 1 to 1048576' --size 4 4 1048577
synth_usage '--seed needs a whole number from 0 to 9223372036854775807' --size 4 4 1 --seed 9223372036854775808
synth_usage '--block needs a block size N from 0 to 1048576' --size 4 4 1 --block 1048577
synth_usage '--retries needs an integer 0..1000' --size 4 4 1 --retries 1001
synth_usage '--attempts needs an integer 1..100000' --size 4 4 1 --attempts 0
synth_usage '--connect needs a seed count from 1 to 100000' --size 4 4 1 --connect 100001
synth_usage '--max-steps needs a whole number from 1 to 9223372036854775807' --size 4 4 1 --max-steps 0
synth_usage '--symmetry is .* \(N from 1 to 1048576\)' --size 4 4 1 --symmetry translate-x:4294967297
synth_usage '--max-seconds needs seconds greater than 0, at most 1e9' --size 4 4 1 --max-seconds 1e10
synth_usage '--time-limit needs seconds greater than 0, at most 1e9' --size 4 4 1 --time-limit 1e10

# The REPL's numbers too; a priority too large for an int is the compile error, not a crash.
printf 'priority 99999999999:\n:seed 18446744073709551616\n:derive 1000001\n:quit\n' > "$tmp/session"
expect 1 ":seed takes a whole number from 0 to 18446744073709551615, got '18446744073709551616'" \
  -- bash -c '"$0" repl < "$1"' "$fgsg" "$tmp/session"
grep -q ":derive takes an optional maximum depth (a whole number from 1 to 1000000), got '1000001'" "$tmp/err" ||
  fail ":derive 1000001 is not refused with its range"
grep -q "error\[E002\]: priority '99999999999' is not a small integer" "$tmp/err" || fail "no E002 for the priority"
exit 0
