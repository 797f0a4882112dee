"""Dataset builds: the same files whatever the workers, backend or interruptions (a real SIGKILL and a
restart included), a manifest that survives a torn line, honest failure records, and clear refusals."""

from __future__ import annotations

import hashlib
import json
import os
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import pytest

from luminous_sim.benchmark import benchmark_entry
from luminous_sim.data import (
    BuildError,
    BuildOptions,
    JobOutcome,
    LocalBackend,
    Manifest,
    ManifestError,
    SplitJob,
    build,
    build_split,
    make_backend,
    split_jobs,
)
from luminous_sim.data.build import MANIFEST, PARTIAL, RUN, SPLITS, _run_job, _Work, run_job
from luminous_sim.data.manifest import _line

REPO = Path(__file__).resolve().parents[2]
SPLIT = "S+"
N = 3
QUICK = BuildOptions(frames=False, video=False)


def tree(root: Path) -> dict[str, str]:
    """Every file under `root` (relative path -> sha256)."""
    return {p.relative_to(root).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file()}


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    """Episodes 0..N-1 of S+ built in this process, without frames, uninterrupted."""
    out = tmp_path_factory.mktemp("reference") / "build"
    report = build_split(out, SPLIT, N, options=QUICK, progress=False)
    assert report.ran == N and len(report.records) == N
    return out


def test_reference_build_has_alfred_trials_splits_and_manifest(reference):
    records = [json.loads(line) for line in (reference / MANIFEST).read_text().splitlines()]
    assert [r["key"] for r in records] == [f"{SPLIT}/{i:06d}" for i in range(N)]
    built = [r for r in records if r["status"] == "built"]
    assert len(built) == N, "every frozen entry is one the oracle solved"
    for r in records:
        entry = benchmark_entry(SPLIT, r["order"])
        assert (r["task_type"], r["floor_plan"], r["task_seed"], r["episode_key"]) == (
            entry.task_type, entry.floor_plan, entry.task_seed, entry.episode_key)
    for r in built:
        trial = reference / SPLIT / r["trial"]
        data = json.loads((trial / "traj_data.json").read_text())
        assert data["task_type"] == r["task_type"] and r["trial"].endswith(data["task_id"])
        assert data["scene"]["floor_plan"] == r["floor_plan"]
        assert not (trial / "raw_images").exists() and not (trial / "video.mp4").exists()  # --no-frames
    splits = json.loads((reference / SPLITS).read_text())
    assert splits == {SPLIT: [{"repeat_idx": k, "task": r["trial"]} for r in built for k in range(3)]}
    assert not (reference / PARTIAL).exists()


def test_more_workers_give_the_same_files(reference, tmp_path):
    with LocalBackend(2) as backend:
        report = build_split(tmp_path / "b", SPLIT, N, backend, QUICK, progress=False)
    assert report.workers == 2
    assert tree(tmp_path / "b") == tree(reference)


def test_ray_backend_gives_the_same_files(reference, tmp_path):
    pytest.importorskip("ray", reason="Ray is not installed (pip install 'luminous-sim[cluster]')")
    with make_backend("ray", workers=2) as backend:
        build_split(tmp_path / "r", SPLIT, N, backend, QUICK, progress=False)
    assert tree(tmp_path / "r") == tree(reference)


@pytest.mark.slow
def test_frames_and_video_are_the_same_whatever_the_workers_and_backend(tmp_path):
    backends = [("local", 1), ("local", 2)] + ([("ray", 2)] if _has_ray() else [])
    trees = []
    for name, workers in backends:
        with make_backend(name, workers) as backend:
            build_split(tmp_path / f"{name}{workers}", SPLIT, N, backend, BuildOptions(), progress=False)
        trees.append(tree(tmp_path / f"{name}{workers}"))
    assert any(k.endswith("video.mp4") for k in trees[0]) and any(".jpg" in k for k in trees[0])
    assert all(t == trees[0] for t in trees[1:])


def _has_ray() -> bool:
    try:
        import ray  # noqa: F401
    except ImportError:
        return False
    return True


def _cli(out: Path, count: int = N) -> list[str]:
    return [sys.executable, "-m", "luminous_sim.cli.main", "dataset", "build", "--split", SPLIT, "--count",
            str(count), "--out", str(out), "--no-frames", "--no-progress"]


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")])}


