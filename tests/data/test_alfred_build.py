"""`luminous dataset build --from-alfred`: the designs of an ALFRED split folder re-solved in their own floor
plans and exported like a split build (the same files whatever the workers, backend or a SIGKILL; a
failed design recorded with its first cause; bad folders refused naming the file)."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from luminous_sim.data import (
    BuildOptions,
    DesignError,
    LocalBackend,
    build_from_alfred,
    design_jobs,
    make_backend,
    structure,
    structure_differences,
)
from luminous_sim.data.build import MANIFEST, PARTIAL, SPLITS
from tests.data.test_build import _env, _has_ray, _kill_when, tree

QUICK = BuildOptions(frames=False, video=False, human_language=True)
"""What the CLI builds with --no-frames: the designs' own human annotations."""
REAL = ("look_at_obj_in_light-AlarmClock-None-DeskLamp-323", "look_at_obj_in_light-Bowl-None-DeskLamp-301")
"""Two of valid_seen's quickest designs (about a second each)."""
UNFIT = "look_at_obj_in_light-Bowl-None-DeskLamp-1"
"""Bowl-301's design moved to FloorPlan1, a kitchen: ALFRED has no look_at_obj_in_light task there."""
SPLIT = "mysplit"


@pytest.fixture(scope="module")
def alfred_split(shared_alfred, tmp_path_factory) -> Path:
    """A small ALFRED split folder: two real designs and one that no scene can be generated for."""
    root = tmp_path_factory.mktemp("alfred") / SPLIT
    for name in REAL:
        src = next((shared_alfred / "valid_seen" / name).glob("*/traj_data.json"))
        dest = root / name / src.parent.name / "traj_data.json"
        dest.parent.mkdir(parents=True)
        shutil.copy(src, dest)
    data = json.loads(next((root / REAL[1]).glob("*/traj_data.json")).read_text())
    data["scene"].update(floor_plan="FloorPlan1", scene_num=1)
    unfit = root / UNFIT / "trial_T20190101_000000_000001" / "traj_data.json"
    unfit.parent.mkdir(parents=True)
    unfit.write_text(json.dumps(data))
    return root


@pytest.fixture(scope="module")
def reference(alfred_split, tmp_path_factory) -> Path:
    """The split built in this process, without frames, uninterrupted."""
    out = tmp_path_factory.mktemp("reference") / "build"
    report = build_from_alfred(out, alfred_split, options=QUICK, progress=False)
    assert report.ran == 3 and (report.built, report.failed) == (2, 1), report.summary()
    return out


def test_designs_are_solved_in_their_own_floor_plans_and_exported_in_alfreds_layout(alfred_split, reference):
    records = [json.loads(line) for line in (reference / MANIFEST).read_text().splitlines()]
    sources = sorted(alfred_split.glob("*/*/traj_data.json"))
    assert [r["key"] for r in records] == [f"{SPLIT}/{p.parent.parent.name}/{p.parent.name}" for p in sources]
    assert [r["order"] for r in records] == [0, 1, 2]
    built = [r for r in records if r["status"] == "built"]
    for r in built:
        source = json.loads((alfred_split / r["design"] / "traj_data.json").read_text())
        assert r["trial"] == r["design"]  # the trial keeps its design's folder names
        ours = json.loads((reference / SPLIT / r["trial"] / "traj_data.json").read_text())
        assert (ours["task_type"], ours["pddl_params"], ours["task_id"]) == (
            source["task_type"], source["pddl_params"], source["task_id"])
        assert ours["scene"]["floor_plan"] == source["scene"]["floor_plan"] == r["floor_plan"]
        problems = structure_differences(structure(ours), [("source", structure(source))])
        assert [p for p in problems if not p.startswith("missing path images[]")] == []  # no frames: no images
        sidecar = json.loads((reference / SPLIT / r["trial"] / "luminous.json").read_text())
        assert sidecar["alfred_design"]["name"] == r["design"] and "run_task" in sidecar["regenerate"]
    splits = json.loads((reference / SPLITS).read_text())
    assert splits == {SPLIT: [{"repeat_idx": k, "task": r["trial"]} for r in built for k in range(3)]}
    assert not (reference / PARTIAL).exists()


def test_a_design_with_no_scene_is_a_recorded_failure_with_its_first_cause(reference):
    (failed,) = [json.loads(line) for line in (reference / MANIFEST).read_text().splitlines()
                 if json.loads(line)["status"] == "failed"]
    assert failed["design"].startswith(UNFIT) and failed["trial"] is None
    assert (failed["stage"], failed["scene_cause"]) == ("task", "no_cdf")
    assert "generated only in Bedroom, LivingRoom" in failed["cause"]
    assert not (reference / SPLIT / UNFIT).exists()


