"""Optional PDDL backends: Fast Downward, directly or through unified-planning.

Both need `pip install up-fast-downward` (which brings unified-planning and a compiled Fast
Downward; nothing is downloaded at run time). `fd` runs that Fast Downward's driver on
`luminous_domain.pddl` and the problem from `problem.build_problem`; `up` goes through
unified-planning's PDDL reader and `OneshotPlanner(name="fast-downward")` (about 4 s more per call,
for importing and parsing). Plans are mapped back to `HighLevelAction`s; `solve` then replays and
checks them like its own.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from collections.abc import Mapping
from pathlib import Path

from luminous_sim.cdf.predicates import Expr
from luminous_sim.errors import PlanningError
from luminous_sim.planning.symbolic.actions import HighLevelAction, act, goto
from luminous_sim.planning.symbolic.problem import PddlProblem, build_problem, domain_text
from luminous_sim.planning.symbolic.relevance import relevance
from luminous_sim.states import WorldState

FD_CONFIGS: dict[str, tuple[list[str], list[str]]] = {
    "lama-first": (["--alias", "lama-first"], []),
    "optimal": ([], ["--search", "astar(hmax())"]),
}
"""Fast Downward configurations: (driver options, search options). `lama-first` is greedy and fast;
`optimal` is A* with h_max, admissible and able to handle the domain's conditional effects (LM-cut
is not)."""

FD_CONFIG = "lama-first"
"""The configuration the `fd` backend uses."""


def fast_downward_driver() -> Path:
    """The `fast-downward.py` driver shipped in the up-fast-downward wheel.

    Raises:
        PlanningError: the package is not installed.
    """
    try:
        import up_fast_downward
    except ImportError:
        raise PlanningError(
            "backend 'fd' needs the up-fast-downward package: pip install up-fast-downward"
        ) from None
    driver = Path(up_fast_downward.__file__).parent / "downward" / "fast-downward.py"
    if not driver.is_file():
        raise PlanningError(f"up-fast-downward has no Fast Downward driver at {driver}")
    return driver


def solve_external(
    backend: str,
    state: WorldState,
    prepared: Expr,
    names: Mapping[str, str],
    at: str | None = None,
    timeout: float = 30.0,
) -> tuple[list[HighLevelAction], float]:
    """Plan with an external backend ("fd" or "up").

    Returns:
        (actions, cost) of the plan found.

    Raises:
        PlanningError: the backend is missing, finds no plan, or runs out of time.
    """
    problem = build_problem(state, prepared, names, at, relevance(state, prepared, names))
    if backend == "fd":
        steps = _run_fd(problem, timeout)
    elif backend == "up":
        steps = _run_up(problem)
    else:
        raise PlanningError(f"no external backend {backend!r}")
    actions = [a for step in steps for a in _to_actions(step, problem)]
    return actions, sum(a.cost for a in actions)


def _run_fd(problem: PddlProblem, timeout: float) -> list[list[str]]:
    driver = fast_downward_driver()
    with tempfile.TemporaryDirectory(prefix="luminous_fd_") as tmp:
        d, p = Path(tmp) / "domain.pddl", Path(tmp) / "problem.pddl"
        d.write_text(domain_text())
        p.write_text(problem.text)
        try:
            before, after = FD_CONFIGS[FD_CONFIG]
            run = subprocess.run(
                [sys.executable, str(driver), *before, str(d), str(p), *after],
                cwd=tmp,
                capture_output=True,
                text=True,
                timeout=timeout,
                check=False,
                env={**os.environ, "PYTHONHASHSEED": "0"},
            )
        except subprocess.TimeoutExpired:
            raise PlanningError(f"Fast Downward found no plan within {timeout:.0f} s") from None
        plan = Path(tmp) / "sas_plan"
        if not plan.is_file():
            tail = (run.stdout + run.stderr).strip().splitlines()[-3:]
            raise PlanningError(
                f"Fast Downward found no plan (exit {run.returncode}): {' / '.join(tail)}"
            )
        lines = [ln.strip() for ln in plan.read_text().splitlines() if ln.strip().startswith("(")]
    return [ln.strip("()").split() for ln in lines]


def _run_up(problem: PddlProblem) -> list[list[str]]:
    try:
        from unified_planning.engines import PlanGenerationResultStatus as Status
        from unified_planning.io import PDDLReader
        from unified_planning.shortcuts import OneshotPlanner, get_environment
    except ImportError:
        raise PlanningError("backend 'up' needs unified-planning and up-fast-downward") from None
    get_environment().credits_stream = None
    parsed = PDDLReader().parse_problem_string(domain_text(), problem.text)
    with OneshotPlanner(name="fast-downward") as planner:
        result = planner.solve(parsed)
    if (
        result.status not in (Status.SOLVED_SATISFICING, Status.SOLVED_OPTIMALLY)
        or result.plan is None
    ):
        raise PlanningError(f"unified-planning/Fast Downward found no plan ({result.status.name})")
    return [[ai.action.name, *(str(p) for p in ai.actual_parameters)] for ai in result.plan.actions]


def _to_actions(step: list[str], problem: PddlProblem) -> list[HighLevelAction]:
    """One PDDL action (name and arguments) as high-level actions."""
    name, args = step[0].lower(), [a.lower() for a in step[1:]]

    def obj(i: int) -> str:
        return problem.objects[args[i]]

    if name == "gotolocation":
        return [goto(problem.locations[args[2]])]
    if name in ("openobject", "closeobject"):
        return [act("OpenObject" if name == "openobject" else "CloseObject", obj(2))]
    if name == "pickupobject":
        return [act("PickupObject", obj(2))]
    if name in ("putobject", "putobjectinreceptacleobject"):
        return [act("PutObject", obj(2), obj(3))]
    if name in ("heatobject", "coolobject", "cleanobject"):
        return [
            act(
                {
                    "heatobject": "HeatObject",
                    "coolobject": "CoolObject",
                    "cleanobject": "CleanObject",
                }[name],
                obj(3),
                obj(2),
            )
        ]
    if name in ("toggleobjecton", "toggleobjectoff"):
        return [act("ToggleObject", obj(2))]
    if name == "sliceobject":
        return [act("SliceObject", obj(2))]
    raise PlanningError(f"unknown PDDL action {step[0]!r} in the plan")
