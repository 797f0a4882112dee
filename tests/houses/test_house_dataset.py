"""The house split: ALFRED tasks across the rooms of generated houses, built in ALFRED's layout like S+/U+."""

from __future__ import annotations

import json

import pytest

from luminous_sim.data import HOUSE_SPLIT, BuildOptions, Manifest, build_houses, house_jobs
from luminous_sim.data.house_build import house_seed
from luminous_sim.vocab import ALFRED_TASK_TYPES

QUICK = BuildOptions(frames=False, video=False)


@pytest.fixture(scope="module")
def built(tmp_path_factory):
    out = tmp_path_factory.mktemp("houses")
    report = build_houses(out, 2, options=QUICK, progress=False)
    return out, report


def test_house_trials_are_alfred_trials_named_by_their_house(built):
    out, report = built
    records = sorted(Manifest(out / "manifest.jsonl"), key=lambda r: r["order"])
    assert [r["task_type"] for r in records] == list(ALFRED_TASK_TYPES[:2])
    assert report.built >= 1, report.summary()
    for r in records:
        if r["status"] != "built":
            continue
        trial = out / HOUSE_SPLIT / r["trial"]
        traj = json.loads((trial / "traj_data.json").read_text())
        side = json.loads((trial / "luminous.json").read_text())
        seed = house_seed(r["order"], r["house_draws"] - 1)
        assert seed == r["house_seed"]
        assert traj["scene"]["floor_plan"] == "env_house" and traj["scene"]["scene_num"] == seed
        assert r["trial"].split("/")[0].endswith(f"-{seed}") and side["house"]["seed"] == seed
        assert side["scene"]["room"]["house"] is not None and r["cross_room"] == side["house"]["cross_room"]
    splits = json.loads((out / "splits.json").read_text())
    assert set(splits) == {HOUSE_SPLIT}


def test_a_house_build_resumes_to_the_same_files(built, tmp_path):
    out, _ = built
    again = build_houses(out, 2, options=QUICK, progress=False)
    assert again.ran == 0
    assert house_jobs(3, start=1)[0].key == "houses/000001"


def test_the_cli_builds_houses_and_refuses_a_count_beside(tmp_path, capsys):
    from luminous_sim.cli.main import main

    with pytest.raises(SystemExit) as exc:
        main(["dataset", "build", "--houses", "1", "--count", "2", "--out", str(tmp_path / "h")])
    assert exc.value.code == 2 and "--houses N gives the count itself" in capsys.readouterr().err
