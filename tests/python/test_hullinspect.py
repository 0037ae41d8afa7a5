"""The Python module against the CLI: same inputs, same results; errors as ValueError with the
CLI's message (naming the Python keyword); Python planners registered and run like built-in ones;
a live Session fed with readings of a known truth replays the simulated mission step for step."""

import csv
import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import hullinspect
from cli_messages import python_message

CLI = os.environ.get("HULLINSPECT_CLI", "hullinspect")
TIMING_KEYS = {"planner_seconds", "tsp_seconds", "tsp_max_seconds"}


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


def cli_error(*args):
    """The one line the CLI prints for bad input, without its "hullinspect: " prefix."""
    done = cli(*args)
    assert done.returncode == 2, (args, done.returncode, done.stderr)
    assert done.stderr.startswith("hullinspect: ") and done.stderr.count("\n") == 1, done.stderr
    return done.stderr[len("hullinspect: "):-1]


class RunMission(unittest.TestCase):
    def check_equal_to_cli(self, cli_args, **kwargs):
        done = cli("run", "--json", *cli_args)
        self.assertIn(done.returncode, (0, 3), done.stderr)
        expected = json.loads(done.stdout)
        result = hullinspect.run_mission(**kwargs)
        for key in TIMING_KEYS:
            expected.pop(key, None)
            result.summary.pop(key, None)
        self.assertEqual(result.summary, expected)
        self.assertEqual(result.complete, expected["complete"])
        self.assertEqual(result.T_c, expected["T_c"])
        self.assertEqual(result.T_m, expected["T_m"])
        self.assertEqual(result.counters["moves"], expected["moves"])
        self.assertEqual(len(result.c), expected["steps"] + 1)
        self.assertEqual(len(result.m), expected["steps"] + 1)
        self.assertEqual(result.c.dtype, np.float64)
        self.assertEqual(result.m.dtype, np.float64)
        if expected["T_m"] is not None:
            self.assertEqual(result.m[expected["T_m"]], 100.0)
            self.assertLess(result.m[expected["T_m"] - 1], 100.0)
        if expected["T_c"] is not None and expected["T_c"] > 0:
            self.assertEqual(result.c[expected["T_c"]], 100.0)
            self.assertLess(result.c[expected["T_c"] - 1], 100.0)
        return result

    def test_part_tsp_equals_cli(self):
        self.check_equal_to_cli(["-a", "part-tsp", "--seed", "3", "--scenario", "imperfect"],
                                algorithm="part-tsp", seed=3, scenario="imperfect")

    def test_defaults_are_the_cli_defaults(self):
        result = self.check_equal_to_cli([])
        self.assertEqual(result.summary["algorithm"], "lawnmower")

    def test_options_and_params_equal_cli(self):
        self.check_equal_to_cli(
            ["-a", "coop-frontier", "-n", "3", "--s2", "9", "--seed", "2", "--alpha", "0.5",
             "--p-c", "0.01", "--time-limit", "900"],
            algorithm="coop-frontier", uavs=3, s2=9, seed=2, alpha=0.5, p_c=0.01, time_limit=900)

    def test_planner_options_starts_and_failures_equal_cli(self):
        self.check_equal_to_cli(
            ["-a", "lawnmower", "-n", "2", "-O", "partitioner.cc=0.02", "--start", "10,5",
             "--start", "200,20", "--fail", "1@40"],
            algorithm="lawnmower", uavs=2, options={"partitioner.cc": 0.02},
            starts=[(10, 5), (200, 20)], fail=["1@40"])

    def test_flags_and_no_fly_boxes_equal_cli(self):
        self.check_equal_to_cli(
            ["-a", "part-tsp", "-n", "3", "--seed", "4", "--separation", "2", "--no-deconfliction",
             "--no-fly-box", "30,5,40,12", "--no-fly-box", "60,0,62,3"],
            algorithm="part-tsp", uavs=3, seed=4, separation=2, no_deconfliction=True,
            strict_separation=False, no_fly_box=["30,5,40,12", (60, 0, 62, 3)])

    def test_hull_path_and_hull_object_equal_cli(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "hull.txt")
            with open(path, "w") as f:
                f.write(("X" * 40 + "\n") * 12)
            args = ["-a", "part-tsp", "-n", "2", "--hull", path, "--seed", "4"]
            self.check_equal_to_cli(args, algorithm="part-tsp", uavs=2, hull=path, seed=4)
            self.check_equal_to_cli(args, algorithm="part-tsp", uavs=2,
                                    hull=hullinspect.Hull.load(path), seed=4)

    def test_errors_are_value_errors_with_the_cli_message(self):
        cases = [
            (["-a", "part-tsp", "--r1", "-1"], dict(algorithm="part-tsp", r1=-1)),
            (["-a", "part-tsp", "-n", "abc"], dict(algorithm="part-tsp", uavs="abc")),
            (["-a", "part-tsp", "-n", "0"], dict(algorithm="part-tsp", uavs=0)),
            (["-a", "part-tsp", "--s2", "4"], dict(algorithm="part-tsp", s2=4)),
            (["-a", "lawnmower", "-O", "tsp-solver=foo"], dict(algorithm="lawnmower",
                                                              options={"tsp-solver": "foo"})),
            (["-a", "part-tsp", "--hull", "/nonexistent/hull.txt"],
             dict(algorithm="part-tsp", hull="/nonexistent/hull.txt")),
            (["--speed", "0"], dict(speed=0)),
            (["--climb-speed", "-1"], dict(climb_speed=-1)),
            (["--fail-one-within", "abc"], dict(fail_one_within="abc")),
            (["--launch", "0,0", "--launch-transfer", "nan"],
             dict(launch=[(0, 0)], launch_transfer=float("nan"))),
            (["--frame-spacing", "0"], dict(frame_spacing=0)),
            (["--cell-size", "abc"], dict(cell_size="abc")),
            (["--seed", "-1"], dict(seed=-1)),
        ]
        for args, kwargs in cases:
            with self.subTest(args=args):
                message = cli_error("run", *args)
                with self.assertRaises(ValueError) as caught:
                    hullinspect.run_mission(**kwargs)
                self.assertEqual(str(caught.exception), python_message(message))

    def test_speed_gives_the_same_steps_in_seconds_of_the_step(self):
        # 0.5 m cells at 1 m/s: steps of 0.5 s; climbing at 1 m/s keeps one step per plane change.
        paper = hullinspect.run_mission("lawnmower", uavs=4)
        fast = hullinspect.run_mission("lawnmower", uavs=4, speed=1, climb_speed=1)
        self.assertEqual(fast.T_c, paper.T_c * 0.5)
        self.assertEqual(fast.T_m, paper.T_m * 0.5)

    def test_unknown_algorithm_lists_the_registered_python_planners_too(self):
        message = cli_error("run", "-a", "part_tsp")
        self.assertTrue(message.endswith(")"), message)
        with self.assertRaises(ValueError) as caught:
            hullinspect.run_mission(algorithm="part_tsp")
        self.assertTrue(str(caught.exception).startswith(python_message(message)[:-1] +
                                                         ", test-go-east, "),
                        str(caught.exception))


