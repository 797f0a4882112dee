"""Layer L5: export a room or house, as it is, to other tools: glTF binary (any viewer), USD, MJCF (MuJoCo).

    from luminous_sim.export import export
    export("out/scene", "glb", "out/scene.glb")        # a scene folder (or scene.json) from `luminous generate`
    export(world, "mjcf", "out/scene.xml")               # a live World: open doors open, sliced things sliced

The world is read through `world.posed.posed_scene` (bodies where PyBullet has them now, joints at their
values, colours and states as drawn); each format has its module (`glb`, `usd`, `mjcf`); `meshes` places the
asset library's meshes. USD needs usd-core and the MuJoCo check mujoco (the `export` extra).
"""

from __future__ import annotations

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
    if not path.is_file():
        what = "has no scene.json" if source.is_dir() else "does not exist"
        raise ExportError(f"{source}: {what}; expected a scene folder written by `luminous generate`")
    try:
        return Scene.load(path)
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


def write(posed: PosedScene, fmt: str, out: Path, ceiling: bool = True) -> ExportResult:
    """Write a posed scene (`world.posed.posed_scene`) in one format."""
    check_format(fmt, out)
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
    from luminous_sim.scene import Scene

    scene = source if isinstance(source, Scene) else load_scene(Path(source))
    with build_world(scene) as world:
        return write(posed_scene(world), fmt, Path(out), ceiling)


__all__ = ["FORMATS", "SUFFIXES", "ExportError", "ExportResult", "Format", "build_world", "check_format", "export",
           "load_scene", "write"]
