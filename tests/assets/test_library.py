"""Every asset in the committed library: loads, settles upright, matches its catalog, joints and regions work."""

from __future__ import annotations

import numpy as np
import pytest

from luminous_sim.assets.catalog import Catalog
from tests.assets.physics_checks import (
    CONTAINER_TYPES,
    ball_stays_inside,
    drop_and_settle,
    joint_sweep,
    measured_bbox,
    region_box_in_base,
)

CATALOG = Catalog.load(include_user=False)
ENTRIES = list(CATALOG)
IDS = [e.id for e in ENTRIES]


def test_catalog_is_not_empty():
    assert len(ENTRIES) > 0


@pytest.mark.parametrize("entry", ENTRIES, ids=IDS)
def test_drops_and_rests_upright(entry):
    r = drop_and_settle(entry)
    assert r["min_z"] > -0.015, f"fell through the floor: {r}"
    assert r["tilt_deg"] < 12.0, f"did not stay upright: {r}"
    assert r["speed"] < 0.02 and r["spin"] < 0.2, f"still moving/jittering after 2 s: {r}"
    assert r["drift"] < 0.1, f"slid or rolled away: {r}"


@pytest.mark.parametrize("entry", ENTRIES, ids=IDS)
def test_bbox_matches_catalog(entry):
    lo, hi = measured_bbox(entry)
    dims = np.array(entry.dims)
    tol = np.maximum(0.03, 0.1 * dims)
    assert np.all(np.abs((hi - lo) - dims) <= tol), f"measured {hi - lo} vs catalog {dims}"
    assert np.all(np.abs(lo - np.array(entry.bbox_min)) <= tol)


ARTICULATED = [e for e in ENTRIES if any(j["kind"] != "fixed" for j in e.joints)]


@pytest.mark.parametrize("entry", ARTICULATED, ids=[e.id for e in ARTICULATED])
def test_joints_move_within_limits(entry):
    for name, (at_upper, at_lower) in joint_sweep(entry).items():
        j = next(j for j in entry.joints if j["name"] == name)
        span = j["upper"] - j["lower"]
        eps = 0.02 * span + 1e-3
        assert j["lower"] - eps <= at_upper <= j["upper"] + eps and j["lower"] - eps <= at_lower <= j["upper"] + eps
        assert abs(at_upper - j["upper"]) < 0.1 * span, f"{name} did not open: {at_upper} of {j['upper']}"
        assert abs(at_lower - j["lower"]) < 0.1 * span, f"{name} did not close: {at_lower}"


WITH_REGIONS = [e for e in ENTRIES if e.regions]


@pytest.mark.parametrize("entry", WITH_REGIONS, ids=[e.id for e in WITH_REGIONS])
def test_regions_lie_inside_the_asset(entry):
    lo, hi = np.array(entry.bbox_min) - 0.01, np.array(entry.bbox_max) + 0.01
    for region in entry.regions:
        rlo, rhi = region_box_in_base(entry, region)
        if region["kind"] == "surface":  # the free space may rise above the asset; its base may not leave it
            rhi = rhi.copy()
            rhi[2] = rlo[2]
        assert np.all(rlo >= lo) and np.all(rhi <= hi), f"{region['name']} {rlo}..{rhi} outside {lo}..{hi}"


CONTAINERS = [
    (e, r) for e in ENTRIES for r in e.regions
    if r["kind"] == "volume" and (e.type in CONTAINER_TYPES or (r["link"] != "base" and "drawer" in r["link"]))
]


@pytest.mark.parametrize("entry,region", CONTAINERS, ids=[f"{e.id}:{r['name']}" for e, r in CONTAINERS])
def test_ball_stays_in_container(entry, region):
    inside, where = ball_stays_inside(entry, region)
    assert inside, f"ball left {region['name']}: ended at {where} (local frame)"


def test_every_room_type_object_has_an_asset():
    from luminous_sim.vocab import ROOM_TYPES, SLICED_TYPES, room_objects

    needed = set(SLICED_TYPES)
    for room in ROOM_TYPES:
        needed |= set(room_objects(room))
    missing = sorted(needed - set(CATALOG.types()))
    assert not missing, f"no asset for: {missing}"


def test_every_receptacle_declares_where_things_go():
    from luminous_sim.vocab import receptacle_objects

    missing = [e.id for e in ENTRIES if receptacle_objects(e.type) and not e.regions]
    assert not missing, f"receptacles without support surfaces or volumes: {missing}"


def test_state_visuals_exist_for_toggleable_and_dirtyable_types():
    on_types = {"DeskLamp", "FloorLamp", "Lamp", "Microwave", "Faucet", "StoveBurner", "StoveKnob", "Television",
                "Laptop", "LightSwitch", "CoffeeMachine", "Toaster"}
    dirty_types = {"Bed", "Bowl", "Cloth", "Cup", "Mirror", "Mug", "Pan", "Plate", "Pot"}
    for e in ENTRIES:
        states = {v["state"] for v in e.visuals}
        if e.type in on_types:
            assert "on" in states, f"{e.id} looks the same switched on"
        if e.type in dirty_types:
            assert "dirty" in states, f"{e.id} looks the same dirty"


def test_sliceable_types_know_their_slices():
    for e in ENTRIES:
        if e.type in {"Apple", "Bread", "Lettuce", "Potato", "Tomato"}:
            assert e.slices and e.slices["count"] == len(e.slices["poses"]) >= 2, e.id
            assert CATALOG.of_type(e.slices["type"]), f"no {e.slices['type']} asset"


def test_articulated_types_have_their_joints():
    want = {"Fridge": "door", "Microwave": "door", "Cabinet": "door", "Safe": "door", "Drawer": "drawer",
            "Box": "lid", "Laptop": "lid", "Toilet": "lid"}
    for e in ENTRIES:
        if e.type in want:
            assert any(j["role"] == want[e.type] and j["kind"] != "fixed" for j in e.joints), e.id


