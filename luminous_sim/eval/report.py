"""An evaluation's reports: JSON, a markdown table in the layout of the paper's Table 4, and a plot.

The table has a row per task type in Table 4's order (Pick, Cool, Stack, Heat, Clean, Examine, Pick Two),
then "Average" (the mean of the per-type values, as Table 4's last row) and "All" (ALFRED's overall
metrics, over every episode). Each evaluation given (a policy on a split) adds a group of columns:
n (episodes drawn / split entries), SR, GC, PLW-SR, PLW-GC, and SR over all entries (undrawn ones count
as failures). Values print as Table 4 prints them (`.295`); "-" where no episode was drawn.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path

from luminous_sim.eval.evaluator import EvalReport
from luminous_sim.eval.metrics import Metrics, type_average
from luminous_sim.fileio import write_atomic

TABLE4_ROWS: tuple[tuple[str, str], ...] = (
    ("pick_and_place_simple", "Pick"),
    ("pick_cool_then_place_in_recep", "Cool"),
    ("pick_and_place_with_movable_recep", "Stack"),
    ("pick_heat_then_place_in_recep", "Heat"),
    ("pick_clean_then_place_in_recep", "Clean"),
    ("look_at_obj_in_light", "Examine"),
    ("pick_two_obj_and_place", "Pick Two"),
)
"""ALFRED's task types as the paper's Table 4 names and orders them."""
COLUMNS: tuple[tuple[str, str], ...] = (("sr", "SR"), ("gc", "GC"), ("plw_sr", "PLW-SR"), ("plw_gc", "PLW-GC"),
                                        ("sr_all", "SR all"))


def _value(value: float | None) -> str:
    if value is None:
        return "-"
    text = f"{value:.3f}"
    return text[1:] if text.startswith("0") else text


def _cells(m: Metrics | None) -> list[str]:
    if m is None:
        return ["0/0"] + ["-"] * len(COLUMNS)
    return [f"{m.episodes}/{m.entries}"] + [_value(getattr(m, key)) for key, _ in COLUMNS]


def markdown_table(reports: Sequence[EvalReport]) -> str:
    """The Table 4-style markdown table of one or more evaluations (a column group each), with notes on
    undrawn entries below it."""
    head = ["Task"]
    for r in reports:
        head += [f"{r.policy} {r.split} ({r.track}) {label}" for label in ("n", *(c for _, c in COLUMNS))]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for task_type, label in TABLE4_ROWS:
        row = [label]
        for r in reports:
            row += _cells(r.per_type.get(task_type))
        lines.append("| " + " | ".join(row) + " |")
    average = ["Average"]
    for r in reports:
        counted = sum(m.episodes for m in r.per_type.values())
        average += [f"{counted}/{len(r.outcomes)}"] + [_value(type_average(r.per_type, k)) for k, _ in COLUMNS]
    lines.append("| " + " | ".join(average) + " |")
    total = ["**All**"]
    for r in reports:
        total += [f"**{c}**" if c != "-" else c for c in _cells(r.overall)]
    lines.append("| " + " | ".join(total) + " |")
    notes = []
    for r in reports:
        causes = r.unavailable()
        if causes:
            notes.append(f"- {r.policy} on {r.split}: {sum(causes.values())} of {len(r.outcomes)} entries had no "
                         "episode (" + ", ".join(f"{k}: {v}" for k, v in causes.items()) + "); they count as "
                         "failures in SR all only.")
    return "\n".join(lines + ([""] + notes if notes else [])) + "\n"


def plot(reports: Sequence[EvalReport], path: Path) -> Path:
    """Bars of SR and GC per task type (and All) for each evaluation, as a PNG (matplotlib, Agg)."""
    import io

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    labels = [label for _, label in TABLE4_ROWS] + ["All"]
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.6), sharey=True)
    width = 0.8 / max(1, len(reports))
    x = np.arange(len(labels))
    for ax, (key, title) in zip(axes, (("sr", "Success rate (SR)"), ("gc", "Goal conditions (GC)")), strict=True):
        for k, r in enumerate(reports):
            values = [getattr(r.per_type[t], key) if t in r.per_type else None for t, _ in TABLE4_ROWS]
            values.append(getattr(r.overall, key))
            heights = [v if v is not None else 0.0 for v in values]
            ax.bar(x + (k - (len(reports) - 1) / 2) * width, heights, width, label=f"{r.policy} {r.split}")
        ax.set_xticks(x, labels, rotation=30)
        ax.set_ylim(0, 1.05)
        ax.set_title(title)
        ax.grid(axis="y", alpha=0.3)
    axes[0].set_ylabel("fraction")
    handles, names = axes[0].get_legend_handles_labels()
    fig.legend(handles, names, loc="lower center", ncol=max(1, len(reports)), fontsize=9, frameon=False)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=110)
    plt.close(fig)
    write_atomic(path, buffer.getvalue())
    return path


def write_reports(report: EvalReport, out_dir: Path) -> dict[str, Path]:
    """`report.json`, `table.md` and `metrics.png` in `out_dir` (each written atomically)."""
    paths = {"json": out_dir / "report.json", "table": out_dir / "table.md", "plot": out_dir / "metrics.png"}
    write_atomic(paths["json"], json.dumps(report.to_dict(), indent=1) + "\n")
    write_atomic(paths["table"], markdown_table([report]))
    plot([report], paths["plot"])
    return paths
