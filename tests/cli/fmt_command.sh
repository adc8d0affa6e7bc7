#!/usr/bin/env bash
# fgsg fmt (#50): on a copy of every .fgsg grammar in examples/ and stdlib/, formatting in
# place keeps every comment, is idempotent (--check then finds nothing) and changes no
# derivation's bytes (the interpreter's .obj, formatted copy against original copy); a
# small grammar formats to exact text; --check, stdin, syntax errors, .cga and usage
# errors have their exit codes, messages, and write nothing.
#   fmt_command.sh FGSG SOURCE_DIR
set -u
fgsg="$1" source="$2"
fail=0
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export FGSG_CACHE_DIR="$work/cache"
comments="$(cd "$(dirname "$0")" && pwd)/fmt_comments.py"

# Two copies of the trees, so imports, assets and surfaces resolve as in the source.
mkdir "$work/original" "$work/formatted"
cp -r "$source/examples" "$source/stdlib" "$work/original/"
cp -r "$source/examples" "$source/stdlib" "$work/formatted/"
cd "$work/formatted" || exit 1
mapfile -t grammars < <(find examples stdlib -name '*.fgsg' | sort)
[ "${#grammars[@]}" -ge 60 ] || { echo "FAIL: only ${#grammars[@]} grammars found"; exit 1; }
# Every one runs standalone; a grammar that cannot would be listed here with its reason.
skip_run=()

"$fgsg" fmt "${grammars[@]}" || { echo "FAIL: fgsg fmt on the examples and stdlib exited $?"; fail=1; }
changed=0
for g in "${grammars[@]}"; do
  cmp -s "$g" "$work/original/$g" || changed=$((changed + 1))
  # Idempotent: formatting the formatted text gives it back.
  "$fgsg" fmt --stdout "$g" >"$work/again" 2>&1 && cmp -s "$work/again" "$g" \
    || { echo "FAIL: fgsg fmt is not idempotent on $g:"; diff "$g" "$work/again" | head -20; fail=1; }
done
# Comments: the same ones, with the same text, in the same order, in every file.
(cd "$work/original" && python3 "$comments" "${grammars[@]}") >"$work/c1"
python3 "$comments" "${grammars[@]}" >"$work/c2"
[ "$(grep -c '^//' "$work/c1")" -ge 500 ] || { echo "FAIL: only $(grep -c '^//' "$work/c1") comments read"; fail=1; }
cmp -s "$work/c1" "$work/c2" || { echo "FAIL: fgsg fmt changed comments:"; diff "$work/c1" "$work/c2" | head; fail=1; }
# The layout did change somewhere (else this test would prove nothing).
[ "$changed" -ge 10 ] || { echo "FAIL: fgsg fmt changed only $changed files"; fail=1; }
out="$("$fgsg" fmt --check "${grammars[@]}")" && [ -z "$out" ] \
  || { echo "FAIL: --check on formatted files: exit $?, listed: $out"; fail=1; }

# The derivation's bytes: interpreter, default seed, .obj (and .mtl) from each copy, under
# the same name and place in each copy (the .obj names its .mtl, the .mtl its textures by
# relative path). A file fmt left as it was needs no second run.
outA="$work/original/fmt-out" outB="$work/formatted/fmt-out"
mkdir "$outA" "$outB"
ran=0 same=0
for g in "${grammars[@]}"; do
  [[ " ${skip_run[*]-} " == *" $g "* ]] && continue
  if cmp -s "$g" "$work/original/$g"; then same=$((same + 1)); continue; fi
  (cd "$work/original" && "$fgsg" run "$g" --engine interp -q -o "$outA/out.obj" >"$work/a.out" 2>&1)
  ra=$?
  (cd "$work/formatted" && "$fgsg" run "$g" --engine interp -q -o "$outB/out.obj" >"$work/b.out" 2>&1)
  rb=$?
  if [ "$ra" -ne 0 ] || [ "$rb" -ne 0 ]; then
    echo "FAIL: fgsg run $g exited $ra (original) and $rb (formatted)"; head -5 "$work/a.out" "$work/b.out"; fail=1
  elif ! diff -r "$outA" "$outB" >/dev/null || [ ! -s "$outA/out.obj" ]; then
    echo "FAIL: formatting $g changed its derivation's .obj"; diff -r "$outA" "$outB" | head -5; fail=1
  fi
  ran=$((ran + 1))
  rm -f "$outA"/* "$outB"/*
done
[ $((ran + same)) -eq "${#grammars[@]}" ] && [ "$ran" -ge 10 ] || { echo "FAIL: ran $ran of ${#grammars[@]} ($same unchanged)"; fail=1; }

cd "$work" || exit 1
# --check on an unformatted file: exit 1, its name on stdout, the file untouched.
cp "$source/examples/mueller_building.fgsg" m.fgsg
out="$("$fgsg" fmt --check m.fgsg "$work/formatted/examples/koch.fgsg")"
rc=$?
[ "$rc" -eq 1 ] && [ "$out" = "m.fgsg" ] || { echo "FAIL: --check exited $rc listing '$out' (expected 1, m.fgsg)"; fail=1; }
cmp -s m.fgsg "$source/examples/mueller_building.fgsg" || { echo "FAIL: --check wrote m.fgsg"; fail=1; }

# Exact layout of a small grammar, from stdin to stdout.
cat >sample.fgsg <<'EOF'
// header   
import "std/cga/facade"   as facade ( floor_height=3.5 );
attr  w=-2*3;     // aligned
const  hh = 1>0?1:-1 ;  // pushed on


derive parallel 4
axiom:F(1)  Lot
F(l)->F(l/3)+F(l/3)--F(l/3)+F(l/3)
Lot ~> S(10,0,8)   facade.Facade
A(x) : x>1 ~> Subdiv("X",1r,x*2){ B |
C }
  : 0.5 ~> B:0.5
     /* block
   comment */ B->[+F{.f.}]  ;F
