"""Writes each examples/*.py (a script with `# %%` cells) as a Jupyter notebook beside a copy of the
scripts and their helper module (as they are installed), so that the examples run both ways: `python3 slr.py` and
`jupyter nbconvert --to notebook --execute slr.ipynb`.

    python3 app/python/notebooks.py EXAMPLES_DIR OUT_DIR

A `# %% [markdown]` cell becomes a markdown cell (its lines without the leading "# "), every other
cell a code cell; the lines before the first marker open the first code cell.
"""
import json
import os
import shutil
import sys


def cells_of(text):
    cells, kind, lines = [], "code", []

    def flush():
        while lines and not lines[-1].strip():
            lines.pop()
        while lines and not lines[0].strip():
            lines.pop(0)
        if lines:
            body = [(ln[2:] if ln.startswith("# ") else ln.lstrip("#")) for ln in lines] if kind == "markdown" else lines
            source = [ln + "\n" for ln in body[:-1]] + [body[-1]]
            cell = {"cell_type": kind, "metadata": {}, "source": source}
            if kind == "code":
                cell.update(execution_count=None, outputs=[])
            cells.append(cell)

    for line in text.splitlines():
        if line.startswith("# %%"):
            flush()
            kind, lines = ("markdown" if "[markdown]" in line else "code"), []
            continue
        lines.append(line)
    flush()
    return cells


def notebook(text):
    return {"cells": cells_of(text),
            "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"},
                         "language_info": {"name": "python"}},
            "nbformat": 4, "nbformat_minor": 4}


def main():
    src, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    for name in sorted(os.listdir(src)):
        if not name.endswith(".py"):
            continue
        shutil.copyfile(os.path.join(src, name), os.path.join(out, name))  # (the scripts too)
        if name.startswith("_"):  # (the helper module, imported by the scripts and notebooks)
            continue
        with open(os.path.join(src, name), encoding="utf-8") as f:
            nb = notebook(f.read())
        with open(os.path.join(out, name[:-3] + ".ipynb"), "w", encoding="utf-8") as f:
            json.dump(nb, f, indent=1, ensure_ascii=False)
            f.write("\n")


if __name__ == "__main__":
    main()
