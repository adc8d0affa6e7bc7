#!/usr/bin/env bash
# Text quoted from an input file in a message is cut to 200 characters with its size: a
# field file whose second line is 50 MB of digits made R015 print all 50 MB.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
python3 -c "
N = 2562
with open('f.sfield', 'w') as f:
    f.write('fgsg-field 1 scalar %d\n' % N + '1' + '0' * 50_000_000 + '\n' + ''.join('0\n' for i in range(N)))
with open('v.vfield', 'w') as f:
    f.write('fgsg-field 1 vector %d\n' % N + 'x' * 1_000_000 + ' 0 0\n')"
printf 'surface sphere(2);\nfield S = scalar("f.sfield");\naxiom: A;\nA ~> I("cube");\n' >scalar.fgsg
printf 'surface sphere(2);\nfield V = vector("v.vfield");\naxiom: A;\nA ~> I("cube");\n' >vector.fgsg
for engine in interp jit; do
  expect 1 "error\[R015\]: .*f\.sfield:2: expected one number, got '10{199}\.\.\.' \(50000001 bytes\)" -- \
    "$fgsg" run scalar.fgsg --engine=$engine -o x.obj
  size=$(wc -c <"$tmp/err")
  [ "$size" -lt 2000 ] || fail "scalar field: $size bytes of messages"
done
expect 1 "v\.vfield:2: 'x{200}\.\.\.' \(1000000 bytes\) is not a number" -- "$fgsg" run vector.fgsg -o x.obj
size=$(wc -c <"$tmp/err")
[ "$size" -lt 2000 ] || fail "vector field: $size bytes of messages"
exit 0
