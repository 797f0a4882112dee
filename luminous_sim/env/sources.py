"""Where a reset's episode comes from, one source per kind (tried in `SOURCES` order; the first that applies
draws): a frozen split's entry the reset or the config asks for, a built trial, the CDF files the reset or the
config names, else one generated on the fly (in the reset's scene, if it gives one). Each draws from
`luminous_sim.episodes`, as the config says (`env.episodes.drawing`)."""

from __future__ import annotations

from abc import ABC, abstractmethod

import numpy as np

from luminous_sim.env.config import EnvConfig
from luminous_sim.env.episodes import cdf_paths, drawing, requested_entry
from luminous_sim.env.reset_options import ResetOptions
from luminous_sim.env.worlds import WorldPool
from luminous_sim.episodes import EpisodeSpec, draw_from_cdf, draw_generated, split_spec, trial_spec
from luminous_sim.world import World

Drawn = tuple[EpisodeSpec, World]


class Source(ABC):
    """One place episodes come from."""

    @abstractmethod
    def draw(self, config: EnvConfig, worlds: WorldPool, options: ResetOptions,
             rng: np.random.Generator) -> Drawn | None:
        """The episode and its world, ready for the first step; None when the reset does not ask for this source."""


class SplitSource(Source):
    """A frozen split's entry (`options.split`/`options.index`, or the config's `split`)."""

    def draw(self, config: EnvConfig, worlds: WorldPool, options: ResetOptions,
             rng: np.random.Generator) -> Drawn | None:
        entry = requested_entry(config, options, rng)
        return None if entry is None else split_spec(entry, worlds, config.verify_expert)


class TrialSource(Source):
    """A built trial's folder (`options.trial`), restored from its files."""

    def draw(self, config: EnvConfig, worlds: WorldPool, options: ResetOptions,
             rng: np.random.Generator) -> Drawn | None:
        return None if not options.trial else trial_spec(options.trial, worlds, config.verify_expert)


class CdfSource(Source):
    """A scene generated from a CDF file (`options.cdf`, or the config's `cdf`)."""

    def draw(self, config: EnvConfig, worlds: WorldPool, options: ResetOptions,
             rng: np.random.Generator) -> Drawn | None:
        paths = cdf_paths(config, options)
        return None if not paths else draw_from_cdf(drawing(config), paths, rng, worlds, options.scene_seed)


class GeneratedSource(Source):
    """Generated on the fly (a room CSSG lays out, or a house), or in the scene the reset gives."""

    def draw(self, config: EnvConfig, worlds: WorldPool, options: ResetOptions,
             rng: np.random.Generator) -> Drawn | None:
        return draw_generated(drawing(config), rng, worlds, scene=options.scene)


SOURCES: tuple[Source, ...] = (SplitSource(), TrialSource(), CdfSource(), GeneratedSource())
"""Every source, in the order a reset tries them (generation always applies, so it comes last)."""


def draw_episode(config: EnvConfig, worlds: WorldPool, options: ResetOptions, rng: np.random.Generator) -> Drawn:
    """The reset's episode from the first source that applies, its worlds from `worlds`."""
    for source in SOURCES:
        drawn = source.draw(config, worlds, options, rng)
        if drawn is not None:
            return drawn
    raise AssertionError("GeneratedSource always applies")
