"""A resumed build trusts nothing it has not checked (issue 27): a trial deleted or damaged is done again, a
manifest line altered or forged is left out and its job done again, a forged path never makes the build
write or delete outside its folder, a smaller count is refused, and several splits stay apart.

Most tests use a job kind of their own that writes a small trial in microseconds, so that hypothesis can
corrupt builds at random and rerun them many times; one test does the issue's cases on a real S+ build.
"""

from __future__ import annotations

import json
import shutil
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from luminous_sim.data import BuildError, BuildOptions, JobOutcome, Manifest, ManifestError, build, build_split
from luminous_sim.data.build import MANIFEST, PARTIAL, SETTINGS, SPLITS
from tests.conftest import file_tree

QUICK = BuildOptions(frames=False, video=False)
N = 5


@dataclass(frozen=True)
class _Writing:
    """A job that writes a trial of two files derived from its key (or fails, every third one)."""

    split: str
    order: int
    task_type: str = "pick_and_place_simple"

    @property
    def key(self) -> str:
        return f"{self.split}/{self.order:06d}"

    def run(self, work: Path, options: BuildOptions) -> JobOutcome:
        if self.order % 3 == 2:
            return JobOutcome(stage="task", cause=f"no Mug in {self.order}", details={"n": self.order})
        trial = work / f"{self.task_type}-Mug-{self.order}" / f"trial_{self.order:03d}"
        (trial / "pddl_states").mkdir(parents=True)
        (trial / "traj_data.json").write_text(json.dumps({"task_id": trial.name, "key": self.key}))
        (trial / "pddl_states" / "s.json").write_text(self.key * 10)
        return JobOutcome(trial=trial, details={"n": self.order})


def jobs(split: str = "mine", count: int = N) -> list[_Writing]:
    return [_Writing(split, i) for i in range(count)]


tree = file_tree


@pytest.fixture()
def reference(tmp_path) -> Path:
    out = tmp_path / "reference"
    build(out, jobs(), options=QUICK, progress=False)
    return out


@pytest.fixture()
def victim(tmp_path) -> Path:
    """A folder outside every build that nothing may touch."""
    path = tmp_path / "elsewhere" / "VICTIM"
    path.mkdir(parents=True)
    (path / "precious.txt").write_text("mine")
    return path


def _trials(out: Path, split: str = "mine") -> list[Path]:
    return sorted(p for p in (out / split).glob("*/*") if p.is_dir())


def test_a_deleted_trial_is_built_again_and_listed(reference, tmp_path):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    shutil.rmtree(_trials(out)[0])
    report = build(out, jobs(), options=QUICK, progress=False)
    assert report.ran == 1 and report.redone == ("mine/000000",)
    assert "done again: mine/000000" in report.summary()
    assert tree(out) == tree(reference)


def test_a_damaged_trial_file_is_built_again(reference, tmp_path):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    (_trials(out)[1] / "traj_data.json").write_text("garbage")
    (_trials(out)[0] / "extra.txt").write_text("not written by the job")
    report = build(out, jobs(), options=QUICK, progress=False)
    assert report.ran == 2 and set(report.redone) == {"mine/000000", "mine/000001"}
    assert tree(out) == tree(reference)


def test_a_forged_trial_path_is_refused_and_nothing_outside_is_touched(reference, tmp_path, victim):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    lines = (out / MANIFEST).read_text().splitlines()
    record = json.loads(lines[0])
    record["trial"] = "../../../../elsewhere/VICTIM"
    lines[0] = json.dumps(record)
    (out / MANIFEST).write_text("\n".join(lines) + "\n")
    before = tree(victim.parent)
    with pytest.raises(ManifestError, match=r"manifest.jsonl: line 1: field 'trial': expected <task>/<trial>"):
        Manifest(out / MANIFEST)
    report = build(out, jobs(), options=QUICK, progress=False)
    assert report.ran == 1 and "field 'trial'" in report.rejected[0] and "line 1" in report.rejected[0]
    assert tree(victim.parent) == before
    assert tree(out) == tree(reference)
    assert all(".." not in e["task"] for e in json.loads((out / SPLITS).read_text())["mine"])


