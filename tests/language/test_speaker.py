"""The learned speaker: data, vocabulary, BLEU, features, training, decoding, checkpoints and CLI.

Torch tests skip (with the reason printed by ``-ra``) when PyTorch is not installed; real-data
tests skip when ``../shared/alfred`` is absent. Synthetic ALFRED-format trajectories cover the rest.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
from pathlib import Path

import numpy as np
import pytest

from luminous_sim.errors import LuminousError
from luminous_sim.language.speaker.bleu import corpus_bleu, sentence_bleu
from luminous_sim.language.speaker.dataset import (
    build_examples,
    encode_goal,
    encode_step,
    find_trajectory_files,
    load_trajectories,
    split_trajectories,
)
from luminous_sim.language.speaker.errors import SpeakerError
from luminous_sim.language.speaker.features import FEATURE_DIM, frame_features, load_step_features
from luminous_sim.language.speaker.records import LowAction, Subgoal, load_trajectory, object_type
from luminous_sim.language.speaker.text import detokenize, tokenize
from luminous_sim.language.speaker.vocab import Vocab

ALFRED = Path(__file__).resolve().parents[2].parent / "shared" / "alfred"
VALID_SEEN = ALFRED / "valid_seen"
HAS_TORCH = importlib.util.find_spec("torch") is not None
needs_torch = pytest.mark.skipif(
    not HAS_TORCH, reason="PyTorch not installed (pip install torch==2.13.0)"
)
needs_alfred = pytest.mark.skipif(
    not VALID_SEEN.is_dir(), reason=f"ALFRED sample data not found at {ALFRED}"
)
TINY = {"emb_dim": 16, "hid_dim": 32, "dropout": 0.0}

# --------------------------------------------------------------------------- synthetic ALFRED data

OBJECTS = ("apple", "mug", "bread")
RECEPS = ("countertop", "fridge", "sinkbasin")
NAV = ("MoveAhead_25", "RotateLeft_90", "RotateRight_90", "LookDown_15")


def _low(
    action: str, high_idx: int, object_id: str | None = None, recep_id: str | None = None
) -> dict:
    api: dict = {"action": action.split("_")[0], "forceAction": True}
    if object_id:
        api["objectId"] = object_id
    if recep_id:
        api["receptacleObjectId"] = recep_id
    args = {"bbox": [1, 2, 3, 4], "point": [2, 3], "mask": [[0, 1]]} if object_id else {}
    return {
        "api_action": api,
        "discrete_action": {"action": action, "args": args},
        "high_idx": high_idx,
    }


def synthetic_traj(i: int, with_images: bool = False) -> dict:
    """A small pick-and-place trajectory in traj_data.json form, varied by ``i``."""
    obj, recep = OBJECTS[i % 3], RECEPS[(i // 3) % 3]
    obj_id = f"{obj.capitalize()}|+00.{i:02d}|+00.90|-01.00"
    recep_id = f"{recep.capitalize()}|+01.00|+00.00|+00.50"
    nav1 = [NAV[(i + k) % 4] for k in range(2 + i % 3)]
    nav2 = [NAV[(i + 2 * k) % 4] for k in range(3)]
    low = (
        [_low(a, 0) for a in nav1]
        + [_low("PickupObject", 1, obj_id)]
        + [_low(a, 2) for a in nav2]
        + [_low("PutObject", 3, obj_id, recep_id)]
    )
    high = [
        {
            "discrete_action": {"action": "GotoLocation", "args": [obj]},
            "high_idx": 0,
            "planner_action": {"action": "GotoLocation", "location": "loc|1|2|0|45"},
        },
        {
            "discrete_action": {"action": "PickupObject", "args": [obj]},
            "high_idx": 1,
            "planner_action": {"action": "PickupObject", "objectId": obj_id},
        },
        {
            "discrete_action": {"action": "GotoLocation", "args": [recep]},
            "high_idx": 2,
            "planner_action": {"action": "GotoLocation", "location": "loc|3|2|1|45"},
        },
        {
            "discrete_action": {"action": "PutObject", "args": [obj, recep]},
            "high_idx": 3,
            "planner_action": {
                "action": "PutObject",
                "objectId": obj_id,
                "receptacleObjectId": recep_id,
            },
        },
        {
            "discrete_action": {"action": "NoOp", "args": []},
            "high_idx": 4,
            "planner_action": {"action": "End", "value": 1},
        },
    ]
    descs = [
        f"Walk to the {obj}.",
        f"Pick up the {obj}.",
        f"Carry it to the {recep}.",
        f"Put the {obj} in the {recep}.",
    ]
    anns = [
        {
            "assignment_id": f"w{k}",
            "votes": [1],
            "task_desc": f"Put a {obj} in the {recep}.",
            "high_descs": descs,
        }
        for k in range(2)
    ]
    images = (
        [
            {"high_idx": a["high_idx"], "image_name": f"{n:09d}.png", "low_idx": n}
            for n, a in enumerate(low)
        ]
        if with_images
        else []
    )
    return {
        "images": images,
        "pddl_params": {"object_target": obj.capitalize()},
        "plan": {"high_pddl": high, "low_actions": low},
        "scene": {"scene_num": 1},
        "task_id": f"trial_T2019_{i:04d}",
        "task_type": "pick_and_place_simple",
        "turk_annotations": {"anns": anns},
    }


def write_dataset(root: Path, n: int = 9, with_images: bool = False) -> Path:
    """``n`` synthetic trajectories under ``root/<split>/<task>/<trial>/traj_data.json``."""
    from PIL import Image

    for i in range(n):
        trial = root / "valid_seen" / f"pick_and_place_simple-{i}" / f"trial_{i:03d}"
        trial.mkdir(parents=True)
        data = synthetic_traj(i, with_images)
        (trial / "traj_data.json").write_text(json.dumps(data))
        if with_images:
            (trial / "raw_images").mkdir()
            for entry in data["images"]:
                colour = ((37 * entry["low_idx"] + 50 * i) % 256, (91 * i) % 256, 128)
                Image.new("RGB", (30, 30), colour).save(trial / "raw_images" / entry["image_name"])
    return root


@pytest.fixture()
def synthetic(tmp_path: Path) -> Path:
    return write_dataset(tmp_path / "data")


# --------------------------------------------------------------------------- text, vocabulary, BLEU


def test_tokenize_lower_cases_and_separates_punctuation() -> None:
    assert tokenize("Turn around,walk to the TV-stand.") == [
        "turn",
        "around",
        ",",
        "walk",
        "to",
        "the",
        "tv",
        "-",
        "stand",
        ".",
    ]
    assert tokenize("Pick up the robot's mug!") == ["pick", "up", "the", "robot's", "mug", "!"]
    assert detokenize(["turn", "left", ",", "then", "stop", "."]) == "Turn left, then stop."


def test_vocab_specials_unknowns_and_json_round_trip(tmp_path: Path) -> None:
    vocab = Vocab.build([["b", "a", "b"], ["c", "b", "a"]], min_freq=2)
    assert vocab.itos[:4] == ["<pad>", "<bos>", "<eos>", "<unk>"]
    assert vocab.itos[4:] == ["b", "a"]
    assert vocab.encode(["a", "zzz"]) == [5, Vocab.unk_id]
    assert vocab.decode([4, 5, Vocab.eos_id, 4]) == ["b", "a"]
    vocab.save(tmp_path / "v.json")
    assert Vocab.load(tmp_path / "v.json") == vocab
    (tmp_path / "bad.json").write_text("{not json")
    with pytest.raises(SpeakerError, match="bad.json"):
        Vocab.load(tmp_path / "bad.json")


def test_bleu_identity_known_value_and_multiple_references() -> None:
    ref = ["go", "to", "the", "table", "with", "the", "safe"]
    assert corpus_bleu([ref], [[ref]]) == pytest.approx(1.0)
    assert corpus_bleu([["xx", "yy", "zz", "ww"]], [[ref]]) == 0.0
    hyp = [
        "go",
        "to",
        "the",
        "table",
        "with",
        "the",
        "box",
    ]  # 6/7, 5/6, 4/5, 3/4 n-grams match, same length
    expected = (6 / 7 * 5 / 6 * 4 / 5 * 3 / 4) ** 0.25
    assert corpus_bleu([hyp], [[ref]]) == pytest.approx(expected)
    assert corpus_bleu([hyp], [[ref, hyp]]) == pytest.approx(1.0)
    short = ["go", "to", "the", "table"]  # brevity penalty exp(1 - 7/4)
    assert corpus_bleu([short], [[ref]]) == pytest.approx(np.exp(1 - 7 / 4))
    assert 0.0 < sentence_bleu(["go", "to", "it"], [ref]) < 1.0


# --------------------------------------------------------------------------- data


def test_encoding_run_length_codes_navigation_and_names_targets() -> None:
    lows = [
        LowAction("RotateLeft_90"),
        LowAction("MoveAhead_25"),
        LowAction("MoveAhead_25"),
        LowAction("MoveAhead_25"),
        LowAction("PutObject", "fridge"),
    ]
    feats = np.arange(5 * 2, dtype=np.float32).reshape(5, 2)
    tokens, aligned = encode_step(Subgoal("PutObject", ("apple", "fridge")), lows, feats)
    assert tokens == [
        "<step>",
        "PutObject",
        "apple",
        "fridge",
        "<sep>",
        "RotateLeft_90",
        "MoveAhead_25",
        "x3",
        "PutObject",
        "fridge",
    ]
    assert aligned.shape == (len(tokens), 2)
    assert aligned[6].tolist() == feats[1:4].mean(axis=0).tolist()  # mean of the run
    assert not aligned[7].any() and not aligned[0].any()
    with pytest.raises(SpeakerError, match="one row per low action"):
        encode_step(Subgoal("GotoLocation"), lows, feats[:3])
    assert encode_goal([Subgoal("GotoLocation", ("mug",)), Subgoal("End")]) == [
        "<goal>",
        "GotoLocation",
        "mug",
    ]
    assert object_type("Apple|+00.1|+00.9|-01.2|AppleSliced_3") == "applesliced"
    assert object_type("Sink|+00.1|+00.9|-01.2|SinkBasin") == "sinkbasin"


def test_synthetic_examples_and_split(synthetic: Path) -> None:
    trajs = load_trajectories(synthetic)
    assert len(trajs) == 9 and all(len(t.subgoals) == 4 for t in trajs)  # End dropped
    examples = build_examples(trajs)
    assert len(examples) == 9 * 2 * (4 + 1)
    first = examples[0]
    assert first.kind == "step" and first.tgt == ("walk", "to", "the", "apple", ".")
    train, held = split_trajectories(trajs, 0.25, seed=3)
    assert len(held) == 2 and {t.key for t in train}.isdisjoint(t.key for t in held)
    assert [t.key for t in held] == [t.key for t in split_trajectories(trajs, 0.25, seed=3)[1]]


@needs_alfred
def test_real_valid_seen_examples() -> None:
    files = find_trajectory_files(VALID_SEEN)
    assert len(files) == 251
    trajs = load_trajectories(VALID_SEEN, max_trajectories=40)
    examples = build_examples(trajs)
    steps = [e for e in examples if e.kind == "step"]
    goals = [e for e in examples if e.kind == "goal"]
    assert len(goals) == sum(len(t.annotations) for t in trajs)
    assert len(steps) == sum(len(t.subgoals) * len(t.annotations) for t in trajs)
    assert all(e.src[0] == "<step>" and "<sep>" in e.src for e in steps)
    assert {"MoveAhead_25", "PickupObject", "PutObject"} <= {tok for e in steps for tok in e.src}


def test_non_json_file_raises_naming_the_file(tmp_path: Path) -> None:
    bad = tmp_path / "split" / "task" / "trial" / "traj_data.json"
    bad.parent.mkdir(parents=True)
    bad.write_text("this is { not json")
    with pytest.raises(SpeakerError, match="not valid JSON") as info:
        load_trajectories(tmp_path)
    assert str(bad) in str(info.value) and isinstance(info.value, LuminousError)


def test_traj_without_turk_annotations_raises(tmp_path: Path) -> None:
    data = synthetic_traj(0)
    del data["turk_annotations"]
    path = tmp_path / "traj_data.json"
    path.write_text(json.dumps(data))
    with pytest.raises(SpeakerError, match="turk_annotations") as info:
        load_trajectory(path)
    assert str(path) in str(info.value)
    assert (
        load_trajectory(path, require_annotations=False).annotations == []
    )  # describing needs none


def test_missing_file_empty_folder_and_broken_plan(tmp_path: Path) -> None:
    with pytest.raises(SpeakerError, match="nope.json: no such file or folder; expected a trajectory file"):
        load_trajectory(tmp_path / "nope.json")
    with pytest.raises(SpeakerError, match="no traj_data.json"):
        load_trajectories(tmp_path)
    data = synthetic_traj(0)
    del data["plan"]["low_actions"]
    (tmp_path / "traj_data.json").write_text(json.dumps(data))
    with pytest.raises(SpeakerError, match="plan"):
        load_trajectory(tmp_path / "traj_data.json")


# --------------------------------------------------------------------------- features


def test_frame_features_on_synthetic_frames(tmp_path: Path) -> None:
    rng = np.random.default_rng(0)
    frames = rng.integers(0, 256, size=(5, 300, 300, 3), dtype=np.uint8)
    feats = frame_features(frames)
    assert feats.shape == (5, FEATURE_DIM) and feats.dtype == np.float32
    assert np.allclose(feats.sum(axis=1), 1.0)
    red, blue = np.zeros((1, 64, 64, 3)), np.zeros((1, 64, 64, 3))
    red[..., 0], blue[..., 2] = 1.0, 1.0
    assert not np.allclose(frame_features(red), frame_features(blue))
    with pytest.raises(SpeakerError, match="shape"):
        frame_features(np.zeros((2, 8, 8)))
    root = write_dataset(tmp_path / "img", n=1, with_images=True)
    trial = next(root.rglob("traj_data.json"))
    data = json.loads(trial.read_text())
    per_low = load_step_features(trial.parent, data["images"], len(data["plan"]["low_actions"]))
    assert per_low.shape == (len(data["plan"]["low_actions"]), FEATURE_DIM)
    traj = load_trajectory(trial, features=True)
    assert [f.shape[0] for f in traj.features] == [len(s) for s in traj.segments]


# --------------------------------------------------------------------------- training and decoding


@needs_torch
@needs_alfred
def test_training_loss_goes_down_on_a_real_subset(tmp_path: Path) -> None:
    from luminous_sim.language.speaker.train import train

    report = train(
        VALID_SEEN,
        tmp_path / "s.pt",
        epochs=3,
        batch_size=32,
        lr=5e-3,
        seed=0,
        max_trajectories=40,
        max_examples=400,
        held_out=0.0,
        dims=TINY,
        progress=False,
    )
    assert len(report.losses) == 3 and report.epochs_run == 3
    assert report.losses[-1] < report.losses[0] - 0.5
    assert report.examples == 400 and report.vocab_size > 100 and report.seconds > 0


@needs_torch
@needs_alfred
def test_overfits_eight_real_examples(tmp_path: Path) -> None:
    import torch

    from luminous_sim.language.speaker.generate import Speaker
    from luminous_sim.language.speaker.train import prepare_data, train

    out = tmp_path / "eight.pt"
    report = train(
        VALID_SEEN,
        out,
        epochs=40,
        batch_size=8,
        lr=1e-2,
        seed=0,
        max_examples=8,
        max_trajectories=3,
        held_out=0.0,
        dims={"emb_dim": 32, "hid_dim": 64, "dropout": 0.0},
        min_freq=1,
        progress=False,
    )
    assert report.examples == 8
    examples, _ = prepare_data(VALID_SEEN, torch.load(out, weights_only=True)["train_args"])
    hyps = Speaker.load(out).generate_tokens([e.src for e in examples], [None] * 8, beam_width=1)
    exact = sum(list(e.tgt) == h for e, h in zip(examples, hyps))
    assert exact >= 1 or corpus_bleu(hyps, [[list(e.tgt)] for e in examples]) > 0.5


@needs_torch
def test_repeat_blocking_bans_words_that_complete_a_seen_ngram() -> None:
    from luminous_sim.language.speaker.decode import repeat_banned

    assert repeat_banned([5, 6, 7, 5, 6], 3) == [7]
    assert repeat_banned([5, 6, 7, 5], 2) == [6]
    assert repeat_banned([5, 6, 7], 3) == [] and repeat_banned([5, 5], 0) == []


@needs_torch
def test_resume_continues_and_matches_an_uninterrupted_run(synthetic: Path, tmp_path: Path) -> None:
    import torch

    from luminous_sim.language.speaker.train import train

    kw = {"batch_size": 8, "seed": 1, "held_out": 0.0, "dims": TINY, "progress": False}
    straight = train(synthetic, tmp_path / "straight.pt", epochs=3, **kw)
    first = train(synthetic, tmp_path / "resumed.pt", epochs=2, **kw)
    assert first.losses == straight.losses[:2]  # same seed, same numbers
    second = train(synthetic, tmp_path / "resumed.pt", epochs=3, resume=True, progress=False)
    assert second.epochs_run == 1 and len(second.losses) == 3
    assert second.losses == straight.losses
    a, b = (torch.load(tmp_path / f, weights_only=True) for f in ("straight.pt", "resumed.pt"))
    assert b["epoch"] == 3
    assert all(torch.equal(a["model"][k], b["model"][k]) for k in a["model"])
    assert not [
        p for p in tmp_path.iterdir() if p.name.endswith(".tmp")
    ]  # atomic writes left nothing
    with pytest.raises(SpeakerError, match="absent.pt: no such file or folder; expected a speaker checkpoint"):
        train(synthetic, tmp_path / "absent.pt", epochs=2, resume=True, progress=False)


@needs_torch
def test_generation_is_deterministic_and_survives_save_load(
    synthetic: Path, tmp_path: Path
) -> None:
    from luminous_sim.language.speaker.generate import Speaker
    from luminous_sim.language.speaker.train import train

    out = tmp_path / "s.pt"
    train(synthetic, out, epochs=4, batch_size=8, lr=1e-2, held_out=0.0, dims=TINY, progress=False)
    sub = {
        "discrete_action": {"action": "GotoLocation", "args": ["fridge"]},
        "planner_action": {"action": "GotoLocation", "location": "loc|1|1|0|45"},
    }
    lows = ["RotateLeft_90", "MoveAhead_25", "MoveAhead_25"]
    one, two = Speaker.load(out), Speaker.load(out)
    for width in (1, 3):
        text = one.describe(sub, lows, beam_width=width)
        assert isinstance(text, str) and text
        assert (
            text
            == one.describe(sub, lows, beam_width=width)
            == two.describe(sub, lows, beam_width=width)
        )
        assert (
            one.describe(
                Subgoal("GotoLocation", ("fridge",)), [LowAction(a) for a in lows], beam_width=width
            )
            == text
        )
    goal = one.describe_goal([("GotoLocation", ["mug"]), ("PickupObject", ["mug"])])
    assert goal == two.describe_goal([("GotoLocation", ["mug"]), ("PickupObject", ["mug"])])
    traj = next(synthetic.rglob("traj_data.json"))
    task_desc, steps = one.describe_trajectory(traj)
    assert len(steps) == 4 and task_desc
    with pytest.raises(SpeakerError, match="without visual features"):
        one.describe(sub, lows, features=np.zeros((3, FEATURE_DIM)))
    out.write_bytes(b"garbage")
    with pytest.raises(SpeakerError, match="s.pt"):
        Speaker.load(out)


@needs_torch
def test_features_path_trains_and_describes_with_synthetic_frames(tmp_path: Path) -> None:
    import torch

    from luminous_sim.language.speaker.generate import Speaker
    from luminous_sim.language.speaker.train import train

    root = write_dataset(tmp_path / "img", n=6, with_images=True)
    report = train(
        root,
        tmp_path / "f.pt",
        epochs=2,
        batch_size=8,
        held_out=0.0,
        features=True,
        dims=TINY,
        progress=False,
    )
    assert report.losses[-1] < report.losses[0]
    speaker = Speaker.load(tmp_path / "f.pt")
    assert speaker.feat_dim == FEATURE_DIM
    frames = np.random.default_rng(1).integers(0, 256, size=(3, 300, 300, 3), dtype=np.uint8)
    feats = torch.from_numpy(frame_features(frames))
    lows = ["RotateLeft_90", "MoveAhead_25", "PickupObject"]
    text = speaker.describe(("PickupObject", ["mug"]), lows, features=feats)
    assert text == speaker.describe(("PickupObject", ["mug"]), lows, features=feats.numpy())
    assert isinstance(speaker.describe(("PickupObject", ["mug"]), lows), str)  # no frames: zeros
    with pytest.raises(SpeakerError, match="rows"):
        speaker.describe(("PickupObject", ["mug"]), lows, features=feats[:2])
    _, steps = speaker.describe_trajectory(next(root.rglob("traj_data.json")))
    assert len(steps) == 4


# --------------------------------------------------------------------------- CLI


@needs_torch
def test_cli_train_describe_and_errors(
    synthetic: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    from luminous_sim.cli import speaker_cmd

    parser = argparse.ArgumentParser(prog="luminous")
    speaker_cmd.register(parser.add_subparsers(dest="command", required=True))
    model = tmp_path / "m.pt"
    args = parser.parse_args(
        [
            "speaker",
            "train",
            "--data",
            str(synthetic),
            "--out",
            str(model),
            "--epochs",
            "2",
            "--emb-dim",
            "16",
            "--hid-dim",
            "32",
            "--held-out",
            "0.2",
            "--quiet",
        ]
    )
    assert args.func(args) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["epochs"] == 2 and "bleu4_steps" in report and model.is_file()
    traj = next(synthetic.rglob("traj_data.json"))
    args = parser.parse_args(
        ["speaker", "describe", "--model", str(model), "--traj", str(traj), "--json"]
    )
    assert args.func(args) == 0
    described = json.loads(capsys.readouterr().out)
    assert len(described["high_descs"]) == 4 and isinstance(described["task_desc"], str)
    args = parser.parse_args(
        ["speaker", "evaluate", "--model", str(model), "--data", str(synthetic), "--beam", "1"]
    )
    assert args.func(args) == 0
    assert json.loads(capsys.readouterr().out)["trajectories"] == 2
    args = parser.parse_args(
        ["speaker", "describe", "--model", str(tmp_path / "none.pt"), "--traj", str(traj)]
    )
    with pytest.raises(LuminousError, match="none.pt"):
        args.func(args)


@needs_torch
@pytest.mark.parametrize("content", [b"root:x:0:0:root:/root:/bin/bash\n", b"", b"\x80\x02}q\x00.", b"PK\x03\x04junk"])
def test_a_file_that_is_not_a_checkpoint_is_a_speaker_error(tmp_path, content):
    """torch.load raises IndexError, EOFError, UnpicklingError ... on foreign bytes: all become one clear error."""
    from luminous_sim.language.speaker.checkpoint import load_checkpoint

    path = tmp_path / "model.pt"
    path.write_bytes(content)
    with pytest.raises(SpeakerError, match="model.pt"):
        load_checkpoint(path)


def test_a_frame_name_never_leaves_raw_images_and_special_files_are_refused(tmp_path):
    """An `images` entry names a file inside raw_images/ (its stem only); a link or a FIFO there is refused, not
    followed or read (a FIFO would block)."""
    import os

    (tmp_path / "raw_images").mkdir()
    outside = tmp_path / "secret.png"
    outside.write_bytes(b"not an image")
    from luminous_sim.language.speaker.features import _frame_file

    assert _frame_file(tmp_path / "raw_images", "../secret.png") is None  # only the stem, inside raw_images/
    (tmp_path / "raw_images" / "secret.png").write_bytes(b"x")
    assert _frame_file(tmp_path / "raw_images", "../secret.png") == tmp_path / "raw_images" / "secret.png"
    (tmp_path / "raw_images" / "000000000.png").symlink_to(outside)
    with pytest.raises(SpeakerError, match="a symbolic link"):
        load_step_features(tmp_path, [{"image_name": "000000000.jpg", "low_idx": 0}], 1)
    os.mkfifo(tmp_path / "raw_images" / "000000001.jpg")
    with pytest.raises(SpeakerError, match="FIFO"):
        load_step_features(tmp_path, [{"image_name": "000000001.jpg", "low_idx": 0}], 1)
