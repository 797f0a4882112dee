"""What the panel says about a scene: each object's id, type, state and support; room labels; the grid."""

from __future__ import annotations

from luminous_sim.scene import STEP, Scene
from luminous_sim.viewer import object_infos, reachable_points, room_labels


def test_every_object_has_its_type_state_and_support(kitchen: Scene):
    infos = object_infos(kitchen)
    assert set(infos) == {o.id for o in kitchen.objects}
    for o in kitchen.objects:
        info = infos[o.id]
        assert info.object_type == o.type
        if o.parent is not None:
            assert info.support.startswith(f"`{o.parent}`")
        text = info.markdown()
        assert f"`{o.id}`" in text and o.type in text
    fridge = next(o for o in kitchen.objects if o.type == "Fridge")
    assert "isOpen: no" in infos[fridge.id].state


def test_the_live_world_s_states_and_bodies_show(kitchen: Scene):
    fridge = next(o for o in kitchen.objects if o.type == "Fridge")
    infos = object_infos(kitchen, {fridge.id: {"isOpen": True, "temperature": "Cold"},
                                   "Apple|slice_1": {"parentReceptacle": fridge.id}}, {"Apple|slice_1": "AppleSliced"})
    assert "isOpen: yes" in infos[fridge.id].state and "temperature: Cold" in infos[fridge.id].state
    assert infos["Apple|slice_1"].object_type == "AppleSliced" and infos["Apple|slice_1"].support == f"`{fridge.id}`"


def test_a_room_is_labelled_inside_it_and_its_grid_is_on_the_step(kitchen: Scene):
    from shapely.geometry import Point, Polygon

    (label,) = room_labels(kitchen)
    assert kitchen.room.room_type in label.text
    assert Polygon(kitchen.room.outline).contains(Point(label.position))
    pts = reachable_points(kitchen)
    assert len(pts) > 10 and pts.shape[1] == 2
    assert abs(pts / STEP - (pts / STEP).round()).max() < 1e-6
