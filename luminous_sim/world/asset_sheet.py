"""Contact sheet: every asset rendered from a three-quarter front view, labelled, on one picture."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from PIL import Image, ImageDraw, ImageFont

from luminous_sim.assets.catalog import AssetEntry
from luminous_sim.assets.objio import png_bytes
from luminous_sim.fileio import write_atomic
from luminous_sim.world.asset_loader import load_asset, set_joint, show_state
from luminous_sim.world.camera import render
from luminous_sim.world.client import add_floor, new_client


def render_thumbnail(entry: AssetEntry, size: int = 200, states_on: bool = False) -> np.ndarray:
    """One asset on a floor, seen from front-right-above, framed by its bounding box."""
    client = new_client()
    try:
        add_floor(client)
        loaded = load_asset(client, entry, (0.0, 0.0, -entry.bbox_min[2]), fixed=True)
        if states_on:
            for j in entry.joints:
                if j["kind"] != "fixed":
                    set_joint(client, loaded, j["name"], j["upper"])
            show_state(client, loaded, "on", True)
            show_state(client, loaded, "dirty", True)
        lo, hi = np.array(entry.bbox_min), np.array(entry.bbox_max)
        lo[2], hi[2] = 0.0, hi[2] - entry.bbox_min[2]
        center = (lo + hi) / 2
        radius = float(np.linalg.norm(hi - lo)) / 2
        direction = np.array([0.55, 1.0, 0.6])
        eye = center + direction / np.linalg.norm(direction) * 1.12 * radius / np.tan(np.radians(22))
        frame = render(client, eye, center, width=size, height=size, fov=45, near=0.01, far=50)
        return frame.rgb
    finally:
        client.disconnect()


def render_sheet(entries: Sequence[AssetEntry], out: Path, tile: int = 160, cols: int | None = None,
                 states_on: bool = False) -> Path:
    """Render all `entries` as a labelled grid PNG at `out` (written atomically)."""
    n = len(entries)
    cols = cols or max(1, min(n, int(np.ceil(np.sqrt(n * 1.6)))))
    rows = (n + cols - 1) // cols
    label_h = 14
    sheet = Image.new("RGB", (cols * tile, rows * (tile + label_h)), "white")
    draw = ImageDraw.Draw(sheet)
    font = ImageFont.load_default()
    for i, entry in enumerate(entries):
        r, c = divmod(i, cols)
        x, y = c * tile, r * (tile + label_h)
        sheet.paste(Image.fromarray(render_thumbnail(entry, tile, states_on)), (x, y))
        draw.text((x + 3, y + tile), entry.id, fill="black", font=font)
    write_atomic(Path(out), png_bytes(sheet))
    return Path(out)
