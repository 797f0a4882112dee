"""Parser coverage over a folder of ALFRED trajectories: parse each, optionally merge per floor plan,
realise each CDF with CSSG in its own floor plan's shell, and write the CDFs and a report.

    report = parse_directory(Path("alfred/valid_seen"), merge=True)
    write_report(report, Path("out"))   # cdf/*.yaml, merged/*.yaml, report.json, report.md
"""

from __future__ import annotations

import json
import re
from collections import Counter
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from luminous_sim.cdf import ChallengeDefinition, dumps
from luminous_sim.data.alfred_merge import MergedCDF, merge_by_floor_plan
from luminous_sim.data.alfred_parser import AlfredParse, AlfredParseError, parse_alfred
from luminous_sim.errors import InfeasibleSceneError
from luminous_sim.fileio import write_atomic


@dataclass(frozen=True)
class Realisation:
    """Whether CSSG generated a scene for a CDF in its floor plan's shell, and if not, the first cause."""

    ok: bool
    cause: str = ""
    message: str = ""


@dataclass
class FileOutcome:
    """One trajectory file: its parse (or why it failed) and its realisation (None when not tried)."""

    path: str
    task_type: str
    parse: AlfredParse | None = None
    error: str = ""
    realised: Realisation | None = None


@dataclass
class CoverageReport:
    """Everything `write_report` writes: per file, per floor plan, and the totals."""

    root: str
    seed: int
    files: list[FileOutcome]
    merged: dict[str, MergedCDF] = field(default_factory=dict)
    merged_realised: dict[str, Realisation] = field(default_factory=dict)

    @property
    def parsed(self) -> int:
        return sum(1 for f in self.files if f.parse is not None)

    @property
    def realised(self) -> int:
        return sum(1 for f in self.files if f.realised is not None and f.realised.ok)

    @property
    def tried(self) -> int:
        return sum(1 for f in self.files if f.realised is not None)

    def by_task_type(self) -> dict[str, dict[str, int]]:
        """Task type -> total, parsed, realised (sorted by type)."""
        out: dict[str, dict[str, int]] = {}
        for f in self.files:
            row = out.setdefault(f.task_type, {"total": 0, "parsed": 0, "realised": 0})
            row["total"] += 1
            row["parsed"] += f.parse is not None
            row["realised"] += bool(f.realised and f.realised.ok)
        return dict(sorted(out.items()))

    def causes(self) -> Counter[str]:
        """First cause of each failed realisation, by frequency (trajectories)."""
        return Counter(f.realised.cause for f in self.files if f.realised is not None and not f.realised.ok)

    def summary(self) -> str:
        """The lines `luminous alfred parse` prints."""
        n = len(self.files)
        lines = [f"parsed: {self.parsed}/{n}"]
        if self.tried:
            lines.append(f"realised (CSSG, own floor plan's shell, seed {self.seed}): {self.realised}/{n}")
        for t, row in self.by_task_type().items():
            real = f", realised {row['realised']}" if self.tried else ""
            lines.append(f"  {t}: parsed {row['parsed']}/{row['total']}{real}")
        if self.merged:
            ok = sum(1 for r in self.merged_realised.values() if r.ok)
            conflicts = sum(len(m.conflicts) for m in self.merged.values())
            lines.append(f"merged: {len(self.merged)} floor plans, {conflicts} conflicts resolved"
                         + (f", realised {ok}/{len(self.merged)}" if self.merged_realised else ""))
        for cause, k in self.causes().most_common():
            lines.append(f"  not realised ({k}): {cause}")
        return "\n".join(lines)


def _types_by_name(cdf: ChallengeDefinition) -> dict[str, str]:
    return {o.name: o.type for o in cdf.scene.objects}


def failure_cause(message: str, cdf: ChallengeDefinition) -> str:
    """The first (most frequent) cause in a CSSG failure message, with object names replaced by their
    types so that causes add up across CDFs (`pan on stove_burner (cdf:...) (20/20)` -> `Pan on StoveBurner`)."""
    text = message.split("samples: ", 1)[1] if "samples: " in message else message.split(": ", 1)[-1]
    first = text.split("; ")[0]
    first = re.sub(r"\s*\((cdf|default):[^)]*\)", "", first)
    first = re.sub(r"\s*\(\d+/\d+\)$", "", first).strip()
    types = _types_by_name(cdf)
    return re.sub(r"\b[a-z][a-z0-9_]*\b", lambda m: types.get(m.group(0), m.group(0)), first)


def realise(cdf: ChallengeDefinition, floor_plan: str, seed: int = 0) -> Realisation:
    """Generate the CDF's scene with CSSG in the floor plan's own room shell."""
    from luminous_sim.cssg import generate
    from luminous_sim.rooms import load_room

    try:
        generate(cdf, seed, room=load_room(floor_plan))
    except InfeasibleSceneError as exc:
        return Realisation(False, failure_cause(str(exc), cdf), str(exc))
    return Realisation(True)


def trajectory_files(root: Path) -> list[Path]:
    """Every traj_data.json under `root`, sorted.

    Raises:
        AlfredParseError: `root` is not a folder, or holds none.
    """
    if not root.is_dir():
        raise AlfredParseError(f"{root}: not a folder; expected a folder of ALFRED trajectories")
    files = sorted(root.rglob("traj_data.json"))
    if not files:
        raise AlfredParseError(f"{root}: no traj_data.json found under it")
    return files


def _task_type_of(path: Path) -> str:
    try:
        value = json.loads(path.read_text()).get("task_type")
    except (OSError, json.JSONDecodeError, AttributeError):
        return "unknown"
    return value if isinstance(value, str) else "unknown"


