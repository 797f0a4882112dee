"""Where ALFRED's real scenes put small objects: counts per (object type, receptacle type), as CSSG's data.

    python scripts/alfred_host_counts.py [--alfred ../shared/alfred] [--out luminous_sim/cssg/data/object_hosts.json]

From every trajectory of a split (valid_seen by default): the receptacle each object was first picked up
from (the high-level plan's GotoLocation before an object's first PickupObject: where AI2-THOR's scene
put it). The project ships the result; it needs no ALFRED files at run time.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.assets.objio import write_atomic
from luminous_sim.vocab import ALL_TYPES, vocab_data

ROOT = Path(__file__).resolve().parents[1]


def count(split: Path) -> tuple[Counter, int]:
    """(object type, receptacle type) pick-up counts and the number of trajectories read."""
    types = {t.lower(): t for t in ALL_TYPES}
    receptacles = set(vocab_data()["receptacle_objects"])
    pairs: Counter = Counter()
    files = sorted(split.glob("*/*/traj_data.json"))
    if not files:
        raise SystemExit(f"{split}: no */*/traj_data.json found (expected an ALFRED split directory)")
    for f in files:
        traj = json.loads(f.read_text())
        location, picked = None, set()
        for step in traj["plan"]["high_pddl"]:
            action, args = step["discrete_action"]["action"], step["discrete_action"]["args"]
            if action == "GotoLocation":
                location = types.get(args[0])
            elif action in ("PickupObject", "PutObject") and args:
                obj = types.get(args[0])
                if action == "PickupObject" and obj and obj not in picked and location in receptacles:
                    pairs[(obj, location)] += 1
                picked.add(obj)
    return pairs, len(files)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--alfred", type=Path, default=ROOT.parent / "shared" / "alfred")
    ap.add_argument("--split", default="valid_seen")
    ap.add_argument("--out", type=Path, default=ROOT / "luminous_sim" / "cssg" / "data" / "object_hosts.json")
    args = ap.parse_args()
    pairs, n = count(args.alfred / args.split)
    hosts: dict[str, dict[str, int]] = {}
    for (obj, rec), k in sorted(pairs.items()):
        hosts.setdefault(obj, {})[rec] = k
    doc = {
        "_doc": (f"Made by scripts/alfred_host_counts.py from ALFRED {args.split} ({n} trajectories). hosts: per "
                 "object type, how often its first pick-up was from each receptacle type (where the scene "
                 "put it)."),
        "hosts": hosts,
    }
    write_atomic(args.out, json.dumps(doc, indent=1, sort_keys=False) + "\n")
    print(f"{args.out}: {sum(pairs.values())} pick-ups of {len(hosts)} types, {n} trajectories")


if __name__ == "__main__":
    main()