def _kill_when(out: Path, ready, timeout: float = 300.0, argv: list[str] | None = None) -> None:
    """Start the build `argv` (default: the split build `_cli(out)`) and SIGKILL it once `ready()` holds."""
    proc = subprocess.Popen(argv or _cli(out), env=_env(), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + timeout
    while not ready() and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    proc.send_signal(signal.SIGKILL)
    proc.wait()


def test_sigkill_mid_job_then_restart_gives_the_files_of_an_uninterrupted_build(reference, tmp_path):
    out = tmp_path / "killed"
    _kill_when(out, lambda: (out / MANIFEST).exists() and (out / PARTIAL).exists()
               and any((out / PARTIAL).iterdir()))
    assert (out / MANIFEST).exists(), "the build was killed before it finished one episode"
    done = subprocess.run(_cli(out), env=_env(), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert tree(out) == tree(reference)


@pytest.mark.slow
@pytest.mark.parametrize("delay", [0.5, 2.0, 4.0, 6.0, 8.0])
def test_sigkill_at_many_moments(reference, tmp_path, delay):
    out = tmp_path / "killed"
    start = time.monotonic()
    _kill_when(out, lambda: time.monotonic() - start > delay)
    done = subprocess.run(_cli(out), env=_env(), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert tree(out) == tree(reference)


def test_a_trial_moved_into_place_but_not_recorded_is_redone(reference, tmp_path):
    """The window between a trial's rename and its manifest line: a restart must not keep a stray copy."""
    out = tmp_path / "b"
    build_split(out, SPLIT, 1, options=QUICK, progress=False)  # episode 0 recorded
    record = _run_job(split_jobs(SPLIT, N)[1], out, QUICK)  # episode 1 in place, no record
    assert record["status"] != "built" or (out / SPLIT / record["trial"]).is_dir()
    stray = out / SPLIT / "pick_and_place_simple-Stray-None-Shelf-1" / "trial_T20000101_000000_000001"
    stray.mkdir(parents=True)  # and a trial no job of this build makes
    (stray / "traj_data.json").write_text("{")
    (out / PARTIAL / "S_000002").mkdir(parents=True)
    (out / PARTIAL / "S_000002" / "half.json").write_text("{")
    build_split(out, SPLIT, N, options=QUICK, progress=False)
    assert tree(out) == tree(reference)


def test_a_worker_of_a_build_run_that_is_over_does_nothing(tmp_path):
    """A worker orphaned by a killed driver must not write into the folder a restarted build cleans."""
    out = tmp_path / "b"
    build(out, [_Failing("x/0", 0)], options=QUICK, progress=False)
    before = tree(out)
    assert run_job(_Work(_Failing("x/1", 1), str(out), QUICK, run="old")) is None  # no run going
    (out / PARTIAL).mkdir()
    (out / PARTIAL / RUN).write_text("new")
    assert run_job(_Work(_Failing("x/1", 1), str(out), QUICK, run="old")) is None
    assert run_job(_Work(_Failing("x/1", 1), str(out), QUICK, run="new"))["cause"] == "no Mug here"
    (out / PARTIAL / RUN).unlink()
    (out / PARTIAL).rmdir()
    assert tree(out) == before


def test_manifest_drops_a_torn_last_line_and_refuses_a_broken_one(tmp_path):
    path = tmp_path / MANIFEST
    m = Manifest(path)
    m.append(_failed("a"))
    with open(path, "ab") as fh:
        fh.write(b'{"key": "b", "sta')  # a kill during the write
    m = Manifest(path)
    assert "a" in m and "b" not in m and len(m) == 1
    m.append(_failed("b"))
    assert [json.loads(line)["key"] for line in path.read_text().splitlines()] == ["a", "b"]
    a, b = (_line(_failed(k)) for k in "ab")
    path.write_text(f'{a}not json\n{b}')
    with pytest.raises(ManifestError, match="line 2 is not a JSON record"):
        Manifest(path)
    path.write_text(a + _line({**_failed("a"), "cause": "other"}))
    with pytest.raises(ManifestError, match="second, different record for 'a'"):
        Manifest(path)


def _failed(key: str) -> dict[str, object]:
    """A manifest record of a failed job, as a build writes it."""
    return {"key": key, "split": "mine", "order": 0, "task_type": "pick_and_place_simple", "status": "failed",
            "stage": "task", "cause": "no Mug here", "trial": None}


@dataclass(frozen=True)
class _Failing:
    """A job kind of its own that fails (or breaks) without writing a trial."""

    key: str
    order: int
    crash: bool = False
    split: str = "mine"
    task_type: str = "pick_and_place_simple"

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        if self.crash:
            raise ValueError("a bug")
        return JobOutcome(stage="task", cause="no Mug here", details={"where": "test"})


def test_failures_are_recorded_with_their_first_cause_and_counted(tmp_path):
    jobs = [_Failing("x/0", 0), _Failing("x/1", 1), _Failing("x/2", 2, crash=True)]
    report = build(tmp_path / "b", jobs, options=QUICK, progress=False)
    assert (report.built, report.failed) == (0, 3)
    rows = report.by_task_type()["pick_and_place_simple"]
    assert (rows["jobs"], rows["built"], rows["failed"]) == (3, 0, 3)
    assert rows["causes"] == [(("task", "no Mug here"), 2), (("crash", "ValueError: a bug"), 1)]
    text = report.summary()
    assert "failed at task (2x): no Mug here" in text and "failed at crash (1x): ValueError: a bug" in text
    records = [json.loads(line) for line in (tmp_path / "b" / MANIFEST).read_text().splitlines()]
    assert [r["status"] for r in records] == ["failed"] * 3 and records[0]["where"] == "test"
    assert json.loads((tmp_path / "b" / SPLITS).read_text()) == {}
    again = build(tmp_path / "b", jobs, options=QUICK, progress=False)  # task failures are not redone; a crash is
    assert again.ran == 1 and again.failed == 3 and again.retried == ("x/2",)
    assert "crashed on" in again.summary() and [r["key"] for r in again.crashed] == ["x/2"]


@dataclass(frozen=True)
class _CrashingOnce:
    """A job that crashes (or, with `stage`, fails at that stage) while `flag` is missing, then builds a trial: an
    installation fault fixed between two runs."""

    key: str
    order: int
    flag: str
    stage: str = "crash"
    split: str = "mine"
    task_type: str = "pick_and_place_simple"

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        if not Path(self.flag).exists():
            if self.stage == "crash":
                raise FileNotFoundError("no room 'FloorPlan10' in the room library")
            return JobOutcome(stage=self.stage, cause="another episode than the frozen split")
        trial = work / "pick_and_place_simple-Mug-0" / f"trial_{self.order}"
        trial.mkdir(parents=True)
        (trial / "traj_data.json").write_text(json.dumps({"key": self.key}))
        return JobOutcome(trial=trial)


@pytest.mark.parametrize("stage", ["crash", "version"])
def test_a_crash_is_never_cached_as_a_result_and_is_retried_on_the_next_run(tmp_path, stage):
    flag = tmp_path / "fixed"
    jobs = [_CrashingOnce("x/0", 0, str(flag), stage), _Failing("x/1", 1)]
    first = build(tmp_path / "b", jobs, options=QUICK, progress=False)
    assert (first.built, first.failed) == (0, 2) and [r["key"] for r in first.crashed] == ["x/0"]
    assert "failed through the installation" in first.summary()
    flag.write_text("")  # the install is fixed
    second = build(tmp_path / "b", jobs, options=QUICK, progress=False)
    assert second.ran == 1 and second.retried == ("x/0",) and (second.built, second.failed) == (1, 1)
    assert not second.crashed and second.records[0]["status"] == "built"
    third = build(tmp_path / "b", jobs, options=QUICK, progress=False)
    assert third.ran == 0 and not third.retried


def test_rebuild_does_every_asked_job_again(tmp_path):
    flag = tmp_path / "fixed"
    flag.write_text("")
    jobs = [_CrashingOnce("x/0", 0, str(flag)), _Failing("x/1", 1)]
    build(tmp_path / "b", jobs, options=QUICK, progress=False)
    again = build(tmp_path / "b", jobs, options=QUICK, progress=False, rebuild=True)
    assert again.ran == 2 and again.rebuilt == 2 and "rebuild was asked for" in again.summary()
    assert (again.built, again.failed) == (1, 1)


def test_refusals_name_the_problem(tmp_path):
    foreign = tmp_path / "foreign"
    foreign.mkdir()
    (foreign / "notes.txt").write_text("mine")
    with pytest.raises(BuildError, match="not empty and holds no dataset build"):
        build(foreign, [_Failing("x/0", 0)], options=QUICK, progress=False)
    out = tmp_path / "b"
    build(out, [_Failing("x/0", 0)], options=QUICK, progress=False)
    with pytest.raises(BuildError, match="other settings .*frames: False there, True now"):
        build(out, [_Failing("x/0", 0)], options=BuildOptions(), progress=False)
    with pytest.raises(BuildError, match="repeated: x/0"):
        build(out, [_Failing("x/0", 0), _Failing("x/0", 1)], options=QUICK, progress=False)
    with pytest.raises(BuildError, match="plain name"):
        build(out, [_Failing("x/0", 0, split="../up")], options=QUICK, progress=False)


def test_a_second_build_in_the_same_folder_is_refused(tmp_path):
    import fcntl

    out = tmp_path / "b"
    build(out, [_Failing("x/0", 0)], options=QUICK, progress=False)
    with open(out / ".build.lock", "a") as held:
        fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)
        with pytest.raises(BuildError, match="another build is running"):
            build(out, [_Failing("x/1", 1)], options=QUICK, progress=False)


def test_cli_refuses_bad_arguments(tmp_path, capsys):
    from luminous_sim.cli.main import main

    assert main(["dataset", "build", "--split", "S+", "--count", "1", "--out", str(tmp_path / "b"),
                 "--address", "10.0.0.1:6379"]) == 2
    assert "--address 10.0.0.1:6379 is for the ray backend" in capsys.readouterr().err
    with pytest.raises(SystemExit) as exc:
        main(["dataset", "build", "--split", "Q+", "--count", "1", "--out", str(tmp_path / "b")])
    assert exc.value.code == 2


def test_a_split_job_writes_the_frozen_episode_and_its_key_in_the_sidecar(tmp_path):
    entry = benchmark_entry("U+", 8)
    outcome = SplitJob("U+", 8).run(tmp_path, QUICK)
    assert outcome.trial is not None, outcome.cause
    traj = json.loads((outcome.trial / "traj_data.json").read_text())
    side = json.loads((outcome.trial / "luminous.json").read_text())
    assert traj["task_type"] == entry.task_type and traj["pddl_params"] == entry.pddl_params
    assert traj["scene"]["floor_plan"] == entry.floor_plan
    init = traj["scene"]["init_action"]
    assert (init["x"], init["z"], init["rotation"], init["horizon"]) == (entry.start.x, entry.start.y,
                                                                         entry.start.rotation, entry.start.horizon)
    assert side["benchmark"]["episode_key"] == entry.episode_key == outcome.details["episode_key"]
    assert (side["benchmark"]["split"], side["benchmark"]["index"]) == ("U+", 8)


def test_a_job_of_a_checkout_that_makes_another_episode_fails_as_version(tmp_path, monkeypatch):
    from dataclasses import replace

    import luminous_sim.benchmark as bench

    real = bench.benchmark_entry
    monkeypatch.setattr(bench, "benchmark_entry", lambda s, i: replace(real(s, i), episode_key="0" * 20))
    outcome = SplitJob("U+", 0).run(tmp_path, QUICK)
    assert outcome.trial is None and outcome.stage == "version" and "new version" in outcome.cause


def test_a_trial_is_synced_once_by_syncfs_or_file_by_file_without_it(tmp_path, monkeypatch):
    build_module = sys.modules["luminous_sim.data.build"]  # `luminous_sim.data.build` is also the function

    trial = tmp_path / "t" / "trial_1"
    (trial / "raw_images").mkdir(parents=True)
    for name in ("traj_data.json", "raw_images/000000000.jpg", "raw_images/000000001.jpg"):
        (trial / name).write_bytes(b"x")
    fsyncs, syncs = [], []
    real_fsync = os.fsync
    monkeypatch.setattr(build_module.os, "fsync", lambda fd: (fsyncs.append(fd), real_fsync(fd))[1])
    if sys.platform.startswith("linux"):
        assert build_module._syncfs() is not None  # glibc and musl have it
    monkeypatch.setattr(build_module, "_syncfs", lambda: lambda fd: (syncs.append(fd), 0)[1])
    build_module._fsync_tree(trial)
    assert len(syncs) == 1 and not fsyncs
    monkeypatch.setattr(build_module, "_syncfs", lambda: lambda fd: -1)  # it failed: each file and folder then
    build_module._fsync_tree(trial)
    assert len(fsyncs) == 5
    monkeypatch.setattr(build_module, "_syncfs", lambda: None)
    build_module._fsync_tree(trial)
    assert len(fsyncs) == 10


def test_reading_a_manifest_never_writes_it(tmp_path):
    """`luminous eval --data` reads a user's manifest: a torn last line is left as it is until a build appends."""
    path = tmp_path / MANIFEST
    path.write_text(_line(_failed("a")) + '{"key": "b", "sta')
    before = path.read_bytes()
    assert len(Manifest(path)) == 1
    assert path.read_bytes() == before
