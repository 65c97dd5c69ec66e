"""The Unified Planning engine `demoplan`, on problems built in Python and read from PDDL."""

from __future__ import annotations

import pathlib
import warnings

import pytest
import unified_planning.engines as upe
from unified_planning.exceptions import UPNoSuitableEngineAvailableException, UPUsageError
from unified_planning.engines import PlanGenerationResultStatus as Status
from unified_planning.io import PDDLReader
from unified_planning.model import Fluent, InstantaneousAction, Object, Problem
from unified_planning.plans import ActionInstance, SequentialPlan
from unified_planning.shortcuts import BoolType, OneshotPlanner, PlanValidator, UserType, get_environment

import demoplan  # noqa: F401  (registers the engine)
import demoplan.up
from demoplan.up import DemoplanEngine
from up_problems import blocks, cube_tower


def cost_of(plan: SequentialPlan) -> int:
    return len(plan.actions)


def test_import_registers_the_engine() -> None:
    assert "demoplan" in get_environment().factory.engines


def test_sussman_anomaly_is_solved_optimally() -> None:
    problem = blocks([["a", "c"], ["b"]], [["c", "b", "a"]])
    with OneshotPlanner(name="demoplan") as planner:
        result = planner.solve(problem)
    assert result.status == Status.SOLVED_OPTIMALLY
    assert result.engine_name == "demoplan"
    # Unstack c, put it down, then build the tower from the bottom: 6 steps, no fewer.
    assert cost_of(result.plan) == 6
    with PlanValidator(name="sequential_plan_validator") as validator:
        assert validator.validate(problem, result.plan).status == upe.ValidationResultStatus.VALID


def test_reversing_a_tower_of_four_takes_eight_steps() -> None:
    # Every block moves (two actions each), and the top one must be put down first.
    problem = blocks([["d", "c", "b", "a"]], [["a", "b", "c", "d"]])
    with OneshotPlanner(name="demoplan") as planner:
        result = planner.solve(problem)
    assert result.status == Status.SOLVED_OPTIMALLY
    assert cost_of(result.plan) == 8


def test_cube_domain_built_in_python_has_the_known_optimal_cost() -> None:
    problem, _ = cube_tower(["c1", "c2", "c3"])
    with OneshotPlanner(name="demoplan") as planner:
        result = planner.solve(problem)
    assert result.status == Status.SOLVED_OPTIMALLY
    # Reach, take and stack for each of c2 and c3, every action costing 1.
    assert len(result.plan.actions) == 6
    names = [a.action.name for a in result.plan.actions]
    assert sorted(names) == ["reach", "reach", "stack", "stack", "take", "take"]
    with PlanValidator(name="demoplan") as validator:
        assert validator.validate(problem, result.plan).status == upe.ValidationResultStatus.VALID


def test_problem_read_from_pddl(cube_domain: pathlib.Path, cube_problem: pathlib.Path) -> None:
    # The example names its table object after its type, which UP forbids unless
    # told otherwise.
    env = get_environment()
    env.error_used_name = False
    try:
        problem = PDDLReader(env).parse_problem(str(cube_domain), str(cube_problem))
        with OneshotPlanner(name="demoplan") as planner:
            result = planner.solve(problem)
    finally:
        env.error_used_name = True
    assert result.status == Status.SOLVED_OPTIMALLY
    assert len(result.plan.actions) == 6


def test_without_a_metric_the_status_is_satisficing() -> None:
    problem = blocks([["a", "c"], ["b"]], [["c", "b", "a"]])
    problem.clear_quality_metrics()
    with OneshotPlanner(name="demoplan") as planner:
        result = planner.solve(problem)
    assert result.status == Status.SOLVED_SATISFICING
    assert cost_of(result.plan) == 6


def test_unsolvable_problem_is_proven_unsolvable() -> None:
    # a on b and b on a at once: no state has both.
    problem = blocks([["a"], ["b"]], [["a", "b"], ["b", "a"]])
    with OneshotPlanner(name="demoplan") as planner:
        result = planner.solve(problem)
    assert result.status == Status.UNSOLVABLE_PROVEN
    assert result.plan is None


