"""The learning side: operator libraries learned from demonstrations, their domains by
priority, Algorithm 1, simulated demonstrations, and recordings as arrays.

Everything calls the library crates directly, as the command line's commands do, so
that a library learned here is the file ``demoplan learn`` writes.
"""

from __future__ import annotations

import dataclasses
import os
import pathlib
import tempfile
from typing import TYPE_CHECKING, Any, Iterable, List, Optional, Sequence

from demoplan import _demoplan
from demoplan.errors import DemoplanError, NoExecutablePlan, error_for_exit_code
from demoplan.planning import Source, _read

if TYPE_CHECKING:
    import numpy


def _count(name: str, value: int, most: int = 2**32 - 1) -> int:
    """``value`` checked as the command line's option ``name`` is: a whole number from 0
    to ``most`` (what the extension's argument holds), or InputError (exit code 36)
    saying so, where the extension would raise OverflowError or TypeError."""
    if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value <= most:
        raise error_for_exit_code(36, f"error: {name}: {value!r} is not a whole number from 0 to {most}")
    return value


@dataclasses.dataclass(frozen=True)
class Provenance:
    """One demonstrated segment behind an operator."""

    recording: str
    hash: str
    participant: str
    hand: str
    start: float
    end: float


@dataclasses.dataclass(frozen=True)
class Operator:
    """A learned operator: its name by rank (``put``, ``put2``, ...), its activity, how
    many segments showed it, its cost ``ceil(lambda * (1 - count / type_count))``, and
    the segments behind it."""

    name: str
    activity: str
    count: int
    cost: int
    provenance: List[Provenance]


@dataclasses.dataclass(frozen=True)
class Level:
    """One level of Algorithm 1: a priority and the operators of its domain."""

    prio: int
    operators: List[str]


class Library:
    """An operator library: create one (``Library()``), load one (:meth:`load`), learn
    from recordings (:meth:`learn`), list its operators, write domains by priority."""

    def __init__(self, lambda_: int = 100) -> None:
        self._inner = _demoplan._Library(lambda_)

    @classmethod
    def load(cls, path: "os.PathLike[str] | str") -> "Library":
        """The library file at ``path``; a damaged or newer one raises InputError naming
        its line."""
        file = pathlib.Path(path)
        try:
            text = file.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as e:
            raise error_for_exit_code(36, f"error: cannot read library {file}: {e}") from None
        return cls.from_json(text, str(file))

    @classmethod
    def from_json(cls, text: str, name: str = "<library>") -> "Library":
        """The library of a library file's text."""
        library = cls.__new__(cls)
        library._inner = _demoplan._Library.from_json(text, name)
        return library

    def to_json(self) -> str:
        """The library file's text (deterministic)."""
        return self._inner.to_json()

    def save(self, path: "os.PathLike[str] | str") -> None:
        """Writes the library file to ``path``, replacing it whole (never half-written)."""
        target = pathlib.Path(path)
        with tempfile.NamedTemporaryFile("w", dir=target.parent, prefix=f".{target.name}.", delete=False, encoding="utf-8") as out:
            out.write(self.to_json())
        os.replace(out.name, target)

    def learn(
        self,
        recordings: Iterable["os.PathLike[str] | str"],
        mapping: Optional["os.PathLike[str] | str"] = None,
        generalise: bool = False,
    ) -> str:
        """Adds the recordings' activities to the library (those it has already counted
        are skipped, by content hash), as ``demoplan learn`` does; returns its log.
        ``generalise=True`` is ``demoplan learn --generalise``: an empty library becomes
        one of generalised operators (docs/operators.md); a library of specific
        operators refuses it (a DemoplanError with exit code 36)."""
        files = [os.fspath(r) for r in recordings]
        if not files:
            raise DemoplanError("learn: no recordings given", 36)
        with tempfile.TemporaryDirectory() as folder:
            self._inner, log = _demoplan.learn(
                self._inner,
                files,
                folder,
                None if mapping is None else os.fspath(mapping),
                generalise,
            )
        return log

    @property
    def lambda_(self) -> int:
        """The largest action cost (the paper's lambda)."""
        return self._inner.lambda_

    @property
    def segments(self) -> int:
        """How many segments the library has counted."""
        return self._inner.segments

    @property
    def recordings(self) -> List[str]:
        """The ids of the recordings learned from."""
        return self._inner.recordings

    def operators(self) -> List[Operator]:
        """Every operator, ranked as ``demoplan operators`` lists them."""
        return [
            Operator(name, activity, count, cost, [Provenance(*p) for p in provenance])
            for name, activity, count, cost, provenance in self._inner.operators()
        ]

    def cards(self) -> str:
        """``demoplan operators``' text: one card per operator."""
        return self._inner.cards()

    def levels(self, keep_without_effects: bool = False) -> List[Level]:
        """The distinct levels of Algorithm 1, priority 1 up to the full domain."""
        return [Level(prio, names) for prio, names in self._inner.levels(keep_without_effects)]

    def domain(self, prio: int, keep_without_effects: bool = False) -> str:
        """The PDDL domain of the most frequent ``prio`` operators of each type, as
        ``demoplan domain --prio`` writes it."""
        return self._inner.domain(prio, keep_without_effects)


@dataclasses.dataclass(frozen=True)
class LevelResult:
    """One planning run of :func:`solve`: its priority, its number of operators (without
    those set aside), how its run ended (``solved``, ``unsolvable``,
    ``relaxed-unreachable``, ``limit``, ``memory``), the plan and its cost when solved,
    expansions and seconds, and what executing the plan in the cube world gave:
    ``executed``, ``step-failed`` (an operator was set aside and the level searched
    again), ``goal-not-reached`` (the loop widened), or ``None`` (no plan, or
    ``execute=False``)."""

    prio: int
    operators: int
    outcome: str
    plan: Optional[str]
    cost: Optional[int]
    expansions: Optional[int]
    seconds: float
    execution: Optional[str] = None


