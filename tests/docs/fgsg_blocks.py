#!/usr/bin/env python3
"""Every ```fgsg block of docs/language.md is a complete grammar that runs, as the page
promises (other pages show fragments: a rule or two of a larger grammar): each is written
to a file of its own and run with `fgsg run`; a block that fails is named with its line.
    fgsg_blocks.py FGSG REPO_ROOT
"""
import os
import re
import subprocess
import sys
import tempfile


def blocks(path):
    """(line, text) of each ```fgsg block of the file."""
    out, lines, start, body = [], open(path, encoding="utf-8").read().split("\n"), None, []
    for number, line in enumerate(lines, 1):
        if start is None and line.strip() == "```fgsg":
            start, body = number + 1, []
        elif start is not None and line.strip() == "```":
            out.append((start, "\n".join(body) + "\n"))
            start = None
        elif start is not None:
            body.append(line)
    return out


def main():
    fgsg, root = sys.argv[1], sys.argv[2]
    pages = [os.path.join(root, "docs", "language.md")]
    count, failed = 0, []
    with tempfile.TemporaryDirectory() as folder:
        for page in pages:
            for line, text in blocks(page):
                count += 1
                grammar = os.path.join(folder, "block%d.fgsg" % line)
                with open(grammar, "w", encoding="utf-8") as f:
                    f.write(text)
                run = subprocess.run([fgsg, "run", grammar, "-o", os.path.join(folder, "out.glb"), "--quiet"],
                                     capture_output=True, text=True, timeout=120)
                if run.returncode != 0:
                    failed.append("%s:%d: %s" % (os.path.relpath(page, root), line, run.stderr.strip()[:400]))
    for f in failed:
        print("FAIL: " + f)
    if failed or count == 0:
        raise SystemExit("%d of %d documented grammars failed" % (len(failed), count))
    print("ok: %d documented grammars run" % count)


main()
