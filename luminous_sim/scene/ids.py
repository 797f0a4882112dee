"""AI2-THOR style object ids: `Type|+x.xx|+h.hh|+y.yy` in THOR axes (x, height, depth)."""

from __future__ import annotations


def thor_object_id(object_type: str, position: tuple[float, float, float], taken: set[str]) -> str:
    """The id ALFRED would give an object at `position` (ours: x, y, z up), unique among `taken`.

    THOR's (x, y, z) is our (x, z, y); two decimals, sign always shown, zero padded ("+00.46").
    A clash (two objects at the same rounded spot) gets a `|k` suffix.
    """
    x, y, z = position
    base = f"{object_type}|{x:+06.2f}|{z:+06.2f}|{y:+06.2f}"
    oid, k = base, 1
    while oid in taken:
        k += 1
        oid = f"{base}|{k}"
    taken.add(oid)
    return oid


def type_of_id(object_id: str) -> str:
    """The object type an AI2-THOR/ALFRED id names (its `objectType`).

    `Apple|+00.46|+00.82|+02.27` -> Apple; a slice `Apple|...|AppleSliced_2` -> AppleSliced; a basin
    `Sink|...|SinkBasin` -> SinkBasin (the part after the position names the sub-object); our clash suffix
    `Apple|...|2` -> Apple.
    """
    parts = object_id.split("|")
    last = parts[-1]
    head, _, tail = last.rpartition("_")
    if head.isalpha() and tail.isdigit():
        return head
    if len(parts) == 5 and last.isalpha():
        return last
    return parts[0]
