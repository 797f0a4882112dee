"""A user's dataset folder is hostile input (`luminous eval --data`): every path read from it stays inside it
(split keys, task paths, trial folders, with no symbolic link on the way), every episode file inside `--out`,
special and oversized files are refused before they are read, and a trial that cannot be read, holds a value
of the wrong kind or out of range, or whose task its restored scene makes impossible is a broken trial: an
`unavailable` outcome with cause `broken_trial`, counted in SR all, and `luminous eval` exits 1 naming it."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from luminous_sim.cli.main import main
from luminous_sim.eval import evaluate_data
from luminous_sim.eval.metrics import BROKEN_TRIAL
from luminous_sim.limits import MAX_EPISODE_FILE_BYTES, MAX_INPUT_BYTES

REPO = Path(__file__).resolve().parents[2]
FAST = {"max_steps": 2}


@pytest.fixture(scope="module")
def source(uplus_build) -> Path:
    """One built trial folder (U+ entry 0), copied by every test that changes it."""
    splits = json.loads((uplus_build / "splits.json").read_text())
    return uplus_build / "U+" / splits["U+"][0]["task"]


def _folder(root: Path, source: Path, *tasks: str, split: str = "S") -> Path:
    """A dataset folder in ALFRED's layout at `root` holding a copy of `source` at each of `tasks`."""
    for task in tasks:
        shutil.copytree(source, root / split / task)
    (root / "splits.json").write_text(json.dumps({split: [{"repeat_idx": 0, "task": t} for t in tasks]}))
    return root


def _edit(path: Path, change) -> None:
    data = json.loads(path.read_text())
    change(data)
    path.write_text(json.dumps(data))


def _files(root: Path) -> set[str]:
    return {p.relative_to(root).as_posix() for p in root.rglob("*") if not p.is_dir()}


def _eval(data: Path, out: Path, capsys, policy: str = "oracle", fast: bool = True) -> tuple[int, str]:
    code = main(["eval", "--policy", policy, "--data", str(data), "--out", str(out),
                 *(["--env", "max_steps=2"] if fast else [])])
    return code, capsys.readouterr().err


# -- paths from splits.json stay inside the folder, episode files inside --out -----------------------------------

@pytest.mark.parametrize("key", ["../../escape", "@abs", "..", "", ".hidden", "a/b", "a\\b", "x" * 256])
def test_split_keys_that_are_not_plain_names_are_refused_before_any_work(key, source, tmp_path, capsys):
    outside = tmp_path / "w" / "escape"
    shutil.copytree(source, outside / "t" / "r")
    key = str(tmp_path / "w" / "escape") if key == "@abs" else key
    data = tmp_path / "w" / "x" / "data"
    data.mkdir(parents=True)
    (data / "splits.json").write_text(json.dumps({key: [{"repeat_idx": 0, "task": "t/r"}]}))
    before = _files(tmp_path)
    code, err = _eval(data, tmp_path / "w" / "x" / "out", capsys)
    assert code == 2 and err.count("\n") == 1, err
    assert "splits.json: split " in err and "expected a plain folder name" in err, err
    assert _files(tmp_path) == before  # no episode file written anywhere, nothing outside read into an outcome


@pytest.mark.parametrize("task", ["../escape/r", "@abs", "t/../../escape/r", "t//r", "./t/r", "a/b/c", "", 3])
def test_task_paths_that_climb_out_or_are_not_plain_are_refused(task, source, tmp_path, capsys):
    shutil.copytree(source, tmp_path / "escape" / "r")
    task = str(tmp_path / "escape" / "r") if task == "@abs" else task
    data = tmp_path / "data"
    (data / "S").mkdir(parents=True)
    (data / "splits.json").write_text(json.dumps({"S": [{"repeat_idx": 0, "task": task}]}))
    code, err = _eval(data, tmp_path / "out", capsys)
    assert code == 2 and "field 'task': expected '<task>/<trial>'" in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("where", ["trial", "task"])
def test_a_trial_reached_through_a_symbolic_link_is_a_broken_trial_and_never_read(where, source, tmp_path, capsys):
    elsewhere = tmp_path / "elsewhere"
    shutil.copytree(source, elsewhere / "r")
    data = tmp_path / "data"
    (data / "S").mkdir(parents=True)
    if where == "trial":
        (data / "S" / "t").mkdir()
        os.symlink(elsewhere / "r", data / "S" / "t" / "r")
    else:
        os.symlink(elsewhere, data / "S" / "t")
    (data / "splits.json").write_text(json.dumps({"S": [{"repeat_idx": 0, "task": "t/r"}]}))
    os.unlink(elsewhere / "r" / "luminous.json")
    os.mkfifo(elsewhere / "r" / "luminous.json")  # read through the link, it would block forever
    code, err = _eval(data, tmp_path / "out", capsys, policy="random")
    assert code == 1, err
    assert f"S 0 ({BROKEN_TRIAL}): {data / 'S' / 't'}" in err and "a symbolic link" in err, err
    assert "1 of 1 entries are broken trials (S/t/r)" in err, err
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["unavailable"] == {BROKEN_TRIAL: 1} and report["overall"]["sr_all"] == 0.0
    assert sorted(p.name for p in (tmp_path / "out" / "episodes").iterdir()) == ["S-0.json"]


