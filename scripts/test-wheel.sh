#!/usr/bin/env bash
# The Python package as a user installs it: `maturin build --release` makes the abi3 wheel, pip
# installs it into a fresh virtual environment (in a temporary directory, removed afterwards)
# with the pinned test requirements, and the pytest suite and the guide's examples
# (docs/python.md) run against the installed package from outside the source tree, and mypy
# --strict checks python/tests/typing against its stubs (the types a user's checker sees).
#
#   bash scripts/test-wheel.sh          (just test-wheel)
#
# maturin is the one of .tools/pyvenv (scripts/setup-python.sh installs it); the wheel is built
# by cargo in the usual target directory, so it reuses the develop build's compilation.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$PWD"
maturin="$repo/.tools/pyvenv/bin/maturin"
scratch=$(mktemp -d "${TMPDIR:-/tmp}/spherekit-wheel-XXXXXX")
trap 'rm -rf "$scratch"' EXIT

(cd python && "$maturin" build --release --locked --quiet --out "$scratch/dist")
wheels=("$scratch"/dist/spherekit-*.whl)
[ "${#wheels[@]}" -eq 1 ] || { echo "test-wheel: expected one wheel, got ${wheels[*]}" >&2; exit 1; }
wheel=${wheels[0]}
echo "test-wheel: $(basename "$wheel"), $(stat -c %s "$wheel") bytes"
case "$(basename "$wheel")" in
  *-cp39-abi3-*) ;;
  *) echo "test-wheel: not an abi3 wheel for CPython >= 3.9" >&2; exit 1 ;;
esac

python3 -m venv "$scratch/venv"
py="$scratch/venv/bin/python"
"$py" -m pip install --quiet --disable-pip-version-check "$wheel" -r python/test-requirements.txt

# From a directory where python/ is not importable: the package must be the installed one,
# and its stubs and py.typed with it.
cd "$scratch"
"$py" - "$scratch/venv" <<'PY'
import pathlib, sys
import spherekit
venv = pathlib.Path(sys.argv[1]).resolve()
package = pathlib.Path(spherekit.__file__).resolve().parent
assert venv in package.parents, f"spherekit imported from {package}, not from the fresh venv {venv}"
shipped = {p.name for p in package.iterdir()}
for name in ("py.typed", "__init__.py", "_curve.pyi", "_scipy.pyi", "_spherekit.pyi"):
    assert name in shipped, f"the wheel lacks spherekit/{name}"
print(f"test-wheel: spherekit {spherekit.__version__} from {package}")
PY
"$py" -m mypy --strict --no-incremental "$repo/python/tests/typing"
MPLBACKEND=Agg "$py" -m pytest -q -p no:cacheprovider --rootdir "$repo/python" -c "$repo/python/pyproject.toml" \
  "$repo/python/tests" "$repo/docs/python.md"
