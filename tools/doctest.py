#!/usr/bin/python3
"""Runs the shell examples of README.md and docs/**/*.md and compares the output they show.

The convention (documented at the top of docs/user-guide.md):

* A ```sh block is a shell example. It runs with bash (`set -e -o pipefail`) in a scratch
  directory that looks like the repository root: every top-level entry of the repository is
  linked into it and `build/release` points at the build under test, which is also first on
  PATH (so `hullinspect ...` and `build/release/hullinspect ...` both work). Files the example
  writes land in the scratch directory; the blocks of one document share it, in order.
* If the next fenced block after a ```sh block (only blank lines between) is a ```text block
  or a plain ``` block, it is the example's output (stdout and stderr together) and must match
  exactly, numbers included; trailing spaces and trailing blank lines are ignored.
* In a shown output, `{{...}}` stands for any text within one line (timings, paths), and a line
  that is only `{{...}}` stands for any number of lines (a long output shortened). Nothing else
  is masked.
* An HTML comment on the line before the ```sh block controls it:
    <!-- doctest: skip REASON -->   never run (root-only, needs a cluster, ...)
    <!-- doctest: long REASON -->   run only with --long (takes minutes)
    <!-- doctest: exit N -->        the block must exit with status N (default 0)
    <!-- doctest: timeout S -->     allow S seconds (default 120)
  Several can be combined: `<!-- doctest: exit 2; timeout 10 -->`. Skipped and long blocks are
  listed with their reason in the test's output.

`--update` rewrites every shown output that does not match with the real one, keeping the
`{{...}}` placeholders where the line still has the same shape.
"""

import argparse
import difflib
import os
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
PLACEHOLDER = "{{...}}"
DIRECTIVE = re.compile(r"^\s*<!--\s*doctest:\s*(.*?)\s*-->\s*$")
FENCE_OPEN = re.compile(r"^```(\S*)\s*$")
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
DEFAULT_TIMEOUT = 120


@dataclass
class Block:
    path: Path
    line: int  # 1-based line of the ```sh fence
    script: str
    output: list | None = None  # shown output lines, None if no output block
    output_range: tuple | None = None  # (first, last) 0-based line indexes of the output body
    skip: str | None = None
    long: str | None = None
    exit_status: int = 0
    timeout: float = DEFAULT_TIMEOUT
    directive_errors: list = field(default_factory=list)


def parse_directive(text, block):
    # A reason runs to the end of the comment unless another directive follows after a ';'.
    parts = re.split(r";\s*(?=(?:skip|long|exit|timeout)\b)", text)
    for part in filter(None, (p.strip() for p in parts)):
        word, _, rest = part.partition(" ")
        rest = rest.strip()
        if word == "skip":
            block.skip = rest or "(no reason given)"
        elif word == "long":
            block.long = rest or "(no reason given)"
        elif word == "exit" and rest.isdigit():
            block.exit_status = int(rest)
        elif word == "timeout" and re.fullmatch(r"\d+(\.\d+)?", rest):
            block.timeout = float(rest)
        else:
            block.directive_errors.append(f"unknown doctest directive '{part}'")


def fenced_blocks(lines):
    """Yields (info, first_body_line, end_line) for every fenced block (0-based indexes)."""
    i = 0
    while i < len(lines):
        m = FENCE_OPEN.match(lines[i])
        if not m:
            i += 1
            continue
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != "```":
            j += 1
        yield m.group(1), i, j
        i = j + 1


def parse(path):
    lines = path.read_text(encoding="utf-8").split("\n")
    fences = list(fenced_blocks(lines))
    blocks = []
    for k, (info, start, end) in enumerate(fences):
        if info != "sh":
            continue
        block = Block(path, start + 1, "\n".join(lines[start + 1:end]) + "\n")
        prev = start - 1
        if prev >= 0:
            m = DIRECTIVE.match(lines[prev])
            if m:
                parse_directive(m.group(1), block)
        if k + 1 < len(fences):
            ninfo, nstart, nend = fences[k + 1]
            between = lines[end + 1:nstart]
            if ninfo in ("", "text") and all(not s.strip() for s in between):
                block.output = lines[nstart + 1:nend]
                block.output_range = (nstart + 1, nend)
        blocks.append(block)
    return blocks


def normalise(text):
    out = [line.rstrip() for line in text.replace("\r\n", "\n").split("\n")]
    while out and not out[-1]:
        out.pop()
    return out


def expected_regex(expected):
    parts = []
    for line in expected:
        if line.strip() == PLACEHOLDER:
            parts.append(r"(?:[^\n]*\n)*?")
        else:
            pieces = line.rstrip().split(PLACEHOLDER)
            parts.append("[^\n]*?".join(re.escape(p) for p in pieces) + r"\n")
    return re.compile("".join(parts))


def matches(expected, actual):
    exp = normalise("\n".join(expected))
    return expected_regex(exp).fullmatch("".join(a + "\n" for a in actual)) is not None


def remask_line(expected_line, actual_line):
    """The actual line with the expected line's placeholders kept, if they have the same shape."""
    pieces = expected_line.split(PLACEHOLDER)
    regex = []
    for piece in pieces:
        pos = 0
        chunk = []
        for m in NUMBER.finditer(piece):
            chunk.append(re.escape(piece[pos:m.start()]) + "(" + NUMBER.pattern + ")")
            pos = m.end()
        chunk.append(re.escape(piece[pos:]))
        regex.append("".join(chunk))
    m = re.fullmatch("([^\n]*?)".join(regex), actual_line)
    if not m:
        return None
    # Rebuild from the actual text, putting the placeholders back over their groups.
    groups = list(m.groups())
    out, gi, pos = [], 0, 0
    # group order: numbers of piece 0, placeholder 0, numbers of piece 1, ...
    spans = [m.span(g + 1) for g in range(len(groups))]
    numbers_per_piece = [len(NUMBER.findall(p)) for p in pieces]
    for pi, count in enumerate(numbers_per_piece):
        gi += count
        if pi < len(pieces) - 1:
            start, end = spans[gi]
            out.append(actual_line[pos:start] + PLACEHOLDER)
            pos = end
            gi += 1
    out.append(actual_line[pos:])
    return "".join(out)