class HullsAndInstances(unittest.TestCase):
    def test_default_hull_mask(self):
        hull = hullinspect.Hull.default()
        self.assertEqual(hull.mask.shape, (hull.height, hull.width))
        self.assertEqual(hull.mask.dtype, np.bool_)
        self.assertEqual(int(hull.mask.sum()), hull.cells)

    def test_instance_truth_and_prior(self):
        hull = hullinspect.Hull.default()
        perfect = hullinspect.make_instance(hull, 5, scenario="perfect")
        self.assertEqual(perfect.truth.dtype, np.int8)
        self.assertTrue(np.array_equal(perfect.truth, perfect.prior))
        self.assertTrue(np.array_equal(perfect.truth < 0, ~hull.mask))
        poor = hullinspect.make_instance(hull, 5, scenario="imperfect")
        self.assertTrue(np.array_equal(poor.truth, perfect.truth))  # same seed, same C
        self.assertFalse(np.array_equal(poor.prior, poor.truth))
        self.assertEqual(perfect.corroded_cells, int((perfect.truth == 1).sum()))

    def test_instance_equals_the_cli_trace(self):
        with tempfile.TemporaryDirectory() as tmp:
            trace = os.path.join(tmp, "t.json")
            done = cli("run", "-a", "lawnmower", "--seed", "9", "--scenario", "imperfect",
                       "--p-c", "0.01", "--trace", trace)
            self.assertIn(done.returncode, (0, 3), done.stderr)
            with open(trace) as f:
                data = json.load(f)
        inst = hullinspect.make_instance(None, 9, scenario="imperfect", p_c=0.01)
        self.assertTrue(np.array_equal(inst.truth, rows_array(data["truth"])))
        self.assertTrue(np.array_equal(inst.prior, rows_array(data["prior"])))

    def test_bad_scenario_option_is_the_cli_message(self):
        message = cli_error("run", "--p-c", "2")
        with self.assertRaises(ValueError) as caught:
            hullinspect.make_instance(hullinspect.Hull.default(), 5, p_c=2)
        self.assertEqual(str(caught.exception), python_message(message))

    def test_load_hull_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "hull.txt")
            with open(path, "w") as f:
                f.write("XXX.\nXXXX\n")
            hull = hullinspect.Hull.load(path)
            # Row y = 0 is the bottom row: the file's last line.
            self.assertEqual(hull.mask.tolist(), [[True, True, True, True],
                                                  [True, True, True, False]])
            with self.assertRaises(ValueError):
                hullinspect.Hull.load(os.path.join(tmp, "missing.txt"))
            # A FIFO nobody writes to is refused at once, not waited on.
            fifo = os.path.join(tmp, "hull.fifo")
            os.mkfifo(fifo)
            with self.assertRaisesRegex(ValueError, "is a FIFO, expected a regular file"):
                hullinspect.Hull.load(fifo)


