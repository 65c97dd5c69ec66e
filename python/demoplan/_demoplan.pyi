"""Type stubs of the Rust extension module (crates/demoplan-py/src/lib.rs)."""

from typing import List, Optional, Tuple

__version__: str

def run(argv: List[str], program: Optional[List[str]] = None) -> int: ...
def plan(
    domain: str,
    domain_name: str,
    problem: str,
    problem_name: str,
    search: Optional[str],
    alias: Optional[str] = None,
    time_limit: Optional[float] = None,
    memory_limit: Optional[int] = None,
    h2_mutexes: bool = False,
    remove_dominated_operators: bool = False,
) -> Tuple[str, Optional[str], Optional[int], str]: ...
def validate(
    domain: str,
    domain_name: str,
    problem: str,
    problem_name: str,
    plan: str,
    plan_name: str,
) -> Tuple[bool, str, Optional[int]]: ...

class _Library:
    def __init__(self, lambda_: int) -> None: ...
    @staticmethod
    def from_json(text: str, name: str) -> "_Library": ...
    def to_json(self) -> str: ...
    @property
    def lambda_(self) -> int: ...
    @property
    def segments(self) -> int: ...
    @property
    def recordings(self) -> List[str]: ...
    def operators(
        self,
    ) -> List[Tuple[str, str, int, int, List[Tuple[str, str, str, str, float, float]]]]: ...
    def cards(self) -> str: ...
    def levels(self, keep_without_effects: bool) -> List[Tuple[int, List[str]]]: ...
    def domain(self, prio: int, keep_without_effects: bool) -> str: ...

def solve(
    library: _Library,
    problem: str,
    problem_name: str,
    search: str,
    keep_without_effects: bool = False,
    time_limit: Optional[float] = None,
    memory_limit: Optional[int] = None,
    execute: bool = True,
) -> Tuple[
    List[Tuple[int, int, str, Optional[str], Optional[int], Optional[int], float, Optional[str]]],
    float,
    List[Tuple[str, str, int, int, str, List[str], List[str], str]],
    float,
    Optional[str],
]: ...
def read_poses(path: str) -> Tuple[List[str], List[float], List[float]]: ...
def learn(
    library: _Library,
    files: List[str],
    folder: str,
    mapping: Optional[str] = None,
    generalise: bool = False,
) -> Tuple[_Library, str]: ...
def simulate(
    out: str, participants: int, per_participant: int, seed: int, cubes: Optional[int] = None
) -> List[str]: ...
def tower_problem(
    tower: Optional[str] = None,
    paper_goal: Optional[int] = None,
    cubes: Optional[int] = None,
    hands: Optional[int] = None,
) -> str: ...
