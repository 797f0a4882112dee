"""Loading and saving: round trips, and the safety rules (no code, size limit, safe references)."""

from __future__ import annotations

import json
import sys
import types
from pathlib import Path

import pytest
import yaml

from luminous_sim import cdf as C
from luminous_sim.cdf import CDFValidationError, dump, dumps, load, loads
from luminous_sim.cdf.reader import MAX_BYTES, MAX_NODES, parse_text
from tests.cdf.helpers import BASE, EXAMPLES, base

BASE_YAML = yaml.safe_dump(BASE, sort_keys=False)


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("suffix", [".yaml", ".json"])
def test_examples_round_trip(path: Path, suffix: str, tmp_path: Path) -> None:
    cdf = load(path)
    out = dump(cdf, tmp_path / f"copy{suffix}")
    again = load(out)
    assert again == cdf
    assert dumps(again) == dumps(cdf)


def test_json_and_yaml_text() -> None:
    cdf = loads(BASE_YAML)
    assert loads(json.dumps(BASE), fmt="json") == cdf
    assert loads(BASE_YAML.encode()) == cdf
    assert C.to_document(cdf)["cdf_version"] == 2
    assert cdf.object_named("apple").type == "Apple"  # type: ignore[union-attr]
    assert cdf.object_named("banana") is None


def test_load_names_the_file(tmp_path: Path) -> None:
    path = tmp_path / "kitchen.yaml"
    path.write_text(BASE_YAML.replace("type: Apple", "type: Aple"))
    with pytest.raises(CDFValidationError) as info:
        load(path)
    assert str(info.value).startswith(f"{path}: scene.objects[2].type: unknown object type 'Aple'")


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("!!python/object/apply:os.system ['echo hacked']", "could not determine a constructor"),
        ("a: !!python/name:os.system", "could not determine a constructor"),
        ("a: !!binary aGVsbG8=", "could not determine a constructor"),
        ("a: !!set {x, y}", "could not determine a constructor"),
        ("a: !custom 3", "could not determine a constructor"),
        ("a: 1\na: 2\n", "duplicate key 'a'"),
        ("a: [1\n", "invalid YAML"),
        ("--- 1\n--- 2\n", "expected a single document"),
        ("a: &x [*x]\n", "refers to itself"),
        ("[" * 200 + "]" * 200, "nested"),
    ],
)
def test_unsafe_or_malformed_yaml_is_rejected(text: str, fragment: str) -> None:
    with pytest.raises(CDFValidationError) as info:
        loads(text, source="bad.yaml")
    assert str(info.value).startswith("bad.yaml: ")
    assert fragment in str(info.value)


def test_billion_laughs_is_rejected_quickly() -> None:
    lines = ['a0: &a0 ["lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol", "lol"]']
    for i in range(1, 10):
        lines.append(f"a{i}: &a{i} [" + ", ".join([f"*a{i - 1}"] * 9) + "]")
    with pytest.raises(CDFValidationError, match=f"more than {MAX_NODES} values"):
        loads("\n".join(lines))


def test_small_aliases_are_fine() -> None:
    data = parse_text("base: &b {type: Mug}\nx: *b\ny: {<<: *b, name: m}\n")
    assert data["y"] == {"type": "Mug", "name": "m"}


def test_yaml_12_booleans_and_no_timestamps() -> None:
    data = parse_text("a: on\nb: yes\nc: true\nd: 2021-01-01\ne: False\n")
    assert data == {"a": "on", "b": "yes", "c": True, "d": "2021-01-01", "e": False}


def test_json_duplicate_keys_and_errors() -> None:
    with pytest.raises(CDFValidationError, match="duplicate key 'a'"):
        loads('{"a": 1, "a": 2}', fmt="json")
    with pytest.raises(CDFValidationError, match="invalid JSON"):
        loads("{", fmt="json")
    with pytest.raises(CDFValidationError, match="unknown format"):
        loads("{}", fmt="toml")


def test_size_limit(tmp_path: Path) -> None:
    big = BASE_YAML + "description: " + "x" * MAX_BYTES + "\n"
    with pytest.raises(CDFValidationError, match=f"expected at most {MAX_BYTES}"):
        loads(big, source="big.yaml")
    path = tmp_path / "big.yaml"
    path.write_text(big)
    with pytest.raises(CDFValidationError, match=f"larger than {MAX_BYTES} bytes"):
        load(path)


