"""Where the asset library lives: the repository's `urdf_assets/` (or $LUMINOUS_ASSETS), and a user
library for imported meshes (~/.luminous/user_assets or $LUMINOUS_USER_ASSETS)."""

from __future__ import annotations

import os
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parents[2]


def asset_root() -> Path:
    """The built-in asset library folder."""
    return Path(os.environ.get("LUMINOUS_ASSETS", REPO_ROOT / "urdf_assets"))


def user_asset_root() -> Path:
    """The folder holding the user's imported assets and their catalog."""
    default = Path.home() / ".luminous" / "user_assets"
    return Path(os.environ.get("LUMINOUS_USER_ASSETS", default))


def coacd_cache_dir(root: Path | None = None) -> Path:
    """Content-addressed cache of convex decompositions (committed with the library)."""
    return (root or asset_root()) / "_cache" / "coacd"
