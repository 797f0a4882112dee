"""Where ALFRED's real scenes put small objects: counts per (object type, receptacle type), and how often
each type lies on the floor, as CSSG's data.

    python scripts/alfred_host_counts.py [--alfred ../shared/alfred] [--out luminous_sim/cssg/data/object_hosts.json]

From every trajectory of a split (valid_seen by default):
- hosts: the receptacle each object was picked up from the first time, before the agent had put it anywhere
  (the planner's `coordinateReceptacleObjectId` of that PickupObject: where AI2-THOR's scene put it), each
  object counted once per trajectory (both objects of a pick_two task count);
- floor: per type, first pick-ups from no receptacle (the floor), and of its distinct placements in
  `scene.object_poses` (every pickupable object of the scene, as ALFRED randomised it for that trajectory),
  how many rest on the floor: the object's centre at most its
  asset's half height + FLOOR_SLACK above the floor (AI2-THOR's floors are at y = 0). Low shelves and the
  bottoms of base cabinets pass that test too, so the share is an upper bound for kitchen and bathroom things;
  `placement.json`'s `on_floor` says which types CSSG lets lie on the floor.
The project ships the result; it needs no ALFRED files at run time.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.fileio import write_atomic
from luminous_sim.vocab import ALL_TYPES, vocab_data

ROOT = Path(__file__).resolve().parents[1]
FLOOR_SLACK = 0.03
"""metres above its resting height that an object's centre may be and still count as lying on the floor."""


def _files(split: Path) -> list[Path]:
    files = sorted(split.glob("*/*/traj_data.json"))
    if not files:
        raise SystemExit(f"{split}: no */*/traj_data.json found (expected an ALFRED split directory)")
    return files


def count(split: Path) -> tuple[Counter, Counter, int]:
    """(object type, receptacle type) first pick-up counts, first pick-ups from no receptacle (the floor) per
    object type, and the number of trajectories read."""
    types = {t.lower(): t for t in ALL_TYPES}
    receptacles = set(vocab_data()["receptacle_objects"])
    pairs: Counter = Counter()
    loose: Counter = Counter()
    files = _files(split)
    for f in files:
        traj = json.loads(f.read_text())
        handled: set[str] = set()
        for step in traj["plan"]["high_pddl"]:
            act = step["planner_action"]
            if act["action"] not in ("PickupObject", "PutObject") or "objectId" not in act:
                continue
            oid = act["objectId"]
            if act["action"] == "PickupObject" and oid not in handled:
                obj = types.get(oid.split("|")[0].lower())
                rec = (act.get("coordinateReceptacleObjectId") or [None])[0]
                if obj and rec in receptacles:
                    pairs[(obj, rec)] += 1
                elif obj and rec is None:
                    loose[obj] += 1
            handled.add(oid)
    return pairs, loose, len(files)


def floor_counts(split: Path) -> dict[str, tuple[int, int]]:
    """Per object type with an asset: (placements on the floor, distinct placements) over the split."""
    catalog = default_catalog()
    rest: dict[str, float | None] = {}
    on: Counter = Counter()
    total: Counter = Counter()
    for f in _files(split):
        seen = set()
        for p in json.loads(f.read_text())["scene"]["object_poses"]:
            pos = p["position"]
            key = (p["objectName"], round(pos["x"], 2), round(pos["z"], 2))
            if key in seen:
                continue
            seen.add(key)
            t = p["objectName"].split("_")[0]
            if t not in rest:
                entries = catalog.of_type(t)
                rest[t] = max(e.dims[2] for e in entries) / 2 + FLOOR_SLACK if entries else None
            if rest[t] is None:
                continue
            total[t] += 1
            on[t] += pos["y"] <= rest[t]
    return {t: (on[t], total[t]) for t in sorted(total)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--alfred", type=Path, default=ROOT.parent / "shared" / "alfred")
    ap.add_argument("--split", default="valid_seen")
    ap.add_argument("--out", type=Path, default=ROOT / "luminous_sim" / "cssg" / "data" / "object_hosts.json")
    args = ap.parse_args()
    pairs, loose, n = count(args.alfred / args.split)
    hosts: dict[str, dict[str, int]] = {}
    for (obj, rec), k in sorted(pairs.items()):
        hosts.setdefault(obj, {})[rec] = k
    floor = {t: {"on_floor": k, "placements": m, "picked_up_from_floor": loose.get(t, 0)}
             for t, (k, m) in floor_counts(args.alfred / args.split).items()}
    doc = {
        "_doc": (f"Made by scripts/alfred_host_counts.py from ALFRED {args.split} ({n} trajectories). hosts: per "
                 "object type, how often it was picked up from each receptacle type before the agent had moved it "
                 "(where the scene put it). floor: per object type, of its placements in the trajectories' "
                 "scene.object_poses, how many rest on the floor (centre within half its height + "
                 f"{FLOOR_SLACK} m of y = 0; an upper bound where low cabinets hold the type), and how many first "
                 "pick-ups were from no receptacle (the floor)."),
        "hosts": hosts,
        "floor": floor,
    }
    write_atomic(args.out, json.dumps(doc, indent=1, sort_keys=False) + "\n")
    print(f"{args.out}: {sum(pairs.values())} pick-ups of {len(hosts)} types, {n} trajectories; "
          f"{sum(v['placements'] for v in floor.values())} placements of {len(floor)} types")


if __name__ == "__main__":
    main()
