"""examples/python/compensation.ipynb runs headless (Debian's nbclient and ipykernel) without a
cell error, draws its figures, and its kernel imports the multicpg this test imports.

MULTICPG_NOTEBOOK_KERNEL names the kernel to run it with (tests/python_install_test.sh: a venv's
kernel, docs/python.md "The notebook from the venv"); by default Debian's python3."""

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
KERNEL = os.environ.get("MULTICPG_NOTEBOOK_KERNEL")


def test_the_notebook_runs_and_draws_its_figures(tmp_path, monkeypatch):
    package = pathlib.Path(multicpg.__file__).resolve().parent
    if KERNEL is None:
        # Debian's interpreter, started in tmp_path: it finds the multicpg this test imports (a
        # build folder or an installed one) by absolute path.
        monkeypatch.setenv("PYTHONPATH",
                           os.pathsep.join([str(package.parent), os.environ.get("PYTHONPATH", "")]))
    else:
        # The named kernel's interpreter finds multicpg on its own.
        monkeypatch.delenv("PYTHONPATH", raising=False)
    monkeypatch.setenv("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # ipykernel's debugger notice
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    notebook.cells.append(nbformat.v4.new_code_cell("print('multicpg from', multicpg.__file__)"))
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name=KERNEL or "python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()  # raises CellExecutionError, with the cell and its traceback, on an error
    outputs = [o for cell in notebook.cells if cell.cell_type == "code"
               for o in cell.get("outputs", [])]
    assert not [o for o in outputs if o.get("output_type") == "error"]
    figures = [o for o in outputs if "image/png" in o.get("data", {})]
    assert len(figures) == FIGURES
    text = "".join(o.get("text", "") for o in outputs if o.get("output_type") == "stream")
    assert "converged" in text and "notebook ran in" in text
    imported = pathlib.Path(text.split("multicpg from ")[1].strip()).resolve()
    assert imported.parent == package, imported