SURFACES = [(e, r) for e in ENTRIES for r in e.regions
            if r["kind"] == "surface" and r["link"] == "base" and e.type not in ("StoveBurner", "TowelHolder",
                                                                                 "HandTowelHolder", "ToiletPaperHanger")]  # noqa: E501


@pytest.mark.parametrize("entry,region", SURFACES, ids=[f"{e.id}:{r['name']}" for e, r in SURFACES])
def test_support_surfaces_are_flat_where_declared(entry, region):
    """Downward rays over a support region hit at its declared height (no seams, no pillows in the way)."""
    from luminous_sim.world.asset_loader import load_asset
    from luminous_sim.world.client import new_client

    client = new_client()
    try:
        load_asset(client, entry, fixed=True)
        client.performCollisionDetection()  # rays miss static bodies whose broadphase box is stale
        cx, cy, cz = region["center"]
        sx, sy, clearance = region["size"]
        top = cz + min(clearance, 0.25) - 0.005  # start inside the free space (under any overhang)
        off = []
        for fx in (-0.4, 0.0, 0.4):
            for fy in (-0.4, 0.0, 0.4):
                x, y = cx + fx * sx, cy + fy * sy
                hit = client.rayTest([x, y, top], [x, y, cz - 0.5])[0]
                z = hit[3][2] if hit[0] >= 0 else -1.0
                if abs(z - cz) > 0.025:
                    off.append((round(fx, 1), round(fy, 1), round(z, 3)))
        assert len(off) <= 1, f"surface at z={cz} is not where things would rest: {off}"
    finally:
        client.disconnect()


RIDGE = 0.006
"""Height (m) above a support surface at which a ridge inside its region tilts what rests on it."""


@pytest.mark.parametrize("entry,region", [(e, r) for e, r in SURFACES if e.type != "Plate"],
                         ids=[f"{e.id}:{r['name']}" for e, r in SURFACES if e.type != "Plate"])
def test_nothing_stands_proud_of_a_support_surface_up_to_its_edges(entry, region):
    """Out to the region's edges, nothing within 3 cm above the surface (a bed's turned-down sheet once
    stood 13 mm proud at the head end, and a laptop put there tilted and slid as it settled). Plates are
    left out: their region spans the rising rim on purpose, so that an apple fits on a side plate."""
    from luminous_sim.world.asset_loader import load_asset
    from luminous_sim.world.client import new_client

    client = new_client()
    try:
        load_asset(client, entry, fixed=True)
        client.performCollisionDetection()
        cx, cy, cz = region["center"]
        sx, sy, _ = region["size"]
        proud = []
        for fx in (-0.47, -0.25, 0.0, 0.25, 0.47):
            for fy in (-0.47, -0.25, 0.0, 0.25, 0.47):
                x, y = cx + fx * sx, cy + fy * sy
                hit = client.rayTest([x, y, cz + 0.03], [x, y, cz - 0.5])[0]
                if hit[0] >= 0 and hit[3][2] - cz > RIDGE:
                    proud.append((fx, fy, round(hit[3][2] - cz, 3)))
        assert not proud, f"{entry.id} {region['name']}: ridges above z={cz} at {proud}"
    finally:
        client.disconnect()


STATEFUL = sorted({(e.type, s) for e in ENTRIES for s in ("on", "dirty")
                   if any(v["state"] == s for v in e.visuals)})


@pytest.mark.parametrize("type_name,state", STATEFUL, ids=[f"{t}:{s}" for t, s in STATEFUL])
def test_state_visuals_look_different(type_name, state):
    """Switched on (lit lamp, running water, lit screen) or dirty, an asset renders visibly differently."""
    from luminous_sim.world.asset_loader import load_asset, show_state
    from luminous_sim.world.camera import render
    from luminous_sim.world.client import new_client

    entry = CATALOG.of_type(type_name)[0]
    client = new_client()
    try:
        loaded = load_asset(client, entry, (0.0, 0.0, -entry.bbox_min[2]), fixed=True)
        for j in entry.joints:  # open lids and doors so a lit laptop screen or microwave shows
            if j["kind"] != "fixed":
                from luminous_sim.world.asset_loader import set_joint

                set_joint(client, loaded, j["name"], j["upper"])
        lo, hi = np.array(entry.bbox_min), np.array(entry.bbox_max)
        centre = (lo + hi) / 2 - [0, 0, entry.bbox_min[2]]
        radius = float(np.linalg.norm(hi - lo))
        frames = []
        for active in (False, True):
            show_state(client, loaded, state, active)
            eye = centre + np.array([0.3, 1.0, 0.9]) * radius
            frames.append(render(client, eye, centre, width=96, height=96, fov=45, near=0.01).rgb.astype(int))
        changed = (np.abs(frames[1] - frames[0]).sum(axis=2) > 30).mean()
        assert changed > 0.002, f"{entry.id} looks the same {state} ({changed:.4f} of pixels changed)"
    finally:
        client.disconnect()


def test_fridge_shelves_end_behind_the_closed_doors_shelves():
    """Things put in a fridge must not stand where its door's shelves swing shut (they were pushed 1-4 cm
    while settling)."""
    from luminous_sim.assets.builders.kitchen import DOOR_SHELF_DEPTH
    from luminous_sim.assets.registry import build_spec

    for v in range(4):
        spec = build_spec("Fridge", v)
        door = next(j for j in spec.joints if j.role == "door")
        for r in spec.regions:
            assert r.center[1] + r.size[1] / 2 <= door.origin[1] - DOOR_SHELF_DEPTH, (v, r.name)
