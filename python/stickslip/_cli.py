"""The ``stickslip`` console script of the wheel: the same command line as the Rust binary."""

from __future__ import annotations

import signal
import sys

from . import _native


def main() -> None:
    """Runs ``stickslip`` with the process's arguments and exits with its code."""
    # The Rust binary dies on Ctrl-C; Python's handler would wait for the command to return.
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    sys.stdout.flush()
    sys.stderr.flush()
    sys.exit(_native.run(sys.argv[1:]))


if __name__ == "__main__":
    main()
