"""The Python API against the installed command line: the same numbers to the last digit, the
same one-line errors, and the files the commands write."""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest

import stickslip
from conftest import ROOT, cli_json, run

#: Parameter sets of both models: defaults, other friction, an option, a law that is missing.
SETS = [
    ("woodpecker", {}),
    ("woodpecker", {"mu_d": 0.3}),
    ("woodpecker", {"mu_d": 0.3, "counterpart": "extremes", "periods": 5}),
    ("woodpecker", {"z0": -0.012}),
    ("pulled-mass", {}),
    ("pulled-mass", {"mu_s": 0.4, "mu_d": 0.35, "mass": 0.06, "k": 45.0, "force": 0.18}),
    ("pulled-mass", {"force": 0.1 / 3, "periods": 3}),
    ("belt", {}),
    ("belt", {"mu_d": 0.45, "v_b": 0.3, "periods": 3}),
    ("belt", {"mu_d": 0.5}),
]


def flags(params: dict) -> list[str]:
    return [f"--{k.replace('_', '-')}={v!r}" if isinstance(v, float) else f"--{k.replace('_', '-')}={v}" for k, v in params.items()]


@pytest.mark.parametrize(("model", "params"), SETS)
def test_eval_is_the_commands_json_to_the_last_digit(command, model, params):
    want = cli_json(command, "eval", model, *flags(params), "--json")
    got = stickslip.eval(model, **params)
    assert got.data == want
    # Same floats, bit for bit (== on floats would also pass for -0.0 against 0.0).
    assert json.dumps(got.data) == json.dumps(want)


@pytest.mark.parametrize(("model", "params"), [SETS[1], SETS[3], SETS[5], SETS[8]])
def test_series_and_events_are_the_commands_csv_files(command, tmp_path, model, params):
    done = run(command, "eval", model, *flags(params), "--csv", str(tmp_path))
    assert done.returncode == 0, done.stderr
    got = stickslip.eval(model, **params)
    assert sorted(got.series) == sorted(law["id"] for law in got.laws)
    assert set(got.summaries) == set(got.series)
    for law in got.series:
        for kind, tables in (("timeseries", got.series), ("events", got.events)):
            path = tmp_path / f"{kind}_{law}.csv"
            if not path.exists():
                assert tables[law] is None
                continue
            with path.open(newline="") as f:
                rows = list(csv.reader(f))
            table = tables[law]
            assert list(table.keys()) == rows[0]
            assert len(table) == len(rows) - 1
            for i, name in enumerate(rows[0]):
                cells = [r[i] for r in rows[1:]]
                column = table[name]
                if isinstance(column, np.ndarray):
                    assert column.dtype == np.float64
                    assert column.tolist() == [float(c) for c in cells]
                else:
                    assert column == cells


def test_a_parameter_out_of_range_is_a_value_error_with_the_commands_message(command):
    done = run(command, "eval", "woodpecker", "--mu-d", "2")
    assert done.returncode == 2
    with pytest.raises(ValueError) as caught:
        stickslip.eval("woodpecker", mu_d=2)
    error = caught.value
    assert isinstance(error, stickslip.StickslipUsageError)
    assert isinstance(error, stickslip.StickslipError)
    assert error.code == 2
    assert "error: " + str(error) == done.stderr.strip()
    assert str(error).startswith("invalid parameter mu_d = 2: must satisfy")


def test_periods_out_of_range_and_unknown_names_are_refused():
    for bad in ({"periods": 0}, {"periods": 10**7}, {"periods": -1}):
        with pytest.raises(ValueError, match="periods"):
            stickslip.eval("pulled-mass", **bad)
    with pytest.raises(ValueError, match="pulled-mass, woodpecker, belt"):
        stickslip.eval("seesaw")
    with pytest.raises(ValueError, match="for parameter"):
        stickslip.eval("woodpecker", F=1.0)
    with pytest.raises(ValueError, match="counterpart"):
        stickslip.eval("woodpecker", counterpart="sideways")
    with pytest.raises(ValueError, match="mu_d"):
        stickslip.eval("woodpecker", mu_d=True)


def test_the_rich_display_says_the_regime_and_shows_checks_formulas_and_figure():
    e = stickslip.eval("woodpecker")
    html = e._repr_html_()
    assert e.regime["id"] == "double_slip_stick"
    assert e.regime["words"] in html
    assert html.count("<tr>") == len(e.checks) + 1
    assert "<math" in html and "<svg" in html
    assert "(41)" in html  # t_SL of phase I, the paper's equation number
    assert repr(e).startswith("<stickslip.Evaluation woodpecker:")


def test_the_belt_is_read_by_its_own_law():
    e = stickslip.eval("belt", mu_d=0.3)
    assert [law["id"] for law in e.laws] == ["exact"]
    assert e.summaries["exact"] is e.data["integration"]
    assert e.series["exact"]["t_s"].dtype == np.float64
    assert e.passed
    html = e._repr_html_()
    assert "exact integration: " in html and "(B14)" in html and "<svg" in html
    assert html.count("<tr>") == len(e.checks) + 1


