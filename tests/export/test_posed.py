"""The world read out for export: bodies as they are (slices for the sliced apple, doors at their open
angle), states, and the structure."""

from __future__ import annotations

import pytest

from luminous_sim.scene import Scene


def test_sliced_apple_is_its_slices_and_open_doors_are_open(changed: Scene, posed) -> None:
    apple = next(o for o in changed.objects if o.type == "Apple")
    ids = {o.object_id for o in posed.objects}
    assert apple.id not in ids
    slices = [o for o in posed.objects if o.object_id.startswith(f"{apple.id}|AppleSliced_")]
    assert len(slices) >= 2 and all(o.object_type == "AppleSliced" and o.states["isSliced"] for o in slices)
    fridge = next(o for o in posed.objects if o.object_type == "Fridge")
    assert fridge.states["isOpen"]
    door = next(j for j in fridge.joints if j.role == "door")
    assert door.value == pytest.approx(door.upper, abs=1e-3)


def test_every_body_is_read_out_with_its_links(world, posed) -> None:
    assert {o.object_id for o in posed.objects} == set(world.built.objects)
    for obj in posed.objects:
        assert obj.links[0].name == "base"
        assert {link.name for link in obj.links} == set(world.built.objects[obj.object_id].link_index)
    kinds = {b.kind for b in posed.structure}
    assert kinds == {"floor", "wall", "ceiling", "light"}
    assert sum(not b.visible for b in posed.structure) == 1  # the hidden floor under the slabs


def test_slicing_at_set_up_is_refused_once_the_episode_started(changed: Scene) -> None:
    from luminous_sim.errors import LuminousError
    from luminous_sim.world import World

    with World(changed) as w:
        w.step("RotateLeft")
        with pytest.raises(LuminousError, match="set_up_sliced is scene set-up"):
            w.set_up_sliced(["anything"])


def test_hidden_state_visuals_are_left_out(posed) -> None:
    from luminous_sim.export.meshes import visual_parts

    hidden = 0
    for obj in posed.objects:
        shown = {(p.link, int(p.name.rsplit("_", 1)[1])) for p in visual_parts(obj)}
        assert shown == {key for key, rgba in obj.colours.items() if rgba[3] > 0}, obj.object_id
        hidden += sum(rgba[3] == 0 for rgba in obj.colours.values())
    assert hidden > 0  # the kitchen has switched-off appliances and clean dishes: their "on"/"dirty" visuals
