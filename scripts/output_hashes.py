"""Hashes of everything a behaviour-preserving change must leave byte-identical.

`python scripts/output_hashes.py [--seeds N] [--out FILE]` prints one line per group:

- scenes: every example CDF x seeds 0..N-1 and the empty CDF of each room type (procedural rooms),
  plus the empty CDF in a few converted AI2-THOR rooms, as scene JSON;
- rooms: procedural shells of every type and shape, and every shipped converted FloorPlan;
- catalog: `urdf_assets/catalog.json` and every file it lists;
- demo: the demo episode's trajectory.json and its frames.

Compare two runs with `diff`. The demo episode takes about half a minute.
"""

from __future__ import annotations

import argparse
import hashlib
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

ROOT = Path(__file__).resolve().parents[1]
CONVERTED = ("FloorPlan1", "FloorPlan12", "FloorPlan205", "FloorPlan310", "FloorPlan405")


def _digest(chunks) -> str:
    h = hashlib.sha256()
    for chunk in chunks:
        h.update(chunk if isinstance(chunk, bytes) else str(chunk).encode())
    return h.hexdigest()[:16]


def scene_hashes(seeds: int) -> dict[str, str]:
    from luminous_sim import cdf
    from luminous_sim.cssg import empty_cdf, generate
    from luminous_sim.errors import InfeasibleSceneError
    from luminous_sim.rooms.library import load_room
    from luminous_sim.vocab import ROOM_TYPES

    def one(doc, seed, room=None) -> str:
        try:
            return generate(doc, seed=seed, room=room).scene.to_json()
        except InfeasibleSceneError as e:
            return f"infeasible: {e}"

    out = {}
    for path in sorted((ROOT / "cdf" / "examples").glob("*.yaml")):
        doc = cdf.load(path)
        out[f"scenes/{path.stem}"] = _digest(one(doc, s) for s in range(seeds))
    for room_type in ROOM_TYPES:
        out[f"scenes/empty_{room_type}"] = _digest(one(empty_cdf(room_type), s) for s in range(seeds))
    for name in CONVERTED:
        room = load_room(name)
        out[f"scenes/converted_{name}"] = _digest(one(empty_cdf(room.room_type), s, room) for s in range(2))
    return out


def room_hashes() -> dict[str, str]:
    import numpy as np

    from luminous_sim.rooms import SHAPES, generate_shell
    from luminous_sim.rooms.library import load_room, room_names
    from luminous_sim.vocab import ROOM_TYPES

    shells = []
    for room_type in ROOM_TYPES:
        for shape in SHAPES:
            for seed in range(5):
                try:
                    shells.append(generate_shell(room_type, np.random.default_rng(seed), shape=shape).model_dump_json())
                except Exception as e:  # a shape a room type does not take
                    shells.append(f"{type(e).__name__}: {e}")
    converted = (load_room(n).model_dump_json() for n in room_names(include_procedural=False))
    return {"rooms/procedural": _digest(shells), "rooms/converted": _digest(converted)}


def catalog_hash() -> dict[str, str]:
    lib = ROOT / "urdf_assets"
    files = sorted(p for p in lib.rglob("*") if p.is_file() and "_cache" not in p.parts)
    return {"catalog": _digest(chunk for p in files for chunk in (str(p.relative_to(lib)), p.read_bytes()))}


def demo_hash() -> dict[str, str]:
    from luminous_sim.demo import run_demo_episode

    with tempfile.TemporaryDirectory() as tmp:
        run_demo_episode(Path(tmp), seed=0)
        ep = Path(tmp)
        traj = (ep / "trajectory.json").read_bytes()
        frames = sorted((ep / "frames").glob("*"))
        return {"demo/trajectory": _digest([traj]),
                "demo/frames": _digest(chunk for p in frames for chunk in (p.name, p.read_bytes()))}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", type=int, default=10)
    ap.add_argument("--skip", nargs="*", default=[], choices=["scenes", "rooms", "catalog", "demo"])
    ap.add_argument("--out", type=Path)
    args = ap.parse_args()
    groups = {"catalog": catalog_hash, "rooms": room_hashes, "scenes": lambda: scene_hashes(args.seeds),
              "demo": demo_hash}
    lines = []
    for name, fn in groups.items():
        if name in args.skip:
            continue
        for key, value in fn().items():
            lines.append(f"{key} {value}")
            print(lines[-1], flush=True)
    if args.out:
        args.out.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
