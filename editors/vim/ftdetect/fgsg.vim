" .fgsg files are fgsg grammars (editors/vim/syntax/fgsg.vim).
autocmd BufRead,BufNewFile *.fgsg setfiletype fgsg
