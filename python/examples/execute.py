"""Executes a notebook of this folder as CI does (nbclient, the python3 kernel), stopping at the
first cell that raises (the notebook's asserts), and writes the executed copy with its figures.

    python python/examples/execute.py python/examples/outer_solar_system.ipynb out/outer_solar_system.ipynb
"""
import os
import sys
import time

import nbformat
from nbclient import NotebookClient


def main(path, out):
    notebook = nbformat.read(path, as_version=4)
    start = time.perf_counter()
    NotebookClient(notebook, timeout=600, kernel_name="python3",
                   resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}}).execute()
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    nbformat.write(notebook, out)
    figures = sum(1 for cell in notebook.cells if cell.cell_type == "code"
                  for o in cell.get("outputs", []) if "image/png" in o.get("data", {}))
    print(f"{path}: executed in {time.perf_counter() - start:.1f} s, {figures} figures; wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: execute.py NOTEBOOK.ipynb OUT.ipynb")
    main(sys.argv[1], sys.argv[2])
