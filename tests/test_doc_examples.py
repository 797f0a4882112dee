"""The examples in the docs run, so that the docs cannot drift from the code.

Every fenced ```python block of README.md, docs/*.md and envs/README.md runs: a page's python blocks run in
order as one program (a block may use what an earlier one on the page defined), in a subprocess in a
temporary folder that holds links to the repository's `cdf/`, `envs/` and `examples/` (so relative paths in
the examples resolve and whatever they write lands in the temporary folder). Every ```bash/```sh block runs
too, one subprocess per block; each of its commands must be a `luminous ...` command.

A block that cannot run here (it needs a cluster, your own data or model, or runs for minutes) is marked on
the line before it with `<!-- not-run: why -->`; a heavier block that should still run now and then is
marked `<!-- slow: why -->` (it runs with `-m slow`). Both need a reason.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
PAGES = sorted([REPO / "README.md", REPO / "envs" / "README.md", *(REPO / "docs").glob("*.md")])
RUN_LANGS = {"python": "python", "py": "python", "bash": "shell", "sh": "shell", "shell": "shell",
             "console": "shell"}
MARK = re.compile(r"<!--\s*(not-run|slow)\s*:?(.*?)-->")
LINKED = ("cdf", "envs", "examples")
TIMEOUT = {"fast": 240, "slow": 600}


@dataclass(frozen=True)
class Block:
    page: Path
    line: int
    """1-based line of the opening fence."""
    kind: str
    """`python` or `shell`."""
    code: str
    mark: str
    """"", "not-run" or "slow"."""
    reason: str

    @property
    def where(self) -> str:
        return f"{self.page.relative_to(REPO)}:{self.line}"


def blocks(page: Path) -> list[Block]:
    """The runnable-language fenced blocks of a page, with the marker on the line before each."""
    lines = page.read_text(encoding="utf-8").splitlines()
    out: list[Block] = []
    i = 0
    while i < len(lines):
        m = re.match(r"^```(\w+)\s*$", lines[i])
        if m is None and lines[i].startswith("```"):
            i = _fence_end(lines, i) + 1
            continue
        if m is None:
            i += 1
            continue
        end = _fence_end(lines, i)
        lang = m[1].lower()
        if lang in RUN_LANGS:
            before = lines[i - 1] if i else ""
            mark = MARK.search(before)
            out.append(Block(page, i + 1, RUN_LANGS[lang], "\n".join(lines[i + 1:end]) + "\n",
                             mark[1] if mark else "", mark[2].strip() if mark else ""))
        i = end + 1
    return out


def _fence_end(lines: list[str], start: int) -> int:
    for j in range(start + 1, len(lines)):
        if lines[j].startswith("```"):
            return j
    raise AssertionError(f"an unclosed ``` fence at line {start + 1}")


ALL = [b for page in PAGES for b in blocks(page)]


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(REPO), env.get("PYTHONPATH", "")) if p)
    env["PATH"] = os.pathsep.join((str(Path(sys.executable).parent), env.get("PATH", "")))
    env["MPLBACKEND"] = "Agg"
    return env


def _workdir(tmp_path: Path) -> Path:
    for name in LINKED:
        (tmp_path / name).symlink_to(REPO / name, target_is_directory=True)
    return tmp_path


def _run(cmd: list[str], cwd: Path, where: str, timeout: int) -> None:
    out = subprocess.run(cmd, cwd=cwd, env=_env(), capture_output=True, text=True, timeout=timeout, check=False)
    assert out.returncode == 0, (f"the example at {where} failed (exit {out.returncode}):\n"
                                 f"{out.stdout[-3000:]}\n{out.stderr[-5000:]}")


def _speed(marks: list[str]) -> list:
    return [pytest.mark.slow] if "slow" in marks else []


def _python_cases() -> list:
    cases = []
    for page in PAGES:
        run = [b for b in ALL if b.page == page and b.kind == "python" and b.mark != "not-run"]
        if run:
            cases.append(pytest.param(page, id=str(page.relative_to(REPO)),
                                      marks=_speed([b.mark for b in run])))
    return cases


def _shell_cases() -> list:
    return [pytest.param(b, id=b.where, marks=_speed([b.mark]))
            for b in ALL if b.kind == "shell" and b.mark != "not-run"]


def _commands(code: str) -> list[str]:
    """The commands of a shell block: comments dropped, backslash continuations joined."""
    joined = re.sub(r"\\\n\s*", " ", code)
    return [c for c in (ln.split(" #")[0].strip() for ln in joined.splitlines()) if c and not c.startswith("#")]


@pytest.mark.parametrize("page", _python_cases())
def test_a_pages_python_examples_run(page: Path, tmp_path: Path):
    run = [b for b in ALL if b.page == page and b.kind == "python" and b.mark != "not-run"]
    program = "".join(f"# --- {b.where}\n{b.code}" for b in run)
    script = tmp_path / "doc_example.py"
    script.write_text(program, encoding="utf-8")
    slow = any(b.mark == "slow" for b in run)
    work = tmp_path / "work"
    work.mkdir()
    _run([sys.executable, str(script)], _workdir(work), ", ".join(b.where for b in run),
         TIMEOUT["slow" if slow else "fast"])


@pytest.mark.parametrize("block", _shell_cases())
def test_a_shell_example_runs(block: Block, tmp_path: Path):
    commands = _commands(block.code)
    wrong = [c for c in commands if not c.startswith("luminous ")]
    assert not wrong, (f"{block.where}: only `luminous ...` commands run here; mark the block "
                       f"<!-- not-run: why --> or <!-- slow: why -->: {wrong}")
    script = tmp_path / "doc_example.sh"
    script.write_text("set -euo pipefail\n" + "\n".join(commands) + "\n", encoding="utf-8")
    work = tmp_path / "work"
    work.mkdir()
    _run(["bash", str(script)], _workdir(work), block.where, TIMEOUT["slow" if block.mark == "slow" else "fast"])


def test_every_marker_has_a_reason_and_a_block():
    problems = []
    for page in PAGES:
        lines = page.read_text(encoding="utf-8").splitlines()
        for i, line in enumerate(lines):
            m = MARK.search(line)
            if m is None:
                continue
            where = f"{page.relative_to(REPO)}:{i + 1}"
            if not m[2].strip():
                problems.append(f"{where}: <!-- {m[1]}: ... --> needs a reason")
            after = lines[i + 1] if i + 1 < len(lines) else ""
            lang = re.match(r"^```(\w+)", after)
            if not lang or lang[1].lower() not in RUN_LANGS:
                problems.append(f"{where}: a {m[1]} marker must sit on the line just before a ```python or "
                                "```bash block")
    assert not problems, "\n".join(problems)


def test_the_examples_are_found():
    """The extraction works: the pages hold runnable examples, some of which run in the fast suite."""
    run = [b for b in ALL if b.mark == ""]
    assert any(b.kind == "python" for b in run) and any(b.kind == "shell" for b in run), ALL
    assert {p.name for p in PAGES} >= {"README.md", "env.md", "cdf.md", "architecture.md"}


def test_relative_links_point_at_files():
    """Every relative link of the pages names a file or folder that exists (anchors are not checked)."""
    broken = []
    for page in PAGES:
        text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            path = target.split("#", 1)[0]
            if not path or re.match(r"^[a-z]+:", path):
                continue
            if not (page.parent / path).exists():
                broken.append(f"{page.relative_to(REPO)}: {target}")
    assert not broken, "broken links:\n" + "\n".join(broken)
