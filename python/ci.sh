#!/usr/bin/env bash
# The Python package's checks (called by .ci/run): build the wheel with maturin (one more release
# build of the crate, feature `python`), install it into a fresh virtual environment, and run
# python/tests there: the API against the installed `stickslip` command, to the last digit, and
# the example notebook (python/examples/stickslip.ipynb) executed with nbclient. Run from
# anywhere: python/ci.sh
set -euxo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

python3 -m pip install -q 'maturin>=1.5,<2'
rm -rf target/wheels
maturin build --release --locked --out target/wheels
wheel=$(ls target/wheels/stickslip-*.whl)
ls -l "$wheel"

venv=target/py-venv
rm -rf "$venv"
python3 -m venv "$venv"
"$venv/bin/pip" install -q "$wheel" pytest nbclient nbformat ipykernel
# Installed, not the source tree: the tests import stickslip from site-packages.
"$venv/bin/python" -c 'import stickslip, sys; assert "site-packages" in stickslip.__file__, stickslip.__file__'
"$venv/bin/stickslip" --version
"$venv/bin/pytest" -q -p no:cacheprovider python/tests
