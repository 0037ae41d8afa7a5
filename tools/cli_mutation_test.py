#!/usr/bin/env python3
"""Whole-CLI mutation test (scripts/long-test runs it long on the ASan/UBSan build; CTest runs a
short slice of it on the release build).

Mutates seed inputs of every file format the CLI reads (text and PGM hull masks, hull JSON,
meshes: STL ASCII/binary, OBJ, PLY, gzip; YAML experiment configs, TSP instances, mission traces,
--geo files, no-fly and corrosion masks, defect CSV/JSON) with a seeded random stream: bit flips,
deletions, insertions, duplicated chunks, hostile tokens, numbers replaced by hostile numbers,
32-bit fields overwritten, truncation. Each mutated file goes through every command that reads
it, by its option and through an experiment config that names it, in a directory of valid
fixture files. Every run must:
  - end with exit status 0, 2 (bad input) or 3 (a valid but unfinished result): never 1 (no
    environment fails here), a signal, a run longer than --timeout or a sanitizer report;
  - on exit 2, print exactly one stderr line "hullinspect: ..." that names the mutated file (or
    the option or config key it came through), nothing on stdout;
  - on a refusal (exit 2), leave the directory exactly as it was (nothing created, changed or
    removed); otherwise (exit 0 or 3, a result) leave every file that was there unchanged
    (outputs are new files).
Failing inputs are copied to OUT/findings/ with the command and its stderr. Prints a summary;
exit status 0 when nothing was found.
"""
import argparse
import concurrent.futures
import hashlib
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

TOKENS = [b"1e400", b"-1", b"18446744073709551616", b"4294967306", b"nan", b"inf", b"\n", b"\x00",
          b"[", b"]", b"{", b"}", b"\"", b",", b":", b"9999999999", b"P5", b"P2", b"#", b"X", b".",
          b"\xff", b"-0", b"0.5", b"1e-300", b"\r\n", b"  ", b"null", b"true", b"- ", b"&a", b"*a"]

# Numbers a field may be replaced by: out of every range, beyond 32/64 bits, denormal, not finite.
NUMBERS = [b"1e308", b"-1e308", b"1e-320", b"0", b"-0", b"-1", b"4294967308", b"99999999999",
           b"18446744073709551617", b"nan", b"-inf", b"0.1e4000", b"1e30", b"2147483648", b"3",
           b"1000000", b"0x10", b"1.5"]

NUMBER = re.compile(rb"-?\d+(\.\d+)?([eE][-+]?\d+)?")

# The fixtures of every case directory: an 8 x 4 hull of 0.5 m cells (4 m x 2 m, starboard).
HULL = b"XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n"


def mutate(data, rng):
    data = bytearray(data)
    # Half the inputs get one change only, so that many still parse and reach the later checks.
    for _ in range(1 if rng.random() < 0.5 else rng.randint(2, 4)):
        op = rng.randrange(8)
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
        elif op == 5:
            numbers = list(NUMBER.finditer(bytes(data)))
            if numbers:
                m = rng.choice(numbers)
                data[m.start():m.end()] = rng.choice(NUMBERS)
        elif op == 6 and len(data) >= 4:
            # A binary count or index (an STL facet count, a PLY list length) set to anything.
            at = rng.randrange(len(data) - 3)
            data[at:at + 4] = rng.getrandbits(32).to_bytes(4, "little")
        else:
            data = data[:pos]
    return bytes(data)


# How each format is read: (label, argv, config) per reader. {F} is the mutated file's name,
# {W} the case directory (the working directory of the run); a config is written to c.yaml and
# read by `experiment --dry-run --config c.yaml`.
def experiment(yaml):
    return ("experiment config", ["experiment", "--dry-run", "--config", "c.yaml"], yaml)


