"""The rgb track's perception (issue 45): the network's scores on an evaluation perception dataset (U+'s frames:
structures no training frame came from), per room type (mean IoU over the types tasks name, pixel accuracy,
depth's absolute relative error), and its cost per step at ALFRED's 300x300 (the network, and the instance
tracker after it), the median and spread of repeats.

    luminous dataset perception --split U+ --count 48 --out out/perception-uplus
    python benchmarks/bench_perception.py --data out/perception-uplus [--perception PT] [--repeats 5]
    python benchmarks/bench_perception.py --data out/perception-uplus --colour-baseline out/perception

`--colour-baseline TRAIN` scores a reference instead of a network: each pixel given the commonest type of its
colour (16 levels a channel) in TRAIN's frames (every other pixel each way counted): what colour alone tells.

Figures: docs/benchmarks.md, "Perception (bench_perception.py)".
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from benchmarks.machine import cpu_model


def colour_baseline(train: Path, data: Path, levels: int = 16) -> dict[str, dict[str, float | int]]:
    """The colour-lookup reference's scores on `data` (counted on `train`; depth is not predicted, so its error
    is left out)."""
    from luminous_sim.agents.perception_net import CLASSES
    from luminous_sim.agents.perception_scores import PerceptionScores
    from luminous_sim.data import iter_shards

    def bins(rgb: np.ndarray) -> np.ndarray:
        q = (rgb // (256 // levels)).astype(np.int64)
        return (q[..., 0] * levels + q[..., 1]) * levels + q[..., 2]

    counts = np.zeros((levels**3, CLASSES), np.int64)
    for _, arrays in iter_shards(train):
        np.add.at(counts, (bins(arrays["rgb"][:, ::2, ::2]).ravel(),
                           arrays["types"][:, ::2, ::2].ravel().astype(np.int64)), 1)
    lookup = counts.argmax(1)
    scores = PerceptionScores()
    for record, arrays in iter_shards(data):
        truth = arrays["types"].astype(np.int64)
        scores.add(str(record["room_type"]), lookup[bins(arrays["rgb"])], truth, np.ones(truth.shape),
                   np.zeros(truth.shape))
    return scores.summary()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, required=True, help="a perception dataset (e.g. `--split U+`'s)")
    parser.add_argument("--perception", type=Path, default=None, help="a checkpoint (default: the shipped one)")
    parser.add_argument("--repeats", type=int, default=5, help="timing repeats (default 5)")
    parser.add_argument("--frames", type=int, default=20, help="frames timed per repeat (default 20)")
    parser.add_argument("--threads", type=int, default=1, help="torch threads while timing (default 1)")
    parser.add_argument("--colour-baseline", type=Path, default=None, metavar="TRAIN",
                        help="score the colour-lookup reference counted on this training dataset instead")
    args = parser.parse_args()
    if args.colour_baseline is not None:
        print(json.dumps({"colour_baseline": str(args.colour_baseline), "data": str(args.data), "cpu": cpu_model(),
                          "scores": colour_baseline(args.colour_baseline, args.data)}, indent=1))
        return 0

    import torch

    from luminous_sim.agents import InstanceTracker, Intrinsics, OwnPose, Perception, default_perception
    from luminous_sim.agents.perception_scores import score_dataset
    from luminous_sim.data import iter_shards, read_header

    perception = Perception.load(args.perception) if args.perception else default_perception()
    header = read_header(args.data)
    print(f"CPU {cpu_model()}, {os.cpu_count()} cores, load {os.getloadavg()[0]:.1f}; torch {torch.__version__}",
          file=sys.stderr)
    start = time.perf_counter()
    scores = score_dataset(perception, args.data)
    scored_s = time.perf_counter() - start

    torch.set_num_threads(args.threads)
    _, arrays = next(iter(iter_shards(args.data)))
    frames = arrays["rgb"][: args.frames]
    side = frames.shape[1]
    net_ms, tracker_ms = [], []
    for _ in range(args.repeats):
        tracker = InstanceTracker(Intrinsics(side, side))
        t_net = t_track = 0.0
        for rgb in frames:
            t = time.process_time()
            types, depth = perception.predict(rgb)
            t_net += time.process_time() - t
            t = time.process_time()
            tracker.update(types, depth, OwnPose())
            t_track += time.process_time() - t
        net_ms.append(1000 * t_net / len(frames))
        tracker_ms.append(1000 * t_track / len(frames))
    params = sum(p.numel() for p in perception.net.parameters())
    report = {
        "data": {"path": str(args.data), "evaluation": header["evaluation"], "entries": header.get("entries", []),
                 "manifest_sha256": header["manifest_sha256"]},
        "checkpoint": {"parameters": params, "side": perception.side, "record_data": perception.record.get("data"),
                       "command": perception.record.get("command"),
                       "held_apart_last_epoch": (perception.record.get("epochs") or [{}])[-1].get("held_apart")},
        "scores": scores, "scored_s": round(scored_s, 1),
        "ms_per_frame": {"size": side, "threads": args.threads,
                         "network_median": round(float(np.median(net_ms)), 1),
                         "network_range": [round(min(net_ms), 1), round(max(net_ms), 1)],
                         "tracker_median": round(float(np.median(tracker_ms)), 1),
                         "tracker_range": [round(min(tracker_ms), 1), round(max(tracker_ms), 1)]},
        "cpu": cpu_model(), "load_end": round(os.getloadavg()[0], 1),
    }
    print(json.dumps(report, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
