"""The instruction parser: a goal directive (and, when given, the step instructions) to ALFRED's task type and
`pddl_params`, as the modular ALFRED agents (FILM, HLSM) begin. Trained on ALFRED's train annotations
(`train_parser`, every human annotation of every trajectory; a share of the task designs held apart to choose
the epochs, never valid_seen); the trained checkpoint ships in the package (`default_parser`), and training
again with the same data and seed writes the same bytes (one thread, deterministic kernels, seeded order).

Each annotation is learnt twice: its directive alone, and its directive with its step instructions, so one
model answers both ways it is asked."""

from __future__ import annotations

import random
from collections import Counter
from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import torch
from torch import nn

from luminous_sim.agents.annotations import SLOTS, Annotated, allowed, held_apart, read_annotations
from luminous_sim.agents.checkpoints import load_checkpoint, save_checkpoint
from luminous_sim.agents.mentions import Mention, mentions
from luminous_sim.agents.parser_model import PAD, SEP, UNK, ParserNet, ParserShape
from luminous_sim.agents.swaps import receptacles, swap_parent
from luminous_sim.errors import LuminousError
from luminous_sim.language.speaker import tokenize
from luminous_sim.vocab import ALFRED_TASK_TYPES, LAMPS, abilities

FORMAT = "luminous-instruction-parser/1"
PARSER_FILE = Path(__file__).with_name("data") / "instruction_parser.pt"
"""The shipped checkpoint (package data)."""
HEADS: tuple[str, ...] = ("task_type", *SLOTS)
MAX_WORDS = 160
"""Words read of one input (a directive is under 40; the longest step instructions add about 120)."""
MIN_COUNT = 2
"""A word seen fewer times in training is read as unknown."""
POINTER_SLOTS: tuple[str, ...] = SLOTS[:4]
"""The slots the pointer may fill from a name in the input (all but `object_sliced`)."""
MAX_MENTIONS = 32
"""Names of one input the pointer reads (the directive's come first)."""
EPSILON = 1e-3
"""A type's floor when a name's probability is shared among the types it may mean ("sink": Sink, SinkBasin)."""


class ParserError(LuminousError):
    """A parser checkpoint that cannot be read, or bad input to training; the message names the file."""


@dataclass(frozen=True)
class ParsedTask:
    """What the parser read from an instruction: ALFRED's task type and its five arguments."""

    task_type: str
    pddl_params: dict[str, Any]

    def to_dict(self) -> dict[str, Any]:
        return {"task_type": self.task_type, "pddl_params": dict(self.pddl_params)}


@dataclass(frozen=True)
class TrainSettings:
    """How the parser is trained (the defaults made the shipped checkpoint)."""

    seed: int = 0
    epochs: int = 8
    batch_size: int = 64
    lr: float = 2e-3
    held_apart: float = 0.1
    """The share of ALFRED's train task designs held apart to report (and choose the epochs on)."""
    pointer: bool = True
    """Learn the pointer head (copy a named type into a slot)."""
    recurrent: bool = True
    """A bidirectional GRU after the convolutions."""
    swap: float = 0.5
    """The share of inputs, drawn afresh each epoch, whose parent's name is swapped for another receptacle's
    (`swaps.swap_parent`; 0: ALFRED's sentences only)."""


def slot_may_hold(slot: str, object_type: str) -> bool:
    """Whether a named type the classifier never learnt for `slot` may still fill it: a receptacle as the
    parent, something pickupable as the object, a movable receptacle, a lamp."""
    if slot == "toggle_target":
        return object_type in LAMPS
    a = abilities(object_type)
    return {"object_target": a.pickupable, "parent_target": a.receptacle,
            "mrecep_target": a.movable_receptacle}.get(slot, False)


def words(directive: str, steps: Sequence[str] = ()) -> list[str]:
    """The parser's input words: the directive's, then (with steps) the separator and the steps'."""
    out = tokenize(directive)
    if steps:
        out += [SEP, *(w for s in steps for w in tokenize(s))]
    return out[:MAX_WORDS]


@dataclass(frozen=True)
class Encoded:
    """A batch as the network reads it: word ids, each name's words (to average), which names are real, and
    the names."""

    ids: torch.Tensor
    spans: torch.Tensor
    present: torch.Tensor
    found: list[list[Mention]]


