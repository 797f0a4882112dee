"""ALFRED's human annotations carried into a trial that re-solves their design (method (b)).

A design's people wrote a goal directive and one step instruction per subgoal of ALFRED's expert. The
re-solved trial keeps every annotation as ALFRED has it (`assignment_id`, `votes`, `task_desc`,
`high_descs`) when our expert's subgoals are ALFRED's, one for one. Where they differ (a sliced object: ALFRED's
expert puts the knife down at once, ours carries it on), the steps would describe another plan, so the
annotation keeps its human directive and takes the templates' steps for our plan; the sidecar says which.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

HUMAN = "human"
TEMPLATES = "templates"


@dataclass(frozen=True)
class HumanLanguage:
    """A design's human annotations and the subgoals of ALFRED's expert they describe."""

    annotations: tuple[Mapping[str, Any], ...]
    """`turk_annotations.anns` of the design's traj_data.json, as they are (each with `task_desc` and
    `high_descs` checked to be text)."""
    plan: tuple[str, ...]
    """ALFRED's subgoals (`plan.high_pddl[].discrete_action.action`), its closing NoOp left out."""


def trial_annotations(human: HumanLanguage, ours: Sequence[str],
                      templates: Sequence[Mapping[str, Any]]) -> list[dict[str, Any]]:
    """The trial's `turk_annotations.anns`. `ours`: the trial's subgoals (NoOp left out); `templates`: its
    template annotations (the first one's steps stand in where ALFRED's plan is not ours)."""
    same_plan = tuple(ours) == human.plan
    return [{**ann, "high_descs": list(ann["high_descs"] if same_plan and len(ann["high_descs"]) == len(ours)
                                      else templates[0]["high_descs"])} for ann in human.annotations]


def language_note(human: HumanLanguage, anns: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    """The sidecar's account of a trial's annotations `anns` (`trial_annotations`): per annotation, whether
    its steps are its people's (`HUMAN`) or the templates' (`TEMPLATES`)."""
    steps = [HUMAN if list(a["high_descs"]) == list(h["high_descs"]) else TEMPLATES
             for a, h in zip(anns, human.annotations, strict=True)]
    return {"annotations": "the ALFRED design's own (turk_annotations as ALFRED has them)", "high_descs": steps,
            "alfred_plan": list(human.plan),
            "why_templates": "where ALFRED's expert's subgoals are not ours, the steps are the templates' for our "
                             "plan and the directive stays the annotator's"}
