#!/usr/bin/env python3
"""Mutation testing for fgsg (issue #51): does the suite notice a one-line change?

For each curated mutation of an area (tests/mutations/<area>.txt) the tool applies it in a
git worktree of its own, rebuilds only the area's targets, runs the area's tests and
records the mutation as

  killed     a test failed: the suite notices the change
  timeout    a test ran past its limit (counted as killed: the change does not go unseen)
  stillborn  the mutated source did not build (counted as killed, reported apart: it says
             nothing about the tests)
  survived   every test passed: nothing notices the change
  equivalent survived, and its list line says why no test can notice it (its reason
             starts with 'equivalent:', e.g. a check another check makes redundant); left
             out of the kill rate, listed apart. Killed all the same, it counts as killed
             and the report says the mark is wrong.

and restores the file byte for byte before the next one. It never touches the checkout
it was started from, nor its build/: other people edit and build there while a run takes
an hour. Default layout, git-ignored:

  build-mutate/src     `git worktree add --detach` of the commit under test (HEAD)
  build-mutate/build   its Ninja Release unity build, the listed files compiled alone
                       (ccache where installed)

  scripts/mutate.py --prepare              worktree, configure, build every area's targets
  scripts/mutate.py --area cga --area ga   run two areas' mutations
  scripts/mutate.py --all --report r.json  every area; JSON report and r.txt beside it
  scripts/mutate.py --list                 the areas, their mutations, each one checked

A mutation list is one mutation a line, fields separated by ' | ' (a literal ' | ' in code
is written '\\|'):

  runtime/cga/roof.cpp | if (angle <= 0) | if (angle < 0) | a zero pitch is a flat roof

The fragment must occur exactly once in its file at the commit under test, so a list
cannot silently go stale when the code moves. The header says what to build and run:

  # targets: test_runtime fgsg
  # tests: ^runtime: .*roof
  # timeout: 120          (seconds per test)

docs/testing.md ("Mutation testing") has the measured kill rates.
"""

import argparse
import hashlib
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field


class MutateError(Exception):
    """A problem with the input or the setup; reported as one line, exit status 2."""


@dataclass
class Mutation:
    path: str          # relative to the source root
    original: str      # exact fragment, found exactly once in the file
    replacement: str
    why: str
    list_file: str
    list_line: int

    def where(self):
        return f"{self.list_file}:{self.list_line}"

    def marked_equivalent(self):
        # Its list says no test can tell it from the original (and why).
        return self.why.lower().startswith("equivalent:")


@dataclass
class Area:
    name: str
    list_file: str
    targets: list
    tests: str
    timeout: int
    mutations: list = field(default_factory=list)
    test_files: list = field(default_factory=list)  # Catch2 sources under tests/unit/<lib>/
    resolved_tests: str = ""  # test_regex() at the commit under test

    def test_regex(self, source_root):
        """The CTest regex: the header's, or'ed with one for each test case of the test files."""
        parts = [self.tests] if self.tests else []
        for relative in self.test_files:
            parts += test_case_patterns(source_root, relative)
        return "|".join(parts)


# ---------------------------------------------------------------------------- lists

FIELD_SEPARATOR = re.compile(r"(?<!\\) \| ")


