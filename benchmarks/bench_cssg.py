"""CSSG quality and speed vs the uniform-random baseline, per room type, plus a picture grid.

    python benchmarks/bench_cssg.py --n 100          # the issue's figures (slow: physics on every scene)
    python benchmarks/bench_cssg.py --n 10 --no-physics
    python benchmarks/bench_cssg.py --n 60 --alfred-rooms        # in the 30 AI2-THOR rooms of each type
    python benchmarks/bench_cssg.py --n 60 --alfred-rooms --empty-cdf   # defaults and implicit rules only
    python benchmarks/bench_cssg.py --methods cssg uniform learned front atiss --n 10 --episodes 4
                                   # methods compared on the same rooms and tasks (layout_methods.py)

Per room type it uses the example CDF of that room type (explicit relations) and reports, for CSSG
and the baseline: explicit relations met, implicit rules met, scenes with interpenetrations > 1 cm,
objects that moved (> 1 cm) or fell while settling, required objects reachable by the agent, objects to
interact with that a sight line from where the agent stands meets (world/sightlines.py); then the
median time of one layout sample, of one valid scene (resamples included), and of a valid scene + PyBullet
build + settle. With --alfred-rooms the rooms are the shells converted from AI2-THOR's FloorPlans (seed i
uses room i modulo 30) instead of procedural ones; with --empty-cdf the CDF asks only for the room type.

Then the natural-room measures (cssg/natural.py), each over the objects it applies to: functional groups
(seats at a table facing it, sofa facing the TV or coffee table, armchairs facing the seating group,
bedside tables at the bed's head, sofa clear of a dining table, drawer units against a wall), the free
floor the agent reaches (pooled share, scenes with >= 95%, the largest region cut off), furniture square
to the room, small objects on plausible hosts (not ruled out; on a receptacle type ALFRED's scenes use for
the type, over every object of a type ALFRED shows and over those whose room holds such a receptacle) and
small objects on the floor against a wall.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim import cdf
from luminous_sim.assets.catalog import default_catalog
from luminous_sim.cssg import Generated, choose_room, generate, sample_uniform
from luminous_sim.errors import LuminousError

EXAMPLES = {
    "Kitchen": "kitchen_coffee_mug",
    "LivingRoom": "livingroom_painting_sofa",
    "Bedroom": "bedroom_reading_desk",
    "Bathroom": "bathroom_soap",
}


def _to_interact(object_type: str) -> bool:
    """Whether the agent would pick up, switch, open or put into things of this type."""
    from luminous_sim.vocab import abilities

    ab = abilities(object_type)
    return ab.pickupable or ab.toggleable or ab.openable or ab.receptacle


def _rate(hits: int, total: int) -> str:
    return f"{100 * hits / total:5.1f}% ({hits}/{total})" if total else "  n/a"


def _alfred_rooms(room_type: str) -> list:
    from luminous_sim.rooms.library import load_room, room_names

    rooms = [load_room(n) for n in room_names(include_procedural=False) if n.startswith("FloorPlan")]
    return [r for r in rooms if r.room_type == room_type]


def run(room_type: str, n: int, physics: bool, grid_dir: Path | None, alfred: bool = False,
        empty: bool = False) -> None:
    from luminous_sim.cssg import empty_cdf
    from luminous_sim.world.physics_check import check_physics

    source = "empty CDF" if empty else f"{EXAMPLES[room_type]}.yaml"
    doc = empty_cdf(room_type) if empty else \
        cdf.load(Path(__file__).resolve().parents[1] / "cdf" / "examples" / f"{EXAMPLES[room_type]}.yaml")
    rooms = _alfred_rooms(room_type) if alfred else []
    catalog = default_catalog()
    rows = {}
    natural: dict[str, dict] = {}
    tops = []
    for method in ("cssg", "baseline"):
        exp = imp = req_ok = req_total = pen_scenes = moved = fell = infeasible = soft = soft_total = 0
        targets = unseen = 0
        exp_total = imp_total = 0
        sample_times, scene_times, full_times = [], [], []
        nat = natural[method] = {"checks": {}, "free": 0, "reached": 0, "ok": 0, "scenes": 0, "cut": 0.0}
        for seed in range(n):
            t0 = time.perf_counter()
            if method == "cssg":
                try:
                    g = generate(doc, seed=seed, catalog=catalog, room=rooms[seed % len(rooms)] if rooms else None)
                except LuminousError:  # no valid layout (or no room) for this seed
                    infeasible += 1
                    continue
                scene_times.append(time.perf_counter() - t0)
                sample_times.append(scene_times[-1] / (g.report.attempt + 1))
            else:
                rng = np.random.default_rng(np.random.SeedSequence([seed, 0]))
                shell = rooms[seed % len(rooms)] if rooms else choose_room(doc, rng, catalog)
                draft, report = sample_uniform(doc, shell, rng, catalog)
                g = Generated(draft.to_scene("uniform", seed), report)
                sample_times.append(time.perf_counter() - t0)
            _natural(g.scene, catalog, nat)
            rels = g.report.relations
            exp += sum(r.met for r in rels if r.explicit and r.hard)
            exp_total += sum(1 for r in rels if r.explicit and r.hard)
            soft += sum(r.met for r in rels if r.explicit and not r.hard)
            soft_total += sum(1 for r in rels if r.explicit and not r.hard)
            imp += sum(r.met for r in rels if not r.explicit)
            imp_total += sum(1 for r in rels if not r.explicit)
            auto = tuple(f"_auto{i}" for i in range(5))
            required = [o for o in g.scene.objects if o.name and not o.name.endswith(auto)]
            req_total += len(required)
            req_ok += sum(o.id not in g.report.unreachable for o in required) - sum(
                1 for nme in g.report.unplaced if nme in g.report.required)
            if physics:
                ph = check_physics(g.scene)
                layout = scene_times[-1] if method == "cssg" else sample_times[-1]  # every resample counted
                full_times.append(ph.seconds["build"] + ph.seconds["settle"] + layout)
                pen_scenes += bool(ph.interpenetrations)
                moved += len(ph.moved)
                fell += len(ph.fell)
                targets += sum(1 for o in g.scene.objects if _to_interact(o.type))
                unseen += len(ph.unseeable)
            if method == "cssg" and grid_dir is not None and len(tops) < 6:
                tops.append(g)
        rows[method] = (exp, exp_total, imp, imp_total, req_ok, req_total, pen_scenes, moved, fell, infeasible,
                        sample_times, scene_times, full_times, soft, soft_total, targets - unseen, targets)
    where = f", {len(rooms)} AI2-THOR rooms" if rooms else ""
    print(f"\n== {room_type} ({source}, {n} seeds{where}) ==")
    print(f"{'':34}{'CSSG':>22}{'baseline':>22}")
    c, b = rows["cssg"], rows["baseline"]
    print(f"{'explicit hard relations met':34}{_rate(c[0], c[1]):>22}{_rate(b[0], b[1]):>22}")
    print(f"{'explicit soft relations met':34}{_rate(c[13], c[14]):>22}{_rate(b[13], b[14]):>22}")
    print(f"{'implicit rules met':34}{_rate(c[2], c[3]):>22}{_rate(b[2], b[3]):>22}")
    print(f"{'required objects reachable':34}{_rate(c[4], c[5]):>22}{_rate(b[4], b[5]):>22}")
    if physics:
        print(f"{'scenes with interpenetration>1cm':34}{c[6]:>22}{b[6]:>22}")
        print(f"{'objects moved >1cm while settling':34}{c[7]:>22}{b[7]:>22}")
        print(f"{'objects fell while settling':34}{c[8]:>22}{b[8]:>22}")
        print(f"{'objects to interact with, seen':34}{_rate(c[15], c[16]):>22}{_rate(b[15], b[16]):>22}")
    print(f"{'infeasible (no valid layout)':34}{c[9]:>22}{'-':>22}")
    _print_natural(natural["cssg"], natural["baseline"])

    def med(xs: list[float]) -> str:
        return f"{1000 * statistics.median(xs):.0f} ms" if xs else "n/a"

    print(f"{'median time per layout sample':34}{med(c[10]):>22}{med(b[10]):>22}")
    print(f"{'median time per valid scene':34}{med(c[11]):>22}{'-':>22}")
    if physics:
        print(f"{'median valid layout+build+settle':34}{med(c[12]):>22}{med(b[12]):>22}")
    if grid_dir is not None and tops:
        _grid(tops, grid_dir / f"cssg_{room_type}.png")


def _natural(scene, catalog, acc: dict) -> None:
    """Add one scene's natural-room measures to `acc`."""
    from luminous_sim.cssg.natural import (
        alignment_checks,
        floor_object_checks,
        floor_reach,
        functional_checks,
        host_checks,
    )

    for c in (functional_checks(scene, catalog) + alignment_checks(scene) + host_checks(scene, catalog)
              + floor_object_checks(scene, catalog)):
        hit = acc["checks"].setdefault(c.rule, [0, 0])
        hit[0] += c.met
        hit[1] += 1
    fr = floor_reach(scene, catalog)
    acc["free"] += fr.free
    acc["reached"] += fr.reached
    acc["scenes"] += 1
    acc["ok"] += fr.share >= 0.95
    acc["cut"] = max(acc["cut"], fr.largest_cut_off)


