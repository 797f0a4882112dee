"""The size bounds of a CDF (`limits.MAX_CDF_INSTANCES`, `MAX_CDF_RELATIONS`, `MAX_CDF_STEPS`).

Checked on the plain document before pydantic builds anything (`loader.from_document`), and again on
a built ChallengeDefinition (`validate.check`, for documents made in code), so that no validation,
cross-field check or generation starts on a document larger than the limits. Each problem is one Issue
naming the key path where the limit is crossed (`scene.objects[3].count`).
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from luminous_sim.cdf.issues import Issue
from luminous_sim.limits import MAX_CDF_INSTANCES, MAX_CDF_RELATIONS, MAX_CDF_STEPS

__all__ = ["document_issues", "size_issues"]


def _count(value: Any) -> int:
    """An object's count as the generator would take it: 1 when absent or not an integer (the schema
    refuses those with its own message)."""
    if isinstance(value, int) and not isinstance(value, bool) and value >= 1:
        return value
    return 1


def size_issues(counts: Iterable[Any], relations: int, steps: int) -> list[Issue]:
    """Issues for instance counts (one per declared object), a relation count and a step count over the
    limits; empty when the document is within them."""
    issues: list[Issue] = []
    total = 0
    for i, count in enumerate(counts):
        total += _count(count)
        if total > MAX_CDF_INSTANCES:
            issues.append(Issue(f"scene.objects[{i}].count",
                                f"scene.objects[0..{i}] ask for {total} object instances; a CDF may ask for at "
                                f"most {MAX_CDF_INSTANCES} in all (luminous_sim.limits.MAX_CDF_INSTANCES)"))
            break
    if relations > MAX_CDF_RELATIONS:
        issues.append(Issue(f"scene.relations[{MAX_CDF_RELATIONS}]",
                            f"{relations} relations; a CDF may state at most {MAX_CDF_RELATIONS} "
                            "(luminous_sim.limits.MAX_CDF_RELATIONS)"))
    if steps > MAX_CDF_STEPS:
        issues.append(Issue(f"execution[{MAX_CDF_STEPS}]",
                            f"{steps} execution steps; a CDF may hold at most {MAX_CDF_STEPS} "
                            "(luminous_sim.limits.MAX_CDF_STEPS)"))
    return issues


def _length(value: Any) -> int:
    return len(value) if isinstance(value, (list, tuple)) else 0


def document_issues(doc: Any) -> list[Issue]:
    """`size_issues` of a plain (upgraded, not yet validated) document; parts of the wrong shape count
    as empty (the schema reports them)."""
    if not isinstance(doc, dict):
        return []
    scene = doc.get("scene")
    scene = scene if isinstance(scene, dict) else {}
    objects = scene.get("objects")
    counts = [o.get("count") if isinstance(o, dict) else None for o in objects] \
        if isinstance(objects, (list, tuple)) else []
    return size_issues(counts, _length(scene.get("relations")), _length(doc.get("execution")))
