"""USD (usd-core's `pxr`): one Xform prim per body under /World/Objects, at the body's pose, carrying its
objectId, type and states as `luminous:` attributes, with a Mesh child per visual mesh bound to a
UsdPreviewSurface material of its colour; the structure's boxes under /World/Structure. Z up, metres.

`.usda` writes text, `.usd`/`.usdc` the binary crate format."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import numpy as np
import trimesh

from luminous_sim.errors import LuminousError
from luminous_sim.export.meshes import RGBA, box_matrix, box_mesh, object_matrix, visual_parts
from luminous_sim.fileio import atomic_file
from luminous_sim.world.posed import PosedObject, PosedScene

NAMESPACE = "luminous"
"""Prefix of the attributes this exporter adds (`luminous:objectId`, `luminous:type`, `luminous:isOpen`, ...)."""


def _pxr() -> Any:
    try:
        from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade, Vt
    except ImportError as exc:
        raise LuminousError("USD export needs usd-core: pip install 'luminous-sim[export]' "
                            "(or pip install usd-core)") from exc
    return Gf, Sdf, Usd, UsdGeom, UsdShade, Vt


def prim_name(object_id: str) -> str:
    """A valid prim name for an objectId (`Apple|+01.25|+00.90|+04.58` -> `Apple_p01_25_p00_90_p04_58`):
    signs spelt, anything else not a letter, digit or underscore made one; the id itself is an attribute."""
    text = object_id.replace("+", "p").replace("-", "m")
    text = re.sub(r"[^A-Za-z0-9_]", "_", text)
    return text if text[:1].isalpha() or text[:1] == "_" else f"_{text}"


class _Writer:
    def __init__(self) -> None:
        self.Gf, self.Sdf, self.Usd, self.UsdGeom, self.UsdShade, self.Vt = _pxr()
        self.stage = self.Usd.Stage.CreateInMemory()
        self.UsdGeom.SetStageUpAxis(self.stage, self.UsdGeom.Tokens.z)
        self.UsdGeom.SetStageMetersPerUnit(self.stage, 1.0)
        world = self.UsdGeom.Xform.Define(self.stage, "/World")
        self.stage.SetDefaultPrim(world.GetPrim())
        self.stage.DefinePrim("/World/Looks", "Scope")
        self.materials: dict[RGBA, Any] = {}

    def material(self, rgba: RGBA) -> Any:
        if rgba in self.materials:
            return self.materials[rgba]
        path = f"/World/Looks/m{len(self.materials)}"
        material = self.UsdShade.Material.Define(self.stage, path)
        shader = self.UsdShade.Shader.Define(self.stage, f"{path}/surface")
        shader.CreateIdAttr("UsdPreviewSurface")
        vt = self.Sdf.ValueTypeNames
        shader.CreateInput("diffuseColor", vt.Color3f).Set(self.Gf.Vec3f(*rgba[:3]))
        shader.CreateInput("opacity", vt.Float).Set(float(rgba[3]))
        shader.CreateInput("roughness", vt.Float).Set(0.8)
        material.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
        self.materials[rgba] = material
        return material

    def xform(self, path: str, matrix: np.ndarray) -> Any:
        prim = self.UsdGeom.Xform.Define(self.stage, path)
        prim.AddTransformOp().Set(self.Gf.Matrix4d(matrix.T.tolist()))  # USD's matrices are row-vector ones
        return prim

    def mesh(self, path: str, mesh: trimesh.Trimesh, rgba: RGBA) -> Any:
        prim = self.UsdGeom.Mesh.Define(self.stage, path)
        prim.CreatePointsAttr(self.Vt.Vec3fArray.FromNumpy(np.ascontiguousarray(mesh.vertices, dtype=np.float32)))
        prim.CreateFaceVertexCountsAttr(self.Vt.IntArray.FromNumpy(np.full(len(mesh.faces), 3, dtype=np.int32)))
        prim.CreateFaceVertexIndicesAttr(self.Vt.IntArray.FromNumpy(
            np.ascontiguousarray(mesh.faces.reshape(-1), dtype=np.int32)))
        prim.CreateSubdivisionSchemeAttr(self.UsdGeom.Tokens.none)
        prim.CreateDisplayColorAttr([self.Gf.Vec3f(*rgba[:3])])
        lo, hi = mesh.bounds
        prim.CreateExtentAttr([self.Gf.Vec3f(*map(float, lo)), self.Gf.Vec3f(*map(float, hi))])
        self.UsdShade.MaterialBindingAPI.Apply(prim.GetPrim()).Bind(self.material(rgba))
        return prim

    def attributes(self, prim: Any, values: dict[str, Any]) -> None:
        vt = self.Sdf.ValueTypeNames
        for key, value in values.items():
            # Int64: a scene's seed runs to 2**63-1, beyond a 32-bit Int
            kind = vt.Bool if isinstance(value, bool) else vt.Double if isinstance(value, float) \
                else vt.Int64 if isinstance(value, int) else vt.String
            prim.CreateAttribute(f"{NAMESPACE}:{key}", kind, custom=True).Set(value)


def _object_attributes(obj: PosedObject) -> dict[str, Any]:
    values: dict[str, Any] = {"objectId": obj.object_id, "type": obj.object_type, "asset": obj.asset,
                              "fixed": obj.fixed, "mass": float(sum(link.mass for link in obj.links))}
    values.update({k: v for k, v in obj.states.items() if isinstance(v, bool | str | int | float)})
    for joint in obj.joints:
        if joint.kind != "fixed":
            values[f"joint:{joint.name}"] = float(joint.value)
    return values


def write_usd(posed: PosedScene, out: Path, ceiling: bool = True) -> None:
    """Write the posed scene to `out` (.usd/.usdc binary, .usda text), atomically: the stage is built in memory,
    exported to a temporary file beside `out` (of the same suffix, which picks the format) and moved onto it, so
    a reader (or a kill) sees the old file or the new one, never none or a torn one."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    w = _Writer()
    w.attributes(w.stage.GetPrimAtPath("/World"), {"room": posed.room, "seed": posed.seed})
    w.stage.DefinePrim("/World/Structure", "Scope")
    for i, box in enumerate(posed.structure):
        if not box.visible or (not ceiling and box.kind in ("ceiling", "light")):
            continue
        path = f"/World/Structure/{box.kind}_{i}"
        prim = w.xform(path, box_matrix(box))
        w.attributes(prim.GetPrim(), {"name": box.name, "kind": box.kind})
        w.mesh(f"{path}/mesh", box_mesh(box), box.rgba)
    w.stage.DefinePrim("/World/Objects", "Scope")
    used: set[str] = set()
    for obj in posed.objects:
        name = prim_name(obj.object_id)
        while name in used:
            name += "_"
        used.add(name)
        path = f"/World/Objects/{name}"
        prim = w.xform(path, object_matrix(obj))
        w.attributes(prim.GetPrim(), _object_attributes(obj))
        for part in visual_parts(obj):
            w.mesh(f"{path}/{part.name}", part.mesh, part.rgba)
    with atomic_file(out, suffix=f".tmp{out.suffix}") as tmp:  # the suffix picks binary or text
        if not w.stage.GetRootLayer().Export(str(tmp)):
            raise LuminousError(f"{out}: USD could not write the file")