def parse_directory(
    root: Path, *, merge: bool = False, realise_scenes: bool = True, seed: int = 0,
    progress: Callable[[Iterable[Any], str], Iterable[Any]] | None = None,
) -> CoverageReport:
    """Parse every trajectory under `root`; merge per floor plan and realise with CSSG if asked.

    Args:
        root: a folder with `.../traj_data.json` files (an ALFRED split, or part of one).
        merge: also merge the parses of each floor plan.
        realise_scenes: generate each parsed (and merged) CDF with CSSG in its floor plan's shell.
        seed: CSSG's seed.
        progress: wraps an iterable with a progress display (`tqdm`-like: (iterable, description)).
    """
    wrap = progress or (lambda items, _desc: items)
    outcomes = []
    for path in wrap(trajectory_files(root), "parse"):
        rel = str(path.relative_to(root))
        try:
            parse = parse_alfred(path, source=rel)
        except AlfredParseError as exc:
            outcomes.append(FileOutcome(rel, _task_type_of(path), error=str(exc)))
            continue
        outcomes.append(FileOutcome(rel, parse.task_type, parse))
    report = CoverageReport(str(root), seed, outcomes)
    if realise_scenes:
        for f in wrap([f for f in outcomes if f.parse is not None], "realise"):
            assert f.parse is not None
            f.realised = realise(f.parse.cdf, f.parse.floor_plan, seed)
    if merge:
        report.merged = merge_by_floor_plan(f.parse for f in outcomes if f.parse is not None)
        if realise_scenes:
            report.merged_realised = {
                plan: realise(m.cdf, plan, seed) for plan, m in wrap(list(report.merged.items()), "realise merged")
            }
    return report


def cdf_file_name(rel: str) -> str:
    """`task-dir/trial_x/traj_data.json` -> `task-dir.trial_x.yaml`."""
    return ".".join(Path(rel).parent.parts) + ".yaml"


def _realised_json(r: Realisation | None) -> Any:
    return None if r is None else {"ok": r.ok, "cause": r.cause, "message": r.message}


def report_json(report: CoverageReport) -> dict[str, Any]:
    """The content of report.json."""
    files = []
    for f in report.files:
        entry: dict[str, Any] = {"file": f.path, "task_type": f.task_type, "parsed": f.parse is not None}
        if f.parse is None:
            entry["error"] = f.error
        else:
            entry["cdf"] = f"cdf/{cdf_file_name(f.path)}"
            entry |= f.parse.to_json()
            entry.pop("source")
        entry["realised"] = _realised_json(f.realised)
        files.append(entry)
    merged = [
        {"cdf": f"merged/{plan}.yaml", **m.to_json(), "realised": _realised_json(report.merged_realised.get(plan))}
        for plan, m in report.merged.items()
    ]
    return {
        "root": report.root, "seed": report.seed, "total": len(report.files), "parsed": report.parsed,
        "realised": report.realised if report.tried else None, "by_task_type": report.by_task_type(),
        "not_realised_causes": dict(report.causes().most_common()), "files": files, "merged": merged,
    }


def report_markdown(report: CoverageReport) -> str:
    """The content of report.md: the totals, then each file's kept and dropped items."""
    lines = ["# ALFRED task parser report", "", f"Source: `{report.root}`; CSSG seed {report.seed}.", "",
             "```text", report.summary(), "```", ""]
    for f in report.files:
        lines.append(f"## {f.path}")
        if f.parse is None:
            lines += ["", f"Not parsed: {f.error}", ""]
            continue
        if f.realised is not None:
            lines += ["", "Realised by CSSG." if f.realised.ok else f"Not realised: {f.realised.cause}."]
        lines += ["", f"CDF: `cdf/{cdf_file_name(f.path)}`", "", "Kept:", ""]
        lines += [f"- {n.item}: {n.reason} ({n.field})" for n in f.parse.kept]
        lines += ["", "Dropped:", ""]
        lines += [f"- {n.item}: {n.reason} ({n.field})" for n in f.parse.dropped]
        lines.append("")
    for plan, m in report.merged.items():
        r = report.merged_realised.get(plan)
        lines += [f"## merged {plan}", "", f"From {len(m.sources)} trajectories; CDF `merged/{plan}.yaml`."]
        if r is not None:
            lines.append("Realised by CSSG." if r.ok else f"Not realised: {r.cause}.")
        lines += ["", "Conflicts:", ""] + ([
            f"- {c.object} {c.about}: {', '.join(f'{v} ({n})' for v, n in c.options)} -> {c.chosen}: "
            f"{c.resolution}" for c in m.conflicts] or ["- none"])
        lines += ["", "Left out:", ""] + [f"- {n.item}: {n.reason}" for n in m.notes] + [""]
    return "\n".join(lines)


def write_report(report: CoverageReport, out: Path) -> list[Path]:
    """Write each parsed CDF (`cdf/`), each merged one (`merged/`), report.json and report.md, atomically.

    Returns:
        The files written.
    """
    written = []
    for f in report.files:
        if f.parse is not None:
            path = out / "cdf" / cdf_file_name(f.path)
            write_atomic(path, dumps(f.parse.cdf))
            written.append(path)
    for plan, m in report.merged.items():
        path = out / "merged" / f"{plan}.yaml"
        write_atomic(path, dumps(m.cdf))
        written.append(path)
    for name, text in (("report.json", json.dumps(report_json(report), indent=2) + "\n"),
                       ("report.md", report_markdown(report))):
        write_atomic(out / name, text)
        written.append(out / name)
    return written

