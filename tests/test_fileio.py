"""The one home of atomic writes and one-line message text (`luminous_sim.fileio`)."""

from __future__ import annotations

import os

import pytest

from luminous_sim.fileio import atomic_file, one_line, shown, write_atomic


def test_a_write_that_fails_leaves_the_old_file_and_no_temporary(tmp_path):
    path = tmp_path / "out.json"
    write_atomic(path, "old\n")
    with pytest.raises(RuntimeError), atomic_file(path) as tmp:
        tmp.write_text("half")
        raise RuntimeError("killed mid-write")
    assert path.read_text() == "old\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.json"]


def test_a_finished_write_replaces_the_file_with_ordinary_permissions(tmp_path):
    path = tmp_path / "sub" / "video.mp4"
    with atomic_file(path, suffix=".mp4") as tmp:
        assert tmp.suffix == ".mp4" and tmp.parent == path.parent
        tmp.write_bytes(b"new")
    umask = os.umask(0)
    os.umask(umask)
    assert path.read_bytes() == b"new" and (path.stat().st_mode & 0o777) == (0o666 & ~umask)


def test_messages_are_one_line_and_cut():
    assert one_line("a\nb\t c", 100) == "a b c"
    assert one_line("x" * 50, 10) == "x" * 7 + "..."
    assert shown("line\nbreak", 60) == "'line\\nbreak'"
    assert len(shown(list(range(100)), 20)) == 20


def test_the_old_home_still_works_with_a_warning():
    from luminous_sim.assets import objio

    with pytest.warns(DeprecationWarning, match="luminous_sim.fileio.write_atomic"):
        assert objio.write_atomic is write_atomic
