# The REPL's :step 2 export (one flattened mesh) is fgsg run --step 2 --instancing off
# --group-by none of the saved grammar, byte for byte. The interpreter prints what the JIT
# printed (its output follows, after a line saying so) and exports the same bytes.
"$FGSG" run plant.fgsg --step 2 --instancing off --group-by none -q -o run.glb && cmp two.glb run.glb && echo "two.glb = fgsg run --step 2"
mv two.glb jit.glb
echo "--engine interp:"
"$FGSG" repl --engine interp < "$(dirname "$0")/step.script" 2>&1
echo "exit $?"
cmp jit.glb two.glb && echo "interp two.glb = jit two.glb"
