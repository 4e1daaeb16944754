"""The exceptions of stickslip: each carries the one-line message the command line prints
(without its ``error:`` label) and the command line's exit code."""

from __future__ import annotations


class StickslipError(Exception):
    """A command that failed: exit code 1 (the engine, a figure, a fit that did not converge,
    Chromium failing to print) or 3 (a negative verdict, raised by :func:`stickslip.cli` only:
    ``check`` and ``fit`` return their verdicts as data).

    Attributes: ``code`` (the exit code of the command line), ``message`` (its one-line
    message), ``stdout`` (what the command printed before failing, e.g. a flagged fit's JSON).
    """

    def __init__(self, message: str, code: int = 1, stdout: str = "") -> None:
        super().__init__(message)
        self.message = message
        self.code = code
        self.stdout = stdout


class StickslipUsageError(StickslipError, ValueError):
    """Bad input (exit code 2): a parameter out of range (the message names it and its valid
    range), an unknown option, an unreadable scenario or data file, an unwritable folder."""


def error_for(code: int, message: str, stdout: str = "") -> StickslipError:
    """The exception of a refusal with exit code ``code`` and the one-line ``message``."""
    for label in ("error: ", "verdict: "):
        if message.startswith(label):
            message = message[len(label):]
            break
    cls = StickslipUsageError if code == 2 else StickslipError
    return cls(message, code, stdout)
