"""Learning curves of `train_ppo.py` runs against CPU time: the imitation rounds of a warm start (`warm_start.json`:
the success of each round's own rollouts) and PPO's training episodes after it (`curve.csv`, a moving average),
with held-out success rates as dashed lines.

    python scripts/plot_ppo_runs.py --run "seed 0=out/ppo/seed0" --run "seed 1=out/ppo/seed1" \\
        --ref "walk-stop (held-out)=0.0" --out docs/images/ppo_objectnav_bc.png
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import sys
from collections.abc import Sequence
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from luminous_sim.fileio import write_atomic  # noqa: E402


def _pair(text: str, what: str) -> tuple[str, str]:
    name, sep, value = text.partition("=")
    if not sep or not name or not value:
        raise SystemExit(f"{what} {text!r}: expected NAME=VALUE")
    return name, value


def run_points(folder: Path, window: int) -> tuple[list[tuple[float, float]], list[tuple[float, float]]]:
    """(CPU-minutes, success) of each imitation round, and PPO's moving average over `window` episodes.

    Raises:
        SystemExit: the folder has neither file.
    """
    warm_path, curve_path = folder / "warm_start.json", folder / "curve.csv"
    if not warm_path.exists() and not curve_path.exists():
        raise SystemExit(f"{folder}: no warm_start.json or curve.csv (not a train_ppo.py output folder)")
    rounds = [(r["cpu_seconds"] / 60, r["successes"] / max(r["episodes"], 1))
              for r in (json.loads(warm_path.read_text()) if warm_path.exists() else [])]
    curve: list[tuple[float, float]] = []
    if curve_path.exists():
        with curve_path.open(newline="") as fh:
            rows = list(csv.DictReader(fh))
        if rows:
            w = max(1, min(window, len(rows)))
            success = np.convolve([float(r["success"]) for r in rows], np.ones(w) / w, "valid")
            minutes = [float(r["cpu_seconds"]) / 60 for r in rows][w - 1:]
            curve = list(zip(minutes, success.tolist(), strict=True))
    return rounds, curve


def plot(runs: dict[str, Path], refs: dict[str, float], out: Path, *, window: int = 100, title: str = "") -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4.2))
    for i, (name, folder) in enumerate(runs.items()):
        rounds, curve = run_points(folder, window)
        if rounds:
            ax.plot(*zip(*rounds, strict=True), "o:", color=f"C{i}", label=f"{name}: imitation rounds (own rollouts)")
        if curve:
            ax.plot(*zip(*curve, strict=True), "-", color=f"C{i}", label=f"{name}: PPO training episodes "
                                                                        f"({window}-episode mean)")
    for j, (name, value) in enumerate(refs.items()):
        ax.axhline(value, ls="--", color=f"C{len(runs) + j}", label=name)
    ax.set(xlabel="CPU-minutes (trainer and env workers)", ylabel="success rate", ylim=(-0.02, 1.02))
    ax.legend(fontsize=7, loc="upper right")
    if title:
        ax.set_title(title, fontsize=9)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110)
    plt.close(fig)
    write_atomic(out, buf.getvalue())


def main(argv: Sequence[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--run", action="append", required=True, metavar="NAME=DIR", help="a train_ppo.py output folder")
    p.add_argument("--ref", action="append", default=[], metavar="NAME=RATE", help="a dashed line (e.g. held-out SR)")
    p.add_argument("--window", type=int, default=100, help="episodes in PPO's moving average (default 100)")
    p.add_argument("--title", default="")
    p.add_argument("--out", type=Path, required=True, help="the PNG to write")
    args = p.parse_args(argv)
    runs = {name: Path(value) for name, value in (_pair(r, "--run") for r in args.run)}
    refs = {}
    for name, value in (_pair(r, "--ref") for r in args.ref):
        try:
            refs[name] = float(value)
        except ValueError:
            raise SystemExit(f"--ref {name}={value}: the rate must be a number") from None
    plot(runs, refs, args.out, window=args.window, title=args.title)
    print(f"wrote {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
