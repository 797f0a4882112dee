"""`house_objectnav`: ObjectNav (`objectnav`'s goal, Stop rule and scoring) across the rooms of a house. Each
episode generates a house from the seed it draws (`cssg.generate_house` on `HOUSE_CDF`, the house of
`luminous generate --house`: a kitchen, a living room, a bedroom and a bathroom; the floor plan is drawn
anew for each seed), so the floor plan changes every episode. The start is at least `min_start_distance` m
(geodesic) from every target's success region, and in a room that holds no instance of the target type in
a share `cross_room_share` of the episodes (drawn per episode; the rest start in a room that holds one); where
the drawn kind of start has no grid point that far, the other kind is used. The reset's `info` says which
room the agent starts in and which rooms hold a target (`start_room`, `target_rooms`).
"""

from __future__ import annotations

import numpy as np

from luminous_sim.env.kinds.objectnav import ObjectNav, ObjectNavGoal
from luminous_sim.env.navscore import start_keys
from luminous_sim.episodes import Goal
from luminous_sim.scene import Scene
from luminous_sim.tasks import TaskSamplingError
from luminous_sim.world import AgentPose, World, WorldView
from luminous_sim.world.agent import GRID

HOUSE_CDF = """
cdf_version: 2
name: env_house
description: The house of `luminous generate --house` (cdf/examples/houses/default_house.yaml).
scene:
  house:
    rooms:
      - {name: kitchen, type: Kitchen, min_area: 9, max_area: 16}
      - {name: living, type: LivingRoom, min_area: 14}
      - {name: bedroom, type: Bedroom, min_area: 9}
      - {name: bathroom, type: Bathroom, max_area: 8}
    adjacency:
      - [kitchen, living]
      - [bedroom, living]
"""


def house_scene(seed: int, front_door: bool = True) -> Scene:
    """The house of `HOUSE_CDF` generated from `seed` (without a front door: as houses were before they had one)."""
    from luminous_sim.cdf import loads
    from luminous_sim.cssg import generate_house

    text = HOUSE_CDF if front_door else HOUSE_CDF + "    front_door: false\n"
    return generate_house(loads(text, source="house_objectnav"), seed).scene


def target_rooms(view: WorldView, instances: tuple[str, ...]) -> frozenset[str]:
    """The house rooms that hold the instances (by the centre of each one's box)."""
    shell = view.scene.room
    rooms = set()
    for oid in instances:
        lo, hi = view.aabb(oid)
        room = shell.room_at(float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2)
        if room is not None:
            rooms.add(room)
    return frozenset(rooms)


class HouseObjectNav(ObjectNav):
    """ObjectNav in a house generated per episode, starting in another room than the target for a share."""

    def rooms(self) -> tuple[str, ...]:
        return ("LivingRoom",)  # not used to lay out a room: the house has every type

    def generate_scene(self, room_type: str, seed: int) -> Scene:
        return house_scene(seed, front_door=bool(self.options["front_door"]))

    def draw_start(self, world: World, goal: Goal, rng: np.random.Generator) -> AgentPose | None:
        if not isinstance(goal, ObjectNavGoal):
            raise TypeError(f"{self.name}: expected an ObjectNavGoal")
        view = world.view()
        far = start_keys(view, goal.region(view), self.options["min_start_distance"])
        rooms = target_rooms(view, goal.instances(view))
        shell = view.scene.room
        apart = [k for k in far if shell.room_at(k[0] * GRID, k[1] * GRID) not in rooms]
        inside = [k for k in far if k not in set(apart)]
        cross = bool(rng.random() < self.options["cross_room_share"])
        keys = (apart or inside) if cross else (inside or apart)
        if not keys:
            raise TaskSamplingError(f"{self.name}: no start {self.options['min_start_distance']:g} m from the "
                                    f"{goal.object_type}")
        gx, gy = keys[int(rng.integers(len(keys)))]
        return AgentPose(gx * GRID, gy * GRID, 90 * int(rng.integers(4)), 30)