def rows_array(rows):
    """A trace's rows ('.' non-hull, digits) as an int8 array [y][x]."""
    return np.array([[-1 if ch == "." else int(ch) for ch in row] for row in rows], dtype=np.int8)


SMALL = {
    "hull": "rectangle",
    "grid": {"width": 30, "height": 10},
    "scenarios": ["perfect"],
    "uavs": [2],
    "algorithms": ["lawnmower", "part-tsp"],
    "instances": 2,
    "curve": {"step": 10, "end": 100},
}
TIMING_COLUMNS = {"planner_seconds", "tsp_seconds", "tsp_max_seconds", "wall_seconds",
                  "seconds"}


def without_timings(rows):
    return [{k: v for k, v in r.items() if k not in TIMING_COLUMNS} for r in rows]


class Experiments(unittest.TestCase):
    def test_rows_equal_the_cli_runs_csv(self):
        with tempfile.TemporaryDirectory() as tmp:
            config = os.path.join(tmp, "small.yaml")
            with open(config, "w") as f:
                json.dump(SMALL, f)  # JSON is YAML
            done = cli("experiment", "--config", config, "--out", os.path.join(tmp, "cli"),
                       "--jobs", "2")
            self.assertEqual(done.returncode, 0, done.stderr)
            with open(os.path.join(tmp, "cli", "runs.csv"), newline="") as f:
                expected = list(csv.DictReader(f))
            out = os.path.join(tmp, "py")
            from_path = hullinspect.run_experiment(config, jobs=2, out=out)
            self.assertTrue(os.path.exists(os.path.join(out, "manifest.json")))
            from_dict = hullinspect.run_experiment(SMALL, jobs=2)
        self.assertEqual(len(expected), 4)
        self.assertEqual(list(from_path[0].keys()), list(expected[0].keys()))
        self.assertEqual(without_timings(from_path), without_timings(expected))
        self.assertEqual(without_timings(from_dict), without_timings(expected))
        frame = hullinspect.to_dataframe(from_dict)
        self.assertEqual(len(frame), 4)
        self.assertEqual(frame["T_m"].dtype.kind, "i")
        self.assertEqual(set(frame["algorithm"]), {"lawnmower", "part-tsp"})

    def test_preset_name(self):
        with tempfile.TemporaryDirectory() as tmp:
            message = cli_error("experiment", "--preset", "no-such-preset", "--out",
                                os.path.join(tmp, "out"))
        with self.assertRaises(ValueError) as caught:
            hullinspect.run_experiment("no-such-preset")
        self.assertEqual(str(caught.exception), python_message(message, keyword="config"))

    def test_jobs_do_not_change_results(self):
        one = hullinspect.run_experiment(SMALL, jobs=1)
        two = hullinspect.run_experiment(SMALL, jobs=2)
        self.assertEqual(without_timings(one), without_timings(two))


