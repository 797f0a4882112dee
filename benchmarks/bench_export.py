"""Export: time and file size per format (glb, usd, usda, mjcf) for a room and a 6-room house, and the MuJoCo
settle check (largest displacement in 2 s of MuJoCo).

    python benchmarks/bench_export.py                  # the kitchen of cdf/examples/kitchen_apple_fridge.yaml
                                                       # (seed 0, fridge/cabinets/drawers open, the apple
                                                       # sliced) and a house of 6 rooms (seed 0)
    python benchmarks/bench_export.py --rooms 4 --repeats 1

The house is bench_houses.py's: Kitchen, LivingRoom, Bedroom, Bathroom, Bedroom, Bathroom, the kitchen opening
onto the living room. Times are wall-clock medians of `--repeats` writes (the first write of a run loads the
meshes from disk; later ones find them cached, as a second export in one process does), on a shared machine:
compare them with care. Building the world (once per scene) is reported apart.
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from luminous_sim import cdf
from luminous_sim.cssg import generate, generate_house
from luminous_sim.export import build_world, write
from luminous_sim.scene import Scene
from luminous_sim.world.posed import posed_scene

REPO = Path(__file__).resolve().parents[1]
TYPES = ("Kitchen", "LivingRoom", "Bedroom", "Bathroom", "Bedroom", "Bathroom", "Bedroom", "LivingRoom")
FILES = (("glb", "scene.glb"), ("usd", "scene.usd"), ("usd", "scene.usda"), ("mjcf", "scene.xml"))


def room_scene() -> Scene:
    """The kitchen with its openable furniture open and its apple sliced (states exported as they are)."""
    scene = generate(cdf.load(REPO / "cdf" / "examples" / "kitchen_apple_fridge.yaml"), seed=0).scene
    objects = []
    for o in scene.objects:
        if o.type in ("Fridge", "Microwave", "Cabinet", "Drawer"):
            o = o.model_copy(update={"states": {**o.states, "isOpen": True}})
        elif o.type == "Apple":
            o = o.model_copy(update={"states": {**o.states, "isSliced": True}})
        objects.append(o)
    return scene.model_copy(update={"objects": tuple(objects)})


def house_scene(n: int) -> Scene:
    rooms = [{"name": f"{t.lower()}{i}", "type": t} for i, t in enumerate(TYPES[:n])]
    doc = {"cdf_version": 2, "name": f"house_{n}_rooms",
           "scene": {"house": {"rooms": rooms, "adjacency": [[rooms[0]["name"], rooms[1]["name"]]]}}}
    return generate_house(cdf.from_document(doc, f"<house of {n} rooms>"), seed=0).scene


def measure(name: str, scene: Scene, repeats: int, folder: Path) -> None:
    from luminous_sim.export.mjcf import settle_check

    t0 = time.perf_counter()
    with build_world(scene) as world:
        built = time.perf_counter() - t0
        posed = posed_scene(world)
    print(f"\n{name}: {len(posed.objects)} bodies, {sum(len(o.links) for o in posed.objects)} links, "
          f"{sum(j.kind != 'fixed' for o in posed.objects for j in o.joints)} joints; world built in {built:.2f} s")
    print(f"{'format':8} {'file':12} {'write s (median)':>17} {'first write s':>14} {'size MB':>8}")
    for fmt, file in FILES:
        out = folder / f"{name}_{file}"
        times = [write(posed, fmt, out).seconds for _ in range(repeats)]
        print(f"{fmt:8} {file:12} {statistics.median(times):17.2f} {times[0]:14.2f} {out.stat().st_size / 1e6:8.2f}")
    t0 = time.perf_counter()
    check = settle_check(folder / f"{name}_scene.xml", seconds=2.0)
    took = time.perf_counter() - t0
    print(f"MuJoCo settle check (2 s, {check.bodies} free bodies, {check.joints} joints; {took:.1f} s):"
          f" largest move {check.xy[0] * 1000:.2f} mm sideways ({check.xy[1]}), {check.z[0] * 1000:.2f} mm vertically "
          f"({check.z[1]}), hinge {check.angle[0]:.5f} rad ({check.angle[1] or '-'}), slide "
          f"{check.slide[0] * 1000:.2f} mm ({check.slide[1] or '-'}): {'within' if check.ok else 'BEYOND'} the "
          "tolerance (10 mm / 20 mm / 0.02 rad / 10 mm)")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rooms", type=int, default=6, help="rooms in the house (3..8, default 6)")
    parser.add_argument("--repeats", type=int, default=3, help="writes per format (default 3)")
    args = parser.parse_args(argv)
    print(f"load average at start: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory() as tmp:
        measure("room", room_scene(), args.repeats, Path(tmp))
        measure(f"house{args.rooms}", house_scene(args.rooms), args.repeats, Path(tmp))
    print(f"\nload average at end: {', '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
