"""The perception dataset (`luminous dataset perception`): frames with exact depth and labels, for learning the
rgb track's depth and segmentation (issue 45, docs/perception.md).

Each job renders one episode's frames from the agent's own camera (agent height, ALFRED's 300x300 by default):
the start and an exploratory walk of random moves, turns and tilts, then (from the start again) every other
frame of the expert's path (held objects, opened receptacles, close views of what is acted on). A job's
episode is either generated on the fly in one of CSSG's own room shapes (in no split: every split is laid out
in one of ALFRED's floor plans) or a built trial of a dataset folder (`trials`: e.g. ALFRED's train designs
re-solved), restored from its files; a trial in a U+ or U+test structure is refused (`EVALUATION_ONLY`). An
evaluation dataset renders entries of a frozen split instead (`evaluation_jobs`: U+'s frames, to measure
perception on structures never trained on).

One shard per job (`shards/shard-NNNNN.npz`: `rgb` uint8 (N, H, W, 3), `depth` uint16 millimetres, `types`
uint8 type indices (the env's `instance_types`; 0 structure and none), `instances` int16 body ids (-1 none),
`expert` bool per frame), written atomically, then its record appended to `manifest.jsonl` (the build's
`Manifest`: a killed run resumes where it stopped). A record names the scene by content
(`Scene.content_key`), its room structure and type, the episode's task type, frames and the shard's sha256.
The same seed gives the same shards, whichever worker renders them.
"""

from __future__ import annotations

import hashlib
import io
import json
import sys
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.data.backends import Backend, map_jobs
from luminous_sim.data.manifest import Manifest, Record
from luminous_sim.errors import LuminousError
from luminous_sim.fileio import write_atomic
from luminous_sim.limits import MAX_BUILD_JOBS
from luminous_sim.scene import Scene
from luminous_sim.splits import PLUS_SPLITS

FORMAT = "luminous-perception/1"
SPLIT = "perception"
"""The `split` field of every record (the manifest is the build's)."""
SHARDS = "shards"
EXPERT_FRAMES = 24
"""Most frames kept from the expert's path (every other step)."""
EXPLORE_FRAMES = 16
"""Frames of the exploratory walk (each after one to three random actions)."""
EVALUATION_ONLY = frozenset(s for name in ("U+", "U+test") for s in PLUS_SPLITS[name].structures)
"""Room structures no training frame may come from (S+'s may, with other layouts, as ALFRED's seen split shares
its structures with its training split)."""
WALK = ("MoveAhead", "MoveAhead", "MoveAhead", "RotateLeft", "RotateRight", "LookUp", "LookDown")
SEED_STRIDE = 1_000_003
"""Episode seeds of a dataset seed are `seed * SEED_STRIDE + index` (no two seeds' first million overlap)."""


class PerceptionDataError(LuminousError):
    """A perception dataset that cannot be made or read: bad options, a refused trial, a broken shard."""


class EvaluationStructure(PerceptionDataError):
    """A training job's episode is in a U+ or U+test structure (recorded as the failed job's `cause`)."""


@dataclass(frozen=True)
class PerceptionJob:
    """One shard: generated episode `index` of the dataset `seed`, or the built trial `trial`."""

    index: int
    seed: int
    size: int = 300
    trial: str = ""
    """A trial folder (absolute); "" for a generated episode."""
    split: str = ""
    """A frozen split whose entry `entry` this job renders (an evaluation dataset: `evaluation_jobs`)."""
    entry: int = -1

    @property
    def key(self) -> str:
        return f"perception/{self.index:05d}"

    @property
    def shard(self) -> str:
        return f"{SHARDS}/shard-{self.index:05d}.npz"

    @property
    def episode_seed(self) -> int:
        return self.seed * SEED_STRIDE + self.index


def perception_jobs(seed: int, generated: int, trials: Sequence[Path] = (), size: int = 300) -> list[PerceptionJob]:
    """A training dataset's jobs: `generated` episodes generated on the fly, then one per trial folder."""
    jobs = [PerceptionJob(i, seed, size) for i in range(generated)]
    jobs += [PerceptionJob(generated + k, seed, size, str(Path(t).resolve())) for k, t in enumerate(trials)]
    return jobs


