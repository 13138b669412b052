#!/usr/bin/env bash
# Installs what the web build and its tests need, only when it is missing (idempotent), then
# runs the given command. Rust tools (wasm-bindgen, wasm-pack) and wasm-opt go to .tools/
# (git-ignored); Chromium comes from Debian; the end-to-end test's npm packages from
# tests/e2e/package-lock.json.
#
#   bash scripts/setup-web.sh [--e2e] <command>...
#
# The web build (the justfile's `web`) runs wasm-pack (cargo, then the wasm-bindgen CLI of exactly
# the version in Cargo.lock), then binaryen's wasm-opt; the wasm tests use that CLI's test runner.
set -euo pipefail
cd "$(dirname "$0")/.."
tools="$PWD/.tools"
mkdir -p "$tools/bin"
export PATH="$tools/bin:$HOME/.cargo/bin:$PATH"

e2e=false
if [[ "${1:-}" == "--e2e" ]]; then
  e2e=true
  shift
fi

apt_updated=false
apt_install() {
  if [[ "$apt_updated" == false ]]; then
    apt-get update -qq
    apt_updated=true
  fi
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "$@" >/dev/null
}

if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
  echo "setup-web: adding the wasm32-unknown-unknown target" >&2
  rustup target add wasm32-unknown-unknown
fi

# The CLI must match the wasm-bindgen crate exactly.
bindgen_version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
if ! wasm-bindgen --version 2>/dev/null | grep -qx "wasm-bindgen $bindgen_version"; then
  echo "setup-web: installing wasm-bindgen-cli $bindgen_version into .tools/" >&2
  # --locked first; the registry may lack a locked transitive version, then resolve afresh.
  cargo install --locked --quiet wasm-bindgen-cli --version "$bindgen_version" --root "$tools" \
    || cargo install --quiet wasm-bindgen-cli --version "$bindgen_version" --root "$tools"
fi

# wasm-pack builds the npm package (the justfile's `web`). It runs with `--mode no-install` and
# `--no-opt`: it takes the wasm-bindgen CLI above from PATH and downloads nothing; wasm-opt
# below is run on its output by the recipe. It only runs other tools, so it is built without
# optimisation (`--debug`): about half the compile time of a release build.
wasm_pack_version=0.15.1
if ! wasm-pack --version 2>/dev/null | grep -qx "wasm-pack $wasm_pack_version"; then
  echo "setup-web: installing wasm-pack $wasm_pack_version into .tools/" >&2
  cargo install --locked --debug --quiet wasm-pack --version "$wasm_pack_version" --root "$tools" \
    || cargo install --debug --quiet wasm-pack --version "$wasm_pack_version" --root "$tools"
fi

# wasm-opt: Debian's binaryen (version 108) cannot read the reference-types output of current
# wasm-bindgen (it stops at `table.fill`), so take binaryen's own build from the npm registry
# (it runs on node) and put it first on PATH.
binaryen_version=123.0.0
if ! "$tools/bin/wasm-opt" --version 2>/dev/null | grep -q "version ${binaryen_version%%.*}"; then
  echo "setup-web: installing binaryen $binaryen_version (wasm-opt) into .tools/" >&2
  mkdir -p "$tools/binaryen"
  (cd "$tools/binaryen" && npm install --no-audit --no-fund --silent --no-save "binaryen@$binaryen_version")
  ln -sf "$tools/binaryen/node_modules/.bin/wasm-opt" "$tools/bin/wasm-opt"
fi

if [[ "$e2e" == true ]]; then
  if ! command -v chromium >/dev/null 2>&1; then
    echo "setup-web: installing chromium" >&2
    apt_install chromium
  fi
  if [[ ! -d tests/e2e/node_modules/playwright-core ]]; then
    echo "setup-web: npm ci in tests/e2e" >&2
    (cd tests/e2e && npm ci --no-audit --no-fund --silent)
  fi
fi

exec "$@"
