"""Moved: `luminous_sim.episodes` (the CDF source) and `luminous_sim.env.episodes.cdf_paths`; this path warns and
forwards until 0.3.0."""

from luminous_sim.lazy import moved_getattr

__getattr__ = moved_getattr(__name__, {
    **dict.fromkeys(("cdf_scene", "load_cdf", "start_pose"), "luminous_sim.episodes"),
    "cdf_paths": "luminous_sim.env.episodes"}, "0.3.0")
