# spherekit tasks. `./run <recipe>` installs what is missing and runs one of these.
set shell := ["bash", "-euo", "pipefail", "-c"]

# List the recipes
default:
    @just --list

# The main job: sample an example scene (orientations on S³) with the CLI
demo:
    cargo run --quiet --release -p spherekit-snapshot --bin spherekit -- sample examples/orientations.json --deriv

# Everything CI runs, fast checks first
test: fmt-check lint unit doc

# Formatting
fmt-check:
    cargo fmt --all --check

# Clippy on every target, warnings are errors
lint:
    cargo clippy --workspace --all-targets --all-features --locked -- -D warnings

# Unit, integration, property and CLI tests, and doctests
unit:
    cargo test --workspace --all-features --locked

# API docs, warnings are errors
doc:
    RUSTDOCFLAGS="-D warnings" cargo doc --workspace --all-features --no-deps --locked

# Find repeated code (a tool of the development machines)
duplicates:
    duplicates --most 20