def test_a_record_with_the_right_check_but_a_forged_path_is_refused_too(reference, tmp_path, victim):
    from luminous_sim.data.manifest import _line

    out = tmp_path / "b"
    shutil.copytree(reference, out)
    records = [json.loads(line) for line in (out / MANIFEST).read_text().splitlines()]
    for r in records:
        r.pop("check")
    records[0]["trial"] = "../../../../elsewhere/VICTIM"
    (out / MANIFEST).write_text("".join(_line(r) for r in records))  # a forger who knows the digest
    before = tree(victim.parent)
    report = build(out, jobs(), options=QUICK, progress=False)
    assert "field 'trial'" in report.rejected[0]
    assert tree(victim.parent) == before and tree(out) == tree(reference)


@pytest.mark.parametrize("field", ["split", "order", "key", "status", "sha256", "files", "trial", "check"])
def test_a_record_missing_a_field_is_named_and_its_job_done_again(reference, tmp_path, field):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    lines = (out / MANIFEST).read_text().splitlines()
    record = json.loads(lines[1])
    del record[field]
    lines[1] = json.dumps(record)
    (out / MANIFEST).write_text("\n".join(lines) + "\n")
    with pytest.raises(ManifestError, match=f"line 2: field '{field}'"):
        Manifest(out / MANIFEST)
    report = build(out, jobs(), options=QUICK, progress=False)
    assert f"field '{field}'" in report.rejected[0] and not (out / PARTIAL).exists()
    assert tree(out) == tree(reference)


def test_links_planted_in_the_build_are_removed_never_followed(reference, tmp_path, victim):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    (victim / "task" / "trial_9").mkdir(parents=True)
    (victim / "task" / "trial_9" / "f").write_text("keep")
    before = tree(victim.parent)
    trial = _trials(out)[0]
    (out / "mine" / "linked-task").symlink_to(victim / "task")  # a task folder that is a link
    shutil.rmtree(trial)
    trial.symlink_to(victim)  # a trial folder that is a link
    (out / PARTIAL).symlink_to(victim)  # .partial a link: the run id must not land in the victim
    build(out, jobs(), options=QUICK, progress=False)
    assert tree(victim.parent) == before
    assert tree(out) == tree(reference)


def test_a_split_folder_that_is_a_link_is_replaced(reference, tmp_path, victim):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    shutil.rmtree(out / "mine")
    (out / "mine").symlink_to(victim.parent)
    before = tree(victim.parent)
    report = build(out, jobs(), options=QUICK, progress=False)
    assert len(report.redone) == 4  # every built trial of the split
    assert tree(victim.parent) == before and tree(out) == tree(reference)


def test_a_smaller_count_is_refused_and_a_larger_one_extends(reference, tmp_path):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    with pytest.raises(BuildError, match=r"manifest.jsonl holds 2 finished job\(s\) of split mine .*at least 5, not 3"):
        build(out, jobs(count=3), options=QUICK, progress=False)
    assert tree(out) == tree(reference)
    report = build(out, jobs(count=7), options=QUICK, progress=False)
    assert report.ran == 2 and len(json.loads((out / SPLITS).read_text())["mine"]) == 3 * 5


def test_several_splits_stay_apart(reference, tmp_path):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    report = build(out, jobs("other", 2), options=QUICK, progress=False)
    assert report.others == {"mine": 4} and "also holds 4 trial(s) of mine" in report.summary()
    listed = json.loads((out / SPLITS).read_text())
    assert set(listed) == {"mine", "other"} and len(listed["other"]) == 2 * 3 and len(listed["mine"]) == 4 * 3
    again = build(out, jobs(), options=QUICK, progress=False)  # the first split resumes as it was
    assert again.ran == 0 and again.others == {"other": 2}