HULL_READERS = [
    ("run --hull", ["run", "--hull", "{F}", "--uavs", "2", "--time-limit", "300", "--json"], None),
    ("partition --hull", ["partition", "--hull", "{F}", "--uavs", "2", "--out", "{W}/p.txt"], None),
    experiment("hull: {F}\nuavs: [2]\ninstances: 1\n"),
]
MESH_READERS = [
    ("hull import", ["hull", "import", "{F}", "--out", "{W}/imported", "--cell-size", "0.25"], None),
    ("run --hull mesh", ["run", "--hull", "{F}", "--cell-size", "0.25", "--uavs", "1", "--json"], None),
    experiment("hull: {{mesh: {F}, cell-size: 0.25}}\nuavs: [1]\ninstances: 1\n"),
]
MAP_READERS = [
    ("run --prior", ["run", "--hull", "hull.txt", "--prior", "{F}", "--uavs", "2", "--json"], None),
    ("run --truth", ["run", "--hull", "hull.txt", "--truth", "{F}", "--uavs", "2", "--json"], None),
    experiment("hull: hull.txt\ntruth: {F}\nuavs: [2]\ninstances: 1\n"),
]
NO_FLY_READERS = [
    ("run --no-fly", ["run", "--hull", "hull.txt", "--no-fly", "{F}", "--uavs", "2", "--json"], None),
    ("partition --no-fly", ["partition", "--hull", "hull.txt", "--no-fly", "{F}", "--uavs", "2",
                            "--out", "{W}/p.txt"], None),
    ("plan --no-fly", ["plan", "--hull", "hull.txt", "--no-fly", "{F}", "--uavs", "2",
                       "--trace", "{W}/plan.json"], None),
    experiment("hull: hull.txt\nno-fly: {{file: {F}}}\nuavs: [2]\ninstances: 1\n"),
]
DEFECT_READERS = [
    ("run --prior-defects", ["run", "--hull", "hull.txt", "--prior-defects", "{F}", "--uavs", "2",
                             "--json"], None),
    ("run --truth-defects", ["run", "--hull", "hull.txt", "--truth-defects", "{F}", "--uavs", "2",
                             "--json"], None),
    experiment("hull: hull.txt\nprior-defects: {F}\nuavs: [2]\ninstances: 1\n"),
]
READERS = {
    "text_mask": HULL_READERS,
    "pgm": HULL_READERS,
    "hull_json": HULL_READERS,
    "mesh": MESH_READERS,
    "yaml_config": [("experiment --dry-run", ["experiment", "--dry-run", "--config", "{F}"], None)],
    "tsp_json": [("tsp", ["tsp", "--time-limit", "2", "{F}"], None)],
    "trace_json": [
        ("view", ["view", "{F}", "--out", "{W}/out.html"], None),
        ("export", ["export", "{F}", "--out", "{W}/e", "--format", "csv"], None),
    ],
    "geo": [
        ("export --geo", ["export", "trace.json", "--out", "{W}/e", "--format", "qgc", "--geo",
                          "{F}"], None),
        ("run --export --geo", ["run", "--hull", "hull.txt", "--uavs", "2", "--export", "{W}/e",
                                "--format", "wpl", "--geo", "{F}"], None),
    ],
    "user_map": MAP_READERS,
    "no_fly": NO_FLY_READERS,
    "defects_csv": DEFECT_READERS,
    "defects_json": DEFECT_READERS,
}

def input_name(fmt, name, hint):
    """The input keeps its seed's suffix (the readers pick the format by it: .csv or .json
    defects, .pgm or .txt masks); a mesh seed of the fuzz corpus has fuzz_mesh's hint byte
    instead (and .gz for a gzip seed)."""
    if fmt == "mesh":
        return "input" + (".stl", ".obj", ".ply")[hint % 3] + (".gz" if name.endswith(".gz") else "")
    return "input" + (os.path.splitext(name)[1] or ".json")


def snapshot(directory):
    """Every file and directory below `directory` with a digest of its bytes."""
    state = {}
    for root, dirs, files in os.walk(directory):
        for d in dirs:
            state[os.path.relpath(os.path.join(root, d), directory) + "/"] = None
        for f in files:
            p = os.path.join(root, f)
            with open(p, "rb") as h:
                state[os.path.relpath(p, directory)] = hashlib.sha256(h.read()).hexdigest()
    return state


def names_its_input(err, name, argv, config):
    """A message names the file, or the option (`--prior`) or config it came through."""
    line = err.decode("utf-8", "replace")
    if name in line or (config is not None and "c.yaml" in line):
        return True
    return any(a.startswith("--") and a in line for a in argv)


def check(cli, fixtures, case, timeout):
    fmt, name, hint, index, data, reader = case
    label, argv, config = reader
    work = os.path.join(fixtures["base"], f"case-{index}-{label.replace(' ', '_')}")
    os.makedirs(work)
    shutil.copy(fixtures["hull"], os.path.join(work, "hull.txt"))
    shutil.copy(fixtures["trace"], os.path.join(work, "trace.json"))
    path = input_name(fmt, name, hint)
    with open(os.path.join(work, path), "wb") as f:
        f.write(data)
    if config is not None:
        with open(os.path.join(work, "c.yaml"), "w") as f:
            f.write(config.format(F=path))
    args = [a.format(F=path, W=work) for a in argv]
    before = snapshot(work)
    env = dict(os.environ, ASAN_OPTIONS="detect_leaks=1", UBSAN_OPTIONS="print_stacktrace=1")
    try:
        r = subprocess.run([cli] + args, capture_output=True, timeout=timeout, env=env, cwd=work)
        status, out, err = r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired:
        status, out, err = "timeout", b"", b""
    after = snapshot(work)
    problem = None
    if status not in (0, 2, 3):
        problem = f"exit {status}"
    elif b"Sanitizer" in err or b"runtime error:" in err:
        problem = "sanitizer report"
    elif status == 2 and (err.count(b"\n") != 1 or not err.startswith(b"hullinspect: ")
                          or not err.endswith(b"\n")):
        problem = "not one line"
    elif status == 2 and out:
        problem = "printed to stdout on failure"
    elif status == 2 and not names_its_input(err, path, args, config):
        problem = "names neither the file nor its option"
    elif status == 2 and after != before:
        changed = sorted(k for k in set(before) | set(after) if before.get(k) != after.get(k))
        problem = "left the directory changed on failure: " + ", ".join(changed[:3])
    elif any(after.get(k) != v for k, v in before.items()):
        problem = "changed an input"
    shutil.rmtree(work, ignore_errors=True)
    return problem, status, err, args, config


