"""Dataset builds: many independent jobs, each writing one ALFRED trial (or recording why it could not),
resumable and safe against a kill at any moment, on any backend (`data.backends`).

Method (a) of the paper is `SplitJob`: episode `index` of a frozen S+/U+/U+test split
(`episodes.entry_spec`: its layout, task, initial state and start) solved by the oracle, exported in
ALFRED's json_2.1.0 layout. Another job kind
(a real ALFRED task design re-solved in its own floor plan, method (b)) plugs into the same `build`.

A build folder holds::

    build.json            the settings the build was started with (a resumed build must match them)
    manifest.jsonl        one record per finished job (built or failed, with the first cause)
    splits.json           ALFRED's oct21.json layout: split -> [{"repeat_idx", "task"}]
    <split>/<task>/<trial>/   traj_data.json, raw_images/, pddl_states/, video.mp4, luminous.json

How it survives a kill: each job writes its trial under `.partial/<job>/`, syncs it and renames it
into place, and only then does the driver append (and fsync) its manifest record. A restarted build
waits for the current job of any worker the killed one left running (`.workers.lock`; such a worker
then sees a new run id in `.partial/RUN` and does nothing more), removes `.partial/` and any trial
folder that the manifest does not list (one renamed into place just before the kill), and runs the
jobs the manifest lacks. Each job depends on
its own key alone, so the files are the same whatever the worker count, backend or interruptions.

What a resumed build trusts: nothing it has not checked. The manifest is validated line by line
(`manifest.check_record`: a forged trial path is refused, never followed); each finished trial's digest
is recomputed from its files and compared with its record, and a trial that is missing, damaged or
holds a symbolic link is done again (a record that disagrees with its job too); nothing is followed
through a symbolic link, so a build writes and deletes inside its folder only. A build is extended,
never shrunk: a job list that leaves out finished jobs of a split it builds (a smaller `--count`) is
refused. One folder may hold several splits (each its own folder, its own records and its own entry
of `splits.json`).
"""

from __future__ import annotations

import contextlib
import functools
import hashlib
import json
import os
import shutil
import sys
import time
import uuid
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Protocol

from luminous_sim.data.alfred_export import ExportError, export_alfred
from luminous_sim.data.backends import Backend, map_jobs
from luminous_sim.data.manifest import Manifest, Record, plain_name
from luminous_sim.errors import LuminousError, link_or_kind
from luminous_sim.fileio import one_line, write_atomic
from luminous_sim.limits import MAX_BUILD_JOBS
from luminous_sim.splits import oct21_document

BUILD_FORMAT = "luminous-dataset-build/2"
"""/2: split entries are the frozen splits' (`luminous_sim.benchmark`); a /1 build (entries of the old definition)
is refused rather than resumed with trials of other episodes."""
SETTINGS = "build.json"
MANIFEST = "manifest.jsonl"
SPLITS = "splits.json"
PARTIAL = ".partial"
LOCK = ".build.lock"
WORKERS_LOCK = ".workers.lock"
RUN = "RUN"
"""`.partial/RUN`: the id of the build run now going; a job of another run (a worker orphaned by a killed
build) sees it changed and leaves the folder alone."""
ANNOTATIONS = 3
"""Instructions per trajectory (ALFRED has about three per trajectory, `repeat_idx` 0..2)."""
CAUSES_SHOWN = 2
"""Most frequent failure causes shown per task type in the summary."""
RETRIED_STAGES = ("crash", "version")
"""Failures of the installation, not of the task: an exception (a bug, missing data) or an episode this install
makes differently from the frozen split. Their records are never kept as results: the next run does the job
again."""


def retried(record: Record) -> bool:
    """Whether a manifest record is a failure of the installation (`RETRIED_STAGES`), done again on the next run."""
    return record.get("status") == "failed" and record.get("stage") in RETRIED_STAGES


class BuildError(LuminousError):
    """A build that cannot start: a folder holding something else, settings that differ from the build
    being resumed, another build running in the same folder, a bad job list."""


