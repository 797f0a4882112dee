"""The shipped data (luminous_sim.resources): the asset library is checked against the digest in code before use,
and a missing, empty, incomplete or other library is an error naming what is missing, where, and what provides
it, never an empty catalog."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from luminous_sim.assets.catalog import Catalog
from luminous_sim.errors import AssetError
from luminous_sim.resources import (
    ASSET_LIBRARY_SHA256,
    asset_library,
    cache_root,
    library_check,
    library_digest,
    shipped_asset_library_dir,
    verify_library,
)


def _library(root: Path, assets: int = 1) -> Path:
    """A small library of its own: a catalog listing `assets` assets, each with a URDF and a mesh."""
    entries = []
    for i in range(assets):
        folder = root / "Mug" / f"Mug_{i:02d}"
        folder.mkdir(parents=True)
        (folder / f"Mug_{i:02d}.urdf").write_text(f"<robot name='Mug_{i:02d}'/>")
        (folder / "base.obj").write_text(f"v 0 0 {i}\n")
        entries.append({"id": f"Mug_{i:02d}", "urdf": f"Mug/Mug_{i:02d}/Mug_{i:02d}.urdf",
                        "files": [f"Mug/Mug_{i:02d}/base.obj"]})
    (root / "catalog.json").write_text(json.dumps({"version": 1, "assets": entries}))
    return root


def test_the_shipped_library_has_the_digest_in_code():
    assert library_digest(shipped_asset_library_dir()) == ASSET_LIBRARY_SHA256
    assert asset_library() == shipped_asset_library_dir()
    assert len(Catalog.load(include_user=False).types()) > 100


def test_a_changed_file_is_refused_with_its_digest_and_the_way_out(tmp_path):
    root = _library(tmp_path / "lib")
    good = library_digest(root)
    verify_library(root, good)
    (root / "Mug" / "Mug_00" / "base.obj").write_text("v 0 0 0.5\n")  # a mesh rebuilt with another coacd
    with pytest.raises(AssetError, match=r"digest [0-9a-f]{16}\.\.\., expected") as err:
        verify_library(root, good)
    assert "LUMINOUS_ASSETS_DIGEST=" in str(err.value) and str(root) in str(err.value)


@pytest.mark.parametrize("damage, message", [
    (lambda r: (r / "catalog.json").unlink(), "no catalog.json there"),
    (lambda r: (r / "catalog.json").write_text('{"version": 1, "assets": []}'), "lists no assets"),
    (lambda r: (r / "Mug" / "Mug_00" / "base.obj").unlink(), "missing or not regular files, e.g. Mug/Mug_00/base.obj"),
    (lambda r: (r / "catalog.json").write_text("{not json"), "not a valid asset catalog"),
    (lambda r: (r / "catalog.json").write_text(json.dumps(
        {"assets": [{"id": "x", "urdf": "../../etc/passwd", "files": []}]})), "outside the library folder"),
])
def test_a_missing_or_incomplete_library_names_what_is_missing(tmp_path, damage, message):
    root = _library(tmp_path / "lib")
    damage(root)
    with pytest.raises(AssetError, match=message) as err:
        library_digest(root)
    assert str(root) in str(err.value)


def test_an_empty_library_named_by_LUMINOUS_ASSETS_is_an_error_not_an_empty_catalog(tmp_path, monkeypatch, capsys):
    from luminous_sim.cli.main import main

    monkeypatch.setenv("LUMINOUS_ASSETS", str(tmp_path))
    with pytest.raises(AssetError, match=r"no asset library at .* \(no catalog.json there\): LUMINOUS_ASSETS"):
        Catalog.load()
    assert main(["assets", "list"]) == 2
    err = capsys.readouterr().err
    assert "no asset library at" in err and "luminous assets build" in err


def test_a_library_of_ones_own_needs_its_digest_named(tmp_path, monkeypatch):
    root = _library(tmp_path / "lib", assets=2)
    monkeypatch.setenv("LUMINOUS_ASSETS", str(root))
    with pytest.raises(AssetError, match="set LUMINOUS_ASSETS_DIGEST="):
        asset_library()
    monkeypatch.setenv("LUMINOUS_ASSETS_DIGEST", library_digest(root))
    assert asset_library() == root


def test_a_stamp_spares_the_hashing_until_a_file_changes(tmp_path, monkeypatch):
    root = _library(tmp_path / "lib")
    good = library_digest(root)
    monkeypatch.setenv("LUMINOUS_CACHE", str(tmp_path / "cache"))
    verify_library(root, good)
    assert list((cache_root() / library_check.STAMPS).iterdir())
    calls = []
    monkeypatch.setattr(library_check, "library_digest", lambda r: calls.append(r) or good)
    verify_library(root, good)
    assert calls == []  # the stamp matched: no hashing
    mesh = root / "Mug" / "Mug_00" / "base.obj"
    mesh.write_text("v 1 1 1\n")
    monkeypatch.undo()
    monkeypatch.setenv("LUMINOUS_CACHE", str(tmp_path / "cache"))
    with pytest.raises(AssetError, match="digest"):  # the change is seen: the stamp is named by sizes and mtimes
        verify_library(root, good)


def test_cache_root_follows_LUMINOUS_CACHE_then_XDG_CACHE_HOME_then_home(tmp_path, monkeypatch):
    monkeypatch.setenv("LUMINOUS_CACHE", str(tmp_path / "a"))
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert cache_root() == tmp_path / "a"
    monkeypatch.delenv("LUMINOUS_CACHE")
    assert cache_root() == tmp_path / "xdg" / "luminous"
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert cache_root() == tmp_path / "home" / ".cache" / "luminous"


def test_assets_digest_prints_a_librarys_digest(tmp_path, capsys):
    from luminous_sim.cli.main import main

    root = _library(tmp_path / "lib")
    assert main(["assets", "digest", str(root)]) == 0
    assert capsys.readouterr().out.startswith(f"{library_digest(root)}  {root} (not the shipped library's)")
    assert main(["assets", "digest"]) == 0
    assert f"{ASSET_LIBRARY_SHA256}  " in capsys.readouterr().out
