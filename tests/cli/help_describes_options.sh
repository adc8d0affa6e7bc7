#!/usr/bin/env bash
# Every option a subcommand accepts is described in its --help: for each command, every
# option name written anywhere in cli/ (and -o, -q) is tried on it; one the command does
# not refuse as unknown must have a line of its own in `fgsg CMD --help` that starts with
# it ("  --seed N   ...", "  -o, --output FILE  ..."). batch is Python's argparse, which
# describes each of its options itself. usage: help_describes_options.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
mapfile -t names < <({ grep -oh '"--[a-z][a-z0-9-]*' "$source"/cli/*.cpp | tr -d '"'; echo -o; echo -q; } |
                     grep -vx -e --help -e --version | sort -u)
[ "${#names[@]}" -gt 40 ] || { echo "FAIL: only ${#names[@]} option names found in cli/"; exit 1; }
for cmd in run check ir synth repl compile atlas evolve field view; do
  help="$("$fgsg" "$cmd" --help 2>&1 </dev/null)"
  accepted=0
  for name in "${names[@]}"; do
    # A value that is no file: an option that takes it fails on it, a switch leaves it as
    # the (missing) input; either way nothing runs long.
    out="$(timeout 20 "$fgsg" "$cmd" "$name" /nonexistent/x.fgsg 2>&1 </dev/null)"
    grep -q "unknown option '$name'" <<<"$out" && continue
    accepted=$((accepted + 1))
    grep -Eq -- "^ +(-[a-z][^,]*, )?$name([ =,]|$)" <<<"$help" \
      || { echo "FAIL: fgsg $cmd accepts $name, which fgsg $cmd --help does not describe"; fail=1; }
  done
  [ "$accepted" -gt 0 ] || { echo "FAIL: fgsg $cmd accepts none of the options (is 'unknown option' still said?)"; fail=1; }
done
exit $fail
