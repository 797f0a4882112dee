"""A token vocabulary with the four special tokens and a JSON form."""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Iterable
from pathlib import Path

from luminous_sim.language.speaker.errors import SpeakerError, check_regular_file

PAD, BOS, EOS, UNK = "<pad>", "<bos>", "<eos>", "<unk>"
SPECIALS: tuple[str, ...] = (PAD, BOS, EOS, UNK)


class Vocab:
    """Bidirectional token <-> id map; ids 0..3 are ``<pad> <bos> <eos> <unk>``.

    Args:
        tokens: The non-special tokens, in id order (specials are prepended and never repeated).
    """

    def __init__(self, tokens: Iterable[str] = ()) -> None:
        self.itos: list[str] = list(SPECIALS)
        self.stoi: dict[str, int] = {t: i for i, t in enumerate(self.itos)}
        for tok in tokens:
            if tok not in self.stoi:
                self.stoi[tok] = len(self.itos)
                self.itos.append(tok)

    pad_id = 0
    bos_id = 1
    eos_id = 2
    unk_id = 3

    @classmethod
    def build(cls, sequences: Iterable[Iterable[str]], min_freq: int = 1) -> Vocab:
        """Build a vocabulary from token sequences.

        Args:
            sequences: Token lists to count.
            min_freq: Tokens seen fewer times than this map to ``<unk>``.

        Returns:
            A vocabulary ordered by descending frequency, ties alphabetical (deterministic).
        """
        counts = Counter(tok for seq in sequences for tok in seq)
        kept = sorted(
            (t for t, c in counts.items() if c >= min_freq), key=lambda t: (-counts[t], t)
        )
        return cls(kept)

    def __len__(self) -> int:
        return len(self.itos)

    def __contains__(self, token: str) -> bool:
        return token in self.stoi

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Vocab) and self.itos == other.itos

    def encode(self, tokens: Iterable[str]) -> list[int]:
        """Map tokens to ids; unknown tokens become ``<unk>``."""
        return [self.stoi.get(t, self.unk_id) for t in tokens]

    def decode(self, ids: Iterable[int], strip: bool = True) -> list[str]:
        """Map ids to tokens; with ``strip``, stop at ``<eos>`` and drop ``<pad>`` and ``<bos>``."""
        out = []
        for i in ids:
            tok = self.itos[int(i)]
            if strip and tok == EOS:
                break
            if strip and tok in (PAD, BOS):
                continue
            out.append(tok)
        return out

    def to_json(self) -> list[str]:
        """The JSON-able form: the full token list in id order."""
        return list(self.itos)

    @classmethod
    def from_json(cls, items: list[str], source: str = "vocabulary") -> Vocab:
        """Rebuild from :meth:`to_json` output; ``source`` names it in errors."""
        if not isinstance(items, list) or list(items[: len(SPECIALS)]) != list(SPECIALS):
            raise SpeakerError(
                f"{source}: not a speaker vocabulary (must start with {list(SPECIALS)})"
            )
        if not all(isinstance(t, str) for t in items) or len(set(items)) != len(items):
            raise SpeakerError(f"{source}: vocabulary tokens must be unique strings")
        return cls(items[len(SPECIALS) :])

    def save(self, path: str | Path) -> None:
        """Write the vocabulary as a JSON list."""
        Path(path).write_text(json.dumps(self.to_json(), indent=0))

    @classmethod
    def load(cls, path: str | Path) -> Vocab:
        """Read a vocabulary written by :meth:`save`.

        Raises:
            SpeakerError: The file is missing, not JSON, or not a vocabulary.
        """
        check_regular_file(path, "a vocabulary file (JSON)")
        try:
            items = json.loads(Path(path).read_text())
        except FileNotFoundError:
            raise SpeakerError(f"{path}: vocabulary file not found") from None
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            raise SpeakerError(f"{path}: not a JSON vocabulary ({exc})") from None
        return cls.from_json(items, source=str(path))
