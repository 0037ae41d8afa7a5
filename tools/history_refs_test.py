#!/usr/bin/python3
"""Tests of tools/history_refs.py (run by CTest as history_refs_tool).

Each kind of citation is found, text that only resembles one is not, and a scratch tree without
git is scanned file by file (binary and build files left out).
"""

import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import history_refs  # noqa: E402

# Citations of each kind, assembled here so that the checker does not find them in this file.
SESSION, ROUND, ISSUE, COMMIT = "sess" + "ion", "Ro" + "und", "iss" + "ue", "com" + "mit"
CITING = [
    f"measured in {SESSION} 12 on the tuning seeds",
    f"# The {SESSION}-7 rows switch options off",
    f"{SESSION.capitalize()}s 27 and 28 added it",
    f"{ROUND} 2 of the assignment",
    f"see {ISSUE} 15 item 1",
    f"the {ISSUE.capitalize()}-12 repro",
    f"({ISSUE} #4)",
    f"fixed in {COMMIT} " + "1a2b3c4",
    "main " + "at e8fd7e2, the corpus the runs left",
    "release build " + "at 278a84e, load average 6.4",
    "lives on the branch `parttsp` (" + "at 82a75cf, with `tsp` merged)",
]

NOT_CITING = [
    "a UAV's live session (the Python module's Session)",
    "escape rounds run after attempt 0",
    "three rounds of 2-opt, then Or-opt",
    "hash 5f6762874a04fea0 of the hull",  # a data hash, not a commit
    "the build takes 1000000 steps",
    "see docs/model.md §10 for the issues a failure raises",
    "seeds 1 000 000 … 1 000 099",
    "commit the journal line at 3 s",
]


class Citations(unittest.TestCase):
    def test_every_kind_of_citation_is_found(self):
        for line in CITING:
            with self.subTest(line=line):
                self.assertEqual(len(history_refs.citations(line)), 1)

    def test_text_that_only_resembles_one_is_not(self):
        for line in NOT_CITING:
            with self.subTest(line=line):
                self.assertEqual(history_refs.citations(line), [])

    def test_the_line_number_is_reported(self):
        text = f"one\ntwo, as in {SESSION} 3\nthree\n"
        self.assertEqual(history_refs.citations(text), [(2, "a development session",
                                                         f"two, as in {SESSION} 3")])


class Tree(unittest.TestCase):
    def test_a_tree_without_git_is_scanned_file_by_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            (root / "docs").mkdir()
            (root / "docs" / "page.md").write_text(f"Clean.\nAs measured in {SESSION} 9.\n")
            (root / "src.cpp").write_text("// what it does\n")
            (root / "data.bin").write_bytes(ISSUE.encode() + b" 5\0\1\2")  # binary: skipped
            (root / "build").mkdir()
            (root / "build" / "log.txt").write_text(f"{ISSUE} 5\n")  # build output: skipped
            count, report = history_refs.check(root)
            self.assertEqual(report, ["docs/page.md:2: cites a development session: "
                                      f"As measured in {SESSION} 9."])

    def test_the_command_exits_1_on_a_citation_and_0_without(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            (root / "a.md").write_text("fine\n")
            tool = str(Path(history_refs.__file__))
            ok = subprocess.run([sys.executable, tool, "--root", tmp], capture_output=True,
                                text=True)
            self.assertEqual(ok.returncode, 0, ok.stderr)
            (root / "a.md").write_text(f"see {ISSUE} 3\n")
            bad = subprocess.run([sys.executable, tool, "--root", tmp], capture_output=True,
                                 text=True)
            self.assertEqual(bad.returncode, 1)
            self.assertIn(f"a.md:1: cites an issue number: see {ISSUE} 3", bad.stdout)


if __name__ == "__main__":
    unittest.main()