class GoEast(hullinspect.Planner):
    """Test planner: every UAV flies east until the edge, then hovers."""

    def start(self, context):
        self.width = context.hull.shape[1]

    def decide(self, view):
        assert view.map.dtype == np.int8
        return ["E" if x + 1 < self.width else "hover" for (x, y, z, transit, failed) in view.uavs]


class BadAction(hullinspect.Planner):
    def decide(self, view):
        return ["N"] * len(view.uavs) if view.t < 3 else ["up"] * len(view.uavs)


class OffTheGrid(hullinspect.Planner):
    def decide(self, view):
        return ["S"] * len(view.uavs)


class Recorder(hullinspect.Planner):
    """Records what it is shown; flies like NearestUnknown."""
    seen = []

    def start(self, context):
        Recorder.seen.append(("context", sorted(vars(context))))

    def decide(self, view):
        Recorder.seen.append(("view", sorted(vars(view))))
        return NearestUnknown().decide(view)


class NearestUnknown(hullinspect.Planner):
    """Close-up sweep: descend, then each UAV steps towards the nearest open cell (M = 0 or 2)."""

    def decide(self, view):
        actions = []
        open_y, open_x = np.nonzero((view.map == 0) | (view.map == 2))
        for (x, y, z, transit, failed) in view.uavs:
            if transit or failed or len(open_x) == 0:
                actions.append("hover")
            elif z == 2:
                actions.append("change")
            else:
                i = int(np.argmin(np.abs(open_x - x) + np.abs(open_y - y)))
                tx, ty = int(open_x[i]), int(open_y[i])
                actions.append("E" if tx > x else "W" if tx < x else "N" if ty > y else
                               "S" if ty < y else "hover")
        return actions


hullinspect.register_planner("test-go-east", GoEast)
hullinspect.register_planner("test-bad-action", BadAction)
hullinspect.register_planner("test-off-grid", OffTheGrid)
hullinspect.register_planner("test-recorder", Recorder)
hullinspect.register_planner("test-nearest", NearestUnknown)


