"""The functions of the package: ``eval`` through the library's evaluation of one parameter
set, the others through the command line itself (its dispatch, run in-process with the output
captured), so every number is the command line's to the last digit.

Parameters are keyword arguments named like the model's flags with ``_`` for ``-`` (``mu_d``,
``z0``, ``m_sleeve``, ``force``), in SI units (m, kg, N, N/m, m/s²); options take their words
(``counterpart="extremes"``, ``omega="bird"``). ``stickslip eval woodpecker --help`` lists them.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence, Union

import numpy as np

from . import _native
from .errors import error_for

PathLike = Union[str, "os.PathLike[str]"]


def cli(*argv: Any, check: bool = True) -> str:
    """Runs ``stickslip ARGV…`` in this process and returns what it prints on stdout.

    ``cli("eval", "woodpecker", "--mu-d", 0.3, "--json")`` prints nothing and returns the JSON
    text. With ``check`` (default) an exit code other than 0 raises the command line's one-line
    message as :class:`~stickslip.StickslipError` (:class:`~stickslip.StickslipUsageError`, a
    ``ValueError``, for bad input, exit code 2).
    """
    code, out, err = _native.call([_text(a) for a in argv])
    if check and code != 0:
        raise error_for(code, _last_line(err), out)
    return out


def run(argv: Sequence[Any]) -> int:
    """Runs the command line on the process's stdout and stderr and returns its exit code
    (what the ``stickslip`` console script does)."""
    return _native.run([_text(a) for a in argv])


@dataclass(frozen=True)
class Series:
    """One CSV file of ``stickslip eval --csv`` as columns: a NumPy array per numeric column
    (``t_s`` in s, ``x_m``/``y_m`` in m, ``v_m_s`` in m/s, ``a_m_s2`` in m/s², ``stuck`` 0 or
    1), a list of strings per text column (``kind`` of an event)."""

    columns: dict[str, Any]

    def __getitem__(self, name: str) -> Any:
        return self.columns[name]

    def __contains__(self, name: object) -> bool:
        return name in self.columns

    def __len__(self) -> int:
        first = next(iter(self.columns.values()), [])
        return len(first)

    def keys(self) -> Iterable[str]:
        return self.columns.keys()

    def rows(self) -> list[dict[str, Any]]:
        """The rows as dicts (numbers as float)."""
        names = list(self.columns)
        return [
            {n: _item(self.columns[n][i]) for n in names} for i in range(len(self))
        ]


@dataclass(frozen=True)
class Evaluation:
    """One parameter set of a model evaluated as ``stickslip eval MODEL … --json`` does.

    ``data`` is exactly ``json.loads`` of that command's output (guide §14, SI units):
    ``model``, ``params``, ``closed_form`` (the closed forms, ``regime``), the exact
    integration's summary of each law (the paper's models: ``linear`` and ``harmonic``,
    ``None`` for a law that does not exist; the belt: ``integration``), ``checks`` (closed form
    against integration). ``laws`` lists the model's laws (``id``, ``name``, ``summary``: the
    key of its summary in ``data``); ``regime`` says the closed forms' regime in words (``id``,
    ``words``, ``why``); ``series`` and ``events`` hold the time series and event lists of each
    law by its id (``eval --csv``) as NumPy arrays, ``None`` for a law that does not exist.
    """

    data: dict[str, Any]
    regime: dict[str, Any]
    applicability: list[Any]
    laws: list[dict[str, str]]
    series: dict[str, Series | None]
    events: dict[str, Series | None]
    setup: dict[str, Any] = field(repr=False)

    def __getitem__(self, key: str) -> Any:
        return self.data[key]

    @property
    def model(self) -> str:
        return self.data["model"]

    @property
    def params(self) -> dict[str, Any]:
        """Every input parameter and the derived ones (SI)."""
        return self.data["params"]

    @property
    def closed_form(self) -> dict[str, Any]:
        """The linear law's closed forms by JSON key (guide §14) (SI; ``None`` where undefined)."""
        return self.data["closed_form"]

    @property
    def summaries(self) -> dict[str, dict[str, Any] | None]:
        """The exact integration's summary of each law, by the law's id (``None`` for a law
        that does not exist for the parameters)."""
        return {law["id"]: self.data[law["summary"]] for law in self.laws}

    @property
    def linear(self) -> dict[str, Any] | None:
        """The exact integration of the linearized law (the paper's models; ``None`` if it
        does not exist)."""
        return self.data["linear"]

    @property
    def harmonic(self) -> dict[str, Any]:
        """The exact integration of the harmonic law (the paper's models)."""
        return self.data["harmonic"]

    @property
    def checks(self) -> list[dict[str, Any]]:
        """Closed form against numeric, with relative error, tolerance and ``pass``."""
        return self.data["checks"]

    @property
    def passed(self) -> bool:
        """Every check passes."""
        return all(c["pass"] for c in self.checks)

    def figure_svg(self) -> str:
        """The model's motion figure for these parameters (SVG text), as the report draws it."""
        return _native.figure(json.dumps(self.setup))

    def _repr_html_(self) -> str:
        from ._display import evaluation_html

        return evaluation_html(self)

    def __repr__(self) -> str:
        n_pass = sum(c["pass"] for c in self.checks)
        return (
            f"<stickslip.Evaluation {self.model}: {self.regime['words']}; "
            f"{n_pass}/{len(self.checks)} checks pass>"
        )