def test_more_workers_give_the_same_files(alfred_split, reference, tmp_path):
    with LocalBackend(2) as backend:
        report = build_from_alfred(tmp_path / "b", alfred_split, backend=backend, options=QUICK, progress=False)
    assert report.workers == 2 and report.failed == 1
    assert "failed at task (1x)" in report.summary()
    assert tree(tmp_path / "b") == tree(reference)


@pytest.mark.slow  # the Ray backend itself runs in the fast suite in tests/data/test_build.py
def test_ray_backend_gives_the_same_files(alfred_split, reference, tmp_path):
    if not _has_ray():
        pytest.skip("Ray is not installed (pip install 'luminous-sim[cluster]')")
    with make_backend("ray", workers=2) as backend:
        build_from_alfred(tmp_path / "r", alfred_split, backend=backend, options=QUICK, progress=False)
    assert tree(tmp_path / "r") == tree(reference)


@pytest.mark.slow
def test_frames_and_video_are_the_same_whatever_the_workers_and_backend(alfred_split, tmp_path):
    backends = [("local", 1), ("local", 2)] + ([("ray", 2)] if _has_ray() else [])
    trees = []
    for name, workers in backends:
        with make_backend(name, workers) as backend:
            build_from_alfred(tmp_path / f"{name}{workers}", alfred_split, backend=backend, progress=False)
        trees.append(tree(tmp_path / f"{name}{workers}"))
    assert any(k.endswith("video.mp4") for k in trees[0]) and any(".jpg" in k for k in trees[0])
    assert all(t == trees[0] for t in trees[1:])


def _cli(split: Path, out: Path, *more: str) -> list[str]:
    return [sys.executable, "-m", "luminous_sim.cli.main", "dataset", "build", "--from-alfred", str(split),
            "--out", str(out), "--no-frames", "--no-progress", *more]