def test_a_trial_folder_of_a_manifest_that_is_a_link_is_a_broken_trial(uplus_build, tmp_path):
    build = tmp_path / "b"
    shutil.copytree(uplus_build, build)
    splits = json.loads((build / "splits.json").read_text())
    trial = build / "U+" / splits["U+"][0]["task"]
    shutil.move(trial, tmp_path / "moved")
    os.symlink(tmp_path / "moved", trial)
    report = evaluate_data("random", build, episodes=[0], env_kwargs=FAST)
    (outcome,) = report.outcomes
    assert outcome.end == "unavailable" and outcome.cause == BROKEN_TRIAL and "a symbolic link" in outcome.detail


def test_a_traj_data_file_that_is_a_link_in_a_plain_tree_is_a_broken_trial(source, tmp_path):
    data = tmp_path / "data"
    shutil.copytree(source, data / "S" / "t" / "r")
    shutil.copytree(source, tmp_path / "elsewhere")
    (data / "S" / "t" / "r" / "traj_data.json").unlink()
    os.symlink(tmp_path / "elsewhere" / "traj_data.json", data / "S" / "t" / "r" / "traj_data.json")
    os.symlink(tmp_path / "elsewhere", data / "S" / "t" / "linked")  # a linked folder is not followed: not listed
    (outcome,) = evaluate_data("random", data, env_kwargs=FAST).outcomes
    assert outcome.cause == BROKEN_TRIAL and "traj_data.json: a symbolic link" in outcome.detail
    assert outcome.trial == "S/t/r"


@pytest.mark.parametrize("make, says", [
    (lambda p: os.mkfifo(p), "a FIFO (named pipe)"),
    (lambda p: os.symlink(p.parent / "elsewhere.json", p), "a symbolic link"),
    (lambda p: p.mkdir(), "a folder"),
    (lambda p: os.truncate(p.write_bytes(b"") or p, MAX_INPUT_BYTES + 1), "over"),
])
def test_a_splits_index_that_is_not_a_small_regular_file_is_refused(make, says, source, tmp_path, capsys):
    data = _folder(tmp_path / "data", source, "t/r")
    (data / "elsewhere.json").write_text(json.dumps({"S": [{"repeat_idx": 0, "task": "t/r"}]}))
    (data / "splits.json").unlink()
    make(data / "splits.json")
    code, err = _eval(data, tmp_path / "out", capsys)
    assert code == 2 and f"{data / 'splits.json'}: {says}" in err, err


def test_a_manifest_that_is_a_link_is_refused_not_passed_over(uplus_build, tmp_path, capsys):
    build = tmp_path / "b"
    shutil.copytree(uplus_build, build)
    shutil.move(build / "manifest.jsonl", tmp_path / "m.jsonl")
    os.symlink(tmp_path / "m.jsonl", build / "manifest.jsonl")
    code, err = _eval(build, tmp_path / "out", capsys)
    assert code == 2 and "manifest.jsonl: a symbolic link" in err, err


def test_a_failed_manifest_record_of_the_wrong_kind_is_named(uplus_build, tmp_path, capsys):
    from luminous_sim.data.manifest import _line

    build = tmp_path / "b"
    shutil.copytree(uplus_build, build)
    lines = (build / "manifest.jsonl").read_text().splitlines()
    record = {k: v for k, v in json.loads(lines[0]).items() if k != "check"}
    record.update(status="failed", stage="oracle", cause="x", trial=None, layout="three")
    lines[0] = _line(record).strip()
    (build / "manifest.jsonl").write_text("\n".join(lines) + "\n")
    code, err = _eval(build, tmp_path / "out", capsys)
    assert code == 2 and err.count("\n") == 1 and "'layout'" in err and "'three'" in err, err


def test_a_listing_over_the_episode_limit_is_refused(source, tmp_path, monkeypatch, capsys):
    import luminous_sim.eval.trials as trials

    monkeypatch.setattr(trials, "MAX_EVAL_EPISODES", 3)
    data = tmp_path / "data"
    data.mkdir()
    (data / "splits.json").write_text(json.dumps({"S": [{"task": f"t/r{i}"} for i in range(4)]}))
    code, err = _eval(data, tmp_path / "out", capsys)
    assert code == 2 and "more than 3 trials (luminous_sim.limits.MAX_EVAL_EPISODES)" in err, err


