"""ai2thor 2.1.0's `Event`: what `Controller.step` returns, for one state of a World.

The fields ALFRED's code reads: `metadata` (ai2thor 2.1.0's keys: `agent`, `objects` with their per-object
fields, `inventoryObjects`, `lastAction`, `lastActionSuccess`, `errorMessage`, `reachablePositions`, ...),
`frame` (RGB, uint8 H x W x 3), `depth_frame` (float32 millimetres, as ai2thor 2.1.0 converts it),
`instance_segmentation_frame` (uint8 H x W x 3, one colour per object), `color_to_object_id` /
`object_id_to_color`, `instance_masks` / `instance_detections2D`, `pose`, `pose_discrete`.
"""

from __future__ import annotations

import hashlib
from typing import Any

import numpy as np

STEP_SIZE = 0.25
"""ai2thor 2.1.0's `pose_discrete` grid (hard-coded there too)."""


def object_name(object_id: str, object_type: str) -> str:
    """THOR's object `name`, as our export writes it in `object_poses`: type + '_' + 8 hex digits."""
    return f"{object_type}_{hashlib.sha1(object_id.encode()).hexdigest()[:8]}"


def object_color(object_id: str, taken: set[tuple[int, int, int]]) -> tuple[int, int, int]:
    """A colour for an object's segmentation pixels, from its id (stable across frames and runs), never
    black (the background) and not one in `taken`."""
    digest = hashlib.sha1(object_id.encode()).digest()
    k = 0
    while True:
        r, g, b = digest[k % 18], digest[(k + 1) % 18], digest[(k + 2) % 18]
        color = (int(r), int(g), int(b))
        if color != (0, 0, 0) and color not in taken:
            return color
        k += 1
        if k % 18 == 0:
            digest = hashlib.sha1(digest).digest()


class Event:
    """One step's result: metadata and the images of the agent's camera."""

    def __init__(self, metadata: dict[str, Any], frame: np.ndarray, depth_frame: np.ndarray | None = None,
                 instance_segmentation_frame: np.ndarray | None = None,
                 color_to_object_id: dict[tuple[int, int, int], str] | None = None,
                 instance_masks: dict[str, np.ndarray] | None = None,
                 instance_detections2D: dict[str, Any] | None = None):
        self.metadata = metadata
        self.screen_width = int(metadata.get("screenWidth") or frame.shape[1])
        self.screen_height = int(metadata.get("screenHeight") or frame.shape[0])
        self.frame = frame
        self.depth_frame = depth_frame
        self.normals_frame: np.ndarray | None = None
        self.class_segmentation_frame: np.ndarray | None = None
        self.instance_segmentation_frame = instance_segmentation_frame
        self.color_to_object_id: dict[tuple[int, int, int], str] = dict(color_to_object_id or {})
        self.object_id_to_color: dict[str, tuple[int, int, int]] = {v: k for k, v in self.color_to_object_id.items()}
        self.instance_masks: dict[str, np.ndarray] = dict(instance_masks or {})
        self.instance_detections2D = instance_detections2D
        self.class_masks: dict[str, np.ndarray] = {}
        self.class_detections2D: dict[str, list[Any]] = {}
        for oid, mask in self.instance_masks.items():
            cls = oid.split("|")[0]
            self.class_masks[cls] = mask if cls not in self.class_masks else np.logical_or(self.class_masks[cls], mask)
        for oid, box in (instance_detections2D or {}).items():
            self.class_detections2D.setdefault(oid.split("|")[0], []).append(box)
        self.third_party_camera_frames: list[np.ndarray] = []
        self.events = [self]

    @property
    def cv2img(self) -> np.ndarray:
        return self.frame[..., ::-1]

    @property
    def pose(self) -> tuple[int, int, int, int]:
        """(x, z, rotation, horizon), each times 1000 and rounded, as ai2thor 2.1.0 gives it."""
        agent = self.metadata["agent"]
        loc = agent["position"]
        return (round(loc["x"] * 1000), round(loc["z"] * 1000), round(agent["rotation"]["y"] * 1000),
                round(agent["cameraHorizon"] * 1000))

    @property
    def pose_discrete(self) -> tuple[int, int, int, int]:
        """(x, z) in 0.25 m cells, rotation in quarter turns, horizon in degrees, as ai2thor 2.1.0 gives it."""
        agent = self.metadata["agent"]
        loc = agent["position"]
        return (int(loc["x"] / STEP_SIZE), int(loc["z"] / STEP_SIZE), int(agent["rotation"]["y"] / 90.0),
                round(agent["cameraHorizon"]))

    def get_object(self, object_id: str) -> dict[str, Any] | None:
        for obj in self.metadata["objects"]:
            if obj["objectId"] == object_id:
                return obj
        return None

    def objects_by_type(self, object_type: str) -> list[dict[str, Any]]:
        return [obj for obj in self.metadata["objects"] if obj["objectType"] == object_type]

    def __repr__(self) -> str:
        m = self.metadata
        return (f"<luminous_sim.thor.Event action={m.get('lastAction')!r} success={m.get('lastActionSuccess')} "
                f"error={m.get('errorMessage')!r}>")