def _print_natural(c: dict, b: dict) -> None:
    print("natural rooms")
    for rule in sorted(set(c["checks"]) | set(b["checks"])):
        cc, bb = c["checks"].get(rule, (0, 0)), b["checks"].get(rule, (0, 0))
        print(f"{'  ' + rule:34}{_rate(*cc):>22}{_rate(*bb):>22}")
    print(f"{'  free floor reached (pooled)':34}{_rate(c['reached'], c['free']):>22}"
          f"{_rate(b['reached'], b['free']):>22}")
    print(f"{'  scenes reaching >= 95% of it':34}{_rate(c['ok'], c['scenes']):>22}{_rate(b['ok'], b['scenes']):>22}")
    print(f"{'  largest region cut off':34}{c['cut']:>20.2f}m2{b['cut']:>20.2f}m2")


def _grid(generated: list, out: Path) -> None:
    from PIL import Image, ImageOps

    from luminous_sim.world.scene_builder import build_scene
    from luminous_sim.world.views import top_down

    tiles = []
    for g in generated:
        built = build_scene(g.scene, settle_steps=0)
        try:
            img = top_down(built, px_per_m=80, labels=False)
        finally:
            built.client.disconnect()
        tiles.append(ImageOps.pad(img, (360, 360), color="white"))  # scaled to fill its tile
    cols = 3
    rows = (len(tiles) + cols - 1) // cols
    sheet = Image.new("RGB", (cols * 360, rows * 360), "white")
    for i, t in enumerate(tiles):
        sheet.paste(t, ((i % cols) * 360, (i // cols) * 360))
    out.parent.mkdir(parents=True, exist_ok=True)
    sheet.save(out)
    print(f"picture grid: {out}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", "--seeds", type=int, default=20, help="scenes (seeds) per room type and method")
    ap.add_argument("--rooms", nargs="*", default=list(EXAMPLES))
    ap.add_argument("--no-physics", action="store_true")
    ap.add_argument("--grid-dir", type=Path, default=Path("out/bench"))
    ap.add_argument("--alfred-rooms", action="store_true", help="rooms converted from AI2-THOR's FloorPlans")
    ap.add_argument("--empty-cdf", action="store_true", help="a CDF that asks only for the room type")
    ap.add_argument("--methods", nargs="+", help="compare these methods instead (layout_methods.METHODS): "
                    "cssg uniform learned front atiss")
    ap.add_argument("--episodes", type=int, default=0, help="with --methods: oracle episodes per task type")
    args = ap.parse_args()
    if args.methods:
        from layout_methods import compare

        compare(args.methods, args.rooms, args.n, args.episodes, not args.no_physics)
        return
    for room in args.rooms:
        run(room, args.n, not args.no_physics, None if args.alfred_rooms or args.empty_cdf else args.grid_dir,
            args.alfred_rooms, args.empty_cdf)


if __name__ == "__main__":
    main()
