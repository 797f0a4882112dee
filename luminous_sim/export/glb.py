"""glTF binary (.glb) with trimesh: one node per body, named by its objectId, at the body's pose, holding its
visual meshes with their material colours (a PBR base colour each); the structure under a `structure` node."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh
from trimesh.visual.material import PBRMaterial

from luminous_sim.export.meshes import RGBA, box_matrix, box_mesh, object_matrix, visual_parts
from luminous_sim.world.posed import PosedScene

ROOT = "scene"
"""The root node: it turns the world's z-up frame into glTF's y-up one (x stays, z becomes y, y becomes -z),
so that a viewer shows the floor down; everything else hangs under it in the world's own coordinates."""
Z_UP_TO_Y_UP = np.array([[1.0, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, 0], [0, 0, 0, 1]])
STRUCTURE = "structure"
"""The node the floor, walls and ceiling hang under (their own nodes: `floor#0`, `wall#3`, `ceiling#0`)."""


def coloured_mesh(mesh: trimesh.Trimesh, rgba: RGBA, name: str) -> trimesh.Trimesh:
    colour = [round(255 * min(max(c, 0.0), 1.0)) for c in rgba]
    material = PBRMaterial(name=name, baseColorFactor=colour, metallicFactor=0.0, roughnessFactor=0.8,
                           alphaMode="BLEND" if rgba[3] < 1.0 else "OPAQUE", doubleSided=True)
    out = trimesh.Trimesh(mesh.vertices, mesh.faces, process=False)
    out.visual = trimesh.visual.TextureVisuals(material=material)
    return out


def material_name(rgba: RGBA) -> str:
    return "rgba_" + "_".join(f"{c:.3f}" for c in rgba)


def glb_scene(posed: PosedScene, ceiling: bool = True) -> trimesh.Scene:
    """The posed scene as a trimesh scene (what `write_glb` writes)."""
    scene = trimesh.Scene()
    scene.graph.update(frame_from=scene.graph.base_frame, frame_to=ROOT, matrix=Z_UP_TO_Y_UP)
    scene.graph.update(frame_from=ROOT, frame_to=STRUCTURE, matrix=np.eye(4))
    for box in posed.structure:
        if not box.visible or (not ceiling and box.kind in ("ceiling", "light")):
            continue
        scene.add_geometry(coloured_mesh(box_mesh(box), box.rgba, material_name(box.rgba)), node_name=box.name,
                           geom_name=box.name, parent_node_name=STRUCTURE, transform=box_matrix(box))
    for obj in posed.objects:
        scene.graph.update(frame_from=ROOT, frame_to=obj.object_id, matrix=object_matrix(obj))
        for part in visual_parts(obj):
            name = f"{obj.object_id}/{part.name}"
            scene.add_geometry(coloured_mesh(part.mesh, part.rgba, material_name(part.rgba)), node_name=name,
                               geom_name=name, parent_node_name=obj.object_id)
    return scene


def write_glb(posed: PosedScene, out: Path, ceiling: bool = True) -> None:
    """Write the posed scene to `out` as binary glTF (metres; y up, as glTF wants, by the root node `scene`)."""
    from luminous_sim.fileio import write_atomic

    data = glb_scene(posed, ceiling).export(file_type="glb")
    write_atomic(Path(out), bytes(data))
