#!/usr/bin/env bash
# The Python package's tests: installs ./python[test] from this checkout into
# a fresh virtual environment (the build compiles libweft with cargo), builds
# the `weft` command the tests compare against, and runs pytest.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
venv=$here/.venv-test
python=${PYTHON:-python3}

rm -rf "$venv" "$here/build" "$here"/*.egg-info
"$python" -m venv "$venv"
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check "$here[test]"

# The command line tool sits behind a `cli` feature when Cargo.toml has one.
features=()
if sed -n '/^\[features\]/,/^\[/p' "$root/Cargo.toml" | grep -qE '^\s*cli\s*='; then
  features=(--features cli)
fi
(cd "$root" && "${CARGO:-cargo}" build --quiet --release --bin weft "${features[@]}")

# Run from the tests folder so `import weft` finds the installed package,
# not the source folder.
cd "$here/tests"
"$venv/bin/python" -m pytest -p no:cacheprovider -q "$@" .
