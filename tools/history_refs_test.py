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

CITING = [
    "measured in session 12 on the tuning seeds",
    "# The session-7 rows switch options off",
    "Sessions 27 and 28 added it",
    "Round 2 of the assignment",
    "see issue 15 item 1",
    "the Issue-12 repro",
    "(issue #4)",
    "fixed in commit 1a2b3c4",
    "main at e8fd7e2, the corpus the runs left",
    "release build at 278a84e, load average 6.4",
    "lives on the branch `parttsp` (at 82a75cf, with `tsp` merged)",
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
        text = "one\ntwo, as in session 3\nthree\n"
        self.assertEqual(history_refs.citations(text), [(2, "a development session",
                                                         "two, as in session 3")])


class Tree(unittest.TestCase):
    def test_a_tree_without_git_is_scanned_file_by_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            (root / "docs").mkdir()
            (root / "docs" / "page.md").write_text("Clean.\nAs measured in session 9.\n")
            (root / "src.cpp").write_text("// what it does\n")
            (root / "data.bin").write_bytes(b"issue 5\0\1\2")  # binary: skipped
            (root / "build").mkdir()
            (root / "build" / "log.txt").write_text("issue 5\n")  # build output: skipped
            count, report = history_refs.check(root)
            self.assertEqual(report, ["docs/page.md:2: cites a development session: "
                                      "As measured in session 9."])

    def test_the_command_exits_1_on_a_citation_and_0_without(self):
        with tempfile.TemporaryDirectory() as tmp:
            root = Path(tmp)
            (root / "a.md").write_text("fine\n")
            tool = str(Path(history_refs.__file__))
            ok = subprocess.run([sys.executable, tool, "--root", tmp], capture_output=True,
                                text=True)
            self.assertEqual(ok.returncode, 0, ok.stderr)
            (root / "a.md").write_text("see issue 3\n")
            bad = subprocess.run([sys.executable, tool, "--root", tmp], capture_output=True,
                                 text=True)
            self.assertEqual(bad.returncode, 1)
            self.assertIn("a.md:1: cites an issue number: see issue 3", bad.stdout)


if __name__ == "__main__":
    unittest.main()
