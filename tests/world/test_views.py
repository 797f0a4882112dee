"""Top-down pictures: labels name each piece once and never pile up."""

from __future__ import annotations

from PIL import ImageDraw

from luminous_sim.cssg import empty_cdf, generate
from luminous_sim.world.scene_builder import build_scene
from luminous_sim.world.views import top_down


def test_labels_skip_fixture_parts_and_never_overlap(monkeypatch):
    scene = generate(empty_cdf("Kitchen"), seed=0).scene
    assert any(o.type == "StoveKnob" for o in scene.objects)
    written: list[tuple[float, float, str]] = []
    original = ImageDraw.ImageDraw.text

    def spy(self, xy, text, *args, **kwargs):
        written.append((xy[0], xy[1], text))
        return original(self, xy, text, *args, **kwargs)

    monkeypatch.setattr(ImageDraw.ImageDraw, "text", spy)
    built = build_scene(scene, settle_steps=0)
    try:
        img = top_down(built, px_per_m=80, labels=True)
    finally:
        built.client.disconnect()
    draw = ImageDraw.Draw(img)
    assert written and not {t for _, _, t in written} & {"StoveKnob", "StoveBurner", "SinkBasin", "Faucet"}
    boxes = []
    for x, y, t in written:
        _, _, w, h = draw.textbbox((0, 0), t)
        boxes.append((x, y, x + w, y + h))
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]), (a, b)


def test_a_ceiling_overhead_and_the_outdoors_beyond_but_not_from_above():
    import numpy as np

    from luminous_sim.scene import scene_reachable_grid
    from luminous_sim.world.views import egocentric

    scene = generate(empty_cdf("Bedroom"), seed=0).scene
    built = build_scene(scene, settle_steps=0)
    try:
        x, y = scene_reachable_grid(scene)[0]
        up = egocentric(built, float(x), float(y), 0.0, horizon_deg=-80.0).rgb[..., :3]
        white = np.all(up >= 250, axis=-1).mean()
        assert white < 0.01, f"{white:.0%} of the view up is the white void"
        top = np.asarray(top_down(built, px_per_m=40, labels=False))
        poses = [built.client.getBasePositionAndOrientation(b)[0][2] for b in built.overhead]
        for b in built.overhead:
            built.client.removeBody(b)
        built.overhead.clear()
        bare = np.asarray(top_down(built, px_per_m=40, labels=False))
    finally:
        built.client.disconnect()
    assert np.array_equal(top, bare)  # from above: the room alone, as without ceiling and outdoors
    assert max(poses) > scene.room.wall_height - 0.1  # and the ceiling put back after the picture


def test_every_object_is_labelled_by_its_cdf_name_and_no_labels_overlap():
    import itertools

    from luminous_sim import cdf
    from luminous_sim.world.label_layout import boxes_overlap
    from luminous_sim.world.views import labelled, labelled_top_down
    from tests.world.conftest import EXAMPLES

    doc = cdf.load(EXAMPLES / "kitchen_coffee_mug.yaml")
    scene = generate(doc, seed=0).scene
    small = [o for o in scene.objects if o.layer == "object"]
    assert len(small) >= 15
    built = build_scene(scene, settle_steps=0)
    try:
        picture = labelled_top_down(built, px_per_m=90)
    finally:
        built.client.disconnect()
    by_id = {label.key: label for label in picture.labels}
    assert len(by_id) == len(picture.labels)
    assert set(by_id) == {o.id for o in labelled(scene)} >= {o.id for o in small}
    assert {o.type for o in scene.objects if o.id not in by_id} <= {"StoveKnob", "StoveBurner", "SinkBasin", "Faucet"}
    for a, b in itertools.combinations(picture.labels, 2):
        assert not boxes_overlap(a.box, b.box), (a, b)
    assert all(0 <= label.box[0] and label.box[2] <= picture.image.width for label in picture.labels)
    names = {o.name: by_id[o.id].text for o in scene.objects if o.name in {s.name for s in doc.scene.objects}}
    assert names == {n: n for n in ("counter", "coffee_machine", "table", "stool", "mug")}
    auto = next(o for o in small if o.name and o.name.endswith("_auto0"))
    assert by_id[auto.id].text == auto.type


def test_a_sliced_object_is_labelled_at_its_slices_and_a_gone_one_not_at_all():
    from luminous_sim.world.views import labelled_top_down

    scene = generate(empty_cdf("Kitchen"), seed=0).scene
    small = [o for o in scene.objects if o.layer == "object"]
    sliced, gone = small[0], small[1]
    built = build_scene(scene, settle_steps=0)
    try:
        built.objects[f"{sliced.id}|{sliced.type}Sliced_1"] = built.objects.pop(sliced.id)
        del built.objects[gone.id]
        labels = {label.key: label.text for label in labelled_top_down(built, px_per_m=60).labels}
    finally:
        built.client.disconnect()
    assert labels[sliced.id] == f"{sliced.type} (sliced)" and gone.id not in labels
