"""Text commands carried out in the embodied world: each command the text game carried out
(`TextGame.history`) as the planner action on the object ids it names, run by the oracle's script runner
(`planning.ScriptOracle`) in a `World`: "go to R" walks to R's interaction place, "take O from R" picks O up
there, "move O to R" puts it in R, "heat O with R" is ALFRED's heating sequence at R, "use O" switches O.
What a command says of where things are is checked in the world before it is carried out: "take O from R"
needs O in or on R (through a bowl on it) there and then, every interaction needs the agent to have gone to
R (or to the receptacle a bowl R stands on), so a command naming the wrong instance fails as it would in
the text game. A thing the text game shows on a receptacle it does not stand on (a floor lamp beside a table)
is walked to first. Looking, examining and the inventory change nothing and have no action."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

from luminous_sim.planning.symbolic import HighLevelAction
from luminous_sim.text.alfworld_problem import fixed_holder, is_receptacle
from luminous_sim.text.game import TextAction

if TYPE_CHECKING:
    from luminous_sim.world import World

_PLAIN = {"take": "PickupObject", "open": "OpenObject", "close": "CloseObject", "use": "ToggleObject",
          "slice": "SliceObject"}
_DEVICE = {"heat": "HeatObject", "cool": "CoolObject", "clean": "CleanObject"}


@dataclass(frozen=True)
class CarriedOut:
    """How carrying text commands out went: whether every one worked, and the first that did not, and why."""

    ok: bool
    failed_at: int | None = None
    cause: str = ""


def embodied_actions(a: TextAction, free: Mapping[str, str] = {}) -> list[HighLevelAction]:
    """The planner actions of one command (`free`: the text game's `free` things, walked to first)."""
    if a.verb == "go to":
        return [HighLevelAction("GotoLocation", {"objectId": a.receptacle})]
    if a.verb in ("take", "use") and a.target in free:
        return [HighLevelAction("GotoLocation", {"objectId": a.target}),
                HighLevelAction(_PLAIN[a.verb], {"objectId": a.target})]
    if a.verb in _PLAIN:
        return [HighLevelAction(_PLAIN[a.verb], {"objectId": a.target or a.receptacle})]
    if a.verb == "move":
        return [HighLevelAction("PutObject", {"objectId": a.target, "receptacleObjectId": a.receptacle})]
    if a.verb in _DEVICE:
        return [HighLevelAction(_DEVICE[a.verb], {"objectId": a.target, "receptacleObjectId": a.receptacle})]
    return []


def carry_out(world: World, history: Iterable[TextAction], free: Mapping[str, str] = {}) -> CarriedOut:
    """Carry the commands out in `world` (prepared for the same episode), checking what each says of where
    things are; stops at the first that fails."""
    from luminous_sim.planning import ScriptOracle

    oracle = ScriptOracle(world, record_frames=False)
    at: str | None = None
    for k, a in enumerate(history):
        why = _misplaced(world, a, at, free)
        if why:
            return CarriedOut(False, k, why)
        traj = oracle.execute(embodied_actions(a, free))
        if not traj.success:
            return CarriedOut(False, k, traj.failures[0] if traj.failures else "failed")
        at = a.receptacle if a.verb == "go to" else at
    return CarriedOut(True)


def _misplaced(world: World, a: TextAction, at: str | None, free: Mapping[str, str]) -> str:
    """Why the command's claim of where things are does not hold in the world ("" when it does)."""
    if a.verb in ("go to", "look", "inventory", "help", "examine"):
        return ""
    state = world.view().state

    def shown_at(oid: str) -> str | None:
        h = fixed_holder(state, oid)
        return h if h is not None else free.get(oid) if state[oid].parent is None else None

    if a.verb == "take":
        assert a.target is not None
        if a.receptacle != at or (shown_at(a.target) != a.receptacle and a.receptacle not in state.ancestors(a.target)):
            return f"{a.target} is not on or in {a.receptacle} where the agent stands ({at})"
        return ""
    place = a.receptacle if a.verb in ("open", "close", "heat", "cool", "clean", "move") else a.target
    assert place is not None
    where = place if place == at or is_receptacle(state[place].object_type) else shown_at(place)
    if where != at:
        return f"{place} is not where the agent stands ({at})"
    return ""
