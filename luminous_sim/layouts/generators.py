"""Layout generators behind one interface: CSSG, the uniform baseline and (later) learned models each give a
`Layout` for a room and a seed; `realize` turns any of them into a validated scene the same way."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.cdf.schema import ChallengeDefinition
from luminous_sim.layouts.convert import layout_of_scene
from luminous_sim.layouts.model import Layout
from luminous_sim.rooms.shell import RoomShell


@runtime_checkable
class LayoutGenerator(Protocol):
    """Anything that furnishes a room: `name` for reports, `layout(shell, seed)` for the layout.

    The same shell and seed must give the same layout. A generator may leave out small objects and assets
    (a learned model predicts categories and boxes only): `realize` matches and furnishes what is missing.
    """

    name: str

    def layout(self, shell: RoomShell, seed: int) -> Layout: ...


@dataclass
class CSSGLayouts:
    """CSSG (`cssg.generate`) for a CDF (default: an empty one of the room's type), as layouts."""

    cdf: ChallengeDefinition | None = None
    catalog: Catalog | None = None
    name: str = "cssg"

    def layout(self, shell: RoomShell, seed: int) -> Layout:
        from luminous_sim.cssg import empty_cdf, generate

        catalog = self.catalog or default_catalog()
        doc = self.cdf or empty_cdf(shell.room_type)
        return layout_of_scene(generate(doc, seed=seed, room=shell, catalog=catalog).scene, catalog)


@dataclass
class UniformLayouts:
    """The uniform-random baseline (`cssg.generate_uniform`), as layouts."""

    cdf: ChallengeDefinition | None = None
    catalog: Catalog | None = None
    name: str = "uniform"

    def layout(self, shell: RoomShell, seed: int) -> Layout:
        from luminous_sim.cssg import generate_uniform

        catalog = self.catalog or default_catalog()
        return layout_of_scene(generate_uniform(shell, seed, catalog, self.cdf), catalog)
