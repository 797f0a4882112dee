"""Scene-synthesis measures as the field reports them (PhyScene, and DiffuScene, ATISS, InstructScene after it),
read off a finished scene's geometry alone, so that every generator is measured the same way
([scene_measures.md](../../docs/scene_measures.md)):

- walkable rate: the free floor (the floor less interior walls and the footprints of what stands in the agent's
  way) eroded by the robot's radius, the part of it connected to the door, over all of it;
- accessible rate: the things on the floor whose footprint, dilated by the robot's radius, meets a walkable region,
  as a share of them, each region weighted by its share of the walkable area (PhyScene's `accessable_rate`);
  beside it the same over every thing, wall pieces and high ones too, and the wall pieces within the agent's
  reach (ALFRED's 1.5 m from the camera) of the walkable floor;
- category presence per room and the category KL divergence (CKL) between two sets of rooms.

The object collision rate needs the objects' collision meshes, so it lives with the simulator
(`world.object_collisions`). Followed: PhyScene's published evaluation code (`scripts/eval/walkable_metric.py`
and its accessibility loop), with the choices stated in the doc above: exact polygons instead of a 256-pixel
image, a round (not square) erosion, the door reached within the radius and 5 cm.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, field
from statistics import median

import shapely
from shapely.geometry import Point
from shapely.geometry.base import BaseGeometry

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.scene import Scene, SceneObject, blocks_agent, footprint
from luminous_sim.vocab.agent_body import CAMERA_HEIGHT, VISIBILITY_DISTANCE

ROBOT_RADIUS = 0.15
"""Metres the free floor is eroded by, and each object's footprint dilated by: half of PhyScene's `robot_width`
of 0.3 m, which its code uses as the width of a square erosion kernel and of the line drawn round each box."""
REACH_SLACK = 0.05
"""A region meets the door, or an object, within the radius and this much more (PhyScene: one pixel more)."""
MEASURED_HEIGHT = 1.5
"""Objects whose centre is higher (wall cabinets, shelves over a counter) are left out of the accessible rate, as
PhyScene leaves boxes centred above 1.5 m out of its floor map; `accessible_rate_all` keeps them."""
WALL_LAYER = "decoration"
"""The layer of what hangs on a wall (paintings, switches, towel holders, windows' blinds): not on the floor, so
out of PhyScene's population (3D-FRONT's rooms have no such things), measured by reach instead."""


@dataclass
class FloorMeasures:
    """The walkable and accessible rates of one scene (a room, or a house as a whole)."""

    walkable_rate: float
    accessible_rate: float
    accessible_rate_all: float
    """The accessible rate over every top-level thing, wall pieces and things centred high included."""
    wall_reach_rate: float
    """The wall pieces within the agent's reach (VISIBILITY_DISTANCE from its camera, standing on a walkable
    region), weighted by region as the accessible rate is; 1.0 when there are none."""
    walkable_area: float
    """Square metres of free floor after erosion (the walkable rate's denominator)."""
    regions: int
    """Connected regions of the eroded free floor."""
    objects: int
    """Top-level things on the floor centred below MEASURED_HEIGHT (the accessible rate's population)."""
    wall_pieces: int = 0
    """Top-level things on the walls (WALL_LAYER; `wall_reach_rate`'s population)."""
    inaccessible: list[str] = field(default_factory=list)
    """Ids of those on the floor that no walkable region meets."""
    inaccessible_above: list[str] = field(default_factory=list)
    """Ids of the other things (wall pieces, things centred higher) that no walkable region meets within the radius
    (the rest of `accessible_rate_all`'s misses)."""
    out_of_reach: list[str] = field(default_factory=list)
    """Ids of the wall pieces out of the agent's reach from every walkable region."""
    doors: list[str] = field(default_factory=list)
    """The doors whose region was measured (their rates averaged, as PhyScene does); empty: no door, the largest
    region stands for the door's."""

    def to_dict(self) -> dict:
        return {k: round(v, 4) if isinstance(v, float) else v for k, v in asdict(self).items()}


def _measured(obj: SceneObject) -> bool:
    return obj.parent is None and obj.layer != "structure"


def _on_floor(obj: SceneObject, catalog: Catalog) -> bool:
    return obj.layer != WALL_LAYER and _centre_height(obj, catalog) <= MEASURED_HEIGHT


def free_floor(scene: Scene, catalog: Catalog | None = None, radius: float = ROBOT_RADIUS) -> BaseGeometry:
    """Where the robot's centre may be: the floor (less a house's interior walls) eroded by `radius`, less every
    footprint that stands in the agent's way (`scene.blocks_agent`) dilated by `radius`. The things themselves,
    not the room's fixture slots (a toilet's slot is deeper than the toilet)."""
    catalog = catalog or default_catalog()
    room = scene.room
    walls = room.interior_footprints()
    floor = room.polygon().difference(shapely.union_all(walls)) if walls else room.polygon()
    floor = floor.buffer(-radius, join_style="mitre")
    feet = [footprint(e, o.position[0], o.position[1], o.yaw).buffer(radius)
            for o in scene.objects if blocks_agent(o, e := catalog.for_object(o))]
    return floor.difference(shapely.union_all(feet)) if feet else floor


def _regions(free: BaseGeometry) -> list[BaseGeometry]:
    parts = list(getattr(free, "geoms", [free]))
    return [p for p in parts if not p.is_empty and p.area > 1e-9]


def _door_points(scene: Scene) -> list[tuple[str, Point]]:
    room = scene.room
    return [(d.id, Point(room.wall(d.wall).point(d.offset + d.width / 2))) for d in room.doors]


def floor_measures(scene: Scene, catalog: Catalog | None = None, radius: float = ROBOT_RADIUS) -> FloorMeasures:
    """The walkable and accessible rates of `scene` for a robot of `radius`."""
    catalog = catalog or default_catalog()
    regions = _regions(free_floor(scene, catalog, radius))
    total = sum(r.area for r in regions)
    doors = _door_points(scene)
    things = [o for o in scene.objects if _measured(o)]
    low = {o.id for o in things if _on_floor(o, catalog)}
    wall = sorted(o.id for o in things if o.layer == WALL_LAYER)
    if not total:
        high = sorted(o.id for o in things if o.id not in low)
        return FloorMeasures(0.0, 0.0, 0.0, 0.0, 0.0, 0, len(low), len(wall), sorted(low), high, wall,
                             [d for d, _ in doors])
    if doors:
        rates = []
        for _, point in doors:
            near = [(r.distance(point), i) for i, r in enumerate(regions)]
            dist, best = min(near)
            rates.append(regions[best].area / total if dist <= radius + REACH_SLACK else 0.0)
        walkable = sum(rates) / len(rates)
    else:
        walkable = max(r.area for r in regions) / total
    shapes = {o.id: footprint(catalog.for_object(o), o.position[0], o.position[1], o.yaw) for o in things}
    meets = {oid: {i for i, r in enumerate(regions) if shp.distance(r) <= radius + REACH_SLACK}
             for oid, shp in shapes.items()}
    heights = {o.id: abs(_centre_height(o, catalog) - CAMERA_HEIGHT) for o in things if o.layer == WALL_LAYER}
    reaches = {oid: {i for i, r in enumerate(regions) if math.hypot(shapes[oid].distance(r), h) <= VISIBILITY_DISTANCE}
               for oid, h in heights.items()}

    def rate(ids: Sequence[str], by: Mapping[str, set[int]]) -> float:
        if not ids:
            return 1.0
        return sum(sum(1 for oid in ids if i in by[oid]) / len(ids) * r.area / total
                   for i, r in enumerate(regions))

    missed = {oid for oid, m in meets.items() if not m}
    return FloorMeasures(walkable, rate(sorted(low), meets), rate(sorted(shapes), meets), rate(wall, reaches), total,
                         len(regions), len(low), len(wall), sorted(missed & low), sorted(missed - low),
                         sorted(oid for oid, m in reaches.items() if not m), [d for d, _ in doors])


def _centre_height(obj: SceneObject, catalog: Catalog) -> float:
    entry = catalog.for_object(obj)
    return obj.position[2] + (entry.bbox_min[2] + entry.bbox_max[2]) / 2


def presence(scene: Scene, windows: bool = True) -> frozenset[str]:
    """The object types a room holds (a house: all its rooms'); with `windows`, `Window` when the shell has one (a
    window is part of our room shell, an object in AI2-THOR's lists)."""
    types = {o.type for o in scene.objects}
    if windows and scene.room.windows:
        types.add("Window")
    return frozenset(types)


SMOOTHING = 0.5
"""Added to every category's room count before the frequencies are normalised (so that a category one side never
shows does not make the divergence infinite)."""


def category_kl(reference: Iterable[Iterable[str]], generated: Iterable[Iterable[str]],
                vocabulary: Iterable[str] | None = None, smoothing: float = SMOOTHING) -> float:
    """KL(reference || generated) of the category frequencies of two sets of rooms, on presence: each category's
    count is the rooms that hold it, plus `smoothing`, over `vocabulary` (default: every category either side
    shows), normalised to a distribution. Natural log."""
    ref, gen = Counter(), Counter()
    for types in reference:
        ref.update(set(types))
    for types in generated:
        gen.update(set(types))
    vocab = sorted(set(vocabulary) if vocabulary is not None else set(ref) | set(gen))
    p = _normalised(ref, vocab, smoothing)
    q = _normalised(gen, vocab, smoothing)
    return float(sum(pi * math.log(pi / qi) for pi, qi in zip(p, q) if pi > 0))


def _normalised(counts: Mapping[str, int], vocab: Sequence[str], smoothing: float) -> list[float]:
    raw = [counts.get(c, 0) + smoothing for c in vocab]
    total = sum(raw)
    return [r / total for r in raw]


@dataclass(frozen=True)
class CKLFigures:
    """CKL on equal halves: the reference's own split-half (the floor), the generator, and categories drawn
    uniformly from the catalog (the ceiling); each the median over `draws` random halves."""

    floor: float
    generated: float
    ceiling: float
    half: int
    draws: int

    def to_dict(self) -> dict:
        return {k: round(v, 4) if isinstance(v, float) else v for k, v in asdict(self).items()}


def ckl_figures(reference: Sequence[frozenset[str]], generated: Sequence[frozenset[str]], catalog_types: Sequence[str],
                draws: int = 200, seed: int = 0) -> CKLFigures:
    """CKL like for like: each draw splits the reference rooms into two random halves A and B; the floor is
    KL(A || B), the generator's KL(A || a random sample of as many generated rooms), the ceiling KL(A || as many
    rooms of categories drawn uniformly from `catalog_types`, each room as many as a reference room of B holds).
    The vocabulary is the reference's and the catalog's categories together."""
    rng = random.Random(seed)
    half = len(reference) // 2
    if half < 1 or len(generated) < half:
        raise ValueError(f"ckl_figures needs at least 2 reference rooms and {half} generated rooms, "
                         f"got {len(reference)} and {len(generated)}")
    vocab = sorted({c for r in reference for c in r} | set(catalog_types))
    floor, gen, ceiling = [], [], []
    for _ in range(draws):
        order = rng.sample(range(len(reference)), len(reference))
        a = [reference[i] for i in order[:half]]
        b = [reference[i] for i in order[half:2 * half]]
        sample = rng.sample(list(generated), half)
        uniform = [frozenset(rng.sample(list(catalog_types), min(len(r), len(catalog_types)))) for r in b]
        floor.append(category_kl(a, b, vocab))
        gen.append(category_kl(a, sample, vocab))
        ceiling.append(category_kl(a, uniform, vocab))
    return CKLFigures(median(floor), median(gen), median(ceiling), half, draws)

