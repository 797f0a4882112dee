"""`luminous generate`: CSSG from a CDF to scene files, one folder per scene."""

from __future__ import annotations

import argparse
from pathlib import Path


def register(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("generate", help="generate scenes from a CDF with CSSG")
    parser.add_argument("--cdf", type=Path, help="challenge definition (YAML/JSON); default: an empty one")
    parser.add_argument("--room-type", default="Kitchen", help="room type when no CDF is given")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--count", type=int, default=1, help="scenes with seeds seed, seed+1, ...")
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--room", help="a room-library name (e.g. FloorPlan12, kitchen_L); overrides the CDF's")
    parser.add_argument("--baseline", action="store_true", help="uniform-random placement instead of CSSG")
    parser.add_argument("--no-physics", action="store_true", help="skip the PyBullet settling check")
    parser.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    import numpy as np
    from tqdm import tqdm

    from luminous_sim import cdf as cdf_mod
    from luminous_sim.cssg import Generated, empty_cdf, generate, sample_uniform
    from luminous_sim.scene_outputs import write_scene_outputs

    doc = cdf_mod.load(args.cdf) if args.cdf else empty_cdf(args.room_type)
    shell = None
    if args.room:
        from luminous_sim.rooms.library import shell_for

        shell = shell_for(args.room, np.random.default_rng(args.seed))
    failures = 0
    for k in tqdm(range(args.count), desc="scenes", unit="scene", disable=args.count == 1):
        seed = args.seed + k
        if args.baseline:
            from luminous_sim.assets.catalog import default_catalog
            from luminous_sim.cssg import choose_room

            rng = np.random.default_rng(np.random.SeedSequence([seed, 0]))
            room = shell or choose_room(doc, rng)
            draft, report = sample_uniform(doc, room, rng, default_catalog())
            generated = Generated(draft.to_scene("uniform", seed, source=doc.name or ""), report)
        else:
            generated = generate(doc, seed=seed, room=shell)
        sub = args.out if args.count == 1 else args.out / f"scene_{seed:05d}"
        report = write_scene_outputs(generated, sub, physics=not args.no_physics)
        ok = report["layout"]["ok"] and report.get("physics", {}).get("ok", True)
        failures += not ok
        if args.count == 1:
            print(f"wrote {sub}/scene.json ({len(generated.scene.objects)} objects, room {generated.scene.room.name}), "
                  f"report.json (valid: {ok}), top_down.png, egocentric.png")
    if args.count > 1:
        print(f"wrote {args.count} scenes under {args.out} ({args.count - failures} fully valid)")
    return 0