def evaluation_jobs(split: str, entries: Sequence[int], seed: int = 0, size: int = 300) -> list[PerceptionJob]:
    """An evaluation dataset's jobs: entries of a frozen split (e.g. U+'s, whose structures no training frame
    comes from); `luminous agents train-perception` refuses such a dataset."""
    return [PerceptionJob(k, seed, size, split=split, entry=int(e)) for k, e in enumerate(entries)]


def built_trials(build: Path) -> list[Path]:
    """The trial folders a dataset build wrote (its manifest's built records, in job order).

    Raises:
        PerceptionDataError: the folder has no manifest.jsonl.
    """
    manifest_path = Path(build) / "manifest.jsonl"
    if not manifest_path.is_file():
        raise PerceptionDataError(f"--trials {build}: no manifest.jsonl (expected a `luminous dataset build` folder)")
    records = sorted((r for r in Manifest(manifest_path) if r["status"] == "built"),
                     key=lambda r: (r["split"], r["order"]))
    return [Path(build) / r["split"] / r["trial"] for r in records]


def _env(size: int) -> Any:
    from luminous_sim.env import LuminousEnv

    return LuminousEnv(width=size, height=size, depth=True, segmentation=True, instance_types=True,
                       verify_expert=False)


def _frame(obs: dict[str, Any], expert: bool) -> dict[str, np.ndarray | bool]:
    depth = np.clip(np.asarray(obs["depth"])[..., 0] * 1000.0, 0, 65535)
    return {"rgb": np.asarray(obs["rgb"], np.uint8), "depth": np.round(depth).astype(np.uint16),
            "types": np.asarray(obs["instance_types"]).astype(np.uint8),
            "instances": np.asarray(obs["segmentation"]).astype(np.int16), "expert": expert}


def render_frames(job: PerceptionJob, env: Any = None) -> tuple[list[dict[str, Any]], dict[str, Any]]:
    """The job's frames and what they are of (scene key, structure, room type, task type).

    Raises:
        EvaluationStructure: a training job's episode is in an evaluation-only structure (`EVALUATION_ONLY`).
    """
    own = env is None
    env = env or _env(job.size)
    try:
        options = {"trial": job.trial} if job.trial else {"split": job.split, "index": job.entry} if job.split else None
        obs, _ = env.reset(seed=job.episode_seed, options=options)
        episode = env.episode
        scene = episode.scene
        if not job.split and scene.room.name in EVALUATION_ONLY:
            raise EvaluationStructure(f"{job.trial or job.key}: its structure {scene.room.name} is in U+ or "
                                      "U+test, whose structures never feed training")
        about = {"scene_key": scene.content_key(), "structure": scene.room.name,
                 "room_type": scene.room.room_type, "task_type": episode.goal.task_type}
        frames = [_frame(obs, False)]
        rng = np.random.default_rng([job.episode_seed, 7])
        index = {name: env.actions.index(name) for name in WALK}
        done = False
        for _ in range(EXPLORE_FRAMES):
            for _ in range(int(rng.integers(1, 4))):
                obs, _, terminated, truncated, _ = env.step(index[WALK[int(rng.integers(len(WALK)))]])
                done = terminated or truncated  # ALFRED's failure limit: moves into walls fail
                if done:
                    break
            frames.append(_frame(obs, False))
            if done:
                break
        # the expert's path from the start again (the world is reused within a scene: a cheap reset)
        obs, _ = env.reset(seed=job.episode_seed, options=options)
        frames.append(_frame(obs, True))
        for step in range(2 * EXPERT_FRAMES):
            try:
                action = env.expert_action()
            except LuminousError:
                break
            obs, _, terminated, truncated, _ = env.step(action)
            if step % 2 == 1 or terminated or truncated:
                frames.append(_frame(obs, True))
            if terminated or truncated or len(frames) >= EXPLORE_FRAMES + 1 + EXPERT_FRAMES:
                break
        return frames, about
    finally:
        if own:
            env.close()


def shard_bytes(frames: Sequence[dict[str, Any]]) -> bytes:
    """The frames as one compressed npz (deterministic bytes: no timestamps in numpy's zip entries)."""
    buf = io.BytesIO()
    arrays: dict[str, Any] = {"expert": np.array([bool(f["expert"]) for f in frames])}
    arrays.update({k: np.stack([f[k] for f in frames]) for k in ("rgb", "depth", "types", "instances")})
    np.savez_compressed(buf, **arrays)
    return buf.getvalue()


