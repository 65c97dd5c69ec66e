"""demoplan.plan and demoplan.validate, in-process."""

from __future__ import annotations

import pathlib
import signal
import threading
import time
import _thread

import pytest

import demoplan

BLOCKS_DOMAIN = """
(define (domain blocks)
  (:requirements :strips :typing)
  (:types block)
  (:predicates (on ?x ?y - block) (ontable ?x - block) (clear ?x - block)
               (holding ?x - block) (handempty))
  (:action pick-up :parameters (?x - block)
    :precondition (and (clear ?x) (ontable ?x) (handempty))
    :effect (and (not (ontable ?x)) (not (clear ?x)) (not (handempty)) (holding ?x)))
  (:action put-down :parameters (?x - block)
    :precondition (holding ?x)
    :effect (and (not (holding ?x)) (clear ?x) (handempty) (ontable ?x)))
  (:action stack :parameters (?x ?y - block)
    :precondition (and (holding ?x) (clear ?y))
    :effect (and (not (holding ?x)) (not (clear ?y)) (clear ?x) (handempty) (on ?x ?y)))
  (:action unstack :parameters (?x ?y - block)
    :precondition (and (on ?x ?y) (clear ?x) (handempty))
    :effect (and (holding ?x) (clear ?y) (not (clear ?x)) (not (handempty)) (not (on ?x ?y)))))
"""


def reverse_tower(n: int) -> str:
    """A tower b0 (bottom) .. b{n-1}, to be rebuilt upside down."""
    blocks = [f"b{i}" for i in range(n)]
    init = ["(handempty)", f"(ontable {blocks[0]})", f"(clear {blocks[-1]})"]
    init += [f"(on {a} {b})" for b, a in zip(blocks, blocks[1:])]
    goal = [f"(on {b} {a})" for b, a in zip(blocks, blocks[1:])]
    return (
        f"(define (problem reverse-{n}) (:domain blocks) (:objects {' '.join(blocks)} - block)"
        f" (:init {' '.join(init)}) (:goal (and {' '.join(goal)})))"
    )


