"""The trials of a built dataset folder, in the order ALFRED's evaluation takes them. A build of ours is read
from its `manifest.jsonl`: every job in order, a built one with its trial, a failed one with its cause (it is
part of the population: an evaluation counts it as a failure). Else the folder's `splits.json` (ALFRED's
`oct21.json` layout, `{split: [{"repeat_idx": k, "task": "<task>/<trial>"}]}`), each trajectory once
(annotation 0), else every `traj_data.json` under the folder in sorted order (a user's folder in ALFRED's
layout whose trials carry our sidecar)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.data.manifest import plain_name
from luminous_sim.errors import LuminousError, link_or_kind, read_json_file
from luminous_sim.limits import MAX_EVAL_EPISODES, MAX_INPUT_BYTES

TRAJ = "traj_data.json"
SPLITS = "splits.json"
MANIFEST = "manifest.jsonl"


@dataclass(frozen=True)
class TrialRef:
    """One trial to evaluate: its split (the folder it lies in), its place in that split, its folder."""

    split: str
    index: int
    path: Path
    """The trial folder."""
    rel: str
    """The trial folder relative to the dataset folder ("" for a job that built none)."""
    unbuilt: str = ""
    """Why the build wrote no trial for this job (its stage and cause); "" for a trial."""
    named: tuple[str, str, int] | None = None
    """(task type, floor plan, layout) as the build recorded them (for an unbuilt job)."""
    stage: str = ""
    """The build stage an unbuilt job failed at (`data.JobOutcome.stage`); "" for a trial."""
    broken: str = ""
    """Why the trial folder cannot be read where it is listed (not a folder inside the dataset folder, reached
    through a symbolic link, or without its traj_data.json); "" when it can be. Its outcome is `unavailable`
    with cause `broken_trial`, and nothing in it is read."""


def _from_splits(root: Path, doc: Any) -> list[TrialRef]:
    where = root / SPLITS
    if not isinstance(doc, dict) or not all(isinstance(v, list) for v in doc.values()):
        raise LuminousError(f"{where}: expected {{split: [{{'repeat_idx', 'task'}}, ...]}}")
    out: list[TrialRef] = []
    for split, items in doc.items():
        if not plain_name(split):
            shown = repr(split) if len(repr(split)) <= 60 else repr(split)[:57] + "..."
            raise LuminousError(f"{where}: split {shown}: expected a plain folder name (the split's folder inside "
                                "the dataset folder: no '/', not '.'-led, not empty)")
        seen: dict[str, None] = {}
        for k, item in enumerate(items):
            task: Any = item.get("task") if isinstance(item, dict) else None
            parts = task.split("/") if isinstance(task, str) else []
            if not parts or len(parts) > 2 or not all(plain_name(part) for part in parts):
                raise LuminousError(f"{where}: {split}[{k}]: field 'task': expected '<task>/<trial>' (or '<trial>'), "
                                    "plain folder names inside the split's folder")
            repeat = item.get("repeat_idx", 0)
            if not isinstance(repeat, int) or isinstance(repeat, bool) or repeat < 0:
                raise LuminousError(f"{where}: {split}[{k}]: field 'repeat_idx': expected a whole number >= 0")
            seen.setdefault(task, None)
            if len(out) + len(seen) > MAX_EVAL_EPISODES:
                raise LuminousError(f"{where}: lists more than {MAX_EVAL_EPISODES} trials "
                                    "(luminous_sim.limits.MAX_EVAL_EPISODES)")
        for i, task in enumerate(seen):
            rel = f"{split}/{task}"
            out.append(TrialRef(split, i, root / rel, rel))
    return out


def _from_manifest(root: Path, path: Path) -> list[TrialRef]:
    from luminous_sim.data import Manifest

    out = []
    for r in sorted(Manifest(path, repair=False), key=lambda r: (r["split"], r["order"])):
        if r["status"] == "built" and r["trial"]:
            rel = f"{r['split']}/{r['trial']}"
            out.append(TrialRef(r["split"], r["order"], root / rel, rel))
        else:
            plan, layout = r.get("floor_plan", ""), r.get("layout", 0) or 0
            if not isinstance(plan, str) or not isinstance(layout, int) or isinstance(layout, bool) or layout < 0:
                raise LuminousError(f"{path}: the record of {r['split']} job {r['order']}: fields 'floor_plan' and "
                                    f"'layout': expected a floor plan's name and a whole number >= 0, got "
                                    f"{plan!r} and {layout!r}")
            named = (str(r["task_type"]), plan, layout)
            out.append(TrialRef(r["split"], r["order"], root, "", unbuilt=f"{r.get('stage')}: {r.get('cause')}",
                                named=named, stage=str(r.get("stage") or "")))
    return out


def _from_tree(root: Path) -> list[TrialRef]:
    """Every folder under `root` that holds a traj_data.json, in sorted order; links are not followed (a folder
    reached through one is not listed; a traj_data.json that is a link is listed, and refused when read)."""
    from luminous_sim.benchmark import trial_folders

    try:
        folders, _ = trial_folders(root, MAX_EVAL_EPISODES)
    except LuminousError as exc:
        raise LuminousError(f"{exc} (luminous_sim.limits.MAX_EVAL_EPISODES)") from None
    found = [folder.relative_to(root).as_posix() for folder in folders]
    refs = []
    counts: dict[str, int] = {}
    for rel in sorted(found):
        name = rel.split("/")[0] if rel.count("/") >= 2 else ""
        refs.append(TrialRef(name, counts.get(name, 0), root / rel, rel))
        counts[name] = counts.get(name, 0) + 1
    return refs


def confined(root: Path, rel: str) -> str:
    """Why the folder `rel` (a relative path) is not a trial folder inside the dataset folder `root`, or "":
    each step from `root` must be a real folder (no symbolic link on the way), and the folder must resolve to a
    place inside `root`. Only `lstat` is used: nothing is opened or followed."""
    import stat

    here = Path(root)
    for part in Path(rel).parts:
        if part in ("", ".", ".."):
            return f"{rel}: not a plain path inside the dataset folder"
        here = here / part
        try:
            mode = os.lstat(here).st_mode
        except FileNotFoundError:
            return f"{here}: no such folder; expected a trial folder"
        except OSError as exc:
            return f"{here}: cannot read ({exc.strerror or exc}); expected a trial folder"
        if stat.S_ISLNK(mode):
            return f"{here}: a symbolic link (links are never followed); expected a trial folder inside {root}"
        if not stat.S_ISDIR(mode):
            return f"{here}: {link_or_kind(here)}; expected a trial folder"
    if not here.resolve().is_relative_to(Path(root).resolve()):
        return f"{here}: outside the dataset folder {root}"
    try:
        os.lstat(here / TRAJ)
    except FileNotFoundError:
        return f"{here}: holds no {TRAJ}"
    except OSError as exc:
        return f"{here / TRAJ}: cannot read ({exc.strerror or exc})"
    return ""


def list_trials(root: Path, split: str | None = None) -> list[TrialRef]:
    """The trials under the dataset folder `root` (of `split` only, if given).

    A listed trial folder that is not a real folder inside `root` (reached through a symbolic link, missing,
    a file) or holds no traj_data.json is still listed, with why in `TrialRef.broken`.

    Raises:
        LuminousError: `root` is no folder (or a link); its manifest.jsonl or splits.json is a link, not a
            regular file, over its size limit or malformed (a split key that is not a plain folder name, a task
            path that is absolute, climbs out with `..` or is not made of plain folder names); or it lists
            more than `limits.MAX_EVAL_EPISODES` trials. The message names the path and the field.
    """
    root = Path(root)
    if root.is_symlink() or not root.is_dir():
        raise LuminousError(f"{root}: {link_or_kind(root)}; expected a dataset folder (a `luminous dataset build` "
                            "output or ALFRED's layout)")
    index = root / SPLITS
    manifest = root / MANIFEST
    if os.path.lexists(manifest):
        refs = _from_manifest(root, manifest)
    elif os.path.lexists(index):
        doc = read_json_file(index, MAX_INPUT_BYTES,
                             "the dataset folder's splits.json (luminous_sim.limits.MAX_INPUT_BYTES)")
        refs = _from_splits(root, doc)
    else:
        refs = _from_tree(root)
    if split is not None:
        refs = [r for r in refs if r.split == split]
    out = []
    for r in refs:
        broken = "" if r.unbuilt else confined(root, r.rel)
        out.append(TrialRef(r.split, r.index, r.path, r.rel, named=("", "", 0), broken=broken) if broken else r)
    return out


def trial_problem(path: Path | str) -> str:
    """Why the trial folder `path` cannot be played (`benchmark.read_trial`'s refusal: a file that cannot be
    read, a field missing, of the wrong kind or out of range, a task impossible in the restored scene), or ""."""
    from luminous_sim.benchmark import read_trial

    try:
        read_trial(Path(path))
    except LuminousError as exc:
        return str(exc)
    return ""
