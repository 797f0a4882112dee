"""The main job end to end: generate and furnish a room of each type with CSSG, build them in PyBullet
and write their scene files and pictures; then, in a generated kitchen, sample an ALFRED task, solve
it with the oracle, and write the trajectory, its frames, a video, the instructions and a top-down
picture of the path."""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from PIL import Image
from shapely.geometry import Point

from luminous_sim.assets.objio import write_atomic
from luminous_sim.cssg.baseline import empty_cdf
from luminous_sim.cssg.generate import generate
from luminous_sim.scene.model import Scene
from luminous_sim.vocab import ROOM_TYPES


@dataclass(frozen=True)
class DemoRoom:
    room_type: str
    scene_json: Path
    top_down: Path
    egocentric: list[Path]
    objects: int
    settle_moved: int


def _png(img: Image.Image | np.ndarray, path: Path) -> Path:
    import io

    if isinstance(img, np.ndarray):
        img = Image.fromarray(img)
    buf = io.BytesIO()
    img.save(buf, format="PNG")
    write_atomic(path, buf.getvalue())
    return path


def free_grid(scene: Scene, built) -> np.ndarray:
    """Grid points (0.25 m) an agent could stand on: inside the room, clear of furniture and fixtures."""
    from luminous_sim.cssg.pose import footprint
    from luminous_sim.assets.catalog import default_catalog

    cat = default_catalog()
    blocks = [footprint(cat.for_object(o), o.position[0], o.position[1], o.yaw, margin=0.2)
              for o in scene.objects if o.parent is None]
    pts = scene.room.grid_points(0.25)
    return np.array([p for p in pts if not any(b.contains(Point(p)) for b in blocks)])


def _viewpoints(scene: Scene, grid: np.ndarray, k: int = 2) -> list[tuple[float, float, float]]:
    """`k` standing points spread over the room, each facing where the room is deepest."""
    if len(grid) == 0:
        return []
    poly = scene.room.polygon()
    c = np.array(poly.centroid.coords[0])
    order = np.argsort(np.linalg.norm(grid - c, axis=1))
    picks = [grid[order[0]], grid[order[len(order) // 2]]][:k]
    out = []
    for x, y in picks:
        best = max(range(0, 360, 90), key=lambda a: poly.exterior.distance(Point(x, y)) * 0 +
                   _depth(poly, x, y, a))
        out.append((float(x), float(y), float(best)))
    return out


def _depth(poly, x: float, y: float, yaw_deg: float) -> float:
    d = 0.0
    while poly.contains(Point(x + math.sin(math.radians(yaw_deg)) * d, y + math.cos(math.radians(yaw_deg)) * d)):
        d += 0.25
        if d > 20:
            break
    return d


DEMO_TASKS = ("pick_heat_then_place_in_recep", "pick_cool_then_place_in_recep", "pick_and_place_simple")
"""Task types the demo tries in order until one succeeds (the first is the most involved)."""


def run_demo_episode(out: Path, seed: int = 0):
    """A generated kitchen, an ALFRED task and the oracle's trajectory, written under `out`."""
    from luminous_sim.episode import run_episode

    scene = generate(empty_cdf("Kitchen"), seed=seed).scene
    result = None
    for task_type in DEMO_TASKS:
        result = run_episode(scene, task_type, seed, out_dir=Path(out))
        if result.success:
            break
    return result


def run_demo(out: Path, seed: int = 0, room_types: tuple[str, ...] = ROOM_TYPES) -> list[DemoRoom]:
    """One furnished room per room type: scene JSON, a labelled top-down picture, egocentric views."""
    from luminous_sim.world.scene_builder import build_scene, settle_report
    from luminous_sim.world.views import egocentric, top_down

    out = Path(out)
    results = []
    for i, room_type in enumerate(room_types):
        generated = generate(empty_cdf(room_type), seed=seed)
        scene = generated.scene
        stem = out / f"{i}_{room_type.lower()}"
        scene.save(stem / "scene.json")
        write_atomic(stem / "layout_report.json", json.dumps(generated.report.to_dict(), indent=1) + "\n")
        built = build_scene(scene)
        try:
            report = settle_report(built)
            grid = free_grid(scene, built)
            top = _png(top_down(built, grid=grid), stem / "top_down.png")
            egos = []
            for j, (x, y, yaw) in enumerate(_viewpoints(scene, grid)):
                frame = egocentric(built, x, y, yaw, horizon_deg=15.0, width=480, height=360, fov=75)
                egos.append(_png(frame.rgb, stem / f"egocentric_{j}.png"))
        finally:
            built.client.disconnect()
        write_atomic(stem / "settle.json", json.dumps({"moved": report.moved, "fell": report.fell}, indent=1) + "\n")
        results.append(DemoRoom(room_type, stem / "scene.json", top, egos, len(scene.objects), len(report.moved)))
    return results
