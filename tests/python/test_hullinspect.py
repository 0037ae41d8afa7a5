"""The Python module against the CLI: same inputs, same results; errors as ValueError with the
CLI's message; Python planners registered and run through the shared mission checks."""

import json
import os
import subprocess
import tempfile
import unittest

import numpy as np

import hullinspect

CLI = os.environ.get("HULLINSPECT_CLI", "hullinspect")
TIMING_KEYS = {"planner_seconds", "tsp_seconds", "tsp_max_seconds"}


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True)


class RunMission(unittest.TestCase):
    def check_equal_to_cli(self, cli_args, **kwargs):
        done = cli("run", "--json", *cli_args)
        self.assertIn(done.returncode, (0, 3), done.stderr)
        expected = json.loads(done.stdout)
        result = hullinspect.run_mission(**kwargs)
        for key in TIMING_KEYS:
            expected.pop(key)
            result.summary.pop(key)
        self.assertEqual(result.summary, expected)
        self.assertEqual(result.complete, expected["complete"])
        self.assertEqual(result.T_c, expected["T_c"])
        self.assertEqual(result.T_m, expected["T_m"])
        self.assertEqual(result.counters["moves"], expected["moves"])
        self.assertEqual(len(result.c), expected["steps"] + 1)
        self.assertEqual(result.m[-1], 100.0 if expected["complete"] else result.m[-1])
        self.assertEqual(result.c.dtype, np.float64)

    def test_part_tsp_equals_cli(self):
        self.check_equal_to_cli(["-a", "part-tsp", "--seed", "3", "--scenario", "imperfect"],
                                algorithm="part-tsp", seed=3, scenario="imperfect")

    def test_options_and_params_equal_cli(self):
        self.check_equal_to_cli(
            ["-a", "coop-frontier", "-n", "3", "--s2", "9", "--seed", "2", "--alpha", "0.5",
             "--p-c", "0.01", "--time-limit", "900"],
            algorithm="coop-frontier", uavs=3, s2=9, seed=2, alpha=0.5, p_c=0.01, time_limit=900)

    def test_lawnmower_with_partitioner_option(self):
        self.check_equal_to_cli(["-a", "lawnmower", "-O", "partitioner.cc=0.02"],
                                algorithm="lawnmower", options={"partitioner.cc": 0.02})

    def test_errors_are_value_errors_with_the_cli_message(self):
        done = cli("run", "-a", "part-tsp", "--r1", "-1")
        self.assertEqual(done.returncode, 2)
        with self.assertRaises(ValueError) as caught:
            hullinspect.run_mission(algorithm="part-tsp", r1=-1)
        self.assertEqual("hullinspect: " + str(caught.exception) + "\n", done.stderr)
        with self.assertRaisesRegex(ValueError, "did you mean part-tsp"):
            hullinspect.run_mission(algorithm="part_tsp")


class HullsAndInstances(unittest.TestCase):
    def test_default_hull_mask(self):
        hull = hullinspect.Hull.default()
        self.assertEqual(hull.mask.shape, (hull.height, hull.width))
        self.assertEqual(hull.mask.dtype, np.bool_)
        self.assertEqual(int(hull.mask.sum()), hull.cells)

    def test_instance_truth_and_prior(self):
        hull = hullinspect.Hull.default()
        perfect = hullinspect.make_instance(hull, 5, scenario="perfect")
        self.assertTrue(np.array_equal(perfect.truth, perfect.prior))
        self.assertTrue(np.array_equal(perfect.truth < 0, ~hull.mask))
        poor = hullinspect.make_instance(hull, 5, scenario="imperfect")
        self.assertTrue(np.array_equal(poor.truth, perfect.truth))  # same seed, same C
        self.assertFalse(np.array_equal(poor.prior, poor.truth))
        with self.assertRaisesRegex(ValueError, r"--p-c: must be a number in \[0, 1\]"):
            hullinspect.make_instance(hull, 5, p_c=2)

    def test_load_hull_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "hull.txt")
            with open(path, "w") as f:
                f.write("XXX.\nXXXX\n")
            hull = hullinspect.Hull.load(path)
            self.assertEqual(hull.mask.tolist(), [[True, True, True, True], [True, True, True, False]])


SMALL = {
    "hull": "rectangle",
    "grid": {"width": 30, "height": 10},
    "scenarios": ["perfect"],
    "uavs": [2],
    "algorithms": ["lawnmower", "part-tsp"],
    "instances": 2,
    "curve": {"step": 10, "end": 100},
}


class Experiments(unittest.TestCase):
    def test_rows_equal_runs_csv(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "results")
            rows = hullinspect.run_experiment(SMALL, jobs=2, out=out)
            with open(os.path.join(out, "runs.csv")) as f:
                lines = f.read().splitlines()
        self.assertEqual(len(rows), 4)
        self.assertEqual(list(rows[0].keys()), lines[0].split(","))
        self.assertIn("partitioner.iteration-limit=2000", rows[0]["planner_options"])
        frame = hullinspect.to_dataframe(rows)
        self.assertEqual(len(frame), 4)
        self.assertEqual(frame["T_m"].dtype.kind, "i")
        self.assertEqual(set(frame["algorithm"]), {"lawnmower", "part-tsp"})

    def test_jobs_do_not_change_results(self):
        one = hullinspect.run_experiment(SMALL, jobs=1)
        two = hullinspect.run_experiment(SMALL, jobs=2)
        self.assertEqual(one, two)


class GoEast(hullinspect.Planner):
    """Test planner: every UAV flies east until the edge, then hovers."""

    def start(self, context):
        self.width = context.hull.shape[1]
        self.saw_truth = hasattr(context, "truth")

    def decide(self, view):
        assert view.map.dtype == np.int8
        return ["E" if x + 1 < self.width else "hover" for (x, y, z, transit, failed) in view.uavs]


class BadAction(hullinspect.Planner):
    def decide(self, view):
        return ["N"] * len(view.uavs) if view.t < 3 else ["up"] * len(view.uavs)


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
hullinspect.register_planner("test-nearest", NearestUnknown)


class PythonPlanners(unittest.TestCase):
    def test_registered_planner_runs_and_is_listed(self):
        result = hullinspect.run_mission(algorithm="test-go-east", uavs=2, time_limit=50)
        self.assertFalse(result.complete)
        self.assertGreater(result.counters["moves"], 0)
        names = [e["name"] for e in hullinspect.catalog("planners")]
        self.assertIn("test-go-east", names)

    def test_python_planner_completes_a_small_experiment(self):
        config = dict(SMALL, algorithms=["test-nearest", "lawnmower"])
        rows = hullinspect.run_experiment(config, jobs=2)
        self.assertEqual(len(rows), 4)
        self.assertTrue(all(r["complete"] == "1" for r in rows))

    def test_bad_action_names_uav_and_step(self):
        with self.assertRaises(ValueError) as caught:
            hullinspect.run_mission(algorithm="test-bad-action", uavs=2)
        self.assertEqual(str(caught.exception),
                         "planner 'test-bad-action': UAV 0 at t = 3: unknown action 'up' "
                         "(expected N, S, E, W, hover or change)")

    def test_names_cannot_be_registered_twice(self):
        with self.assertRaisesRegex(ValueError, "already registered"):
            hullinspect.register_planner("test-go-east", GoEast)
        with self.assertRaisesRegex(ValueError, "not a subclass"):
            hullinspect.register_planner("test-object", object)


if __name__ == "__main__":
    unittest.main()
