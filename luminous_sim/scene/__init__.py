"""Layer L1: the scene description (what goes where), independent of any simulator, and the plain geometry
of a scene that the generator, the simulator and the planner share: poses and footprints, receptacle
regions, sight lines into them, the agent's reach and its reachable 0.25 m grid."""

from luminous_sim.scene.agent_grid import (
    AGENT_HEIGHT,
    STEP,
    blocks_agent,
    largest_component,
    reachable_grid,
    scene_reachable_grid,
)
from luminous_sim.scene.model import SCENE_STATES, Layer, Scene, SceneError, SceneObject, check_scene
from luminous_sim.scene.pose import (
    WallPose,
    against_wall,
    footprint,
    front_zone,
    local_to_world,
    rotate,
    yaw_facing,
)
from luminous_sim.scene.raster import distance_transform, feature_transform, label4, minimum_filter_box
from luminous_sim.scene.reach import REACH, horizontal_reach, reach_of
from luminous_sim.scene.regions import (
    RegionSpot,
    can_hold,
    edge_slides,
    fits,
    hang_pose,
    hanger_back,
    open_tops,
    region_spots,
    sample_in_region,
    scan_region,
)
from luminous_sim.scene.sight import Shade, View, in_sight, shades

__all__ = [
    "AGENT_HEIGHT",
    "REACH",
    "SCENE_STATES",
    "STEP",
    "Layer",
    "RegionSpot",
    "Scene",
    "SceneError",
    "SceneObject",
    "Shade",
    "View",
    "WallPose",
    "against_wall",
    "blocks_agent",
    "can_hold",
    "check_scene",
    "distance_transform",
    "edge_slides",
    "feature_transform",
    "fits",
    "footprint",
    "front_zone",
    "hang_pose",
    "hanger_back",
    "horizontal_reach",
    "in_sight",
    "label4",
    "largest_component",
    "local_to_world",
    "minimum_filter_box",
    "open_tops",
    "reach_of",
    "reachable_grid",
    "region_spots",
    "rotate",
    "sample_in_region",
    "scan_region",
    "scene_reachable_grid",
    "shades",
    "yaw_facing",
]
