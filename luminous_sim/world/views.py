"""Pictures of a built scene: a labelled top-down view and egocentric snapshots."""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from luminous_sim.scene import Scene, SceneObject
from luminous_sim.world.camera import Frame, render
from luminous_sim.world.label_layout import Box, LabelSpec, PlacedLabel, place_labels
from luminous_sim.world.scene_builder import BuiltScene

AGENT_EYE_HEIGHT = 1.5


def _project(view: np.ndarray, proj: np.ndarray, pts: np.ndarray, w: int, h: int) -> np.ndarray:
    homo = np.hstack([pts, np.ones((len(pts), 1))])
    clip = homo @ view @ proj  # PyBullet matrices are column-major, i.e. row-vector convention
    ndc = clip[:, :3] / clip[:, 3:4]
    return np.stack([(ndc[:, 0] + 1) / 2 * w, (1 - ndc[:, 1]) / 2 * h], axis=1)


@dataclass(frozen=True)
class TopDown:
    """A top-down picture and where its object labels went (boxes in the picture's pixels)."""

    image: Image.Image
    labels: tuple[PlacedLabel, ...]


def top_down(built: BuiltScene, px_per_m: int = 90, labels: bool = True, grid: np.ndarray | None = None,
             path: np.ndarray | None = None) -> Image.Image:
    """The picture of `labelled_top_down`."""
    return labelled_top_down(built, px_per_m=px_per_m, labels=labels, grid=grid, path=path).image


def labelled_top_down(built: BuiltScene, px_per_m: int = 90, labels: bool = True, grid: np.ndarray | None = None,
                      path: np.ndarray | None = None) -> TopDown:
    """A near-orthographic view from high above (north up), every object labelled (`object_labels`); `grid`
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
    drawn = np.zeros((0, 2))
    if path is not None and len(path):
        px = _project(view, proj, np.hstack([path, np.full((len(path), 1), 0.05)]), w, h)
        draw.line([tuple(p) for p in px], fill=(220, 30, 30), width=3)
        for (x, y), colour in ((px[0], (30, 160, 30)), (px[-1], (220, 30, 30))):
            draw.ellipse([x - 5, y - 5, x + 5, y + 5], fill=colour)
        drawn = _densify(px)
    if grid is not None and len(grid):
        pts = _project(view, proj, np.hstack([grid, np.zeros((len(grid), 1))]), w, h)
        for x, y in pts:
            draw.ellipse([x - 2, y - 2, x + 2, y + 2], fill=(40, 160, 255))
    if not labels:
        return TopDown(img, ())

    def to_px(xyz: np.ndarray) -> tuple[float, float]:
        x, y = _project(view, proj, xyz[None], w, h)[0]
        return float(x), float(y)

    rooms = _room_labels(built, to_px)
    placed = place_labels(object_labels(built, to_px), w, h, obstacles=[box for _, box in rooms], avoid=drawn)
    img = draw_labels(img, placed, {o.id: o.layer for o in built.scene.objects})
    draw = ImageDraw.Draw(img)
    for text, box in rooms:
        draw.rectangle(box, fill=(255, 255, 255), outline=ROOM_INK)
        _write(draw, text, box, ROOM_INK)
    return TopDown(img, tuple(placed))


def _densify(line: np.ndarray, spacing: float = 3.0) -> np.ndarray:
    """Points every `spacing` pixels along a polyline (N, 2)."""
    out = [line[:1]]
    for a, b in itertools.pairwise(line):
        n = max(int(np.hypot(*(b - a)) / spacing), 1)
        out.append(a + (b - a) * np.linspace(0, 1, n + 1)[1:, None])
    return np.concatenate(out)


ROOM_INK = (20, 40, 140)
OBJECT_INK = (150, 20, 20)
"""Small objects' labels and markers are red; furniture, fixtures and decorations are labelled in black."""
PIECE_INK = (0, 0, 0)
LEADER_INK = (90, 90, 90)
PAD = 1
"""Pixels of white around a label's text."""


def labelled(scene: Scene) -> list[SceneObject]:
    """The objects a top-down picture labels: all but the parts of a fixture (a stove's knobs, a sink's basin),
    unless the CDF names one."""
    return [o for o in scene.objects if o.layer == "object" or o.parent is None or o.cdf_name is not None]


