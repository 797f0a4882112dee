"""Layer L5: agents for the benchmark. The modular reference agent (`ModularAgent`; `modular` is its factory for
`luminous eval --policy luminous_sim.agents:modular --track privileged`) is made of swappable parts, one module
each: the instruction parser (`InstructionParser`; `default_parser` ships trained on ALFRED's train
annotations, `train_parser` makes it again), the camera (`Intrinsics`, `unproject`), its own pose (`OwnPose`),
the semantic map (`SemanticMap`), A* over that map (`plan_path`), the search priors (`SearchPriors`) and the
task type's subgoals (`subgoals`). In the rgb track (`modular_rgb`) depth and object types come from RGB
(`Perception`: a small U-Net trained on the simulator's labels by `train_perception`; `default_perception` is
the one `LUMINOUS_PERCEPTION` names) and instances from them (`InstanceTracker`); `PerceptionScores` measures
it. Torch loads only when a parser or a perception network is used.

Typical use::

    from luminous_sim.agents import default_parser
    print(default_parser().parse("Put a chilled apple in the microwave.").to_dict())
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.agents.annotations import SLOTS, Annotated, AnnotationError, read_annotations
    from luminous_sim.agents.camera import FOV_DEGREES, Intrinsics, unproject
    from luminous_sim.agents.instances import InstanceTracker
    from luminous_sim.agents.modular_agent import (
        AgentSettings,
        ModularAgent,
        TrackError,
        modular,
        modular_no_steps,
        modular_rgb,
    )
    from luminous_sim.agents.navigation import plan_path
    from luminous_sim.agents.own_pose import OwnPose
    from luminous_sim.agents.parser import (
        InstructionParser,
        ParsedTask,
        ParserError,
        TrainSettings,
        accuracy,
        default_parser,
        train_parser,
    )
    from luminous_sim.agents.perception import Perception, PerceptionError, default_perception
    from luminous_sim.agents.perception_scores import TASK_NAMED, PerceptionScores
    from luminous_sim.agents.perception_training import PerceptionSettings, train_perception
    from luminous_sim.agents.priors import SearchPriors, default_priors
    from luminous_sim.agents.semantic_map import SemanticMap
    from luminous_sim.agents.subgoals import Subgoal, subgoals

_WHERE = {
    "SLOTS": "annotations", "Annotated": "annotations", "AnnotationError": "annotations",
    "read_annotations": "annotations",
    "InstructionParser": "parser", "ParsedTask": "parser", "ParserError": "parser", "TrainSettings": "parser",
    "accuracy": "parser", "default_parser": "parser", "train_parser": "parser",
    "FOV_DEGREES": "camera", "Intrinsics": "camera", "unproject": "camera",
    "AgentSettings": "modular_agent", "ModularAgent": "modular_agent", "TrackError": "modular_agent",
    "modular": "modular_agent", "modular_no_steps": "modular_agent", "plan_path": "navigation", "OwnPose": "own_pose",
    "SearchPriors": "priors", "default_priors": "priors", "SemanticMap": "semantic_map",
    "Subgoal": "subgoals", "subgoals": "subgoals", "modular_rgb": "modular_agent", "InstanceTracker": "instances",
    "Perception": "perception", "PerceptionError": "perception", "default_perception": "perception",
    "TASK_NAMED": "perception_scores", "PerceptionScores": "perception_scores",
    "PerceptionSettings": "perception_training", "train_perception": "perception_training",
}

__all__ = ["FOV_DEGREES", "SLOTS", "TASK_NAMED", "AgentSettings", "Annotated", "AnnotationError", "InstanceTracker",
           "InstructionParser", "Intrinsics", "ModularAgent", "OwnPose", "ParsedTask", "ParserError", "Perception",
           "PerceptionError", "PerceptionScores", "PerceptionSettings", "SearchPriors", "SemanticMap", "Subgoal",
           "TrackError", "TrainSettings", "accuracy", "default_parser", "default_perception", "default_priors",
           "modular", "modular_no_steps", "modular_rgb", "plan_path", "read_annotations", "subgoals",
           "train_parser", "train_perception", "unproject"]

__getattr__ = lazy_getattr(__name__, _WHERE)