@dataclasses.dataclass(frozen=True)
class SetAside:
    """An operator :func:`solve` set aside for the problem: its name and id, the level
    and the step (1-based) of the plan that failed, the step as a plan line, the facts
    it promised that the world did not give (``(not ...)`` for a delete), the grounded
    facts over the step's objects, and the whole reason in ``demoplan execute``'s words."""

    name: str
    id: str
    prio: int
    step: int
    action: str
    promised: List[str]
    found: List[str]
    why: str


@dataclasses.dataclass(frozen=True)
class Solved:
    """The result of Algorithm 1 with execution in the loop: every planning run (a level
    searched again after an operator was set aside appears again), the cumulative time
    over all of them (failed ones and executions included), the operators set aside, the
    seconds spent executing plans, and the run that gave the plan, if any."""

    levels: List[LevelResult]
    cumulative_seconds: float
    set_aside: List[SetAside] = dataclasses.field(default_factory=list)
    execution_seconds: float = 0.0

    @property
    def plan_level(self) -> Optional[LevelResult]:
        """The run whose plan is the answer: the last, when it is solved and its plan
        executed (or was not executed)."""
        last = self.levels[-1] if self.levels else None
        if last is not None and last.outcome == "solved" and last.execution in (None, "executed"):
            return last
        return None

    @property
    def replans(self) -> int:
        """Plans that failed execution, each followed by another search."""
        return sum(1 for level in self.levels if level.execution in ("step-failed", "goal-not-reached"))


def solve(
    library: Library,
    problem: Source,
    search: str = "astar(lmcut())",
    time_limit: Optional[float] = None,
    memory_limit: Optional[int] = None,
    keep_without_effects: bool = False,
    execute: bool = True,
) -> Solved:
    """The paper's Algorithm 1 with execution in the loop (``demoplan solve``): plans
    ``problem`` (PDDL text or a path) on the library's levels, priority 1 upwards, until
    one gives a plan, and executes each plan in the cube world; an operator whose step
    fails is set aside and the level searched again (docs/execution.md). Raises
    :class:`~demoplan.errors.NoExecutablePlan` when plans were found and none executes,
    and :class:`~demoplan.errors.InputError` for a scene the cube world cannot lay out.
    ``execute=False`` is Algorithm 1 alone (``--no-execute``). The limits are per
    planning run. The GIL is released."""
    text, name = _read(problem, "problem")
    rows, cumulative, aside, execution_seconds, none = _demoplan.solve(
        library._inner,
        text,
        name,
        search,
        keep_without_effects,
        time_limit,
        memory_limit,
        execute,
    )
    solved = Solved(
        [LevelResult(*row) for row in rows],
        cumulative,
        [SetAside(*a) for a in aside],
        execution_seconds,
    )
    if none is not None:
        raise NoExecutablePlan(none.rstrip(), 45, solved.set_aside, solved)
    return solved


def simulate(
    out: "os.PathLike[str] | str",
    participants: int = 3,
    per_participant: int = 4,
    seed: int = 7,
    cubes: Optional[int] = None,
) -> List[pathlib.Path]:
    """Simulated demonstrations of people stacking cubes (``demoplan simulate``): writes
    the recordings, their ground truth and ``simulation.json`` to ``out``; returns the
    recordings' paths."""
    folder = pathlib.Path(out)
    names = _demoplan.simulate(
        os.fspath(folder),
        _count("participants", participants),
        _count("per_participant", per_participant),
        _count("seed", seed, 2**64 - 1),
        None if cubes is None else _count("cubes", cubes),
    )
    return [folder / name for name in names]


class Recording:
    """A recording in demoplan's format, read whole: its entities, frame times and the
    pose of every entity in every frame."""

    def __init__(self, path: "os.PathLike[str] | str") -> None:
        self.path = pathlib.Path(path)
        self.entities, self.times, self._poses = _demoplan.read_poses(str(self.path))

    def to_numpy(self) -> "numpy.ndarray[Any, Any]":
        """The poses as an array of frames x entities x 7 (x, y, z in metres, then the
        quaternion qx, qy, qz, qw), float32, NaN where an entity was not observed. A fixed
        entity (the table) has its fixed pose in every frame. Needs numpy."""
        try:
            import numpy
        except ImportError:
            raise ImportError(
                "Recording.to_numpy needs numpy, which is not installed: pip install numpy"
            ) from None
        array = numpy.array(self._poses, dtype=numpy.float32)
        return array.reshape(len(self.times), len(self.entities), 7)


def tower_problem(
    tower: Optional[Sequence[str]] = None,
    paper_goal: Optional[int] = None,
    cubes: Optional[int] = None,
    hands: Optional[int] = None,
) -> str:
    """A tower problem for learned domains (``demoplan problem``) as PDDL text: the cubes
    of ``tower`` stacked bottom first (e.g. ``["cube_1", "cube_2", "cube_3"]``), or the paper's goal
    ``paper_goal`` (1-5), on a table of ``cubes`` cubes with ``hands`` hands."""
    return _demoplan.tower_problem(
        None if tower is None else ",".join(tower),
        None if paper_goal is None else _count("paper_goal", paper_goal, 2**64 - 1),
        None if cubes is None else _count("cubes", cubes, 2**64 - 1),
        None if hands is None else _count("hands", hands, 2**64 - 1),
    )
