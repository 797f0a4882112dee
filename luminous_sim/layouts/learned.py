"""The learned generator behind the one interface: an ATISS-like model (`atiss_net`) furnishes a room given
its outline, doors and fixtures; `train_layouts` trains one on CSSG's layouts (`trainset`).

torch is needed only here, and only when a model is trained or first used (`pip install .[learn]`).
"""

from __future__ import annotations

import hashlib
import io
import time
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from luminous_sim.assets.catalog import Catalog, default_catalog
from luminous_sim.errors import LuminousError
from luminous_sim.layouts import trainset
from luminous_sim.layouts.convert import layout_of_scene, room_of_shell
from luminous_sim.layouts.inputs import read_bytes
from luminous_sim.layouts.model import Layout, LayoutError, LayoutObject, Provenance
from luminous_sim.rooms.shell import RoomShell
from luminous_sim.vocab import ROOM_TYPES

MODEL_FILE = "learned_layouts.pt"
"""The trained model shipped in `layouts/data/` (`luminous train-layouts` with its defaults remakes it)."""
_LOADED: dict[str, Any] = {}


def default_model_path() -> Path:
    return Path(str(resources.files("luminous_sim.layouts").joinpath("data", MODEL_FILE)))


def _torch():
    try:
        import torch
    except ImportError:
        raise LuminousError("the learned layout generator needs torch: pip install 'luminous-sim[learn]'") from None
    return torch


def load_model(path: Path | None = None) -> dict:
    """A checkpoint (loaded once per file): its `net` (in eval mode), vocabulary, room-type masks and info."""
    path = Path(path or default_model_path())
    key = str(path.resolve())
    if key not in _LOADED:
        torch = _torch()
        if not path.exists():
            raise LayoutError(f"{path}: no such model file (train one with `luminous train-layouts --out {path}`)")
        raw = read_bytes(path, "a layout model checkpoint (.pt)")  # names a folder, a device or a FIFO
        try:
            data = torch.load(io.BytesIO(raw), weights_only=True)
        except Exception as exc:  # torch raises many kinds for a file that is not its checkpoint
            raise LayoutError(f"{path}: not a layout model checkpoint ({type(exc).__name__})") from None
        if not isinstance(data, dict) or data.get("format") != "luminous-layout-model/1":
            raise LayoutError(f"{path}: format: expected 'luminous-layout-model/1'")
        from luminous_sim.layouts.atiss_net import from_checkpoint

        data["net"] = from_checkpoint(data)
        data["sha256"] = hashlib.sha256(raw).hexdigest()[:16]
        _LOADED[key] = data
    return _LOADED[key]


@dataclass
class LearnedLayouts:
    """Furniture by the learned model (default: the shipped one), around the room's fixtures as CSSG's
    structure layer lays them. It predicts categories and boxes only; `realize` matches them to assets,
    repairs overlaps and adds the small objects."""

    model: Path | None = None
    catalog: Catalog | None = None
    name: str = "learned"
    _data: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def layout(self, shell: RoomShell, seed: int) -> Layout:
        from luminous_sim.cssg import structure_scene
        from luminous_sim.layouts.atiss_net import sample

        data = self._data or load_model(self.model)
        self._data = data
        catalog = self.catalog or default_catalog()
        fixtures = list(layout_of_scene(structure_scene(shell, seed, catalog), catalog).objects)
        frame = trainset.RoomFrame.of(shell.outline)
        raster, extent = trainset.room_view(shell, [trainset.box_polygon(o) for o in fixtures
                                                    if trainset.is_fixture(o)], frame)
        vocab: list[str] = data["vocab"]
        allowed = np.array([c in data["allowed"].get(shell.room_type, []) for c in vocab])
        drawn = sample(data["net"], raster, ROOM_TYPES.index(shell.room_type), extent, allowed,
                       _inside(shell, frame), seed)
        objects = list(fixtures)
        for k, d in enumerate(drawn):
            x, y = frame.to_world(*d.centre)
            objects.append(LayoutObject(id=f"learned_{k}", category=vocab[d.category], size=d.size,
                                        position=(round(x, 4), round(y, 4), round(d.size[2] / 2, 4)),
                                        yaw=round(d.yaw, 6), layer="furniture"))
        return Layout(room=room_of_shell(shell), objects=tuple(objects),
                      provenance=Provenance(generator=self.name, seed=seed, source=shell.name,
                                            notes={"model": data["sha256"], "furniture": len(drawn)}))


def _inside(shell: RoomShell, frame) -> np.ndarray:
    """[y, x] over the centre bins: whether the bin's centre lies on the floor."""
    import shapely

    c = np.array([trainset.pos_value(k) for k in range(trainset.POS_BINS)])
    u, v = np.meshgrid(c, c)
    return np.asarray(shapely.contains_xy(shell.polygon(), frame.cx + u * frame.half, frame.cy + v * frame.half))


@dataclass(frozen=True)
class TrainResult:
    path: Path
    layouts: int
    examples: int
    losses: list[float]
    seconds: float


def train_layouts(out: Path, per_type: int = 80, epochs: int = 16, seed: int = 0, augment: bool = True,
                  progress=None) -> TrainResult:
    """Train a model on CSSG's layouts in `per_type` rooms of each type (`trainset.cssg_layouts`) and write its
    checkpoint to `out` atomically. The same arguments give the same model."""
    torch = _torch()
    from luminous_sim.fileio import write_atomic
    from luminous_sim.layouts.atiss_net import NetConfig, TrainConfig, checkpoint, train

    t0 = time.perf_counter()
    pairs = trainset.cssg_layouts(per_type)
    if not pairs:
        raise LuminousError("no training layouts: CSSG found no valid layout in any training room")
    vocab = sorted({o.category for lay, _ in pairs for o in lay.objects if trainset.is_furniture(o)})
    allowed = {rt: sorted({o.category for lay, sh in pairs if sh.room_type == rt for o in lay.objects
                           if trainset.is_furniture(o)}) for rt in ROOM_TYPES}
    examples = [e for lay, sh in pairs for e in trainset.examples_of(lay, sh, vocab, augment)]
    net, losses = train(examples, NetConfig(len(vocab)), TrainConfig(epochs=epochs, seed=seed), progress)
    thor = sum(sh.name.startswith("FloorPlan") for _, sh in pairs)
    info = {"data": f"CSSG layouts (empty CDF per room type) in {len(pairs) - thor} procedural shells and "
                    f"{thor} AI2-THOR FloorPlan shells (seen scenes); furniture from CSSG, fixtures and walls "
                    "from the rooms", "per_type": per_type, "layouts": len(pairs), "examples": len(examples),
            "augment": augment, "epochs": epochs, "seed": seed, "losses": [round(x, 4) for x in losses]}
    buf = io.BytesIO()
    torch.save(checkpoint(net, vocab, allowed, info), buf)
    out = Path(out)
    write_atomic(out, buf.getvalue())
    _LOADED.pop(str(out.resolve()), None)
    return TrainResult(out, len(pairs), len(examples), losses, time.perf_counter() - t0)

