#!/usr/bin/env python3
"""scripts/check_private_names.py (#47): on two small files of one "library", it names
each private name both define in one namespace with file:line of each, exits 1, and
leaves alone what a unity batch accepts: names in comments and strings, a name in another
namespace, a declaration that is no definition, an alias repeated word for word.

Usage: test_check_private_names.py SCRIPTS/check_private_names.py
"""
import os
import subprocess
import sys
import tempfile

script = sys.argv[1]
tmp = tempfile.mkdtemp(prefix="fgsg_private_names_")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def write(name, text):
    with open(os.path.join(tmp, name), "w") as f:
        f.write(text)


write("a.cpp", r'''#include <vector>
#define HELPER(x) namespace { int fromMacro = x; }
namespace fgsg::rt {
namespace {
// namespace { int commented; }
constexpr double kPi = 3.14159265358979323846;
const char* kText = "namespace { int inString; }";
int helper(int x) { return x + '}'; }
struct Box { int a{1}; };
using Complex = std::complex<double>;
using Ring = std::vector<int>;
enum Colour { kRed, kGreen = (1, 2) };
}  // namespace
struct Impl { Impl(); int a_, b_; };
Impl::Impl() : a_{1}, b_{2} {}
static int afterConstructor() { return 1; }
static int twice(int x) { return 2 * x; }
}  // namespace fgsg::rt
''')
write("b.cpp", r'''namespace fgsg::rt {
namespace {
/* namespace { int commented; } */
const double kPi = 3.14159;
const char* kOther = R"(namespace { int inString; })";
struct Box;
using Complex = std::complex<double>;
using Ring = std::vector<long>;
enum class Scoped { kRed };
constexpr int kBlue = 1, kGreen = 3;
}  // namespace
static int helper(int);
static int helper(int x) { return x; }
static int afterConstructor() { return 2; }
}  // namespace fgsg::rt
namespace fgsg::rt::cga {
namespace { int twice(int x) { return x + x; } }
}
''')
# The manifest CMake writes: target, source dir, ;-separated sources.
with open(os.path.join(tmp, "unity_targets.txt"), "w") as f:
    f.write(f"lib_one\t{tmp}\ta.cpp;b.cpp\n")
run = subprocess.run([sys.executable, script, os.path.join(tmp, "unity_targets.txt")], capture_output=True, text=True)
# Files are named relative to the repository the script is in.
root = os.path.dirname(os.path.dirname(os.path.abspath(script)))
a, b = (os.path.relpath(os.path.join(tmp, name), root) for name in ("a.cpp", "b.cpp"))
# By hand: in fgsg::rt both files define kPi (a:6, b:4), Ring with two different aliases
# (a:11, b:8), helper (a:8 in the anonymous namespace, b:12 static), afterConstructor
# (a:16, b:14) and kGreen (a:12 an enumerator, b:10 a second declarator); twice is in
# fgsg::rt in a but in fgsg::rt::cga in b; Box is only declared in b; Complex is the same
# alias in both; b's kRed is scoped (Scoped::kRed). Sorted by namespace, then name.
expected = [
    f"lib_one: `fgsg::rt::Ring` is private to 2 files, which one unity batch would define twice "
    f"(FGSG_UNITY_BUILD): {a}:11, {b}:8",
    f"lib_one: `fgsg::rt::afterConstructor` is private to 2 files, which one unity batch would define twice "
    f"(FGSG_UNITY_BUILD): {a}:16, {b}:14",
    f"lib_one: `fgsg::rt::helper` is private to 2 files, which one unity batch would define twice "
    f"(FGSG_UNITY_BUILD): {a}:8, {b}:12",
    f"lib_one: `fgsg::rt::kGreen` is private to 2 files, which one unity batch would define twice "
    f"(FGSG_UNITY_BUILD): {a}:12, {b}:10",
    f"lib_one: `fgsg::rt::kPi` is private to 2 files, which one unity batch would define twice "
    f"(FGSG_UNITY_BUILD): {a}:6, {b}:4",
]
check(run.returncode == 1, f"exit status {run.returncode}, expected 1")
check(run.stdout.splitlines() == expected, "report:\n" + run.stdout + "expected:\n" + "\n".join(expected))
check(run.stderr.startswith("5 private name(s)"), f"summary: {run.stderr!r}")

# One file alone has nothing to clash with: exit 0, no output.
with open(os.path.join(tmp, "unity_targets.txt"), "w") as f:
    f.write(f"lib_two\t{tmp}\ta.cpp\n")
run = subprocess.run([sys.executable, script, os.path.join(tmp, "unity_targets.txt")], capture_output=True, text=True)
check(run.returncode == 0 and run.stdout == "", f"one file: exit {run.returncode}, output {run.stdout!r}")

# A file the reader cannot follow is an error (2), not names silently missed.
write("c.cpp", "namespace {\nint unclosed() {\n")
with open(os.path.join(tmp, "unity_targets.txt"), "w") as f:
    f.write(f"lib_three\t{tmp}\tc.cpp\n")
run = subprocess.run([sys.executable, script, os.path.join(tmp, "unity_targets.txt")], capture_output=True, text=True)
check(run.returncode == 2 and "c.cpp: unbalanced braces" in run.stderr, f"unbalanced: {run.returncode} {run.stderr!r}")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
