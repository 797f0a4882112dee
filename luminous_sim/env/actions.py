"""The flat action spaces: ALFRED's navigation actions, Stop, and each interaction on one of m targets,
and the full ALFRED form (a dict) that `LuminousEnv.step` takes as well.

Two kinds of target (`EnvConfig.targets`):

* `points` (the default): a k x k grid of image points (m = k * k). Target (r, c) is the pixel at the
  centre of that cell, x = (c + 0.5) * width / k, y likewise; it goes to `World.step` as ALFRED's `point`
  (`PutObject` puts the held object on what the point shows).
* `objects` (for research): m visible-object slots. The env lists the objects in view and within reach
  that some interaction applies to (the held one aside), most pixels first, in its `objects` observation;
  slot i names the i-th of them by object id. An empty slot is a failed action (`no_target`).

Index layout::

    0..4        MoveAhead, RotateLeft, RotateRight, LookUp, LookDown
    5           Stop
    6 + i*m + t interaction i (PickupObject, PutObject, OpenObject, CloseObject, ToggleObjectOn,
                ToggleObjectOff, SliceObject) on target t (a grid cell r * k + c, or a slot)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from luminous_sim.errors import FailureCode

NAVIGATION: tuple[str, ...] = ("MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown")
STOP = "Stop"
STOP_NAMES = frozenset({STOP, "<<stop>>"})
"""Names that end the episode: ours, and the stop token of ALFRED's models."""
INTERACTIONS: tuple[str, ...] = (
    "PickupObject", "PutObject", "OpenObject", "CloseObject", "ToggleObjectOn", "ToggleObjectOff", "SliceObject",
)
ALFRED_ACTIONS = frozenset(NAVIGATION + INTERACTIONS)
"""What the dict form may name (besides Stop): ALFRED's low-level actions, no teleports."""
TARGET_KINDS: tuple[str, ...] = ("points", "objects")


class EmptySlot(LookupError):
    """An object-slot action names a slot with no object in it."""


def nav_api(name: str) -> dict[str, Any]:
    """The api action ALFRED sends for a navigation step."""
    if name == "MoveAhead":
        return {"action": "MoveAhead", "forceAction": True, "moveMagnitude": 0.25}
    return {"action": name, "forceAction": True}


def interaction_api(name: str, target: dict[str, Any]) -> dict[str, Any]:
    """The api action of an interaction on a target (`{"point": ...}` or `{"objectId": ...}`)."""
    if name == "PutObject":
        key = "receptacleObjectId" if "objectId" in target else "point"
        return {"action": name, key: target.get("objectId", target.get("point")), "forceAction": True,
                "placeStationary": True}
    return {"action": name, **target}