def test_a_damaged_trial_of_another_split_is_no_longer_listed(reference, tmp_path):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    (_trials(out)[0] / "traj_data.json").write_text("x")
    report = build(out, jobs("other", 1), options=QUICK, progress=False)
    assert report.dropped == ("mine/000000",) and "build their split again" in report.summary()
    assert len(json.loads((out / SPLITS).read_text())["mine"]) == 3 * 3
    build(out, jobs(), options=QUICK, progress=False)
    assert len(json.loads((out / SPLITS).read_text())["mine"]) == 4 * 3


@pytest.mark.parametrize("content,match", [("[]", "expected a JSON object"), ("{", "not JSON")])
def test_a_broken_settings_file_is_named(reference, tmp_path, content, match):
    out = tmp_path / "b"
    shutil.copytree(reference, out)
    (out / SETTINGS).write_text(content)
    with pytest.raises(BuildError, match=f"build.json: {match}"):
        build(out, jobs(), options=QUICK, progress=False)


def test_a_manifest_that_is_a_folder_is_named(tmp_path):
    out = tmp_path / "b"
    build(out, jobs(count=1), options=QUICK, progress=False)
    (out / MANIFEST).unlink()
    (out / MANIFEST).mkdir()
    with pytest.raises(ManifestError, match="manifest.jsonl: a folder; expected the build.s manifest"):
        build(out, jobs(count=1), options=QUICK, progress=False)


def test_counts_over_the_limit_are_refused_before_any_work(tmp_path, capsys):
    from luminous_sim.cli.main import main
    from luminous_sim.data import split_jobs

    with pytest.raises(BuildError, match="count must be from 0 to 100000"):
        split_jobs("S+", 2**63 - 1)
    with pytest.raises(SystemExit) as exc:
        main(["dataset", "build", "--split", "S+", "--count", str(2**63 - 1), "--out", str(tmp_path / "b")])
    assert exc.value.code == 2
    assert "argument --count: expected a whole number from 0 to 100000" in capsys.readouterr().err
    assert not (tmp_path / "b").exists()


# ---------------------------------------------------------------- at random

def _corrupt_bytes(data: bytes, draw) -> bytes:
    kind = draw(st.sampled_from(["truncate", "splice", "flip", "line"]))
    if kind == "truncate":
        return data[: draw(st.integers(0, len(data)))]
    if kind == "splice":
        i = draw(st.integers(0, len(data)))
        j = draw(st.integers(i, min(len(data), i + 40)))
        return data[:i] + draw(st.binary(max_size=40)) + data[j:]
    if kind == "flip":
        i = draw(st.integers(0, len(data) - 1))
        return data[:i] + bytes([data[i] ^ draw(st.integers(1, 255))]) + data[i + 1:]
    lines = data.split(b"\n")
    i = draw(st.integers(0, len(lines) - 1))
    lines[i] = draw(st.sampled_from([b"[]", b"{}", b"null", b"1e999", b"[" * 5000, b'{"key": 3}', b""]))
    return b"\n".join(lines)


JSON = st.recursive(st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20),
                    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner, max_size=3),
                    max_leaves=6)
FORGED = st.sampled_from(["../../../../elsewhere/VICTIM", "/tmp", "a/../../b", ".hidden/t", "a/b/c", "a", "..", ""])


def _corrupt_record(data: bytes, draw) -> bytes:
    lines = data.decode().splitlines()
    i = draw(st.integers(0, len(lines) - 1))
    record = json.loads(lines[i])
    name = draw(st.sampled_from(sorted(record)))
    action = draw(st.sampled_from(["delete", "value", "path"]))
    if action == "delete":
        del record[name]
    elif action == "value":
        record[name] = draw(JSON)
    else:
        record[draw(st.sampled_from(["trial", "split", "key"]))] = draw(FORGED)
    lines[i] = json.dumps(record)
    return ("\n".join(lines) + "\n").encode()