def updated_output(expected, actual):
    if any(line.strip() == PLACEHOLDER for line in expected):
        k = [line.strip() for line in expected].index(PLACEHOLDER)
        head, tail = expected[:k], expected[k + 1:]
        if len(actual) > len(head) + len(tail):
            return (updated_output(head, actual[:len(head)]) + [PLACEHOLDER]
                    + updated_output(tail, actual[len(actual) - len(tail):] if tail else []))
        return list(actual)
    masked = [line for line in expected if PLACEHOLDER in line]
    out = []
    for line in actual:
        for j, exp in enumerate(masked):
            remasked = remask_line(exp, line)
            if remasked is not None:
                out.append(remasked)
                del masked[j]
                break
        else:
            out.append(line)
    return out


def make_scratch(bin_dir):
    scratch = Path(tempfile.mkdtemp(prefix="hullinspect-doctest-"))
    for entry in REPO.iterdir():
        if entry.name in (".git", "build"):
            continue
        (scratch / entry.name).symlink_to(entry)
    (scratch / "build").mkdir()
    (scratch / "build" / "release").symlink_to(bin_dir)
    return scratch


def run_block(block, scratch, bin_dir):
    env = dict(os.environ)
    env["PATH"] = f"{scratch / 'build' / 'release'}:{env.get('PATH', '/usr/bin:/bin')}"
    env["LC_ALL"] = "C.UTF-8"
    env["TZ"] = "UTC"
    env["COLUMNS"] = "100"
    env.pop("HULLINSPECT_JOBS", None)
    try:
        proc = subprocess.run(["/bin/bash", "-e", "-o", "pipefail", "-c", block.script],
                              cwd=scratch, env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.STDOUT, timeout=block.timeout)
    except subprocess.TimeoutExpired as e:
        out = e.stdout.decode("utf-8", "replace") if e.stdout else ""
        return None, normalise(out)
    return proc.returncode, normalise(proc.stdout.decode("utf-8", "replace"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("files", nargs="*", type=Path,
                        help="markdown files (default: README.md and docs/**/*.md)")
    parser.add_argument("--bin", type=Path, default=REPO / "build" / "release",
                        help="build directory holding hullinspect (default: build/release)")
    parser.add_argument("--update", action="store_true",
                        help="rewrite the shown outputs that do not match")
    parser.add_argument("--long", action="store_true", help="also run blocks marked long")
    parser.add_argument("-k", dest="pattern", default=None,
                        help="only blocks whose command contains this text")
    args = parser.parse_args()

    bin_dir = args.bin.resolve()
    if not (bin_dir / "hullinspect").is_file():
        print(f"doctest: --bin {args.bin}: no hullinspect binary there (build first)",
              file=sys.stderr)
        return 2
    files = args.files or [REPO / "README.md"] + sorted((REPO / "docs").rglob("*.md"))
    failures, checked, ran, skipped = 0, 0, 0, []
    for path in files:
        path = path.resolve()
        blocks = parse(path)
        rel = path.relative_to(REPO) if path.is_relative_to(REPO) else path
        if not blocks:
            continue
        scratch = make_scratch(bin_dir)
        lines = path.read_text(encoding="utf-8").split("\n")
        replacements = []
        try:
            for block in blocks:
                where = f"{rel}:{block.line}"
                for err in block.directive_errors:
                    print(f"FAIL {where}: {err}")
                    failures += 1
                if args.pattern and args.pattern not in block.script:
                    continue
                if block.skip:
                    skipped.append(f"{where}: skipped: {block.skip}")
                    continue
                if block.long and not args.long:
                    skipped.append(f"{where}: long, run with --long: {block.long}")
                    continue
                status, actual = run_block(block, scratch, bin_dir)
                ran += 1
                problem = None
                if status is None:
                    problem = f"timed out after {block.timeout:g} s"
                elif status != block.exit_status:
                    problem = f"exit status {status}, expected {block.exit_status}"
                if block.output is not None:
                    checked += 1
                    if not matches(block.output, actual):
                        if args.update and problem is None:
                            new = updated_output(normalise("\n".join(block.output)), actual)
                            replacements.append((block.output_range, new))
                            print(f"UPDATED {where}")
                        else:
                            problem = problem or "output differs from the one shown"
                if problem:
                    failures += 1
                    print(f"FAIL {where}: {problem}\n  $ " + block.script.strip().replace(
                        "\n", "\n    "))
                    if block.output is not None:
                        diff = difflib.unified_diff(normalise("\n".join(block.output)), actual,
                                                    "shown", "actual", lineterm="")
                        print("\n".join("  " + d for d in diff))
                    else:
                        print("\n".join("  | " + a for a in actual[-20:]))
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
        if replacements:
            for (first, last), new in sorted(replacements, reverse=True):
                lines[first:last] = new
            tmp = path.with_name(path.name + ".doctest-tmp")
            tmp.write_text("\n".join(lines), encoding="utf-8")
            os.replace(tmp, path)
    for s in skipped:
        print(s)
    print(f"doctest: ran {ran} blocks ({checked} with shown output), {len(skipped)} not run, "
          f"{failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
