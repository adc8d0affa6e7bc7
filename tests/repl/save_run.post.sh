echo "--- fgsg run saved.fgsg"
"$FGSG" run saved.fgsg --stats --quiet -o run.glb | grep -v '^time\.'
test -s out.obj && echo "out.obj written"