def _corrupt_files(out: Path, draw) -> None:
    trials = _trials(out)
    trial = draw(st.sampled_from(trials))
    kind = draw(st.sampled_from(["delete", "garbage", "truncate", "extra", "remove_file", "link"]))
    target = trial / draw(st.sampled_from(["traj_data.json", "pddl_states/s.json"]))
    if kind == "delete":
        shutil.rmtree(trial)
    elif kind == "garbage":
        target.write_bytes(draw(st.binary(max_size=50)))
    elif kind == "truncate":
        target.write_bytes(target.read_bytes()[: draw(st.integers(0, 5))])
    elif kind == "extra":
        (trial / draw(st.sampled_from(["x.json", "pddl_states/y"]))).write_text("extra")
    elif kind == "remove_file":
        target.unlink()
    else:
        target.unlink()
        target.symlink_to(out.parent / "elsewhere" / "VICTIM" / "precious.txt")


def _corrupt_and_rerun(data, reference: Path, victim: Path, tmp_path_factory) -> None:
    out = tmp_path_factory.mktemp("corrupt") / "b"
    shutil.copytree(reference, out)
    (out.parent / "elsewhere").symlink_to(victim.parent)
    before = tree(victim.parent)
    what = data.draw(st.sampled_from(["bytes", "record", "files", "files+record"]))
    manifest = out / MANIFEST
    if what == "bytes":
        manifest.write_bytes(_corrupt_bytes(manifest.read_bytes(), data.draw))
    if what in ("files", "files+record"):
        _corrupt_files(out, data.draw)
    if what in ("record", "files+record"):
        manifest.write_bytes(_corrupt_record(manifest.read_bytes(), data.draw))
    report = build(out, jobs(), options=QUICK, progress=False)  # no exception: every altered line is told
    assert all("manifest.jsonl: line " in r for r in report.rejected)
    assert tree(victim.parent) == before
    (out.parent / "elsewhere").unlink()
    assert tree(out) == tree(reference)


FUZZ = {"deadline": None, "suppress_health_check": [HealthCheck.function_scoped_fixture]}


@settings(max_examples=60, **FUZZ)
@given(data=st.data())
def test_random_corruption_of_manifest_and_trials_then_a_rerun_gives_the_uninterrupted_tree(
        data, reference, victim, tmp_path_factory):
    _corrupt_and_rerun(data, reference, victim, tmp_path_factory)


@pytest.mark.slow(reason="2,000 random corruptions, about a minute")
@settings(max_examples=2000, **FUZZ)
@given(data=st.data())
def test_many_random_corruptions(data, reference, victim, tmp_path_factory):
    _corrupt_and_rerun(data, reference, victim, tmp_path_factory)


def test_the_issue_cases_on_a_real_split_build(tmp_path, capsys):
    """A real S+ build (no frames): a deleted trial and a traj_data.json overwritten with garbage are built
    again by the CLI's rerun, and a forged trial path touches nothing outside the folder."""
    from luminous_sim.cli.main import main

    out = tmp_path / "b"
    build_split(out, "S+", 2, options=QUICK, progress=False)
    reference = tree(out)
    trials = sorted(p for p in (out / "S+").glob("*/*") if p.is_dir())
    assert len(trials) == 2
    shutil.rmtree(trials[0])
    (trials[1] / "traj_data.json").write_text("garbage")
    argv = ["dataset", "build", "--split", "S+", "--count", "2", "--out", str(out), "--no-frames", "--no-progress"]
    assert main(argv) == 0
    assert "2 finished trial(s) missing or damaged, done again" in capsys.readouterr().out
    assert tree(out) == reference
    assert main(argv[:5] + ["1"] + argv[6:]) == 2
    assert "a build is extended, never shrunk" in capsys.readouterr().err
