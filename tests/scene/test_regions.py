"""Sampling spots in receptacle regions: the fast intersection test draws exactly what testing every
footprint with shapely draws."""

from __future__ import annotations

import math

import numpy as np
import pytest
from shapely.geometry import Polygon, box

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.scene.pose import rotate
from luminous_sim.scene.regions import EDGE_INSET, RegionSpot, sample_in_region


def _reference(entry, spot, rng, occupied, tries=20):
    """sample_in_region as first written: a shapely polygon and intersects() per footprint and try."""
    lo, hi = np.array(entry.bbox_min[:2]), np.array(entry.bbox_max[:2])
    center_local, half = (lo + hi) / 2, (hi - lo) / 2
    for _ in range(tries):
        k = int(rng.integers(4))
        ex, ey = half if k % 2 == 0 else half[::-1]
        room_x, room_y = spot.size[0] / 2 - ex, spot.size[1] / 2 - ey
        if room_x < 0 or room_y < 0:
            continue
        room_x -= min(EDGE_INSET, room_x / 2)
        room_y -= min(EDGE_INSET, room_y / 2)
        px, py = rng.uniform(-room_x, room_x), rng.uniform(-room_y, room_y)
        target = rotate(np.array([[px, py]]), spot.yaw)[0] + spot.center
        yaw = spot.yaw + k * math.pi / 2
        origin = target - rotate(center_local[None], yaw)[0]
        corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [hi[0], hi[1]], [lo[0], hi[1]]])
        fp = Polygon(rotate(corners, yaw) + origin)
        if any(fp.intersects(o) for o in occupied):
            continue
        return float(origin[0]), float(origin[1]), yaw, fp
    return None


@pytest.mark.parametrize("yaw", [0.0, math.pi / 2, math.pi, 0.3])
@pytest.mark.parametrize("object_type", ["Mug", "Pan", "Knife"])
def test_fast_intersection_test_draws_what_shapely_draws(yaw, object_type):
    entry = default_catalog().of_type(object_type)[0]
    spot = RegionSpot(None, "top", "surface", (1.0, 2.0), (0.6, 0.4), 0.9, 0.5, yaw)  # type: ignore[arg-type]
    for seed in range(25):
        occupied = [box(0.95, 1.95, 1.05, 2.08)]
        mine, ref = np.random.default_rng(seed), np.random.default_rng(seed)
        for _ in range(8):
            a, b = sample_in_region(entry, spot, mine, occupied), _reference(entry, spot, ref, occupied)
            assert (a is None) == (b is None)
            if a is None:
                break
            assert (a[0], a[1], a[3]) == b[:3] and a[4].equals_exact(b[3], 0.0)
            occupied.append(a[4])


def test_a_region_covered_beyond_max_fill_is_given_up_at_once():
    entry = default_catalog().of_type("Mug")[0]
    spot = RegionSpot(None, "top", "surface", (0.0, 0.0), (0.6, 0.4), 0.9, 0.5, 0.0)  # type: ignore[arg-type]
    half_full = [box(-0.3, -0.2, 0.0, 0.2)]  # half the region's 0.24 m2
    rng = np.random.default_rng(0)
    state = rng.bit_generator.state
    assert sample_in_region(entry, spot, rng, half_full, max_fill=0.5) is None
    assert rng.bit_generator.state == state  # nothing drawn
    assert sample_in_region(entry, spot, rng, half_full, max_fill=0.9) is not None
    assert sample_in_region(entry, spot, np.random.default_rng(0), half_full) is not None  # no limit by default


