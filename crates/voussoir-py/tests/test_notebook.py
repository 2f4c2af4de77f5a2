"""The example notebook runs top to bottom and prints the paper's numbers."""

import re
import shutil
from pathlib import Path

import nbclient
import nbformat

import voussoir as v

NOTEBOOK = Path(__file__).resolve().parents[3] / "examples" / "python" / "paper-arch.ipynb"


def _text(cell):
    return "".join(o.get("text", "") for o in cell.get("outputs", []) if o.get("output_type") == "stream")


def test_notebook_executes(tmp_path):
    assert NOTEBOOK.is_file(), f"missing {NOTEBOOK}"
    nb = nbformat.read(NOTEBOOK, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute()  # raises CellExecutionError on any failing cell
    out = "\n".join(_text(c) for c in nb.cells if c.cell_type == "code")
    arch = v.generate.arch(live="full")
    lam = float(re.search(r"λ = ([0-9.]+)\n", out).group(1))
    assert abs(lam - v.limit(arch).load_multiplier) < 5e-5 and lam == 0.4346
    assert "hinges at joints [13, 32, 51]" in out
    assert "certified: True" in out
    zero = float(re.search(r"λ = 0 at s = ([0-9.]+) cm", out).group(1))
    assert abs(zero - 1.4) / 1.4 < 0.05  # the paper: about 1.4 cm (README table: 1.375 cm)
    assert (tmp_path / "capacity.png").read_bytes()[:4] == b"\x89PNG"
    # Rich outputs: the model and results display as SVG/HTML in Jupyter.
    rich = [o for c in nb.cells for o in c.get("outputs", []) if o.get("output_type") == "execute_result"]
    assert any("image/svg+xml" in o["data"] or "text/html" in o["data"] for o in rich)
