"""ALFRED's interaction actions in the PyBullet world: the dispatcher. It resolves the target and checks
reach (`reach`), asks the pure object-state rules (`luminous_sim.states`) whether the action is allowed
and what it changes, carries out the physical side (`placement`, `hand`, `articulation`, `slicing`,
state visuals), and keeps the pure state in step with the physics."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from luminous_sim.errors import Failure, FailureCode
from luminous_sim.states import effects as fx
from luminous_sim.states import rules
from luminous_sim.states.model import WorldState
from luminous_sim.states.tables import DEFAULT_SLICE_COUNTS, SLICE_OF
from luminous_sim.vocab import abilities
from luminous_sim.world.articulation import move_joint
from luminous_sim.world.asset_loader import show_state
from luminous_sim.world.doors import hits_agent, swept_boxes
from luminous_sim.world.hand import carry, grab
from luminous_sim.world.initial_state import initial_state
from luminous_sim.world.placement import place
from luminous_sim.world.reach import reach_failure, resolve, type_of
from luminous_sim.world.results import StepResult
from luminous_sim.world.slicing import slice_body

if TYPE_CHECKING:
    from luminous_sim.world.world import World

SETTLE_AFTER = frozenset({"PutObject", "SliceObject"})
"""Actions after which physics must run (things were placed); joints and holding are kinematic."""


class Interactions:
    """The interaction half of a World: the pure state, the random stream of real puts, and dispatch."""

    def __init__(self, world: World):
        self.world = world
        self.state: WorldState = initial_state(world)
        self.rng = np.random.default_rng(np.random.SeedSequence([world.scene.seed, 7]))

    @property
    def held(self) -> str | None:
        return self.state.held

    def type_of(self, oid: str | None) -> str:
        return type_of(self.state, oid)

    def carry(self, oid: str) -> None:
        """Keep the held object (and what it carries) in front of the camera after the agent moves."""
        carry(self.world, self.state, oid)

    def set_dirty(self, oid: str, dirty: bool = True) -> None:
        """Make an object dirty or clean, in the pure state and its visuals (scene set-up only)."""
        loaded = self.world.built.objects.get(oid)
        if loaded is None or oid not in self.state.objects:
            return
        self.state = rules.apply(self.state, [fx.SetState(oid, "isDirty", dirty)]) \
            if self.state.objects[oid].isDirty != dirty else self.state
        show_state(self.world.client, loaded, "dirty", dirty)

    def set_sliced(self, oid: str) -> None:
        """Slice an object without a knife, in the pure state and the physics (scene set-up only); an object
        that is not sliceable, already sliced or not in the world is left alone."""
        st = self.state.objects.get(oid)
        if oid not in self.world.built.objects or st is None or st.isSliced \
                or not abilities(st.object_type).sliceable:
            return
        effects: list[fx.Effect] = [fx.SetState(oid, "isSliced", True)]
        if st.object_type in SLICE_OF:
            count = self.state.slice_counts.get(oid, DEFAULT_SLICE_COUNTS.get(st.object_type, 1))
            effects.append(fx.Slice(oid, SLICE_OF[st.object_type], count))
        self._apply_physical("SliceObject", effects, oid, None)
        self.state = rules.apply(self.state, effects)
        self._settle()

    # ------------------------------------------------------------------ dispatch

    def run(self, name: str, act: dict[str, Any]) -> StepResult:
        """Run one interaction action; a failure leaves the world as it was."""
        world, state = self.world, self.state
        if name == "PutObject":
            target = act.get("objectId") or self.held
            receptacle = resolve(world, state, act, "receptacleObjectId")
            if target is None:
                return StepResult.fail(FailureCode.NOT_HOLDING, "nothing is held", act)
            if receptacle is None:
                return StepResult.fail(FailureCode.NO_TARGET, "PutObject needs receptacleObjectId, a mask or a point",
                                       act)
            if target != self.held:
                return StepResult.fail(FailureCode.NOT_HOLDING, f"{target} is not the held object", act)
            why = reach_failure(world, state, receptacle)
        else:
            target = resolve(world, state, act)
            receptacle = None
            if target is None:
                return StepResult.fail(FailureCode.NO_TARGET,
                                       f"{name} needs an objectId, a mask or a point on an object",
                                       act)
            why = reach_failure(world, state, target)
        if why:
            return StepResult.of(why, act)
        why = rules.failure(name, state, target, receptacle)
        if not why and name == "OpenObject" and hits_agent(swept_boxes(world, target), world.agent.x, world.agent.y):
            why = Failure(FailureCode.BLOCKED, f"{target} cannot be opened: it would hit the agent (step back first)")
        if why:
            return StepResult.of(why, act)
        effects = rules.effects(name, state, target, receptacle)
        why = self._apply_physical(name, effects, target, receptacle)
        if why:
            return StepResult.of(why, act)
        self.state = rules.apply(self.state, effects)
        if name in SETTLE_AFTER:
            self._settle()
        elif self.held:
            self.carry(self.held)
        return StepResult.ok(act)

    # ------------------------------------------------------------------ physical side

    def _settle(self) -> None:
        for _ in range(self.world.config.interaction_steps):
            self.world.client.stepSimulation()
        if self.held:
            self.carry(self.held)

    def _apply_physical(self, name: str, effects: list, target: str, receptacle: str | None) -> Failure | None:
        if name == "PutObject":
            assert receptacle is not None
            why = place(self.world, self.state, target, receptacle, self.rng)
            if why:
                return why
        for e in effects:
            if isinstance(e, fx.MoveJoint):
                move_joint(self.world, self.state, e.object_id, e.open)
            elif isinstance(e, fx.ShowVisual):
                loaded = self.world.built.objects.get(e.object_id)
                if loaded is not None:
                    show_state(self.world.client, loaded, e.state, e.visible)
            elif isinstance(e, fx.Attach):
                grab(self.world, self.state, e.object_id)
            elif isinstance(e, fx.Slice):
                slice_body(self.world, e.object_id, e.sliced_type)
        return None