def parse_list(path):
    """Reads one area's list; a malformed line is an error that names it."""
    name = os.path.splitext(os.path.basename(path))[0]
    header = {}
    mutations = []
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        if not stripped:
            continue
        if stripped.startswith("#"):
            m = re.match(r"#\s*(targets|tests|test-files|timeout)\s*:\s*(.*)$", stripped)
            if m:
                header[m.group(1)] = m.group(2).strip()
            continue
        fields = [p.replace("\\|", "|") for p in FIELD_SEPARATOR.split(line)]
        if len(fields) != 4:
            raise MutateError(f"{path}:{number}: expected 'file | original | replacement | why' "
                              f"(4 fields separated by ' | ', a literal ' | ' written '\\|'), "
                              f"found {len(fields)} fields")
        file_path, original, replacement, why = (p.strip() for p in fields)
        if not original:
            raise MutateError(f"{path}:{number}: the original fragment is empty")
        if original == replacement:
            raise MutateError(f"{path}:{number}: the replacement is the original fragment")
        mutations.append(Mutation(file_path, original, replacement, why, path, number))
    if not header.get("targets"):
        raise MutateError(f"{path}: the header has no '# targets:' line")
    if not header.get("tests") and not header.get("test-files"):
        raise MutateError(f"{path}: the header names no tests ('# tests:' or '# test-files:')")
    try:
        timeout = int(header.get("timeout", "300"))
    except ValueError:
        raise MutateError(f"{path}: '# timeout:' is not a whole number of seconds")
    if not mutations:
        raise MutateError(f"{path}: no mutations")
    return Area(name, path, header["targets"].split(), header.get("tests", ""), timeout, mutations,
                header.get("test-files", "").split())


TEST_CASE = re.compile(r'^\s*TEST_CASE\(\s*"((?:[^"\\]|\\.)*)"', re.M)


def test_case_patterns(source_root, relative):
    """CTest name patterns for a Catch2 file's test cases: catch_discover_tests names them
    '<library>:<name>' (tests/CMakeLists.txt), the library being the folder under tests/unit."""
    match = re.match(r"tests/unit/([^/]+)/[^/]+\.cpp$", relative)
    if not match:
        raise MutateError(f"test file {relative}: expected tests/unit/<library>/<name>.cpp")
    try:
        with open(os.path.join(source_root, relative), encoding="utf-8") as f:
            names = TEST_CASE.findall(f.read())
    except OSError as error:
        raise MutateError(f"test file {relative}: {error.strerror}")
    if not names:
        raise MutateError(f"test file {relative}: no TEST_CASE found")
    library = match.group(1)
    unquote = lambda text: re.sub(r"\\(.)", r"\1", text)  # \" and \\ in the C++ literal
    # CTest's regular expressions take a backslash before any special character.
    escape = lambda text: re.sub(r"([][\\.^$*+?(){}|])", r"\\\1", text)
    return ["^" + escape(f"{library}:{unquote(name)}") + "$" for name in names]


def locate(mutation, text):
    """The one offset of the fragment in the file's text; an error for 0 or several."""
    count = text.count(mutation.original)
    if count != 1:
        what = "not found" if count == 0 else f"found {count} times (must be unique)"
        raise MutateError(f"{mutation.where()}: fragment {mutation.original!r} {what} in {mutation.path}")
    return text.index(mutation.original)


def line_of(text, offset):
    return text.count("\n", 0, offset) + 1


# ------------------------------------------------------------------- the worktree