def test_timeout_gives_the_timeout_status() -> None:
    # Blind search on reversing a tower of 13 blocks: far more than a second of work.
    order = [f"b{i}" for i in range(13)]
    problem = blocks([order], [list(reversed(order))])
    with OneshotPlanner(name="demoplan", params={"search": "astar(blind())"}) as planner:
        result = planner.solve(problem, timeout=1.0)
    assert result.status == Status.TIMEOUT
    assert result.plan is None



def test_memory_limit_gives_the_memout_status() -> None:
    # The same blind search under a 64 MB memory limit and a long timeout: its state
    # registry outgrows the limit long before the minute is up, and the child process
    # stops itself (exit 22), which UP sees as MEMOUT.
    order = [f"b{i}" for i in range(13)]
    problem = blocks([order], [list(reversed(order))])
    params = {"search": "astar(blind())", "memory_limit": "64M"}
    with OneshotPlanner(name="demoplan", params=params) as planner:
        result = planner.solve(problem, timeout=60.0)
    assert result.status == Status.MEMOUT
    assert result.plan is None

def conditional_problem() -> Problem:
    thing = UserType("thing")
    lit = Fluent("lit", BoolType(), t=thing)
    powered = Fluent("powered", BoolType())
    switch = InstantaneousAction("switch", t=thing)
    t = switch.parameter("t")
    switch.add_effect(lit(t), True, condition=powered())
    problem = Problem("conditional")
    problem.add_fluent(lit, default_initial_value=False)
    problem.add_fluent(powered, default_initial_value=True)
    problem.add_action(switch)
    lamp = Object("lamp", thing)
    problem.add_object(lamp)
    problem.add_goal(lit(lamp))
    return problem


def test_conditional_effects_are_refused_by_default() -> None:
    problem = conditional_problem()
    assert not DemoplanEngine.supports(problem.kind)
    # Chosen by kind, UP never picks the engine for the problem...
    with pytest.raises(UPNoSuitableEngineAvailableException):
        OneshotPlanner(problem_kind=problem.kind, optimality_guarantee="SOLVED_OPTIMALLY")
    # ...an engine made directly refuses it (UP's error_on_failed_checks)...
    with pytest.raises(UPUsageError, match="cannot establish whether demoplan can solve this problem"):
        DemoplanEngine().solve(problem)
    # ...and one asked for by name warns before it tries.
    with OneshotPlanner(name="demoplan") as planner:
        with pytest.warns(UserWarning, match="cannot establish whether demoplan can solve this problem"):
            result = planner.solve(problem)
    assert result.status == Status.UNSUPPORTED_PROBLEM


def test_conditional_effects_with_checks_off_are_unsupported() -> None:
    problem = conditional_problem()
    with OneshotPlanner(name="demoplan") as planner:
        planner.skip_checks = True
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = planner.solve(problem)
    assert result.status == Status.UNSUPPORTED_PROBLEM
    assert result.plan is None


def test_validator_rejects_an_invalid_plan_with_the_reason() -> None:
    problem, actions = cube_tower(["c1", "c2"])
    objects = {o.name: o for o in problem.all_objects}
    # Taking c2 without reaching for it first: the precondition (acted-on left c2) fails.
    bad = SequentialPlan([ActionInstance(actions["take"], (objects["left"], objects["c2"], objects["the-table"]))])
    with PlanValidator(name="demoplan") as validator:
        result = validator.validate(problem, bad)
    assert result.status == upe.ValidationResultStatus.INVALID
    assert result.reason == upe.FailedValidationReason.INAPPLICABLE_ACTION
    assert result.inapplicable_action is not None
    assert result.inapplicable_action.action.name == "take"
    log = "".join(m.message for m in result.log_messages or [])
    assert "unsatisfied precondition" in log
    assert "acted-on left c2" in log


def test_validator_names_unsatisfied_goals() -> None:
    problem, actions = cube_tower(["c1", "c2"])
    objects = {o.name: o for o in problem.all_objects}
    short = SequentialPlan([ActionInstance(actions["reach"], (objects["left"], objects["c2"]))])
    with PlanValidator(name="demoplan") as validator:
        result = validator.validate(problem, short)
    assert result.status == upe.ValidationResultStatus.INVALID
    assert result.reason == upe.FailedValidationReason.UNSATISFIED_GOALS
    assert "on-top c2 c1" in "".join(m.message for m in result.log_messages or [])
