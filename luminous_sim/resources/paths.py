"""Where the shipped data and the caches are (see the package's docstring)."""

from __future__ import annotations

import os
from pathlib import Path

HERE = Path(__file__).resolve().parent
ASSETS_VAR = "LUMINOUS_ASSETS"
CACHE_VAR = "LUMINOUS_CACHE"


def shipped_asset_library_dir() -> Path:
    """The asset library that ships with the package."""
    return HERE / "urdf_assets"


def asset_library_dir() -> Path:
    """The asset library folder in use: `$LUMINOUS_ASSETS`, else the shipped one (not checked: see
    `asset_library`)."""
    named = os.environ.get(ASSETS_VAR, "").strip()
    return Path(named).expanduser() if named else shipped_asset_library_dir()


def room_library_dir() -> Path:
    """The shipped room library (`<FloorPlan>.json` files in subfolders)."""
    return HERE / "cdf" / "rooms"


def schema_dir() -> Path:
    """The shipped JSON Schemas (CDF, layouts)."""
    return HERE / "cdf" / "schema"


def examples_dir() -> Path:
    """The shipped example CDFs (`luminous cdf examples --out DIR` copies them out)."""
    return HERE / "cdf" / "examples"


def default_house() -> Path:
    """The house CDF `luminous generate --house` uses when none is named."""
    return examples_dir() / "houses" / "default_house.yaml"


def cache_root() -> Path:
    """The cache folder: `$LUMINOUS_CACHE`, else `$XDG_CACHE_HOME/luminous`, else `~/.cache/luminous`."""
    named = os.environ.get(CACHE_VAR, "").strip()
    if named:
        return Path(named).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME", "").strip()
    return (Path(xdg).expanduser() if xdg else Path.home() / ".cache") / "luminous"
