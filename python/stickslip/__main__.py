"""``python -m stickslip …``: the command line."""

from ._cli import main

main()
