#!/usr/bin/python3
"""Finds references to the project's development history in its files.

The project speaks of itself only: docs, comments, test names, bench configs and tools say what a
thing is, does or measures, never which development session, issue or commit it came from (that
history belongs in `git log`). This lists every line that cites one:

* a numbered session or round of work (the word, then a number, after a blank or a hyphen);
* a numbered issue (the word, then a number, after a blank, a hyphen or "#");
* a commit by its hash ("commit", or "main", "build", "branch" or "merged" and "at", then seven
  to forty hexadecimal digits).

The tests (history_refs_test.py) hold examples of each, assembled at run time so that this
checker does not find them in its own tests.

The files are the ones git tracks (`git ls-files`), or, where the checkout has no git, every
text file under the source tree but build, result and hidden directories. Exit status 0 when
none cites history, 1 (one line per citation: file:line: text) when some do, 2 on bad usage.

    /usr/bin/python3 tools/history_refs.py [--root DIR]
"""

import argparse
import re
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
MAX_BYTES = 2_000_000  # larger files are data (meshes, traces), not prose

# A hexadecimal word that looks like an abbreviated or full commit hash: 7 to 40 hex digits with
# at least one letter and one digit (so neither a plain number nor an English word matches).
HASH = r"(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}\b"
PATTERNS = [
    ("a development session", re.compile(r"\bsessions?[ -]#?[0-9]+\b", re.IGNORECASE)),
    ("a round of work", re.compile(r"\brounds? #?[0-9]+\b", re.IGNORECASE)),
    ("an issue number", re.compile(r"\bissues?[ -]#?[0-9]+\b", re.IGNORECASE)),
    ("a commit hash", re.compile(r"\bcommits? " + HASH, re.IGNORECASE)),
    ("a commit hash", re.compile(r"\b(?:main|build|branch|checkout|merged?|HEAD)\b[^\n]{0,24}?\bat "
                                 + HASH)),
]

# This checker and its test spell out what they look for.
SELF = {"tools/history_refs.py", "tools/history_refs_test.py"}
SKIPPED_DIRS = {"build", "results", "report", "node_modules", "__pycache__"}


def tracked_files(root):
    """The files git tracks under root, or None when root is not the top of a git checkout."""
    try:
        top = subprocess.run(["git", "-C", str(root), "rev-parse", "--show-toplevel"],
                             capture_output=True, check=True, timeout=60, text=True).stdout
        if Path(top.strip()).resolve() != root.resolve():
            return None
        out = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--cached", "--others",
                              "--exclude-standard"], capture_output=True,
                             check=True, timeout=60).stdout
    except (OSError, subprocess.CalledProcessError, subprocess.TimeoutExpired):
        return None
    return [p for p in out.decode("utf-8", "surrogateescape").split("\0") if p]


def tree_files(root):
    """Every file under root but build, result and hidden directories (no git)."""
    files = []
    for path in sorted(root.rglob("*")):
        rel = path.relative_to(root)
        if any(part.startswith(".") or part in SKIPPED_DIRS or part.startswith("build")
               for part in rel.parts[:-1]):
            continue
        if path.is_file() and not path.is_symlink():
            files.append(rel.as_posix())
    return files


def text_of(path):
    """The file's text, or None for binary, unreadable or data-sized files."""
    try:
        if path.stat().st_size > MAX_BYTES:
            return None
        data = path.read_bytes()
    except OSError:
        return None
    if b"\0" in data:
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return None


def citations(text):
    """(line number, what, line) for every line of text that cites history."""
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        for what, pattern in PATTERNS:
            if pattern.search(line):
                found.append((number, what, line.strip()))
                break
    return found


def check(root):
    files = tracked_files(root)
    if files is None:
        files = tree_files(root)
    report = []
    for rel in files:
        if rel in SELF:
            continue
        text = text_of(root / rel)
        if text is None:
            continue
        for number, what, line in citations(text):
            report.append(f"{rel}:{number}: cites {what}: {line[:160]}")
    return len(files), report


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=Path, default=REPO, help="checkout to scan (default: this one)")
    args = parser.parse_args(argv)
    if not args.root.is_dir():
        print(f"history_refs: --root {args.root}: not a directory", file=sys.stderr)
        return 2
    count, report = check(args.root.resolve())
    for line in report:
        print(line)
    if report:
        print(f"history_refs: {len(report)} line(s) cite development history; say what the thing "
              "is or does instead (history belongs in git log)", file=sys.stderr)
        return 1
    print(f"history_refs: {count} files, none cites development history")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
