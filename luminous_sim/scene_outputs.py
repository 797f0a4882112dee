"""Write what `luminous generate` produces for one scene: scene JSON, validation report (layout, physics and the
field's scene measures: walkable, accessible and object collision rates, docs/scene_measures.md), a labelled
top-down picture with the reachable grid, and an egocentric snapshot."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from luminous_sim.assets.objio import png_bytes
from luminous_sim.cssg import Generated, HouseGenerated, HouseReport, LayoutReport, floor_measures
from luminous_sim.fileio import write_atomic


def write_scene_outputs(generated: Generated | HouseGenerated, out_dir: Path, physics: bool = True) -> dict:
    """Write the files for one generated scene (a room or a house) into `out_dir`; returns the combined report
    (a house's `layout` holds each room's CSSG report and which rooms its connected floor reaches)."""
    from luminous_sim.world import build_scene, check_physics, egocentric, scene_collisions, top_down

    out_dir = Path(out_dir)
    scene = generated.scene
    report = {**cdf_summary(generated), "layout": generated.report.to_dict(),
              "measures": floor_measures(scene).to_dict()}
    if physics:
        report["physics"] = check_physics(scene).to_dict()
        report["measures"]["collision"] = scene_collisions(scene).to_dict()
    built = build_scene(scene)
    try:
        grid = _reachable(scene)
        write_atomic(out_dir / "top_down.png", png_bytes(top_down(built, grid=grid)))
        if len(grid):
            x, y, yaw = _view_from(scene, grid)
            frame = egocentric(built, x, y, yaw, horizon_deg=15.0, width=400, height=300, fov=75)
            write_atomic(out_dir / "egocentric.png", png_bytes(frame.rgb))
    finally:
        built.close()
    scene.save(out_dir / "scene.json")
    # the CDF summary first (satisfies_cdf, the unplaced objects), then the layout and physics checks
    write_atomic(out_dir / "report.json", json.dumps(report, indent=1) + "\n")
    return report


def cdf_summary(generated: Generated | HouseGenerated) -> dict:
    """The top of report.json: whether the scene satisfies its CDF (every check of the layout report passed, every
    object the CDF names placed), the objects the CDF names that were not placed, and the others (room defaults,
    implicit companions) left out."""
    rep = generated.report
    layouts: list[LayoutReport] = list(rep.rooms.values()) if isinstance(rep, HouseReport) else [rep]
    named = sorted({n for r in layouts for n in r.unplaced if n in r.required})
    others = sorted({n for r in layouts for n in r.unplaced if n not in r.required})
    return {"satisfies_cdf": bool(rep.ok) and not named, "unplaced_named_by_cdf": named, "unplaced_others": others}


def summary_lines(where: Path, report: dict) -> list[str]:
    """What the console says of a scene's report beyond 'valid': a scene that does not satisfy its CDF, and the
    objects left out."""
    lines = []
    if not report["satisfies_cdf"]:
        named = report["unplaced_named_by_cdf"]
        why = f"objects it names were not placed: {', '.join(named)}" if named else "its layout checks failed"
        lines.append(f"warning: {where}: the scene does NOT satisfy its CDF ({why}; report.json says which)")
    others = report["unplaced_others"]
    if others:
        lines.append(f"note: {where}: {len(others)} other object(s) left out: "
                     f"{', '.join(others[:8])}{', ...' if len(others) > 8 else ''}")
    return lines


def _reachable(scene) -> np.ndarray:
    from luminous_sim.scene import scene_reachable_grid

    return scene_reachable_grid(scene)


def _view_from(scene, grid: np.ndarray) -> tuple[float, float, float]:
    """A standing point near the room's middle (a house's largest room's), facing the direction with the most
    room (in a house, up to its interior walls)."""
    from shapely.geometry import Point

    poly = scene.room.polygon()
    c = np.array(poly.centroid.coords[0])
    if scene.room.house is not None:
        biggest = max(scene.room.house.rooms, key=lambda r: (r.polygon().area, r.name))
        c = np.array(biggest.polygon().centroid.coords[0])
        poly = scene.room.free_floor()
    x, y = grid[int(np.argmin(np.linalg.norm(grid - c, axis=1)))]

    def depth(a: float) -> float:
        d = 0.0
        while d < 20 and poly.contains(Point(x + np.sin(np.radians(a)) * d, y + np.cos(np.radians(a)) * d)):
            d += 0.25
        return d

    return float(x), float(y), float(max(range(0, 360, 90), key=depth))
