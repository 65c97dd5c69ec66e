"""The learning side through Python: simulate, learn, levels, domains, Algorithm 1, and
recordings as arrays."""

from __future__ import annotations

import builtins
import math
import pathlib
import subprocess
from typing import Any, List

import pytest

import demoplan


@pytest.fixture(scope="module")
def recordings(tmp_path_factory: pytest.TempPathFactory) -> List[pathlib.Path]:
    out = tmp_path_factory.mktemp("simulated")
    return demoplan.simulate(out, participants=2, per_participant=2, seed=7)


def test_simulate_writes_the_recordings_it_returns(recordings: List[pathlib.Path]) -> None:
    assert len(recordings) == 4
    for path in recordings:
        assert path.is_file() and path.suffix == ".jsonl"
        assert (path.parent / "simulation.json").is_file()


def test_learned_library_equals_what_demoplan_learn_writes(
    recordings: List[pathlib.Path], tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    library = demoplan.Library()
    log = library.learn(recordings)
    assert "wrote" in log
    written = tmp_path / "library.json"
    subprocess.run(
        [str(demoplan_binary), "learn", *map(str, recordings), "-o", str(written)],
        check=True,
        capture_output=True,
    )
    assert library.to_json() == written.read_text()
    # Loading the file gives the same library, and saving it writes the same file.
    loaded = demoplan.Library.load(written)
    assert loaded.to_json() == library.to_json()
    loaded.save(tmp_path / "again.json")
    assert (tmp_path / "again.json").read_text() == written.read_text()


def test_learning_twice_counts_each_recording_once(recordings: List[pathlib.Path]) -> None:
    library = demoplan.Library()
    library.learn(recordings[:2])
    library.learn(recordings)
    once = demoplan.Library()
    once.learn(recordings)
    assert library.to_json() == once.to_json()


def test_generalise_learns_what_demoplan_learn_generalise_writes(
    recordings: List[pathlib.Path], tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    library = demoplan.Library()
    library.learn(recordings, generalise=True)
    written = tmp_path / "general.json"
    subprocess.run(
        [str(demoplan_binary), "learn", *map(str, recordings), "--generalise", "-o", str(written)],
        check=True,
        capture_output=True,
    )
    assert library.to_json() == written.read_text()
    assert '"operator_form": "generalised"' in library.to_json()
    # Learning into it again keeps it generalised; a specific library refuses.
    library.learn(recordings)
    assert library.to_json() == written.read_text()
    specific = demoplan.Library()
    specific.learn(recordings[:1])
    with pytest.raises(demoplan.DemoplanError) as raised:
        specific.learn(recordings, generalise=True)
    assert raised.value.exit_code == 36
    assert "one library holds operators of one form" in raised.value.message


def test_operators_have_counts_costs_and_provenance(recordings: List[pathlib.Path]) -> None:
    library = demoplan.Library()
    library.learn(recordings)
    operators = library.operators()
    assert operators
    assert sum(o.count for o in operators) == library.segments
    ids = set(library.recordings)
    assert len(ids) == 4
    for op in operators:
        assert op.name.startswith(op.activity)
        assert 0 <= op.cost <= library.lambda_
        assert len(op.provenance) == op.count
        assert all(p.recording in ids and p.start <= p.end for p in op.provenance)
    # The most frequent operator of each type is the cheapest of its type.
    by_type: dict[str, List[demoplan.Operator]] = {}
    for op in operators:
        by_type.setdefault(op.activity, []).append(op)
    for ops in by_type.values():
        first = next(o for o in ops if o.name == o.activity)
        assert first.cost == min(o.cost for o in ops)
    assert operators[0].name in library.cards()


def test_levels_domains_and_algorithm_1(recordings: List[pathlib.Path]) -> None:
    library = demoplan.Library()
    library.learn(recordings)
    levels = library.levels()
    assert [level.prio for level in levels] == sorted(level.prio for level in levels)
    assert len(levels[-1].operators) >= len(levels[0].operators)
    domain = library.domain(levels[-1].prio)
    assert domain.lstrip().startswith(";") or "(define (domain" in domain
    problem = demoplan.tower_problem(["cube_1", "cube_2"])
    full = demoplan.plan(domain, problem)
    solved = demoplan.solve(library, problem)
    # Priorities in order (a level searched again after the execution loop set an
    # operator aside appears again).
    tried = list(dict.fromkeys(r.prio for r in solved.levels))
    assert tried == [level.prio for level in levels][: len(tried)]
    level = solved.plan_level
    assert level is not None and level.plan is not None and level.cost is not None
    # A slim level's plan costs at least the full domain's optimum.
    assert level.cost >= full.cost
    assert demoplan.validate(domain, problem, level.plan).valid
    # Executed in the cube world, by default.
    assert level.execution == "executed"


FIXTURES = pathlib.Path(__file__).resolve().parents[2] / "crates" / "closed-loop" / "tests" / "fixtures"


def test_solve_sets_aside_an_operator_whose_step_fails() -> None:
    library = demoplan.Library.load(FIXTURES / "broken-idle-library.json")
    problem = demoplan.tower_problem(paper_goal=1, cubes=3, hands=1)
    solved = demoplan.solve(library, problem)
    assert [(r.prio, r.execution) for r in solved.levels] == [(1, "step-failed"), (1, "executed")]
    assert [s.name for s in solved.set_aside] == ["idle"]
    aside = solved.set_aside[0]
    assert aside.step == 1 and aside.action.startswith("(idle left_hand cube_")
    assert any(f.startswith("(inhand left_hand") for f in aside.promised)
    assert not any(f.startswith("(inhand") for f in aside.found)
    assert solved.replans == 1 and solved.execution_seconds > 0
    level = solved.plan_level
    assert level is not None and level.plan is not None
    assert "(idle " not in level.plan
    # Without execution: Algorithm 1's plan, with the idle, and nothing set aside.
    plain = demoplan.solve(library, problem, execute=False)
    assert plain.plan_level is not None and plain.plan_level.plan is not None
    assert "(idle " in plain.plan_level.plan
    assert plain.set_aside == [] and plain.levels[0].execution is None


def test_no_executable_plan_is_an_exception_with_what_was_set_aside() -> None:
    library = demoplan.Library.load(FIXTURES / "no-executable-library.json")
    problem = demoplan.tower_problem(paper_goal=1, cubes=3, hands=1)
    with pytest.raises(demoplan.NoExecutablePlan) as raised:
        demoplan.solve(library, problem)
    error = raised.value
    assert isinstance(error, demoplan.DemoplanError)
    assert error.exit_code == 45
    assert [s.name for s in error.set_aside] == ["idle"]
    assert str(error).startswith("No executable plan")
    assert error.solved is not None and error.solved.plan_level is None
    # Without execution the same library plans.
    assert demoplan.solve(library, problem, execute=False).plan_level is not None


def test_damaged_library_names_its_line(tmp_path: pathlib.Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "demoplan-library",\n "version": 999}\n')
    with pytest.raises(demoplan.InputError, match="bad.json"):
        demoplan.Library.load(bad)


def test_recording_to_numpy(recordings: List[pathlib.Path]) -> None:
    import numpy
    recording = demoplan.Recording(recordings[0])
    array = recording.to_numpy()
    assert array.shape == (len(recording.times), len(recording.entities), 7)
    assert array.dtype == numpy.float32
    # Observed poses have unit quaternions; missing ones are NaN in all 7 numbers.
    for frame in array[:50]:
        for pose in frame:
            if math.isnan(float(pose[0])):
                assert numpy.isnan(pose).all()
            else:
                assert abs(float(numpy.linalg.norm(pose[3:])) - 1.0) < 1e-3


def test_to_numpy_says_it_needs_numpy(recordings: List[pathlib.Path], monkeypatch: pytest.MonkeyPatch) -> None:
    recording = demoplan.Recording(recordings[0])
    real_import = builtins.__import__

    def no_numpy(name: str, *args: Any, **kwargs: Any) -> Any:
        if name == "numpy" or name.startswith("numpy."):
            raise ImportError("No module named 'numpy'")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_numpy)
    with pytest.raises(ImportError, match="needs numpy"):
        recording.to_numpy()


def test_bad_recording_is_an_input_error(tmp_path: pathlib.Path) -> None:
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"format": "nonsense"}\n')
    with pytest.raises(demoplan.InputError, match="bad.jsonl"):
        demoplan.Recording(bad)
