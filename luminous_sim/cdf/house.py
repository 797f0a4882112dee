"""Cross-field checks of a CDF's house (`scene.house`): room names, adjacency, sizes that cannot fit, the
front door's room, and each room's objects and relations.

A room's `objects` and `relations` are checked by the room CDF's own checks (`validate.check` on a room CDF
holding that section), their key paths moved under `scene.house.rooms[i]`; on top, an object name is unique
across the house and a relation names objects of its own room only. Each problem is an Issue with the key
path of the offending value; `validate.check` runs these.
"""

from __future__ import annotations

import difflib
from typing import TYPE_CHECKING

from luminous_sim.cdf.issues import Issue
from luminous_sim.cdf.schema import MIN_ROOM_AREA

if TYPE_CHECKING:
    from luminous_sim.cdf.schema import ChallengeDefinition, HouseRoomSpec, HouseSpec, ObjectSpec

__all__ = ["check_house", "house_names", "room_cdf"]


def check_house(cdf: ChallengeDefinition) -> list[Issue]:
    """Every problem of `cdf.scene.house` (none when there is no house)."""
    house = cdf.scene.house
    if house is None:
        return []
    issues = _beside_house(cdf)
    names = _room_names(house, issues)
    issues += _adjacency(house, names)
    issues += _sizes(house)
    issues += _front_door(house, names)
    issues += _room_sections(house)
    types = set(cdf.scene.room_type)
    for i, room in enumerate(house.rooms):
        if room.type not in types:
            issues.append(Issue(f"scene.house.rooms[{i}].type",
                                f"{room.type} is not among scene.room_type ({', '.join(cdf.scene.room_type)}); "
                                "expected the house's room types there, or no scene.room_type"))
    return issues


def house_names(cdf: ChallengeDefinition) -> dict[str, ObjectSpec]:
    """Every object a house's rooms declare, by name (the first of a repeated name); empty without a house."""
    out: dict[str, ObjectSpec] = {}
    for room in cdf.scene.house.rooms if cdf.scene.house is not None else ():
        for obj in room.objects:
            out.setdefault(obj.name, obj)
    return out


def room_cdf(room: HouseRoomSpec) -> ChallengeDefinition:
    """A room CDF holding one house room's section (its type, objects and relations), not validated again."""
    from luminous_sim.cdf.schema import ChallengeDefinition, SceneSpec

    scene = SceneSpec.model_construct(room_type=(room.type,), room=None, objects=room.objects,
                                      relations=room.relations, house=None)
    return ChallengeDefinition.model_construct(cdf_version=2, name=room.name, description=None, scene=scene,
                                               task=None, execution=None)


def _beside_house(cdf: ChallengeDefinition) -> list[Issue]:
    """What a house CDF may not hold: a single room, objects or relations outside its rooms."""
    issues = []
    if cdf.scene.room is not None:
        issues.append(Issue("scene.room", "a house draws its own rooms; expected no scene.room beside scene.house"))
    for key in ("objects", "relations"):
        if getattr(cdf.scene, key):
            issues.append(Issue(f"scene.{key}", f"a house's objects and relations belong to its rooms; expected "
                                f"scene.house.rooms[i].{key} instead of scene.{key} beside scene.house"))
    return issues


def _front_door(house: HouseSpec, names: list[str]) -> list[Issue]:
    if house.front_door is None or house.front_door is False or house.front_door in names:
        return []
    hint = difflib.get_close_matches(house.front_door, names, n=1)
    extra = f"; did you mean {hint[0]!r}?" if hint else ""
    return [Issue("scene.house.front_door", f"unknown room {house.front_door!r}{extra} (expected a name in "
                  f"scene.house.rooms: {', '.join(names)})")]