class PythonPlanners(unittest.TestCase):
    def test_registered_planner_runs_and_is_listed(self):
        result = hullinspect.run_mission(algorithm="test-go-east", uavs=2, time_limit=50)
        self.assertFalse(result.complete)
        self.assertEqual(result.counters["steps"], 50)
        self.assertGreater(result.counters["moves"], 0)
        entries = {e["name"]: e for e in hullinspect.catalog("planners")}
        self.assertIn("test-go-east", entries)
        self.assertEqual(entries["test-go-east"]["description"],
                         "Test planner: every UAV flies east until the edge, then hovers.")

    def test_view_and_context_hold_no_truth(self):
        Recorder.seen.clear()
        hullinspect.run_mission(algorithm="test-recorder", uavs=2, time_limit=5)
        self.assertEqual(Recorder.seen[0], ("context", ["hull", "plane_change_steps", "prior", "s1",
                                                        "s2", "starts", "time_limit", "uavs"]))
        self.assertEqual(Recorder.seen[1], ("view", ["map", "prior", "t", "uavs"]))
        self.assertEqual(len(Recorder.seen), 6)

    def test_python_planner_completes(self):
        result = hullinspect.run_mission(algorithm="test-nearest", uavs=2, hull=small_hull(),
                                         seed=3, scenario="imperfect")
        self.assertTrue(result.complete)
        self.assertTrue(np.all(np.diff(result.m) >= 0))
        self.assertTrue(np.all(np.diff(result.c) >= 0))

    def test_jobs_with_python_planners_equal_jobs_1(self):
        config = dict(SMALL, algorithms=["test-nearest", "lawnmower"], instances=3)
        one = hullinspect.run_experiment(config, jobs=1)
        two = hullinspect.run_experiment(config, jobs=2)
        self.assertEqual(len(one), 6)
        self.assertTrue(all(r["complete"] == "1" for r in one))
        self.assertEqual(without_timings(one), without_timings(two))

    def test_bad_action_names_uav_and_step(self):
        with self.assertRaises(ValueError) as caught:
            hullinspect.run_mission(algorithm="test-bad-action", uavs=2)
        self.assertEqual(str(caught.exception),
                         "planner 'test-bad-action': UAV 0 at t = 3: unknown action 'up' "
                         "(expected N, S, E, W, hover or change)")

    def test_simulator_rules_apply(self):
        with self.assertRaisesRegex(RuntimeError, r"UAV 0 at \(\d+, 0\) was told to move south "
                                                  r"off the 230 × 30 grid"):
            hullinspect.run_mission(algorithm="test-off-grid", uavs=1, starts=[(100, 0)])

    def test_python_exceptions_pass_through(self):
        class Broken(hullinspect.Planner):
            def decide(self, view):
                raise KeyError("broken planner")
        hullinspect.register_planner("test-broken", Broken)
        with self.assertRaisesRegex(KeyError, "broken planner"):
            hullinspect.run_mission(algorithm="test-broken")

    def test_names_cannot_be_registered_twice(self):
        with self.assertRaisesRegex(ValueError, "already registered"):
            hullinspect.register_planner("test-go-east", GoEast)
        with self.assertRaisesRegex(ValueError, "part-tsp.*already registered"):
            hullinspect.register_planner("part-tsp", GoEast)
        with self.assertRaisesRegex(ValueError, "not a subclass"):
            hullinspect.register_planner("test-object", object)

    def test_names_that_need_quoting_are_refused(self):
        for name in ["", "two\nlines", 'say "hi"', "it's", "a,b"]:
            with self.assertRaisesRegex(ValueError, "a planner name must be 1 to 64 letters"):
                hullinspect.register_planner(name, GoEast)


def small_hull():
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "hull.txt")
        with open(path, "w") as f:
            f.write(("X" * 24 + "\n") * 9)
        return hullinspect.Hull.load(path)


def readings(session, truth, failed=()):
    """What perfect cameras report: every expected cell with its value in `truth`."""
    return [(x, y, z, truth[y][x] == 1) for (x, y, z) in session.expected_readings(failed)]


