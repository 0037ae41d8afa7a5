#!/usr/bin/env python3
"""Whole-CLI mutation test (run by scripts/long-test, normally on the ASan/UBSan build).

Mutates seed inputs of every file format the CLI reads (text and PGM hull masks, hull JSON, meshes,
YAML experiment configs, TSP instances, mission traces) with a seeded random stream and feeds each to the command that reads it.
Every run must end with exit status 0, 2 (bad input; exactly one stderr line "hullinspect: ...") or
3 (a valid but unfinished mission), never 1, a signal, a time-out or a sanitizer report. Failing
inputs are copied to OUT/findings/. Prints a summary; exit status 0 when nothing was found.
"""
import argparse
import concurrent.futures
import os
import random
import shutil
import subprocess
import sys
import tempfile
import time

TOKENS = [b"1e400", b"-1", b"18446744073709551616", b"4294967306", b"nan", b"inf", b"\n", b"\x00",
          b"[", b"]", b"{", b"}", b"\"", b",", b":", b"9999999999", b"P5", b"P2", b"#", b"X", b".",
          b"\xff", b"-0", b"0.5", b"1e-300", b"\r\n", b"  ", b"null", b"true", b"- ", b"&a", b"*a"]


def mutate(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        op = rng.randrange(6)
        pos = rng.randrange(len(data) + 1)
        if op == 0 and data:
            data[min(pos, len(data) - 1)] ^= 1 << rng.randrange(8)
        elif op == 1 and data:
            del data[pos:pos + rng.randint(1, 16)]
        elif op == 2:
            data[pos:pos] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 8)))
        elif op == 3:
            data[pos:pos] = rng.choice(TOKENS)
        elif op == 4 and data:
            start = rng.randrange(len(data))
            data[pos:pos] = data[start:start + rng.randint(1, 64)]
        else:
            data = data[:pos]
    return bytes(data)


# The command that reads each format of the seed directory. The exported waypoint files have no
# CLI reader (only the round-trip tests read them back), so fuzz_export_readers covers them alone.
def command(fmt, path, work):
    if fmt in ("text_mask", "pgm", "hull_json"):
        return ["run", "--hull", path, "-n", "2", "--time-limit", "300", "--json"]
    if fmt == "mesh":
        return ["hull", "import", path, "--out", os.path.join(work, "imported"), "--cell-size", "0.25"]
    if fmt == "yaml_config":
        return ["experiment", "--dry-run", "--config", path]
    if fmt == "tsp_json":
        return ["tsp", "--time-limit", "2", path]
    if fmt == "trace_json":
        return ["view", path, "--out", os.path.join(work, "out.html")]
    return None


def input_name(fmt, hint):
    """The mesh reader picks the format by the file name's suffix: the fuzz corpus's hint byte."""
    if fmt == "mesh":
        return "input" + (".stl", ".obj", ".ply")[hint % 3]
    return "input" + {"text_mask": ".txt", "pgm": ".pgm", "yaml_config": ".yaml"}.get(fmt, ".json")


def check(cli, fmt, hint, index, data, base):
    work = os.path.join(base, f"case-{index}")
    os.makedirs(work)
    path = os.path.join(work, input_name(fmt, hint))
    with open(path, "wb") as f:
        f.write(data)
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1", UBSAN_OPTIONS="print_stacktrace=1")
    try:
        r = subprocess.run([cli] + command(fmt, path, work), capture_output=True, timeout=120,
                           env=env, cwd=work)
        status, err = r.returncode, r.stderr
    except subprocess.TimeoutExpired:
        status, err = "timeout", b""
    problem = None
    if status not in (0, 2, 3):
        problem = f"exit {status}"
    elif b"Sanitizer" in err or b"runtime error:" in err:
        problem = "sanitizer report"
    elif status == 2 and (err.count(b"\n") != 1 or not err.startswith(b"hullinspect: ")):
        problem = "not one line"
    shutil.rmtree(work, ignore_errors=True)
    return problem, status, err


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--seeds", required=True, help="directory with one sub-directory per format")
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--out", default="build/mutation")
    args = parser.parse_args()
    args.cli = os.path.abspath(args.cli)
    rng = random.Random(args.seed)
    seeds = []
    for fmt in sorted(os.listdir(args.seeds)):
        d = os.path.join(args.seeds, fmt)
        if command(fmt, "", "") is None:
            continue
        for name in sorted(os.listdir(d)):
            with open(os.path.join(d, name), "rb") as f:
                data = f.read()
            # A mesh seed of fuzz/corpus starts with fuzz_mesh's format-hint byte, not file bytes.
            hint = 0
            if fmt == "mesh" and data:
                hint, data = data[0], data[1:]
            seeds.append((fmt, hint, data))
    cases = []
    for i in range(args.count):
        fmt, hint, data = seeds[i % len(seeds)]
        cases.append((fmt, hint, i, mutate(data, rng)))
    base = tempfile.mkdtemp(prefix="hullinspect-mutation-")
    findings = os.path.join(args.out, "findings")
    os.makedirs(findings, exist_ok=True)
    statuses = {}
    found = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(check, args.cli, fmt, hint, i, data, base): (fmt, i, data)
                   for fmt, hint, i, data in cases}
        start = time.monotonic()
        for done, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            fmt, i, data = futures[fut]
            problem, status, err = fut.result()
            statuses[(fmt, status)] = statuses.get((fmt, status), 0) + 1
            # A progress line now and then: a run cut short still tells how far it got.
            if done % 500 == 0:
                elapsed = time.monotonic() - start
                print(f"progress: {done} of {len(cases)} inputs in {elapsed:.0f} s, "
                      f"{found} findings so far", flush=True)
            if problem:
                found += 1
                with open(os.path.join(findings, f"{fmt}-{i}.input"), "wb") as f:
                    f.write(data)
                with open(os.path.join(findings, f"{fmt}-{i}.stderr"), "wb") as f:
                    f.write(err)
                print(f"FINDING {fmt} #{i}: {problem}: {err[:300]!r}", flush=True)
    shutil.rmtree(base, ignore_errors=True)
    for (fmt, status), n in sorted(statuses.items(), key=str):
        print(f"  {fmt}: exit {status}: {n}")
    print(f"{len(cases)} mutated inputs, {found} findings")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
