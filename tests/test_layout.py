"""The layout is the architecture: no module of the engine imports, even inside a function, a
module that imports it back (directly or through others)."""
import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent / "stiefelsym"


def _modules() -> dict[str, Path]:
    out = {}
    for p in ROOT.rglob("*.py"):
        parts = list(p.relative_to(ROOT.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = p
    return out


def _edges(mods: dict[str, Path]) -> dict[str, set[str]]:
    edges: dict[str, set[str]] = {m: set() for m in mods}
    for m, p in mods.items():
        pkg = m if p.name == "__init__.py" else m.rsplit(".", 1)[0]
        for node in ast.walk(ast.parse(p.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                if node.level:
                    base = pkg.split(".")[: len(pkg.split(".")) - node.level + 1]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                subs = [f"{target}.{a.name}" for a in node.names if f"{target}.{a.name}" in mods]
                for c in (subs if subs and len(subs) == len(node.names) else [target] + subs):
                    if c in mods and c != m:
                        edges[m].add(c)
            elif isinstance(node, ast.Import):
                edges[m].update(a.name for a in node.names if a.name in mods and a.name != m)
    return edges


def _cycles(edges: dict[str, set[str]]) -> list[list[str]]:
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))
    for v in edges:
        if v not in index:
            visit(v)
    return out


def test_no_import_circle_in_the_engine():
    assert _cycles(_edges(_modules())) == []


def test_the_detector_sees_a_circle():
    assert _cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": set()}) == [["a", "b", "c"]]


def test_a_fixed_size_run_loads_neither_the_free_algebra_nor_its_checker():
    """The families of sizes a claim is stated on (read by every run) live apart from the dimension-free
    method: a modular run's process imports neither the free algebra, nor that method, nor the
    certificate checker (start-up time of a one-claim run)."""
    import subprocess
    import sys
    code = ("import sys\n"
            "from stiefelsym.run.runner import run_one\n"
            "from stiefelsym.claims import load_catalog, Size\n"
            "c = load_catalog().get('neumann-flow')\n"
            "res = run_one(c, Size(2, 1), 'modular', 0)\n"
            "assert res.verdict == 'checked', res.verdict\n"
            "print(' '.join(sorted(m for m in sys.modules if m.startswith('stiefelsym'))))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert "stiefelsym.methods.families" in out
    for m in ("stiefelsym.free", "stiefelsym.methods.dimension_free", "stiefelsym.certificate_check"):
        assert m not in out, m


def test_no_review_file_under_tests_is_collected_or_imported_by_pytest():
    """The files of the reviews (tests/adversary/sNN/) replace what gives verdicts in the process that imports them;
    none may be a file pytest collects or imports on its own in the project's test run (a test module, a conftest,
    a doctest text file, the __init__.py of a package with code): they are kept as *.in and copied under their
    names by the tests that run them."""
    adversary = ROOT.parent / "tests" / "adversary"
    found = []
    for p in adversary.rglob("*"):
        if p.parent == adversary or not p.is_file():
            continue
        name = p.name
        if name.startswith("test_") and name.endswith(".py") or name.endswith("_test.py") or name == "conftest.py" \
                or name.startswith("test") and name.endswith(".txt"):
            found.append(p)
        elif name == "__init__.py" and p.read_text(encoding="utf-8").strip() not in ("", "# ruff: noqa"):
            found.append(p)
    assert not found, found
