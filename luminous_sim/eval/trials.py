"""The trials of a built dataset folder, in the order ALFRED's evaluation takes them. A build of ours is read
from its `manifest.jsonl`: every job in order, a built one with its trial, a failed one with its cause (it is
part of the population: an evaluation counts it as a failure). Else the folder's `splits.json` (ALFRED's
`oct21.json` layout, `{split: [{"repeat_idx": k, "task": "<task>/<trial>"}]}`), each trajectory once
(annotation 0), else every `traj_data.json` under the folder in sorted order (a user's folder in ALFRED's
layout whose trials carry our sidecar)."""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from luminous_sim.errors import LuminousError, link_or_kind
from luminous_sim.limits import MAX_INPUT_BYTES

TRAJ = "traj_data.json"
SPLITS = "splits.json"


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


def _from_splits(root: Path, doc: Any) -> list[TrialRef]:
    if not isinstance(doc, dict) or not all(isinstance(v, list) for v in doc.values()):
        raise LuminousError(f"{root / SPLITS}: expected {{split: [{{'repeat_idx', 'task'}}, ...]}}")
    out = []
    for split, items in doc.items():
        seen: list[str] = []
        for k, item in enumerate(items):
            task = item.get("task") if isinstance(item, dict) else None
            if not isinstance(task, str) or Path(task).is_absolute() or ".." in Path(task).parts:
                raise LuminousError(f"{root / SPLITS}: {split}[{k}]: field 'task': expected '<task>/<trial>' inside "
                                    "the folder")
            if task not in seen:
                seen.append(task)
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
            named = (str(r["task_type"]), str(r.get("floor_plan", "")), int(r.get("layout", 0) or 0))
            out.append(TrialRef(r["split"], r["order"], root, "", unbuilt=f"{r.get('stage')}: {r.get('cause')}",
                                named=named))
    return out


def list_trials(root: Path, split: str | None = None) -> list[TrialRef]:
    """The trials under the dataset folder `root` (of `split` only, if given).

    Raises:
        LuminousError: `root` is no folder, its splits.json is malformed, or a listed trial has no traj_data.json;
            the message names the path.
    """
    root = Path(root)
    if root.is_symlink() or not root.is_dir():
        raise LuminousError(f"{root}: {link_or_kind(root)}; expected a dataset folder (a `luminous dataset build` "
                            "output or ALFRED's layout)")
    index = root / SPLITS
    manifest = root / "manifest.jsonl"
    if manifest.is_file() and not manifest.is_symlink():
        refs = _from_manifest(root, manifest)
    elif index.is_file() and not index.is_symlink():
        if index.stat().st_size > MAX_INPUT_BYTES:
            raise LuminousError(f"{index}: over {MAX_INPUT_BYTES} bytes")
        try:
            refs = _from_splits(root, json.loads(index.read_bytes()))
        except ValueError as exc:
            raise LuminousError(f"{index}: not JSON ({exc})") from None
    else:
        refs = []
        counts: dict[str, int] = {}
        for traj in sorted(root.rglob(TRAJ)):
            rel = traj.parent.relative_to(root).as_posix()
            name = rel.split("/")[0] if rel.count("/") >= 2 else ""
            refs.append(TrialRef(name, counts.get(name, 0), traj.parent, rel))
            counts[name] = counts.get(name, 0) + 1
    if split is not None:
        refs = [r for r in refs if r.split == split]
    for r in refs:
        if not r.unbuilt and not (r.path / TRAJ).is_file():
            raise LuminousError(f"{r.path}: listed in {SPLITS} but holds no {TRAJ}")
    return refs
