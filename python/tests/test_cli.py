"""The command line through Python (the console script and ``python -m demoplan``) is
the binary's: same output, same exit codes."""

from __future__ import annotations

import pathlib
import shutil
import subprocess
import sys
from typing import List, Sequence, Tuple

import pytest

import demoplan


def run(command: Sequence[str], cwd: pathlib.Path) -> Tuple[int, str, str]:
    done = subprocess.run(list(command), capture_output=True, text=True, cwd=cwd, check=False)
    return done.returncode, done.stdout, done.stderr


def console_script() -> List[str]:
    path = shutil.which("demoplan", path=str(pathlib.Path(sys.executable).parent))
    assert path is not None, "the demoplan console script is not installed beside this Python"
    return [path]


def entry_points(binary: pathlib.Path) -> List[List[str]]:
    return [[str(binary)], console_script(), [sys.executable, "-m", "demoplan"]]


# Commands whose output has no timings, so that it must be identical byte for byte.
DETERMINISTIC = [
    ["--version"],
    ["--help"],
    ["check", "DOMAIN", "PROBLEM"],
    ["validate", "DOMAIN", "PROBLEM", "PLAN"],
    ["validate", "DOMAIN", "PROBLEM", "BADPLAN"],
    ["check", "DOMAIN", "BROKEN"],
    ["check", "DOMAIN", "MISSING"],
    ["no-such-command"],
]


@pytest.mark.parametrize("args", DETERMINISTIC, ids=lambda a: " ".join(a))
def test_same_output_and_exit_code_as_the_binary(
    args: List[str], tmp_path: pathlib.Path, demoplan_binary: pathlib.Path, cube_domain: pathlib.Path, cube_problem: pathlib.Path
) -> None:
    (tmp_path / "plan.txt").write_text(
        "(reach left c2)\n(take left c2 table)\n(stack left c2 c1)\n"
        "(reach left c3)\n(take left c3 table)\n(stack left c3 c2)\n"
    )
    (tmp_path / "bad.txt").write_text("(take left c2 table)\n")
    (tmp_path / "broken.pddl").write_text("(define (problem p) (:domain cube-stacking)\n  (:init (on-top c9 table))\n")
    names = {
        "DOMAIN": str(cube_domain),
        "PROBLEM": str(cube_problem),
        "PLAN": "plan.txt",
        "BADPLAN": "bad.txt",
        "BROKEN": "broken.pddl",
        "MISSING": "missing.pddl",
    }
    argv = [names.get(a, a) for a in args]
    results = [run(entry + argv, tmp_path) for entry in entry_points(demoplan_binary)]
    binary = results[0]
    for result in results[1:]:
        assert result == binary
    # The cases cover success and failures of several kinds.
    expected_code = {
        "--version": 0,
        "--help": 0,
        "PLAN": 0,
        "BADPLAN": 1,
        "BROKEN": 31,
        "MISSING": 36,
        "no-such-command": 36,
    }.get(args[-1], 0)
    assert binary[0] == expected_code, binary


def test_plan_writes_the_same_plan_with_the_same_exit_code(
    tmp_path: pathlib.Path, demoplan_binary: pathlib.Path, cube_domain: pathlib.Path, cube_problem: pathlib.Path
) -> None:
    plans = []
    for i, entry in enumerate(entry_points(demoplan_binary)):
        plan_file = tmp_path / f"plan-{i}"
        code, out, _ = run(
            entry + ["plan", str(cube_domain), str(cube_problem), "--search", "astar(lmcut())", "--plan-file", str(plan_file)],
            tmp_path,
        )
        assert code == 0
        assert "Solution found!" in out
        plans.append(plan_file.read_text())
    assert plans[0] == plans[1] == plans[2]
    assert "; cost = 6" in plans[0]


def test_version_is_the_crates(demoplan_binary: pathlib.Path, tmp_path: pathlib.Path) -> None:
    _, out, _ = run([str(demoplan_binary), "--version"], tmp_path)
    assert out.split() == ["demoplan", demoplan.__version__]


@pytest.mark.parametrize("entry", ["console script", "python -m demoplan"])
def test_a_grids_cells_run_this_command_again(entry: str, tmp_path: pathlib.Path) -> None:
    """A grid runs each cell as a child process of its own command line. In Python this
    process's executable is the interpreter, so the children must be
    ``python -m demoplan ... --cell ID``: a wrong command line would crash every cell
    (exit 1, "cell(s) crashed")."""
    command = console_script() if entry == "console script" else [sys.executable, "-m", "demoplan"]
    out = tmp_path / "grid"
    grid = ["study", "-o", str(out), "--seeds", "3", "--hands", "1", "--heights", "2", "--time-limit", "60"]
    code, stdout, stderr = run(command + grid + ["-j", "2"], tmp_path)
    assert code == 0, stdout + stderr
    assert "6 runs (6 computed now, 0 from earlier results, 2 at a time)" in stdout, stdout
    assert "crashed" not in stderr, stderr
    records = sorted(out.glob("runs-00001-00100/*/record.json"))
    assert len(records) == 6
    for record in records:
        assert '"crashed"' not in record.read_text()
