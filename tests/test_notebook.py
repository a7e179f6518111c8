"""The example notebook (examples/notebook.ipynb) runs top to bottom in a fresh kernel, and its
results display as Markdown and LaTeX."""
from pathlib import Path

import pytest

NOTEBOOK = Path(__file__).resolve().parents[1] / "examples" / "notebook.ipynb"


def test_the_example_notebook_runs(tmp_path):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    pytest.importorskip("ipykernel")
    nb = nbformat.read(NOTEBOOK, as_version=4)
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    shown = [o["data"] for o in outputs if o.get("output_type") == "execute_result"]
    assert any("text/markdown" in d and "text/latex" in d for d in shown)
    assert any("**euclidean-flow**" in d.get("text/markdown", "") for d in shown)
    assert any("**fails**" in d.get("text/markdown", "") for d in shown)
