"""A short human-readable summary of a CDF (what `luminous cdf validate` prints)."""

from __future__ import annotations

from luminous_sim.cdf.graph import resolve_order
from luminous_sim.cdf.predicates import to_sexpr
from luminous_sim.cdf.schema import ChallengeDefinition, HighLevelStep


def summarize(cdf: ChallengeDefinition, limit: int = 80) -> str:
    """One line per aspect: room (or house), objects and relations, task, execution, placement order."""
    scene = cdf.scene
    room = scene.room if isinstance(scene.room, str) else ("constraints" if scene.room else "any")
    instances = sum(o.count for o in scene.objects)
    lines = [
        f"room: {'/'.join(scene.room_type)} ({room}); {len(scene.objects)} objects "
        f"({instances} instances), {len(scene.relations)} relations",
    ]
    if scene.house is not None:
        rooms = ", ".join(f"{r.name} ({r.type})" for r in scene.house.rooms)
        size = (f"{scene.house.size.width:g} x {scene.house.size.depth:g} m" if scene.house.size
                else "size from the rooms")
        lines = [f"house: {len(scene.house.rooms)} rooms: {rooms}; {len(scene.house.adjacency)} doorways asked; {size}"]
        lines += [f"room {r.name}: {len(r.objects)} objects ({sum(o.count for o in r.objects)} instances), "
                  f"{len(r.relations)} relations" for r in scene.house.rooms if r.objects or r.relations]
    if cdf.task is not None:
        goal = to_sexpr(cdf.task.goal)
        goal = goal if len(goal) <= limit else goal[: limit - 3] + "..."
        lines.append(f"task: {cdf.task.type or 'custom'}; goal {goal}")
    if cdf.execution:
        high = sum(isinstance(s, HighLevelStep) for s in cdf.execution)
        lines.append(f"execution: {high} high-level, {len(cdf.execution) - high} low-level steps")
    order = resolve_order(cdf)
    if order:
        lines.append("placement order: " + ", ".join(order))
    return "\n".join(lines)
