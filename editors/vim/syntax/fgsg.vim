" Vim syntax file for fgsg grammars (.fgsg; docs/language.md). Install: copy or link
" editors/vim/ into ~/.vim/pack/fgsg/start/fgsg/ (docs/editors.md).
if exists('b:current_syntax')
  finish
endif

syn keyword fgsgDeclaration attr const field texture tileset import surface
syn keyword fgsgKeyword derive turtle collision axiom priority PRIORITY design as
syn match fgsgKeyword "#ignore\>"
syn match fgsgKeyword "#consider\>"
syn keyword fgsgConstant true false epsilon NIL
syn match fgsgConstant "ε"
syn match fgsgSection "^\s*\%(production\|decomposition\|homomorphism\|interpretation\)\s*:\s*$"
" A rule's predecessor: the first name of a line with an arrow after it (after a label `3:`).
syn match fgsgRule "^\s*\%(\w\+\s*:\s*\)\?\zs\h\w*\ze\%([^;]\{-}\)\%(\~>\|->\|→\|⇝\|\s=\s\)"
syn match fgsgArrow "\~>\|->\|→\|⇝"
syn match fgsgNumber "\%([[:alnum:]_.]\)\@1<!\%(\d\+\%(\.\d*\)\=\|\.\d\+\)\%([eE][+-]\=\d\+\)\=r\=\>"
syn region fgsgString start=+"+ skip=+\\.+ end=+"\|$+ contains=fgsgEscape oneline
syn match fgsgEscape contained "\\."
syn match fgsgComment "//.*$" contains=@Spell
syn region fgsgComment start="/\*" end="\*/" contains=@Spell

hi def link fgsgDeclaration Statement
hi def link fgsgKeyword Keyword
hi def link fgsgConstant Constant
hi def link fgsgSection PreProc
hi def link fgsgRule Function
hi def link fgsgArrow Operator
hi def link fgsgNumber Number
hi def link fgsgString String
hi def link fgsgEscape SpecialChar
hi def link fgsgComment Comment

let b:current_syntax = 'fgsg'
