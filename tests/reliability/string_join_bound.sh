#!/usr/bin/env bash
# A string `+` is bounded: a rule that joins a string to itself doubles it each step, and
# without the 1 MiB bound it took all memory (R020 only from the allocator, or the kernel's
# OOM killer) before any limit was asked. x is 1 byte, so the 21st join would be 2 MiB.
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
printf 'version "2023.0"\n\n@StartRule\nLot --> A("x")\n\nA(s) --> A(s + s)\n' >double.cga
# The interpreter locates the join; compiled code names the file (its join has no place).
expect 1 "double\.cga:6:12: error\[R020\]: a string joined with \+ would be 2097152 bytes, past the limit of 1 MiB" -- \
  "$fgsg" run double.cga --engine=interp -o x.obj
expect 1 "error\[R020\]: a string joined with \+ would be 2097152 bytes" -- "$fgsg" run double.cga --engine=jit -o x.obj
[ ! -e x.obj ] || fail "an output was written"
exit 0
