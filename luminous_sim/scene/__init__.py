"""Layer L1: the scene description (what goes where), independent of any simulator."""

from luminous_sim.scene.model import Scene, SceneObject

__all__ = ["Scene", "SceneObject"]
