"""Per-step data from Python (traces as DataFrames, typed runs.csv and samples.csv), defaults and
keyword-named errors, and the Python-side input checks (Session readings and priors, seeds, jobs,
Ctrl-C during an experiment with a Python planner)."""

import inspect
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

import numpy as np
import pandas as pd

import hullinspect
from cli_messages import python_message

CLI = os.environ.get("HULLINSPECT_CLI", "hullinspect")
SMALL = {"hull": "rectangle", "grid": {"width": 30, "height": 10}, "scenarios": ["perfect"],
         "uavs": [2], "algorithms": ["lawnmower", {"name": "part-tsp", "options": {"r1": 3}}],
         "instances": 2, "time_limit": 60, "curve": {"step": 10, "end": 50}}


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


class Traces(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.path = os.path.join(cls.tmp.name, "t.json")
        cls.result = hullinspect.run_mission(algorithm="part-tsp", uavs=3, seed=3,
                                             scenario="imperfect", trace=cls.path)
        cls.trace = hullinspect.read_trace(cls.path)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_trace_file_equals_the_cli_trace(self):
        cli_path = os.path.join(self.tmp.name, "cli.json")
        done = cli("run", "-a", "part-tsp", "-n", "3", "--seed", "3", "--scenario", "imperfect",
                   "--trace", cli_path)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open(cli_path) as f:
            expected = json.load(f)
        with open(self.path) as f:
            got = json.load(f)
        for data in (expected, got):
            data["result"].pop("planner_seconds", None)
            for key in [k for k in data["result"] if k.endswith("seconds")]:
                data["result"].pop(key)
        self.assertEqual(got, expected)

    def test_in_memory_trace_equals_the_file(self):
        self.assertIsNotNone(self.result.trace)
        self.assertEqual(self.result.trace.data["frames"], self.trace.data["frames"])
        kept = hullinspect.run_mission(algorithm="part-tsp", uavs=3, seed=3, scenario="imperfect",
                                       keep_trace=True)
        self.assertEqual(kept.trace.data["frames"], self.trace.data["frames"])
        self.assertIsNone(hullinspect.run_mission(seed=3).trace)

    def test_uavs_frame_of_a_mission_with_launch_sites(self):
        # With launch sites each UAV's state also says whether it is airborne, its battery and
        # its steps away from the hull; a UAV away is in transit (it cannot act).
        path = os.path.join(self.tmp.name, "sorties.json")
        done = cli("run", "-n", "2", "--seed", "2", "--launch", "105,0", "--launch", "125,0",
                   "--endurance", "400", "--swap-time", "30", "--trace", path)
        self.assertEqual(done.returncode, 0, done.stderr)
        uavs = hullinspect.read_trace(path).uavs
        for column in ("airborne", "battery_left", "away_left"):
            self.assertIn(column, uavs.columns)
        self.assertEqual(uavs["airborne"].dtype, bool)
        away = uavs["away_left"] > 0
        self.assertTrue(away.any())
        self.assertTrue(uavs.loc[away, "in_transit"].all())
        on_hull = uavs.loc[~away]
        self.assertTrue((on_hull["in_transit"] == (on_hull["transit_left"] > 0)).all())
        self.assertTrue((~uavs["airborne"]).any())
        self.assertTrue(uavs["battery_left"].between(0, 400).all())

    def test_uavs_frame_has_one_row_per_uav_and_step(self):
        uavs = self.trace.uavs
        steps = self.result.counters["steps"]
        self.assertEqual(len(uavs), 3 * (steps + 1))
        for column in ("t", "k", "x", "y", "z", "transit_left", "active", "in_transit", "mode"):
            self.assertIn(column, uavs.columns)
        self.assertEqual(uavs["t"].dtype, np.int64)
        self.assertEqual(uavs["active"].dtype, bool)
        self.assertTrue(uavs["z"].isin([1, 2]).all())
        self.assertEqual(sorted(uavs.loc[uavs.t == 0, "k"]), [0, 1, 2])
        # One step moves a UAV by at most one cell.
        moved = uavs.sort_values(["k", "t"]).groupby("k")[["x", "y"]].diff().abs().sum(axis=1)
        self.assertLessEqual(moved.max(), 1)
        # The mode is the last annotation at or before t.
        notes = self.trace.annotations
        self.assertGreater(len(notes), 0)
        last = notes.iloc[-1]
        later = uavs[(uavs.k == last.k) & (uavs.t >= last.t)]
        self.assertTrue((later["mode"] == last["mode"]).all())

    def test_map_changes_rebuild_the_series(self):
        changes = self.trace.map_changes
        self.assertEqual(list(changes.columns), ["t", "cell", "x", "y", "value"])
        self.assertTrue(((changes.x + changes.y * self.trace.width) == changes.cell).all())
        final = self.trace.map_at(self.result.counters["steps"])
        truth = self.trace.truth
        self.assertEqual(int(np.isin(final, (1, 3)).sum()), int(self.trace.series.known.iloc[-1]))
        self.assertEqual(int(((final == 3) & (truth == 1)).sum()),
                         int(self.trace.series.inspected.iloc[-1]))
        self.assertEqual(len(self.trace.series), len(self.result.m))

    def test_session_records_the_same_trace(self):
        inst = hullinspect.make_instance(None, 3, scenario="imperfect")
        session = hullinspect.Session("part-tsp", prior=inst.prior, uavs=3, keep_trace=True)
        actions = None
        while actions is None or actions:
            actions = session.step([(x, y, z, inst.truth[y][x] == 1)
                                    for (x, y, z) in session.expected_readings()])
        live = session.trace()
        columns = ["t", "k", "x", "y", "z", "transit_left", "active", "mode"]
        pd.testing.assert_frame_equal(live.uavs[columns], self.trace.uavs[columns])
        pd.testing.assert_frame_equal(live.map_changes, self.trace.map_changes)
        with self.assertRaisesRegex(ValueError, r"^trace: this Session records no trace"):
            hullinspect.Session("part-tsp").trace()

    def test_trace_cannot_replace_an_input(self):
        hull = os.path.join(self.tmp.name, "hull.txt")
        with open(hull, "w") as f:
            f.write("XXXXXXXXXX\n" * 4)
        with self.assertRaisesRegex(ValueError, r"^trace: "):
            hullinspect.run_mission(uavs=1, hull=hull, trace=hull)
        with open(hull) as f:
            self.assertEqual(f.read(), "XXXXXXXXXX\n" * 4)
        with self.assertRaisesRegex(ValueError, r"^trace: "):
            hullinspect.run_mission(uavs=1, trace=os.path.join(self.tmp.name, "no", "t.json"))

    def test_bad_trace_names_the_file(self):
        bad = os.path.join(self.tmp.name, "bad.json")
        with open(bad, "w") as f:
            f.write('{"format": "hullinspect-trace"}\n')
        with self.assertRaisesRegex(ValueError, "^" + re.escape(bad) + ": "):
            hullinspect.read_trace(bad)


class ResultFrames(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.out = os.path.join(cls.tmp.name, "r")
        cls.rows = hullinspect.run_experiment(SMALL, jobs=2, out=cls.out)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_runs_are_typed(self):
        runs = hullinspect.read_runs(self.out)
        self.assertEqual(len(runs), 4)
        self.assertEqual(runs["complete"].dtype, bool)
        self.assertEqual(runs["T_m"].dtype, pd.Int64Dtype())
        self.assertEqual(runs["run_id"].dtype, object)
        self.assertTrue(all(isinstance(r, str) and len(r) == 16 for r in runs["run_id"]))
        self.assertEqual(runs["uavs"].dtype, np.int64)
        # Planner options as columns: missing where the planner has no such option.
        self.assertIn("r1", runs.columns)
        self.assertEqual(set(runs.loc[runs.algorithm == "part-tsp", "r1"]), {3})
        self.assertTrue(runs.loc[runs.algorithm == "lawnmower", "r1"].isna().all())
        # The rows run_experiment returns give the same frame.
        pd.testing.assert_frame_equal(hullinspect.to_dataframe(self.rows), runs)

    def test_incomplete_runs_have_missing_times(self):
        runs = hullinspect.read_runs(os.path.join(self.out, "runs.csv"))
        incomplete = runs[~runs.complete]
        self.assertTrue(incomplete["T_m"].isna().all())
        self.assertTrue(runs.loc[runs.complete, "T_m"].notna().all())

    def test_samples_are_long(self):
        samples = hullinspect.read_samples(self.out)
        self.assertEqual(list(samples.columns), ["run_id", "t", "inspected", "known"])
        self.assertEqual(len(samples), 4 * 6)  # t = 0, 10, …, 50
        self.assertEqual(sorted(set(samples.t)), [0, 10, 20, 30, 40, 50])
        wide = pd.read_csv(os.path.join(self.out, "samples.csv"), dtype={"run_id": str})
        first = wide.iloc[0]
        row = samples[(samples.run_id == first.run_id) & (samples.t == 20)].iloc[0]
        self.assertEqual(row.known, first["known_20"])
        self.assertEqual(row.inspected, first["inspected_20"])

    def test_resume_runs_the_same_experiment_again(self):
        again = hullinspect.run_experiment(SMALL, jobs=1, out=self.out, resume=True)
        self.assertEqual([r["run_id"] for r in again], [r["run_id"] for r in self.rows])
        with self.assertRaisesRegex(ValueError, "^out: .*: is not empty: pass resume=True"):
            hullinspect.run_experiment(SMALL, jobs=1, out=self.out)


class DefaultsAndKeywords(unittest.TestCase):
    def test_defaults_are_the_cli_defaults(self):
        done = cli("run", "--json")
        self.assertIn(done.returncode, (0, 3), done.stderr)
        expected = json.loads(done.stdout)
        result = hullinspect.run_mission()
        for key in ("algorithm", "uavs", "s2", "seed", "T_c", "T_m", "moves"):
            self.assertEqual(result.summary[key], expected[key], key)
        signature = inspect.signature(hullinspect.run_mission).parameters
        self.assertEqual(signature["algorithm"].default, expected["algorithm"])
        self.assertEqual(signature["uavs"].default, expected["uavs"])
        self.assertEqual(signature["s2"].default, expected["s2"])
        self.assertEqual(inspect.signature(hullinspect.run_experiment).parameters["jobs"].default,
                         0)  # `hullinspect experiment --jobs` default: every core

    def test_errors_name_the_keyword(self):
        cases = [
            (["-a", "part-tsp", "--r1", "-1"], dict(algorithm="part-tsp", r1=-1), "r1: "),
            (["-n", "abc"], dict(uavs="abc"), "uavs: "),
            (["--s2", "4"], dict(s2=4), "s2: "),
            (["--time-limit", "0"], dict(time_limit=0), "time_limit: "),
            (["--p-c", "2"], dict(p_c=2), "p_c: "),
        ]
        for args, kwargs, prefix in cases:
            with self.subTest(args=args):
                done = cli("run", *args)
                self.assertEqual(done.returncode, 2, done.stderr)
                message = done.stderr.removeprefix("hullinspect: ").rstrip("\n")
                with self.assertRaises(ValueError) as caught:
                    hullinspect.run_mission(**kwargs)
                text = str(caught.exception)
                self.assertTrue(text.startswith(prefix), text)
                self.assertNotIn("--", text.split(":")[0])
                self.assertEqual(text, python_message(message))


class InputChecks(unittest.TestCase):
    def test_session_refuses_readings_that_are_not_true_or_false(self):
        session = hullinspect.Session("part-tsp", uavs=2)
        expected = session.expected_readings()
        for value in ("no", "yes", 2, 0.5, None, np.int8(7)):
            with self.subTest(value=value):
                bad = [(x, y, z, False) for (x, y, z) in expected]
                bad[0] = (*expected[0], value)
                with self.assertRaisesRegex(ValueError,
                                            r"^readings\[0\]: corroded must be True or False"):
                    session.step(bad)
                self.assertEqual(session.state.t, 0)
        for value in (False, 0, np.bool_(False), np.int8(0)):
            ok = [(x, y, z, value) for (x, y, z) in expected]
            self.assertEqual(len(hullinspect.Session("part-tsp", uavs=2).step(ok)), 2)

    def test_session_refuses_prior_values_other_than_0_and_1(self):
        hull = hullinspect.Hull.default()
        y, x = np.argwhere(hull.mask)[0]
        for value in (7, np.nan, 0.5, -1):
            with self.subTest(value=value):
                prior = np.zeros(hull.mask.shape)
                prior[y, x] = value
                with self.assertRaisesRegex(ValueError, rf"^prior\[{y}\]\[{x}\]: expected 0 or 1"):
                    hullinspect.Session("part-tsp", prior=prior)
        # make_instance's C′ (-1 off the hull) is accepted as it is.
        inst = hullinspect.make_instance(None, 3, scenario="imperfect")
        hullinspect.Session("part-tsp", prior=inst.prior)

    def test_make_instance_seed_is_a_value_error_naming_seed(self):
        for seed in (-1, 2**64, 1.5, "3", True):
            with self.subTest(seed=seed):
                with self.assertRaisesRegex(ValueError, r"^seed: must be an integer in "
                                                        r"\[0, 18446744073709551615\]"):
                    hullinspect.make_instance(None, seed)
        self.assertEqual(hullinspect.make_instance(None, 2**64 - 1).seed, 2**64 - 1)

    def test_battery_keywords_fly_sorties_and_bad_ones_are_value_errors(self):
        r = hullinspect.run_mission("sweep-inspect", uavs=4, seed=1, launch=[(115, 0)],
                                    endurance=400, swap_time=60)
        self.assertTrue(r.complete)
        self.assertGreater(r.counters["sorties"], 4)
        self.assertEqual(r.counters["battery_crashes"], 0)
        for kw, message in (
                (dict(endurance=400), r"^endurance: needs a launch site"),
                (dict(launch=[(115, 0)], endurance=float("nan")),
                 r"^endurance: must be a number of seconds"),
                (dict(launch=[(115, 0)], endurance=400, reserve=400),
                 r"^reserve: must be below the endurance of 400 s"),
                (dict(launch=[(115, 0)], endurance=100),
                 r"^endurance: 100 s cannot reach the farthest hull cell \(0, 29\)")):
            with self.subTest(**{k: str(v) for k, v in kw.items()}):
                with self.assertRaisesRegex(ValueError, message):
                    hullinspect.run_mission("lawnmower", uavs=4, seed=1, **kw)

    def test_run_experiment_jobs_in_the_cli_range(self):
        for jobs in (-1, 100000, 2.0, "2"):
            with self.subTest(jobs=jobs):
                with self.assertRaisesRegex(ValueError,
                                            r"^jobs: must be an integer in \[0, 4096\]"):
                    hullinspect.run_experiment(SMALL, jobs=jobs)
        done = cli("experiment", "--config", "/nonexistent.yaml", "--jobs", "4097", "--out", "x")
        self.assertIn("--jobs: ", done.stderr)
        self.assertIn("4096", done.stderr)

    def test_ctrl_c_stops_an_experiment_whose_planner_sleeps(self):
        with tempfile.TemporaryDirectory() as tmp:
            started = os.path.join(tmp, "started")
            # decide() also records the threads run_experiment started that take SIGINT: the
            # kernel may hand Ctrl-C to any of them, and then this sleep would not wake.
            script = textwrap.dedent(f"""
                import os, signal, time, hullinspect
                signal.signal(signal.SIGINT, signal.default_int_handler)
                before = set(os.listdir("/proc/self/task"))
                def taking_sigint(tids):
                    taking = 0
                    for tid in tids:
                        try:
                            with open(f"/proc/self/task/{{tid}}/status") as f:
                                blocked = next(int(line.split()[1], 16) for line in f
                                               if line.startswith("SigBlk:"))
                        except (OSError, StopIteration):
                            continue
                        taking += not blocked & (1 << (signal.SIGINT - 1))
                    return taking
                class Sleepy(hullinspect.Planner):
                    def decide(self, view):
                        new = set(os.listdir("/proc/self/task")) - before
                        with open({started!r} + ".tmp", "w") as f:
                            f.write(f"{{len(new)}} {{taking_sigint(new)}}")
                        os.replace({started!r} + ".tmp", {started!r})
                        time.sleep(60)
                        return ["hover"] * len(view.uavs)
                hullinspect.register_planner("sleepy", Sleepy)
                config = dict({SMALL!r}, algorithms=["sleepy", "lawnmower"])
                try:
                    hullinspect.run_experiment(config, jobs=2, out={os.path.join(tmp, "r")!r})
                except KeyboardInterrupt:
                    print("interrupted")
                """)
            child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE,
                                     stderr=subprocess.PIPE, text=True, env=os.environ)
            try:
                deadline = time.monotonic() + 60
                while not os.path.exists(started) and time.monotonic() < deadline:
                    time.sleep(0.05)
                self.assertTrue(os.path.exists(started), "decide() never ran")
                with open(started) as f:
                    threads, taking = map(int, f.read().split())
                self.assertGreaterEqual(threads, 2)  # the serving worker and the jobs' threads
                self.assertEqual(taking, 0)
                child.send_signal(signal.SIGINT)
                # The sleep lasts 60 s; the interrupt must end the process long before.
                out, err = child.communicate(timeout=20)
            finally:
                if child.poll() is None:
                    child.kill()
                    child.communicate()
            self.assertEqual(child.returncode, 0, err)
            self.assertEqual(out, "interrupted\n")
            # As a CLI killed by Ctrl-C leaves it: running, its journals ready for resume=True.
            with open(os.path.join(tmp, "r", "manifest.json")) as f:
                self.assertEqual(json.load(f)["status"], "running")


if __name__ == "__main__":
    unittest.main()