@dataclass
class InstructionParser:
    """A trained parser: its vocabulary, the answers of each head, and the network."""

    vocab: list[str]
    answers: dict[str, list[Any]]
    net: ParserNet
    record: dict[str, Any] = field(default_factory=dict)
    """How it was trained: settings, examples, the held-apart accuracy per epoch."""

    def __post_init__(self) -> None:
        self._index = {w: i for i, w in enumerate(self.vocab)}
        self.net.eval()

    def encode(self, batch: Sequence[list[str]]) -> Encoded:
        """Word ids, padded to the longest input (0 is padding), and the names each input contains."""
        width = max(1, *(len(w) for w in batch))
        ids = np.zeros((len(batch), width), np.int64)
        unk = self._index[UNK]
        found = [mentions(ws)[:MAX_MENTIONS] for ws in batch]
        spans = np.zeros((len(batch), max(1, *(len(f) for f in found)), width), np.float32)
        present = np.zeros(spans.shape[:2], bool)
        for r, ws in enumerate(batch):
            ids[r, :len(ws)] = [self._index.get(w, unk) for w in ws]
            for j, m in enumerate(found[r]):
                spans[r, j, m.start:m.end] = 1.0 / (m.end - m.start)
                present[r, j] = True
        return Encoded(torch.from_numpy(ids), torch.from_numpy(spans), torch.from_numpy(present), found)

    def parse(self, directive: str, steps: Sequence[str] = ()) -> ParsedTask:
        """The task one instruction asks for."""
        return self.parse_many([(directive, tuple(steps))])[0]

    def parse_many(self, items: Sequence[tuple[str, Sequence[str]]], batch_size: int = 256) -> list[ParsedTask]:
        """The tasks of many (directive, steps) pairs, in order: the type and arguments decoded together, the
        most likely whole that ALFRED's task definitions allow (`annotations.allowed`)."""
        out: list[ParsedTask] = []
        with torch.no_grad():
            for start in range(0, len(items), batch_size):
                part = items[start:start + batch_size]
                enc = self.encode([words(d, s) for d, s in part])
                logits, pointer = self.net(enc.ids, enc.spans, enc.present)
                probs = [torch.softmax(lg, -1).numpy() for lg in logits]
                point = None if pointer is None else torch.softmax(pointer, 1).numpy()
                out += [self._decode([p[r] for p in probs], None if point is None else point[r], enc.found[r])
                        for r in range(len(part))]
        return out

    def slot_scores(self, probs: list[np.ndarray], point: np.ndarray | None, found: Sequence[Mention]
                    ) -> dict[str, dict[Any, float]]:
        """Each slot's values and their log-probabilities: the classifier's, mixed, where the pointer is
        learnt, with the pointer's choice of a name (its share of a name that may mean several types goes by
        the classifier)."""
        out: dict[str, dict[Any, float]] = {}
        for k, slot in enumerate(SLOTS, start=1):
            dist = {v: float(probs[k][i]) for i, v in enumerate(self.answers[slot])}
            if point is not None and slot in POINTER_SLOTS:
                j = POINTER_SLOTS.index(slot)
                mixed = {v: float(point[0, j]) * q for v, q in dist.items()}
                for i, m in enumerate(found[:point.shape[0] - 1]):
                    types = [t for t in sorted(m.types) if t in dist or slot_may_hold(slot, t)]
                    weights = [dist.get(t, 0.0) + EPSILON for t in types]
                    for t, w in zip(types, weights, strict=True):
                        mixed[t] = mixed.get(t, 0.0) + float(point[1 + i, j]) * w / sum(weights)
                dist = mixed
            out[slot] = {v: float(np.log(max(q, 1e-12))) for v, q in dist.items()}
        return out

    def _decode(self, probs: list[np.ndarray], point: np.ndarray | None, found: Sequence[Mention]) -> ParsedTask:
        """The best task type with, for each slot, its best value the type allows."""
        slots = self.slot_scores(probs, point, found)
        best: tuple[float, str, dict[str, Any]] | None = None
        for t, task_type in enumerate(self.answers["task_type"]):
            total, picks = float(np.log(max(float(probs[0][t]), 1e-12))), {}
            for slot in SLOTS:
                options = [(score, v) for v, score in slots[slot].items() if allowed(task_type, slot, v)]
                if not options:
                    break
                score, value = max(options, key=lambda o: o[0])
                total += score
                picks[slot] = value
            else:
                if best is None or total > best[0]:
                    best = (total, task_type, picks)
        assert best is not None, "every task type allows some answer"
        return ParsedTask(best[1], best[2])

    def save(self, path: Path) -> None:
        """Write the checkpoint atomically (the same parser, the same bytes)."""
        payload = {"format": FORMAT, "vocab": self.vocab, "answers": self.answers, "shape": self.net.shape.to_dict(),
                   "model": self.net.state_dict(), "record": self.record}
        save_checkpoint(payload, path)

    @classmethod
    def load(cls, path: Path) -> InstructionParser:
        """A parser from its checkpoint.

        Raises:
            ParserError: missing, unreadable, or not a parser checkpoint.
        """
        data = load_checkpoint(path, FORMAT, "parser", "luminous agents train-parser", ParserError)
        try:
            shape = data["shape"]
            net = ParserNet(ParserShape(shape["words"], tuple(shape["answers"]), shape.get("pointers", 0),
                                        shape.get("recurrent", False), shape["embedding"], shape["hidden"],
                                        shape["dropout"]))
            net.load_state_dict(data["model"])
            answers = {h: list(data["answers"][h]) for h in HEADS}
            return cls(list(data["vocab"]), answers, net, dict(data["record"]))
        except (KeyError, TypeError, ValueError, RuntimeError) as exc:  # RuntimeError: weights of other shapes
            raise ParserError(f"{path}: a parser checkpoint with a missing or damaged part "
                              f"({type(exc).__name__}: {str(exc)[:120]})") from None


