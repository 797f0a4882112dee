"""The registry of procedural builders: one function per object type, called once per variant."""

from __future__ import annotations

import hashlib
import importlib
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from luminous_sim.assets.spec import MIN_VARIANTS, AssetSpec, Category
from luminous_sim.errors import AssetError
from luminous_sim.vocab import check_type

BuilderFn = Callable[[int, np.random.Generator], AssetSpec]


@dataclass(frozen=True)
class BuilderInfo:
    """A registered builder: the type it makes, how many variants, and its category."""

    type: str
    variants: int
    category: Category
    fn: BuilderFn


_REGISTRY: dict[str, BuilderInfo] = {}


def register(type_name: str, variants: int, category: Category) -> Callable[[BuilderFn], BuilderFn]:
    """Decorator registering `fn(variant, rng) -> AssetSpec` as the builder of `type_name`."""
    check_type(type_name)
    if variants < MIN_VARIANTS[category]:
        raise ValueError(f"{type_name}: {category} needs >= {MIN_VARIANTS[category]} variants")

    def deco(fn: BuilderFn) -> BuilderFn:
        if type_name in _REGISTRY:
            raise ValueError(f"two builders registered for {type_name}")
        _REGISTRY[type_name] = BuilderInfo(type_name, variants, category, fn)
        return fn

    return deco


def builders() -> dict[str, BuilderInfo]:
    """All registered builders, by type (imports the builder modules on first use)."""
    importlib.import_module("luminous_sim.assets.builders")
    return dict(sorted(_REGISTRY.items()))


def variant_rng(type_name: str, variant: int) -> np.random.Generator:
    """The builder's random stream for one variant: fixed by (type, variant), independent of build order."""
    digest = hashlib.sha256(f"{type_name}:{variant}".encode()).digest()
    return np.random.default_rng(int.from_bytes(digest[:8], "little"))


def build_spec(type_name: str, variant: int) -> AssetSpec:
    """Run the builder of `type_name` for one variant and check what it returned."""
    info = builders().get(type_name)
    if info is None:
        raise AssetError(f"no builder for object type {type_name!r}")
    if not 0 <= variant < info.variants:
        raise AssetError(f"{type_name} has variants 0..{info.variants - 1}, not {variant}")
    spec = info.fn(variant, variant_rng(type_name, variant))
    if (spec.type, spec.variant, spec.category) != (type_name, variant, info.category):
        raise AssetError(f"builder of {type_name} returned {spec.asset_id} ({spec.category})")
    spec.validate()
    return spec
