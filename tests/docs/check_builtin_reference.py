#!/usr/bin/env python3
"""docs/language.md's "Builtin reference" is what `fgsg builtin-reference` prints from the
table fgsg lsp hovers with (frontend/builtin_docs.cpp), so the page cannot drift from it:
the text between its two markers must be that output, byte for byte. With --update the
section is rewritten from the table (docs/editors.md: after changing the table).
    check_builtin_reference.py FGSG REPO_ROOT [--update]
"""
import difflib
import subprocess
import sys

BEGIN = "<!-- builtin-reference:begin -->\n"
END = "<!-- builtin-reference:end -->\n"


def main():
    if len(sys.argv) not in (3, 4) or (len(sys.argv) == 4 and sys.argv[3] != "--update"):
        sys.exit(__doc__)
    fgsg, root = sys.argv[1], sys.argv[2]
    path = root + "/docs/language.md"
    page = open(path, encoding="utf-8").read()
    begin, end = page.find(BEGIN), page.find(END)
    if begin < 0 or end < begin:
        sys.exit(f"{path}: no section between '{BEGIN.strip()}' and '{END.strip()}'")
    written = page[begin + len(BEGIN):end]
    generated = subprocess.run([fgsg, "builtin-reference"], check=True, capture_output=True,
                               encoding="utf-8").stdout
    if written == generated:
        print(f"{path}: the builtin reference is the table's ({generated.count(chr(10))} lines)")
        return
    if len(sys.argv) == 4:
        with open(path, "w", encoding="utf-8") as f:
            f.write(page[:begin + len(BEGIN)] + generated + page[end:])
        print(f"{path}: builtin reference regenerated")
        return
    line = page[:begin].count("\n") + 2  # the first line after the begin marker
    diff = difflib.unified_diff(written.splitlines(True), generated.splitlines(True),
                                f"docs/language.md (from line {line})", "fgsg builtin-reference")
    sys.stdout.writelines(diff)
    sys.exit(f"FAIL: {path}'s builtin reference differs from the table (frontend/builtin_docs.cpp); "
             f"edit the table, not the page, and regenerate: python3 tests/docs/check_builtin_reference.py "
             f"build/bin/fgsg . --update")


if __name__ == "__main__":
    main()
