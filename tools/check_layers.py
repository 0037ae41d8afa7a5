#!/usr/bin/python3
"""Refuses an #include of a module that is not below the including module.

The modules and what each uses are declared once, in CMakeLists.txt (hullinspect_module(NAME USES
...)); every build of the library passes that table here as NAME=USE1,USE2 arguments
(cmake/Modules.cmake). A file of module M (src/M/ or include/hullinspect/M/) may include
"hullinspect/X/..." only when X is M or a module M uses, directly or through the modules it uses,
and no path with '..'. Every folder under src/ and include/hullinspect/ must be a declared module.
Prints one line per problem (file:line: what and why) and exits 1 if there is any, 0 otherwise.

  tools/check_layers.py --source DIR core= files=core grid=core world=grid,files ...
"""

import argparse
import pathlib
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]hullinspect/([^/">]+)/')
RELATIVE = re.compile(r'^\s*#\s*include\s*[<"][^">]*\.\./')
SUFFIXES = {".cpp", ".hpp", ".h", ".cc", ".inl"}


def parse_table(entries):
    """{module: [directly used modules]} from NAME=USE1,USE2 words, in declaration order."""
    table = {}
    for entry in entries:
        name, sep, uses = entry.partition("=")
        if not sep or not name:
            raise SystemExit(f"check_layers: '{entry}': expected NAME=USE1,USE2 (USES may be empty)")
        if name in table:
            raise SystemExit(f"check_layers: module '{name}' is declared twice")
        used = [u for u in uses.split(",") if u]
        for u in used:
            if u not in table:
                raise SystemExit(f"check_layers: module '{name}' uses '{u}', not declared before it")
        table[name] = used
    return table


def allowed_modules(table):
    """{module: the modules its files may include: itself and everything below it}."""
    allowed = {}
    for name, used in table.items():  # declaration order: every used module is already done
        below = {name}
        for u in used:
            below |= allowed[u]
        allowed[name] = below
    return allowed


def module_files(source):
    """(module, path) for every C++ file under src/<module>/ and include/hullinspect/<module>/."""
    for root in (source / "src", source / "include" / "hullinspect"):
        if not root.is_dir():
            continue
        for path in sorted(root.rglob("*")):
            if path.is_file() and path.suffix in SUFFIXES:
                parts = path.relative_to(root).parts
                if len(parts) > 1:  # include/hullinspect/version.hpp belongs to no module
                    yield parts[0], path


def problems(source, table):
    allowed = allowed_modules(table)
    found = []
    for module, path in module_files(source):
        shown = path.relative_to(source)
        if module not in allowed:
            found.append(f"{shown}: folder '{module}' is not a declared module "
                         f"(declare it with hullinspect_module in CMakeLists.txt)")
            continue
        with open(path, encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, start=1):
                if RELATIVE.match(line):
                    found.append(f"{shown}:{number}: includes a path with '..', which can reach "
                                 f"any module (write \"hullinspect/<module>/...\")")
                    continue
                match = INCLUDE.match(line)
                if not match:
                    continue
                included = match.group(1)
                if included.endswith((".hpp", ".h")):  # hullinspect/version.hpp: no module
                    continue
                if included not in allowed:
                    found.append(f"{shown}:{number}: includes module '{included}', which is not "
                                 f"a declared module")
                elif included not in allowed[module]:
                    found.append(f"{shown}:{number}: module '{module}' includes module "
                                 f"'{included}', which is not below it (it uses: "
                                 f"{', '.join(sorted(allowed[module] - {module})) or 'nothing'})")
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", type=pathlib.Path, required=True, help="the checkout")
    parser.add_argument("modules", nargs="+", help="NAME=USE1,USE2, in declaration order")
    args = parser.parse_args()
    found = problems(args.source, parse_table(args.modules))
    for line in found:
        print(line)
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
