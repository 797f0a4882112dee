"""A generated scene: the room shell and every object with its asset, pose, support and state.

Serialised as deterministic JSON (sorted keys, rounded floats) so that the same CDF, room and seed
give byte-identical files.
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any, Final, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from luminous_sim.errors import LuminousError, mode_kind
from luminous_sim.limits import MAX_INPUT_BYTES
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
        """A scene from its JSON text.

        Raises:
            LuminousError: one line naming `where`, not JSON, or the first fields that are wrong.
        """
        try:
            data = json.loads(text)
        except RecursionError:
            raise LuminousError(f"{where}: not a valid scene file (nested too deeply)") from None
        except ValueError as exc:
            raise LuminousError(f"{where}: not a valid scene file (not JSON: {exc})") from None
        if not isinstance(data, dict):
            raise LuminousError(f"{where}: not a valid scene file (expected a JSON object, got {type(data).__name__})")
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            errors = exc.errors(include_url=False)
            shown = "; ".join(f"{_path(e['loc'])}: {e['msg']}" for e in errors[:3])
            more = f" (and {len(errors) - 3} more)" if len(errors) > 3 else ""
            raise LuminousError(f"{where}: not a valid scene file ({shown}{more})") from None
        except ValueError as exc:
            raise LuminousError(f"{where}: not a valid scene file ({' '.join(str(exc).split())})") from None

    def save(self, path: Path) -> None:
        from luminous_sim.assets.objio import write_atomic

        write_atomic(Path(path), self.to_json())

    @classmethod
    def load(cls, path: Path) -> Scene:
        """A scene file (`scene.json`): a regular file within `limits.MAX_INPUT_BYTES`.

        Raises:
            LuminousError: one line naming the file: missing, a folder, a device or a FIFO, too large, not UTF-8,
                or not a valid scene.
        """
        path = Path(path)
        try:
            mode = os.stat(path).st_mode
        except OSError as exc:
            raise LuminousError(f"{path}: cannot read ({exc.strerror or exc}); expected a scene file (scene.json)"
                                ) from None
        if not stat.S_ISREG(mode):
            raise LuminousError(f"{path}: {mode_kind(mode)}; expected a scene file (scene.json)")
        try:
            with open(path, "rb") as fh:
                raw = fh.read(MAX_INPUT_BYTES + 1)
        except OSError as exc:
            raise LuminousError(f"{path}: cannot read ({exc.strerror or exc})") from None
        if len(raw) > MAX_INPUT_BYTES:
            raise LuminousError(f"{path}: more than {MAX_INPUT_BYTES} bytes; a scene file may hold at most "
                                f"{MAX_INPUT_BYTES} (luminous_sim.limits.MAX_INPUT_BYTES)")
        try:
            text = raw.decode("utf-8")
        except UnicodeDecodeError as exc:
            raise LuminousError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
        return cls.from_json(text, where=str(path))


def _path(loc: tuple[Any, ...]) -> str:
    return "".join(f"[{p}]" if isinstance(p, int) else f".{p}" for p in loc).lstrip(".") or "(top level)"
