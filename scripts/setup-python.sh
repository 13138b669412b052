#!/usr/bin/env bash
# Installs the Python test environment, only what is missing, then builds the `spherekit`
# extension into it and runs the given command (if any) with the venv's bin/ first on PATH.
#
#   bash scripts/setup-python.sh [command...]
#
# Everything comes from PyPI into .tools/pyvenv (git-ignored): the pinned test requirements
# (python/test-requirements.txt: numpy, scipy, numpy-quaternion, pytest, matplotlib) and
# maturin, which builds crates/spherekit-py with cargo into target/ (so a rebuild after a small
# change is incremental). Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."
venv="$PWD/.tools/pyvenv"
mapfile -t pins < <(grep -v '^#' python/test-requirements.txt)
pins+=(maturin==1.15.0)

if [ ! -x "$venv/bin/python" ]; then
  echo "setup-python: creating $venv" >&2
  python3 -m venv "$venv"
fi
stamp="$venv/.pins"
if [ "$(cat "$stamp" 2>/dev/null)" != "${pins[*]}" ]; then
  echo "setup-python: installing ${pins[*]}" >&2
  "$venv/bin/pip" install --quiet --disable-pip-version-check "${pins[@]}"
  echo "${pins[*]}" >"$stamp"
fi

# Build and install the extension in place (cargo decides whether anything changed).
# This is what `pip install ./python` does, without building a wheel each time.
(cd python && VIRTUAL_ENV="$venv" PATH="$venv/bin:$PATH" "$venv/bin/maturin" develop --release --locked --quiet)

[ "$#" -eq 0 ] || PATH="$venv/bin:$PATH" exec "$@"
