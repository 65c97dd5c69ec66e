#!/usr/bin/env python3
"""A stand-in for Fast Downward's (or SymK's) fast-downward.py in bench/compare-fd's test:
the same command line (`--overall-time-limit T [--overall-memory-limit M] DOMAIN PROBLEM
--search S`, or `--alias NAME` before the files), a plan file `sas_plan` in the working directory and log lines in Fast
Downward's words. It knows the plans of the test's instances by problem file name:

- `reach-c.pddl`: solved, the optimal plan (cost 2);
- `reach-d.pddl`: out of time (exit 23, no plan), as Fast Downward reports it.

With FAKE_PEER_WRONG=1 it claims cost 2 for `reach-c.pddl` with a plan that does not
reach the goal, which compare-fd must catch. With FAKE_PEER_HANG=FILE it writes FILE and
then waits (for a kill) on `reach-d.pddl`, so that a test can interrupt the grid while
the cell runs."""

import argparse
import os
import sys
import time
from pathlib import Path

ap = argparse.ArgumentParser()
ap.add_argument("--overall-time-limit")
ap.add_argument("--overall-memory-limit")
ap.add_argument("--alias")
ap.add_argument("domain")
ap.add_argument("problem")
ap.add_argument("--search")
args = ap.parse_args()
if (args.alias is None) == (args.search is None):
    ap.error("give --search or --alias")  # exit 2, as the driver's argparse
if args.alias and sys.argv.index("--alias") > sys.argv.index(args.domain):
    # The real driver takes the files' later options as the search component's.
    ap.error("--alias is a driver option: it goes before the input files")

print(f"INFO     planner time limit: {args.overall_time_limit}")
if args.alias:
    print(f"INFO     alias: {args.alias}")
else:
    print(f"INFO     search configuration: {args.search}")
name = Path(args.problem).name
if name == "reach-c.pddl":
    plan = ["(move a b)", "(move b c)"]
    if os.environ.get("FAKE_PEER_WRONG") == "1":
        plan = ["(move a b)", "(move b a)"]
    Path("sas_plan").write_text("\n".join(plan) + "\n; cost = 2 (unit cost)\n")
    for line in ["Solution found!", "Plan length: 2 step(s).", "Plan cost: 2",
                 "Expanded 3 state(s).", "Generated 6 state(s).", "Search time: 0.0001s",
                 "Total time: 0.0012s"]:
        print(f"[t=0.0012s, 8800 KB] {line}")
    print("Peak memory: 8800 KB")
    sys.exit(0)
if os.environ.get("FAKE_PEER_HANG"):
    Path(os.environ["FAKE_PEER_HANG"]).write_text(f"{os.getpid()}\n")
    while True:
        time.sleep(1)
print("[t=0.5s, 8800 KB] Time limit has been reached.")
print("Peak memory: 8800 KB")
sys.exit(23)
