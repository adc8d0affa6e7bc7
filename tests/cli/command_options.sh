#!/usr/bin/env bash
# Every subcommand reads its options the same way (CLI11, cli/command_line.h): `--flag value`
# and `--flag=value` alike; an unknown option, a missing value or a second input file is a
# usage error (exit 2) naming it and the command's --help (usage: command_options.sh FGSG SOURCE_DIR).
set -u
fgsg="$1" source="$2"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
fail=0
koch="$source/examples/koch.fgsg"
expect() {  # CODE PATTERN ARGS...
  local code=$1 pattern=$2; shift 2
  "$fgsg" "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
  local got=$?
  if [ "$got" -ne "$code" ] || ! grep -Eq -- "$pattern" "$tmp/err" "$tmp/out"; then
    echo "FAIL: fgsg $* exited $got (expected $code, /$pattern/):"; cat "$tmp/err"; fail=1
  fi
}

# Unknown options and missing values, in every command that takes options.
for cmd in run check ir compile field view; do
  expect 2 "fgsg $cmd: unknown option '--bogus' \(see fgsg $cmd --help\)" "$cmd" "$koch" --bogus
  expect 2 "more than one grammar file given" "$cmd" "$koch" "$koch"
done
expect 2 "unknown option '--bogus' \(see fgsg repl --help\)" repl --bogus
expect 2 "unknown option '--bogus' \(see fgsg atlas --help\)" atlas "$source/tests/data/meshes/elephant.off" --bogus
expect 2 "unknown option '--bogus' \(see fgsg evolve --help\)" evolve "$source/examples/assets/ornament_tiles.json" --bogus
expect 2 "fgsg synth: error: unknown option '--bogus'" synth "$source/examples/synthesis/castle.txt" --size 4 4 1 --bogus
expect 2 "fgsg synth: error: --size needs X Y \[Z\]" synth "$source/examples/synthesis/castle.txt" --size 4
expect 2 "fgsg run: --seed needs a value" run "$koch" --seed
expect 2 "fgsg field: --seeds needs a value" field "$koch" --seeds
expect 2 "fgsg ir: no grammar file given" ir --llvm
expect 2 "fgsg repl: --engine gpu: unknown engine" repl --engine gpu

# --flag=value and --flag value mean the same; the last of a repeated option wins.
"$fgsg" run "$koch" --seed 3 -o "$tmp/a.obj" --quiet && "$fgsg" run "$koch" --seed=3 --output="$tmp/b.obj" -q \
  && "$fgsg" run "$koch" --seed 9 --seed 3 -o "$tmp/c.obj" --quiet || { echo "FAIL: run with --seed"; fail=1; }
cmp -s "$tmp/a.obj" "$tmp/b.obj" && cmp -s "$tmp/a.obj" "$tmp/c.obj" || { echo "FAIL: --seed=3, --seed 3 and --seed 9 --seed 3 differ"; fail=1; }
# Repeatable options keep every value: two --set, both applied.
printf 'attr a = 1;\nattr b = 1;\nAxiom ~> S(a, b, 1) I("cube");\n' > "$tmp/ab.fgsg"
"$fgsg" run "$tmp/ab.fgsg" --set a=2 --set=b=3 -o "$tmp/ab.obj" --quiet || { echo "FAIL: two --set"; fail=1; }
grep -q "^v 2 3 1" "$tmp/ab.obj" || { echo "FAIL: --set a=2 --set=b=3 did not both apply:"; grep "^v" "$tmp/ab.obj" | head -8; fail=1; }
# The REPL takes --engine either way.
echo ':quit' | "$fgsg" repl --engine interp >/dev/null 2>&1 || { echo "FAIL: repl --engine interp"; fail=1; }
echo ':quit' | "$fgsg" repl --engine=interp >/dev/null 2>&1 || { echo "FAIL: repl --engine=interp"; fail=1; }
# synth: Z may be left out before the example file.
"$fgsg" synth --size 6 5 "$source/examples/synthesis/summer_like.json" --labels "$tmp/l.txt" >/dev/null 2>&1 \
  || { echo "FAIL: synth --size X Y FILE"; fail=1; }
[ -s "$tmp/l.txt" ] || { echo "FAIL: synth --size X Y FILE wrote no labels"; fail=1; }
exit $fail
