#!/usr/bin/env bash
# Tile sets with a field of the wrong type (reproducers 10a-10f) are located E712 errors,
# exit 1, naming the tile or border entry, the key and what was expected; never an abort.
. "$(dirname "$0")/lib.sh"
cd "$tmp" || fail "no scratch folder"
synth() { expect 1 "$2" -- "$fgsg" synth "$inputs/inputs_$1" --size 4 4 1 --labels l.txt; \
          same_message "$fgsg" synth "$inputs/inputs_$1" --size 4 4 1 --labels l.txt; }
synth 10a_tiles_symmetry_number.json \
  'inputs_10a_tiles_symmetry_number.json:1: error\[E712\]: tile `a`: "symmetry" must be a symmetry class X, L, T, I, \\ or F \(a string\), got number \(3\)'
synth 10b_tiles_asset_number.json 'json:1: error\[E712\]: tile `a`: "asset" must be an asset name \(a string; "none" for no asset\), got number \(5\)'
synth 10c_tiles_empty_string.json 'json:1: error\[E712\]: tile `a`: "empty" must be true or false, got string \("yes"\)'
synth 10d_tiles_connect_number.json 'json:1: error\[E712\]: tile `a`: "connect" must be true or false, got number \(1\)'
synth 10e_tiles_border_fixed_string.json 'json:1: error\[E712\]: border entry `xmin`: "fixed" must be true or false, got string \("yes"\)'
synth 10f_tiles_background_number.json 'json:1: error\[E712\]: tile `a`: "background" must be true or false, got number \(0\)'
[ ! -e l.txt ] || fail "a labels file was written for a tile set that does not load"
exit 0
