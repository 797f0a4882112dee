"""The asset library's integrity: a digest of its catalog and of every file the catalog lists, compared with the
digest shipped in code before the library is used. The frozen splits' episode keys depend on the assets' sizes,
so a library rebuilt with other coacd or numpy versions would silently make another benchmark: it is refused.

Hashing the library (about 47 MB) costs a fraction of a second; a process checks it once, and a stamp in the
cache folder, named by every listed file's size, mtime and inode, lets later processes skip the hashing until a
file changes.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
from functools import lru_cache
from pathlib import Path, PurePosixPath

from luminous_sim.errors import AssetError
from luminous_sim.resources.paths import ASSETS_VAR, asset_library_dir, cache_root, shipped_asset_library_dir

ASSET_LIBRARY_SHA256 = "cbab76162049ee1be8250ce8d98b7005fbfc607fea6adcef99552a47f96a6388"
"""`library_digest` of the shipped library. A deliberate rebuild (`luminous assets build`) changes it: put the
new value (`luminous assets digest`) here, and freeze the splits again if their episode keys changed."""
DIGEST_VAR = "LUMINOUS_ASSETS_DIGEST"
"""With `LUMINOUS_ASSETS` naming a library of one's own: the digest that library must have."""
CATALOG_NAME = "catalog.json"
STAMPS = "asset-checks"
BLOCK = 1 << 20


def listed_files(root: Path) -> list[str]:
    """The catalog and every file it lists (relative POSIX paths, sorted).

    Raises:
        AssetError: no catalog, an unreadable one, one listing no assets, or a listed path outside the library.
    """
    path = root / CATALOG_NAME
    if not path.is_file():
        raise AssetError(_missing(root, f"no {CATALOG_NAME} there"))
    try:
        assets = json.loads(path.read_text())["assets"]
        files = {CATALOG_NAME} | {f for a in assets for f in (*a["files"], a["urdf"], a.get("lod_urdf") or "") if f}
    except (ValueError, KeyError, TypeError) as exc:
        raise AssetError(f"{path}: not a valid asset catalog ({type(exc).__name__}: {exc})") from None
    if not assets:
        raise AssetError(_missing(root, f"its {CATALOG_NAME} lists no assets"))
    for rel in files:
        p = PurePosixPath(rel)
        if not isinstance(rel, str) or p.is_absolute() or ".." in p.parts or "\\" in rel:
            raise AssetError(f"{path}: lists {rel!r}, a path outside the library folder")
    return sorted(files)


def library_digest(root: Path) -> str:
    """SHA-256 over each listed file's path and content (the catalog included).

    Raises:
        AssetError: see `listed_files`; a listed file that is missing or not a regular file.
    """
    root = Path(root)
    h = hashlib.sha256()
    missing = []
    for rel in listed_files(root):
        path = root / rel
        if path.is_symlink() or not path.is_file():
            missing.append(rel)
            continue
        f = hashlib.sha256()
        with path.open("rb") as fh:
            while block := fh.read(BLOCK):
                f.update(block)
        h.update(rel.encode() + b"\0" + f.digest())
    if missing:
        raise AssetError(_missing(root, f"{len(missing)} file(s) its catalog lists are missing or not regular "
                                        f"files, e.g. {missing[0]}"))
    return h.hexdigest()


def _signature(root: Path) -> str:
    """A digest of every listed file's size, mtime and inode (what a stamp is named by)."""
    h = hashlib.sha256(str(root.resolve()).encode())
    for rel in listed_files(root):
        try:
            st = (root / rel).stat()
        except OSError:
            return ""
        h.update(f"{rel}\0{st.st_size}\0{st.st_mtime_ns}\0{st.st_ino}\n".encode())
    return h.hexdigest()


def verify_library(root: Path, expected: str) -> None:
    """Refuse the library at `root` unless its digest is `expected`.

    Raises:
        AssetError: a missing or incomplete library, or another digest (the message says what to do).
    """
    root = Path(root)
    signature = _signature(root)
    stamp = cache_root() / STAMPS / signature if signature else None
    with contextlib.suppress(OSError):  # an unreadable stamp only costs the hashing
        if stamp is not None and stamp.is_file() and not stamp.is_symlink() and stamp.read_text() == expected:
            return
    got = library_digest(root)
    if got != expected:
        shipped = root.resolve() == shipped_asset_library_dir().resolve()
        fix = ("reinstall luminous-sim (pip install --force-reinstall luminous-sim); a developer who rebuilt it "
               "on purpose puts the new digest in luminous_sim/resources/library_check.py" if shipped else
               f"for a library you built on purpose, set {DIGEST_VAR}={got}; else unset {ASSETS_VAR} to use the "
               "shipped library")
        raise AssetError(f"asset library {root}: digest {got[:16]}..., expected {expected[:16]}... (the frozen S+/U+ "
                         "episodes depend on the assets' sizes, so another library would make another benchmark); "
                         f"{fix}")
    if stamp is not None:
        _write_stamp(stamp, got)


def _write_stamp(stamp: Path, digest: str) -> None:
    from luminous_sim.fileio import write_atomic

    with contextlib.suppress(OSError):  # a read-only cache only costs the next process the hashing
        write_atomic(stamp, digest)


def _missing(root: Path, what: str) -> str:
    if root.resolve() == shipped_asset_library_dir().resolve():
        fix = "the package's own library is incomplete: reinstall luminous-sim (pip install --force-reinstall)"
    else:
        fix = f"{ASSETS_VAR} names it; unset it to use the shipped library, or build one with " \
              "`luminous assets build --out DIR`"
    return f"no asset library at {root} ({what}): {fix}"


@lru_cache(maxsize=4)
def _checked(root: str, expected: str) -> Path:
    verify_library(Path(root), expected)
    return Path(root)


def asset_library() -> Path:
    """The asset library folder in use, checked (once a process) against its digest: the shipped digest, or
    `$LUMINOUS_ASSETS_DIGEST` for a library `$LUMINOUS_ASSETS` names.

    Raises:
        AssetError: a missing, incomplete or other library.
    """
    root = asset_library_dir()
    own = os.environ.get(ASSETS_VAR, "").strip() and os.environ.get(DIGEST_VAR, "").strip()
    return _checked(str(root), own or ASSET_LIBRARY_SHA256)