def _room_sections(house: HouseSpec) -> list[Issue]:
    """Each room's objects and relations: names unique across the house, relations within their room, and
    the room CDF's own checks (paths moved under the room)."""
    from luminous_sim.cdf.relations import STRUCTURE_ELEMENTS
    from luminous_sim.cdf.validate import check

    issues: list[Issue] = []
    owner: dict[str, tuple[int, str]] = {}
    for i, room in enumerate(house.rooms):
        for j, obj in enumerate(room.objects):
            if obj.name in owner and owner[obj.name][0] != i:
                k, other = owner[obj.name]
                issues.append(Issue(f"scene.house.rooms[{i}].objects[{j}].name",
                                    f"{obj.name!r} is already an object of room {other!r} (scene.house.rooms[{k}]); "
                                    "expected object names unique across the house"))
            owner.setdefault(obj.name, (i, room.name))
    for i, room in enumerate(house.rooms):
        if not room.objects and not room.relations:
            continue
        here = f"scene.house.rooms[{i}]"
        mine = {o.name for o in room.objects}
        elsewhere: set[int] = set()
        for j, rel in enumerate(room.relations):
            for key in ("subject", "target"):
                name = getattr(rel, key)
                if name is None or name in mine or name in STRUCTURE_ELEMENTS or name not in owner:
                    continue
                elsewhere.add(j)
                k, other = owner[name]
                issues.append(Issue(f"{here}.relations[{j}].{key}",
                                    f"{name!r} is an object of room {other!r} (scene.house.rooms[{k}]), not of room "
                                    f"{room.name!r}; a relation holds within one room (expected an object of "
                                    f"{here}.objects{' or a room element' if key == 'target' else ''})"))
        for issue in check(room_cdf(room)):
            path = here + issue.path.removeprefix("scene")
            if any(issue.path.startswith(f"scene.relations[{j}]") for j in elsewhere):
                continue
            message = issue.message.replace("scene.objects", f"{here}.objects (room {room.name!r})")
            issues.append(Issue(path, message))
    return issues


def _room_names(house: HouseSpec, issues: list[Issue]) -> list[str]:
    first: dict[str, int] = {}
    for i, room in enumerate(house.rooms):
        if room.name in first:
            issues.append(Issue(f"scene.house.rooms[{i}].name",
                                f"duplicate room name {room.name!r} (first at scene.house.rooms[{first[room.name]}]); "
                                "expected unique names"))
        first.setdefault(room.name, i)
    return list(first)


def _adjacency(house: HouseSpec, names: list[str]) -> list[Issue]:
    issues = []
    seen: dict[frozenset[str], int] = {}
    for j, pair in enumerate(house.adjacency):
        bad = False
        for k, name in enumerate(pair):
            if name not in names:
                hint = difflib.get_close_matches(name, names, n=1)
                extra = f"; did you mean {hint[0]!r}?" if hint else ""
                issues.append(Issue(f"scene.house.adjacency[{j}][{k}]",
                                    f"unknown room {name!r}{extra} (expected a name in scene.house.rooms: "
                                    f"{', '.join(names)})"))
                bad = True
        if bad:
            continue
        if pair[0] == pair[1]:
            issues.append(Issue(f"scene.house.adjacency[{j}]",
                                f"room {pair[0]!r} is paired with itself; expected two different rooms"))
            continue
        key = frozenset(pair)
        if key in seen:
            issues.append(Issue(f"scene.house.adjacency[{j}]",
                                f"{pair[0]!r}-{pair[1]!r} is already listed at scene.house.adjacency[{seen[key]}]"))
        seen.setdefault(key, j)
    return issues


def _sizes(house: HouseSpec) -> list[Issue]:
    issues = []
    for i, room in enumerate(house.rooms):
        if room.min_area is not None and room.max_area is not None and room.min_area > room.max_area:
            issues.append(Issue(f"scene.house.rooms[{i}].min_area",
                                f"min_area ({room.min_area:g}) is larger than max_area ({room.max_area:g}); "
                                "expected min_area <= max_area"))
    if house.size is None:
        return issues
    area = house.size.width * house.size.depth
    least = sum(r.min_area if r.min_area is not None else MIN_ROOM_AREA for r in house.rooms)
    if least > area + 1e-9:
        issues.append(Issue("scene.house.size",
                            f"the rooms need at least {least:g} m^2 (their min_area, else {MIN_ROOM_AREA:g} m^2 "
                            f"each) but the house is {house.size.width:g} x {house.size.depth:g} = {area:g} m^2; "
                            "expected a larger house or smaller rooms"))
    if all(r.max_area is not None for r in house.rooms):
        most = sum(r.max_area or 0.0 for r in house.rooms)
        if most < area - 1e-9:
            issues.append(Issue("scene.house.size",
                                f"the rooms cover at most {most:g} m^2 (their max_area) but the house is {area:g} "
                                "m^2 and its rooms fill it; expected a smaller house or a larger max_area"))
    return issues