def eval(model: str, *, periods: int | None = None, **params: float | str) -> Evaluation:
    """Evaluates every closed form of ``model`` ("pulled-mass", "woodpecker", "belt") for its
    default set overridden by ``params`` (SI units; options as words) and checks it against the
    exact integration over ``periods`` periods (default 8, as the command line), integrating
    each of the model's laws (the paper's models: the harmonic law and its linearization).

    ``stickslip.eval("woodpecker", mu_d=0.3).data == json.loads(<stickslip eval woodpecker
    --mu-d 0.3 --json>)``, to the last digit. Bad input raises
    :class:`~stickslip.StickslipUsageError` (a ``ValueError``) with the command line's message.
    """
    setup: dict[str, Any] = {"model": model, "params": {}, "choices": {}}
    for key, value in params.items():
        if isinstance(value, str):
            setup["choices"][key] = value
        elif isinstance(value, bool) or not isinstance(value, (int, float, np.floating, np.integer)):
            raise error_for(2, f"invalid value {value!r} for {key}: a number (SI units) or an option's word")
        else:
            setup["params"][key] = float(value)
    if periods is not None and not isinstance(periods, (int, np.integer)):
        raise error_for(2, f"invalid value {periods!r} for periods: a whole number 1 to 1000000")
    evaluation, extras, files, laws = _native.evaluate(
        json.dumps(setup), None if periods is None else int(periods)
    )
    extras = json.loads(extras)
    tables = {name: _columns(text) for name, text in files}
    ids = [law_id for law_id, _, _ in laws]
    return Evaluation(
        data=json.loads(evaluation),
        regime=extras["closed_form"],
        applicability=extras["applicability"],
        laws=[{"id": i, "name": n, "summary": s} for i, n, s in laws],
        series={law: tables.get(f"timeseries_{law}.csv") for law in ids},
        events={law: tables.get(f"events_{law}.csv") for law in ids},
        setup=setup,
    )


def check(
    model: str,
    formula: str | None = None,
    *,
    quantity: str | None = None,
    formulas: PathLike | None = None,
    regime: str | None = None,
    samples: int | None = None,
    seed: int | None = None,
    out: PathLike | None = None,
    scenario: PathLike | None = None,
    **params: float | str,
) -> Any:
    """Puts your own ``formula`` (LaTeX or plain, e.g. ``"\\\\mu_s W - F"``) for ``quantity``
    against the exact integration, as ``stickslip check MODEL FORMULA --quantity NAME --json``:
    at the given parameters and on a seeded sample of the regimes where the quantity is
    measured. Returns the report (a dict; a list of them for ``formulas``, a TOML file of
    ``[[check]]`` tables). A formula that disagrees is a verdict in the report
    (``verdict``), not an exception; with ``out`` the pages are written there too.
    """
    argv = ["check", model, "--json", *_model_flags(params)]
    argv += _flags(
        quantity=quantity,
        formulas=formulas,
        regime=regime,
        samples=samples,
        seed=seed,
        out=out,
        scenario=scenario,
    )
    # After `--`, a formula that starts with a minus sign is not read as a flag.
    return _json_of(argv + ([] if formula is None else ["--", formula]), verdicts=True)


