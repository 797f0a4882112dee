"""The learned layout model (torch; imported only where it is trained or used): ATISS's idea at a small size.

A room is encoded from its image (a small CNN over floor, door clearances, fixtures and the furniture
placed so far: the top-down view Deep Priors draws), its type and extent; the furniture placed so far is
also an unordered set of tokens (no positions in the sequence, so the order they came in does not matter);
a transformer over the room token, a query token and the set gives the query's state, from which the next
object is read attribute by attribute: category (or the end), width, depth, height, centre (one of the
image's cells, scored from the CNN's per-cell features against the state), yaw; each a distribution over
bins conditioned on the attributes chosen before it.

Training follows ATISS: each step takes a room's furniture in a fresh random order, keeps a random number
of them as the set placed so far and teaches the next one (or the end, when all are kept).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass

import numpy as np
import torch
from torch import nn

from luminous_sim.layouts.trainset import (
    POS_BINS,
    RASTER,
    SIZE_BINS,
    SUB,
    YAW_BINS,
    Example,
    occupancy,
    pos_value,
    size_value,
)
from luminous_sim.vocab import ROOM_TYPES

ATTRIBUTES = ("w", "d", "h", "x", "y", "yaw")
ATTRIBUTE_BINS = (SIZE_BINS, SIZE_BINS, SIZE_BINS, POS_BINS, POS_BINS, YAW_BINS)
HEADS = ("w", "d", "h", "yaw")
"""Attributes read by a head of their own; the centre (x, y) is scored per cell (`centre_logits`)."""
SPATIAL = 32
"""channels of the per-cell features the centre is scored from."""
MAX_OBJECTS = 24


@dataclass(frozen=True)
class NetConfig:
    categories: int
    width: int = 64
    layers: int = 2
    heads: int = 4


class LayoutNet(nn.Module):
    """Room + set of placed objects -> distributions of the next object's attributes."""

    def __init__(self, cfg: NetConfig):
        super().__init__()
        self.cfg = cfg
        w = cfg.width
        self.c1 = nn.Conv2d(4, 16, 3, padding=1)
        self.c2 = nn.Conv2d(16, 32, 3, stride=2, padding=1)
        self.c3 = nn.Conv2d(32, 64, 3, stride=2, padding=1)
        self.c4 = nn.Conv2d(64, 64, 3, stride=2, padding=1)
        self.pool = nn.Linear(64 * (RASTER // 8) ** 2, w)
        self.lateral = nn.ModuleList(nn.Conv2d(c, SPATIAL, 1) for c in (16, 32, 64))
        self.cell_bias = nn.Conv2d(SPATIAL, 1, 1)
        self.cell_query = nn.Linear(w, SPATIAL)
        self.cell_feature = nn.Linear(SPATIAL, w)
        self.sub_head = nn.Sequential(nn.Linear(w, w), nn.ReLU(), nn.Linear(w, SUB * SUB))
        self.room_type = nn.Embedding(len(ROOM_TYPES), w)
        self.extent = nn.Linear(3, w)
        self.query = nn.Parameter(torch.zeros(1, 1, w))
        self.category = nn.Embedding(cfg.categories, w)
        self.attr_emb = nn.ModuleList(nn.Embedding(n, w) for n in ATTRIBUTE_BINS)
        layer = nn.TransformerEncoderLayer(w, cfg.heads, 2 * w, dropout=0.0, batch_first=True)
        self.encoder = nn.TransformerEncoder(layer, cfg.layers, enable_nested_tensor=False)
        self.category_head = nn.Linear(w, cfg.categories + 1)  # the last class is the end
        self.attr_heads = nn.ModuleDict({a: nn.Sequential(nn.Linear(w, w), nn.ReLU(), nn.Linear(w, n))
                                         for a, n in zip(ATTRIBUTES, ATTRIBUTE_BINS, strict=True) if a in HEADS})

    @property
    def end(self) -> int:
        return self.cfg.categories

    def encode(self, raster: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """The room image (B, 4, R, R) -> a global feature (B, W) and per-cell features (B, SPATIAL, R, R)."""
        relu = nn.functional.relu
        f1 = relu(self.c1(raster))
        f2 = relu(self.c2(f1))
        f3 = relu(self.c3(f2))
        f4 = relu(self.c4(f3))
        cells = self.lateral[0](f1)
        for lat, f in ((self.lateral[1], f2), (self.lateral[2], f3)):
            cells = cells + nn.functional.interpolate(lat(f), size=(RASTER, RASTER), mode="nearest")
        return self.pool(f4.flatten(1)), relu(cells)

    def state(self, raster: torch.Tensor, room_type: torch.Tensor, extent: torch.Tensor, objects: torch.Tensor,
              mask: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """The query's state (B, W) and the per-cell features, given rooms (images with the furniture placed so
        far) and those pieces as `objects` (B, N, 7) bin rows, `mask` (B, N) True where a row is padding."""
        glob, cells = self.encode(raster)
        room = glob + self.room_type(room_type) + self.extent(extent)
        tokens = self.category(objects[..., 0].clamp(min=0))
        for i, emb in enumerate(self.attr_emb):
            tokens = tokens + emb(objects[..., i + 1].clamp(min=0))
        b = raster.shape[0]
        seq = torch.cat([room[:, None], self.query.expand(b, 1, -1), tokens], dim=1)
        pad = torch.cat([torch.zeros(b, 2, dtype=torch.bool), mask], dim=1)
        return self.encoder(seq, src_key_padding_mask=pad)[:, 1], cells

    def _context(self, state: torch.Tensor, category: torch.Tensor, chosen: Sequence[torch.Tensor]) -> torch.Tensor:
        c = state + self.category(category)
        for i, value in enumerate(chosen):
            c = c + self.attr_emb[i](value)
        return c

    def attribute_logits(self, state: torch.Tensor, category: torch.Tensor,
                         chosen: Sequence[torch.Tensor]) -> torch.Tensor:
        """Logits of attribute number len(chosen) (not x or y) given the category and those before it."""
        return self.attr_heads[ATTRIBUTES[len(chosen)]](self._context(state, category, chosen))

    def centre_logits(self, state: torch.Tensor, cells: torch.Tensor, category: torch.Tensor,
                      size: Sequence[torch.Tensor]) -> torch.Tensor:
        """Logits (B, R * R) of the centre's image cell (index y * R + x) given the category and the size."""
        q = self.cell_query(self._context(state, category, size))
        logits = torch.einsum("bc,bcyx->byx", q, cells) + self.cell_bias(cells)[:, 0]
        return logits.flatten(1)

    def sub_logits(self, state: torch.Tensor, cells: torch.Tensor, category: torch.Tensor,
                   size: Sequence[torch.Tensor], cell: torch.Tensor) -> torch.Tensor:
        """Logits (B, SUB * SUB) of the centre's place within its cell (index sy * SUB + sx)."""
        feature = cells.flatten(2)[torch.arange(len(cell)), :, cell]
        return self.sub_head(self._context(state, category, size) + self.cell_feature(feature))


def batch_of(examples: Sequence[Example], rng: np.random.Generator) -> dict[str, torch.Tensor]:
    """ATISS's training batch: each room's furniture in a random order, a random number of them kept as
    placed (drawn into the image's fourth channel and given as the set), the next one (or the end) the target."""
    n = max(1, max(len(e.objects) for e in examples))
    objects = np.full((len(examples), n, 7), -1, dtype=np.int64)
    target = np.full((len(examples), 7), -1, dtype=np.int64)
    images = np.zeros((len(examples), 4, RASTER, RASTER), dtype=np.float32)
    for i, e in enumerate(examples):
        order = rng.permutation(len(e.objects))
        k = int(rng.integers(len(e.objects) + 1))
        objects[i, :k] = e.objects[order[:k]]
        if k < len(e.objects):
            target[i] = e.objects[order[k]]
        images[i, :3] = e.raster
        images[i, 3] = occupancy(objects[i, :k], float(e.extent[2]) * 4)
    return {
        "raster": torch.from_numpy(images),
        "room_type": torch.tensor([e.room_type for e in examples]),
        "extent": torch.from_numpy(np.stack([e.extent for e in examples])),
        "objects": torch.from_numpy(objects),
        "mask": torch.from_numpy(objects[..., 0] < 0),
        "target": torch.from_numpy(target),
    }


def loss_of(net: LayoutNet, batch: dict[str, torch.Tensor]) -> torch.Tensor:
    """Cross-entropy of the next object's category (or end) and, where there is one, of its attributes
    (teacher-forced: each conditioned on the true values before it), per example."""
    state, cells = net.state(batch["raster"], batch["room_type"], batch["extent"], batch["objects"], batch["mask"])
    target = batch["target"]
    is_end = target[:, 0] < 0
    category = torch.where(is_end, torch.full_like(target[:, 0], net.end), target[:, 0])
    loss = nn.functional.cross_entropy(net.category_head(state), category)
    keep = ~is_end
    if keep.any():
        s, c, t = state[keep], cells[keep], target[keep]
        size = [t[:, 1], t[:, 2], t[:, 3]]
        terms = [net.attribute_logits(s, t[:, 0], size[:i]) for i in range(3)]
        parts = [nn.functional.cross_entropy(logits, size[i]) for i, logits in enumerate(terms)]
        cell = (t[:, 5] // SUB) * RASTER + t[:, 4] // SUB
        parts.append(nn.functional.cross_entropy(net.centre_logits(s, c, t[:, 0], size), cell))
        parts.append(nn.functional.cross_entropy(net.sub_logits(s, c, t[:, 0], size, cell),
                                                 (t[:, 5] % SUB) * SUB + t[:, 4] % SUB))
        parts.append(nn.functional.cross_entropy(net.attribute_logits(s, t[:, 0], [t[:, j] for j in range(1, 6)]),
                                                 t[:, 6]))
        loss = loss + sum(parts) * keep.float().mean()  # type: ignore[operator]
    return loss


@dataclass(frozen=True)
class TrainConfig:
    epochs: int = 16
    batch: int = 32
    lr: float = 2e-3
    seed: int = 0


def train(examples: Sequence[Example], cfg: NetConfig, train_cfg: TrainConfig,
          progress=None) -> tuple[LayoutNet, list[float]]:
    """A model trained on `examples` (deterministic for a seed: one CPU thread, seeded draws); the mean
    loss of each epoch."""
    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        torch.manual_seed(train_cfg.seed)
        rng = np.random.default_rng(train_cfg.seed)
        net = LayoutNet(cfg)
        opt = torch.optim.AdamW(net.parameters(), lr=train_cfg.lr, weight_decay=1e-4)
        steps = train_cfg.epochs * math.ceil(len(examples) / train_cfg.batch)
        sched = torch.optim.lr_scheduler.OneCycleLR(opt, train_cfg.lr, total_steps=max(1, steps))
        history = []
        for _ in range(train_cfg.epochs):
            order = rng.permutation(len(examples))
            total = 0.0
            for start in range(0, len(order), train_cfg.batch):
                batch = batch_of([examples[i] for i in order[start:start + train_cfg.batch]], rng)
                loss = loss_of(net, batch)
                opt.zero_grad()
                loss.backward()
                opt.step()
                sched.step()
                total += float(loss.detach()) * len(batch["target"])
            history.append(total / len(examples))
            if progress is not None:
                progress(len(history), history[-1])
        return net, history
    finally:
        torch.set_num_threads(threads)


def checkpoint(net: LayoutNet, vocab: list[str], allowed: dict[str, list[str]], info: dict) -> dict:
    """What a checkpoint file holds: weights, config, category vocabulary, the categories seen per room type,
    and how it was trained."""
    return {"format": "luminous-layout-model/1", "config": asdict(net.cfg), "vocab": vocab, "allowed": allowed,
            "info": info, "state": net.state_dict()}


def from_checkpoint(data: dict) -> LayoutNet:
    net = LayoutNet(NetConfig(**data["config"]))
    net.load_state_dict(data["state"])
    net.eval()
    return net


@dataclass(frozen=True)
class Drawn:
    """One generated object, in the unit frame: category index, box size (metres), centre, yaw (radians)."""

    category: int
    size: tuple[float, float, float]
    centre: tuple[float, float]
    yaw: float


@torch.no_grad()
def sample(net: LayoutNet, raster: np.ndarray, room_type: int, extent: np.ndarray, allowed: np.ndarray,
           inside: np.ndarray, seed: int, max_objects: int = MAX_OBJECTS) -> list[Drawn]:
    """Objects drawn one at a time until the end (or `max_objects`). `allowed` (categories,) masks the
    categories this room type was trained with; `inside` (POS_BINS, POS_BINS) [y, x] masks the centres that
    lie on the floor."""
    threads = torch.get_num_threads()
    torch.set_num_threads(1)
    try:
        gen = torch.Generator().manual_seed(seed)
        rt, ext = torch.tensor([room_type]), torch.from_numpy(extent)[None]
        cat_mask = torch.from_numpy(np.append(allowed, True))
        fine = torch.from_numpy(inside).reshape(RASTER, SUB, RASTER, SUB).permute(0, 2, 1, 3).reshape(-1, SUB * SUB)
        on_floor = fine.any(dim=1)
        rows: list[list[int]] = []
        out: list[Drawn] = []

        def draw(logits: torch.Tensor) -> int:
            return int(torch.multinomial(torch.softmax(logits, -1), 1, generator=gen))

        for _ in range(max_objects):
            placed = np.array(rows, dtype=np.int64).reshape(-1, 7)
            image = np.concatenate([raster, occupancy(placed, float(extent[2]) * 4)[None]])[None]
            objs = torch.from_numpy(placed)[None]
            state, cells = net.state(torch.from_numpy(image), rt, ext, objs,
                                     torch.zeros(1, objs.shape[1], dtype=torch.bool))
            cat = draw(net.category_head(state)[0].masked_fill(~cat_mask, -math.inf))
            if cat == net.end:
                break
            category = torch.tensor([cat])
            chosen: list[torch.Tensor] = []
            for _ in range(3):
                chosen.append(torch.tensor([draw(net.attribute_logits(state, category, chosen)[0])]))
            cell = draw(net.centre_logits(state, cells, category, chosen)[0].masked_fill(~on_floor, -math.inf))
            sub = draw(net.sub_logits(state, cells, category, chosen, torch.tensor([cell]))[0]
                       .masked_fill(~fine[cell], -math.inf))
            x, y = (cell % RASTER) * SUB + sub % SUB, (cell // RASTER) * SUB + sub // SUB
            chosen += [torch.tensor([x]), torch.tensor([y])]
            chosen.append(torch.tensor([draw(net.attribute_logits(state, category, chosen)[0])]))
            row = [cat] + [int(c) for c in chosen]
            rows.append(row)
            out.append(Drawn(cat, (size_value(row[1]), size_value(row[2]), size_value(row[3])),
                             (pos_value(row[4]), pos_value(row[5])), row[6] * 2 * math.pi / YAW_BINS))
        return out
    finally:
        torch.set_num_threads(threads)
