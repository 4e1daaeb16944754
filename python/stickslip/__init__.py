"""stickslip: the stick-slip models of a physics paper (the pulled mass, the falling
woodpecker toy): every closed form evaluated and checked against an exact, event-driven
integration, in Python.

>>> import stickslip
>>> e = stickslip.eval("woodpecker", mu_d=0.3)      # SI units; a notebook shows e richly
>>> e.closed_form["v_avg"], e.harmonic["regime"]     # the numbers of `stickslip eval --json`
>>> e.series["harmonic"]["t_s"], e.series["harmonic"]["y_m"]   # NumPy arrays

Also :func:`check` (your own formula against the integration), :func:`claims`, :func:`sweep`
(arrays), :func:`fit`, :func:`worksheet`, :func:`handout` and :func:`report` (files written as
the command line does), :func:`cli` for any command line. Bad input raises
:class:`StickslipUsageError` (a ``ValueError``) with the command line's one-line message.
"""

from ._api import (
    Evaluation,
    Series,
    Written,
    check,
    claims,
    cli,
    eval,
    fit,
    handout,
    report,
    run,
    sweep,
    worksheet,
)
from ._native import __version__
from .errors import StickslipError, StickslipUsageError

__all__ = [
    "Evaluation",
    "Series",
    "StickslipError",
    "StickslipUsageError",
    "Written",
    "__version__",
    "check",
    "claims",
    "cli",
    "eval",
    "fit",
    "handout",
    "report",
    "run",
    "sweep",
    "worksheet",
]
