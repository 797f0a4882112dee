"""Layer L5: export a room or house, as it is, to other tools: glTF binary (any viewer), USD, MJCF (MuJoCo).

    from luminous_sim.export import export
    export("out/scene", "glb", "out/scene.glb")        # a scene folder (or scene.json) from `luminous generate`
    export(world, "mjcf", "out/scene.xml")               # a live World: open doors open, sliced things sliced

The world is read through `world.posed.posed_scene` (bodies where PyBullet has them now, joints at their
values, colours and states as drawn); each format has its module (`glb`, `usd`, `mjcf`); `meshes` places the
asset library's meshes. USD needs usd-core and the MuJoCo check mujoco (the `export` extra).
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Literal, get_args

from luminous_sim.errors import LuminousError

if TYPE_CHECKING:
    from luminous_sim.scene import Scene
    from luminous_sim.world import World
    from luminous_sim.world.posed import PosedScene

Format = Literal["glb", "usd", "mjcf"]
FORMATS: tuple[str, ...] = get_args(Format)
SUFFIXES: dict[str, tuple[str, ...]] = {"glb": (".glb",), "usd": (".usd", ".usda", ".usdc"), "mjcf": (".xml",)}
"""The file suffixes each format writes (USD: `.usda` is text, `.usd`/`.usdc` binary)."""


class ExportError(LuminousError):
    """A scene that cannot be exported as asked: no scene there, an unknown format, a missing extra."""


@dataclass(frozen=True)
class ExportResult:
    """What `export` wrote."""

    path: Path
    format: str
    objects: int
    """Bodies written (a sliced object counts its slices)."""
    bytes: int
    seconds: float
    """Writing only (not building the world)."""


def load_scene(source: Path) -> Scene:
    """The scene of a scene folder (its scene.json) or of a scene file.

    Raises:
        ExportError: no scene there, or not a valid one (the message names the path).
    """
    from luminous_sim.scene import Scene

    source = Path(source)
    path = source / "scene.json" if source.is_dir() else source
    if source.is_dir() and not os.path.lexists(path):
        raise ExportError(f"{source}: has no scene.json; expected a scene folder written by `luminous generate`")
    if not os.path.lexists(path):
        raise ExportError(f"{source}: does not exist; expected a scene folder written by `luminous generate`")
    try:
        return Scene.load(path)  # refuses a FIFO, a device or a folder there without opening it for reading
    except LuminousError as exc:
        raise ExportError(str(exc)) from None


def build_world(scene: Scene) -> World:
    """The scene built in PyBullet with its initial states, `isSliced` included (the world slices those)."""
    from luminous_sim.world import World, WorldConfig

    world = World(scene, WorldConfig(cull=False))
    world.set_up_sliced(o.id for o in scene.objects if o.states.get("isSliced"))
    return world


def check_format(fmt: str, out: Path | None = None) -> str:
    """`fmt` if it is one of FORMATS (and `out` ends in one of its suffixes).

    Raises:
        ExportError: an unknown format or a suffix that does not fit it.
    """
    if fmt not in FORMATS:
        raise ExportError(f"unknown export format {fmt!r}; expected one of {', '.join(FORMATS)}")
    if out is not None and Path(out).suffix.lower() not in SUFFIXES[fmt]:
        raise ExportError(f"{out}: a {fmt} file ends in {' or '.join(SUFFIXES[fmt])}")
    return fmt


def check_posed(posed: PosedScene) -> None:
    """Every pose and size of a posed scene finite and within `limits.MAX_LAYOUT_COORDINATE_M` (a live world
    whose physics blew up, or a body thrown away, would otherwise write a file of NaN vertices).

    Raises:
        ExportError: naming the body (or structure box) and what is wrong.
    """
    from luminous_sim.limits import MAX_LAYOUT_COORDINATE_M

    def bad(values: tuple[float, ...] | list[float]) -> bool:
        return not all(math.isfinite(v) and abs(v) <= MAX_LAYOUT_COORDINATE_M for v in values)

    for box in posed.structure:
        if bad((*box.center, *box.size, *box.orientation)):
            raise ExportError(f"structure {box.name}: pose or size not finite or beyond "
                              f"+-{MAX_LAYOUT_COORDINATE_M:g} m; nothing was written")
    for obj in posed.objects:
        for link in obj.links:
            if bad((*link.position, *link.orientation, *link.com_position, *link.com_orientation)):
                raise ExportError(f"{obj.object_id} ({link.name}): pose not finite or beyond "
                                  f"+-{MAX_LAYOUT_COORDINATE_M:g} m; nothing was written")
        if bad([j.value for j in obj.joints]) or not (math.isfinite(obj.scale) and obj.scale > 0):
            raise ExportError(f"{obj.object_id}: a joint value or the scale is not finite; nothing was written")


def write(posed: PosedScene, fmt: str, out: Path, ceiling: bool = True) -> ExportResult:
    """Write a posed scene (`world.posed.posed_scene`) in one format, atomically (the old file or the new one).

    Raises:
        ExportError: an unknown format, a suffix that does not fit it, or a pose that is not finite (`check_posed`).
    """
    check_format(fmt, out)
    check_posed(posed)
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    if fmt == "glb":
        from luminous_sim.export.glb import write_glb

        write_glb(posed, out, ceiling=ceiling)
    elif fmt == "usd":
        from luminous_sim.export.usd import write_usd

        write_usd(posed, out, ceiling=ceiling)
    else:
        from luminous_sim.export.mjcf import MjcfOptions, write_mjcf

        write_mjcf(posed, out, MjcfOptions(ceiling=ceiling))
    return ExportResult(out, fmt, len(posed.objects), out.stat().st_size, time.perf_counter() - t0)


def export(source: World | Scene | Path | str, fmt: str, out: Path | str, ceiling: bool = True) -> ExportResult:
    """Export a room or house as it is to `out` in `fmt` (glb, usd or mjcf).

    Args:
        source: a live `World` (exported as it is now: doors as opened, slices in place of what was sliced,
            what was moved where it went), a `Scene`, or a scene folder / scene.json (built first, with its
            initial states).
        fmt: one of FORMATS.
        out: the file to write (`.glb`; `.usd`, `.usdc` or `.usda`; `.xml`).
        ceiling: include the ceiling and its light (a viewer looking from above sees through without them).

    Raises:
        ExportError: no scene at `source`, an unknown format, a suffix that does not fit it, or a missing
            optional package (usd-core for USD).
    """
    from luminous_sim.world import World
    from luminous_sim.world.posed import posed_scene

    check_format(fmt, Path(out))
    if isinstance(source, World):
        return write(posed_scene(source), fmt, Path(out), ceiling)
    from luminous_sim.scene import Scene, check_scene

    if isinstance(source, Scene):
        scene = check_scene(source, "the scene to export")
        where = "the scene to export"
    else:
        scene, where = load_scene(Path(source)), str(source)
    try:
        world = build_world(scene)
    except LuminousError as exc:  # an asset the catalog lacks, ...: said of the scene it came from
        raise ExportError(f"{where}: {exc}") from None
    with world:
        return write(posed_scene(world), fmt, Path(out), ceiling)


__all__ = ["FORMATS", "SUFFIXES", "ExportError", "ExportResult", "Format", "build_world", "check_format",
           "check_posed", "export", "load_scene", "write"]