def test_an_oversized_file_is_refused_before_parsing_naming_the_limit(tmp_path: Path) -> None:
    """Issue 27: the size is checked first (a huge sparse file of garbage gets the size error, not a parse
    error), in a message naming the file and luminous_sim.limits.MAX_CDF_BYTES."""
    from luminous_sim.limits import MAX_CDF_BYTES

    path = tmp_path / "huge.yaml"
    with open(path, "wb") as fh:
        fh.write(b"{{{ not yaml")
        fh.truncate(10 * MAX_CDF_BYTES)
    with pytest.raises(CDFValidationError) as err:
        load(path)
    text = str(err.value)
    assert str(path) in text and str(MAX_CDF_BYTES) in text and "MAX_CDF_BYTES" in text, text
    assert len(text.splitlines()) == 1, text


def test_file_errors(tmp_path: Path) -> None:
    with pytest.raises(CDFValidationError, match="cannot read the file"):
        load(tmp_path / "missing.yaml")
    with pytest.raises(CDFValidationError, match="folder.yaml: a folder; expected a regular CDF file"):
        load(_dir_named(tmp_path, "folder.yaml"))
    with pytest.raises(CDFValidationError, match="unknown file suffix '.txt'"):
        load(tmp_path / "notes.txt")
    bad = tmp_path / "latin1.yaml"
    bad.write_bytes("cdf_version: 2\nname: caf\xe9\n".encode("latin-1"))
    with pytest.raises(CDFValidationError, match="not UTF-8"):
        load(bad)


def _dir_named(root: Path, name: str) -> Path:
    path = root / name
    path.mkdir()
    return path


def test_room_names_resolve_through_the_library_when_it_exists(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    doc = base()
    doc["scene"]["room"] = "kitchen_galley"
    monkeypatch.setitem(sys.modules, "luminous_sim.rooms.library", None)  # not importable
    C.from_document(doc)  # the fallback accepts names shaped like procedural ones
    fake = types.ModuleType("luminous_sim.rooms.library")
    fake.has_room = lambda name: name == "kitchen_only_this"  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "luminous_sim.rooms.library", fake)
    with pytest.raises(CDFValidationError, match="unknown room 'kitchen_galley'"):
        C.from_document(doc)
    doc["scene"]["room"] = "kitchen_only_this"
    C.from_document(doc)


def test_assets_resolve_through_the_catalog(monkeypatch: pytest.MonkeyPatch) -> None:
    fake = types.ModuleType("luminous_sim.assets.catalog")

    class Entry:
        type = "Apple"

    class Catalog:
        def __contains__(self, name: str) -> bool:
            return name in ("Apple_07", "Chair_00")

        def get(self, name: str) -> Entry:
            entry = Entry()
            entry.type = name.split("_")[0]
            return entry

    fake.default_catalog = Catalog  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "luminous_sim.assets.catalog", fake)
    doc = base()
    doc["scene"]["objects"][2]["asset"] = "Apple_07"
    assert C.from_document(doc).scene.objects[2].asset == "Apple_07"
    doc["scene"]["objects"][2]["asset"] = "Apple_08"
    with pytest.raises(CDFValidationError, match="unknown asset 'Apple_08'"):
        C.from_document(doc)
    doc["scene"]["objects"][2]["asset"] = "Chair_00"
    with pytest.raises(
        CDFValidationError,
        match=r"scene.objects\[2\].asset: asset 'Chair_00' is a Chair; expected an asset of type Apple",
    ):
        C.from_document(doc)


def test_a_broken_sibling_module_falls_back(monkeypatch: pytest.MonkeyPatch) -> None:
    fake = types.ModuleType("luminous_sim.rooms.library")

    def has_room(name: str) -> bool:
        raise RuntimeError("half written")

    fake.has_room = has_room  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, "luminous_sim.rooms.library", fake)
    doc = base()
    doc["scene"]["room"] = "FloorPlan1"
    with pytest.raises(CDFValidationError, match="unknown room"):
        C.from_document(doc)


def test_python_data_is_checked_like_text() -> None:
    deep: object = "leaf"
    for _ in range(5000):
        deep = [deep]
    doc = base()
    doc["description"] = deep
    with pytest.raises(CDFValidationError, match="nested deeper"):
        C.from_document(doc)
    loop: dict = base()
    loop["scene"]["self"] = loop
    with pytest.raises(CDFValidationError, match="refers to itself"):
        C.from_document(loop)
