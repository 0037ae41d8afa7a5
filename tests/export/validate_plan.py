#!/usr/bin/python3
"""Validates QGroundControl .plan files against tests/export/qgc_plan.schema.json (python3-jsonschema).

Usage: validate_plan.py PLAN...   Exit 0 when every file is valid, 1 otherwise (one line per error).
"""
import json
import pathlib
import sys

import jsonschema

schema = json.loads((pathlib.Path(__file__).parent / "qgc_plan.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
validator = jsonschema.Draft202012Validator(schema)
bad = 0
for name in sys.argv[1:]:
    with open(name) as f:
        plan = json.load(f)
    for error in validator.iter_errors(plan):
        path = "/".join(str(p) for p in error.absolute_path)
        print(f"{name}: {path}: {error.message}")
        bad += 1
sys.exit(1 if bad or len(sys.argv) < 2 else 0)
