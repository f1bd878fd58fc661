#!/usr/bin/env bash
# Issue 13 in CI (called by .ci/run): the Python package exactly as README's "From Python"
# installs it, on a fresh machine: a venv, `pip install ./python` (maturin builds the
# extension with the crate's lean release profile), the test dependencies, the CLI for the
# agreement tests, pytest, and the Dask example on a two-worker LocalCluster checked
# against a single-process run. Also rustfmt and clippy of the python crate (its own
# workspace). See docs/scale.md.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
say() { printf -- '--- %s (t=%ss)\n' "$*" "$((SECONDS - start))"; }
VENV=${CARRY_VENV:-${TMPDIR:-/tmp}/carry-python-ci}
DASK_SHOTS=${DASK_SHOTS:-20000}

say "rustfmt of the python crate"
(cd python && cargo fmt --check)

say "the python crate stands on core, io and lab only: no clap, no carry-cli (issue 24)"
if (cd python && cargo tree -e normal,build --prefix none) | grep -E '^(clap|carry-cli) '; then
  echo "python/ depends on clap or carry-cli" >&2
  exit 1
fi

say "venv $VENV"
python3 -m venv --clear "$VENV"
# shellcheck disable=SC1091
source "$VENV/bin/activate"
python -m pip install --quiet --upgrade pip
python -m pip install --quiet pytest numpy pandas "dask[dataframe]" distributed
python --version

say "pip install ./python (README)"
python -m pip install --quiet ./python
python -c "import carry; print('carry', carry.__version__, carry.__file__)"

say "clippy of the python crate (release: shares build scripts and proc-macros with the build above)"
# PYO3_PYTHON: PyO3's build script asks the venv's interpreter for its version.
(cd python && PYO3_PYTHON="$VENV/bin/python" cargo clippy --release --quiet -- -D warnings)

say "the CLI for the agreement tests (the root workspace's: the python crate depends on core, io and lab only)"
# .ci/run's `cargo test --workspace` has built it already (debug, the core optimised; IEEE
# arithmetic gives the same numbers at every opt-level): a second, release build of the whole
# CLI would cost minutes of CI for nothing. Run alone, this script builds it.
if [ -x target/debug/carry ] && [ -n "${CI:-}" ]; then
  export CARRY_CLI=$PWD/target/debug/carry
else
  cargo build --release --quiet -p carry-cli --bin carry
  export CARRY_CLI=$PWD/target/release/carry
fi

say "pytest python/tests"
# From the repository root, so `import carry` is the installed package, not python/carry.
python -m pytest -q -p no:cacheprovider python/tests

say "Dask: $DASK_SHOTS shots on a LocalCluster with two workers, checked against one process"
python python/examples/dask_sweep.py --shots "$DASK_SHOTS" --workers 2 --check

say "python done in $((SECONDS - start)) s"