def run_job(job_and_out: tuple[PerceptionJob, str]) -> Record:
    """Render one job's shard into the dataset folder and return its manifest record (failed: why)."""
    job, out = job_and_out
    base: Record = {"key": job.key, "split": SPLIT, "order": job.index, "seed": job.seed,
                    "episode_seed": job.episode_seed, "source": _source(job),
                    "trial_dir": job.trial}
    try:
        frames, about = render_frames(job)
    except LuminousError as exc:
        return {**base, "status": "failed", "trial": None, "task_type": "", "stage": "render",
                "cause": type(exc).__name__, "error": str(exc).splitlines()[0][:300]}
    data = shard_bytes(frames)
    write_atomic(Path(out) / job.shard, data)
    return {**base, **about, "status": "built", "trial": job.shard, "files": 1, "frames": len(frames),
            "expert_frames": sum(bool(f["expert"]) for f in frames), "size": job.size,
            "sha256": hashlib.sha256(data).hexdigest()}


def _source(job: PerceptionJob) -> str:
    return f"{job.split}:{job.entry}" if job.split else "trial" if job.trial else "generated"


@dataclass
class PerceptionReport:
    """What a perception build did: shards made now and before, failures by cause, frames in all."""

    made: int
    kept: int
    failed: dict[str, int]
    frames: int

    def summary(self) -> str:
        failed = ", ".join(f"{k} {v}" for k, v in sorted(self.failed.items())) or "none"
        return (f"{self.made + self.kept} shards ({self.made} made now, {self.kept} before), {self.frames} "
                f"frames; failed: {failed}")


def build_perception(out: Path, jobs: Sequence[PerceptionJob], backend: Backend | None = None,
                     progress: bool = False) -> PerceptionReport:
    """Render every job not yet in `out/manifest.jsonl` (a record whose shard is missing or altered is done
    again), append each record as its shard lands. `out/perception.json` (the format, the jobs' options) says
    `complete: false` until the last job is done, then gives the finished manifest's sha256.

    Raises:
        PerceptionDataError: too many jobs, or `out` holds a perception dataset of another seed or size.
    """
    if len(jobs) > MAX_BUILD_JOBS:
        raise PerceptionDataError(f"{len(jobs)} perception jobs: at most {MAX_BUILD_JOBS}")
    evaluation = _evaluation(jobs)
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    _check_same_options(out, jobs)
    header = {"format": FORMAT, "seed": jobs[0].seed if jobs else 0, "size": jobs[0].size if jobs else 300,
              "evaluation": evaluation, "jobs": len(jobs),
              "generated": sum(not j.trial and not j.split for j in jobs),
              "trials": sum(bool(j.trial) for j in jobs), "entries": [j.entry for j in jobs if j.split]}
    write_atomic(out / "perception.json", json.dumps({**header, "complete": False}, indent=1, sort_keys=True) + "\n")
    manifest = Manifest(out / "manifest.jsonl", repair=True)
    stale = [r["key"] for r in manifest if r["status"] == "built" and not _intact(out, r)]
    manifest.remove(stale)
    todo = [j for j in jobs if j.key not in manifest]
    kept = len(jobs) - len(todo)
    made = 0
    for _, record in map_jobs(run_job, [(j, str(out)) for j in todo], backend):
        manifest.append(record)
        made += 1
        if progress:
            print(f"\rperception: {kept + made}/{len(jobs)} shards", end="", file=sys.stderr, flush=True)
    if progress:
        print(file=sys.stderr)
    manifest.sorted_rewrite(lambda r: r["order"])
    mine = {j.key for j in jobs}
    records = [r for r in manifest if r["key"] in mine]
    failed: dict[str, int] = {}
    for r in records:
        if r["status"] == "failed":
            failed[r["cause"]] = failed.get(r["cause"], 0) + 1
    header = {**header, "complete": True, "manifest_sha256": manifest_digest(out)}
    write_atomic(out / "perception.json", json.dumps(header, indent=1, sort_keys=True) + "\n")
    return PerceptionReport(made, kept, failed, sum(int(r.get("frames", 0)) for r in records))


def manifest_digest(out: Path) -> str:
    """The sha256 of the dataset's manifest.jsonl (what a checkpoint records as its data)."""
    return hashlib.sha256((Path(out) / "manifest.jsonl").read_bytes()).hexdigest()