def git(repo, *args, check=True):
    result = subprocess.run(["git", "-C", repo, *args], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise MutateError(f"git {' '.join(args)} in {repo}: {result.stderr.strip()}")
    return result.stdout.strip()


def main_checkout(start):
    """The repository's main working tree, also when started from a linked worktree."""
    common = git(start, "rev-parse", "--path-format=absolute", "--git-common-dir")
    return os.path.dirname(common)


JOURNAL = "mutation-applied.json"


class Workspace:
    """The worktree and build of one run; owns the one mutation applied at a time."""

    def __init__(self, repo, worktree, build, commit):
        self.repo = os.path.realpath(repo)
        self.worktree = os.path.realpath(worktree)
        self.build = os.path.realpath(build)
        self.commit = commit
        self.applied = None  # (absolute path, original bytes) while a mutation is in
        self.interrupted_in = None  # the file a Ctrl-C found mutated (then restored)
        self.journal = os.path.join(os.path.dirname(self.worktree), JOURNAL)

    def refuse_shared_paths(self):
        # The whole point: other people's checkout and builds are never written to.
        for path, what in ((self.worktree, "--worktree"), (self.build, "--build-dir")):
            if path == self.repo or path == os.path.join(self.repo, "build"):
                raise MutateError(f"{what} {path} is the shared checkout or its build; "
                                  "mutations run in a worktree of their own")
        cache = os.path.join(self.build, "CMakeCache.txt")
        if os.path.exists(cache):
            with open(cache, errors="replace") as f:
                home = re.search(r"^CMAKE_HOME_DIRECTORY:INTERNAL=(.*)$", f.read(), re.M)
            if home and os.path.realpath(home.group(1)) != self.worktree:
                raise MutateError(f"--build-dir {self.build} is the build of {home.group(1)}, "
                                  f"not of the worktree {self.worktree}")

    def ensure(self):
        """Creates the worktree at the commit, or moves a clean one to it; checks HEAD."""
        self.refuse_shared_paths()
        self.recover()
        if not os.path.exists(self.worktree):
            os.makedirs(os.path.dirname(self.worktree), exist_ok=True)
            git(self.repo, "worktree", "add", "--detach", self.worktree, self.commit)
        else:
            if not os.path.exists(os.path.join(self.worktree, ".git")):
                raise MutateError(f"{self.worktree} exists and is not a git worktree")
            dirty = git(self.worktree, "status", "--porcelain", "--untracked-files=no")
            if dirty:
                raise MutateError(f"worktree {self.worktree} has changes (a mutation left behind?):\n"
                                  f"{dirty}\nrestore them (git -C {self.worktree} diff) and run again")
            if git(self.worktree, "rev-parse", "HEAD") != self.commit:
                git(self.worktree, "checkout", "--quiet", "--detach", self.commit)
        head = git(self.worktree, "rev-parse", "HEAD")
        if head != self.commit:
            raise MutateError(f"worktree {self.worktree} is at {head}, not the requested {self.commit}")

    # A mutation is journalled before it is written, so that a run killed outright
    # (SIGKILL, power) still has its file restored by the next run.
    def apply(self, mutation, text):
        path = os.path.join(self.worktree, mutation.path)
        with open(path, "rb") as f:
            original = f.read()
        offset = locate(mutation, text)
        mutated = text[:offset] + mutation.replacement + text[offset + len(mutation.original):]
        backup = self.journal + ".orig"
        write_atomically(backup, original)
        write_atomically(self.journal, json.dumps({"path": path, "backup": backup,
                                                   "sha256": sha256(original)}).encode())
        self.applied = (path, original)
        write_atomically(path, mutated.encode("utf-8"))

    def restore(self):
        if self.applied is None:
            return
        # A second Ctrl-C must not cut the restore in half.
        blocked = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
        try:
            self._restore()
        finally:
            signal.pthread_sigmask(signal.SIG_SETMASK, blocked)

    def _restore(self):
        path, original = self.applied
        write_atomically(path, original)
        with open(path, "rb") as f:
            if f.read() != original:
                raise MutateError(f"could not restore {path}; its original is in {self.journal}.orig")
        self.applied = None
        for leftover in (self.journal, self.journal + ".orig"):
            if os.path.exists(leftover):
                os.remove(leftover)

    def recover(self):
        """Restores a file that a killed run left mutated."""
        if not os.path.exists(self.journal):
            return
        with open(self.journal) as f:
            entry = json.load(f)
        if not os.path.realpath(entry["path"]).startswith(self.worktree + os.sep):
            raise MutateError(f"{self.journal} names {entry['path']}, outside {self.worktree}")
        with open(entry["backup"], "rb") as f:
            original = f.read()
        if sha256(original) != entry["sha256"]:
            raise MutateError(f"{self.journal}: the backup does not match its checksum; "
                              f"restore {entry['path']} by hand (git checkout in the worktree)")
        write_atomically(entry["path"], original)
        print(f"mutate: restored {entry['path']} left mutated by an interrupted run", flush=True)
        os.remove(entry["backup"])
        os.remove(self.journal)


def sha256(data):
    return hashlib.sha256(data).hexdigest()


def write_atomically(path, data):
    temporary = path + ".mutate-tmp"
    with open(temporary, "wb") as f:
        f.write(data)
    mode = os.stat(path).st_mode if os.path.exists(path) else None
    if mode is not None:
        os.chmod(temporary, mode)
    os.replace(temporary, path)
    # A restored file gets a fresh time stamp, so the next build notices it even when
    # the mutation and the restore land within one time-stamp tick.
    now = time.time()
    os.utime(path, (now, now))


# ---------------------------------------------------------------- build and tests

# Ignored test inputs and tools that tests need (scripts/fetch-test-meshes.sh, the glTF
# validator of scripts/install-node-packages.sh); the worktree links to the checkout's copy
# instead of installing them again.
SHARED_IGNORED_DATA = ["tests/data/meshes", "tools/node"]


class Commands:
    """How to build and test: CMake and CTest by default, shell commands for tests."""

    def __init__(self, args, workspace):
        self.args = args
        self.ws = workspace

    def substitute(self, template, area):
        return template.format(src=shlex.quote(self.ws.worktree), build=shlex.quote(self.ws.build),
                               targets=" ".join(shlex.quote(t) for t in area.targets),
                               tests=shlex.quote(area.resolved_tests), timeout=area.timeout,
                               jobs=self.args.jobs)

    def configure(self):
        if self.args.build_cmd:
            return
        for relative in SHARED_IGNORED_DATA:
            source = os.path.join(self.ws.repo, relative)
            link = os.path.join(self.ws.worktree, relative)
            if os.path.isdir(source) and not os.path.lexists(link):
                os.makedirs(os.path.dirname(link), exist_ok=True)  # tools/ is ignored, not in the worktree
                os.symlink(source, link)
        if os.path.exists(os.path.join(self.ws.build, "build.ninja")):
            return
        launcher = []
        if shutil.which("ccache"):
            launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
        # A unity build (batches of eight files) with every file of every list compiled
        # alone: the first build takes about half the time, and a mutant rebuilds one file.
        mutated = sorted({m.path for a in load_areas(self.args.lists, [], True) for m in a.mutations})
        run_logged(["cmake", "-S", self.ws.worktree, "-B", self.ws.build, "-G", "Ninja",
                    "-DCMAKE_BUILD_TYPE=Release", "-DFGSG_UNITY_BUILD=ON",
                    "-DFGSG_UNITY_EXCLUDE=" + ";".join(mutated), *launcher], "configure", self.ws)

    def build(self, area_targets, area=None):
        """True when the build succeeded."""
        if self.args.build_cmd:
            command = self.substitute(self.args.build_cmd, area)
            return run_shell(command, self.ws.worktree, None).returncode == 0
        result = run_logged(["cmake", "--build", self.ws.build, "-j", str(self.args.jobs),
                             "--target", *area_targets], "build", self.ws, check=False)
        return result.returncode == 0

    def test(self, area):
        """'passed', 'failed' or 'timeout', and the output's tail."""
        if self.args.test_cmd:
            command = self.substitute(self.args.test_cmd, area)
            try:
                result = run_shell(command, self.ws.worktree, area.timeout)
            except subprocess.TimeoutExpired:
                return "timeout", ""
            return ("passed" if result.returncode == 0 else "failed"), result.stdout[-2000:]
        command = ["ctest", "--test-dir", self.ws.build, "-R", area.resolved_tests, "--no-tests=error",
                   "--timeout", str(area.timeout), "--stop-on-failure", "-j", str(self.args.jobs),
                   "--output-on-failure"]
        # The whole run also has a limit, in case a test ignores its own.
        try:
            result = run_bounded(command, area.timeout * 4 + 600)
        except subprocess.TimeoutExpired:
            return "timeout", ""
        output = result.stdout
        if result.returncode == 0:
            return "passed", output[-2000:]
        if re.search(r"\*\*\*Timeout", output):
            return "timeout", output[-2000:]
        return "failed", output[-2000:]


def run_bounded(command, timeout, **options):
    """subprocess.run whose timeout (or Ctrl-C) ends the command's whole process group:
    a test's children would otherwise keep its output pipe open and the wait forever."""
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               text=True, encoding="utf-8", errors="replace",  # a test may print any byte
                               start_new_session=True, **options)
    try:
        output, _ = process.communicate(timeout=timeout)
    except BaseException:
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        process.communicate()
        raise
    return subprocess.CompletedProcess(command, process.returncode, output, "")


