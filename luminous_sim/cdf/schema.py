"""The CDF document model (current version), validated with pydantic: unknown keys are errors.

Structure (YAML)::

    cdf_version: 2
    name: apple_in_fridge                  # optional
    scene:
      room_type: Kitchen                   # or a list of room types
      room: FloorPlan12                    # a room name, or constraints {shape, min_area, ...}
      objects:   [{name, type, count, asset, layer, attributes, state}]
      relations: [{subject, relation, target, weight, hard}]
    task:                                  # optional
      type: pick_cool_then_place_in_recep  # optional ALFRED task type
      agent: {position: [x, y], rotation: 90, horizon: 30}
      initial: "(isOpen fridge)"           # optional ground literals
      goal: "(and (inReceptacle apple fridge) (isCool apple))"
    execution:                             # optional: high-level and/or low-level steps
      - {action: PickupObject, object: apple}
      - {action: MoveAhead}

Cross-field rules (names, receptacle compatibility, cycles) live in `validate.py`; they run when a
ChallengeDefinition is built, so an invalid one cannot exist.
"""

from __future__ import annotations

import re
from typing import Annotated, Any, ClassVar, Literal, TypeAlias, get_args

from pydantic import (
    AfterValidator,
    AliasChoices,
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Discriminator,
    Field,
    PlainSerializer,
    PlainValidator,
    StrictBool,
    Tag,
    ValidationInfo,
    WithJsonSchema,
    field_serializer,
    model_validator,
)

from luminous_sim.cdf import refs
from luminous_sim.cdf.predicates import Expr, ExprError, expr_from_data, to_sexpr
from luminous_sim.cdf.relations import ALIASES, RELATIONS, canonical, unknown_relation_message
from luminous_sim.errors import VocabularyError
from luminous_sim.limits import MAX_CDF_INSTANCES, MAX_CDF_RELATIONS, MAX_CDF_STEPS
from luminous_sim.vocab import ALFRED_TASK_TYPES, ALL_TYPES, NAVIGATION_ACTIONS, ROOM_TYPES, check_type

CDF_VERSION = 2
"""The version this model describes; older documents are upgraded on load (see upgrade.py)."""

EXPRESSION_MARKER = {"$comment": "cdf-expression"}
"""Placeholder in the generated JSON Schema, replaced by a recursive definition on export."""

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]*$"


def _name(value: str) -> str:
    if not _NAME.fullmatch(value) or len(value) > 64:
        raise ValueError(
            f"invalid name {value!r}; expected a letter then letters, digits or '_' (at most 64)"
        )
    return value


def _object_type(value: str) -> str:
    try:
        return check_type(value)
    except VocabularyError as exc:
        raise ValueError(str(exc)) from None


def _relation(value: Any) -> Any:
    if isinstance(value, str):
        canon = canonical(value)
        if canon is None:
            raise ValueError(unknown_relation_message(value))
        return canon
    return value


_ROOM_TYPE_ALIASES = {t.lower(): t for t in ROOM_TYPES} | {"living_room": "LivingRoom"}


def _room_types(value: Any) -> Any:
    items = [value] if isinstance(value, str) else value
    if isinstance(items, (list, tuple)):
        return [_ROOM_TYPE_ALIASES.get(v.lower(), v) if isinstance(v, str) else v for v in items]
    return value


def _expression(value: Any) -> Expr:
    try:
        return expr_from_data(value)
    except ExprError as exc:
        raise ValueError(str(exc)) from None


