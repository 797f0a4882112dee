"""Layer L5: agents for the benchmark (the modular reference agent of issue 43, part by part). Its first part is
the instruction parser: a goal directive (and step instructions) to ALFRED's task type and `pddl_params`
(`InstructionParser`, `default_parser` ships trained on ALFRED's train annotations; `train_parser` makes it
again). Torch loads only when a parser is used.

Typical use::

    from luminous_sim.agents import default_parser
    print(default_parser().parse("Put a chilled apple in the microwave.").to_dict())
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from luminous_sim.lazy import lazy_getattr

if TYPE_CHECKING:
    from luminous_sim.agents.annotations import SLOTS, Annotated, AnnotationError, read_annotations
    from luminous_sim.agents.parser import (
        InstructionParser,
        ParsedTask,
        ParserError,
        TrainSettings,
        accuracy,
        default_parser,
        train_parser,
    )

_WHERE = {
    "SLOTS": "annotations", "Annotated": "annotations", "AnnotationError": "annotations",
    "read_annotations": "annotations",
    "InstructionParser": "parser", "ParsedTask": "parser", "ParserError": "parser", "TrainSettings": "parser",
    "accuracy": "parser", "default_parser": "parser", "train_parser": "parser",
}

__all__ = ["SLOTS", "Annotated", "AnnotationError", "InstructionParser", "ParsedTask", "ParserError",
           "TrainSettings", "accuracy", "default_parser", "read_annotations", "train_parser"]

__getattr__ = lazy_getattr(__name__, _WHERE)
