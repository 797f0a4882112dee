"""Each task kind's options (`EnvConfig.task_options`), declared once as a pydantic model per kind: their names,
their defaults and their ranges. A kind reads its own from here (`TaskKind.defaults`); a config is checked
against them without importing a kind's module (which loads the simulator)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pydantic import BaseModel, ConfigDict, Field, ValidationError
from pydantic.fields import FieldInfo

from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES

MAX_TASK_DISTANCE = 100.0
"""Largest distance (metres) a task option may name (a success or minimum start distance): a house is under 30 m."""
SUCCESS_DISTANCE = 1.0
"""RoboTHOR's ObjectNav success distance (m)."""
MIN_START_DISTANCE = 2.0
"""The least geodesic distance (m) from an ObjectNav start to a target's region."""
CROSS_ROOM_SHARE = 0.75
"""The share of house ObjectNav episodes that start in another room than the target."""


def _distance(default: float, what: str) -> float:
    return Field(default, ge=0.0, le=MAX_TASK_DISTANCE, description=what)


def _share(default: float, what: str) -> float:
    return Field(default, ge=0.0, le=1.0, description=what)


class KindOptions(BaseModel):
    """A kind's options: numbers, each within its range; a kind without options takes none."""

    model_config = ConfigDict(extra="forbid", frozen=True, strict=True)


class AlfredOptions(KindOptions):
    house: float = _share(0.0, "1 plays each episode in a house generated for it (0: one room)")
    cross_room_share: float = _share(0.0, "the share of house episodes whose object and receptacle (or lamp) are "
                                          "in different rooms")


class ObjectNavOptions(KindOptions):
    success_distance: float = _distance(SUCCESS_DISTANCE, "Stop within this distance (m) of a target's view")
    min_start_distance: float = _distance(MIN_START_DISTANCE, "start at least this far (m) from every target")


class ObjectNavPickupOptions(KindOptions):
    min_start_distance: float = _distance(MIN_START_DISTANCE, "start at least this far (m) from every target")


class HouseObjectNavOptions(ObjectNavOptions):
    cross_room_share: float = _share(CROSS_ROOM_SHARE, "the share of episodes starting in another room")
    front_door: float = _share(1.0, "0 draws the houses without a front door (as Luminous-HouseNav-64-v1)")


KIND_OPTION_MODELS: dict[str, type[KindOptions]] = {
    **dict.fromkeys(ALFRED_TASK_TYPES, AlfredOptions),
    "objectnav": ObjectNavOptions,
    "objectnav_pickup": ObjectNavPickupOptions,
    "house_objectnav": HouseObjectNavOptions,
}
"""Kind name -> its options (a kind not listed takes none)."""
KIND_OPTIONS: dict[str, tuple[str, ...]] = {k: tuple(m.model_fields) for k, m in KIND_OPTION_MODELS.items()}
"""Kind name -> the names of its options."""


def kind_defaults(kind: str) -> dict[str, float]:
    """The kind's options at their defaults (none for a kind without options)."""
    model = KIND_OPTION_MODELS.get(kind)
    return model().model_dump() if model is not None else {}


def check_task_options(task_types: tuple[str, ...], options: Mapping[str, float]) -> None:
    """Refuse options no kind of `task_types` takes, and values out of their range.

    Raises:
        LuminousError: one line naming the option and what was expected.
    """
    known = {o for t in task_types for o in KIND_OPTIONS.get(t, ())}
    bad = sorted(set(options) - known)
    if bad:
        raise LuminousError(f"env config task_options: {bad}; the task types {', '.join(task_types)} take "
                            f"{', '.join(sorted(known)) or 'none'}")
    for kind in dict.fromkeys(task_types):
        model = KIND_OPTION_MODELS.get(kind)
        mine = {k: float(v) for k, v in options.items() if model is not None and k in model.model_fields}
        if model is None or not mine:
            continue
        try:
            model(**mine)
        except ValidationError as exc:
            name = str(exc.errors()[0]["loc"][0])
            field = model.model_fields[name]
            low, high = field_bounds(field)
            raise LuminousError(f"env config task_options.{name}: expected a number in {low:g}..{high:g} "
                                f"({field.description}), got {mine[name]:g}") from None


def field_bounds(field: FieldInfo) -> tuple[Any, Any]:
    """The `ge` and `le` bounds a pydantic field declares (None where it declares none)."""
    low = next((rule.ge for rule in field.metadata if hasattr(rule, "ge")), None)
    high = next((rule.le for rule in field.metadata if hasattr(rule, "le")), None)
    return low, high
