#!/usr/bin/env python3
"""bench/compare-fd as a grid, with a fake peer (bench/tests/fake-fast-downward.py) in
the place of Fast Downward and SymK, so that it needs neither: 2 instances x demoplan,
FD and SymK, each (instance, planner, configuration) a cell in Lab's run layout.

    DEMOPLAN_BIN=target/debug/demoplan python3 bench/tests/test_compare_fd.py

DEMOPLAN_BIN (default target/debug/demoplan) is the demoplan binary the cells run and
validate plans with; a missing binary is a failure, not a skip. CI runs this
(.ci/run, "compare-fd's grid")."""

import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent.parent
SCRIPT = REPO / "bench" / "compare-fd"
FAKE = HERE / "fake-fast-downward.py"
DEMOPLAN = Path(os.environ.get("DEMOPLAN_BIN", REPO / "target" / "debug" / "demoplan")).resolve()

DOMAIN = """(define (domain line)
  (:requirements :strips :typing)
  (:types place)
  (:predicates (at ?p - place) (road ?from ?to - place))
  (:action move
    :parameters (?from ?to - place)
    :precondition (and (at ?from) (road ?from ?to))
    :effect (and (not (at ?from)) (at ?to))))
"""


def problem(goal):
    return f"""(define (problem reach-{goal}) (:domain line)
  (:objects a b c d - place)
  (:init (at a) (road a b) (road b a) (road b c) (road c d))
  (:goal (at {goal})))
"""