def test_sigkill_mid_job_then_restart_gives_the_files_of_an_uninterrupted_build(alfred_split, reference, tmp_path):
    out = tmp_path / "killed"
    _kill_when(out, lambda: (out / PARTIAL).exists() and any(p.name != "RUN" for p in (out / PARTIAL).iterdir()),
               argv=_cli(alfred_split, out))
    assert (out / "build.json").exists(), "the build was killed before it started"
    done = subprocess.run(_cli(alfred_split, out), env=_env(), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert "3 designs" in done.stdout and "2 built, 1 failed" in done.stdout
    assert tree(out) == tree(reference)


def test_count_takes_the_first_designs_in_path_order(alfred_split):
    jobs = design_jobs(alfred_split, count=2)
    assert [j.design.name.split("/")[0] for j in jobs] == [REAL[0], UNFIT]
    assert [j.order for j in jobs] == [0, 1] and {j.split for j in jobs} == {SPLIT}
    assert len(design_jobs(alfred_split)) == 3


def test_a_missing_empty_or_malformed_split_folder_is_refused_naming_it(tmp_path, capsys):
    from luminous_sim.cli.main import main

    def refused(split: Path) -> str:
        assert main(["dataset", "build", "--from-alfred", str(split), "--out", str(tmp_path / "b")]) == 2
        return capsys.readouterr().err

    assert f"{tmp_path / 'none'}: no such ALFRED split folder" in refused(tmp_path / "none")
    (tmp_path / "empty").mkdir()
    assert "no <task>/<trial>/traj_data.json files" in refused(tmp_path / "empty")
    bad = tmp_path / "bad" / "pick_and_place_simple-Mug-None-Shelf-1" / "trial_T1" / "traj_data.json"
    bad.parent.mkdir(parents=True)
    bad.write_text('{"task_type": "pick_and_place_simple"')
    assert f"{bad}: not JSON" in refused(tmp_path / "bad")
    bad.write_text(json.dumps({"task_type": "stack_blocks", "pddl_params": {"object_target": "Mug"},
                               "scene": {"floor_plan": "FloorPlan1", "scene_num": 1}}))
    # the one ALFRED reader (as `alfred parse`) checks the required keys before their values
    assert f"{bad}: missing key 'plan.high_pddl'" in refused(tmp_path / "bad")
    assert not (tmp_path / "b").exists()
    with pytest.raises(DesignError, match="not a folder"):
        design_jobs(bad)


def test_cli_wants_one_source(tmp_path, alfred_split, capsys):
    from luminous_sim.cli.main import main

    for argv in (["--out", str(tmp_path / "b")],
                 ["--split", "S+", "--count", "1", "--from-alfred", str(alfred_split), "--out", str(tmp_path / "b")]):
        with pytest.raises(SystemExit) as exc:
            main(["dataset", "build", *argv])
        assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "one of the arguments --split --houses --from-alfred is required" in err
    assert "not allowed with argument" in err


def _source(alfred_split: Path, name: str) -> dict:
    return json.loads(next((alfred_split / name).glob("*/traj_data.json")).read_text())


def test_a_trial_keeps_its_designs_human_annotations_as_alfred_has_them(alfred_split, reference):
    """Where ALFRED's subgoals are ours, every annotation is the design's own (worker, votes, directive, steps);
    splits.json lists each one, and the sidecar says the steps are the people's."""
    listed = json.loads((reference / SPLITS).read_text())[SPLIT]
    for name in REAL:
        (trial,) = (reference / SPLIT / name).iterdir()
        data = json.loads((trial / "traj_data.json").read_text())
        anns = _source(alfred_split, name)["turk_annotations"]["anns"]
        assert data["turk_annotations"]["anns"] == anns
        side = json.loads((trial / "luminous.json").read_text())
        assert side["language"]["high_descs"] == ["human"] * len(anns)
        assert not any(k.startswith("turk_annotations") for k in side["generated"])
        assert sorted(e["repeat_idx"] for e in listed if e["task"] == f"{name}/{trial.name}") == list(range(len(anns)))


def test_where_alfreds_plan_is_not_ours_the_directive_stays_and_the_steps_are_the_templates():
    from luminous_sim.data import HumanLanguage
    from luminous_sim.data.alfred_language import language_note, trial_annotations

    ann = {"assignment_id": "A1", "votes": [1, 1, 1], "task_desc": "Put a cut apple in a pot.",
           "high_descs": ["walk to the counter", "pick up the knife", "slice the apple", "put it in the pot"]}
    human = HumanLanguage((ann,), ("GotoLocation", "PickupObject", "SliceObject", "PutObject"))
    templates = [{"task_desc": "Place a sliced apple in a pot.", "high_descs": ["a", "b", "c", "d", "e"]}]
    ours = ("GotoLocation", "PickupObject", "SliceObject", "PutObject", "PutObject")
    (kept,) = trial_annotations(human, ours, templates)
    assert kept == {**ann, "high_descs": ["a", "b", "c", "d", "e"]}
    assert language_note(human, [kept])["high_descs"] == ["templates"]
    (same,) = trial_annotations(human, ours[:4], templates)
    assert same == ann and language_note(human, [same])["high_descs"] == ["human"]


def test_templates_and_the_design_seed_are_options_recorded_in_the_build(alfred_split, tmp_path, capsys):
    """`--language templates` writes template instructions; the seed and language are in build.json, so a
    rerun with another is refused; both are refused for a split build, and the human language with a speaker."""
    from luminous_sim.cli.main import main

    out = tmp_path / "t"
    argv = ["dataset", "build", "--from-alfred", str(alfred_split), "--out", str(out), "--no-frames", "--no-progress"]
    assert main([*argv, "--count", "1", "--language", "templates", "--seed", "7"]) == 0
    settings = json.loads((out / "build.json").read_text())
    assert (settings["design_seed"], settings["language"]) == (7, "templates")
    (trial,) = (out / SPLIT / REAL[0]).iterdir()
    anns = json.loads((trial / "traj_data.json").read_text())["turk_annotations"]["anns"]
    assert len(anns) == 3 and all(a["assignment_id"].startswith("LUMINOUS_") for a in anns)
    assert main([*argv, "--count", "1", "--seed", "7"]) == 2
    assert "language: 'templates' there, 'human' now" in capsys.readouterr().err
    assert main([*argv, "--count", "1", "--language", "templates"]) == 2
    assert "design_seed: 7 there, 0 now" in capsys.readouterr().err
    for more in (["--split", "S+", "--seed", "1"], ["--from-alfred", str(alfred_split), "--language", "human",
                                                     "--speaker", str(tmp_path / "speaker.pt")]):
        with pytest.raises(SystemExit) as exc:
            main(["dataset", "build", *more, "--out", str(tmp_path / "x")])
        assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "--language and --seed are for --from-alfred" in err and "give one or the other" in err
