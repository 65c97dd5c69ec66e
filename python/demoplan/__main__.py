"""``python -m demoplan`` and the ``demoplan`` console script: the command line of the
Rust binary, run inside the extension, with its output and exit codes."""

from __future__ import annotations

import signal
import sys
from typing import List, Optional

from demoplan._demoplan import run


def main(argv: Optional[List[str]] = None) -> None:
    """Runs ``demoplan`` with ``argv`` (default: this process's arguments) and exits with
    its exit code."""
    args = sys.argv[1:] if argv is None else argv
    # Whatever Python has buffered goes out before Rust writes to the same descriptors.
    sys.stdout.flush()
    sys.stderr.flush()
    # The binary dies of Ctrl-C at once; Python's handler would only set a flag that no
    # Rust code looks at, so give SIGINT back its default action, as the binary has it.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    # "demoplan" as the program's name, so that help and errors read as the binary's.
    # A grid runs its cells as child processes of this same command: Python running the
    # package, not the interpreter's executable alone.
    sys.exit(run(["demoplan", *args], [sys.executable, "-m", "demoplan"]))


if __name__ == "__main__":
    main()
