"""The example notebook (python/examples/stickslip.ipynb) runs top to bottom in a fresh kernel
with the installed package, and its outputs say what the paper and the guide say."""

from __future__ import annotations

import json
import shutil

import nbclient
import nbformat

from conftest import ROOT

NOTEBOOK = ROOT / "python" / "examples" / "stickslip.ipynb"
#: The notebook's sweep of F: grid step (N).
STEP = (0.35 - 0.05) / 60


def executed(tmp_path):
    """The notebook run in `tmp_path` (it writes its worksheets there)."""
    shutil.copy(NOTEBOOK, tmp_path / NOTEBOOK.name)
    nb = nbformat.read(tmp_path / NOTEBOOK.name, as_version=4)
    client = nbclient.NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}
    )
    client.execute()
    return nb


def printed_json(nb):
    """Every line a code cell printed that is a JSON object, in order."""
    found = []
    for cell in nb.cells:
        for out in cell.get("outputs", []):
            if out.get("output_type") == "stream" and out.get("name") == "stdout":
                for line in out["text"].splitlines():
                    if line.startswith("{"):
                        found.append(json.loads(line))
    return found


def test_the_example_notebook_runs_and_shows_the_papers_results(tmp_path):
    nb = executed(tmp_path)
    fig15, band, verdicts, worksheets = printed_json(nb)

    # Fig. 15: two slips and two sticks per period under both laws, every check passing.
    assert fig15["closed_form_regime"] == fig15["linear"] == fig15["harmonic"] == "double_slip_stick"
    assert fig15["slips_per_period"] == 2
    passed, total = map(int, fig15["checks_passed"].split("/"))
    assert passed == total > 10

    # The rich display of the Fig. 15 result: the figure (SVG) and formulas (MathML).
    html = [
        out["data"]["text/html"]
        for cell in nb.cells
        for out in cell.get("outputs", [])
        if "text/html" in out.get("data", {})
    ]
    assert len(html) == 1 and "<svg" in html[0] and "<math" in html[0]
    assert "two slips and two sticks per period" in html[0]

    # The late-stick band found by the sweep lies between 1/Θ·W and φ_c·W, within a grid step.
    assert band["set_c_regime"] == "slip_stick_late"
    assert band["closed_form_from_N"] <= band["sweep_from_N"] < band["closed_form_from_N"] + STEP
    assert band["closed_form_to_N"] - STEP < band["sweep_to_N"] <= band["closed_form_to_N"]

    # The paper's (27) agrees; twice it does not.
    assert list(verdicts.values()) == ["agrees", "disagrees"]

    # A class of 28: sheets, key, Moodle and GIFT banks, written where the notebook runs.
    assert worksheets["students"] == 28
    assert {"worksheets.html", "answer-key.json", "worksheets.moodle.xml", "worksheets.gift.txt"} <= set(
        worksheets["files"]
    )
    assert (tmp_path / "class-worksheets" / "worksheets.moodle.xml").stat().st_size > 0