@dataclass(frozen=True)
class BuildOptions:
    """What each trial holds beyond traj_data.json: frames (raw_images/) and a video of them; `speaker`: a
    learned speaker's checkpoint whose instructions replace the templates' (`language.speaker.annotate`)."""

    frames: bool = True
    video: bool = True
    speaker: str | None = None
    human_language: bool = False
    """--from-alfred: each design's own human annotations in place of the templates (`data.alfred_language`)."""
    design_seed: int | None = None
    """--from-alfred: the seed of every design's scene (recorded, so that a rerun cannot mix two)."""
    alfworld: bool = True
    """Write ALFWorld's problem (`initial_state.pddl`) beside each traj_data.json (`--no-alfworld`: not)."""

    def settings(self) -> dict[str, Any]:
        extra: dict[str, Any] = {}
        if self.speaker is not None:
            from luminous_sim.language.speaker.annotate import checkpoint_digest

            extra["speaker_sha256"] = checkpoint_digest(self.speaker)
        if self.design_seed is not None:
            extra.update(design_seed=self.design_seed, language="human" if self.human_language else "templates")
        return {"format": BUILD_FORMAT, "frames": self.frames, "video": self.video and self.frames,
                "alfworld": self.alfworld,
                "annotations": "the designs' own" if self.human_language else ANNOTATIONS, **extra}


@dataclass(frozen=True)
class JobOutcome:
    """What a job did: the trial folder it wrote (inside its work folder), or the stage and first cause
    of its failure; `details` are recorded in the manifest as they are (JSON values, deterministic)."""

    trial: Path | None = None
    stage: str | None = None
    """Where a job failed: "version" (this checkout makes another episode than the frozen split), "layout"
    (generating the layout), "task" (no task of the type fits the scene),
    "oracle" (the oracle did not solve it), "export" (the export refused it) or "crash" (an unexpected error,
    a bug: its type and message are the cause)."""
    cause: str | None = None
    details: dict[str, Any] = field(default_factory=dict)


class Job(Protocol):
    """One unit of a build: `key` unique in the build folder, `split` the folder its trial goes to,
    `order` its place in that split's listing, `task_type` the ALFRED task type it asks for (known
    before it runs: failures count against it). `run` writes at most one trial under `work`."""

    @property
    def task_type(self) -> str: ...

    @property
    def key(self) -> str: ...

    @property
    def split(self) -> str: ...

    @property
    def order(self) -> int: ...

    def run(self, work: Path, options: BuildOptions) -> JobOutcome: ...


def _failure_cause(exc: BaseException) -> str:
    return str(exc) or type(exc).__name__


@dataclass(frozen=True)
class IndexedJob:
    """The naming part of a `Job` that is episode `index` of a split: key `<split>/<index:06d>`, listed in index
    order."""

    split: str
    index: int

    @property
    def key(self) -> str:
        return f"{self.split}/{self.index:06d}"

    @property
    def order(self) -> int:
        return self.index


