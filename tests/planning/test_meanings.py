"""The planner reads predicate meaning from the task layer's table (`tasks.MEANINGS`), as evaluation does."""

from __future__ import annotations

import dataclasses
import re

from luminous_sim.cdf.predicates import parse_expr
from luminous_sim.planning.symbolic import ACTIONS, domain_text, solve, to_pddl_problem
from luminous_sim.tasks import (
    MEANINGS,
    PddlParams,
    TaskInstance,
    goal_conditions,
    goal_for,
    goal_satisfied,
)
from tests.planning.scenes import kitchen


def _domain_predicates() -> dict[str, int]:
    block = domain_text().split("(:predicates", 1)[1].split("(:functions", 1)[0]
    return {
        m.group(1): m.group(2).count("?")
        for m in re.finditer(r"\((\w+)((?:\s+\?\w+\s+-\s+\w+)*)\)", block)
    }


def test_every_goal_predicate_is_in_the_domain_and_achieved_by_a_planner_action():
    declared = _domain_predicates()
    for name, m in MEANINGS.items():
        if m.pddl == "=":
            continue  # PDDL's built-in equality
        arity = len(m.alfred_match) + (name == "holds")  # (holds ?agent ?o)
        assert declared.get(m.pddl) == arity, name
        for act in (m.achieved_by, m.undone_by):
            assert act is None or act in ACTIONS, (name, act)


def test_a_meaning_changed_in_the_table_shows_in_evaluation_and_planning(monkeypatch):
    state = kitchen()
    apple = next(k for k, o in state.objects.items() if o.object_type == "Apple")
    goal = parse_expr("(isHot apple)")
    names = {"apple": apple}
    assert not goal_satisfied(goal, state, names) and solve(state, goal, names).actions
    params = PddlParams("Apple", "CounterTop")
    task = TaskInstance(
        "pick_heat_then_place_in_recep",
        params,
        goal_for(params, "pick_heat_then_place_in_recep"),
        0,
    )
    before = goal_conditions(task, state)

    # redefine "hot" in the table as true of everything
    hot = dataclasses.replace(MEANINGS["isHot"], holds=lambda s, a: True)
    monkeypatch.setitem(MEANINGS, "isHot", hot)
    assert goal_satisfied(goal, state, names)
    assert solve(state, goal, names).actions == []
    assert goal_conditions(task, state)[0] > before[0]
    assert "(isHot " in to_pddl_problem(state, goal, names=names).split("(:goal", 1)[0]

    monkeypatch.setitem(MEANINGS, "isHot", dataclasses.replace(hot, pddl="isWarm"))
    assert "(isWarm " in to_pddl_problem(state, goal, names=names).split("(:goal", 1)[1]