@dataclass(frozen=True)
class ActionTable:
    """Discrete index <-> api action, for one image size and kind of target.

    Attributes:
        width: image width (pixels).
        height: image height (pixels).
        grid: k, the grid's side (`points` targets).
        slots: the number of object slots; 0 for `points` targets.
    """

    width: int
    height: int
    grid: int
    slots: int = 0

    @property
    def targets(self) -> int:
        """m, the targets per interaction."""
        return self.slots or self.grid**2

    @property
    def n(self) -> int:
        """The number of discrete actions."""
        return len(NAVIGATION) + 1 + len(INTERACTIONS) * self.targets

    @property
    def first_interaction(self) -> int:
        return len(NAVIGATION) + 1

    def point(self, cell: int) -> tuple[int, int]:
        """The (x, y) pixel of grid cell `cell` (row-major)."""
        r, c = divmod(cell, self.grid)
        return int((c + 0.5) * self.width / self.grid), int((r + 0.5) * self.height / self.grid)

    def points(self) -> list[tuple[int, int]]:
        """Every grid point, in cell order."""
        return [self.point(i) for i in range(self.grid**2)]

    def decode(self, index: int, slots: Sequence[str] = ()) -> dict[str, Any]:
        """The api action of a discrete index (`{"action": "Stop"}` for Stop).

        Args:
            index: the action.
            slots: the object ids in the slots now (`objects` targets).

        Raises:
            IndexError: the index is outside the space.
            EmptySlot: an object-slot action on an empty slot.
        """
        if not 0 <= index < self.n:
            raise IndexError(f"action {index} is outside 0..{self.n - 1}")
        if index < len(NAVIGATION):
            return nav_api(NAVIGATION[index])
        if index == len(NAVIGATION):
            return {"action": STOP}
        kind, t = divmod(index - self.first_interaction, self.targets)
        name = INTERACTIONS[kind]
        if not self.slots:
            return interaction_api(name, {"point": list(self.point(t))})
        if t >= len(slots):
            raise EmptySlot(f"{name} on object slot {t}, which is empty ({len(slots)} objects in view)")
        return interaction_api(name, {"objectId": slots[t]})

    def index(self, name: str, target: int | None = None) -> int:
        """The discrete index of a navigation action, Stop, or an interaction on target `target`."""
        if name in NAVIGATION:
            return NAVIGATION.index(name)
        if name in STOP_NAMES:
            return len(NAVIGATION)
        if target is None or not 0 <= target < self.targets:
            raise ValueError(f"{name} needs a target in 0..{self.targets - 1}, got {target}")
        return self.first_interaction + INTERACTIONS.index(name) * self.targets + target

    def cell_on(self, mask: np.ndarray) -> int | None:
        """The first grid cell (row-major) whose point lies on a boolean (H, W) mask, if any."""
        for cell, (x, y) in enumerate(self.points()):
            if mask[y, x]:
                return cell
        return None

    def labels(self) -> list[str]:
        """A readable name per index: `MoveAhead`, `Stop`, `PickupObject@(r,c)` or `PickupObject#slot`."""
        out = list(NAVIGATION) + [STOP]
        for name in INTERACTIONS:
            if self.slots:
                out += [f"{name}#{t}" for t in range(self.slots)]
            else:
                out += [f"{name}@({r},{c})" for r in range(self.grid) for c in range(self.grid)]
        return out

    def to_api(self, action: Any, slots: Sequence[str] = ()) -> tuple[dict[str, Any] | None, FailureCode | None, str]:
        """The api action an env action sends (a discrete index, or an ALFRED dict passed on as it is), or None
        with the code and message of an invalid one (outside the space, an empty slot, an unknown name, not an
        action at all)."""
        if isinstance(action, np.ndarray) and action.shape == () and action.dtype.kind in "iu":
            action = int(action)
        if isinstance(action, int | np.integer) and not isinstance(action, bool):
            if not 0 <= int(action) < self.n:
                return None, FailureCode.INVALID_ARGUMENT, f"action {action} is outside 0..{self.n - 1}"
            try:
                return self.decode(int(action), slots), None, ""
            except EmptySlot as exc:
                return None, FailureCode.NO_TARGET, str(exc)
        if isinstance(action, dict) and isinstance(action.get("action"), str):
            name = action["action"]
            if name in STOP_NAMES or name in ALFRED_ACTIONS:
                return dict(action), None, ""
            return None, FailureCode.UNKNOWN_ACTION, (f"unknown action {name!r}; expected Stop or one of "
                                                      f"{', '.join(sorted(ALFRED_ACTIONS))}")
        return None, FailureCode.INVALID_ARGUMENT, (f"an action is an index in 0..{self.n - 1} or a dict "
                                                    f"with an 'action' name, not {type(action).__name__}")

    def from_api(self, api: dict[str, Any] | None, slots: Sequence[str],
                 masks: Callable[[], Mapping[str, np.ndarray]]) -> int | dict[str, Any]:
        """An api action (object ids, as the oracle sends them) in the env's action form for the current view: a
        discrete index when one names it (an interaction's grid point on its target's mask, or its slot), else
        the api dict itself; Stop for None. `masks` gives the view's instance masks (asked only when needed)."""
        if api is None:
            return self.index("Stop")
        name = api["action"]
        if name in NAVIGATION:
            return self.index(name)
        target = api.get("receptacleObjectId") if name == "PutObject" else api.get("objectId")
        if self.slots:
            slot = list(slots).index(target) if isinstance(target, str) and target in slots else None
            return self.index(name, slot) if slot is not None else dict(api)
        mask = masks().get(target) if name in INTERACTIONS and isinstance(target, str) else None
        cell = self.cell_on(mask) if mask is not None else None
        return self.index(name, cell) if cell is not None else dict(api)
