#!/usr/bin/env bash
# Inputs that are not regular files (/dev/zero, a FIFO, a directory, links to them) are
# refused at once by every reader, with a message naming the file and what it is; they used
# to be read forever (memory growing) or reported as "no such file".
fgsg=$1 root=$2
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
mkfifo pipe.fgsg
ln -s /dev/zero zero.txt
mkdir folder.fgsg

# Grammar files: fgsg check, fgsg run, the REPL's :load.
expect 1 '/dev/zero: is a character device, not a grammar file' -- "$fgsg" check /dev/zero
expect 1 'pipe\.fgsg: is a FIFO \(named pipe\), not a grammar file' -- "$fgsg" check pipe.fgsg
expect 1 'folder\.fgsg: is a directory, not a grammar file' -- "$fgsg" run folder.fgsg -o x.obj
expect 1 'nothing\.fgsg: no such file' -- "$fgsg" check nothing.fgsg
echo ':load /dev/zero' >load.script
expect 1 '/dev/zero: is a character device, not a grammar file' -- bash -c "'$fgsg' repl <load.script"
same_message bash -c "'$fgsg' repl <load.script"

# A field file (reproducer 16), directly and through a link, with both engines.
cp "$inputs/readers_16_field_file_devzero.fgsg" field.fgsg
sed 's|"/dev/zero"|"zero.txt"|' field.fgsg >field_link.fgsg
for engine in interp jit; do
  expect 1 '^field\.fgsg:2:1: error\[R015\]: field F1: /dev/zero: is a character device, not a field file$' -- \
    "$fgsg" run field.fgsg --engine=$engine -o x.obj
  expect 1 "field F1: zero\.txt: is a symbolic link to '/dev/zero', a character device, not a field file" -- \
    "$fgsg" run field_link.fgsg --engine=$engine -o x.obj
done

# Synthesis examples: fgsg synth, and Synthesize in a grammar with both engines.
expect 1 '/dev/zero: error\[E701\]: cannot open example file: is a character device, not an example file' -- \
  "$fgsg" synth /dev/zero --size 4 4 1
expect 1 'pipe\.fgsg: error\[E701\]: cannot open example file: is a FIFO \(named pipe\), not an example file' -- \
  "$fgsg" synth pipe.fgsg --size 4 4 1
echo 'axiom: S(4, 1, 4) Synthesize("/dev/zero", 2, 2, 1);' >synth.fgsg
for engine in interp jit; do
  expect 1 'cannot open example file: is a character device, not an example file' -- \
    "$fgsg" run synth.fgsg --engine=$engine -o x.glb
done
# Images: a synthesis mask.
expect 1 'zero\.txt: is a symbolic link' -- \
  "$fgsg" synth "$root/examples/synthesis/castle.txt" --size 4 4 1 --mask zero.txt
exit 0
