#!/usr/bin/env python3
"""SIGKILL/resume trials of `hullinspect experiment` (run by scripts/long-test).

Runs one experiment uninterrupted as the reference, then for each trial starts the same experiment,
SIGKILLs it after a trial-specific number of finished runs (sometimes twice, across resumes), resumes
it to completion with --resume and checks that runs.csv, samples.csv and curves.csv are
byte-identical to the reference (timings.csv holds wall-clock times; manifest.json timestamps).
Exit status 0 when every trial was lossless; prints one line per trial.
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

CONFIG = """name: kill-resume
hull: rectangle
grid: {width: 40, height: 12}
scenarios: [{name: dense, p_c: 0.02, l_c: 3}]
uavs: [1, 2, 3, 4]
algorithms: [lawnmower, part-tsp, coop-frontier]
instances: 60
curve: {step: 20, end: 400}
"""
COMPARED = ["runs.csv", "samples.csv", "curves.csv"]


def rows(path):
    try:
        with open(path, "rb") as f:
            return max(0, f.read().count(b"\n") - 1)
    except FileNotFoundError:
        return 0


def run_until_killed(cli, config, out, kill_after, resume, jobs):
    args = [cli, "experiment", "--config", config, "--out", out, "--jobs", str(jobs)]
    if resume:
        args.append("--resume")
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 300
    while proc.poll() is None and time.monotonic() < deadline:
        if rows(os.path.join(out, "runs.csv")) >= kill_after:
            proc.send_signal(signal.SIGKILL)
            break
        time.sleep(0.002)
    status = proc.wait()
    return status == -signal.SIGKILL


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cli", required=True)
    parser.add_argument("--trials", type=int, default=12)
    args = parser.parse_args()
    work = tempfile.mkdtemp(prefix="hullinspect-kill-resume-")
    config = os.path.join(work, "config.yaml")
    with open(config, "w") as f:
        f.write(CONFIG)
    reference = os.path.join(work, "reference")
    subprocess.run([args.cli, "experiment", "--config", config, "--out", reference, "--jobs", "2"],
                   check=True, stdout=subprocess.DEVNULL)
    total = rows(os.path.join(reference, "runs.csv"))
    failures = 0
    killed_total = 0
    for trial in range(args.trials):
        out = os.path.join(work, f"trial-{trial}")
        # Kill points spread over the run; every third trial is killed twice (once while resuming).
        first = 1 + (trial * 61) % (total - 2)
        kills = [first] + ([min(total - 1, first + 37 + trial)] if trial % 3 == 2 else [])
        jobs = 1 + trial % 2
        killed = 0
        for n, at in enumerate(kills):
            killed += run_until_killed(args.cli, config, out, at, resume=n > 0, jobs=jobs)
        done = subprocess.run([args.cli, "experiment", "--config", config, "--out", out, "--resume",
                               "--jobs", "2"], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
        same = done.returncode == 0 and all(
            open(os.path.join(out, f), "rb").read() == open(os.path.join(reference, f), "rb").read()
            for f in COMPARED)
        killed_total += killed
        print(f"trial {trial + 1}: SIGKILL x{killed} (at >= {kills} of {total} runs, --jobs {jobs}), "
              f"resumed: {'lossless' if same else 'DIFFERENT ' + done.stderr.decode(errors='replace')}")
        failures += not same
        shutil.rmtree(out, ignore_errors=True)
    shutil.rmtree(work, ignore_errors=True)
    print(f"{args.trials} trials, {killed_total} SIGKILLs, {failures} not lossless")
    return 1 if failures or killed_total < args.trials else 0


if __name__ == "__main__":
    sys.exit(main())