def test_check_returns_the_report_and_a_wrong_formula_as_a_verdict(command):
    args = ["pulled-mass", "2 g T \\varphi^3 \\Gamma", "--quantity", "v_avg", "--regime", "slip_stick", "--json"]
    done = run(command, "check", *args)
    assert done.returncode == 3
    report = stickslip.check(
        "pulled-mass", "2 g T \\varphi^3 \\Gamma", quantity="v_avg", regime="slip_stick"
    )
    assert report == json.loads(done.stdout)
    assert report["agrees"] is False
    right = stickslip.check(
        "pulled-mass", "g T \\varphi^3 \\Gamma", quantity="v_avg", regime="slip_stick"
    )
    assert right["agrees"] is True
    # A formula that starts with a minus sign is a formula, not a flag.
    negative = stickslip.check("pulled-mass", "-(0 - t_{SL})", quantity="t_slip")
    assert negative["formula"] == "-(0 - t_{SL})"
    with pytest.raises(ValueError, match="quantity"):
        stickslip.check("pulled-mass", "g T", quantity="no_such_quantity")


def test_claims_are_the_commands_json(command):
    want = cli_json(command, "claims", "--samples", "30", "woodpecker", "--mu-d=0.3", "--json")
    assert stickslip.claims("woodpecker", samples=30, mu_d=0.3) == want


def test_sweep_returns_the_grid_as_arrays(tmp_path):
    s = stickslip.sweep(
        "pulled-mass", "force", 0.1, 0.5, 5, mu_s=0.4, mu_d=0.35, mass=0.06, k=45.0
    )
    assert s["force_N"].tolist() == pytest.approx([0.1, 0.2, 0.3, 0.4, 0.5])
    assert s["v_avg_harmonic_m_s"].dtype == np.float64
    assert s["regime_closed_form"][:2] == ["slip_stick", "slip_stick_late"]
    kept = stickslip.sweep("woodpecker", "mu_d", 0.2, 0.4, 3, out=tmp_path / "sw")
    assert len(kept) == 3
    # μd = 0.2: continuous slip, no v̄ of a periodic orbit (a blank cell).
    assert math.isnan(kept["v_avg_harmonic_m_s"][0]) and kept["slips_harmonic"][0] == 0
    assert (tmp_path / "sw" / "sweep.csv").exists() and (tmp_path / "sw" / "sweep.svg").exists()


def test_fit_recovers_the_example_track(tmp_path):
    fitted = stickslip.fit(ROOT / "scenarios" / "tracked-toy-example.csv", out=tmp_path / "fit")
    assert fitted["converged"] is True
    assert {"fit.json", "fit.csv", "fit.svg"} <= {p.name for p in (tmp_path / "fit").iterdir()}


def test_worksheet_handout_and_report_write_files_like_the_command(tmp_path):
    ws = stickslip.worksheet("woodpecker", students=3, out=tmp_path / "ws", format=["html", "gift"])
    assert ws.message.startswith("wrote ") and "3 students" in ws.message
    assert Path("answer-key.json") in ws.files and Path("worksheets.gift.txt") in ws.files
    key = json.loads((tmp_path / "ws" / "answer-key.json").read_text())
    assert len(key["students"]) == 3
    assert "fig15-double-slip-stick" in stickslip.handout()
    h = stickslip.handout("fig15-double-slip-stick", out=tmp_path / "h", format="md")
    assert any(p.suffix == ".md" for p in h.files)
    with pytest.raises(ValueError, match="scene"):
        stickslip.handout("no-such-scene", out=tmp_path / "h2")


def test_cli_returns_stdout_and_raises_the_one_line_error():
    printed = stickslip.cli("eval", "woodpecker", "--mu-d", 0.3, "--json")
    assert json.loads(printed) == stickslip.eval("woodpecker", mu_d=0.3).data
    assert stickslip.cli("--version").strip() == f"stickslip {stickslip.__version__}"
    with pytest.raises(stickslip.StickslipUsageError) as caught:
        stickslip.cli("evl")
    # clap's one-line error, as the command prints it.
    assert str(caught.value).startswith("unrecognized subcommand 'evl'")


def test_the_package_is_the_installed_one_with_its_stubs():
    package = Path(stickslip.__file__).parent
    assert "site-packages" in package.parts, package
    assert (package / "py.typed").exists() and (package / "_native.pyi").exists()


def test_the_console_script_is_the_command_line(command, tmp_path):
    done = run(command, "--version")
    assert (done.returncode, done.stdout.strip()) == (0, f"stickslip {stickslip.__version__}")
    bad = run(command, "eval", "pulled-mass", "--mu-s", "-1")
    assert bad.returncode == 2 and bad.stderr.startswith("error: invalid parameter mu_s = -1")
    assert bad.stdout == ""
    wrote = run(command, "sweep", "woodpecker", "--param", "mu_d", "--from", "0.2", "--to", "0.3", "--steps", "2", "-o", "s", cwd=tmp_path)
    assert wrote.returncode == 0, wrote.stderr
    assert (tmp_path / "s" / "sweep.csv").exists()
    # μd = 0.3: two slips and two sticks per period, a finite v̄.
    assert math.isfinite(float((tmp_path / "s" / "sweep.csv").read_text().splitlines()[2].split(",")[1]))