def claims(
    model: str = "woodpecker",
    *,
    seed: int | None = None,
    samples: int | None = None,
    scenario: PathLike | None = None,
    **params: float | str,
) -> dict[str, Any]:
    """The paper's claims on the given parameters of ``model`` (the other model keeps the
    paper's set) and on a seeded random sample, as ``stickslip claims MODEL --json``."""
    argv = ["claims", *_flags(seed=seed, samples=samples), model, *_flags(scenario=scenario)]
    return _json_of(argv + _model_flags(params) + ["--json"])


def sweep(
    model: str,
    param: str,
    start: float,
    stop: float,
    steps: int,
    *,
    out: PathLike | None = None,
    periods: int | None = None,
    scenario: PathLike | None = None,
    **params: float | str,
) -> Series:
    """Varies ``param`` on ``steps`` uniform grid points from ``start`` to ``stop`` (SI, both
    ends included) and integrates both laws at each point, as ``stickslip sweep MODEL --param
    PARAM --from START --to STOP --steps STEPS``. Returns the columns of ``sweep.csv``:
    NumPy arrays (the parameter, ``v_avg_*_m_s``, ``slips_*``, ``sticks_*``) and lists of
    regime ids. ``out`` keeps ``sweep.csv`` and ``sweep.svg`` in that folder (default: a
    temporary one, removed)."""
    argv = ["sweep", model, "--param", param, "--from", start, "--to", stop, "--steps", steps]
    argv += _flags(periods=periods, scenario=scenario)
    argv += _model_flags(params)
    with _folder(out) as folder:
        cli(*argv, "--out", folder)
        text = (Path(folder) / "sweep.csv").read_text(encoding="utf-8")
    return _columns(text)


def fit(
    file: PathLike,
    *,
    free: Sequence[str] | str | None = None,
    columns: str | None = None,
    units: str | None = None,
    out: PathLike = "fit",
    scenario: PathLike | None = None,
    **params: float | str,
) -> dict[str, Any]:
    """Fits the harmonic woodpecker to the tracked positions in ``file`` (CSV: time in s,
    position in m, cm or mm) as ``stickslip fit FILE --json``: the fitted parameters with
    standard errors, residuals and the verdict; fit.json, fit.csv and fit.svg are written to
    ``out``. A fit whose model does not describe the data is returned, flagged; one that did
    not converge raises :class:`~stickslip.StickslipError` (its JSON in ``.stdout``)."""
    argv = ["fit", file, *_flags(free=free, columns=columns, units=units, out=out, scenario=scenario)]
    return _json_of(argv + _model_flags(params) + ["--json"], verdicts=True)


@dataclass(frozen=True)
class Written:
    """Files a command wrote: the folder, the files in it (sorted) and the command's line."""

    out: Path
    files: list[Path]
    message: str


def worksheet(
    model: str,
    *,
    students: int | None = None,
    out: PathLike = "worksheets",
    seed: int | None = None,
    regime: str | None = None,
    questions: Sequence[str] | str | None = None,
    format: Sequence[str] | str | None = None,
    lang: str | None = None,
    pdf: bool = False,
) -> Written:
    """Exercise sheets, one per student with its own parameter set, and the answer key, as
    ``stickslip worksheet --model MODEL`` (``format``: html, md, moodle, gift; ``lang``: en,
    it). The answer key's data is ``json.load`` of ``out/answer-key.json``."""
    argv = ["worksheet", "--model", model]
    argv += _flags(
        students=students,
        seed=seed,
        regime=regime,
        questions=questions,
        format=format,
        lang=lang,
        pdf=pdf,
        out=out,
    )
    return _written(argv, out)


