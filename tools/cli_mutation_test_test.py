#!/usr/bin/python3
"""Tests of tools/cli_mutation_test.py (run by CTest as cli_mutation_tool).

The checker is run against a stand-in CLI (a shell script) that behaves well or breaks one rule
at a time; it must pass the first and report every other.
"""

import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

TOOL = Path(__file__).resolve().parent / "cli_mutation_test.py"

# The stand-in: writes the fixture trace when asked for it, else misbehaves as $MODE says.
CLI = r"""#!/bin/sh
for a in "$@"; do
  if [ "$prev" = "--trace" ]; then echo '{}' > "$a"; exit 0; fi
  prev="$a"
done
case "$MODE" in
  good) echo "hullinspect: $*: bad input" >&2; exit 2 ;;
  exit1) echo "hullinspect: $*: failed" >&2; exit 1 ;;
  two-lines) printf 'hullinspect: %s\nmore\n' "$*" >&2; exit 2 ;;
  nameless) echo "hullinspect: something is wrong" >&2; exit 2 ;;
  stdout) echo "partial"; echo "hullinspect: $*: bad" >&2; exit 2 ;;
  leaves) touch left-behind; echo "hullinspect: $*: bad" >&2; exit 2 ;;
  overwrites) for f in input.*; do echo x > "$f"; done; exit 0 ;;
  hangs) exec sleep 30 ;;
  signal) kill -SEGV $$ ;;
esac
"""


class MutationChecker(unittest.TestCase):
    def run_tool(self, mode):
        with tempfile.TemporaryDirectory() as tmp:
            cli = Path(tmp) / "cli"
            cli.write_text(CLI)
            cli.chmod(0o755)
            seeds = Path(tmp) / "seeds" / "defects_csv"
            seeds.mkdir(parents=True)
            (seeds / "survey.csv").write_text("x_m,z_m,side,w_m,h_m\n1.0,0.5,starboard,1,0.5\n")
            r = subprocess.run(
                [sys.executable, str(TOOL), "--cli", str(cli), "--seeds", str(seeds.parent),
                 "--count", "1", "--jobs", "1", "--timeout", "1", "--out", str(Path(tmp) / "out")],
                capture_output=True, text=True, env=dict(os.environ, MODE=mode))
            return r.returncode, r.stdout

    def test_a_cli_that_keeps_every_rule_passes(self):
        status, out = self.run_tool("good")
        self.assertEqual(status, 0, out)
        self.assertIn("0 findings", out)

    def test_every_broken_rule_is_a_finding(self):
        expected = {
            "exit1": "exit 1",
            "two-lines": "not one line",
            "nameless": "names neither the file nor its option",
            "stdout": "printed to stdout on failure",
            "leaves": "left the directory changed on failure: left-behind",
            "overwrites": "changed an input",
            "hangs": "exit timeout",
            "signal": "exit -11",
        }
        for mode, problem in expected.items():
            with self.subTest(mode=mode):
                status, out = self.run_tool(mode)
                self.assertEqual(status, 1, out)
                self.assertIn(problem, out)


if __name__ == "__main__":
    unittest.main()