def test_plan_from_paths_has_the_optimal_cost(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    found = demoplan.plan(cube_domain, cube_problem)
    assert found.cost == 6
    assert len(found.steps) == 6
    assert all(step.startswith("(") and step.endswith(")") for step in found.steps)
    assert found.statistics["outcome"] == "solved"
    assert found.statistics["expanded"] >= 1
    # The plan found validates, and its value is its cost.
    verdict = demoplan.validate(cube_domain, cube_problem, found)
    assert verdict.valid and verdict.cost == 6


def test_plan_from_texts() -> None:
    found = demoplan.plan(BLOCKS_DOMAIN, reverse_tower(4), search="astar(hmax())")
    # Every block moves (two actions each): 8 steps.
    assert found.cost == 8


def test_alias_runs_its_search_and_translator_options(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    found = demoplan.plan(cube_domain, cube_problem, alias="demoplan-opt")
    assert found.cost == 6
    translator = found.statistics["translator"]
    assert translator["h2_mutexes"] and translator["remove_dominated_operators"]
    assert demoplan.validate(cube_domain, cube_problem, found).valid
    # Without an alias the translation is Fast Downward's.
    plain = demoplan.plan(cube_domain, cube_problem)
    assert plain.statistics["translator"]["h2_mutexes"] is False


def test_unknown_alias_or_alias_and_search_is_an_input_error(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    with pytest.raises(demoplan.InputError, match="known aliases: seq-opt-lmcut, demoplan-opt") as caught:
        demoplan.plan(cube_domain, cube_problem, alias="seq-opt-nothing")
    assert caught.value.exit_code == 36
    with pytest.raises(demoplan.InputError, match="not both"):
        demoplan.plan(cube_domain, cube_problem, search="astar(blind())", alias="demoplan-opt")


def test_bad_pddl_raises_input_error_with_the_diagnostic(cube_domain: pathlib.Path) -> None:
    broken = "(define (problem p) (:domain cube-stacking)\n  (:objects c1 - cube)\n  (:init (on-top c9 c1))\n  (:goal (clear c1)))\n"
    with pytest.raises(demoplan.InputError) as caught:
        demoplan.plan(cube_domain, broken)
    assert caught.value.exit_code == 31
    assert "c9" in caught.value.diagnostic
    assert "<problem>" in caught.value.diagnostic


def test_bad_search_string_is_an_input_error(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    with pytest.raises(demoplan.InputError) as caught:
        demoplan.plan(cube_domain, cube_problem, search="astar(nonsense())")
    assert caught.value.exit_code == 33


def test_missing_file_is_an_input_error(tmp_path: pathlib.Path, cube_problem: pathlib.Path) -> None:
    with pytest.raises(demoplan.InputError, match="missing.pddl"):
        demoplan.plan(tmp_path / "missing.pddl", cube_problem)


def test_unsupported_pddl_raises_unsupported() -> None:
    domain = BLOCKS_DOMAIN.replace(
        "(:action put-down :parameters (?x - block)\n    :precondition (holding ?x)\n    :effect (and",
        "(:action put-down :parameters (?x - block)\n    :precondition (holding ?x)\n    :effect (and (when (handempty) (clear ?x))",
    )
    assert "when" in domain
    with pytest.raises(demoplan.Unsupported):
        demoplan.plan(domain, reverse_tower(3))


def test_unsolvable_raises_unsolvable() -> None:
    problem = reverse_tower(3).replace("(:goal (and", "(:goal (and (on b0 b1) (on b1 b0)")
    with pytest.raises(demoplan.Unsolvable):
        demoplan.plan(BLOCKS_DOMAIN, problem)


# h² proves `both` never applies (`p` is gone for good once `q` holds), which relaxed
# reachability does not see; `one-dear` is `one` at a higher cost, dominated by it.
H2_DOMAIN = """
(define (domain h) (:requirements :strips :negative-preconditions :action-costs)
  (:predicates (p) (q) (g)) (:functions (total-cost) - number)
  (:action drop-p :parameters () :precondition (p) :effect (and (not (p)) (increase (total-cost) 1)))
  (:action make-q :parameters () :precondition (not (p)) :effect (and (q) (increase (total-cost) 1)))
  (:action both :parameters () :precondition (and (p) (q)) :effect (and (g) (increase (total-cost) 1)))
  (:action one :parameters () :precondition (q) :effect (and (g) (increase (total-cost) 5)))
  (:action one-dear :parameters () :precondition (q) :effect (and (g) (increase (total-cost) 6))))
"""
H2_PROBLEM = "(define (problem h1) (:domain h) (:init (p) (= (total-cost) 0)) (:goal (g)) (:metric minimize (total-cost)))"


def test_plan_takes_the_translator_options_of_the_command_line() -> None:
    plain = demoplan.plan(H2_DOMAIN, H2_PROBLEM, search="astar(blind())")
    off = plain.statistics["translator"]
    assert off["h2_mutexes"] is False and off["remove_dominated_operators"] is False
    assert off["h2_operators_removed"] is None and off["dominated_operators_removed"] is None
    pruned = demoplan.plan(
        H2_DOMAIN, H2_PROBLEM, search="astar(blind())", h2_mutexes=True, remove_dominated_operators=True
    )
    on = pruned.statistics["translator"]
    assert on["h2_mutexes"] is True and on["remove_dominated_operators"] is True
    assert on["h2_operators_removed"] == 1, on
    assert on["dominated_operators_removed"] == 1, on
    # Both keep the optimal cost: drop-p, make-q, one.
    assert plain.cost == pruned.cost == 7
    assert pruned.steps == ["(drop-p)", "(make-q)", "(one)"]


def test_plan_honours_its_time_limit() -> None:
    # Blind search on reversing 13 blocks runs far longer than a second.
    started = time.monotonic()
    with pytest.raises(demoplan.TimeLimit):
        demoplan.plan(BLOCKS_DOMAIN, reverse_tower(13), search="astar(blind())", time_limit=1.0)
    elapsed = time.monotonic() - started
    # A limit-respect check with a loose margin (CONVENTIONS 10), not a speed test.
    assert elapsed < 1.0 + 5.0, elapsed


def test_plan_honours_its_memory_limit() -> None:
    with pytest.raises(demoplan.MemoryLimit):
        demoplan.plan(BLOCKS_DOMAIN, reverse_tower(13), search="astar(blind())", memory_limit=20 << 20)


def test_ctrl_c_stops_the_run_through_the_cancel_flag() -> None:
    # What Ctrl-C does: SIGINT's handler raises KeyboardInterrupt in the main thread,
    # which the extension sees while it waits for the planning thread. Python installs
    # that handler only if SIGINT was not ignored when it started, and a shell's
    # background job (a CI script started with `&`) starts with it ignored, where
    # interrupt_main does nothing: install it as an interactive session has it.
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, _thread.interrupt_main)
    started = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            demoplan.plan(BLOCKS_DOMAIN, reverse_tower(13), search="astar(blind())", time_limit=60.0)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    # Stopped by the flag, long before the 60 s limit (a loose bound).
    assert time.monotonic() - started < 10.0
    # The next run is not cancelled by a stale flag.
    assert demoplan.plan(BLOCKS_DOMAIN, reverse_tower(3)).cost == 6


def test_validate_rejects_an_invalid_plan_with_the_reason(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    verdict = demoplan.validate(cube_domain, cube_problem, "(take left c2 table)\n")
    assert not verdict.valid
    assert verdict.cost is None
    assert "unsatisfied precondition" in verdict.report
    assert "(Set (acted-on left c2) to true)" in verdict.report


def test_validate_rejects_an_unreadable_plan_naming_its_line(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    with pytest.raises(demoplan.InputError, match="<plan>:2"):
        demoplan.validate(cube_domain, cube_problem, "(reach left c2)\n(take left\n")
