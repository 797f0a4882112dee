"""The learned layout generator (issue 19): its training data, training, the shipped model, the interface."""

from __future__ import annotations

import subprocess
import sys
from functools import cache

import numpy as np
import pytest

from luminous_sim.layouts import LayoutError, LayoutGenerator, LearnedLayouts, loads, realize, train_layouts, trainset
from luminous_sim.rooms import generate_shell

from .helpers import REPO

torch = pytest.importorskip("torch")


@cache
def _pairs():
    return trainset.cssg_layouts(1)  # one CSSG layout per room type (a procedural room each)


def _vocab(pairs) -> list[str]:
    return sorted({o.category for lay, _ in pairs for o in lay.objects if trainset.is_furniture(o)})


def test_importing_the_package_does_not_import_torch():
    code = "import sys, luminous_sim.layouts, luminous_sim.cli.main; print('torch' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, check=True)
    assert out.stdout.strip() == "False"


def test_every_view_keeps_the_furniture_on_the_floor_it_was_on():
    pairs = _pairs()
    vocab = _vocab(pairs)
    for layout, shell in pairs:
        views = trainset.examples_of(layout, shell, vocab)
        assert len(views) == 8
        n = sum(trainset.is_furniture(o) for o in layout.objects)
        for ex in views:
            assert len(ex.objects) == n
            floor = ex.raster[0]
            for row in ex.objects:
                u, v = trainset.pos_value(int(row[4])), trainset.pos_value(int(row[5]))
                i = min(trainset.RASTER - 1, int((v + 1) / 2 * trainset.RASTER))
                j = min(trainset.RASTER - 1, int((u + 1) / 2 * trainset.RASTER))
                near = floor[max(0, i - 1):i + 2, max(0, j - 1):j + 2]
                assert near.max() == 1.0, (shell.name, row)
        # turning a view turns the yaws, never the boxes' own width, depth and height
        assert (views[1].objects[:, 1:4] == views[0].objects[:, 1:4]).all()


def _tiny_examples():
    pairs = _pairs()
    vocab = _vocab(pairs)
    return vocab, [e for lay, sh in pairs for e in trainset.examples_of(lay, sh, vocab)]


def _tiny_training(seed: int, epochs: int = 16):
    from luminous_sim.layouts.atiss_net import NetConfig, TrainConfig, train

    vocab, examples = _tiny_examples()
    return train(examples, NetConfig(len(vocab), width=32, layers=1), TrainConfig(epochs=epochs, batch=8, seed=seed))


def test_a_few_steps_of_training_lower_the_loss_and_the_same_seed_gives_the_same_model():
    from luminous_sim.layouts.atiss_net import batch_of, loss_of

    _, examples = _tiny_examples()
    held = [batch_of(examples, np.random.default_rng(k)) for k in range(4)]  # the same prefixes for both

    def loss(net) -> float:
        with torch.no_grad():
            return float(sum(loss_of(net, b) for b in held))

    untrained, _ = _tiny_training(0, epochs=0)
    net, losses = _tiny_training(0)
    assert loss(net) < 0.7 * loss(untrained), (loss(net), loss(untrained))
    again, losses_again = _tiny_training(0)
    assert losses_again == losses
    for (k, a), (_, b) in zip(net.state_dict().items(), again.state_dict().items(), strict=True):
        assert torch.equal(a, b), k


def test_the_shipped_model_furnishes_rooms_deterministically_with_layouts_that_validate_and_realize():
    gen = LearnedLayouts()
    assert isinstance(gen, LayoutGenerator)
    for room_type in ("Kitchen", "LivingRoom", "Bedroom", "Bathroom"):
        shell = generate_shell(room_type, np.random.default_rng(2))
        layout = gen.layout(shell, 4)
        assert layout.provenance.generator == "learned" and layout.provenance.seed == 4
        assert loads(layout.to_json()) == layout
        assert gen.layout(shell, 4) == layout
        learned = [o for o in layout.objects if o.id.startswith("learned_")]
        assert learned, room_type
        floor = shell.polygon()
        from shapely.geometry import Point

        assert all(floor.buffer(0.1).contains(Point(o.position[:2])) for o in learned)
        realized = realize(layout, 4)
        assert not realized.unmatched
        scene = realized.given.generated.scene
        kept = {r.key for r in realized.given.repairs if r.action == "left_out"}
        assert all(o.id in realized.given.ids or o.id in kept for o in learned)
        assert realized.given.generated.report.reachable_points > 0
        assert any(o.layer == "object" for o in scene.objects)  # small objects added by the object layer
    a = gen.layout(generate_shell("Bedroom", np.random.default_rng(2)), 5)
    assert a != gen.layout(generate_shell("Bedroom", np.random.default_rng(2)), 6)


def test_fixtures_come_from_the_room_as_cssg_lays_them():
    from luminous_sim import cssg

    shell = generate_shell("Kitchen", np.random.default_rng(1))
    layout = LearnedLayouts().layout(shell, 3)
    fixtures = sorted(o.asset for o in layout.objects if o.layer == "fixture" and o.parent is None)
    generated = cssg.generate(cssg.empty_cdf("Kitchen"), seed=3, room=shell).scene
    assert generated.notes["attempt"] == 0  # its first attempt's draws: the ones the structure layer makes
    assert fixtures
    assert fixtures == sorted(o.asset for o in generated.objects if o.layer == "fixture" and o.parent is None)


def test_train_layouts_writes_a_checkpoint_that_generates(tmp_path):
    out = tmp_path / "m.pt"
    result = train_layouts(out, per_type=1, epochs=2)
    assert out.is_file() and result.layouts == 4 and len(result.losses) == 2
    layout = LearnedLayouts(out).layout(generate_shell("LivingRoom", np.random.default_rng(0)), 0)
    assert layout.provenance.notes["model"]


def test_a_file_that_is_not_a_checkpoint_is_refused_by_name(tmp_path):
    bad = tmp_path / "bad.pt"
    bad.write_bytes(b"not a model")
    with pytest.raises(LayoutError, match="bad.pt"):
        LearnedLayouts(bad).layout(generate_shell("Bedroom", np.random.default_rng(0)), 0)
    with pytest.raises(LayoutError, match="no such model file"):
        LearnedLayouts(tmp_path / "missing.pt").layout(generate_shell("Bedroom", np.random.default_rng(0)), 0)


def test_generate_method_learned_and_train_layouts_on_the_command_line(tmp_path, capsys):
    from luminous_sim.cli.main import main
    from luminous_sim.scene import Scene

    assert main(["generate", "--method", "learned", "--room-type", "Bedroom", "--seed", "1", "--no-physics",
                 "--out", str(tmp_path / "s")]) == 0
    assert Scene.load(tmp_path / "s" / "scene.json").generator == "learned"
    assert main(["train-layouts", "--out", str(tmp_path / "m.pt"), "--rooms", "1", "--epochs", "1", "--quiet"]) == 0
    assert "wrote" in capsys.readouterr().out
    assert main(["generate", "--method", "learned", "--model", str(tmp_path / "m.pt"), "--room-type", "Bedroom",
                 "--no-physics", "--out", str(tmp_path / "t")]) == 0