# -- special, oversized and deeply nested trial files -----------------------------------------------------------

@pytest.mark.parametrize("name", ["traj_data.json", "luminous.json"])
@pytest.mark.parametrize("case, says", [
    ("fifo", "a FIFO (named pipe)"),
    ("zero", "a symbolic link"),
    ("big", f"over {MAX_INPUT_BYTES} bytes; expected a trial's {{name}} (luminous_sim.limits.MAX_INPUT_BYTES)"),
    ("nested", "not JSON (nested too deeply for the parser)"),
    ("nan", "not JSON (NaN is not a JSON number)"),
])
def test_special_oversized_and_nested_trial_files_are_broken_trials(name, case, says, source, tmp_path):
    """Run in a child with a time and memory limit: before the fix a FIFO blocked forever and a link to /dev/zero
    was read until memory ran out."""
    data = _folder(tmp_path / "data", source, "t/r")
    path = data / "S" / "t" / "r" / name
    if case == "nan":
        path.write_text('{"nan": NaN, ' + path.read_text().lstrip()[1:])
    else:
        path.unlink()
    if case == "fifo":
        os.mkfifo(path)
    elif case == "zero":
        os.symlink("/dev/zero", path)
    elif case == "big":
        path.write_bytes(b"")
        os.truncate(path, MAX_INPUT_BYTES + 1)
    elif case == "nested":
        path.write_text("[" * 200_000)
    out = tmp_path / "out"
    script = ("import resource, sys; resource.setrlimit(resource.RLIMIT_AS, (3 << 30, 3 << 30)); "
              "from luminous_sim.cli.main import main; sys.exit(main(sys.argv[1:]))")
    done = subprocess.run([sys.executable, "-c", script, "eval", "--policy", "random", "--data", str(data), "--out",
                           str(out), "--env", "max_steps=2"], capture_output=True, text=True, timeout=120, cwd=REPO)
    assert done.returncode == 1 and "Traceback" not in done.stderr, done.stderr[-2000:]
    assert f"S 0 ({BROKEN_TRIAL}): {path}: {says.format(name=name)}" in done.stderr, done.stderr[-2000:]
    episode = json.loads((out / "episodes" / "S-0.json").read_text())
    assert episode["end"] == "unavailable" and episode["cause"] == BROKEN_TRIAL and episode["trial"] == "S/t/r"


# -- values of the wrong kind or out of range, and tasks the scene makes impossible -----------------------------

def _retarget(trial: Path, **params: str) -> None:
    """Change the task's pddl_params in traj_data and the sidecar alike (and the sidecar's goal with them)."""
    from luminous_sim.cdf.predicates import to_sexpr
    from luminous_sim.tasks import PddlParams, goal_for

    _edit(trial / "traj_data.json", lambda d: d["pddl_params"].update(params))

    def side(d):
        d["task"]["pddl_params"].update(params)
        d["task"]["goal"] = to_sexpr(goal_for(PddlParams.from_json(d["task"]["pddl_params"]), d["task"]["task_type"]))

    _edit(trial / "luminous.json", side)


def _absent(source: Path, fits) -> str:
    """A type the trial's scene lacks (nor its unsliced parent: `AppleSliced` names an `Apple`) that `fits`."""
    from luminous_sim.tasks import PddlParams
    from luminous_sim.vocab import ALL_TYPES

    present = {o["type"] for o in json.loads((source / "luminous.json").read_text())["scene"]["objects"]}
    return next(t for t in sorted(ALL_TYPES)
                if t not in present and PddlParams.from_json({"object_target": t}).object_target not in present
                and fits(t))


@pytest.mark.parametrize("slot", ["parent_target", "object_target"])
def test_a_task_naming_a_type_the_scene_lacks_is_a_broken_trial_not_the_agents_failure(slot, source, tmp_path,
                                                                                        capsys):
    from luminous_sim.tasks import PddlParams, params_problems

    data = _folder(tmp_path / "data", source, "t/good", "t/bad")
    doc = json.loads((source / "traj_data.json").read_text())
    task_type, params = doc["task_type"], doc["pddl_params"]
    missing = _absent(source, lambda t: not params_problems(task_type, PddlParams.from_json({**params, slot: t})))
    _retarget(data / "S" / "t" / "bad", **{slot: missing})
    code, err = _eval(data, tmp_path / "out", capsys, fast=False)
    assert code == 1, err
    assert f"pddl_params.{slot} {missing!r}: the scene holds no {missing}" in err, err
    assert "1 of 2 entries are broken trials (S/t/bad)" in err, err
    report = json.loads((tmp_path / "out" / "report.json").read_text())
    assert report["entries"] == 2 and report["drawn"] == 1 and report["unavailable"] == {BROKEN_TRIAL: 1}
    assert report["overall"]["sr"] == 1.0 and report["overall"]["sr_all"] == 0.5
    # resumed, the broken trial's outcome file is read back as it is, not played again
    code, err = _eval(data, tmp_path / "out", capsys, fast=False)
    assert code == 1 and "played again" not in err, err