_DEFAULT: InstructionParser | None = None


def default_parser() -> InstructionParser:
    """The shipped parser (loaded once)."""
    global _DEFAULT
    if _DEFAULT is None:
        _DEFAULT = InstructionParser.load(PARSER_FILE)
    return _DEFAULT


def _labels(examples: Sequence[Annotated], parents: Sequence[str] = ()) -> dict[str, list[Any]]:
    """Each head's answers: ALFRED's task types in their order; each slot's values seen (and, as the parent,
    `parents`), sorted ("" first)."""
    answers: dict[str, list[Any]] = {"task_type": list(ALFRED_TASK_TYPES)}
    for slot in SLOTS:
        seen = {e.params[slot] for e in examples} | (set(parents) if slot == "parent_target" else set())
        answers[slot] = sorted(seen, key=lambda v: (str(type(v)), v))
    return answers


def _vocab(examples: Sequence[Annotated]) -> list[str]:
    counts = Counter(w for e in examples for w in words(e.directive, e.steps))
    return [PAD, UNK, SEP, *sorted(w for w, n in counts.items() if n >= MIN_COUNT and w not in (PAD, UNK, SEP))]


def _inputs(examples: Sequence[Annotated]) -> Iterator[tuple[list[str], Annotated]]:
    """Each annotation twice: its directive alone, then with its steps."""
    for e in examples:
        yield words(e.directive), e
        yield words(e.directive, e.steps), e


def accuracy(parser: InstructionParser, examples: Sequence[Annotated], with_steps: bool) -> dict[str, float]:
    """The share of examples whose task type is right, each slot is right, and everything is right
    (`all`: the type and all five slots; `slots`: all five slots)."""
    if not examples:
        return {}
    got = parser.parse_many([(e.directive, e.steps if with_steps else ()) for e in examples])
    right = {h: 0 for h in (*HEADS, "slots", "all")}
    for p, e in zip(got, examples, strict=True):
        hits = {s: p.pddl_params[s] == e.params[s] for s in SLOTS}
        right["task_type"] += p.task_type == e.task_type
        for s in SLOTS:
            right[s] += hits[s]
        right["slots"] += all(hits.values())
        right["all"] += all(hits.values()) and p.task_type == e.task_type
    return {k: v / len(examples) for k, v in right.items()}


def train_parser(alfred: Path, settings: TrainSettings | None = None, progress: bool = False) -> InstructionParser:
    """Train a parser on every annotation under `alfred` (ALFRED's train split), `settings.held_apart` of the
    task designs held apart and scored after each epoch (recorded in the parser's `record`).

    Raises:
        AnnotationError: the data cannot be read.
        ParserError: no annotation to learn from.
    """
    settings = settings or TrainSettings()
    examples = read_annotations(alfred)
    kept, apart = held_apart(examples, settings.held_apart, settings.seed)
    if not kept:
        raise ParserError(f"{alfred}: no annotation to train on")
    threads = torch.get_num_threads()
    torch.set_num_threads(1)  # the same bytes on every run: one thread, deterministic kernels
    try:
        with torch.random.fork_rng(devices=[]):
            torch.manual_seed(settings.seed)
            return _fit(kept, apart, settings, progress, str(alfred))
    finally:
        torch.set_num_threads(threads)


