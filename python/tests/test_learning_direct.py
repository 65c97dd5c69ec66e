"""learn, simulate and tower_problem call the library crates directly: what they write and
how they fail must stay what the command line writes and prints for the same input."""

from __future__ import annotations

import pathlib
import subprocess

import pytest

import demoplan


def test_simulate_writes_the_files_demoplan_simulate_writes(
    tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    ours = tmp_path / "python"
    theirs = tmp_path / "cli"
    recordings = demoplan.simulate(ours, participants=1, per_participant=2, seed=3, cubes=4)
    subprocess.run(
        [str(demoplan_binary), "simulate", "-o", str(theirs), "--participants", "1",
         "--per-participant", "2", "--seed", "3", "--cubes", "4"],
        check=True,
        capture_output=True,
    )
    names = sorted(p.name for p in theirs.iterdir())
    assert sorted(p.name for p in ours.iterdir()) == names
    assert len(recordings) == 2 and all(r.parent == ours and r.name in names for r in recordings)
    for name in names:
        assert (ours / name).read_bytes() == (theirs / name).read_bytes(), name


@pytest.mark.parametrize(
    "arguments", [{"participants": -1}, {"per_participant": 2**40}, {"seed": "7"}, {"cubes": -3}]
)
def test_simulate_refuses_a_count_that_is_no_count(tmp_path: pathlib.Path, arguments: dict) -> None:
    with pytest.raises(demoplan.InputError) as raised:
        demoplan.simulate(tmp_path / "out", **arguments)
    assert raised.value.exit_code == 36
    assert next(iter(arguments)) in raised.value.message
    assert not (tmp_path / "out").exists()


def test_tower_problem_is_the_text_demoplan_problem_writes(
    tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    for ours, argv in [
        (demoplan.tower_problem(paper_goal=2), ["--paper-goal", "2"]),
        (demoplan.tower_problem(["cube_3", "cube_1"], cubes=3, hands=1),
         ["--tower", "cube_3,cube_1", "--cubes", "3", "--hands", "1"]),
    ]:
        out = tmp_path / "problem.pddl"
        subprocess.run([str(demoplan_binary), "problem", "-o", str(out), *argv], check=True, capture_output=True)
        assert ours == out.read_text(encoding="utf-8")


@pytest.mark.parametrize(
    "arguments, named",
    [
        ({"tower": ["cube_1", "cube_2"], "cubes": 1}, "cubes"),
        ({"tower": ["cube_1", "cube_2"], "hands": 3}, "hands"),
        ({"paper_goal": 9}, "paper_goal"),
        ({}, "paper_goal"),
        ({"tower": ["cube_1"]}, "tower"),
    ],
)
def test_tower_problem_refuses_bad_goals_and_scenes_by_name(arguments: dict, named: str) -> None:
    with pytest.raises(demoplan.InputError) as raised:
        demoplan.tower_problem(**arguments)
    assert raised.value.exit_code == 36
    assert named in raised.value.message


def test_learning_a_bad_recording_fails_as_demoplan_learn_does(
    tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    good = demoplan.simulate(tmp_path / "demos", participants=1, per_participant=1)
    bad = tmp_path / "bad.jsonl"
    lines = good[0].read_text(encoding="utf-8").splitlines()
    bad.write_text("\n".join([*lines[:3], '{"t": "soon"}', *lines[3:]]) + "\n", encoding="utf-8")
    library = demoplan.Library()
    with pytest.raises(demoplan.InputError) as raised:
        library.learn([good[0], bad])
    cli = subprocess.run(
        [str(demoplan_binary), "learn", str(good[0]), str(bad), "-o", str(tmp_path / "lib.json")],
        capture_output=True,
        text=True,
    )
    assert raised.value.exit_code == cli.returncode == 31
    assert raised.value.diagnostic == cli.stderr.rstrip()
    assert "bad.jsonl" in raised.value.diagnostic and ":4" in raised.value.diagnostic
    # Nothing was learned: the library is as it was.
    assert library.segments == 0 and library.recordings == []


def test_learning_what_is_no_recording_names_its_line(
    tmp_path: pathlib.Path, demoplan_binary: pathlib.Path
) -> None:
    notes = tmp_path / "notes.txt"
    notes.write_text("not a recording\n", encoding="utf-8")
    with pytest.raises(demoplan.InputError) as raised:
        demoplan.Library().learn([notes])
    cli = subprocess.run(
        [str(demoplan_binary), "learn", str(notes), "-o", str(tmp_path / "lib.json")],
        capture_output=True,
        text=True,
    )
    assert raised.value.exit_code == cli.returncode == 31
    assert raised.value.diagnostic == cli.stderr.rstrip()
    assert "notes.txt:1" in raised.value.diagnostic