def run_shell(command, cwd, timeout):
    return run_bounded(command, timeout, shell=True, cwd=cwd)


def run_logged(command, what, ws, check=True):
    log = os.path.join(os.path.dirname(ws.worktree), f"last-{what}.log")
    with open(log, "w") as out:
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT)
        try:
            process.wait()
        except BaseException:
            # Interrupted (a signal to this process only): the build must not go on.
            process.terminate()
            process.wait()
            raise
        result = subprocess.CompletedProcess(command, process.returncode)
    if check and result.returncode != 0:
        raise MutateError(f"{what} failed ({' '.join(command[:3])} ...); see {log}")
    return result


# ------------------------------------------------------------------------- running

def run_area(area, ws, commands, keep_going, log):
    """Every mutation of one area; a dict for the report."""
    started = time.time()
    record = {"area": area.name, "list": area.list_file, "tests": area.tests, "test_files": area.test_files,
              "targets": area.targets, "results": [], "error": None}
    area.resolved_tests = area.test_regex(ws.worktree)
    log(f"== {area.name}: {len(area.mutations)} mutations; build {' '.join(area.targets)}")
    if not commands.build(area.targets, area):
        raise MutateError(f"{area.name}: the unmutated tree does not build")
    outcome, output = commands.test(area)
    if outcome != "passed":
        # Else every mutation would count as killed by a failure that was there before.
        raise MutateError(f"{area.name}: the area's tests do not pass on the unmutated tree "
                          f"({outcome}):\n{output}")
    record["baseline_seconds"] = round(time.time() - started, 1)
    for index, mutation in enumerate(area.mutations, 1):
        path = os.path.join(ws.worktree, mutation.path)
        try:
            with open(path, encoding="utf-8") as f:
                text = f.read()
            offset = locate(mutation, text)
        except (MutateError, OSError) as error:
            if not keep_going:
                raise MutateError(str(error))
            record["results"].append(result_entry(mutation, None, "invalid", 0, str(error)))
            log(f"  [{index}/{len(area.mutations)}] invalid  {error}")
            continue
        line = line_of(text, offset)
        begun = time.time()
        try:
            ws.apply(mutation, text)
            if not commands.build(area.targets, area):
                status, detail = "stillborn", ""
            else:
                outcome, detail = commands.test(area)
                status = {"passed": "survived", "failed": "killed", "timeout": "timeout"}[outcome]
                if status == "survived" and mutation.marked_equivalent():
                    status = "equivalent"
                elif status != "survived" and mutation.marked_equivalent():
                    log(f"  note: {mutation.where()} is marked equivalent but was {status}: the mark is wrong")
        except KeyboardInterrupt:
            ws.interrupted_in = mutation.path
            raise
        finally:
            ws.restore()
        seconds = round(time.time() - begun, 1)
        record["results"].append(result_entry(mutation, line, status, seconds, ""))
        log(f"  [{index}/{len(area.mutations)}] {status:9} {mutation.path}:{line}  "
            f"{mutation.original!r} -> {mutation.replacement!r}  ({seconds} s)")
    # Back to the unmutated build, so that the build directory matches the tree.
    commands.build(area.targets, area)
    record["seconds"] = round(time.time() - started, 1)
    record.update(tally(record["results"]))
    return record