class LiveSession(unittest.TestCase):
    def replay(self, algorithm, cli_args, fail=None, **params):
        """Runs the CLI with a trace, then a Session fed with readings of the trace's truth; checks
        UAV states and M at every step and the final counters."""
        with tempfile.TemporaryDirectory() as tmp:
            trace_path = os.path.join(tmp, "t.json")
            done = cli("run", "-a", algorithm, "--json", "--trace", trace_path, *cli_args)
            self.assertIn(done.returncode, (0, 3), done.stderr)
            expected = json.loads(done.stdout)
            with open(trace_path) as f:
                trace = json.load(f)
        truth = rows_array(trace["truth"])
        prior = rows_array(trace["prior"])
        session = hullinspect.Session(algorithm, prior=prior, **params)
        state = session.state
        self.assertEqual(state.t, 0)
        self.assertTrue(np.array_equal(state.map, rows_array(trace["initial_map"])))
        m = rows_array(trace["initial_map"]).reshape(-1)
        for t, frame in enumerate(trace["frames"]):
            failed = [fail[0]] if fail and t == fail[1] + 1 else []
            actions = session.step(readings(session, truth, failed), failed=failed)
            state = session.state
            self.assertEqual(state.t, t)
            u = frame["u"]
            want = [(u[5 * k], u[5 * k + 1], u[5 * k + 2], u[5 * k + 3] > 0, u[5 * k + 4] == 0)
                    for k in range(len(u) // 5)]
            self.assertEqual(state.uavs, want, f"t = {t}")
            for i in range(0, len(frame["c"]), 2):
                m[frame["c"][i]] = frame["c"][i + 1]
            self.assertTrue(np.array_equal(state.map.reshape(-1), m), f"M at t = {t}")
            last = t == len(trace["frames"]) - 1
            self.assertEqual(session.finished, last)
            self.assertEqual(actions == [], last)
            if not last:
                self.assertEqual(len(actions), len(want))
        result = session.result()
        for key in ("complete", "T_m", "steps", "moves", "plane_changes", "hovers",
                    "redundant_observations", "observations", "failed_uavs"):
            self.assertEqual(result.summary[key], expected[key], key)
        with self.assertRaisesRegex(ValueError, "the mission has finished"):
            session.step([])

    def test_part_tsp_replays_the_simulated_mission(self):
        self.replay("part-tsp", ["--seed", "3", "--scenario", "imperfect", "-n", "3"], uavs=3)

    def test_coop_frontier_s2_9_replays(self):
        self.replay("coop-frontier", ["--seed", "5", "-n", "2", "--s2", "9"], uavs=2, s2=9)

    def test_failure_reported_in_step_replays_fail_option(self):
        self.replay("lawnmower", ["--seed", "2", "-n", "3", "--fail", "1@40"], fail=(1, 40),
                    uavs=3)

    def test_separation_replays_through_the_deconfliction_layer(self):
        # Flown as the planner gives them, these actions break the separation 4 times: the replay
        # matches only if the Session's actions pass the deconfliction layer as the CLI's do.
        self.replay("coop-frontier", ["--seed", "5", "-n", "3", "--separation", "5"], uavs=3,
                    separation=5)

    def test_python_planner_in_a_session(self):
        hull = small_hull()
        session = hullinspect.Session("test-nearest", hull=hull, uavs=2)
        truth = np.zeros((hull.height, hull.width), dtype=np.int8)
        truth[4][5] = 1
        while True:
            actions = session.step(readings(session, truth))
            if not actions:
                break
            self.assertTrue(set(actions) <= {"N", "S", "E", "W", "hover", "change"})
        self.assertTrue(session.state.complete)
        self.assertEqual(session.state.map[4][5], 3)

    def test_bad_readings_change_nothing(self):
        session = hullinspect.Session("part-tsp", uavs=2)
        truth = np.zeros((30, 230), dtype=np.int8)
        good = readings(session, truth)
        x, y, z = session.expected_readings()[0]
        cases = [
            (good[1:], rf"^readings: no reading of cell \({x}, {y}\) from plane {z} at t = 0 "),
            (good + [(500, 1, 2, False)], r"^readings\[\d+\]: cell \(500, 1\) is outside the "
                                          r"230 × 30 grid$"),
            (good + [(x, y, 1, False)], rf"no UAV senses cell \({x}, {y}\) from plane 1 at t = 0"),
            (good + [(x, y, z, True)], rf"cell \({x}, {y}\) is reported both corroded and clean"),
            (good + [(x, y, 3, False)], r"plane must be 1 or 2 \(got 3\)"),
            (good + [(x, y)], r"expected \(x, y, plane, corroded\)"),
        ]
        for bad, pattern in cases:
            with self.subTest(pattern=pattern):
                with self.assertRaisesRegex(ValueError, pattern):
                    session.step(bad)
                self.assertEqual(session.state.t, 0)
        with self.assertRaisesRegex(ValueError, "no UAV can fail before the first step"):
            session.step(good, failed=[0])
        self.assertEqual(len(session.step(good)), 2)
        with self.assertRaisesRegex(ValueError, r"failed\[0\]: no UAV 7 in a fleet of 2"):
            session.step(readings(session, truth), failed=[7])

    def test_session_arguments(self):
        with self.assertRaisesRegex(ValueError, "scenario does not apply"):
            hullinspect.Session("part-tsp", scenario="imperfect")
        with self.assertRaisesRegex(ValueError, r"prior: expected a path or an array of shape "
                                                r"\(30, 230\)"):
            hullinspect.Session("part-tsp", prior=np.zeros((3, 3)))
        message = cli_error("run", "-a", "part-tsp", "--s2", "4")
        with self.assertRaises(ValueError) as caught:
            hullinspect.Session("part-tsp", s2=4)
        self.assertEqual(str(caught.exception), python_message(message))


if __name__ == "__main__":
    unittest.main()
