"""Where the asset library lives (`luminous_sim.resources`: the shipped one, or $LUMINOUS_ASSETS), and a user
library for imported meshes (~/.luminous/user_assets or $LUMINOUS_USER_ASSETS)."""

from __future__ import annotations

import os
from pathlib import Path

from luminous_sim.resources import asset_library_dir


def asset_root() -> Path:
    """The built-in asset library folder (where `luminous assets build` writes by default; not checked: readers go
    through `luminous_sim.resources.asset_library`)."""
    return asset_library_dir()


def user_asset_root() -> Path:
    """The folder holding the user's imported assets and their catalog."""
    default = Path.home() / ".luminous" / "user_assets"
    return Path(os.environ.get("LUMINOUS_USER_ASSETS", default))


def coacd_cache_dir(root: Path | None = None) -> Path:
    """Content-addressed cache of convex decompositions (committed with the library)."""
    return (root or asset_root()) / "_cache" / "coacd"
