"""ALFRED's exact action records: `api_action` and `discrete_action` dicts for every low-level action,
and the lower-cased type names used in high-level `discrete_action.args`."""

from __future__ import annotations

from typing import Any

from luminous_sim.scene.ids import type_of_id


def nav_api(action: str) -> dict[str, Any]:
    """The api_action ALFRED records for a navigation step."""
    if action == "MoveAhead":
        return {"action": "MoveAhead", "forceAction": True, "moveMagnitude": 0.25}
    return {"action": action, "forceAction": True}


def interaction_api(action: str, object_id: str, receptacle_id: str | None = None) -> dict[str, Any]:
    """The api_action ALFRED records for an interaction (PutObject names the held object and the receptacle)."""
    if action == "PutObject":
        return {"action": "PutObject", "objectId": object_id, "receptacleObjectId": receptacle_id,
                "forceAction": True, "placeStationary": True}
    return {"action": action, "objectId": object_id}


def type_name(object_id: str | None) -> str:
    """The lower-cased type ALFRED writes in `discrete_action.args` (`...|AppleSliced_2` -> `applesliced`)."""
    return type_of_id(object_id).lower() if object_id else ""
