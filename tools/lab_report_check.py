"""Runs Lab's AbsoluteReport over a demoplan grid's eval/properties (argv[1] is the
grid's -o DIR) and checks the report: every run is listed under its domain, with its
coverage, cost (solved runs) and expansions as the properties have them (an attribute
that an algorithm never reports, as SymK's expansions, shows nothing). Called by
tools/lab-report-check, in a venv with Lab installed."""

import json
import pathlib
import sys

from downward.reports.absolute import AbsoluteReport

ATTRIBUTES = ["coverage", "cost", "expansions"]


def cell(text: str) -> str:
    """A txt2tags table cell's value: Lab marks the best with ** and quotes with ""."""
    return text.strip().replace("**", "").replace('""', "").strip()


def tables(report: str) -> dict:
    """(attribute, domain) -> {(problem, algorithm): value} from the report's per-domain
    tables: a section `\t\tDOMAIN` whose table heads `|| ATTRIBUTE | ALG... |`."""
    found = {}
    domain = None
    header = None
    for line in report.splitlines():
        if line.startswith("\t\t") and not line.strip().startswith("="):
            domain = line.strip()
            header = None
        elif line.startswith("\t") and not line.startswith("\t\t"):
            domain = None
        elif domain and line.strip().startswith("||"):
            header = [cell(c) for c in line.strip()[2:].strip(" |").split("|")]
        elif domain and header and line.strip().startswith("|"):
            values = [cell(c) for c in line.strip()[1:].strip(" |").split("|")]
            rows = found.setdefault((header[0], domain), {})
            for algorithm, value in zip(header[1:], values[1:]):
                rows[(values[0], algorithm)] = value
    return found


def main() -> int:
    grid = pathlib.Path(sys.argv[1]).resolve()
    props = json.loads((grid / "eval" / "properties").read_text())
    # Lab expects an evaluation folder named *-eval.
    eval_dir = grid.parent / (grid.name + "-eval")
    eval_dir.symlink_to(grid / "eval")
    out = grid.parent / "lab-report.txt"
    AbsoluteReport(attributes=ATTRIBUTES, format="txt")(str(eval_dir), str(out))
    found = tables(out.read_text())
    # An attribute that an algorithm reports for none of its runs (SymK counts no
    # expansions) is not required of it; one that it reports at all, every run must have
    # (cost: every solved run).
    reported = {(r["algorithm"], a) for r in props.values() for a in ATTRIBUTES if a in r}
    problems = []
    for key, run in props.items():
        for attribute in ATTRIBUTES:
            shown = found.get((attribute, run["domain"]), {}).get(
                (run["problem"], run["algorithm"])
            )
            if attribute not in run:
                required = (run["algorithm"], attribute) in reported and (
                    attribute != "cost" or run["coverage"] == 1
                )
                if required:
                    problems.append(f"{key}: no {attribute} in the properties")
                elif shown not in (None, "None", "", "-", "—"):  # Lab prints None for a missing value
                    problems.append(f"{key}: {attribute} {shown} in the report, none in the properties")
                continue
            if shown is None:
                problems.append(f"{key}: the report lists no {attribute}")
            elif float(shown) != float(run[attribute]):
                problems.append(f"{key}: {attribute} {shown} in the report, {run[attribute]} in the properties")
    listed = {k for rows in found.values() for k in rows}
    print(
        f"lab report: {len(props)} runs in the properties, "
        f"{len({(r['problem'], r['algorithm'], r['domain']) for r in props.values()})} distinct, "
        f"{len(problems)} problem(s)"
    )
    for p in problems:
        print(f"error: {p}", file=sys.stderr)
    if len(props) == 0 or not listed:
        print("error: nothing to report", file=sys.stderr)
        return 1
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