@dataclass(frozen=True)
class SplitJob(IndexedJob):
    """Episode `index` of frozen split `split` (method (a)): `episodes.entry_spec` of its entry (the
    episode `luminous eval --split` and the env's `reset(options={"split": ..., "index": ...})` play), solved
    by the oracle from the entry's start, exported in ALFRED's layout; the manifest record and the trial's
    sidecar carry its `episode_key`."""

    @property
    def task_type(self) -> str:
        from luminous_sim.benchmark import benchmark_entry

        return benchmark_entry(self.split, self.index).task_type

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        from luminous_sim.benchmark import benchmark_entry, start_fields
        from luminous_sim.episode import run_spec
        from luminous_sim.episodes import SplitVersionError, entry_spec

        entry = benchmark_entry(self.split, self.index)
        details: dict[str, Any] = {"floor_plan": entry.floor_plan, "layout": entry.layout,
                                   "layout_seed": entry.layout_seed, "draw": entry.draw, "task_seed": entry.task_seed,
                                   "episode_key": entry.episode_key}

        def failed(stage: str, cause: str) -> JobOutcome:
            return JobOutcome(stage=stage, cause=cause, details=details)

        try:
            made = entry_spec(entry)
        except SplitVersionError as exc:
            return failed("version", _failure_cause(exc))
        assert made.start is not None, "a split entry has its start"
        result, record = run_spec(made, entry.task_seed, record_frames=options.frames,
                                  extra_annotations=ANNOTATIONS - 1, places=options.alfworld)
        traj = record.trajectory
        details.update(goal=result.goal, low_actions=len(traj.low_actions), replans=traj.replans)
        if not result.success:
            done, total = result.goal_conditions
            return failed("oracle", traj.failures[0] if traj.failures else f"{done}/{total} goal conditions met")
        sidecar = {"benchmark": {"split": entry.split, "index": entry.index, "episode_key": made.key,
                                 "start": start_fields(made.start), "dirty": list(made.dirty)}}
        try:
            trial = export_alfred(work, made.scene, record, seed=entry.task_seed,
                                  video=options.video and options.frames, sidecar=sidecar)
        except ExportError as exc:
            return failed("export", _failure_cause(exc))
        return JobOutcome(trial=trial, details=details)


def split_jobs(split: str, count: int, start: int = 0) -> list[SplitJob]:
    """Jobs for episodes `start .. start + count - 1` of `split` (checked: unknown split, negative index,
    a count over `limits.MAX_BUILD_JOBS`)."""
    if not 0 <= count <= MAX_BUILD_JOBS:
        raise BuildError(f"count must be from 0 to {MAX_BUILD_JOBS} (luminous_sim.limits.MAX_BUILD_JOBS), got {count}")
    from luminous_sim.benchmark import benchmark_size

    size = benchmark_size(split)  # raises SplitError for an unknown or unfrozen split
    if start < 0 or start + count > size:
        from luminous_sim.splits import SplitError

        raise SplitError(f"split {split} holds episodes 0..{size - 1}; asked for {start}..{start + count - 1}")
    return [SplitJob(split, i) for i in range(start, start + count)]


def tree_digest(root: Path) -> tuple[int, str]:
    """(number of files, sha256 over their relative paths and contents, in sorted order) under `root`.

    A symbolic link is hashed as a link (its target's name, never what it points to), so a trial in which
    one was planted never matches the digest recorded for the files a job wrote."""
    outer = hashlib.sha256()
    files = sorted(p for p in root.rglob("*") if p.is_symlink() or p.is_file())
    for p in files:
        outer.update(p.relative_to(root).as_posix().encode() + b"\0")
        content = b"symlink\0" + os.readlink(p).encode() if p.is_symlink() else p.read_bytes()
        outer.update(hashlib.sha256(content).digest())
    return len(files), outer.hexdigest()


def _remove(path: Path) -> None:
    """Remove a file, a symbolic link (the link itself, never its target) or a folder (whose links
    `shutil.rmtree` removes without following them)."""
    if path.is_symlink() or (path.exists() and not path.is_dir()):
        path.unlink()
    elif path.is_dir():
        shutil.rmtree(path)


def _open_nofollow(path: Path) -> Any:
    """`path` opened for appending, created if missing, refused (OSError) if it is a symbolic link: a lock
    file planted as a link must not make the build create or touch a file elsewhere."""
    return os.fdopen(os.open(path, os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_NOFOLLOW, 0o644), "a")


def _fsync_dir(path: Path) -> None:
    """fsync a file or a folder (a folder's entries: a rename into it)."""
    fd = os.open(path, os.O_RDONLY)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


@functools.lru_cache(maxsize=1)
def _syncfs() -> Any:
    """The C library's syncfs(2) (Linux), or None where there is none."""
    import ctypes
    import ctypes.util

    if not sys.platform.startswith("linux"):
        return None
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6", use_errno=True)
        call = libc.syncfs
    except (OSError, AttributeError):
        return None
    call.argtypes, call.restype = [ctypes.c_int], ctypes.c_int
    return call


