#!/usr/bin/env bash
# Installs what the project needs, only when it is missing, then runs the given command.
# Everything goes under .tools/ (git-ignored) or the Rust toolchain; safe to run again.
#
#   bash scripts/setup.sh just <recipe>...
set -euo pipefail
cd "$(dirname "$0")/.."
tools="$PWD/.tools"
mkdir -p "$tools/bin"
export PATH="$tools/bin:$PATH"

# `just`, the task runner: a prebuilt wheel from PyPI, or built with cargo as a fallback.
if ! command -v just >/dev/null 2>&1; then
  echo "setup: installing just into .tools/" >&2
  if python3 -m venv "$tools/venv" >/dev/null 2>&1 \
    && "$tools/venv/bin/pip" install --quiet --disable-pip-version-check rust-just==1.59.0; then
    ln -sf "$tools/venv/bin/just" "$tools/bin/just"
  else
    cargo install --locked --quiet just --version 1.59.0 --root "$tools"
  fi
fi

# clippy and rustfmt come with the toolchain; add them if a minimal profile left them out.
for component in clippy rustfmt; do
  if ! rustup component list --installed 2>/dev/null | grep -q "^$component"; then
    rustup component add "$component"
  fi
done

exec "$@"
