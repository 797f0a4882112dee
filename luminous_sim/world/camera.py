"""Camera images from PyBullet: RGB, depth in metres, and instance segmentation (TinyRenderer)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from luminous_sim.world.client import BulletClient, p
from luminous_sim.world.eye_plane import nudged

if TYPE_CHECKING:
    from luminous_sim.world.culling import FrustumCuller
    from luminous_sim.world.raster_scene import CompiledRenderer


@dataclass(frozen=True)
class Frame:
    """One rendered view: rgb (H,W,3) uint8, depth (H,W) float32 metres, seg (H,W) int32 raw PyBullet ids."""

    rgb: np.ndarray
    depth: np.ndarray
    seg: np.ndarray


def render(
    client: BulletClient, eye, target, up=(0.0, 0.0, 1.0), width: int = 300, height: int = 300,
    fov: float = 60.0, near: float = 0.05, far: float = 20.0, renderer: int | None = None,
    shadows: bool = False, light_direction=(0.4, -0.6, 1.0), culler: FrustumCuller | None = None,
    guard: FrustumCuller | None = None, compiled: CompiledRenderer | None = None,
) -> Frame:
    """Render from `eye` looking at `target`; depth converted from the z-buffer to metres. With `culler`
    (TinyRenderer only), links wholly outside the view are left out of the render, and stay hidden after it
    until the client is used otherwise (`culling.CullingClient`): the same frame, faster. With `guard` (or
    `culler`), where a triangle of the scene lies in the plane through the eye, the camera moves a tenth of a
    millimetre forward, since TinyRenderer would never return (`world.eye_plane`). With `compiled` (TinyRenderer
    only, no shadows), the compiled rasteriser draws the frame instead (`world.raster_scene`)."""
    if renderer is None:
        renderer = getattr(client, "luminous_renderer", p.ER_TINY_RENDERER)
    view = client.computeViewMatrix(list(eye), list(target), list(up))
    proj = client.computeProjectionMatrixFOV(fov, width / height, near, far)
    guard = guard or culler
    drawn_by = compiled if compiled is not None and renderer == p.ER_TINY_RENDERER and not shadows else None
    if drawn_by is not None:
        touches = drawn_by.touches_eye_plane(view)  # the guard's test, compiled
    else:
        touches = guard is not None and renderer == p.ER_TINY_RENDERER and guard.touches_eye_plane(view)
    if touches:
        eye, target = nudged(eye, target)
        view = client.computeViewMatrix(list(eye), list(target), list(up))
    if drawn_by is not None:
        rgb, zbuf, seg = drawn_by.render(view, proj, width, height, light_direction)
    else:
        if culler is not None and renderer == p.ER_TINY_RENDERER:
            culler.cull(view, proj, width, height)
            client = culler.client  # through the CullingClient, the render would show the hidden links again
        _, _, rgba, zbuf, seg = client.getCameraImage(
            width, height, view, proj, renderer=renderer, shadow=int(shadows), lightDirection=list(light_direction),
            flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX,
        )
        rgb = np.asarray(rgba, dtype=np.uint8).reshape(height, width, 4)[:, :, :3]
    z = np.asarray(zbuf, dtype=np.float32).reshape(height, width)
    depth = (far * near / (far - (far - near) * z)).astype(np.float32)
    return Frame(rgb, depth, np.asarray(seg, dtype=np.int32).reshape(height, width))
