"""demoplan: planning domains learned from human demonstrations, and an optimal planner.

``import demoplan`` needs neither numpy nor matplotlib. When ``unified-planning`` is
installed, it registers the Unified Planning engine ``demoplan`` (:mod:`demoplan.up`)
with UP's default environment.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import importlib.util
import sys
import types
from typing import Optional, Sequence, Union

from demoplan._demoplan import __version__
from demoplan.errors import (
    Cancelled,
    DemoplanError,
    InputError,
    MemoryLimit,
    NoExecutablePlan,
    TimeLimit,
    Unsolvable,
    Unsupported,
)
from demoplan.learning import (
    Level,
    LevelResult,
    Library,
    Operator,
    Provenance,
    Recording,
    SetAside,
    Solved,
    simulate,
    solve,
    tower_problem,
)
from demoplan.planning import Plan, Validation, plan, validate

__all__ = [
    "__version__",
    "Level",
    "LevelResult",
    "Library",
    "Operator",
    "Provenance",
    "Recording",
    "SetAside",
    "Solved",
    "simulate",
    "solve",
    "tower_problem",
    "Plan",
    "Validation",
    "plan",
    "validate",
    "Cancelled",
    "DemoplanError",
    "InputError",
    "MemoryLimit",
    "NoExecutablePlan",
    "TimeLimit",
    "Unsolvable",
    "Unsupported",
]


def _register_up_engine() -> None:
    """Registers the UP engine with UP's default environment, now if UP is imported,
    else as soon as it is. ``import demoplan`` itself never imports UP (a second or
    more), so that the command line and the engine's child processes start quickly."""
    if "unified_planning" in sys.modules:
        from demoplan import up

        up.register()
    elif importlib.util.find_spec("unified_planning") is not None:
        sys.meta_path.insert(0, _RegisterWithUP())


class _RegisterWithUP(importlib.abc.MetaPathFinder):
    """Finds nothing itself: on the import of ``unified_planning`` it takes the spec the
    other finders give and registers the engine once the package has loaded."""

    def find_spec(
        self,
        fullname: str,
        path: Optional[Sequence[Union[bytes, str]]],
        target: Optional[types.ModuleType] = None,
    ) -> Optional[importlib.machinery.ModuleSpec]:
        if fullname != "unified_planning":
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec(fullname)
        if spec is None or spec.loader is None:
            return spec
        loader = spec.loader
        load = loader.exec_module

        def exec_module(module: types.ModuleType) -> None:
            load(module)
            from demoplan import up

            up.register()

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


_register_up_engine()
