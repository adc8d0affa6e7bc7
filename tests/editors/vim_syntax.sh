#!/usr/bin/env bash
# editors/vim (#50): Vim detects a .fgsg file and its syntax file gives comments, keywords,
# numbers (with CGA's relative sizes), strings and escapes, rule names and arrows the
# expected groups, read back with synID() in a headless Vim. Exit 77 without vim.
#   vim_syntax.sh SOURCE_DIR
set -u
source="$1"
command -v vim >/dev/null 2>&1 || { echo "SKIP: no vim"; exit 77; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
printf '// note\nattr height = 6.5;\nLot ~> S(1r, 2, 3) Print("a\\"b")\naxiom: Lot /* x */\n' >"$work/sample.fgsg"
cat >"$work/probe.vim" <<'VIM'
set nocompatible
execute 'set runtimepath^=' . g:editors . '/vim'
filetype on
syntax on
execute 'edit ' . g:work . '/sample.fgsg'
let s:out = [&filetype]
for [l, c] in [[1, 4], [2, 1], [2, 6], [2, 15], [3, 1], [3, 5], [3, 8], [3, 10], [3, 14], [3, 27], [3, 28], [4, 1], [4, 8], [4, 13]]
  call add(s:out, l . ':' . c . ' ' . synIDattr(synID(l, c, 1), 'name'))
endfor
call writefile(s:out, g:work . '/groups.txt')
qall!
VIM
timeout 30 vim -Nu NONE -es --cmd "let g:editors='$source/editors' | let g:work='$work'" -S "$work/probe.vim" </dev/null
expected='fgsg
1:4 fgsgComment
2:1 fgsgDeclaration
2:6 
2:15 fgsgNumber
3:1 fgsgRule
3:5 fgsgArrow
3:8 
3:10 fgsgNumber
3:14 fgsgNumber
3:27 fgsgString
3:28 fgsgEscape
4:1 fgsgKeyword
4:8 
4:13 fgsgComment'
got="$(cat "$work/groups.txt" 2>/dev/null)"
[ "$got" = "$expected" ] || { echo "FAIL: syntax groups"; diff <(echo "$expected") <(echo "$got"); exit 1; }
echo "ok: Vim highlights a .fgsg sample as expected"
