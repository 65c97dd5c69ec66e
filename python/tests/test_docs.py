"""docs/python.md's worked example runs as written, so that it cannot rot."""

from __future__ import annotations

import re

from conftest import REPO


def test_worked_example_runs() -> None:
    text = (REPO / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "docs/python.md has no python example"
    namespace: dict = {}
    from unified_planning.shortcuts import get_environment

    try:
        exec(compile("\n".join(blocks), "docs/python.md", "exec"), namespace)
    finally:
        get_environment().error_used_name = True
    # The example got as far as planning with the UP engine.
    assert namespace["result"].status.name == "SOLVED_OPTIMALLY"
    assert namespace["solved"].plan_level is not None
