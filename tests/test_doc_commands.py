"""Every `stiefelsym` command shown in the README and the docs is a command the CLI accepts (its
options and values parse), and the transcripts of docs/discover.md are what the commands print."""
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import click
import pytest

from stiefelsym.cli import main

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md"] + sorted(p for p in (ROOT / "docs").glob("*.md") if p.name != "index.md")


def _blocks(text: str) -> list[str]:
    return re.findall(r"```(?:sh|console|bash)\n(.*?)```", text, re.S)


def _commands() -> list[tuple[str, str]]:
    out = []
    for path in DOCS:
        for block in _blocks(path.read_text(encoding="utf-8")):
            lines = block.replace("\\\n", " ").splitlines()
            for line in lines:
                line = line.strip().removeprefix("$ ")
                if line.startswith("stiefelsym "):
                    out.append((path.name, line.split("  #")[0].split(" # ")[0].strip()))
    return out


COMMANDS = _commands()


def test_the_docs_show_commands():
    assert len(COMMANDS) >= 30


@pytest.fixture(scope="module")
def workdir(tmp_path_factory):
    """A folder like a user's: their claims file, the examples, a results file."""
    d = tmp_path_factory.mktemp("user")
    shutil.copy(ROOT / "examples" / "my_claims.py", d / "my_claims.py")
    (d / "examples").symlink_to(ROOT / "examples")
    (d / "reports").mkdir()
    shutil.copy(ROOT / "reports" / "results.json", d / "reports" / "results.json")
    return d


@pytest.mark.parametrize("where, command", COMMANDS, ids=[f"{w}:{c[11:50]}" for w, c in COMMANDS])
def test_every_documented_command_parses(where, command, workdir, monkeypatch):
    """The command's options, choices and values are accepted by the CLI (parsed, not run: some
    take minutes or need a cluster)."""
    monkeypatch.chdir(workdir)
    argv = shlex.split(command.split(" > ")[0])[1:]
    ctx = main.make_context("stiefelsym", list(argv), resilient_parsing=False)
    protected = ctx._protected_args if hasattr(ctx, "_protected_args") else ctx.protected_args
    args = [*protected, *ctx.args]
    name, cmd, rest = main.resolve_command(ctx, args)
    assert cmd is not None, (where, command)
    try:
        cmd.make_context(name, rest, parent=ctx)
    except click.exceptions.Exit:
        pass


def _transcripts() -> list[tuple[str, list[str]]]:
    """(command, printed lines) of docs/discover.md's `$ stiefelsym ...` transcripts."""
    out = []
    for block in _blocks((ROOT / "docs" / "discover.md").read_text(encoding="utf-8")):
        cur = None
        for line in block.splitlines():
            if line.startswith("$ stiefelsym "):
                cur = (line[2:], [])
                out.append(cur)
            elif cur is not None and line.strip():
                cur[1].append(line)
    return [t for t in out if t[1]]


def _normal(line: str) -> str:
    return re.sub(r"in [0-9.]+ s\b", "in … s", line.rstrip())


@pytest.mark.parametrize("command, printed", _transcripts(), ids=lambda x: x[11:50] if isinstance(x, str) else "")
def test_the_discover_transcripts_are_what_the_commands_print(command, printed):
    exe = Path(sys.executable).parent / "stiefelsym"
    proc = subprocess.run([str(exe)] + shlex.split(command)[1:], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr[-2000:]
    got = [_normal(x) for x in proc.stdout.splitlines()]
    assert [_normal(x) for x in printed] == got
