"""Layer L5: the one layout format (`luminous-layout/1`), CSSG scenes to and from it, importers for 3D-FRONT
scenes and ATISS-style object lists, matching to the asset catalog, and repair by CSSG (docs/layouts.md).

Typical use::

    from luminous_sim import layouts
    layout = layouts.import_front(path)            # or layouts.load(path), layouts.import_atiss(path)
    realized = layouts.realize(layout, seed=0)     # realized.given.generated: scene and report
    layout = layouts.LearnedLayouts().layout(shell, seed=0)   # the learned generator (torch, lazily)
"""

from luminous_sim.layouts.atiss import import_atiss
from luminous_sim.layouts.convert import layout_of_scene, room_of_shell, shell_of_room
from luminous_sim.layouts.front import import_front
from luminous_sim.layouts.generators import CSSGLayouts, LayoutGenerator, UniformLayouts
from luminous_sim.layouts.learned import LearnedLayouts, train_layouts
from luminous_sim.layouts.matching import MAX_SCALE, MIN_SCALE, CategoryMatch, SizeMatch, match_category, match_size
from luminous_sim.layouts.model import (
    LAYOUT_FORMAT,
    Layout,
    LayoutDoor,
    LayoutError,
    LayoutObject,
    LayoutRoom,
    LayoutWindow,
    Provenance,
    load,
    loads,
)
from luminous_sim.layouts.realize import Realized, realize
from luminous_sim.layouts.schema import export_schema, schema_dict

__all__ = [
    "LAYOUT_FORMAT",
    "MAX_SCALE",
    "MIN_SCALE",
    "CSSGLayouts",
    "CategoryMatch",
    "Layout",
    "LayoutDoor",
    "LayoutError",
    "LayoutGenerator",
    "LayoutObject",
    "LayoutRoom",
    "LayoutWindow",
    "LearnedLayouts",
    "Provenance",
    "Realized",
    "SizeMatch",
    "UniformLayouts",
    "export_schema",
    "import_atiss",
    "import_front",
    "layout_of_scene",
    "load",
    "loads",
    "match_category",
    "match_size",
    "realize",
    "room_of_shell",
    "schema_dict",
    "shell_of_room",
    "train_layouts",
]