tileset t {
 locus arc = cubic((0.5,0),(1,0.5));
    symbols "AB";
};
EOF
cat >expected.fgsg <<'EOF'
// header
import "std/cga/facade" as facade (floor_height = 3.5);
attr w = -2 * 3;  // aligned
const hh = 1 > 0 ? 1 : -1; // pushed on

derive parallel 4
axiom: F(1) Lot
F(l) -> F(l / 3)+F(l / 3)--F(l / 3)+F(l / 3)
Lot ~> S(10, 0, 8) facade.Facade
A(x) : x > 1 ~> Subdiv("X", 1r, x * 2){ B |
    C }
  : 0.5 ~> B: 0.5
/* block
   comment */ B -> [+F{.f.}] ;F
tileset t {
  locus arc = cubic((0.5, 0), (1, 0.5));
  symbols "AB";
};
EOF
"$fgsg" fmt - <sample.fgsg >got.fgsg || { echo "FAIL: fgsg fmt - exited $?"; fail=1; }
cmp -s got.fgsg expected.fgsg || { echo "FAIL: fgsg fmt - printed:"; diff expected.fgsg got.fgsg; fail=1; }
# In place: the same bytes, written over the file.
cp sample.fgsg inplace.fgsg
"$fgsg" fmt inplace.fgsg && cmp -s inplace.fgsg expected.fgsg || { echo "FAIL: fgsg fmt inplace.fgsg"; fail=1; }
out="$("$fgsg" fmt --check - <sample.fgsg)"
rc=$?
[ "$rc" -eq 1 ] && [ "$out" = "<stdin>" ] || { echo "FAIL: --check - exited $rc listing '$out'"; fail=1; }

# A syntax error: the located error, exit 1, nothing written; other files still formatted.
printf 'axiom: A;\nA -> B(1,;\n' >bad.fgsg
cp bad.fgsg bad.before
cp sample.fgsg other.fgsg
err="$("$fgsg" fmt bad.fgsg other.fgsg 2>&1)"
rc=$?
[ "$rc" -eq 1 ] || { echo "FAIL: a syntax error exited $rc"; fail=1; }
grep -q '^bad.fgsg:2:10: error\[E002\]' <<<"$err" && grep -qF 'fgsg fmt: bad.fgsg not formatted (1 error)' <<<"$err" \
  || { echo "FAIL: a syntax error printed:"; echo "$err"; fail=1; }
cmp -s bad.fgsg bad.before || { echo "FAIL: fgsg fmt wrote a file with a syntax error"; fail=1; }
cmp -s other.fgsg expected.fgsg || { echo "FAIL: the file after the bad one was not formatted"; fail=1; }
[ -z "$(ls -A | grep -v -e '\.fgsg$' -e '\.before$' -e '^original$' -e '^formatted$' -e '^cache$' -e '^again$' -e '^c[12]$' -e '\.out$')" ] \
  || { echo "FAIL: temporary files left: $(ls -A)"; fail=1; }

# A .cga grammar: not supported yet, said so, file untouched.
cp "$(find "$source/examples" -name '*.cga' | head -1)" lot.cga
cp lot.cga lot.before
err="$("$fgsg" fmt lot.cga 2>&1)"
rc=$?
[ "$rc" -eq 1 ] && grep -qF 'lot.cga:1:1: error[E002]: fgsg fmt formats .fgsg grammars; CityEngine CGA (.cga) is not supported yet' <<<"$err" \
  || { echo "FAIL: .cga exited $rc printing: $err"; fail=1; }
cmp -s lot.cga lot.before || { echo "FAIL: fgsg fmt wrote a .cga file"; fail=1; }

# Usage errors: exit 2.
"$fgsg" fmt >/dev/null 2>&1; [ $? -eq 2 ] || { echo "FAIL: fgsg fmt without files did not exit 2"; fail=1; }
err="$("$fgsg" fmt --chek m.fgsg 2>&1)"; rc=$?
[ "$rc" -eq 2 ] && grep -qF "fgsg fmt: unknown option '--chek'" <<<"$err" || { echo "FAIL: --chek: $rc $err"; fail=1; }
"$fgsg" fmt /nonexistent/x.fgsg >/dev/null 2>&1; [ $? -eq 1 ] || { echo "FAIL: a missing file did not exit 1"; fail=1; }

[ "$fail" -eq 0 ] && echo "fgsg fmt: ${#grammars[@]} grammars idempotent, comments kept; $ran reformatted, their derivations unchanged"
exit $fail
