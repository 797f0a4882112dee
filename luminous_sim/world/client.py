"""One PyBullet physics client per World, DIRECT by default, with the project's deterministic settings,
and the renderer: TinyRenderer on the CPU, the EGL plugin automatically where a GPU is present."""

from __future__ import annotations

import contextlib
import ctypes
import glob
import importlib.util
import os
import sys
from collections.abc import Iterator

import numpy as np


@contextlib.contextmanager
def _silenced(*fds: int) -> Iterator[None]:
    """Send what C code writes to these file descriptors to /dev/null (PyBullet prints `argv[0]=` on
    stdout at every connect and its build time on stderr at import)."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(fd) for fd in fds]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        for fd in fds:
            os.dup2(devnull, fd)
        yield
    finally:
        ctypes.CDLL(None).fflush(None)  # C stdio buffers would otherwise reach the real fd later
        for fd, copy in zip(fds, saved):
            os.dup2(copy, fd)
            os.close(copy)
        os.close(devnull)


with _silenced(2):
    import pybullet as p
from pybullet_utils.bullet_client import BulletClient  # noqa: E402

TIME_STEP = 1.0 / 240.0
GRAVITY = -9.81


def body_aabb(client, body: int) -> tuple[np.ndarray, np.ndarray]:
    """World-axis bounds of a body with all its links (a floor lamp's base is only its foot)."""
    lo, hi = map(np.array, client.getAABB(body, -1))
    for j in range(client.getNumJoints(body)):
        a, b = map(np.array, client.getAABB(body, j))
        lo, hi = np.minimum(lo, a), np.maximum(hi, b)
    return lo, hi


def gpu_present() -> bool:
    """Whether an NVIDIA GPU is visible to this process."""
    return bool(glob.glob("/dev/nvidia[0-9]*"))


def resolve_renderer(choice: str = "auto") -> str:
    """"tiny" or "egl": `auto` means EGL where a GPU is present ($LUMINOUS_RENDERER overrides)."""
    choice = os.environ.get("LUMINOUS_RENDERER", choice) if choice == "auto" else choice
    if choice == "auto":
        return "egl" if gpu_present() else "tiny"
    if choice not in ("tiny", "egl"):
        raise ValueError(f"renderer must be auto, tiny or egl, not {choice!r}")
    return choice


def new_client(gui: bool = False, renderer: str = "tiny") -> BulletClient:
    """A fresh client: fixed time step, gravity, deterministic overlapping pairs, no GUI unless asked.

    With renderer "egl" the EGL plugin is loaded first (it must be, before anything is built) and the
    client's camera uses it; if the plugin cannot load, the client falls back to TinyRenderer.
    """
    with _silenced(1):
        client = BulletClient(connection_mode=p.GUI if gui else p.DIRECT)
    client.luminous_renderer = p.ER_TINY_RENDERER
    if renderer == "egl":
        egl = importlib.util.find_spec("eglRenderer")
        if egl is not None and egl.origin is not None \
                and client.loadPlugin(egl.origin, "_eglRendererPlugin") >= 0:
            client.luminous_renderer = p.ER_BULLET_HARDWARE_OPENGL
    client.setPhysicsEngineParameter(
        fixedTimeStep=TIME_STEP, deterministicOverlappingPairs=1, numSolverIterations=50
    )
    client.setGravity(0, 0, GRAVITY)
    return client


def add_floor(client: BulletClient, half_extent: float = 20.0) -> int:
    """A static floor slab whose top is at z = 0."""
    shape = client.createCollisionShape(p.GEOM_BOX, halfExtents=[half_extent, half_extent, 0.05])
    visual = client.createVisualShape(p.GEOM_BOX, halfExtents=[half_extent, half_extent, 0.05],
                                      rgbaColor=[0.62, 0.55, 0.47, 1])
    body = client.createMultiBody(0, shape, visual, [0, 0, -0.05])
    client.changeDynamics(body, -1, lateralFriction=0.9)
    return body
