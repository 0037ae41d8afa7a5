#!/usr/bin/python3
"""Tests of tools/check_layers.py (run by CTest as check_layers_tool).

A made-up checkout of three modules, low <- mid <- high: includes downwards, directly or through a
used module, pass; an include upwards, of an undeclared module or through '..', or a folder that
is not a declared module is reported with its file and line.
"""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import check_layers  # noqa: E402

TABLE = ["low=", "mid=low", "high=mid"]


def checkout(files):
    root = Path(tempfile.mkdtemp())
    for name, text in files.items():
        path = root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    return root


def problems(files, table=TABLE):
    return check_layers.problems(checkout(files), check_layers.parse_table(table))


class CheckLayers(unittest.TestCase):
    def test_includes_downwards_pass(self):
        self.assertEqual(problems({
            "src/high/a.cpp": '#include "hullinspect/high/a.hpp"\n#include "hullinspect/low/b.hpp"\n',
            "include/hullinspect/mid/c.hpp": '#include "hullinspect/low/b.hpp"\n',
            "include/hullinspect/version.hpp": "",
            "src/low/d.cpp": '#include "hullinspect/version.hpp"\n#include "private.hpp"\n',
        }), [])

    def test_an_upward_include_is_reported_with_its_line(self):
        found = problems({"src/low/a.cpp": '// x\n#include "hullinspect/mid/c.hpp"\n'})
        self.assertEqual(len(found), 1)
        self.assertTrue(found[0].startswith("src/low/a.cpp:2: module 'low' includes module 'mid'"),
                        found[0])

    def test_an_upward_include_in_a_public_header_is_reported(self):
        found = problems({"include/hullinspect/mid/c.hpp": '#include <hullinspect/high/a.hpp>\n'})
        self.assertEqual(len(found), 1)
        self.assertIn("include/hullinspect/mid/c.hpp:1: module 'mid' includes module 'high'",
                      found[0])

    def test_siblings_do_not_see_each_other(self):
        table = ["low=", "left=low", "right=low", "top=left,right"]
        self.assertEqual(problems({"src/top/a.cpp": '#include "hullinspect/right/r.hpp"\n'},
                                  table), [])
        found = problems({"src/left/a.cpp": '#include "hullinspect/right/r.hpp"\n'}, table)
        self.assertEqual(len(found), 1)
        self.assertIn("module 'left' includes module 'right'", found[0])

    def test_a_relative_include_out_of_the_folder_is_reported(self):
        found = problems({"src/low/a.cpp": '#include "../mid/private.hpp"\n'})
        self.assertEqual(len(found), 1)
        self.assertIn("src/low/a.cpp:1: includes a path with '..'", found[0])

    def test_undeclared_modules_are_reported(self):
        found = problems({"src/extra/a.cpp": "",
                          "src/low/b.cpp": '#include "hullinspect/nowhere/x.hpp"\n'})
        self.assertEqual(len(found), 2)
        self.assertIn("src/extra/a.cpp: folder 'extra' is not a declared module", found[0])
        self.assertIn("src/low/b.cpp:1: includes module 'nowhere', which is not a declared module",
                      found[1])

    def test_a_module_may_use_only_modules_declared_before_it(self):
        with self.assertRaises(SystemExit):
            check_layers.parse_table(["mid=low", "low="])


if __name__ == "__main__":
    unittest.main()
