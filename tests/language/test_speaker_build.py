"""`luminous dataset build --speaker PATH`: a learned speaker's instructions in place of the templates'."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import pytest

from luminous_sim.cli.main import main
from tests.language.test_speaker import TINY, write_dataset

pytestmark = pytest.mark.skipif(importlib.util.find_spec("torch") is None,
                                reason="PyTorch not installed (pip install torch==2.13.0)")


@pytest.fixture(scope="module")
def speakers(tmp_path_factory) -> tuple[Path, Path]:
    """Two tiny speakers trained on synthetic trajectories (different seeds)."""
    from luminous_sim.language.speaker.train import train

    root = tmp_path_factory.mktemp("speaker")
    data = write_dataset(root / "data")
    out = []
    for seed in (0, 1):
        path = root / f"s{seed}.pt"
        train(data, path, epochs=1, batch_size=8, seed=seed, progress=False, dims=TINY, eval_beam=None)
        out.append(path)
    return out[0], out[1]


def _anns(out: Path) -> list[dict]:
    return json.loads(next(out.rglob("traj_data.json")).read_text())["turk_annotations"]["anns"]


def test_a_build_with_a_speaker_writes_its_instructions_and_resumes_only_with_it(speakers, tmp_path, capsys):
    first, second = speakers
    plain, spoken = tmp_path / "plain", tmp_path / "spoken"
    common = ["dataset", "build", "--split", "U+", "--count", "1", "--no-frames", "--no-progress"]
    assert main([*common, "--out", str(plain)]) == 0
    assert main([*common, "--out", str(spoken), "--speaker", str(first)]) == 0
    templated, learned = _anns(plain), _anns(spoken)
    assert len(learned) == len(templated) == 3
    assert all(len(a["high_descs"]) == len(t["high_descs"]) for a, t in zip(learned, templated, strict=True))
    assert [a["task_desc"] for a in learned] != [t["task_desc"] for t in templated]
    settings = json.loads((spoken / "build.json").read_text())
    assert len(settings["speaker_sha256"]) == 64 and "speaker_sha256" not in json.loads(
        (plain / "build.json").read_text())
    assert main([*common, "--out", str(spoken), "--speaker", str(first)]) == 0  # resumes: nothing to do
    capsys.readouterr()
    assert main([*common, "--out", str(spoken), "--speaker", str(second)]) != 0
    assert "other settings" in capsys.readouterr().err


def test_a_missing_checkpoint_is_refused_before_building(tmp_path, capsys):
    code = main(["dataset", "build", "--split", "U+", "--count", "1", "--no-frames", "--no-progress",
                 "--out", str(tmp_path / "b"), "--speaker", str(tmp_path / "none.pt")])
    assert code != 0 and "none.pt" in capsys.readouterr().err
    assert not (tmp_path / "b" / "build.json").exists()