Name: TypeAlias = Annotated[
    str,
    PlainValidator(lambda v: _name(_as_str(v))),
    WithJsonSchema({"type": "string", "pattern": NAME_PATTERN}),
]
ObjectType: TypeAlias = Annotated[
    str,
    PlainValidator(lambda v: _object_type(_as_str(v))),
    WithJsonSchema({"type": "string", "enum": list(ALL_TYPES)}),
]
RoomName: TypeAlias = Annotated[
    str,
    PlainValidator(lambda v: refs.check_room(_as_str(v))),
    WithJsonSchema({"type": "string", "pattern": refs.SAFE_REF_PATTERN}),
]
AssetName: TypeAlias = Annotated[
    str,
    PlainValidator(lambda v: refs.check_asset(_as_str(v))),
    WithJsonSchema({"type": "string", "pattern": refs.SAFE_REF_PATTERN}),
]
CanonicalRelation: TypeAlias = Literal[
    "on", "in", "beside", "near", "far", "away_from", "face", "in_front_of", "behind", "left_of", "right_of",
    "aligned_with", "under", "above", "against_wall", "in_corner", "in_centre",
]
"""The canonical relation names, spelled out for the type checker; the same names, in the same order, as
`relations.RELATIONS` (pydantic lists them in that order when it rejects a value)."""
assert get_args(CanonicalRelation) == tuple(RELATIONS)
RelationName: TypeAlias = Annotated[
    CanonicalRelation,
    BeforeValidator(_relation),
    WithJsonSchema({"type": "string", "enum": [*RELATIONS, *ALIASES]}),
]
RoomType: TypeAlias = Literal["Kitchen", "LivingRoom", "Bedroom", "Bathroom"]
assert set(get_args(RoomType)) == set(ROOM_TYPES)
Expression: TypeAlias = Annotated[
    Expr,
    PlainValidator(_expression),
    PlainSerializer(to_sexpr, return_type=str),
    WithJsonSchema(EXPRESSION_MARKER),
]
PositiveFinite: TypeAlias = Annotated[float, Field(gt=0, allow_inf_nan=False)]
Finite: TypeAlias = Annotated[float, Field(allow_inf_nan=False)]
Text: TypeAlias = Annotated[str, Field(min_length=1, max_length=200)]


def _as_str(value: Any) -> str:
    if not isinstance(value, str):
        raise ValueError(f"expected a string, got {type(value).__name__} {value!r:.40}")
    return value


MIN_ROOM_SIDE = 2.0
"""Shortest side (m) a house's room may have: room for the agent, a door and one piece of furniture."""
MIN_ROOM_AREA = 4.0
"""Smallest floor (m^2) a house's room may have."""
MAX_HOUSE_SIDE = 30.0
"""Longest side (m) of a house outline; also the widest room a CDF's room constraints may ask for and the
longest side its `attributes.size` may give an object."""


Side: TypeAlias = Annotated[float, Field(gt=0, le=MAX_HOUSE_SIDE, allow_inf_nan=False)]
Area: TypeAlias = Annotated[float, Field(gt=0, le=MAX_HOUSE_SIDE ** 2, allow_inf_nan=False)]


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=True)


class RoomConstraints(_Model):
    """Room structure by constraints: CSSG picks or builds a room that satisfies them."""

    union_tag: ClassVar[str] = "room-constraints"
    shape: Literal["rect", "L", "two_zone"] | None = None
    min_area: Area | None = Field(None, description="m^2")
    max_area: Area | None = Field(None, description="m^2")
    min_width: Side | None = Field(None, description="m")
    max_width: Side | None = Field(None, description="m")

    @model_validator(mode="after")
    def _ranges(self) -> RoomConstraints:
        for lo, hi in (("min_area", "max_area"), ("min_width", "max_width")):
            a, b = getattr(self, lo), getattr(self, hi)
            if a is not None and b is not None and a > b:
                raise ValueError(f"{lo} ({a}) is larger than {hi} ({b}); expected {lo} <= {hi}")
        return self


def _room_tag(value: Any) -> str:
    return "room-constraints" if isinstance(value, (dict, RoomConstraints)) else "room-name"


RoomSpec: TypeAlias = Annotated[
    Annotated[RoomName, Tag("room-name")] | Annotated[RoomConstraints, Tag("room-constraints")],
    Discriminator(_room_tag),
]


class Dims(_Model):
    """Absolute size in metres."""

    union_tag: ClassVar[str] = "size-dims"
    width: Side
    depth: Side
    height: Side


def _size_tag(value: Any) -> str:
    return "size-dims" if isinstance(value, (dict, Dims)) else "size-scale"


Size: TypeAlias = Annotated[
    Annotated[Annotated[float, Field(gt=0, le=10, allow_inf_nan=False)], Tag("size-scale")] | Annotated[Dims, Tag("size-dims")],  # noqa: E501
    Discriminator(_size_tag),
]


class Attributes(_Model):
    """Appearance (paper, after 3D-SLN): colour, material, size (scale factor or dimensions)."""

    colour: Text | None = Field(None, validation_alias=AliasChoices("colour", "color"))
    material: Text | None = None
    size: Size | None = None


