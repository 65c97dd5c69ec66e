"""The Unified Planning engine ``demoplan``: a OneshotPlanner and a PlanValidator.

Planning runs ``python -m demoplan plan ...`` as a child process (UP's ``PDDLPlanner``
writes the problem with ``PDDLWriter``), so that UP's timeout, a memory blow-up or a crash
never takes down the user's interpreter. Statuses follow up-fast-downward 1.0.0: the exit
code maps as in :data:`STATUS_BY_EXIT_CODE`, and a solved problem is
``SOLVED_OPTIMALLY`` when it has a quality metric, ``SOLVED_SATISFICING`` when it has
none. The supported kind is exactly the PDDL fragment demoplan plans on.

``import demoplan`` registers the engine with UP's default environment when
``unified-planning`` is installed; :func:`register` registers it with another one.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from typing import Any, Callable, Dict, List, Optional

import unified_planning as up
from unified_planning.engines import (
    Credits,
    FailedValidationReason,
    LogLevel,
    LogMessage,
    PlanGenerationResultStatus,
    ValidationResult,
    ValidationResultStatus,
)
from unified_planning.engines.mixins import PlanValidatorMixin
from unified_planning.engines.pddl_planner import PDDLPlanner
from unified_planning.io import PDDLWriter
from unified_planning.model import ProblemKind

#: The search demoplan runs unless the engine is given ``search=...``: A* with LM-cut,
#: optimal for the action costs.
DEFAULT_SEARCH = "astar(lmcut())"

_S = PlanGenerationResultStatus

#: The command line's exit code to UP's status, as up-fast-downward 1.0.0 maps Fast
#: Downward's (codes 0-3 are solved and handled apart). Any other code is
#: ``INTERNAL_ERROR``.
STATUS_BY_EXIT_CODE: Dict[int, PlanGenerationResultStatus] = {
    10: _S.UNSOLVABLE_PROVEN,
    11: _S.UNSOLVABLE_PROVEN,
    12: _S.UNSOLVABLE_INCOMPLETELY,
    13: _S.UNSOLVABLE_INCOMPLETELY,
    20: _S.MEMOUT,
    22: _S.MEMOUT,
    24: _S.MEMOUT,
    21: _S.TIMEOUT,
    23: _S.TIMEOUT,
    34: _S.UNSUPPORTED_PROBLEM,
}

_CREDITS = Credits(
    name="demoplan",
    author="demoplan developers",
    contact="https://example.invalid/demoplan",
    website="https://example.invalid/demoplan",
    license="MIT OR Apache-2.0",
    short_description="Optimal A* planning (LM-cut, pattern databases) on domains learned from demonstrations.",
    long_description="demoplan's planner: Fast Downward's translation and optimal A* search, reimplemented in Rust.",
)


def _demoplan_command() -> List[str]:
    """The command line that runs demoplan in a child process: this interpreter with the
    installed package, so that the child is the same demoplan the caller imported."""
    return [sys.executable, "-m", "demoplan"]


class DemoplanEngine(PDDLPlanner, PlanValidatorMixin):  # type: ignore[misc]
    """UP engine ``demoplan``. Options (``OneshotPlanner(name="demoplan", params=...)``):
    ``search``, a demoplan search string (default :data:`DEFAULT_SEARCH`), and
    ``memory_limit``, e.g. ``"2G"`` (default none)."""

    def __init__(self, search: str = DEFAULT_SEARCH, memory_limit: Optional[str] = None) -> None:
        PDDLPlanner.__init__(self, needs_requirements=True)
        PlanValidatorMixin.__init__(self)
        self._search = search
        self._memory_limit = memory_limit
        self._timeout: Optional[float] = None

    @property
    def name(self) -> str:
        return "demoplan"

    @staticmethod
    def get_credits(**kwargs: Any) -> Optional[Credits]:
        return _CREDITS

    @staticmethod
    def supported_kind() -> ProblemKind:
        kind = ProblemKind(version=2)
        kind.set_problem_class("ACTION_BASED")
        kind.set_typing("FLAT_TYPING")
        kind.set_typing("HIERARCHICAL_TYPING")
        kind.set_conditions_kind("NEGATIVE_CONDITIONS")
        kind.set_conditions_kind("EQUALITIES")
        kind.set_quality_metrics("ACTIONS_COST")
        kind.set_actions_cost_kind("INT_NUMBERS_IN_ACTIONS_COST")
        kind.set_actions_cost_kind("STATIC_FLUENTS_IN_ACTIONS_COST")
        kind.set_quality_metrics("PLAN_LENGTH")
        return kind

    @staticmethod
    def supports(problem_kind: ProblemKind) -> bool:
        return bool(problem_kind <= DemoplanEngine.supported_kind())

    @staticmethod
    def supports_plan(plan_kind: "up.plans.PlanKind") -> bool:
        return bool(plan_kind == up.plans.PlanKind.SEQUENTIAL_PLAN)

    @staticmethod
    def satisfies(optimality_guarantee: "up.engines.OptimalityGuarantee") -> bool:
        # A* with an admissible heuristic: every plan it returns is optimal.
        return True

    def _solve(
        self,
        problem: "up.model.AbstractProblem",
        heuristic: Optional[Callable[["up.model.state.State"], Optional[float]]] = None,
        timeout: Optional[float] = None,
        output_stream: Any = None,
    ) -> "up.engines.results.PlanGenerationResult":
        # The child gets the timeout as its own time limit, so that it stops itself with
        # exit 23 and a clean TIMEOUT; PDDLPlanner's kill at the same timeout stays the
        # safety net.
        self._timeout = timeout
        return PDDLPlanner._solve(self, problem, heuristic, timeout, output_stream)

    def _get_cmd(self, domain_filename: str, problem_filename: str, plan_filename: str) -> List[str]:
        cmd = _demoplan_command() + [
            "plan",
            domain_filename,
            problem_filename,
            "--search",
            self._search,
            "--plan-file",
            plan_filename,
        ]
        if self._timeout is not None:
            cmd += ["--overall-time-limit", f"{max(self._timeout, 0.0)}s"]
        if self._memory_limit is not None:
            cmd += ["--overall-memory-limit", self._memory_limit]
        return cmd

    def _result_status(
        self,
        problem: "up.model.Problem",
        plan: Optional["up.plans.Plan"],
        retval: int,
        log_messages: Optional[List[LogMessage]] = None,
    ) -> PlanGenerationResultStatus:
        if retval in (0, 1, 2, 3):
            if plan is None:
                # Solved without a plan file: not a result anyone can use.
                return _S.INTERNAL_ERROR
            if problem.quality_metrics:
                return _S.SOLVED_OPTIMALLY
            return _S.SOLVED_SATISFICING
        return STATUS_BY_EXIT_CODE.get(retval, _S.INTERNAL_ERROR)

    def _validate(self, problem: "up.model.AbstractProblem", plan: "up.plans.Plan") -> ValidationResult:
        assert isinstance(problem, up.model.Problem)
        writer = PDDLWriter(problem, needs_requirements=True)
        with tempfile.TemporaryDirectory() as folder:
            domain = os.path.join(folder, "domain.pddl")
            problem_file = os.path.join(folder, "problem.pddl")
            plan_file = os.path.join(folder, "plan.txt")
            writer.write_domain(domain)
            writer.write_problem(problem_file)
            writer.write_plan(plan, plan_file)
            done = subprocess.run(
                _demoplan_command() + ["validate", domain, problem_file, plan_file],
                capture_output=True,
                text=True,
                check=False,
            )
        logs = [LogMessage(LogLevel.INFO, done.stdout)]
        if done.stderr:
            logs.append(LogMessage(LogLevel.ERROR, done.stderr))
        if done.returncode == 0 and "Plan valid" in done.stdout:
            return ValidationResult(ValidationResultStatus.VALID, self.name, logs)
        if done.returncode != 1:
            # Not a verdict on the plan: the files could not be read or checked.
            return ValidationResult(ValidationResultStatus.UNKNOWN, self.name, logs)
        reason: Optional[FailedValidationReason] = None
        inapplicable = None
        if "Goal not satisfied" in done.stdout:
            reason = FailedValidationReason.UNSATISFIED_GOALS
        failed_step = re.search(r"at time (\d+)", done.stdout)
        if "Plan failed to execute" in done.stdout:
            reason = FailedValidationReason.INAPPLICABLE_ACTION
            if failed_step is not None:
                index = int(failed_step.group(1)) - 1
                actions = plan.actions
                if 0 <= index < len(actions):
                    inapplicable = actions[index]
        return ValidationResult(
            ValidationResultStatus.INVALID,
            self.name,
            logs,
            reason=reason,
            inapplicable_action=inapplicable,
        )


def register(environment: Optional["up.environment.Environment"] = None) -> None:
    """Registers the engine as ``demoplan`` with ``environment`` (default: UP's global
    environment). Registering twice is harmless."""
    env = environment if environment is not None else up.environment.get_environment()
    if "demoplan" not in env.factory.engines:
        env.factory.add_engine("demoplan", __name__, "DemoplanEngine")