def _traj(change):
    return "traj_data.json", change


def _side(change):
    return "luminous.json", change


def _init(**values):
    return _traj(lambda d: d["scene"]["init_action"].update(values))


def _first_mask(value):
    def change(d):
        a = next(a for a in d["plan"]["low_actions"] if a["discrete_action"]["args"].get("mask"))
        a["discrete_action"]["args"]["mask"] = value
    return _traj(change)


WRONG = {
    "rotation 45": (_init(rotation=45), "'scene.init_action.rotation': expected 0, 90, 180 or 270"),
    "rotation text": (_init(rotation="90"), "'scene.init_action.rotation'"),
    "horizon 90": (_init(horizon=90), "'scene.init_action.horizon': expected a whole number of degrees from -30"),
    "x off the grid": (_init(x=0.1), "'scene.init_action.x': expected a finite number on the 0.25 m grid"),
    "x far away": (_init(x=1e9), "'scene.init_action.x'"),
    "z true": (_init(z=True), "'scene.init_action.z'"),
    "dirty text": (_traj(lambda d: d["scene"].update(dirty_and_empty="false")), "'scene.dirty_and_empty'"),
    "floor plan number": (_traj(lambda d: d["scene"].update(floor_plan=3)), "'scene.floor_plan'"),
    "task type number": (_traj(lambda d: d.update(task_type=7)), "'task_type'"),
    "args a list": (_traj(lambda d: d["plan"]["low_actions"][0]["discrete_action"].update(args=[1])),
                    "'plan.low_actions[0].discrete_action.args'"),
    "mask negative": (_first_mask([[-1, 4]]), "discrete_action.args.mask': expected ALFRED's run-length"),
    "mask past the frame": (_first_mask([[89_999, 5]]), "discrete_action.args.mask'"),
    "mask text": (_first_mask("abc"), "discrete_action.args.mask'"),
    "benchmark index text": (_side(lambda d: d["benchmark"].update(index="abc")), "'benchmark.index'"),
    "benchmark a list": (_side(lambda d: d.update(benchmark=[1])), "'benchmark'"),
    "scene seed fraction": (_side(lambda d: d["task"].update(scene_seed=1.5)), "'task.scene_seed'"),
    "custom text": (_side(lambda d: d["task"].update(custom="no")), "'task.custom'"),
    "names list": (_side(lambda d: d["task"].update(names=[["a", "b"]])), "'task.names'"),
    "trivial goal": (_side(lambda d: d["task"].update(goal="(and)")), "its goal '(and)' is not the goal of"),
    "sidecar a list": (("luminous.json", None), "expected a JSON object (the sidecar of a build), got list"),
}


@pytest.mark.parametrize("case", list(WRONG))
def test_a_value_of_the_wrong_kind_or_out_of_range_is_a_broken_trial(case, source, tmp_path):
    (name, change), says = WRONG[case]
    data = _folder(tmp_path / "data", source, "t/r")
    path = data / "S" / "t" / "r" / name
    if change is None:
        path.write_text("[]")
    else:
        _edit(path, change)
    (outcome,) = evaluate_data("oracle", data, env_kwargs=FAST).outcomes
    assert outcome.end == "unavailable" and outcome.cause == BROKEN_TRIAL, (outcome.end, outcome.detail)
    assert says in outcome.detail, outcome.detail
    assert outcome.trial == "S/t/r"


def test_an_intact_trial_is_not_broken(source, tmp_path):
    data = _folder(tmp_path / "data", source, "t/r")
    (outcome,) = evaluate_data("oracle", data).outcomes
    assert outcome.success and outcome.cause == ""


# -- the output folder's own files ------------------------------------------------------------------------------

def test_a_run_file_over_the_limit_is_refused_before_it_is_read(tmp_path, source, capsys):
    data = _folder(tmp_path / "data", source, "t/r")
    out = tmp_path / "out"
    out.mkdir()
    (out / "run.json").write_bytes(b"")
    os.truncate(out / "run.json", MAX_EPISODE_FILE_BYTES + 1)
    code, err = _eval(data, out, capsys)
    assert code == 2 and f"run.json: over {MAX_EPISODE_FILE_BYTES} bytes" in err, err
    assert "luminous_sim.limits.MAX_EPISODE_FILE_BYTES" in err, err