def _evaluation(jobs: Sequence[PerceptionJob]) -> str:
    """The split an evaluation dataset's jobs are entries of ("" for a training dataset).

    Raises:
        PerceptionDataError: entries of a split mixed with training jobs, or of two splits.
    """
    splits = {j.split for j in jobs}
    if len(splits) > 1:
        raise PerceptionDataError("a perception dataset is either a training one (generated episodes, trials) or "
                                  f"an evaluation one (one split's entries), got jobs of {sorted(splits)}")
    return splits.pop() if splits else ""


def read_header(out: Path) -> dict[str, Any]:
    """A perception dataset's `perception.json`.

    Raises:
        PerceptionDataError: missing, not JSON, or not this format.
    """
    path = Path(out) / "perception.json"
    try:
        header = json.loads(path.read_text())
        if header["format"] != FORMAT:
            raise ValueError(f"format {header['format']!r}, expected {FORMAT!r}")
        int(header["seed"]), int(header["size"]), str(header["evaluation"])
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise PerceptionDataError(f"{path}: not a perception dataset's header ({exc})") from None
    return dict(header)


def _check_same_options(out: Path, jobs: Sequence[PerceptionJob]) -> None:
    if not (out / "perception.json").is_file() or not jobs:
        return
    header = read_header(out)
    before = (int(header["seed"]), int(header["size"]), header["evaluation"])
    now = (jobs[0].seed, jobs[0].size, _evaluation(jobs))
    if before != now:
        raise PerceptionDataError(f"{out} holds a perception dataset of seed {before[0]}, size {before[1]}, "
                                  f"evaluation {before[2]!r}; this run asks for seed {now[0]}, size {now[1]}, "
                                  f"evaluation {now[2]!r} (use another folder)")


def _intact(out: Path, record: Record) -> bool:
    path = out / record["trial"]
    return path.is_file() and hashlib.sha256(path.read_bytes()).hexdigest() == record["sha256"]


def read_manifest(out: Path) -> list[Record]:
    """The built shards' records of a perception dataset, in order.

    Raises:
        PerceptionDataError: no manifest.jsonl there.
    """
    path = Path(out) / "manifest.jsonl"
    if not path.is_file():
        raise PerceptionDataError(f"{out}: no manifest.jsonl (expected a `luminous dataset perception` folder)")
    return sorted((r for r in Manifest(path) if r["status"] == "built"), key=lambda r: r["order"])


def iter_shards(out: Path) -> Iterator[tuple[Record, dict[str, np.ndarray]]]:
    """Each built shard's record and arrays, checked against the record's sha256.

    Raises:
        PerceptionDataError: a shard missing or not what its record says.
    """
    for record in read_manifest(out):
        path = Path(out) / record["trial"]
        if not path.is_file():
            raise PerceptionDataError(f"{path}: missing (the manifest lists it)")
        data = path.read_bytes()
        if hashlib.sha256(data).hexdigest() != record["sha256"]:
            raise PerceptionDataError(f"{path}: its sha256 is not the manifest's (altered or torn)")
        with np.load(io.BytesIO(data)) as z:
            yield record, {k: z[k] for k in z.files}


def evaluation_scene_keys(builds: Sequence[Path]) -> set[str]:
    """The scene keys of every trial in the given dataset builds (S, S+, U+, U+test), from their sidecars."""
    keys: set[str] = set()
    for build in builds:
        for trial in built_trials(build):
            side = json.loads((trial / "luminous.json").read_text())
            keys.add(Scene.from_json(json.dumps(side["scene"]), where=str(trial)).content_key())
    return keys


def leaks(out: Path, builds: Sequence[Path]) -> list[str]:
    """Why the perception dataset would feed evaluation scenes to training: an evaluation dataset, records whose
    scene key is a trial's of `builds`, or whose structure is U+'s or U+test's (empty: none)."""
    keys = evaluation_scene_keys(builds)
    evaluation = read_header(out)["evaluation"]
    found = [f"{out}: an evaluation dataset (entries of {evaluation})"] if evaluation else []
    for record in read_manifest(out):
        if record["scene_key"] in keys:
            found.append(f"{record['trial']}: scene {record['scene_key']} is an evaluation trial's")
        if record["structure"] in EVALUATION_ONLY:
            found.append(f"{record['trial']}: structure {record['structure']} is U+'s or U+test's")
    return found