class ObjectStateSpec(_Model):
    """Initial object state (AI2-THOR's metadata names); unset flags are left to the generator."""

    # The docstring is the schema's description. The runtime state is `states.ObjectState`; the JSON
    # Schema keeps the document's name (export keys `$defs` by title).
    model_config = ConfigDict(title="ObjectState")

    isOpen: StrictBool | None = None
    isToggled: StrictBool | None = Field(None, validation_alias=AliasChoices("isToggled", "isOn"))
    isDirty: StrictBool | None = None
    isSliced: StrictBool | None = None
    isHot: StrictBool | None = None
    isCold: StrictBool | None = None
    isFilled: StrictBool | None = None


class ObjectSpec(_Model):
    """A required object: `count` instances of `type`, referred to by `name` elsewhere."""

    name: Name
    type: ObjectType
    count: int = Field(1, ge=1, le=50)
    asset: AssetName | None = None
    layer: Literal["furniture", "object", "decoration"] | None = None
    attributes: Attributes | None = None
    state: ObjectStateSpec | None = None


class Relation(_Model):
    """`subject relation [target]`; a target is a declared name or a room element (wall, ...)."""

    subject: Name
    relation: RelationName
    target: Name | None = None
    weight: PositiveFinite | None = None
    hard: StrictBool = True


_ROOM_TYPE_SCHEMA = {
    "anyOf": [
        {"type": "string", "enum": list(ROOM_TYPES)},
        {"type": "array", "items": {"type": "string", "enum": list(ROOM_TYPES)}, "minItems": 1},
    ]
}


class HouseRoomSpec(_Model):
    """One room of a house: its name (used by `adjacency`), its type, optional floor-area bounds and shape,
    and the objects and relations CSSG must realise in it (as a room CDF's `scene.objects` and
    `scene.relations`; a relation names objects of this room only)."""

    model_config = ConfigDict(title="HouseRoom")

    name: Name
    type: Annotated[RoomType, BeforeValidator(lambda v: _ROOM_TYPE_ALIASES.get(v.lower(), v) if isinstance(v, str)
                                               else v)]
    min_area: Annotated[float, Field(ge=MIN_ROOM_AREA, le=MAX_HOUSE_SIDE ** 2, allow_inf_nan=False)] | None = \
        Field(None, description="m^2")
    max_area: Annotated[float, Field(ge=MIN_ROOM_AREA, le=MAX_HOUSE_SIDE ** 2, allow_inf_nan=False)] | None = \
        Field(None, description="m^2")
    shape: Literal["rect", "L"] | None = Field(
        None, description="rect (default) or L: the room's rectangle loses a corner of the house outline")
    objects: Annotated[tuple[ObjectSpec, ...], Field(max_length=MAX_CDF_INSTANCES)] = ()
    relations: Annotated[tuple[Relation, ...], Field(max_length=MAX_CDF_RELATIONS)] = ()


class HouseSize(_Model):
    """A rectangular house outline, metres along x (`width`) and y (`depth`)."""

    width: Annotated[float, Field(ge=MIN_ROOM_SIDE, le=MAX_HOUSE_SIDE, allow_inf_nan=False)]
    depth: Annotated[float, Field(ge=MIN_ROOM_SIDE, le=MAX_HOUSE_SIDE, allow_inf_nan=False)]


class HouseSpec(_Model):
    """A multi-room house: rooms, the pairs of rooms that must share a door, and optionally the outline.

    The floor-plan generator partitions the outline into the rooms (recursive subdivision); every room is
    reachable through doors; CSSG furnishes each room by its room type's rules. Cross-field checks (names,
    sizes) are in `cdf/house.py`.
    """

    model_config = ConfigDict(title="House")

    rooms: Annotated[tuple[HouseRoomSpec, ...], Field(min_length=2, max_length=12)]
    adjacency: tuple[tuple[Name, Name], ...] = Field(
        (), description="pairs of room names joined by a door (so they share a wall)")
    size: HouseSize | None = Field(None, description="the outline; default: from the rooms' areas")
    front_door: Name | Literal[False] | None = Field(
        None, description="the room whose outside wall holds the front door; default: the first room; false: "
                          "no front door")


