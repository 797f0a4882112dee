"""A generated scene: the room shell and every object with its asset, pose, support and state.

Serialised as deterministic JSON (sorted keys, rounded floats) so that the same CDF, room and seed
give byte-identical files.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from luminous_sim.errors import LuminousError
from luminous_sim.rooms.shell import RoomShell

SCENE_FORMAT: Final = "luminous-scene/1"
Layer = Literal["structure", "fixture", "furniture", "object", "decoration"]


def auto_name(object_type: str, index: int) -> str:
    """The name the generator gives the `index`-th object of a type that the CDF did not ask for."""
    return f"{object_type.lower()}_auto{index}"


def _r(x: float, digits: int = 4) -> float:
    return round(float(x), digits) + 0.0


class SceneObject(BaseModel):
    """One object instance.

    `position` is the asset's base-frame origin in the world (its bottom centre), `yaw` its heading in
    radians about z (the asset's front, +y, turned by yaw). `parent` is the object it rests on or in,
    with the parent's `region`. `states` holds ALFRED-style states (isOpen, isToggled, isDirty, ...).
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    id: str
    type: str
    asset: str
    position: tuple[float, float, float]
    yaw: float = 0.0
    layer: Layer
    fixed: bool = False
    parent: str | None = None
    region: str | None = None
    name: str | None = None
    states: dict[str, bool] = Field(default_factory=dict)
    color_seed: int = 0
    scale: float = 1.0
    color: tuple[float, float, float] | None = None
    """A CDF colour for the object's main material slot (else drawn from the palette by color_seed)."""

    @property
    def cdf_name(self) -> str | None:
        """The instance name the CDF gave it (`mug`, `chair#2`); None when unnamed or named by the generator."""
        prefix = auto_name(self.type, 0).removesuffix("0")
        if self.name is None or (self.name.startswith(prefix) and self.name[len(prefix):].isdigit()):
            return None
        return self.name

    @field_validator("position")
    @classmethod
    def _round_position(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        return (_r(v[0]), _r(v[1]), _r(v[2]))

    @field_validator("yaw")
    @classmethod
    def _round_yaw(cls, v: float) -> float:
        return _r(v, 5)


class Scene(BaseModel):
    """A complete scene: room structure, objects, and how it was made."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    format: Literal["luminous-scene/1"] = SCENE_FORMAT
    room: RoomShell
    seed: int
    generator: str
    objects: tuple[SceneObject, ...]
    source: str = ""
    notes: dict[str, Any] = Field(default_factory=dict)

    def object(self, object_id: str) -> SceneObject:
        for o in self.objects:
            if o.id == object_id:
                return o
        raise KeyError(object_id)

    def of_type(self, object_type: str) -> list[SceneObject]:
        return [o for o in self.objects if o.type == object_type]

    def children(self, parent_id: str) -> list[SceneObject]:
        return [o for o in self.objects if o.parent == parent_id]

    def to_json(self) -> str:
        """Deterministic JSON text."""
        return json.dumps(self.model_dump(mode="json"), indent=1, sort_keys=True) + "\n"

    @classmethod
    def from_json(cls, text: str, where: str = "scene") -> Scene:
        try:
            return cls.model_validate(json.loads(text))
        except (ValueError, ValidationError) as exc:
            raise LuminousError(f"{where}: not a valid scene file ({exc})") from exc

    def save(self, path: Path) -> None:
        from luminous_sim.assets.objio import write_atomic

        write_atomic(Path(path), self.to_json())

    @classmethod
    def load(cls, path: Path) -> Scene:
        path = Path(path)
        if not path.is_file():
            raise LuminousError(f"{path}: no such scene file")
        return cls.from_json(path.read_text(), where=str(path))
