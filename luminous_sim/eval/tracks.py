"""The evaluation's tracks: what an agent may observe and read.

* `rgb` (the default): ALFRED's rules. RGB, the goal directive and the step instructions; no observation the
  simulator alone knows.
* `privileged`: `rgb` with the simulator's depth, instance segmentation and the types of the instances in
  view (`instance_types`), switched on in the evaluation env.

In every track the agent's `info` carries only `failure_code` and `error` (at reset also `episode_seed` and
`high_descs`), never `task_type`, `success`, `goal_conditions`, `subgoal` or the expert's action; the
`objectId` action form is refused (the built-in oracle aside, which is the reference, not an agent); the env
options that add privileged observations are refused outside `privileged`, and the `pose` observation and the
expert's action in every track (docs/evaluation.md).
"""

from __future__ import annotations

from typing import Any

from luminous_sim.errors import LuminousError

TRACKS: tuple[str, ...] = ("rgb", "privileged")
TRACK_OBSERVATIONS: dict[str, tuple[str, ...]] = {"rgb": (), "privileged": ("depth", "segmentation", "instance_types")}
"""The observations each track switches on in the evaluation env."""
PRIVILEGED_OPTIONS: tuple[str, ...] = ("depth", "segmentation", "instance_types", "goal_mask")
"""Env options (observation flags) that only the privileged track may switch on."""
NO_TRACK_OPTIONS: tuple[str, ...] = ("pose", "expert_in_info")
"""Env options no track allows: the pose from the simulator (an agent keeps its own, as ALFRED's agents do) and
the expert's action."""
AGENT_INFO: tuple[str, ...] = ("failure_code", "error")
"""What the agent reads of the env's `info` each step."""
OBJECT_ID_KEYS = frozenset({"objectId", "receptacleObjectId"})


def check_track(track: str) -> str:
    """The track if it is one of `TRACKS`; else LuminousError."""
    if track not in TRACKS:
        raise LuminousError(f"track {track!r}: expected one of {', '.join(TRACKS)}")
    return track


def track_env(track: str, env_kwargs: dict[str, Any] | None) -> dict[str, Any]:
    """The user's env options with the track's observations on; options the track does not allow refused.

    Raises:
        LuminousError: a privileged observation outside the privileged track, object-slot targets outside it,
            or the pose or the expert's action (`NO_TRACK_OPTIONS`: no track allows them).
    """
    check_track(track)
    given = dict(env_kwargs or {})
    for name in NO_TRACK_OPTIONS:
        if given.get(name):
            raise LuminousError(f"env option {name}=true: no track gives an agent the simulator's pose or the "
                                "expert's action (an agent keeps its own pose); leave the option out")
    if track != "privileged":
        wrong = [k for k in PRIVILEGED_OPTIONS if given.get(k)]
        if given.get("targets") == "objects":
            wrong.append("targets=objects")
        if wrong:
            raise LuminousError(f"env option {', '.join(wrong)}: privileged observations (the simulator's, not a "
                                f"camera's) are not part of the {track} track; evaluate with --track privileged")
    return {**given, **{k: True for k in TRACK_OBSERVATIONS[track]}}


def agent_info(info: dict[str, Any], **extra: Any) -> dict[str, Any]:
    """The part of the env's `info` an agent reads (`AGENT_INFO`), with `extra` (the reset's seed and steps)."""
    return {**{k: info.get(k) for k in AGENT_INFO}, **extra}


def object_id_action(action: Any) -> bool:
    """Whether an action names its target by object id (the form no evaluated agent may use)."""
    return isinstance(action, dict) and bool(OBJECT_ID_KEYS & set(action))