def _house_room_types(data: Any) -> Any:
    """A house's room_type defaults to its rooms' types, in order of first appearance."""
    if isinstance(data, dict) and "room_type" not in data and isinstance(data.get("house"), dict):
        rooms = data["house"].get("rooms")
        if isinstance(rooms, (list, tuple)):
            types: list[str] = [r["type"] for r in rooms if isinstance(r, dict) and isinstance(r.get("type"), str)]
            derived = [t for t in dict.fromkeys(_ROOM_TYPE_ALIASES.get(t.lower(), t) for t in types) if t in ROOM_TYPES]
            if derived:
                return {**data, "room_type": derived}
    return data


def _scene_schema(schema: dict[str, Any]) -> None:
    """room_type may be left out when a house is given (it defaults to the house's room types)."""
    schema["required"] = [k for k in schema.get("required", []) if k != "room_type"]
    schema["anyOf"] = [{"required": ["room_type"]}, {"required": ["house"]}]


class SceneSpec(_Model):
    """The indoor-layout section: one room, or a house of several rooms (`house`)."""

    # What a generated `scene.Scene` must satisfy; the JSON Schema keeps the document's name.
    model_config = ConfigDict(title="Scene", json_schema_extra=_scene_schema)

    room_type: Annotated[
        tuple[RoomType, ...],
        BeforeValidator(_room_types),
        Field(min_length=1),
        WithJsonSchema(_ROOM_TYPE_SCHEMA),
    ]
    room: RoomSpec | None = None
    objects: Annotated[tuple[ObjectSpec, ...], Field(max_length=MAX_CDF_INSTANCES)] = ()
    relations: Annotated[tuple[Relation, ...], Field(max_length=MAX_CDF_RELATIONS)] = ()
    house: HouseSpec | None = None

    @model_validator(mode="before")
    @classmethod
    def _derive_room_type(cls, data: Any) -> Any:
        return _house_room_types(data)

    @field_serializer("room_type")
    def _one_room_type(self, value: tuple[str, ...]) -> str | list[str]:
        return value[0] if len(value) == 1 else list(value)


TaskType: TypeAlias = Literal[
    "pick_and_place_simple",
    "pick_two_obj_and_place",
    "look_at_obj_in_light",
    "pick_clean_then_place_in_recep",
    "pick_heat_then_place_in_recep",
    "pick_cool_then_place_in_recep",
    "pick_and_place_with_movable_recep",
]
assert get_args(TaskType) == ALFRED_TASK_TYPES, "TaskType must list vocab's ALFRED_TASK_TYPES in order"


MAX_START_COORDINATE = 25.0
"""Largest |x| or |y| of a start, in metres: every library room lies within 15 m of its origin."""


def _plausible_coordinate(value: float) -> float:
    if abs(value) > MAX_START_COORDINATE:
        raise ValueError(
            f"{value:g} m is outside -{MAX_START_COORDINATE:g}..{MAX_START_COORDINATE:g} m, farther from the "
            "origin than any room extends; expected a start inside the room"
        )
    return value


StartCoordinate: TypeAlias = Annotated[
    float,
    Field(allow_inf_nan=False, json_schema_extra={"minimum": -MAX_START_COORDINATE, "maximum": MAX_START_COORDINATE}),
    AfterValidator(_plausible_coordinate),
]


class AgentPoseSpec(_Model):
    """The agent's start: position (x, y) on the room's floor in metres, yaw in degrees, horizon (+ = down)."""

    # The simulator's pose is `world.agent.AgentPose`; the JSON Schema keeps the document's name.
    # Whether the position lies inside a named room is checked where the room is loaded (rooms is L1).
    model_config = ConfigDict(title="AgentPose")

    position: tuple[StartCoordinate, StartCoordinate] | None = None
    rotation: Literal[0, 90, 180, 270] | None = None
    horizon: Literal[-30, -15, 0, 15, 30, 45, 60] | None = None


class Task(_Model):
    """The task-definition section: initial state and goal as PDDL-like expressions."""

    type: TaskType | None = None
    agent: AgentPoseSpec | None = None
    initial: Expression | None = None
    goal: Expression