def make_fixtures(cli, base):
    """The hull every case directory holds and a real trace (of a mission with corrosion)."""
    hull = os.path.join(base, "hull.txt")
    with open(hull, "wb") as f:
        f.write(HULL)
    trace = os.path.join(base, "trace.json")
    subprocess.run([cli, "run", "--hull", hull, "--uavs", "2", "--p-c", "0.2", "--seed", "3",
                    "--trace", trace], check=True, capture_output=True)
    return {"base": base, "hull": hull, "trace": trace}


def read_seeds(directories, trace):
    seeds = []
    for directory in directories:
        for fmt in sorted(os.listdir(directory)):
            d = os.path.join(directory, fmt)
            if fmt not in READERS or not os.path.isdir(d):
                continue
            for name in sorted(os.listdir(d)):
                with open(os.path.join(d, name), "rb") as f:
                    data = f.read()
                # A mesh seed of fuzz/corpus starts with fuzz_mesh's format-hint byte.
                hint = 0
                if fmt == "mesh" and data:
                    hint, data = data[0], data[1:]
                seeds.append((fmt, name, hint, data))
    with open(trace, "rb") as f:
        seeds.append(("trace_json", "mission.json", 0, f.read()))
    return seeds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--seeds", required=True, action="append",
                        help="directory with one sub-directory per format (repeatable)")
    parser.add_argument("--count", type=int, default=10000, help="mutated inputs")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=120, help="seconds per run")
    parser.add_argument("--out", default="build/mutation")
    args = parser.parse_args()
    args.cli = os.path.abspath(args.cli)
    rng = random.Random(args.seed)
    base = tempfile.mkdtemp(prefix="hullinspect-mutation-")
    fixtures = make_fixtures(args.cli, base)
    seeds = read_seeds(args.seeds, fixtures["trace"])
    # Every reader of a format gets every mutated input of it.
    cases = []
    for i in range(args.count):
        fmt, name, hint, data = seeds[i % len(seeds)]
        mutated = mutate(data, rng)
        for reader in READERS[fmt]:
            cases.append((fmt, name, hint, i, mutated, reader))
    findings = os.path.join(args.out, "findings")
    os.makedirs(findings, exist_ok=True)
    statuses = {}
    found = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(check, args.cli, fixtures, case, args.timeout): case
                   for case in cases}
        start = time.monotonic()
        for done, fut in enumerate(concurrent.futures.as_completed(futures), 1):
            fmt, name, _, i, data, reader = futures[fut]
            problem, status, err, argv, config = fut.result()
            key = (fmt, reader[0], status)
            statuses[key] = statuses.get(key, 0) + 1
            # A progress line now and then: a run cut short still tells how far it got.
            if done % 500 == 0:
                elapsed = time.monotonic() - start
                print(f"progress: {done} of {len(cases)} runs in {elapsed:.0f} s, "
                      f"{found} findings so far", flush=True)
            if problem:
                found += 1
                stem = os.path.join(findings, f"{fmt}-{i}-{reader[0].replace(' ', '_')}")
                with open(stem + ".input", "wb") as f:
                    f.write(data)
                with open(stem + ".txt", "w") as f:
                    f.write(f"seed: {name}\nproblem: {problem}\nargv: {argv}\n"
                            f"config: {config!r}\nexit: {status}\n")
                with open(stem + ".stderr", "wb") as f:
                    f.write(err)
                print(f"FINDING {fmt} #{i} ({name}) via {reader[0]}: {problem}: {err[:300]!r}",
                      flush=True)
    shutil.rmtree(base, ignore_errors=True)
    for (fmt, label, status), n in sorted(statuses.items(), key=str):
        print(f"  {fmt} via {label}: exit {status}: {n}")
    print(f"{args.count} mutated inputs, {len(cases)} runs, {found} findings")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