def result_entry(mutation, line, status, seconds, error):
    return {"file": mutation.path, "line": line, "original": mutation.original,
            "replacement": mutation.replacement, "why": mutation.why,
            "list_line": mutation.where(), "status": status, "seconds": seconds,
            **({"error": error} if error else {})}


def tally(results):
    counts = {key: sum(1 for r in results if r["status"] == key)
              for key in ("killed", "timeout", "stillborn", "survived", "equivalent", "invalid")}
    valid = sum(counts[k] for k in ("killed", "timeout", "stillborn", "survived"))
    detected = counts["killed"] + counts["timeout"] + counts["stillborn"]
    counts["kill_rate"] = round(100.0 * detected / valid, 1) if valid else None
    return counts


def summary_text(report):
    lines = [f"mutation run of {report['commit']} ({report['jobs']} jobs)", ""]
    lines.append(f"{'area':24} {'killed':>6} {'timeout':>7} {'stillborn':>9} {'survived':>8} "
                 f"{'equivalent':>10} {'invalid':>7} {'rate':>6} {'time':>8}")
    for area in report["areas"]:
        if area.get("error"):
            lines.append(f"{area['area']:24} error: {area['error'].splitlines()[0]}")
            continue
        rate = "-" if area["kill_rate"] is None else f"{area['kill_rate']:.1f}%"
        lines.append(f"{area['area']:24} {area['killed']:>6} {area['timeout']:>7} "
                     f"{area['stillborn']:>9} {area['survived']:>8} {area['equivalent']:>10} {area['invalid']:>7} "
                     f"{rate:>6} {area['seconds'] / 60:>6.1f} m")
    for status, title in (("survived", "survivors (nothing notices these changes):"),
                          ("equivalent", "equivalent (survived; left out of the rate, their lists say why):")):
        listed = [(a["area"], r) for a in report["areas"] for r in a.get("results", [])
                  if r["status"] == status]
        if listed:
            lines += ["", title]
            for area, r in listed:
                lines.append(f"  {area}: {r['file']}:{r['line']}  {r['original']!r} -> "
                             f"{r['replacement']!r}  ({r['why']})")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------- main

