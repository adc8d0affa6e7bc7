#!/usr/bin/env bash
# `const z = 1 / 0;` is one error, the documented E027 at the divisor: not E023 ("must be
# a constant expression") and not a second, spurious E010 where z is used.
. "$(dirname "$0")/lib.sh"
g="$inputs/inputs_const_division_by_zero.fgsg"
expect 1 '/inputs_const_division_by_zero.fgsg:1:15: error\[E027\]: division by zero$' -- "$fgsg" check "$g"
[ "$(grep -c 'error\[' "$tmp/err")" -eq 1 ] || { cat "$tmp/err" >&2; fail "more than one error"; }
grep -q '^1 error in ' "$tmp/err" || fail "no error count"
# Other constants that cannot be evaluated are still E023, once, without E010 at their uses.
printf 'const w = Rand(1, 2);\nAxiom ~> S(w, w, 1) I("cube");\n' > "$tmp/rand.fgsg"
expect 1 'rand.fgsg:1:11: error\[E023\]' -- "$fgsg" check "$tmp/rand.fgsg"
[ "$(grep -c 'error\[' "$tmp/err")" -eq 1 ] || { cat "$tmp/err" >&2; fail "E023 comes with other errors"; }
exit 0
