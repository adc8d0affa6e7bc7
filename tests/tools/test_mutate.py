#!/usr/bin/env python3
"""scripts/mutate.py on a fixture repository (issue #51): a two-function Python "project"
whose build is py_compile and whose test checks one of the two functions, so that each
outcome has a mutation that must produce it. Nothing here builds fgsg.

  python3 tests/tools/test_mutate.py [path/to/scripts/mutate.py]
"""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
MUTATE = os.path.abspath(sys.argv.pop(1) if len(sys.argv) > 1 else
                         os.path.join(HERE, "..", "..", "scripts", "mutate.py"))

CALC = """\
def add(a, b):
    return a + b


def limit(x):
    if x > 10:
        return 10
    return x
"""

# add() is tested, limit() is not: a change to limit() must survive.
TEST = "python3 -c 'import calc; assert calc.add(2, 3) == 5'"
BUILD = "python3 -m py_compile calc.py"

LIST = """\
# A fixture area.
# targets: calc
# tests: unused with --test-cmd
# timeout: 3
calc.py | return a + b | return a - b | the tested function changed: killed
calc.py | if x > 10: | if x >= 10: | the untested function changed: survives
calc.py | return a + b | return a +* b | does not compile: stillborn
calc.py | return a + b | while True: pass | never returns: timeout
"""


def git(repo, *args):
    subprocess.run(["git", "-C", repo, *args], check=True, capture_output=True)


