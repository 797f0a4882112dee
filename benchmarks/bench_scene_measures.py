"""Scene quality in the field's own measures (PhyScene's, docs/scene_measures.md), per room type and method.

    python benchmarks/bench_scene_measures.py --n 30                     # cssg, uniform, learned; 30 seeds a type
    python benchmarks/bench_scene_measures.py --n 5 --methods cssg --json out.json

For each method (benchmarks/layout_methods.py: CSSG with the room type's empty CDF, the uniform-random baseline, the
learned layout generator repaired by CSSG; all three furnish the same procedural room per type and seed) and each
seed 0..N-1 of each room type: the object collision rate on the collision meshes (`world.object_collisions`), the
walkable and accessible rates at PhyScene's radius and at the agent's and the issue's wider ones
(`cssg.floor_measures`), and the category KL divergence on presence against AI2-THOR's 30 ALFRED rooms of the type
(`cssg.ckl_figures`: 15 against 15, beside the reference's own split-half, the floor, and categories drawn
uniformly from the catalog, the ceiling). Every seed counts: a method that gives no scene for a seed is counted
as a failure in every measure (walkable and accessible 0, its objects not counted, CKL on the scenes it gave).
One table per measure: the median over scenes, and the share of scenes at the ideal value (to three places) with
its 95% Wilson interval; the collision rate also pooled over objects.

Functional groups (`cssg.room_groups`: seats at a table, a sofa facing the TV or coffee table, side tables at
the bed's head...): per method and room type, the share of rooms holding each group and, of those, the share
where it is met; then the same per room over `--houses` houses of `cdf/examples/houses/default_house.yaml`
(seeds 0..H-1; each room measured as a room of its own, `cssg.house_rooms`), beside CSSG's rooms generated
alone, and the houses' walkable and accessible rates and collision rate as wholes. A house that cannot be
generated counts each of its rooms as holding no group.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from layout_methods import METHODS
from machine import machine
from scipy.stats import binomtest

from luminous_sim import cdf
from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import (
    GROUPS,
    ROBOT_RADIUS,
    GroupState,
    ckl_figures,
    floor_measures,
    generate_house,
    group_rates,
    house_rooms,
    presence,
    reference_rooms,
    room_groups,
)
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.vocab import ROOM_TYPES
from luminous_sim.vocab.agent_body import AGENT_RADIUS

RADII = (ROBOT_RADIUS, AGENT_RADIUS, 0.3)
"""PhyScene's code's half width (the default), our agent's radius, and the issue's 0.3 m."""
HOUSE_CDF = Path(__file__).resolve().parents[1] / "cdf" / "examples" / "houses" / "default_house.yaml"


@dataclass
class Cell:
    """One method's scenes of one room type."""

    seeds: int = 0
    scenes: int = 0
    objects: int = 0
    colliding: int = 0
    scene_collides: list[bool] = field(default_factory=list)
    walkable: dict[float, list[float]] = field(default_factory=dict)
    accessible: dict[float, list[float]] = field(default_factory=dict)
    accessible_all: dict[float, list[float]] = field(default_factory=dict)
    wall_reach: dict[float, list[float]] = field(default_factory=dict)
    inaccessible: dict[str, int] = field(default_factory=dict)
    inaccessible_other: dict[str, int] = field(default_factory=dict)
    out_of_reach: dict[str, int] = field(default_factory=dict)
    presence: list[frozenset[str]] = field(default_factory=list)
    groups: list[dict[str, GroupState]] = field(default_factory=list)
    seconds: list[float] = field(default_factory=list)


def measure_scene(cell: Cell, scene) -> None:
    from luminous_sim.world import scene_collisions

    catalog = default_catalog()
    t0 = time.perf_counter()
    for r in RADII:
        fm = floor_measures(scene, catalog, r)
        cell.walkable.setdefault(r, []).append(fm.walkable_rate)
        cell.accessible.setdefault(r, []).append(fm.accessible_rate)
        cell.accessible_all.setdefault(r, []).append(fm.accessible_rate_all)
        cell.wall_reach.setdefault(r, []).append(fm.wall_reach_rate)
        if r == ROBOT_RADIUS:
            types = {o.id: o.type for o in scene.objects}
            for ids, counts in ((fm.inaccessible, cell.inaccessible), (fm.inaccessible_above, cell.inaccessible_other),
                                (fm.out_of_reach, cell.out_of_reach)):
                for oid in ids:
                    counts[types[oid]] = counts.get(types[oid], 0) + 1
    col = scene_collisions(scene)
    cell.objects += col.objects
    cell.colliding += len(col.colliding)
    cell.scene_collides.append(bool(col.colliding))
    cell.presence.append(presence(scene))
    cell.groups.append(room_groups(scene, catalog))
    cell.seconds.append(time.perf_counter() - t0)


