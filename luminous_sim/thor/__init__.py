"""ai2thor 2.1.0's API on Luminous-Sim, for ALFRED's own code (`ThorEnv`, its task checks, its evaluation
loop) unchanged: `Controller`, `Event`, scene identification from a built dataset folder, and the
`python -m luminous_sim.thor SCRIPT` runner that makes `import ai2thor` resolve here (docs/thor.md)."""

from luminous_sim.thor.controller import Controller
from luminous_sim.thor.event import Event, object_color, object_name
from luminous_sim.thor.scenes import DATA_VAR, SceneIndex, ThorSceneError, Trial, poses_key
from luminous_sim.thor.shim import activate, write_shim

__all__ = [
    "DATA_VAR",
    "Controller",
    "Event",
    "SceneIndex",
    "ThorSceneError",
    "Trial",
    "activate",
    "object_color",
    "object_name",
    "poses_key",
    "write_shim",
]
