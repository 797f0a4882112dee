"""A World's sensor and agent settings."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal


@dataclass(frozen=True)
class WorldConfig:
    """Sensor and agent settings (ALFRED's by default)."""

    width: int = 300
    height: int = 300
    fov: float = 60.0
    render: bool = True
    renderer: Literal["auto", "tiny", "egl"] = "auto"
    visibility_distance: float = 1.5
    min_visible_pixels: int = 10
    settle_steps: int = 240
    interaction_steps: int = 60
    lod_max_size: int = 128
    """Frames whose larger side is at most this many pixels render the assets' decimated level-of-detail
    visuals (collision and physics are the same); larger frames, ALFRED's 300x300 included, the full
    detail. 0 turns the level of detail off."""
    cull: bool = True
    """Leave object links wholly outside the camera's view out of each render (the frame is the same pixel
    for pixel; see `world.culling`)."""
    cull_outdoors: bool = True
    """With `cull`, also leave the outdoors (ground, sky) out of each render where no doorway or window of the
    room shows it (see `world.portals`)."""
    rasteriser: Literal["tinyrenderer", "compiled"] = "tinyrenderer"
    """Who draws the frames: "tinyrenderer", PyBullet's own, or "compiled", TinyRenderer's rasteriser compiled
    with numba (`world.raster_kernel`): the same RGB and segmentation but for rare pixels where two surfaces
    lie within float rounding of each other (about 6 in a million), depth within 1e-4 m, a 64 px step about
    3.2x and a 300 px step about 4.1x cheaper, for about 150 MB more memory per process (numba and LLVM; most
    of it shared libraries). A scene with a visual the compiled one cannot draw is drawn by TinyRenderer (with
    a warning)."""
    structure_last: bool = True
    """Paint the floor, walls, ceiling and outdoors after the objects (the same frame, less shading; see
    `scene_builder.paint_structure_last`)."""

    @property
    def use_lod(self) -> bool:
        """Whether this World loads the level-of-detail visuals."""
        return max(self.width, self.height) <= self.lod_max_size
