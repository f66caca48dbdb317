"""examples/python/compensation.ipynb runs headless (Debian's nbclient and ipykernel) without a
cell error, and draws its figures."""

import os
import pathlib

import nbclient
import nbformat

import multicpg
from conftest import SOURCE_DIR

NOTEBOOK = SOURCE_DIR / "examples" / "python" / "compensation.ipynb"
# Cells that draw a figure: walk (path and gait), R1 failed, the trace, after learning, the
# landscape.
FIGURES = 5


def test_the_notebook_runs_and_draws_its_figures(tmp_path, monkeypatch):
    # The kernel is another interpreter started in tmp_path: it finds the multicpg this test
    # imports (a build folder or an installed one) by absolute path.
    here = str(pathlib.Path(multicpg.__file__).resolve().parents[1])
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join([here, os.environ.get("PYTHONPATH", "")]))
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # ipykernel's debugger notice
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError, with the cell and its traceback, on an error
    outputs = [o for cell in notebook.cells if cell.cell_type == "code"
               for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    figures = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(figures) == FIGURES
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "converged" in text and "notebook ran in" in text