def _fit(kept: list[Annotated], apart: list[Annotated], settings: TrainSettings, progress: bool,
         source: str) -> InstructionParser:
    vocab, answers = _vocab(kept), _labels(kept, receptacles() if settings.swap else ())
    net = ParserNet(ParserShape(len(vocab), tuple(len(answers[h]) for h in HEADS),
                                len(POINTER_SLOTS) if settings.pointer else 0, settings.recurrent))
    parser = InstructionParser(vocab, answers, net)
    pairs = list(_inputs(kept))
    ids = [{v: i for i, v in enumerate(answers[h])} for h in HEADS]
    optimiser = torch.optim.Adam(net.parameters(), lr=settings.lr)
    loss_fn = nn.CrossEntropyLoss()
    order = torch.Generator().manual_seed(settings.seed)
    swaps = random.Random(settings.seed)
    history = []
    for epoch in range(settings.epochs):
        net.train()
        total = 0.0
        for batch in _batches(pairs, settings.batch_size, order):
            chosen = [_swapped(pairs[int(i)], settings.swap, swaps) for i in batch]
            enc = parser.encode([ws for ws, _ in chosen])
            targets = torch.tensor([[ids[k][e.task_type if h == "task_type" else e.params[h]]
                                     for k, h in enumerate(HEADS)] for _, e in chosen], dtype=torch.long)
            logits, pointer = net(enc.ids, enc.spans, enc.present)
            loss = sum(loss_fn(lg, targets[:, k]) for k, lg in enumerate(logits))
            if pointer is not None:
                loss = loss + _pointer_loss(pointer, enc.found, [e for _, e in chosen])
            optimiser.zero_grad()
            loss.backward()  # type: ignore[union-attr]
            optimiser.step()
            total += float(loss.detach()) * len(batch)  # type: ignore[union-attr]
        net.eval()
        scores = {"epoch": epoch + 1, "loss": round(total / len(pairs), 6),
                  "held_apart_directive": _rounded(accuracy(parser, apart, False)),
                  "held_apart_with_steps": _rounded(accuracy(parser, apart, True))}
        history.append(scores)
        if progress:
            print(scores, flush=True)
    parser.record = {"source": Path(source).name, "settings": settings.__dict__, "annotations": len(kept),
                     "held_apart_annotations": len(apart), "epochs": history}
    return parser


def _swapped(pair: tuple[list[str], Annotated], share: float, rng: random.Random) -> tuple[list[str], Annotated]:
    """The input as it is, or (a `share` of the time, where its parent is named) with the parent swapped."""
    if share and rng.random() < share:
        swapped = swap_parent(*pair, rng)
        if swapped is not None:
            return swapped[0][:MAX_WORDS], swapped[1]
    return pair


def _pointer_loss(pointer: torch.Tensor, found: Sequence[Sequence[Mention]], labels: Sequence[Annotated]
                  ) -> torch.Tensor:
    """The pointer's negative log-likelihood: of every name that may mean the slot's answer, or of "none of
    them" where the answer is "" or unnamed."""
    target = torch.zeros(pointer.shape, dtype=torch.bool)
    for r, (names, e) in enumerate(zip(found, labels, strict=True)):
        for j, slot in enumerate(POINTER_SLOTS):
            hits = [1 + i for i, m in enumerate(names) if e.params[slot] and e.params[slot] in m.types]
            target[r, hits or [0], j] = True
    chosen = torch.logsumexp(pointer.masked_fill(~target, -1e4), dim=1)
    return (torch.logsumexp(pointer, dim=1) - chosen).sum(-1).mean()


def _batches(pairs: Sequence[tuple[list[str], Annotated]], size: int, order: torch.Generator) -> list[torch.Tensor]:
    """Batches of similar lengths (directives with directives, directives with steps with their like), in a
    seeded order: little padding, so an epoch costs what its words cost."""
    shuffled = torch.randperm(len(pairs), generator=order).tolist()
    by_length = sorted(shuffled, key=lambda i: len(pairs[i][0]) // 8)  # stable: shuffled within a length band
    batches = [torch.tensor(by_length[i:i + size]) for i in range(0, len(by_length), size)]
    return [batches[int(k)] for k in torch.randperm(len(batches), generator=order)]


def _rounded(scores: dict[str, float]) -> dict[str, float]:
    return {k: round(v, 4) for k, v in scores.items()}
