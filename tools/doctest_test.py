#!/usr/bin/python3
"""Tests of tools/doctest.py on small markdown files (run by CTest as docs_tool)."""

import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

TOOL = Path(__file__).resolve().parent / "doctest.py"


class DocTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.root = Path(self.dir.name)
        # A fake build directory: the tool only needs a hullinspect file there.
        (self.root / "bin").mkdir()
        fake = self.root / "bin" / "hullinspect"
        fake.write_text("#!/bin/sh\necho \"fake hullinspect $*\"\n")
        fake.chmod(0o755)

    def tearDown(self):
        self.dir.cleanup()

    def run_tool(self, text, *extra):
        doc = self.root / "doc.md"
        doc.write_text(text)
        proc = subprocess.run([sys.executable, str(TOOL), "--bin", str(self.root / "bin"),
                               *extra, str(doc)], capture_output=True, text=True)
        return proc.returncode, proc.stdout, doc.read_text()

    def test_matching_output_passes(self):
        status, out, _ = self.run_tool("```sh\necho T_c = 373\n```\n\n```text\nT_c = 373\n```\n")
        self.assertEqual(status, 0, out)
        self.assertIn("ran 1 blocks (1 with shown output), 0 not run, 0 failed", out)

    def test_a_changed_number_fails(self):
        status, out, _ = self.run_tool("```sh\necho T_c = 373\n```\n\n```\nT_c = 368\n```\n")
        self.assertEqual(status, 1)
        self.assertIn("output differs from the one shown", out)
        self.assertIn("+T_c = 373", out)

    def test_placeholders_mask_within_a_line_and_whole_lines(self):
        text = ("```sh\nprintf 'a\\nb 12 ms\\nc\\nd\\ne\\n'\n```\n\n"
                "```text\na\nb {{...}} ms\n{{...}}\ne\n```\n")
        status, out, _ = self.run_tool(text)
        self.assertEqual(status, 0, out)

    def test_a_placeholder_does_not_span_lines(self):
        text = "```sh\nprintf 'b 1\\nx ms\\n'\n```\n\n```text\nb {{...}} ms\n```\n"
        status, _, _ = self.run_tool(text)
        self.assertEqual(status, 1)

    def test_exit_status_is_checked(self):
        status, out, _ = self.run_tool("```sh\nfalse\n```\n")
        self.assertEqual(status, 1)
        self.assertIn("exit status 1, expected 0", out)
        status, out, _ = self.run_tool("<!-- doctest: exit 3 -->\n```sh\nexit 3\n```\n")
        self.assertEqual(status, 0, out)

    def test_skip_and_long_are_reported_with_their_reason(self):
        text = ("<!-- doctest: skip needs root -->\n```sh\nfalse\n```\n\n"
                "<!-- doctest: long takes hours; timeout 5 -->\n```sh\nfalse\n```\n")
        status, out, _ = self.run_tool(text)
        self.assertEqual(status, 0, out)
        self.assertIn("skipped: needs root", out)
        self.assertIn("long, run with --long: takes hours", out)
        status, out, _ = self.run_tool(text, "--long")
        self.assertEqual(status, 1)

    def test_unknown_directive_fails(self):
        status, out, _ = self.run_tool("<!-- doctest: skipp x -->\n```sh\ntrue\n```\n")
        self.assertEqual(status, 1)
        self.assertIn("unknown doctest directive 'skipp x'", out)

    def test_the_build_is_on_path_and_at_build_release(self):
        text = ("```sh\nhullinspect run\nbuild/release/hullinspect view\n```\n\n"
                "```text\nfake hullinspect run\nfake hullinspect view\n```\n")
        status, out, _ = self.run_tool(text)
        self.assertEqual(status, 0, out)

    def test_blocks_of_a_document_share_files(self):
        text = ("```sh\necho 42 > x.txt\n```\n\nthen\n\n```sh\ncat x.txt\n```\n\n```text\n42\n```\n")
        status, out, _ = self.run_tool(text)
        self.assertEqual(status, 0, out)

    def test_update_rewrites_numbers_and_keeps_masks(self):
        text = ("intro\n\n```sh\nprintf 'T_c = 373 s\\nplanner time 50.6 ms\\n'\n```\n\n"
                "```text\nT_c = 368 s\nplanner time {{...}} ms\n```\n\nafter\n")
        status, out, doc = self.run_tool(text, "--update")
        self.assertEqual(status, 0, out)
        self.assertIn("UPDATED", out)
        self.assertEqual(doc, text.replace("T_c = 368", "T_c = 373"))
        status, out, _ = self.run_tool(doc)
        self.assertEqual(status, 0, out)

    def test_update_does_not_rewrite_a_failing_command(self):
        text = "```sh\necho 1; exit 4\n```\n\n```text\n2\n```\n"
        status, _, doc = self.run_tool(text, "--update")
        self.assertEqual(status, 1)
        self.assertEqual(doc, text)


if __name__ == "__main__":
    unittest.main()
