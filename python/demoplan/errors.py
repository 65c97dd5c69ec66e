"""The exceptions demoplan raises. Each carries the Rust error's kind as its class, the
message the command line would print, and the exit code the command line would exit with
for the same failure (README, "Exit codes")."""

from __future__ import annotations

from typing import TYPE_CHECKING, List, Optional

if TYPE_CHECKING:
    from demoplan.learning import SetAside, Solved


class DemoplanError(Exception):
    """Base class of demoplan's errors.

    ``exit_code`` is the code ``demoplan`` on the command line exits with for the same
    failure; ``message`` is what it prints.
    """

    exit_code: int

    def __init__(self, message: str, exit_code: int) -> None:
        super().__init__(message)
        self.message = message
        self.exit_code = exit_code


class InputError(DemoplanError):
    """Bad input: malformed or inconsistent PDDL, a bad search string, a bad recording or
    library, a missing file. ``diagnostic`` is the full report (file, line, what is
    wrong), as the command line prints it."""

    def __init__(self, message: str, exit_code: int, diagnostic: Optional[str] = None) -> None:
        super().__init__(message, exit_code)
        self.diagnostic = diagnostic if diagnostic is not None else message


class Unsupported(DemoplanError):
    """Valid input outside what demoplan supports (exit code 34)."""


class Unsolvable(DemoplanError):
    """The task has no plan: search proved it (exit code 11)."""


class TimeLimit(DemoplanError):
    """The time limit was reached before a plan was found (exit code 23)."""


class MemoryLimit(DemoplanError):
    """The memory limit was reached before a plan was found (exit code 22)."""


class NoExecutablePlan(DemoplanError):
    """:func:`demoplan.solve` found plans, and the cube world executed none of them
    (exit code 45, not one of Fast Downward's). ``set_aside`` lists the operators set
    aside for the problem, each with the step that failed, the facts it promised and
    what the world gave; ``solved`` is the whole result, every attempt included."""

    def __init__(
        self,
        message: str,
        exit_code: int = 45,
        set_aside: "Optional[List[SetAside]]" = None,
        solved: "Optional[Solved]" = None,
    ) -> None:
        super().__init__(message, exit_code)
        self.set_aside = list(set_aside) if set_aside is not None else []
        self.solved = solved


class Cancelled(DemoplanError):
    """The run was cancelled (Ctrl-C reaches Python as KeyboardInterrupt instead; this
    is raised when the cancel flag was set by other means)."""


# Exit codes of the command line (README, "Exit codes") and the class of each.
_BY_EXIT_CODE = {
    11: Unsolvable,
    12: Unsolvable,
    22: MemoryLimit,
    23: TimeLimit,
    31: InputError,
    33: InputError,
    34: Unsupported,
    36: InputError,
    45: NoExecutablePlan,
}


def error_for_exit_code(exit_code: int, message: str) -> DemoplanError:
    """The exception for a failure the command line reports with ``exit_code``."""
    cls = _BY_EXIT_CODE.get(exit_code, DemoplanError)
    if cls is InputError:
        # The first line says what is wrong; the diagnostic adds where, with the source.
        lines = [line for line in message.splitlines() if line.strip()]
        return InputError(lines[0].strip() if lines else message, exit_code, diagnostic=message)
    return cls(message, exit_code)
