"""Houses of several rooms: generation time, reachability across rooms, the oracle on tasks across rooms,
and a picture grid.

    python benchmarks/bench_houses.py                           # 3-8 rooms, 5 seeds each; oracle on 2 seeds each
    python benchmarks/bench_houses.py --seeds 2 --oracle-seeds 1 --pictures /tmp/houses

For each size (3 to 8 rooms: Kitchen, LivingRoom, Bedroom, Bathroom, Bedroom, Bathroom, Bedroom, LivingRoom,
the kitchen asked to open onto the living room) and seed it generates the house (`cssg.generate_house`) and
reports the CPU time (median and range per size; the machine is shared, so CPU time, not wall-clock), the
houses that failed to generate, the rooms that needed furnishing again because furniture cut their floor off,
and reachability across rooms: of every room, whether the house's reachable grid (the agent's grid, which
the simulator's navigation uses) holds all of the room's own reachable floor, and whether the simulator's
navigation grid of the built house has points in every room.

Then, on the first `--oracle-seeds` houses of each size, one episode per ALFRED task type with the task's
object and receptacle (or lamp) in different rooms (`run_episode(..., cross_room=True)`): every sampled task
counts; a house with no such task of a type is counted apart ("no task"). As in `bench_oracle.py`, an
episode redraws its task when the failure says the task, not the oracle, is the problem (ALFRED's generator
drops those too, `episode.REDRAW_ON`); the episodes that did, and those solved after a failed attempt (the
oracle replans), are counted beside the success rate.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim import cdf
from luminous_sim.cdf import ChallengeDefinition
from luminous_sim.cssg import HouseGenerated, generate_house
from luminous_sim.errors import LuminousError
from luminous_sim.vocab import ALFRED_TASK_TYPES

TYPES = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom", "Bedroom", "Bathroom", "Bedroom", "LivingRoom")


def house_cdf(n: int) -> ChallengeDefinition:
    """A house of the first `n` of TYPES, the kitchen opening onto the living room."""
    rooms = [{"name": f"{t.lower()}{i}", "type": t} for i, t in enumerate(TYPES[:n])]
    doc = {"cdf_version": 2, "name": f"house_{n}_rooms",
           "scene": {"house": {"rooms": rooms, "adjacency": [[rooms[0]["name"], rooms[1]["name"]]]}}}
    return cdf.from_document(doc, f"<house of {n} rooms>")


def _nav_rooms(house: HouseGenerated) -> set[str | None]:
    from luminous_sim.world import World

    with World(house.scene) as world:
        return {house.scene.room.room_at(x, y) for x, y in world.nav.points()}


def generation(sizes: list[int], seeds: int, pictures: Path | None) -> tuple[dict[str, Any], dict]:
    out: dict[str, Any] = {}
    houses: dict[tuple[int, int], HouseGenerated] = {}
    for n in sizes:
        doc = house_cdf(n)
        times, failed, redrawn, rooms, reached, nav_ok, replanned = [], [], 0, 0, 0, 0, 0
        for seed in range(seeds):
            t0 = time.process_time()
            try:
                house = generate_house(doc, seed=seed)
            except LuminousError as exc:
                failed.append(f"seed {seed}: {exc}")
                continue
            times.append(time.process_time() - t0)
            houses[(n, seed)] = house
            rooms += len(house.report.rooms_reached)
            reached += sum(house.report.rooms_reached.values())
            redrawn += sum(r["redraws"] > 0 for r in house.scene.notes["rooms"].values())
            replanned += house.report.plan_redraws > 0
            names = {r.name for r in house.scene.room.house.rooms}  # type: ignore[union-attr]
            nav_ok += names <= _nav_rooms(house)
            if pictures is not None:
                _picture(house, pictures / f"house_{n}rooms_seed{seed}.png")
        out[str(n)] = {"houses": seeds, "failed": failed,
                       "cpu_s_median": _r(statistics.median(times)) if times else None,
                       "cpu_s_min": _r(min(times)) if times else None, "cpu_s_max": _r(max(times)) if times else None,
                       "rooms": rooms, "rooms_reached": reached, "rooms_redrawn": redrawn,
                       "houses_nav_grid_in_every_room": nav_ok, "houses_plan_redrawn": replanned}
        row = out[str(n)]
        print(f"{n} rooms: {seeds - len(failed)}/{seeds} houses, CPU s median {row['cpu_s_median']} "
              f"({row['cpu_s_min']}..{row['cpu_s_max']}); rooms reached across doors {reached}/{rooms}; "
              f"navigation grid in every room {nav_ok}/{seeds - len(failed)}; rooms furnished again {redrawn}; "
              f"houses whose floor plan was drawn again {replanned}",
              flush=True)
        for f in failed:
            print(f"  failed: {f}", flush=True)
    return out, houses


def oracle(houses: dict[tuple[int, int], HouseGenerated], oracle_seeds: int) -> dict[str, Any]:
    import luminous_sim.planning as planning
    from luminous_sim.episode import run_episode
    from luminous_sim.tasks.errors import TaskSamplingError

    draws = {"n": 0}
    real_draw = planning.draw_task

    def counted_draw(*args: Any, **kwargs: Any) -> Any:
        draws["n"] += 1
        return real_draw(*args, **kwargs)

    planning.draw_task = counted_draw  # run_episode imports it at each call: count its redraws
    per_type: dict[str, dict[str, Any]] = {t: {"sampled": 0, "success": 0, "no_task": 0, "failures": [],
                                               "redrawn": 0, "recovered": 0, "cpu_s": []}
                                           for t in ALFRED_TASK_TYPES}
    for (n, seed), house in sorted(houses.items()):
        if seed >= oracle_seeds:
            continue
        for t in ALFRED_TASK_TYPES:
            row = per_type[t]
            t0 = time.process_time()
            draws["n"] = 0
            try:
                result, _ = run_episode(house.scene, t, seed, record_frames=False, extra_annotations=0, cross_room=True)
            except TaskSamplingError:
                row["no_task"] += 1
                continue
            row["cpu_s"].append(time.process_time() - t0)
            row["sampled"] += 1
            row["success"] += bool(result.success)
            row["redrawn"] += draws["n"] > 1
            row["recovered"] += bool(result.success and result.failures)
            if not result.success:
                row["failures"].append(f"{n} rooms seed {seed}: {result.failure}")
            print(f"  {n} rooms seed {seed} {t}: {'ok' if result.success else 'FAILED ' + result.failure}", flush=True)
    for t, row in per_type.items():
        rate = row["success"] / row["sampled"] if row["sampled"] else None
        cpu = row.pop("cpu_s")
        row["rate"] = None if rate is None else round(rate, 3)
        row["cpu_s_median"] = _r(statistics.median(cpu)) if cpu else None
        print(f"{t:36s} {row['success']:3d}/{row['sampled']:3d} = {row['rate']}  (no cross-room task in "
              f"{row['no_task']} houses; task redrawn in {row['redrawn']}, solved after a failed attempt in "
              f"{row['recovered']}; CPU s median {row['cpu_s_median']})", flush=True)
    total = sum(r["sampled"] for r in per_type.values())
    ok = sum(r["success"] for r in per_type.values())
    print(f"all types: {ok}/{total} = {ok / max(total, 1):.3f}", flush=True)
    return per_type


def _picture(house: HouseGenerated, path: Path) -> None:
    from luminous_sim.assets.objio import png_bytes
    from luminous_sim.fileio import write_atomic
    from luminous_sim.scene import scene_reachable_grid
    from luminous_sim.world import build_scene, top_down

    built = build_scene(house.scene)
    try:
        write_atomic(path, png_bytes(top_down(built, px_per_m=45, grid=scene_reachable_grid(house.scene))))
    finally:
        built.close()


def picture_grid(folder: Path, out: Path, columns: int = 4) -> None:
    from PIL import Image, ImageDraw

    files = sorted(folder.glob("house_*rooms_seed*.png"), key=lambda p: (int(p.stem.split("_")[1][:-5]), p.stem))
    if not files:
        return
    images = [Image.open(f).convert("RGB") for f in files]
    cell = 420
    rows = (len(images) + columns - 1) // columns
    sheet = Image.new("RGB", (columns * cell, rows * (cell + 16)), "white")
    draw = ImageDraw.Draw(sheet)
    for k, (f, im) in enumerate(zip(files, images, strict=True)):
        im.thumbnail((cell, cell))
        x, y = (k % columns) * cell, (k // columns) * (cell + 16)
        sheet.paste(im, (x, y + 16))
        draw.text((x + 4, y + 2), f.stem, fill=(0, 0, 0))
    sheet.save(out)


def _r(x: float) -> float:
    return round(float(x), 2)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=list(range(3, 9)))
    parser.add_argument("--seeds", type=int, default=5, help="houses per size (default 5)")
    parser.add_argument("--oracle-seeds", type=int, default=2, help="houses per size the oracle runs in (default 2)")
    parser.add_argument("--pictures", type=Path, help="folder for each house's top-down picture and grid.png")
    parser.add_argument("--json", type=Path, help="write the figures here")
    args = parser.parse_args(argv)
    if args.pictures is not None:
        args.pictures.mkdir(parents=True, exist_ok=True)
    gen, houses = generation(args.sizes, args.seeds, args.pictures)
    if args.pictures is not None:
        picture_grid(args.pictures, args.pictures / "grid.png")
        print(f"pictures: {args.pictures} (grid.png)", flush=True)
    figures = {"generation": gen, "oracle": oracle(houses, args.oracle_seeds) if args.oracle_seeds else {}}
    if args.json is not None:
        args.json.write_text(json.dumps(figures, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
