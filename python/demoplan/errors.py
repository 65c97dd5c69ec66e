"""The exceptions demoplan raises. Each carries the Rust error's kind as its class, the
message the command line would print, and the exit code the command line would exit with
for the same failure (README, "Exit codes")."""

from __future__ import annotations

from typing import Optional


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
}


def error_for_exit_code(exit_code: int, message: str) -> DemoplanError:
    """The exception for a failure the command line reports with ``exit_code``."""
    cls = _BY_EXIT_CODE.get(exit_code, DemoplanError)
    if cls is InputError:
        # The first line says what is wrong; the diagnostic adds where, with the source.
        lines = [line for line in message.splitlines() if line.strip()]
        return InputError(lines[0].strip() if lines else message, exit_code, diagnostic=message)
    return cls(message, exit_code)