def _fsync_tree(root: Path) -> None:
    """Make a trial's files and folders durable before it is renamed into place: one syncfs(2) of the
    filesystem that holds them where there is one (a single journal commit, where an fsync of each of a
    trial's hundred files commits the journal a hundred times), else an fsync of each file and folder."""
    syncfs = _syncfs()
    if syncfs is not None:
        fd = os.open(root, os.O_RDONLY)
        try:
            if syncfs(fd) == 0:
                return
        finally:
            os.close(fd)
    for p in sorted(root.rglob("*"), key=lambda p: len(p.parts), reverse=True) + [root]:
        _fsync_dir(p)


@dataclass(frozen=True)
class _Work:
    job: Any
    out: str
    options: BuildOptions
    run: str
    """The run id the driver wrote to `.partial/RUN`."""


@contextlib.contextmanager
def _workers_lock(out: Path, exclusive: bool) -> Iterator[None]:
    """Jobs hold `.workers.lock` shared while they run; a starting build takes it exclusively, so that
    it waits for the current job of any worker a killed build left running before it cleans up."""
    import fcntl

    with _open_nofollow(out / WORKERS_LOCK) as fh:
        fcntl.flock(fh, fcntl.LOCK_EX if exclusive else fcntl.LOCK_SH)
        try:
            yield
        finally:
            fcntl.flock(fh, fcntl.LOCK_UN)


def _work_folder(key: str) -> str:
    """A folder name for a job key: readable, and unique through a digest of the key."""
    readable = "".join(c if c.isalnum() or c in "-_." else "_" for c in key)
    return f"{readable}-{hashlib.sha1(key.encode()).hexdigest()[:10]}"


def _inside(path: Path, root: Path) -> tuple[str, ...]:
    """`path`'s parts below `root` (empty when it is not below it)."""
    try:
        return Path(path).resolve().relative_to(root.resolve()).parts
    except ValueError:
        return ()


def run_job(work: _Work) -> Record | None:
    """Run one job and put its trial in place (in a worker); its manifest record (written by the driver),
    or None when the job belongs to a build run that is over (its driver was killed)."""
    out = Path(work.out)
    with _workers_lock(out, exclusive=False):
        try:
            current = (out / PARTIAL / RUN).read_text()
        except FileNotFoundError:
            current = None
        if current != work.run:
            return None
        return _run_job(work.job, out, work.options)


def _run_job(job: Any, out: Path, options: BuildOptions) -> Record:
    tmp = out / PARTIAL / _work_folder(job.key)
    if tmp.exists():
        shutil.rmtree(tmp)
    tmp.mkdir(parents=True)
    try:
        outcome = job.run(tmp, options)
        if outcome.trial is not None and options.speaker is not None:
            from luminous_sim.language.speaker.annotate import annotate_trial

            annotate_trial(outcome.trial / "traj_data.json", options.speaker)
        if outcome.trial is not None and len(_inside(outcome.trial, tmp)) != 2:
            raise BuildError(f"job {job.key} wrote its trial at {outcome.trial}; expected {tmp}/<task>/<trial>")
    except Exception as exc:  # a bug in one job is recorded, not fatal to a build of thousands
        outcome = JobOutcome(stage="crash", cause=f"{type(exc).__name__}: {exc}")
    record: Record = {**outcome.details, "key": job.key, "split": job.split, "order": job.order,
                      "task_type": job.task_type, "status": "built" if outcome.trial is not None else "failed",
                      "stage": outcome.stage, "cause": outcome.cause, "trial": None}
    if outcome.trial is not None:
        rel = Path(*_inside(outcome.trial, tmp))
        written = tmp / rel
        record["files"], record["sha256"] = tree_digest(written)
        _fsync_tree(written)
        dest = out / job.split / rel
        dest.parent.mkdir(parents=True, exist_ok=True)
        if dest.exists() or dest.is_symlink():  # renamed into place by a killed build that never recorded it
            _remove(dest)
        os.replace(written, dest)
        _fsync_dir(dest.parent)
        record["trial"] = rel.as_posix()
    shutil.rmtree(tmp)
    return record