HighLevelAction: TypeAlias = Literal[
    "GotoLocation",
    "PickupObject",
    "PutObject",
    "OpenObject",
    "CloseObject",
    "ToggleObject",
    "ToggleObjectOn",
    "ToggleObjectOff",
    "SliceObject",
    "HeatObject",
    "CoolObject",
    "CleanObject",
    "NoOp",
]
LowLevelAction: TypeAlias = Literal[
    "MoveAhead",
    "RotateLeft",
    "RotateRight",
    "LookUp",
    "LookDown",
    "PickupObject",
    "PutObject",
    "OpenObject",
    "CloseObject",
    "ToggleObjectOn",
    "ToggleObjectOff",
    "SliceObject",
]


class HighLevelStep(_Model):
    """A planner-level action on named objects (`GotoLocation fridge`, `PutObject -> fridge`)."""

    union_tag: ClassVar[str] = "high-level"
    action: HighLevelAction
    object: Name | None = None
    receptacle: Name | None = None

    @model_validator(mode="after")
    def _arguments(self) -> HighLevelStep:
        if self.action == "NoOp":
            wanted = (False, False)
        elif self.action == "PutObject":
            wanted = (self.object is not None, True)
        else:
            wanted = (True, False)
        for key, need in zip(("object", "receptacle"), wanted):
            have = getattr(self, key) is not None
            if need and not have:
                raise ValueError(f"{self.action} needs '{key}'")
            if have and not need:
                raise ValueError(f"{self.action} takes no '{key}'")
        return self


class LowLevelStep(_Model):
    """An ALFRED low-level action; `objectId`/`receptacleObjectId` name declared objects."""

    union_tag: ClassVar[str] = "low-level"
    action: LowLevelAction
    objectId: Name | None = None
    receptacleObjectId: Name | None = None

    @model_validator(mode="after")
    def _arguments(self) -> LowLevelStep:
        if self.action in NAVIGATION_ACTIONS:
            if self.objectId is not None or self.receptacleObjectId is not None:
                raise ValueError(f"{self.action} takes no objectId or receptacleObjectId")
        elif self.action == "PutObject":
            if self.receptacleObjectId is None:
                raise ValueError("PutObject needs 'receptacleObjectId'")
        elif self.objectId is None:
            raise ValueError(f"{self.action} needs 'objectId'")
        elif self.receptacleObjectId is not None:
            raise ValueError(f"{self.action} takes no 'receptacleObjectId'")
        return self


def _step_tag(value: Any) -> str:
    if isinstance(value, LowLevelStep):
        return "low-level"
    if isinstance(value, dict) and (
        "objectId" in value or "receptacleObjectId" in value or value.get("action") in NAVIGATION_ACTIONS
    ):
        return "low-level"
    return "high-level"


Step: TypeAlias = Annotated[
    Annotated[HighLevelStep, Tag("high-level")] | Annotated[LowLevelStep, Tag("low-level")],
    Discriminator(_step_tag),
]


class ChallengeDefinition(_Model):
    """A validated CDF document (current version).

    Building one runs the cross-field checks of `validate.py` and raises CDFValidationError on a
    problem; pass `context={"source": "file.yaml"}` to `model_validate` to name the file.
    """

    cdf_version: Literal[2]
    name: Text | None = None
    description: Annotated[str, Field(max_length=10_000)] | None = None
    scene: SceneSpec
    task: Task | None = None
    execution: Annotated[tuple[Step, ...], Field(max_length=MAX_CDF_STEPS)] | None = None

    @model_validator(mode="after")
    def _consistent(self, info: ValidationInfo) -> ChallengeDefinition:
        from luminous_sim.cdf.validate import raise_for_issues

        context = info.context if isinstance(info.context, dict) else {}
        raise_for_issues(self, str(context.get("source", "<cdf>")), str(context.get("note", "")))
        return self

    def object_named(self, name: str) -> ObjectSpec | None:
        """The declared object called `name`, if any (in `scene.objects`, or in a house's rooms)."""
        for obj in self.all_objects():
            if obj.name == name:
                return obj
        return None

    def all_objects(self) -> tuple[ObjectSpec, ...]:
        """Every declared object: `scene.objects`, then each house room's, in order."""
        house = self.scene.house
        rooms = house.rooms if house is not None else ()
        return self.scene.objects + tuple(o for r in rooms for o in r.objects)
