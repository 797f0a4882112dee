"""Pictures of a built scene: a labelled top-down view and egocentric snapshots."""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import contextmanager

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from luminous_sim.world.camera import Frame, render
from luminous_sim.world.scene_builder import BuiltScene

AGENT_EYE_HEIGHT = 1.5


def _project(view: np.ndarray, proj: np.ndarray, pts: np.ndarray, w: int, h: int) -> np.ndarray:
    homo = np.hstack([pts, np.ones((len(pts), 1))])
    clip = homo @ view @ proj  # PyBullet matrices are column-major, i.e. row-vector convention
    ndc = clip[:, :3] / clip[:, 3:4]
    return np.stack([(ndc[:, 0] + 1) / 2 * w, (1 - ndc[:, 1]) / 2 * h], axis=1)


def top_down(built: BuiltScene, px_per_m: int = 90, labels: bool = True, grid: np.ndarray | None = None,
             path: np.ndarray | None = None) -> Image.Image:
    """A near-orthographic view from high above (north up), with object types written on them; `grid`
    points are drawn as dots and an agent `path` ((N, 2) metres) as a red line from a green start."""
    minx, miny, maxx, maxy = built.scene.room.bounds
    margin = 0.4
    span_x, span_y = maxx - minx + 2 * margin, maxy - miny + 2 * margin
    w, h = int(span_x * px_per_m), int(span_y * px_per_m)
    cx, cy = (minx + maxx) / 2, (miny + maxy) / 2
    height = 40.0
    fov = math.degrees(2 * math.atan(span_y / 2 / height))
    client = built.client
    eye, target = (cx, cy, height), (cx, cy, 0.0)
    with _overhead_away(built):  # seen from above, through the ceiling, and the room alone
        frame = render(client, eye, target, up=(0, 1, 0), width=w, height=h, fov=fov, near=height - 3.5,
                       far=height + 1.0)
    img = Image.fromarray(frame.rgb)
    draw = ImageDraw.Draw(img)
    view = np.array(client.computeViewMatrix(eye, target, [0, 1, 0])).reshape(4, 4)
    proj = np.array(client.computeProjectionMatrixFOV(fov, w / h, height - 3.5, height + 1.0)).reshape(4, 4)
    if path is not None and len(path):
        px = _project(view, proj, np.hstack([path, np.full((len(path), 1), 0.05)]), w, h)
        draw.line([tuple(p) for p in px], fill=(220, 30, 30), width=3)
        for (x, y), colour in ((px[0], (30, 160, 30)), (px[-1], (220, 30, 30))):
            draw.ellipse([x - 5, y - 5, x + 5, y + 5], fill=colour)
    if grid is not None and len(grid):
        pts = _project(view, proj, np.hstack([grid, np.zeros((len(grid), 1))]), w, h)
        for x, y in pts:
            draw.ellipse([x - 2, y - 2, x + 2, y + 2], fill=(40, 160, 255))
    if labels:
        _draw_labels(draw, built, view, proj, w, h)
        _draw_room_labels(draw, built, view, proj, w, h)
    return img


def _draw_room_labels(draw: ImageDraw.ImageDraw, built: BuiltScene, view: np.ndarray, proj: np.ndarray, w: int,
                      h: int) -> None:
    """A house's room names and types, on a white box near each room's lower-left corner."""
    house = built.scene.room.house
    if house is None:
        return
    font = ImageFont.load_default()
    for room in house.rooms:
        x0, y0, _, _ = room.polygon().bounds
        x, y = _project(view, proj, np.array([[x0 + 0.15, y0 + 0.15, 0.0]]), w, h)[0]
        text = f"{room.name} ({room.room_type})"
        _, _, right, bottom = draw.textbbox((0, 0), text, font=font)
        draw.rectangle([x, y - bottom - 4, x + right + 4, y], fill=(255, 255, 255), outline=(20, 40, 140))
        draw.text((x + 2, y - bottom - 2), text, fill=(20, 40, 140), font=font)


@contextmanager
def _overhead_away(built: BuiltScene) -> Iterator[None]:
    """Move the ceiling and the outdoors far below the room for a while, and back."""
    client = built.client
    poses = [client.getBasePositionAndOrientation(b) for b in built.overhead]
    for b, (pos, orn) in zip(built.overhead, poses, strict=True):
        client.resetBasePositionAndOrientation(b, [pos[0], pos[1], pos[2] - 1000.0], orn)
    try:
        yield
    finally:
        for b, (pos, orn) in zip(built.overhead, poses, strict=True):
            client.resetBasePositionAndOrientation(b, pos, orn)


LABEL_SHIFTS = ((0, 0), (0, 11), (0, -11), (0, 22), (0, -22))
"""Pixel offsets tried, in turn, for a label that would overlap one already written."""


def _draw_labels(draw: ImageDraw.ImageDraw, built: BuiltScene, view: np.ndarray, proj: np.ndarray, w: int,
                 h: int) -> None:
    """The type of each piece of furniture, fixture and wall piece, written on it: not of the parts of
    another fixture (a stove's knobs, a sink's basin), and not where it would overlap a label already
    written (moved up or down a line, else left out), so that labels never pile up."""
    font = ImageFont.load_default()
    boxes: list[tuple[float, float, float, float]] = []
    for obj in built.scene.objects:
        if obj.layer == "object" or obj.parent is not None:
            continue
        pos, _ = built.pose_of(obj.id)
        x, y = _project(view, proj, pos[None], w, h)[0]
        _, _, right, bottom = draw.textbbox((0, 0), obj.type, font=font)
        for dx, dy in LABEL_SHIFTS:
            box = (x - right / 2 + dx, y - 5 + dy, x + right / 2 + dx, y - 5 + dy + bottom)
            if not any(box[0] < b[2] and b[0] < box[2] and box[1] < b[3] and b[1] < box[3] for b in boxes):
                boxes.append(box)
                draw.text((box[0], box[1]), obj.type, fill=(0, 0, 0), font=font)
                break


def egocentric(built: BuiltScene, x: float, y: float, yaw_deg: float, horizon_deg: float = 30.0,
               width: int = 300, height: int = 300, fov: float = 60.0) -> Frame:
    """What an agent standing at (x, y), facing yaw (0 = +y, 90 = +x), pitched down by `horizon`, sees."""
    yaw, pitch = math.radians(yaw_deg), math.radians(horizon_deg)
    eye = np.array([x, y, AGENT_EYE_HEIGHT])
    forward = np.array([math.sin(yaw) * math.cos(pitch), math.cos(yaw) * math.cos(pitch), -math.sin(pitch)])
    return render(built.client, eye, eye + forward, width=width, height=height, fov=fov, near=0.05, far=20)