def run(methods: list[str], room_types: list[str], n: int) -> dict[str, dict[str, Cell]]:
    cells: dict[str, dict[str, Cell]] = {}
    for name in methods:
        method = METHODS[name]
        for rt in room_types:
            if rt not in method.room_types:
                continue
            cell = cells.setdefault(name, {}).setdefault(rt, Cell())
            for seed in range(n):
                cell.seeds += 1
                outcome = method.make(rt, seed)
                if outcome.scene is None:
                    for r in RADII:
                        for values in (cell.walkable, cell.accessible, cell.accessible_all, cell.wall_reach):
                            values.setdefault(r, []).append(0.0)
                    cell.scene_collides.append(True)
                    cell.groups.append({g: GroupState(False, False, 0) for g in GROUPS.values()})
                    continue
                cell.scenes += 1
                measure_scene(cell, outcome.scene)
    return cells


@dataclass
class Houses:
    """The houses' rooms per room type, and the houses as wholes."""

    seeds: int = 0
    failed: list[int] = field(default_factory=list)
    rooms: dict[str, list[dict[str, GroupState]]] = field(default_factory=dict)
    whole: Cell = field(default_factory=Cell)


def houses(n: int) -> Houses:
    doc = cdf.load(HOUSE_CDF)
    assert doc.scene.house is not None, HOUSE_CDF
    house_types = [r.type for r in doc.scene.house.rooms]
    out = Houses()
    for seed in range(n):
        out.seeds += 1
        try:
            house = generate_house(doc, seed=seed)
        except InfeasibleSceneError:
            out.failed.append(seed)
            for rt in house_types:
                out.rooms.setdefault(rt, []).append({g: GroupState(False, False, 0) for g in GROUPS.values()})
            continue
        for kind, scene in house_rooms(house).values():
            out.rooms.setdefault(kind, []).append(room_groups(scene))
        out.whole.seeds += 1
        out.whole.scenes += 1
        measure_scene(out.whole, house.scene)
    return out


def group_table(cells: dict[str, dict[str, Cell]], homes: Houses | None) -> tuple[list[str], dict]:
    lines = ["functional groups: rooms holding the group; of those, rooms where it is met"]
    data: dict = {}
    rows = [(m, rt, c.groups) for m, per in cells.items() for rt, c in per.items()]
    if homes is not None:
        rows += [(f"house ({homes.seeds})", rt, g) for rt, g in homes.rooms.items()]
    alone = {(rt, name) for rt, c in cells.get("cssg", {}).items()
             for name, r in group_rates(c.groups).items() if r["held"]}
    for m, rt, groups in rows:
        for name, g in group_rates(groups).items():
            if not g["held"] and not (m.startswith("house") and (rt, name) in alone):
                continue  # a group no room of the type holds (a house room lacking one CSSG's rooms hold is shown)
            lines.append(f"  {m:12s} {rt:10s} {name:38s} held {wilson(g['held'], g['rooms']):>22s}  "
                         f"met {wilson(g['met'], g['held']):>22s}")
            data.setdefault(m, {}).setdefault(rt, {})[name] = g
    if homes is not None:
        w = homes.whole
        lines.append(f"houses as wholes ({w.scenes}/{homes.seeds} generated; failed seeds {homes.failed or 'none'}): "
                     f"objects colliding {wilson(w.colliding, w.objects)}")
        for r in RADII:
            if w.walkable.get(r):
                lines.append(f"  radius {r:g} m: walkable median {statistics.median(w.walkable[r]):.3f}, "
                             f"accessible median {statistics.median(w.accessible[r]):.3f}, "
                             f"at 1.0 {wilson(*_ideal(w.accessible[r], 1.0))}")
        data["houses"] = {"seeds": homes.seeds, "failed": homes.failed, "objects": w.objects,
                          "colliding": w.colliding, "inaccessible": w.inaccessible,
                          "walkable": {str(r): v for r, v in w.walkable.items()},
                          "accessible": {str(r): v for r, v in w.accessible.items()}}
    return lines, data


def wilson(k: int, n: int) -> str:
    if not n:
        return "n/a"
    ci = binomtest(k, n).proportion_ci(method="wilson")
    return f"{k / n:.3f} [{ci.low:.3f}, {ci.high:.3f}]"


def _ideal(values: list[float], ideal: float) -> tuple[int, int]:
    """Scenes at the ideal as the tables print it, to three places (a 1 cm^2 sliver of floor cut off by exact
    geometry does not make a room unwalkable)."""
    return sum(round(v, 3) == ideal for v in values), len(values)


