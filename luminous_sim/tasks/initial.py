"""A task's initial state (a CDF's `task.initial`): object states set on the scene before the world is
built, and every literal checked once it is. Shared by `luminous run` (`episode.run_task`) and the
environment's CDF scenes."""

from __future__ import annotations

from luminous_sim.cdf import And, Atom, Expr, Not, to_sexpr
from luminous_sim.scene import Scene
from luminous_sim.states import WorldState
from luminous_sim.tasks.errors import TaskError
from luminous_sim.tasks.evaluate import goal_satisfied

STATE_LITERALS: dict[str, str] = {"isOpen": "isOpen", "isToggled": "isToggled", "isOn": "isToggled",
                                  "isDirty": "isDirty", "isFilled": "isFilled", "isHot": "isHot", "isCool": "isCold"}
"""Initial-state predicates a scene object's `states` can be set by (predicate -> state key)."""


DIRTY_FIRST: frozenset[str] = frozenset({"pick_clean_then_place_in_recep"})
"""The task types whose set-up makes things dirty first (ALFRED's `dirty_and_empty`, for cleaning)."""


def alfred_dirty(state: WorldState, task_type: str) -> tuple[str, ...]:
    """The objects ALFRED's set-up makes dirty before a task of `task_type` (for cleaning, every dirtyable
    object that can be picked up, as its `dirty_and_empty` initialisation does), sorted; none for the rest."""
    from luminous_sim.vocab import abilities

    if task_type not in DIRTY_FIRST:
        return ()
    return tuple(sorted(oid for oid, st in state.objects.items()
                        if abilities(st.object_type).dirtyable and abilities(st.object_type).pickupable))


def initial_literals(initial: Expr | None) -> list[tuple[Atom, bool]]:
    """(atom, positive) for each literal of a ground conjunction.

    Raises:
        TaskError: `initial` is not ground literals joined by `and`.
    """
    if initial is None:
        return []
    if isinstance(initial, And):
        return [lit for arg in initial.args for lit in initial_literals(arg)]
    if isinstance(initial, Not) and isinstance(initial.arg, Atom):
        return [(initial.arg, False)]
    if isinstance(initial, Atom):
        return [(initial, True)]
    raise TaskError(f"task.initial: expected ground literals joined by `and`, got {initial}")


def scene_with_initial(scene: Scene, initial: Expr | None, names: dict[str, str]) -> Scene:
    """The scene with the object states `initial` asks for (where things stand is the layout's business;
    `check_initial` checks it once built).

    Raises:
        TaskError: a literal names no object of the scene.
    """
    wanted: dict[str, dict[str, bool]] = {}
    ids = {o.id for o in scene.objects}
    for atom, positive in initial_literals(initial):
        key = STATE_LITERALS.get(atom.pred)
        if key is None or len(atom.args) != 1:
            continue
        oid = names.get(atom.args[0], atom.args[0])
        if oid not in ids:
            raise TaskError(f"task.initial: ({atom.pred} {atom.args[0]}) names no object of the scene")
        wanted.setdefault(oid, {})[key] = positive
    if not wanted:
        return scene
    objects = [o.model_copy(update={"states": {**o.states, **wanted[o.id]}}) if o.id in wanted else o
               for o in scene.objects]
    return scene.model_copy(update={"objects": objects})


def check_initial(state: WorldState, initial: Expr | None, names: dict[str, str]) -> None:
    """Raise `TaskError` when a literal of `initial` does not hold in `state`."""
    for atom, positive in initial_literals(initial):
        literal = atom if positive else Not(atom)
        if not goal_satisfied(literal, state, names):
            raise TaskError(f"task.initial: {to_sexpr(literal)} does not hold in the generated scene "
                            "(object states are set; where objects stand comes from scene.relations)")
