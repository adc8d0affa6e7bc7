#!/usr/bin/env python3
"""Fails on a Catch TEST_CASE name that CTest cannot register whole.

catch_discover_tests makes one CTest entry per test case, and CMake splits a name at ';'
(its list separator): the entry runs a filter that matches no test (--warn NoTests then
fails it only when the whole suite runs). Names the file, line and name of each such case.

  scripts/check_test_names.py [SOURCE_DIR]
"""
import pathlib
import re
import sys

root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
name_re = re.compile(r'TEST_CASE\s*\(\s*"((?:[^"\\]|\\.)*)"')
bad = 0
for path in sorted((root / "tests").rglob("*.cpp")):
    text = path.read_text(encoding="utf-8", errors="replace")
    for m in name_re.finditer(text):
        if ";" in m.group(1):
            line = text.count("\n", 0, m.start()) + 1
            print(f"{path.relative_to(root)}:{line}: a ';' in the test name splits its CTest entry: {m.group(1)!r}")
            bad += 1
print(f"check_test_names: {bad} test name(s) with ';'" if bad else "check_test_names: no test name holds a ';'")
sys.exit(1 if bad else 0)