def tables(cells: dict[str, dict[str, Cell]], draws: int) -> tuple[str, dict]:
    catalog_types = default_catalog().types()
    lines: list[str] = []
    data: dict = {}
    lines.append("object collision rate (collision meshes, support and containment excluded)")
    lines.append(f"  {'method':8s} {'room type':10s} {'scenes':>9s} {'objects colliding (pooled)':>30s} "
                 f"{'scenes with none':>24s}")
    for m, per in cells.items():
        for rt, c in per.items():
            free = sum(not x for x in c.scene_collides)
            lines.append(f"  {m:8s} {rt:10s} {c.scenes:4d}/{c.seeds:<4d} {wilson(c.colliding, c.objects):>30s} "
                         f"{wilson(free, c.seeds):>24s}")
            data.setdefault(m, {}).setdefault(rt, {})["collision"] = {
                "objects": c.objects, "colliding": c.colliding, "scenes": c.scenes, "seeds": c.seeds,
                "scenes_without": free}
    for label, attr in (("walkable rate", "walkable"), ("accessible rate (things on the floor)", "accessible"),
                        ("accessible rate over every thing (wall pieces, things centred high)", "accessible_all"),
                        ("wall pieces within the agent's reach (1.5 m from its camera)", "wall_reach")):
        for r in RADII:
            lines.append(f"{label} at radius {r:g} m: median over scenes, scenes at 1.0")
            for m, per in cells.items():
                for rt, c in per.items():
                    values = getattr(c, attr)[r]
                    k, total = _ideal(values, 1.0)
                    lines.append(f"  {m:8s} {rt:10s} median {statistics.median(values):.3f}  at 1.0 {wilson(k, total)}")
                    data[m][rt].setdefault(attr, {})[str(r)] = {"median": statistics.median(values),
                                                                "at_ideal": k, "seeds": total}
    lines.append(f"category KL on presence against AI2-THOR's ALFRED rooms (15 against 15, median of {draws} halves)")
    lines.append(f"  {'method':8s} {'room type':10s} {'floor':>7s} {'method':>7s} {'ceiling':>8s}  closer to")
    for m, per in cells.items():
        for rt, c in per.items():
            if len(c.presence) < 15:
                lines.append(f"  {m:8s} {rt:10s} n/a ({len(c.presence)} scenes; needs 15)")
                continue
            f = ckl_figures(reference_rooms(rt), c.presence, catalog_types, draws=draws)
            closer = "floor" if f.generated - f.floor < f.ceiling - f.generated else "ceiling"
            lines.append(f"  {m:8s} {rt:10s} {f.floor:7.3f} {f.generated:7.3f} {f.ceiling:8.3f}  {closer}")
            data[m][rt]["ckl"] = f.to_dict()
    lines.append("missed at the default radius, by type (scenes' objects): on the floor | wall pieces and high things "
                 "| wall pieces out of reach")
    for m, per in cells.items():
        for rt, c in per.items():
            parts = [", ".join(f"{t} {k}" for t, k in sorted(d.items(), key=lambda kv: -kv[1])[:6]) or "none"
                     for d in (c.inaccessible, c.inaccessible_other, c.out_of_reach)]
            lines.append(f"  {m:8s} {rt:10s} " + " | ".join(parts))
            data[m][rt].update(inaccessible=c.inaccessible, inaccessible_other=c.inaccessible_other,
                               out_of_reach=c.out_of_reach)
            data[m][rt]["seconds_median"] = statistics.median(c.seconds) if c.seconds else None
    return "\n".join(lines), data


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--n", type=int, default=30, help="seeds per room type (default 30)")
    parser.add_argument("--methods", nargs="+", default=["cssg", "uniform", "learned"], choices=sorted(METHODS))
    parser.add_argument("--room-types", nargs="+", default=list(ROOM_TYPES), choices=list(ROOM_TYPES))
    parser.add_argument("--draws", type=int, default=200, help="random halves for CKL (default 200)")
    parser.add_argument("--houses", type=int, default=20, help="houses for the functional groups (default 20; 0: none)")
    parser.add_argument("--json", type=Path, default=None, help="also write the figures here")
    args = parser.parse_args(argv)
    print(machine())
    start = time.perf_counter()
    cells = run(args.methods, args.room_types, args.n)
    text, data = tables(cells, args.draws)
    print(text)
    lines, data["groups"] = group_table(cells, houses(args.houses) if args.houses else None)
    print("\n".join(lines))
    print(f"{time.perf_counter() - start:.0f} s")
    if args.json is not None:
        args.json.write_text(json.dumps(data, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
