"""The README and the docs: the first claim of the README proves, the site builds strictly, and
docs/index.md is the README with its links made relative to docs/."""
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent


def test_the_readme_is_short_and_its_first_claim_is_proved(tmp_path):
    from stiefelsym.claims import Size, load_claims_file
    from stiefelsym.run.runner import run_one
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(text.splitlines()) < 200
    code = re.search(r"```python\n(# my_claims.py\n.*?)```", text, re.S).group(1)
    path = tmp_path / "my_claims.py"
    path.write_text(code, encoding="utf-8")
    c = next(iter(load_claims_file(str(path))))
    assert run_one(c, Size(4, 2), "exact", 0).verdict == "proved"
    assert run_one(c, None, "free", 0).verdict == "proved"


def test_docs_index_is_the_readme():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    index = (ROOT / "docs" / "index.md").read_text(encoding="utf-8")
    assert index == re.sub(r"\(docs/([a-z]+\.md)\)", r"(\1)", readme)


@pytest.mark.skipif(shutil.which("mkdocs") is None and not (Path(sys.executable).parent / "mkdocs").exists(),
                    reason="mkdocs is not installed")
def test_the_site_builds_strictly(tmp_path):
    exe = Path(sys.executable).parent / "mkdocs"
    r = subprocess.run([str(exe) if exe.exists() else "mkdocs", "build", "--strict", "-d", str(tmp_path / "site")],
                       cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