class MutateHarness(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory(prefix="fgsg-mutate-test-")
        self.repo = os.path.join(self.tmp.name, "repo")
        os.makedirs(os.path.join(self.repo, "lists"))
        self.write("calc.py", CALC)
        self.write("lists/demo.txt", LIST)
        git(self.repo, "init", "-q")
        git(self.repo, "-c", "user.name=t", "-c", "user.email=t@t", "add", ".")
        git(self.repo, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qm", "fixture")
        self.worktree = os.path.join(self.tmp.name, "mutate", "src")
        self.calc = os.path.join(self.worktree, "calc.py")

    def tearDown(self):
        subprocess.run(["git", "-C", self.repo, "worktree", "remove", "--force", self.worktree],
                       capture_output=True)
        self.tmp.cleanup()

    def write(self, relative, text):
        with open(os.path.join(self.repo, relative), "w") as f:
            f.write(text)

    def arguments(self, *extra, test=TEST, build=BUILD):
        return [sys.executable, MUTATE, "--repo", self.repo, "--worktree", self.worktree,
                "--lists", os.path.join(self.repo, "lists"), "--build-cmd", build,
                "--test-cmd", test, *extra]

    def run_mutate(self, *extra, **commands):
        return subprocess.run(self.arguments(*extra, **commands), capture_output=True, text=True,
                              timeout=120)

    def assert_pristine(self):
        with open(self.calc) as f:
            self.assertEqual(f.read(), CALC)
        status = subprocess.run(["git", "-C", self.worktree, "status", "--porcelain",
                                 "--untracked-files=no"], capture_output=True, text=True)
        self.assertEqual(status.stdout, "")

    def test_each_outcome_is_classified_and_the_file_restored(self):
        report = os.path.join(self.tmp.name, "report.json")
        result = self.run_mutate("--area", "demo", "--report", report)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(report) as f:
            data = json.load(f)
        area = data["areas"][0]
        self.assertEqual([r["status"] for r in area["results"]],
                         ["killed", "survived", "stillborn", "timeout"])
        self.assertEqual([r["line"] for r in area["results"]], [2, 6, 2, 2])
        self.assertEqual((area["killed"], area["survived"], area["stillborn"], area["timeout"]),
                         (1, 1, 1, 1))
        self.assertEqual(area["kill_rate"], 75.0)  # killed, stillborn and timeout of 4
        head = subprocess.run(["git", "-C", self.repo, "rev-parse", "HEAD"], capture_output=True,
                              text=True).stdout.strip()
        self.assertEqual(data["commit"], head)
        with open(os.path.splitext(report)[0] + ".txt") as f:
            summary = f.read()
        self.assertIn("calc.py:6  'if x > 10:' -> 'if x >= 10:'", summary)
        self.assert_pristine()
        # The checkout the run started from is never written to.
        with open(os.path.join(self.repo, "calc.py")) as f:
            self.assertEqual(f.read(), CALC)

    def test_a_survivor_marked_equivalent_is_left_out_of_the_rate(self):
        # The untested change marked equivalent: out of the rate; the tested one marked
        # equivalent: killed all the same, and the mark called wrong.
        marked = LIST.replace("the untested function changed: survives",
                              "equivalent: nothing calls limit() in this fixture")
        marked = marked.replace("the tested function changed: killed", "Equivalent: a wrong mark")
        self.write("lists/demo.txt", marked)
        report = os.path.join(self.tmp.name, "report.json")
        result = self.run_mutate("--area", "demo", "--report", report)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(report) as f:
            area = json.load(f)["areas"][0]
        self.assertEqual([r["status"] for r in area["results"]],
                         ["killed", "equivalent", "stillborn", "timeout"])
        self.assertEqual((area["survived"], area["equivalent"]), (0, 1))
        self.assertEqual(area["kill_rate"], 100.0)  # 3 of the 3 that can be told apart
        self.assertIn("demo.txt:5 is marked equivalent but was killed: the mark is wrong", result.stdout)
        with open(os.path.splitext(report)[0] + ".txt") as f:
            self.assertIn("equivalent (survived; left out of the rate", f.read())
        self.assert_pristine()

    def test_a_test_printing_bytes_that_are_not_utf8_is_still_classified(self):
        # A failing test's log held a stray 0x80 and the run ended in a UnicodeDecodeError.
        noisy = ("python3 -c 'import sys, calc; sys.stdout.buffer.write(bytes([0x80, 0xff, 10])); "
                 "sys.stdout.flush(); assert calc.add(2, 3) == 5'")
        report = os.path.join(self.tmp.name, "report.json")
        result = self.run_mutate("--area", "demo", "--report", report, test=noisy)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        with open(report) as f:
            area = json.load(f)["areas"][0]
        self.assertEqual([r["status"] for r in area["results"]],
                         ["killed", "survived", "stillborn", "timeout"])
        self.assert_pristine()

    def test_a_fragment_found_zero_or_several_times_is_an_error(self):
        self.write("lists/demo.txt", LIST.replace("if x > 10:", "if x > 11:"))
        result = self.run_mutate("--area", "demo")
        self.assertEqual(result.returncode, 2)
        self.assertIn("demo.txt:6: fragment 'if x > 11:' not found in calc.py", result.stderr)
        self.write("lists/demo.txt", LIST + "calc.py | return | yield | ambiguous\n")
        result = self.run_mutate("--area", "demo")
        self.assertEqual(result.returncode, 2)
        self.assertIn("demo.txt:9: fragment 'return' found 3 times (must be unique) in calc.py",
                      result.stderr)
        self.assertFalse(os.path.exists(self.worktree), "nothing is set up for a stale list")

    def test_keep_going_records_an_invalid_mutation_and_runs_the_others(self):
        self.write("lists/demo.txt", LIST.replace("if x > 10:", "if x > 11:"))
        result = self.run_mutate("--area", "demo", "--keep-going", test="true")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("invalid", result.stdout)
        self.assertIn("demo", result.stdout)
        self.assert_pristine()

    def test_a_failing_unmutated_tree_is_an_error_not_a_kill(self):
        result = self.run_mutate("--area", "demo", test="false")
        self.assertEqual(result.returncode, 2)
        self.assertIn("do not pass on the unmutated tree", result.stderr)
        self.assert_pristine()

    def test_the_shared_checkout_is_refused(self):
        result = subprocess.run([sys.executable, MUTATE, "--repo", self.repo, "--worktree", self.repo,
                                 "--lists", os.path.join(self.repo, "lists"), "--area", "demo",
                                 "--build-cmd", BUILD, "--test-cmd", TEST],
                                capture_output=True, text=True, timeout=60)
        self.assertEqual(result.returncode, 2)
        self.assertIn("is the shared checkout", result.stderr)

    def test_the_worktree_moves_to_the_requested_commit(self):
        first = subprocess.run(["git", "-C", self.repo, "rev-parse", "HEAD"], capture_output=True,
                               text=True).stdout.strip()
        self.assertEqual(self.run_mutate("--area", "demo", test="true").returncode, 0)
        self.write("calc.py", CALC + "\n\ndef twice(x):\n    return 2 * x\n")
        git(self.repo, "-c", "user.name=t", "-c", "user.email=t@t", "commit", "-qam", "second")
        second = subprocess.run(["git", "-C", self.repo, "rev-parse", "HEAD"], capture_output=True,
                                text=True).stdout.strip()
        worktree_head = lambda: subprocess.run(["git", "-C", self.worktree, "rev-parse", "HEAD"],
                                               capture_output=True, text=True).stdout.strip()
        result = self.run_mutate("--area", "demo", test="true")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(worktree_head(), second)
        result = self.run_mutate("--area", "demo", "--commit", first, test="true")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(worktree_head(), first)

    def interrupt_during_a_test(self, sig):
        """Starts a run whose test waits, signals it while a mutation is applied."""
        marker = os.path.join(self.tmp.name, "testing")
        test = f"if grep -q 'a - b' calc.py; then touch {marker}; sleep 30; fi"
        process = subprocess.Popen(self.arguments("--area", "demo", test=test),
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        deadline = time.time() + 60
        while not os.path.exists(marker) and time.time() < deadline:
            time.sleep(0.05)
        self.assertTrue(os.path.exists(marker), "the first mutation's test never started")
        with open(self.calc) as f:
            self.assertIn("return a - b", f.read())
        process.send_signal(sig)
        _, stderr = process.communicate(timeout=60)
        return process.returncode, stderr

    def test_ctrl_c_restores_the_mutated_file(self):
        returncode, stderr = self.interrupt_during_a_test(signal.SIGINT)
        self.assertEqual(returncode, 130, stderr)
        self.assertIn("restored", stderr)
        self.assert_pristine()

    def test_a_killed_run_is_repaired_by_the_next(self):
        returncode, _ = self.interrupt_during_a_test(signal.SIGKILL)
        self.assertEqual(returncode, -signal.SIGKILL)
        with open(self.calc) as f:
            self.assertIn("return a - b", f.read())  # left mutated: nothing could run
        result = self.run_mutate("--area", "demo", test="true")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("left mutated by an interrupted run", result.stdout)
        self.assert_pristine()

    def test_list_checks_every_mutation_against_the_commit(self):
        result = self.run_mutate("--list")
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("demo: 4 mutations", result.stdout)
        self.write("lists/demo.txt", LIST.replace("if x > 10:", "if x > 11:"))
        result = self.run_mutate("--list")
        self.assertEqual(result.returncode, 1)
        self.assertIn("not found", result.stderr)

    def test_a_malformed_line_names_its_place(self):
        self.write("lists/demo.txt", LIST + "calc.py | return a + b | return a - b\n")
        result = self.run_mutate("--area", "demo")
        self.assertEqual(result.returncode, 2)
        self.assertIn("demo.txt:9: expected 'file | original | replacement | why'", result.stderr)


class TestCasePatterns(unittest.TestCase):
    def test_ctest_names_of_a_catch_file_are_escaped(self):
        sys.path.insert(0, os.path.dirname(MUTATE))
        import mutate
        with tempfile.TemporaryDirectory() as root:
            os.makedirs(os.path.join(root, "tests", "unit", "runtime"))
            with open(os.path.join(root, "tests", "unit", "runtime", "test_x.cpp"), "w") as f:
                f.write('TEST_CASE("cga: Subdiv (1r, 2) on 10 [m]", "[cga]") {}\n'
                        'TEST_CASE("a \\"quoted\\" name") {}\n')
            self.assertEqual(mutate.test_case_patterns(root, "tests/unit/runtime/test_x.cpp"),
                             [r"^runtime:cga: Subdiv \(1r, 2\) on 10 \[m\]$",
                              r'^runtime:a "quoted" name$'])


if __name__ == "__main__":
    unittest.main()