def test_a_scan_finds_the_one_gap_that_random_draws_miss():
    """A 0.6 x 0.4 table top covered but for one gap 4 cm wider than a small object: twenty random draws
    seldom land it there, the scan does, and says none where there is no gap."""
    from luminous_sim.scene.regions import scan_region

    cube = next(e for t in ("Egg", "KeyChain", "SoapBar", "CreditCard") for e in default_catalog().of_type(t)
                if max(e.dims[:2]) < 0.12 and e.dims[2] < 0.4)
    spot = RegionSpot(None, "top", "surface", (0.0, 0.0), (0.6, 0.4), 0.9, 0.5, 0.0)  # type: ignore[arg-type]
    x0, y0 = 0.05, -0.05
    x1, y1 = x0 + max(cube.dims[:2]) + 0.04, y0 + max(cube.dims[:2]) + 0.04  # 2 cm to spare each way
    gap = box(x0, y0, x1, y1)
    occupied = [box(-0.3, -0.2, x0, 0.2), box(x1, -0.2, 0.3, 0.2),  # footprints all around the gap
                box(x0, -0.2, x1, y0), box(x0, y1, x1, 0.2)]
    misses = sum(sample_in_region(cube, spot, np.random.default_rng(s), occupied) is None for s in range(20))
    got = next(scan_region(cube, spot, occupied), None)
    assert got is not None and gap.buffer(1e-6).contains(got[4])
    assert misses > 10
    assert next(scan_region(cube, spot, occupied + [gap]), None) is None


def test_can_hold_counts_height_unless_open_at_the_top_and_things_side_by_side():
    """A plunger stands only on a cabinet shelf taller than it; two spray bottles stand side by side only in
    a garbage can wide enough for both; an open can's rim does not limit what goes in it."""
    from luminous_sim.scene import can_hold

    cat = default_catalog()
    by_id = {e.id: e for t in ("Cabinet", "Plunger", "GarbageCan", "SprayBottle", "Pan", "Apple")
             for e in cat.of_type(t)}
    plunger = by_id["Plunger_02"]  # 0.55 m tall
    assert [e.id for e in cat.of_type("Cabinet") if can_hold(e, plunger)] == ["Cabinet_05"]  # 0.58 m shelves
    spray = by_id["SprayBottle_02"]  # 9 x 11 cm
    assert can_hold(by_id["GarbageCan_00"], spray) and not can_hold(by_id["GarbageCan_00"], spray, 2)
    assert can_hold(by_id["GarbageCan_01"], spray, 2)  # 20.7 cm inside: 2 x 9 cm in a row
    tall = by_id["GarbageCan_02"]
    assert tall.regions[0]["size"][2] < 0.6 and can_hold(tall, plunger)  # open at the top: it may stand out
    assert not can_hold(by_id["Pan_00"], by_id["Plunger_00"])  # 14 cm wide, the pan 12 cm inside


@pytest.mark.parametrize("yaw", [0.0, 0.7])
def test_edge_slides_move_a_pose_to_a_corner_then_across_its_short_side_leaving_room_beside_it(yaw):
    """A 49 x 25 cm pan drawn in the middle of a 54 x 57 cm counter leaves no room for a second; slid to a
    corner, or against the edge across its short side, it does."""
    from luminous_sim.scene import edge_slides, scan_region

    pan = next(e for e in default_catalog().of_type("Pan") if e.id == "Pan_01")
    spot = RegionSpot(None, "top", "surface", (1.0, 2.0), (0.54, 0.573), 0.9, 0.5, yaw)  # type: ignore[arg-type]
    got = sample_in_region(pan, spot, np.random.default_rng(3), [], tries=50)
    assert got is not None
    slides = edge_slides(got, spot)
    assert len(slides) >= 2
    region = Polygon(rotate(np.array([[-0.27, -0.2865], [0.27, -0.2865], [0.27, 0.2865], [-0.27, 0.2865]]), yaw)
                     + np.array([1.0, 2.0]))
    for _x, _y, z, turn, fp in slides[:2]:
        assert region.buffer(1e-6).contains(fp) and (z, turn) == got[2:4]
        assert next(scan_region(pan, spot, [fp]), None) is not None  # room for a second pan beside it
    assert next(scan_region(pan, spot, [got[4]]), None) is None  # where it was drawn, none
    corner = slides[0][4]
    assert region.exterior.distance(corner) < 0.011  # against the edge, a centimetre off it
