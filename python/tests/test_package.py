"""The package itself: what `import demoplan` loads, its version, its errors."""

from __future__ import annotations

import subprocess
import sys

import demoplan


def python(code: str) -> str:
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return done.stdout.strip()


def test_import_needs_neither_numpy_nor_matplotlib_nor_up() -> None:
    loaded = python(
        "import sys, demoplan; "
        "print(sorted(m for m in ('numpy', 'matplotlib', 'unified_planning') if m in sys.modules))"
    )
    assert loaded == "[]"


def test_engine_is_registered_whichever_is_imported_first() -> None:
    check = "print('demoplan' in get_environment().factory.engines)"
    assert python(f"import demoplan\nfrom unified_planning.shortcuts import get_environment\n{check}") == "True"
    assert python(f"from unified_planning.shortcuts import get_environment\nimport demoplan\n{check}") == "True"


def test_version_is_set() -> None:
    parts = demoplan.__version__.split(".")
    assert len(parts) == 3 and all(p.isdigit() for p in parts)


def test_errors_carry_their_kind_and_exit_code() -> None:
    from demoplan.errors import error_for_exit_code

    cases = {
        11: demoplan.Unsolvable,
        22: demoplan.MemoryLimit,
        23: demoplan.TimeLimit,
        31: demoplan.InputError,
        33: demoplan.InputError,
        34: demoplan.Unsupported,
        36: demoplan.InputError,
        45: demoplan.NoExecutablePlan,
    }
    for code, cls in cases.items():
        error = error_for_exit_code(code, "error: what is wrong\n  --> where\n")
        assert type(error) is cls
        assert error.exit_code == code
        assert isinstance(error, demoplan.DemoplanError)
    diagnosed = error_for_exit_code(31, "error: what is wrong\n  --> where\n")
    assert isinstance(diagnosed, demoplan.InputError)
    assert str(diagnosed) == "error: what is wrong"
    assert "--> where" in diagnosed.diagnostic
