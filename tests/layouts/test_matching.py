"""Category matching (table, type names, head words, fuzzy) and size matching (best variant, scale limits)."""

from __future__ import annotations

import pytest

from luminous_sim.assets.catalog import default_catalog
from luminous_sim.layouts import MAX_SCALE, MIN_SCALE, match_category, match_size
from luminous_sim.layouts.matching import category_table, normalise
from luminous_sim.vocab import ALL_TYPES


@pytest.mark.parametrize(("label", "type_", "method"), [
    ("Dining Chair", "Chair", "table"),
    ("Sideboard / Side Cabinet / Console Table", "Dresser", "table"),
    ("double_bed", "Bed", "table"),
    ("L-shaped Sofa", "Sofa", "table"),
    ("CoffeeTable", "CoffeeTable", "table"),
    ("Pan", "Pan", "type name"),
    ("Mug", "Mug", "type name"),
    ("modern upholstered double bed", "Bed", "head words"),
    ("refridgerator", "Fridge", "fuzzy"),
    ("armchiar", "ArmChair", "fuzzy"),
])
def test_labels_match_alfred_types(label, type_, method):
    got = match_category(label, default_catalog())
    assert (got.type, got.method) == (type_, method)


def test_labels_left_out_say_why():
    lamp = match_category("Pendant Lamp", default_catalog())
    assert lamp.type is None and "ceiling" in lamp.reason
    unknown = match_category("spaceship", default_catalog())
    assert unknown.type is None and unknown.method == "none" and unknown.reason


def test_every_table_target_is_a_catalog_type():
    catalog = default_catalog()
    targets = {t for t in category_table().values() if t is not None}
    assert targets <= set(catalog.types()) and targets <= set(ALL_TYPES)
    assert all(normalise(k) == k for k in category_table())


def test_the_best_fitting_variant_is_chosen():
    catalog = default_catalog()
    sofas = catalog.of_type("Sofa")
    corner = max(sofas, key=lambda e: e.dims[1])  # the one deep enough to be an L
    got = match_size("Sofa", tuple(corner.dims), catalog)
    assert got.entry.id == corner.id and got.scale == pytest.approx(1.0, abs=1e-3) and not got.clamped


def test_scales_stay_within_limits_and_say_so():
    catalog = default_catalog()
    huge = match_size("Chair", (2.0, 2.0, 4.0), catalog)
    assert huge.scale == MAX_SCALE and huge.clamped
    tiny = match_size("Chair", (0.1, 0.1, 0.2), catalog)
    assert tiny.scale == MIN_SCALE and tiny.clamped
    assert match_size("NoSuchType", (1, 1, 1), catalog) is None
    report = huge.to_dict()
    assert report["scale_clamped"] and report["got_size"] != report["wanted_size"]
