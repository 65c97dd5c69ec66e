"""The planner in-process: :func:`plan` and :func:`validate`, on PDDL texts or files."""

from __future__ import annotations

import dataclasses
import json
import os
import pathlib
from typing import Any, Dict, List, Optional, Tuple, Union

from demoplan import _demoplan
from demoplan.errors import Cancelled, DemoplanError, MemoryLimit, TimeLimit, Unsolvable

#: PDDL text, or the path of a PDDL file.
Source = Union[str, "os.PathLike[str]"]


@dataclasses.dataclass(frozen=True)
class Plan:
    """A plan found by :func:`plan`: its steps as PDDL actions (``"(take left c2 table)"``),
    its cost, and the run's statistics (the record ``demoplan plan --stats-json`` writes:
    ``expanded``, ``generated``, ``search_time``, ``total_time``, ...)."""

    steps: List[str]
    cost: int
    statistics: Dict[str, Any]

    def text(self) -> str:
        """The plan as a plan file: one action a line, then ``; cost = N``."""
        return "".join(f"{s}\n" for s in self.steps) + f"; cost = {self.cost}\n"


@dataclasses.dataclass(frozen=True)
class Validation:
    """The verdict of :func:`validate`: whether the plan is valid, VAL's report (on an
    invalid plan: the failing step and the unsatisfied precondition, or the goals not
    reached), and the plan's cost when valid."""

    valid: bool
    report: str
    cost: Optional[int]


def _read(source: Source, what: str) -> Tuple[str, str]:
    """The text of ``source`` and the name diagnostics give it: PDDL text is anything
    with a parenthesis in it, anything else is a path."""
    if isinstance(source, str) and "(" in source:
        return source, f"<{what}>"
    path = pathlib.Path(source)
    try:
        return path.read_text(encoding="utf-8"), str(path)
    except OSError as e:
        from demoplan.errors import InputError

        raise InputError(f"error: cannot read {what} {path}: {e.strerror}", 36) from None
    except UnicodeDecodeError as e:
        from demoplan.errors import InputError

        raise InputError(f"error: {path}: not UTF-8 text ({e.reason} at byte {e.start})", 31) from None


def plan(
    domain: Source,
    problem: Source,
    search: Optional[str] = None,
    time_limit: Optional[float] = None,
    memory_limit: Optional[int] = None,
    alias: Optional[str] = None,
    *,
    h2_mutexes: bool = False,
    remove_dominated_operators: bool = False,
) -> Plan:
    """Plans ``problem`` in ``domain`` with demoplan's planner, in this process.

    ``domain`` and ``problem`` are PDDL texts or paths. ``search`` is a search string as
    ``demoplan plan --search`` takes it, or ``alias`` names a configuration as ``demoplan
    plan --alias`` does (``"demoplan-opt"``: its search and its translator options); not
    both. With neither, ``astar(lmcut())``. ``time_limit`` (seconds) covers translation,
    heuristic construction and search; ``memory_limit`` (bytes) is on the Rust heap the
    run allocates, on top of what the process held at its start (the counting
    allocator reads Rust allocations only, not Python objects).

    ``h2_mutexes`` and ``remove_dominated_operators`` are the translator options of
    ``demoplan plan --h2-mutexes --remove-dominated-operators``: h² removes what it
    proves unreachable, the second removes every operator another dominates; both keep
    the optimal cost. Off by default, so the translation is Fast Downward's; beside an
    alias they are switched on in addition to the alias's own. What they removed is in
    the statistics (``statistics["translator"]``).

    The GIL is released while planning. Ctrl-C stops the run through its cancel flag
    and raises KeyboardInterrupt.

    Raises :class:`~demoplan.InputError` (bad PDDL or search string, with the
    diagnostic; an unknown alias, or both a search and an alias, with exit code 36),
    :class:`~demoplan.Unsupported`, :class:`~demoplan.Unsolvable`,
    :class:`~demoplan.TimeLimit` or :class:`~demoplan.MemoryLimit`.
    """
    domain_text, domain_name = _read(domain, "domain")
    problem_text, problem_name = _read(problem, "problem")
    outcome, plan_text, cost, statistics = _demoplan.plan(
        domain_text,
        domain_name,
        problem_text,
        problem_name,
        search,
        alias,
        time_limit,
        memory_limit,
        h2_mutexes,
        remove_dominated_operators,
    )
    stats: Dict[str, Any] = json.loads(statistics)
    if outcome == "solved" and plan_text is not None and cost is not None:
        steps = [line.strip() for line in plan_text.splitlines() if line.startswith("(")]
        return Plan(steps=steps, cost=cost, statistics=stats)
    if outcome in ("unsolvable", "relaxed-unreachable"):
        raise Unsolvable(f"{problem_name}: the task has no plan", 11)
    if outcome == "limit":
        raise TimeLimit(f"{problem_name}: time limit of {time_limit} s reached", 23)
    if outcome == "memory":
        raise MemoryLimit(f"{problem_name}: memory limit of {memory_limit} bytes reached", 22)
    if outcome == "cancelled":
        raise Cancelled(f"{problem_name}: the run was cancelled", 32)
    raise DemoplanError(f"{problem_name}: unexpected outcome {outcome!r}", 32)


def validate(domain: Source, problem: Source, plan: Union[Source, Plan]) -> Validation:
    """Validates ``plan`` (a :class:`Plan`, plan text or a plan file) for ``problem`` in
    ``domain`` with demoplan's independent validator. An invalid plan is a result, not
    an error; bad PDDL or an unreadable plan raises :class:`~demoplan.InputError`."""
    domain_text, domain_name = _read(domain, "domain")
    problem_text, problem_name = _read(problem, "problem")
    if isinstance(plan, Plan):
        plan_text, plan_name = plan.text(), "<plan>"
    else:
        plan_text, plan_name = _read(plan, "plan")
    valid, report, cost = _demoplan.validate(domain_text, domain_name, problem_text, problem_name, plan_text, plan_name)
    return Validation(valid=valid, report=report, cost=cost)