def load_areas(list_dir, names, everything):
    available = sorted(f[:-4] for f in os.listdir(list_dir) if f.endswith(".txt"))
    if everything:
        names = available
    unknown = [n for n in names if n not in available]
    if unknown:
        raise MutateError(f"unknown area {', '.join(unknown)}; the areas are: {', '.join(available)}")
    return [parse_list(os.path.join(list_dir, f"{n}.txt")) for n in names]


def check_against_commit(areas, repo, commit):
    """Every mutation's fragment found exactly once in its file at the commit; errors listed."""
    errors = []
    for area in areas:
        for mutation in area.mutations:
            shown = subprocess.run(["git", "-C", repo, "show", f"{commit}:{mutation.path}"],
                                   capture_output=True)
            if shown.returncode != 0:
                errors.append(f"{mutation.where()}: {mutation.path} does not exist at {commit[:12]}")
                continue
            try:
                locate(mutation, shown.stdout.decode("utf-8"))
            except MutateError as error:
                errors.append(str(error))
    return errors


def parse_arguments(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--area", action="append", default=[], help="an area to run (repeatable)")
    parser.add_argument("--all", action="store_true", help="every area")
    parser.add_argument("--list", action="store_true",
                        help="list the areas and their mutations, each checked against the commit")
    parser.add_argument("--prepare", action="store_true",
                        help="create the worktree and build every area's targets, nothing more")
    parser.add_argument("--jobs", type=int, default=2, help="build and test parallelism (2)")
    parser.add_argument("--repo", help="the repository (default: the one holding this script)")
    parser.add_argument("--commit", default="HEAD", help="the commit to mutate (HEAD)")
    parser.add_argument("--worktree", help="the worktree to mutate in (<repo>/build-mutate/src)")
    parser.add_argument("--build-dir", help="its build directory (<worktree>/../build)")
    parser.add_argument("--lists", help="the folder of mutation lists (<repo>/tests/mutations)")
    parser.add_argument("--keep-going", action="store_true",
                        help="record an invalid mutation or a failing area and go on")
    parser.add_argument("--report", help="write the JSON report here and a text summary beside it")
    parser.add_argument("--build-cmd", help="shell command instead of cmake --build; {src} "
                        "{build} {targets} {tests} {timeout} {jobs} are replaced")
    parser.add_argument("--test-cmd", help="shell command instead of ctest (exit 0: tests passed)")
    args = parser.parse_args(argv)
    if args.jobs < 1:
        parser.error("--jobs must be at least 1")
    if not (args.area or args.all or args.list or args.prepare):
        parser.error("say what to do: --area NAME, --all, --list or --prepare")
    if args.area and args.all:
        parser.error("--area and --all together")
    args.repo = main_checkout(args.repo or here)
    args.lists = args.lists or os.path.join(args.repo, "tests", "mutations")
    args.worktree = os.path.abspath(args.worktree or os.path.join(args.repo, "build-mutate", "src"))
    args.build_dir = os.path.abspath(args.build_dir or
                                     os.path.join(os.path.dirname(args.worktree), "build"))
    return args


def interrupt_as_keyboard_interrupt(signum, frame):
    raise KeyboardInterrupt


def main(argv):
    args = parse_arguments(argv)
    commit = git(args.repo, "rev-parse", "--verify", f"{args.commit}^{{commit}}")
    areas = load_areas(args.lists, args.area, args.all or args.list or (args.prepare and not args.area))
    errors = check_against_commit(areas, args.repo, commit)
    if args.list:
        for area in areas:
            tests = [area.tests] if area.tests else []
            tests += [f"the {len(test_case_patterns(args.repo, f))} test cases of {f}" for f in area.test_files]
            print(f"{area.name}: {len(area.mutations)} mutations; build {' '.join(area.targets)}; "
                  f"tests {'; '.join(tests)}; {area.timeout} s each")
            for m in area.mutations:
                print(f"  {m.path}: {m.original!r} -> {m.replacement!r}  ({m.why})")
        for error in errors:
            print(f"error: {error}", file=sys.stderr)
        return 1 if errors else 0
    if errors and not args.keep_going:
        raise MutateError("the lists do not match the commit:\n  " + "\n  ".join(errors))

    ws = Workspace(args.repo, args.worktree, args.build_dir, commit)
    commands = Commands(args, ws)
    signal.signal(signal.SIGTERM, interrupt_as_keyboard_interrupt)
    ws.ensure()
    commands.configure()
    if args.prepare:
        targets = sorted({t for a in areas for t in a.targets})
        print(f"mutate: building {' '.join(targets)} in {ws.build}", flush=True)
        if not commands.build(targets, areas[0]):
            raise MutateError(f"the build of {commit[:12]} failed; see {os.path.dirname(ws.worktree)}/last-build.log")
        print("mutate: prepared", flush=True)
        return 0

    def log(message):
        print(message, flush=True)

    report = {"commit": commit, "worktree": ws.worktree, "build": ws.build, "jobs": args.jobs,
              "areas": []}
    status = 0
    try:
        for area in areas:
            try:
                report["areas"].append(run_area(area, ws, commands, args.keep_going, log))
            except MutateError as error:
                if not args.keep_going:
                    raise
                status = 1
                report["areas"].append({"area": area.name, "error": str(error)})
                log(f"  error: {error}")
    except KeyboardInterrupt:
        ws.restore()
        print("mutate: interrupted; " + (f"{ws.interrupted_in} is restored" if ws.interrupted_in
                                         else "no mutation was applied"), file=sys.stderr)
        return 130
    text = summary_text(report)
    print("\n" + text, end="")
    if args.report:
        write_atomically(args.report, (json.dumps(report, indent=2) + "\n").encode())
        write_atomically(os.path.splitext(args.report)[0] + ".txt", text.encode())
    return status


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except MutateError as error:
        print(f"mutate: error: {error}", file=sys.stderr)
        sys.exit(2)
    except KeyboardInterrupt:
        print("mutate: interrupted", file=sys.stderr)
        sys.exit(130)