@dataclass(frozen=True)
class BuildReport:
    """What a build call produced over the jobs it was given (resumed ones included)."""

    out: Path
    records: tuple[Record, ...]
    """One manifest record per job asked for, in job order."""
    ran: int
    """Jobs run by this call (the others were finished before it started)."""
    seconds: float
    workers: int
    redone: tuple[str, ...] = ()
    """Keys of finished jobs done again because their trial was missing or damaged (or their record
    disagreed with the job)."""
    dropped: tuple[str, ...] = ()
    """Keys of finished jobs of other splits in the folder (not asked for now) whose trial was missing or
    damaged: no longer listed; building their split again restores them."""
    others: dict[str, int] = field(default_factory=dict)
    """Trials per split that the folder also holds, beside those asked for (each split kept apart)."""
    rejected: tuple[str, ...] = ()
    """Manifest lines left out as unreadable or altered (their jobs were done again), each with its cause."""
    retried: tuple[str, ...] = ()
    """Keys of jobs an earlier run recorded as a crash or a version failure, done again by this call."""
    rebuilt: int = 0
    """Finished jobs done again because the call asked for a rebuild."""

    @property
    def crashed(self) -> tuple[Record, ...]:
        """Records of this call's jobs that failed through the installation (a crash, a version failure)."""
        return tuple(r for r in self.records if retried(r))

    @property
    def built(self) -> int:
        return sum(r["status"] == "built" for r in self.records)

    @property
    def failed(self) -> int:
        return len(self.records) - self.built

    def by_task_type(self) -> dict[str, dict[str, Any]]:
        """Per task type: jobs, built, failed, and failures counted by (stage, first cause), most frequent first."""
        out: dict[str, dict[str, Any]] = {}
        for r in self.records:
            row = out.setdefault(r["task_type"], {"jobs": 0, "built": 0, "failed": 0, "causes": Counter()})
            row["jobs"] += 1
            row["built" if r["status"] == "built" else "failed"] += 1
            if r["status"] != "built":
                row["causes"][(r["stage"], r["cause"])] += 1
        return {t: {**row, "causes": row["causes"].most_common()} for t, row in sorted(out.items())}

    def summary(self) -> str:
        """A table for people: built / failed per task type with the most frequent first causes."""
        rows = self.by_task_type()
        width = max([len(t) for t in rows] + [len("task type")])
        lines = [f"{'task type':<{width}}  built  failed  of", *(
            f"{t:<{width}}  {row['built']:5d}  {row['failed']:6d}  {row['jobs']}" for t, row in rows.items())]
        lines.append(f"{'all':<{width}}  {self.built:5d}  {self.failed:6d}  {len(self.records)}")
        for t, row in rows.items():
            for (stage, cause), n in row["causes"][:CAUSES_SHOWN]:
                lines.append(f"  {t} failed at {stage} ({n}x): {_shorten(cause)}")
            if len(row["causes"]) > CAUSES_SHOWN:
                rest = sum(n for _, n in row["causes"][CAUSES_SHOWN:])
                lines.append(f"  {t}: {rest} more failures with other causes (manifest.jsonl has each)")
        if self.rejected:
            lines.append(f"{len(self.rejected)} manifest line(s) unreadable or altered, left out and their jobs done "
                         f"again; the first: {_shorten(self.rejected[0], 300)}")
        if self.retried:
            lines.append(f"{len(self.retried)} job(s) an earlier run crashed on (or built as another episode) were "
                         f"done again: {', '.join(self.retried[:5])}{' ...' if len(self.retried) > 5 else ''}")
        if self.rebuilt:
            lines.append(f"{self.rebuilt} finished job(s) done again (a rebuild was asked for)")
        if self.crashed:
            first = self.crashed[0]
            lines.append(f"{len(self.crashed)} job(s) failed through the installation, not the task (a crash or "
                         f"another episode than the frozen split; the next run does them again): {first['key']} at "
                         f"{first['stage']}: {_shorten(first['cause'], 300)}")
        if self.redone:
            lines.append(f"{len(self.redone)} finished trial(s) missing or damaged, done again: "
                         f"{', '.join(self.redone[:5])}{' ...' if len(self.redone) > 5 else ''}")
        if self.dropped:
            lines.append(f"{len(self.dropped)} trial(s) of other splits missing or damaged and no longer listed "
                         f"(build their split again to restore them): {', '.join(self.dropped[:5])}"
                         f"{' ...' if len(self.dropped) > 5 else ''}")
        if self.others:
            lines.append("the folder also holds " + ", ".join(f"{n} trial(s) of {s}" for s, n in self.others.items())
                         + " (each split listed apart in splits.json)")
        if self.ran:
            rate = self.ran / self.seconds * 60 if self.seconds > 0 else float("inf")
            lines.append(f"ran {self.ran} jobs in {self.seconds:.1f} s on {self.workers} worker(s): "
                         f"{rate:.1f} jobs/min, {rate / self.workers:.1f} per worker")
        return "\n".join(lines)


