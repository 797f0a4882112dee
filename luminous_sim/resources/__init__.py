"""Layer L0: the data that travels with the package, and where the caches live.

Shipped inside the package (a wheel holds it all; the repository's top-level `urdf_assets/` and `cdf/` are links
to these folders, so there is one copy): the generated asset library (`urdf_assets/`, checked against its digest
in code before use: `asset_library`), the room library (`cdf/rooms/`: ALFRED's FloorPlans converted), the CDF and
layout JSON Schemas (`cdf/schema/`) and the example CDFs (`cdf/examples/`). Every module finds shipped data
through these functions, never relative to a source tree.

Environment variables: `LUMINOUS_ASSETS` (another asset library folder; with `LUMINOUS_ASSETS_DIGEST`, the
digest it must have), `LUMINOUS_CACHE` (the cache folder; default `$XDG_CACHE_HOME/luminous`, else
`~/.cache/luminous`). The room library's `LUMINOUS_ROOM_LIBRARY` is `rooms.library`'s.
"""

from __future__ import annotations

from luminous_sim.resources.library_check import (
    ASSET_LIBRARY_SHA256,
    DIGEST_VAR,
    asset_library,
    library_digest,
    verify_library,
)
from luminous_sim.resources.paths import (
    ASSETS_VAR,
    CACHE_VAR,
    asset_library_dir,
    cache_root,
    default_house,
    examples_dir,
    room_library_dir,
    schema_dir,
    shipped_asset_library_dir,
)

__all__ = [
    "ASSETS_VAR",
    "ASSET_LIBRARY_SHA256",
    "CACHE_VAR",
    "DIGEST_VAR",
    "asset_library",
    "asset_library_dir",
    "cache_root",
    "default_house",
    "examples_dir",
    "library_digest",
    "room_library_dir",
    "schema_dir",
    "shipped_asset_library_dir",
    "verify_library",
]