class CompareFdGrid(unittest.TestCase):
    def setUp(self):
        self.assertTrue(DEMOPLAN.is_file(), f"no demoplan binary at {DEMOPLAN} (DEMOPLAN_BIN)")
        self.tmp = tempfile.TemporaryDirectory(prefix="compare-fd-test-")
        root = Path(self.tmp.name)
        self.suite = root / "suite"
        (self.suite / "line").mkdir(parents=True)
        (self.suite / "line" / "domain.pddl").write_text(DOMAIN)
        rows = ["suite,domain,instance,domain_file,problem_file,optimal_cost,source"]
        for goal, cost in (("c", 2), ("d", 3)):
            (self.suite / "line" / f"reach-{goal}.pddl").write_text(problem(goal))
            rows.append(f"test,line,reach-{goal},line/domain.pddl,line/reach-{goal}.pddl,{cost},test")
        (self.suite / "optimal_costs.csv").write_text("\n".join(rows) + "\n")
        self.list = root / "list.txt"
        self.list.write_text("line/reach-c\nline/reach-d\n")
        self.out = root / "out"

    def tearDown(self):
        self.tmp.cleanup()

    def grid_command(self, *extra):
        return [sys.executable, str(SCRIPT), "--list", str(self.list), "--benchmarks",
                str(self.suite), "--planners", "demoplan,fd,symk", "--demoplan", str(DEMOPLAN),
                "--fd", str(FAKE), "--symk", str(FAKE), "--time-limit", "60", "--out",
                str(self.out), *extra]

    def grid(self, *extra, env=None):
        return subprocess.run(self.grid_command(*extra), capture_output=True, text=True,
                              timeout=600, env={**os.environ, **(env or {})})

    def properties(self):
        return json.loads((self.out / "eval" / "properties").read_text())

    def test_cells_lab_properties_checks_and_summary(self):
        listed = self.grid("--list-cells")
        self.assertEqual(listed.returncode, 0, listed.stderr)
        lines = listed.stdout.splitlines()
        self.assertEqual(lines[0].split("\t")[:5], ["task", "id", "algorithm", "domain", "problem"])
        cells = [line.split("\t") for line in lines[1:]]
        self.assertEqual(len(cells), 6)  # 2 instances x 3 planners x 1 configuration
        self.assertEqual(len({c[1] for c in cells}), 6, "ids are unique")
        self.assertEqual(len({tuple(c[2:5]) for c in cells}), 6, "Lab's names are unique")
        self.assertFalse(self.out.exists(), "--list-cells wrote something")
        # The ids are stable: the same grid lists the same ids.
        self.assertEqual(self.grid("--list-cells").stdout, listed.stdout)

        done = self.grid("-j", "2")
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        props = self.properties()
        self.assertEqual(len(props), 6)
        by_name = {(p["algorithm"], p["problem"]): p for p in props.values()}
        for key, p in props.items():
            self.assertEqual(key, "-".join(p["id"]))
            self.assertEqual(p["id"], [p["algorithm"], p["domain"], p["problem"]])
            run = self.out / p["run_dir"]
            self.assertEqual(json.loads((run / "properties").read_text()), p)
            self.assertTrue((run / "started").is_file())
            self.assertTrue((run / "run.log").is_file())
            self.assertEqual(json.loads((run / "record.json").read_text())["id"], p["compare_fd_id"])
            self.assertEqual(p["planner_time_limit"], 60)
        # demoplan solves both, at the optimal cost, validated.
        for problem_name, cost in (("reach-c", 2), ("reach-d", 3)):
            d = by_name[("demoplan-astar(lmcut())", problem_name)]
            self.assertEqual((d["coverage"], d["cost"], d["error"]), (1, cost, "success"), d)
            self.assertEqual((d["cost_check"], d["plan_valid"]), ("ok", "yes"), d)
            self.assertGreater(d["expansions"], 0)
            self.assertIn("total_time", d)
        # The peers: solved at the optimum on reach-c (read from their log and plan file),
        # out of time on reach-d, in Lab's words.
        for algorithm in ("fd-astar(lmcut())", "symk-sym_bd()"):
            solved = by_name[(algorithm, "reach-c")]
            self.assertEqual((solved["coverage"], solved["cost"], solved["error"]), (1, 2, "success"))
            self.assertEqual((solved["expansions"], solved["generated"], solved["memory"]), (3, 6, 8800))
            self.assertEqual((solved["search_time"], solved["total_time"]), (0.0001, 0.0012))
            self.assertEqual((solved["cost_check"], solved["plan_valid"]), ("ok", "yes"))
            late = by_name[(algorithm, "reach-d")]
            self.assertEqual((late["coverage"], late["error"]), (0, "search-out-of-time"))
            self.assertNotIn("cost", late)
        # SymK ran its own configuration.
        symk_log = self.out / by_name[("symk-sym_bd()", "reach-c")]["run_dir"] / "run.log"
        self.assertIn("search configuration: sym_bd()", symk_log.read_text())
        summary = (self.out / "summary.md").read_text()
        self.assertIn("# demoplan vs FD", summary)
        self.assertIn("# demoplan vs SymK", summary)
        self.assertIn("| **overall** | 2 | 2 | 1 | 1 | 0 |", summary)
        self.assertIn("6: 6 computed now, 0 from earlier results, 2 at a time", summary)
        runs = (self.out / "runs.csv").read_text().splitlines()
        self.assertEqual(len(runs), 7)

    def test_an_alias_is_the_planners_alias_option(self):
        done = self.grid("--planners", "demoplan,fd", "--search", "alias:seq-opt-lmcut")
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        by_name = {(p["algorithm"], p["problem"]): p for p in self.properties().values()}
        ours = by_name[("demoplan-alias:seq-opt-lmcut", "reach-d")]
        self.assertEqual((ours["coverage"], ours["cost"], ours["cost_check"]), (1, 3, "ok"), ours)
        peer = by_name[("fd-alias:seq-opt-lmcut", "reach-c")]
        self.assertEqual((peer["coverage"], peer["cost"], peer["plan_valid"]), (1, 2, "yes"), peer)
        log = (self.out / peer["run_dir"] / "run.log").read_text()
        self.assertIn("alias: seq-opt-lmcut", log)

    def test_finished_cells_are_reused_unless_forced(self):
        first = self.grid()
        self.assertEqual(first.returncode, 0, first.stderr)
        again = self.grid()
        self.assertEqual(again.returncode, 0, again.stderr)
        self.assertIn("6 reused", again.stderr)
        self.assertIn("0 computed now, 6 from earlier results", again.stdout)
        self.assertNotIn("at a time", again.stdout)
        # A cell whose record is gone (or cut short) runs again; the others are reused.
        record = self.out / "runs-00001-00100" / "00002" / "record.json"
        record.write_text(record.read_text()[:20])
        resumed = self.grid()
        self.assertEqual(resumed.returncode, 0, resumed.stderr)
        self.assertIn("5 reused", resumed.stderr)
        self.assertIn("1 computed now, 5 from earlier results, 1 at a time", resumed.stdout)
        self.assertEqual(len(self.properties()), 6)
        forced = self.grid("--force")
        self.assertIn("6 computed now", forced.stdout)

    def test_an_interrupted_grid_resumes_with_every_result_whole(self):
        mark = Path(self.tmp.name) / "peer-running"
        cmd = self.grid_command("--planners", "fd")
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                env={**os.environ, "FAKE_PEER_HANG": str(mark)})
        # Wait for the hanging cell (reach-d, task 2) to be running: on its marker.
        while not mark.exists():
            self.assertIsNone(proc.poll(), "the grid ended before its second cell ran")
            time.sleep(0.05)
        proc.send_signal(signal.SIGINT)
        _, stderr = proc.communicate(timeout=120)
        self.assertEqual(proc.returncode, 130, stderr)
        self.assertIn("interrupted", stderr)
        hung = self.out / "runs-00001-00100" / "00002"
        self.assertTrue((hung / "started").is_file())
        self.assertFalse((hung / "record.json").exists(), "an interrupted cell wrote a result")
        self.assertTrue((self.out / "runs-00001-00100" / "00001" / "record.json").is_file())
        done = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertIn("1 reused", done.stderr)
        self.assertEqual(len(self.properties()), 2)

    def test_the_watchdog_kills_a_peer_past_its_wall_time(self):
        mark = Path(self.tmp.name) / "peer-running"
        done = self.grid("--planners", "fd", "--watchdog", "2", env={"FAKE_PEER_HANG": str(mark)})
        self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
        hung = {p["problem"]: p for p in self.properties().values()}["reach-d"]
        self.assertEqual((hung["coverage"], hung["error"]), (0, "sigkill"), hung)
        self.assertIn("killed by the watchdog after 2 s wall", hung["unexplained_errors"][0])

    def test_a_wrong_plan_of_a_peer_fails_the_grid(self):
        done = self.grid(env={"FAKE_PEER_WRONG": "1"})
        self.assertEqual(done.returncode, 1, done.stdout + done.stderr)
        self.assertIn("COST MISMATCH", done.stdout)
        props = self.properties()
        wrong = [p for p in props.values() if p.get("cost_check") == "mismatch"]
        self.assertEqual(sorted(p["algorithm"] for p in wrong), ["fd-astar(lmcut())", "symk-sym_bd()"])
        for p in wrong:
            self.assertEqual(p["plan_valid"], "no")
            self.assertIn("plan does not validate", p["unexplained_errors"][0])

    def test_plans_of_reused_cells_solved_without_a_validator_are_validated(self):
        # A grid resumed over sessions: cells that ran while no demoplan binary existed
        # carry no verdict on their plans (as the coverage grid's did, 2026-12-06).
        first = self.grid(env={"FAKE_PEER_WRONG": "1"})
        self.assertEqual(first.returncode, 1, first.stdout + first.stderr)
        records = sorted(self.out.glob("runs-*/*/record.json"))
        self.assertEqual(len(records), 6)
        solved = []
        for path in records:
            row = json.loads(path.read_text())
            if row["outcome"] == "solved":
                row.update(plan_valid="", cost_check="ok", note="not validated (demoplan not built)")
                path.write_text(json.dumps(row) + "\n")
                solved.append(path)
        # demoplan's two, and each peer's wrong plan for reach-c (the fake times out on reach-d).
        self.assertEqual(len(solved), 4)
        again = self.grid()
        self.assertIn("6 reused", again.stderr)
        self.assertIn("validated the plans of 4 reused cells", again.stderr)
        # The peers' wrong plans are caught now, and the grid fails as on a fresh run.
        self.assertEqual(again.returncode, 1, again.stdout + again.stderr)
        by_algorithm = {}
        for p in self.properties().values():
            by_algorithm.setdefault(p["algorithm"], []).append(p)
        for p in by_algorithm["demoplan-astar(lmcut())"]:
            self.assertEqual((p["plan_valid"], p["cost_check"]), ("yes", "ok"), p)
        for algorithm in ("fd-astar(lmcut())", "symk-sym_bd()"):
            (p,) = [p for p in by_algorithm[algorithm] if p["problem"] == "reach-c"]
            self.assertEqual((p["plan_valid"], p["cost_check"]), ("no", "mismatch"), p)
            self.assertIn("plan does not validate", p["unexplained_errors"][0])
        # The cells' own records say so too, so the next resume does not validate again.
        for path in solved:
            self.assertIn(json.loads(path.read_text())["plan_valid"], ("yes", "no"))
        self.assertNotIn("validated the plans", self.grid().stderr)


if __name__ == "__main__":
    unittest.main()