def _shorten(text: str | None, limit: int = 160) -> str:
    return one_line(text or "", limit)


class _Lock:
    """An exclusive lock on a build folder (released by the kernel if the process dies)."""

    def __init__(self, out: Path):
        self.path = out / LOCK

    def __enter__(self) -> _Lock:
        import fcntl

        self._fh = _open_nofollow(self.path)  # held until __exit__
        try:
            fcntl.flock(self._fh, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self._fh.close()
            raise BuildError(f"{self.path.parent}: another build is running in this folder") from None
        return self

    def __exit__(self, *exc: object) -> None:
        self._fh.close()


def _check_settings(out: Path, options: BuildOptions) -> None:
    """Write build.json in a fresh folder; in one that holds a build, refuse different settings."""
    path = out / SETTINGS
    wanted = options.settings()
    if path.exists() or path.is_symlink():
        if path.is_symlink() or not path.is_file():
            raise BuildError(f"{path}: {link_or_kind(path)}; expected the build's settings")
        try:
            have = json.loads(path.read_bytes()[:1_000_000])
        except (ValueError, RecursionError) as exc:
            raise BuildError(f"{path}: not JSON ({exc})") from None
        if not isinstance(have, dict):
            raise BuildError(f"{path}: expected a JSON object of build settings, got {type(have).__name__}")
        if have != wanted:
            diff = ", ".join(f"{k}: {have.get(k)!r} there, {wanted.get(k)!r} now" for k in sorted(wanted)
                             if have.get(k) != wanted.get(k))
            raise BuildError(f"{out} holds a build made with other settings ({diff}); use the same options "
                             "or another folder")
        return
    others = sorted(p.name for p in out.iterdir() if p.name not in (LOCK, WORKERS_LOCK))
    if others:
        raise BuildError(f"{out} is not empty and holds no dataset build ({SETTINGS} missing; it has "
                         f"{', '.join(others[:5])}{' ...' if len(others) > 5 else ''}); choose a new or empty folder")
    write_atomic(path, json.dumps(wanted, indent=1, sort_keys=True) + "\n")


def _clean(out: Path, manifest: Manifest, splits: set[str]) -> int:
    """Remove what a killed build left: `.partial/`, trial folders (`<split>/<task>/<trial>`) the
    manifest does not list, and task folders left empty, in the folders of `splits` and any other real
    folder of `out`; a symbolic link or a file where a split, task or trial folder belongs is removed
    itself, never followed. The number of trial folders removed."""
    _remove(out / PARTIAL)
    listed = {(r["split"], r["trial"]) for r in manifest if r.get("trial")}
    removed = 0
    for split in sorted(splits):
        root = out / split
        if root.is_symlink() or (root.exists() and not root.is_dir()):
            _remove(root)
    for root in sorted(p for p in out.iterdir() if not p.is_symlink() and p.is_dir() and not p.name.startswith(".")):
        split = root.name
        for task in sorted(root.iterdir()):
            if task.is_symlink() or not task.is_dir():
                _remove(task)
                continue
            for trial in sorted(task.iterdir()):
                if (split, f"{task.name}/{trial.name}") not in listed or trial.is_symlink() or not trial.is_dir():
                    _remove(trial)
                    removed += 1
            if not any(task.iterdir()):
                task.rmdir()
    return removed


def _intact(out: Path, record: Record) -> bool:
    """Whether a built record's trial is a real folder (no link on the way) whose files have the digest
    the record holds (recomputed from the files, not taken from the record)."""
    split, trial = out / record["split"], out / record["split"] / record["trial"]
    if any(p.is_symlink() for p in (split, trial.parent, trial)) or not trial.is_dir():
        return False
    return tree_digest(trial) == (record["files"], record["sha256"])


def _verify(out: Path, manifest: Manifest, jobs: Sequence[Job]) -> tuple[list[str], list[str], list[str]]:
    """The finished jobs to do again: (keys of `jobs` whose record disagrees with the job or whose trial is
    missing or damaged; keys of other records whose trial is missing or damaged; keys of `jobs` whose record is a
    crash or a version failure, `retried`)."""
    by_key = {j.key: j for j in jobs}
    redo: list[str] = []
    drop: list[str] = []
    again: list[str] = []
    for r in manifest:
        job = by_key.get(r["key"])
        if job is not None and retried(r):
            again.append(r["key"])
        elif job is not None and (r["split"], r["order"], r["task_type"]) != (job.split, job.order, job.task_type):
            redo.append(r["key"])
        elif r["status"] == "built" and not _intact(out, r):
            (redo if job is not None else drop).append(r["key"])
    return redo, drop, again


def _check_scope(out: Path, manifest: Manifest, jobs: Sequence[Job]) -> None:
    """Refuse a job list that leaves out finished jobs of a split it builds (a build is extended, never
    shrunk: its splits.json would silently keep listing them)."""
    keys = {j.key for j in jobs}
    for split in sorted({j.split for j in jobs}):
        left = sorted((r["order"], r["key"]) for r in manifest if r["split"] == split and r["key"] not in keys)
        if left:
            mine = [j.order for j in jobs if j.split == split]
            raise BuildError(
                f"{out / MANIFEST} holds {len(left)} finished job(s) of split {split} that this build does not "
                f"ask for (e.g. {left[0][1]}); a build is extended, never shrunk: ask for all of them (a count of "
                f"at least {max(o for o, _ in left) + 1}, not {len(mine)}) or use another folder")


def _check_jobs(jobs: Sequence[Job]) -> None:
    keys = Counter(j.key for j in jobs)
    twice = [k for k, n in keys.items() if n > 1]
    if twice:
        raise BuildError(f"job keys must be unique; repeated: {', '.join(sorted(twice)[:5])}")
    for split in {j.split for j in jobs}:
        if not plain_name(split) or split in (SETTINGS, MANIFEST, SPLITS):
            raise BuildError(f"a split's folder name must be a plain name, got {split!r}")


def splits_document(manifest: Manifest) -> dict[str, list[dict[str, object]]]:
    """ALFRED's oct21.json layout over every trial the manifest lists, per split in job order (one entry per
    annotation: `ANNOTATIONS`, or the number a record states, as a trial with its design's people's has)."""
    built: dict[str, list[tuple[int, str]]] = {}
    counts: dict[str, int] = {}
    for r in manifest:
        if r.get("trial"):
            built.setdefault(r["split"], []).append((r["order"], r["trial"]))
            counts[r["trial"]] = r.get("annotations", ANNOTATIONS)
    return oct21_document({s: [t for _, t in sorted(v)] for s, v in sorted(built.items())}, counts)


def build(out: Path, jobs: Sequence[Job], backend: Backend | None = None, options: BuildOptions | None = None,
          progress: bool = True, rebuild: bool = False) -> BuildReport:
    """Run the `jobs` the build folder `out` has not finished, on `backend` (default: this process), and
    write `splits.json`; resumable after a kill at any moment (see the module's docstring). A job an earlier run
    recorded as a crash or a version failure is done again (`retried`); with `rebuild` every one of `jobs` is.

    Raises:
        BuildError: `out` holds something else or a build with other settings, another build runs there,
            or two jobs share a key.
        ManifestError: the manifest is corrupt.
    """
    from tqdm import tqdm

    out = Path(out)
    options = options or BuildOptions()
    _check_jobs(jobs)
    out.mkdir(parents=True, exist_ok=True)
    with _Lock(out):
        _check_settings(out, options)
        manifest = Manifest(out / MANIFEST, repair=True)
        _check_scope(out, manifest, jobs)
        run = uuid.uuid4().hex
        with _workers_lock(out, exclusive=True):  # waits for the job of any orphaned worker to end
            rebuilt = [j.key for j in jobs if j.key in manifest] if rebuild else []
            manifest.remove(rebuilt)
            redone, dropped, again = _verify(out, manifest, jobs)
            manifest.remove(redone + dropped + again)
            _clean(out, manifest, {j.split for j in jobs} | {r["split"] for r in manifest})
            write_atomic(out / PARTIAL / RUN, run)
        todo = [j for j in jobs if j.key not in manifest]
        workers = backend.workers if backend is not None else 1
        start = time.perf_counter()
        with tqdm(total=len(jobs), initial=len(jobs) - len(todo), file=sys.stderr, disable=not progress,
                  unit="traj", desc=f"building {out.name}", dynamic_ncols=True) as bar:
            failed = 0
            for work, record in map_jobs(run_job, [_Work(j, str(out), options, run) for j in todo], backend):
                if record is None:
                    raise BuildError(f"job {work.job.key} found another build run going in {out}")
                manifest.append(record)
                failed += record["status"] != "built"
                bar.set_postfix(failed=failed, refresh=False)
                bar.update()
        seconds = time.perf_counter() - start
        manifest.sorted_rewrite(lambda r: (r["split"], r["order"], r["key"]))
        write_atomic(out / SPLITS, json.dumps(splits_document(manifest), indent=1, sort_keys=True) + "\n")
        shutil.rmtree(out / PARTIAL, ignore_errors=True)
        asked = {j.split for j in jobs}
        others = dict(sorted(Counter(r["split"] for r in manifest if r["trial"] and r["split"] not in asked).items()))
        return BuildReport(out, tuple(manifest[j.key] for j in jobs), len(todo), seconds, workers,
                           tuple(redone), tuple(dropped), others, tuple(manifest.rejected), tuple(again),
                           len(rebuilt))


def build_split(out: Path, split: str, count: int | None = None, backend: Backend | None = None,
                options: BuildOptions | None = None, progress: bool = True, rebuild: bool = False) -> BuildReport:
    """Method (a): episodes 0 .. count-1 of the frozen split `split` (S+, U+, U+test; None: all of them) into
    the build folder `out` (`rebuild`: every one done again)."""
    from luminous_sim.benchmark import benchmark_size

    return build(out, split_jobs(split, benchmark_size(split) if count is None else count), backend, options,
                 progress, rebuild)


def built_count(out: Path, split: str) -> int:
    """How many leading episodes of `split` the build folder `out` has records for (0 for a new folder): what
    a build of at least that count resumes without shrinking."""
    path = Path(out) / MANIFEST
    if not path.is_file() or path.is_symlink():
        return 0
    orders = [r["order"] for r in Manifest(path, repair=True) if r["split"] == split]
    return max(orders) + 1 if orders else 0