def object_labels(built: BuiltScene, to_px: Callable[[np.ndarray], tuple[float, float]]) -> list[LabelSpec]:
    """One label per labelled object still there, anchored at its position: its CDF name, else its type (a
    sliced one's, marked so, at the middle of its slices). Small objects come first, so that they get the
    spots nearest them; furniture may be written on itself."""
    font = ImageFont.load_default()
    draw = ImageDraw.Draw(Image.new("RGB", (1, 1)))
    specs = []
    for obj in sorted(labelled(built.scene), key=lambda o: o.layer != "object"):
        text = obj.cdf_name or obj.type
        parts = [obj.id] if obj.id in built.objects else [k for k in built.objects if k.startswith(f"{obj.id}|")]
        if not parts:
            continue
        if parts != [obj.id]:
            text = f"{text} (sliced)"
        anchor = to_px(np.mean([built.pose_of(k)[0] for k in parts], axis=0))
        left, top, right, bottom = draw.textbbox((0, 0), text, font=font)
        size = (right - left + 2 * PAD, bottom - top + 2 * PAD)
        specs.append(LabelSpec(obj.id, text, anchor, size, on_anchor=obj.layer != "object"))
    return specs


def draw_labels(img: Image.Image, placed: list[PlacedLabel], layers: dict[str, str]) -> Image.Image:
    """Write placed labels on `img` (widened with white if some went to the legend column beside it): leader
    lines and anchor dots first, then white boxes with the text."""
    right = max((math.ceil(p.box[2]) for p in placed), default=0)
    if right > img.width:
        wide = Image.new(img.mode, (right + 2, img.height), "white")
        wide.paste(img, (0, 0))
        img = wide
    draw = ImageDraw.Draw(img)
    for p in placed:
        ink = OBJECT_INK if layers.get(p.key) == "object" else PIECE_INK
        end = p.leader_end
        if end is not None:
            draw.line([p.anchor, end], fill=LEADER_INK, width=1)
        if end is not None or layers.get(p.key) == "object":
            x, y = p.anchor
            draw.ellipse([x - 2, y - 2, x + 2, y + 2], fill=ink)
    for p in placed:
        ink = OBJECT_INK if layers.get(p.key) == "object" else PIECE_INK
        draw.rectangle(p.box, fill=(255, 255, 255), outline=(200, 200, 200))
        _write(draw, p.text, p.box, ink)
    return img


def _write(draw: ImageDraw.ImageDraw, text: str, box: Box, ink: tuple[int, int, int]) -> None:
    font = ImageFont.load_default()
    left, top, _, _ = draw.textbbox((0, 0), text, font=font)
    draw.text((box[0] + PAD - left, box[1] + PAD - top), text, fill=ink, font=font)


def _room_labels(built: BuiltScene, to_px: Callable[[np.ndarray], tuple[float, float]]) -> list[tuple[str, Box]]:
    """A house's room names and types, each in a box near the room's lowest (then leftmost) corner, and its
    exterior doorways ("front door") just inside them."""
    shell = built.scene.room
    house = shell.house
    if house is None:
        return []
    font = ImageFont.load_default()
    draw = ImageDraw.Draw(Image.new("RGB", (1, 1)))
    out = []
    for room in house.rooms:
        x0, y0 = min(room.outline, key=lambda p: (p[1], p[0]))
        x, y = to_px(np.array([x0 + 0.15, y0 + 0.15, 0.0]))
        text = f"{room.name} ({room.room_type})"
        left, top, right, bottom = draw.textbbox((0, 0), text, font=font)
        out.append((text, (x, y - (bottom - top) - 2 * PAD, x + right - left + 2 * PAD, y)))
    for door in shell.doors:
        x, y = to_px(np.array([*shell.wall(door.wall).point(door.offset + door.width / 2, 0.3), 0.0]))
        text = "front door"
        left, top, right, bottom = draw.textbbox((0, 0), text, font=font)
        half_w, half_h = (right - left) / 2 + PAD, (bottom - top) / 2 + PAD
        out.append((text, (x - half_w, y - half_h, x + half_w, y + half_h)))
    return out


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


def egocentric(built: BuiltScene, x: float, y: float, yaw_deg: float, horizon_deg: float = 30.0,
               width: int = 300, height: int = 300, fov: float = 60.0) -> Frame:
    """What an agent standing at (x, y), facing yaw (0 = +y, 90 = +x), pitched down by `horizon`, sees."""
    yaw, pitch = math.radians(yaw_deg), math.radians(horizon_deg)
    eye = np.array([x, y, AGENT_EYE_HEIGHT])
    forward = np.array([math.sin(yaw) * math.cos(pitch), math.cos(yaw) * math.cos(pitch), -math.sin(pitch)])
    return render(built.client, eye, eye + forward, width=width, height=height, fov=fov, near=0.05, far=20)
