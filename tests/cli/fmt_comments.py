#!/usr/bin/env python3
"""Prints each grammar's name, then its comments, one per line (a block comment's line
breaks as \\n), as a scanner independent of fgsg reads them: strings are skipped, a line
comment loses its trailing blanks. tests/cli/fmt_command.sh compares them before and after
fgsg fmt. usage: fmt_comments.py FILE..."""
import sys


def comments(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if c == '"':
            i += 1
            while i < n and text[i] not in '"\n':
                i += 2 if text[i] == '\\' else 1
            i += 1
        elif text.startswith('//', i):
            end = text.find('\n', i)
            end = n if end < 0 else end
            out.append(text[i:end].rstrip(' \t\r\f'))
            i = end
        elif text.startswith('/*', i):
            end = text.find('*/', i + 2)
            end = n if end < 0 else end + 2
            out.append(text[i:end])
            i = end
        else:
            i += 1
    return out


for name in sys.argv[1:]:
    print(f'== {name}')
    with open(name, encoding='utf-8') as f:
        for comment in comments(f.read()):
            print(comment.replace('\\', '\\\\').replace('\n', '\\n'))
