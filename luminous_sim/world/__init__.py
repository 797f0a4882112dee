"""Layer L2: the only package that imports pybullet (building, rendering, physics, actions)."""