def handout(
    scene: str | None = None,
    *,
    out: PathLike = "handouts",
    format: Sequence[str] | str | None = None,
    lang: str | None = None,
    pdf: bool = False,
) -> Written | str:
    """The two-page lecture handout of a built-in ``scene`` (e.g. "fig15-double-slip-stick"),
    as ``stickslip handout SCENE``; without a scene, the list of scenes (text)."""
    if scene is None:
        return cli("handout", "--list")
    argv = ["handout", scene, *_flags(format=format, lang=lang, pdf=pdf, out=out)]
    return _written(argv, out)


def report(
    *scenarios: PathLike, out: PathLike = "reports", format: Sequence[str] | str | None = None
) -> Written:
    """The report of the built-in scenes (or of the given scenario files), as ``stickslip
    report``: HTML and Markdown pages, the explorer and the classroom material in ``out``."""
    return _written(["report", *scenarios, *_flags(format=format, out=out)], out)


# --- helpers -------------------------------------------------------------------------------


def _text(value: Any) -> str:
    """An argument as the command line reads it: floats to the shortest repr that reads back
    to the same double, so the Rust side parses the very number given."""
    if isinstance(value, bool):
        raise TypeError("a flag's value cannot be a bool")
    if isinstance(value, (float, np.floating)):
        return repr(float(value))
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    return str(value)


def _flag(key: str) -> str:
    return "--" + key.replace("_", "-")


def _flags(**options: Any) -> list[str]:
    """``--key value`` for each option given (``None`` and ``False`` left out; ``True`` as the
    flag alone; a list joined with commas)."""
    argv: list[str] = []
    for key, value in options.items():
        if value is None or value is False:
            continue
        if value is True:
            argv.append(_flag(key))
        elif isinstance(value, (list, tuple)):
            argv += [_flag(key), ",".join(_text(v) for v in value)]
        else:
            argv += [_flag(key), _text(value)]
    return argv


def _model_flags(params: Mapping[str, Any]) -> list[str]:
    """The model's flags, ``--key=value`` so that a negative number is a value."""
    argv = []
    for key, value in params.items():
        if isinstance(value, bool):
            raise error_for(2, f"invalid value {value!r} for {key}: a number (SI units) or an option's word")
        argv.append(f"{_flag(key)}={_text(value)}")
    return argv


def _last_line(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    return lines[-1] if lines else "the command failed"


def _json_of(argv: list[Any], verdicts: bool = False) -> Any:
    """The JSON a command prints; exit 3 (a negative verdict, reported in full) is data when
    ``verdicts``."""
    code, out, err = _native.call([_text(a) for a in argv])
    if code == 0 or (verdicts and code == 3):
        return json.loads(out)
    raise error_for(code, _last_line(err), out)


def _written(argv: list[Any], out: PathLike) -> Written:
    message = cli(*argv).strip()
    folder = Path(out)
    files = sorted(p.relative_to(folder) for p in folder.rglob("*") if p.is_file())
    return Written(out=folder, files=files, message=message)


class _folder:
    """``out`` itself, or a temporary folder removed on exit."""

    def __init__(self, out: PathLike | None) -> None:
        self.out = out
        self.tmp: tempfile.TemporaryDirectory[str] | None = None

    def __enter__(self) -> str:
        if self.out is not None:
            return os.fspath(self.out)
        self.tmp = tempfile.TemporaryDirectory(prefix="stickslip-")
        return os.path.join(self.tmp.name, "out")

    def __exit__(self, *exc: object) -> None:
        if self.tmp is not None:
            self.tmp.cleanup()


def _columns(text: str) -> Series:
    """A CSV text as columns: float arrays where every cell is a number or blank (a quantity
    that does not exist there, e.g. v̄ in continuous slip: NaN), else lists of strings."""
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    columns: dict[str, Any] = {}
    for i, name in enumerate(header):
        cells = [r[i] for r in body]
        try:
            numbers = [float(c) if c else math.nan for c in cells]
        except ValueError:
            columns[name] = cells
        else:
            columns[name] = np.array(numbers, dtype=np.float64)
    return Series(columns)


def _item(value: Any) -> Any:
    return float(value) if isinstance(value, np.floating) else value
