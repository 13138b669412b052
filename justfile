# spherekit tasks. `./run <recipe>` installs what is missing and runs one of these.
set shell := ["bash", "-euo", "pipefail", "-c"]

# List the recipes
default:
    @just --list

# Sample an example scene (orientations on S³) with the CLI
demo:
    cargo run --quiet --release -p spherekit-cli --bin spherekit -- sample examples/orientations.json --deriv

# Everything CI runs, fast checks first (installs Chromium with apt-get when it is missing)
test: fmt-check lint lint-wasm core-features corpus-check unit doc publish-check test-wasm test-e2e test-package test-python test-wheel

# The Rust and Python checks, for contributors: no root, no browser, no WebAssembly
check: fmt-check lint core-features corpus-check unit doc publish-check test-python

# Formatting
fmt-check:
    cargo fmt --all --check

# Clippy on every target, warnings are errors
lint:
    cargo clippy --workspace --all-targets --all-features --locked -- -D warnings

# Clippy for the browser target (the crates that ship to wasm), warnings are errors
lint-wasm:
    bash scripts/setup-web.sh cargo clippy -p spherekit-wasm --target wasm32-unknown-unknown --locked -- -D warnings

# The core crate alone, as a user gets it: default features, and no-default-features with libm
core-features:
    cargo test -p spherekit --locked --lib --tests
    cargo check -p spherekit --locked --no-default-features --features libm

# The committed robustness corpus and fuzz dictionary are what the generator writes from the registry
corpus-check:
    cargo run --quiet --locked -p spherekit-cli -- methods --json > target/registry.json
    python3 scripts/robustness_corpus.py --registry target/registry.json --check

# Rewrite tests/robustness and fuzz/scene.dict from the generator (after adding a method or a case)
corpus:
    cargo run --quiet --locked -p spherekit-cli -- methods --json > target/registry.json
    python3 scripts/robustness_corpus.py --registry target/registry.json

# Unit, integration, property and CLI tests, and doctests. `--all-features` includes the core's and
# the scene's `compact` (the browser build's constructions and every-sphere methods, once on S^m),
# so everything runs the shipped wasm path natively; then the golden images again without them,
# the path of the CLI and Python (`core-features` runs the core's own tests without it)
unit:
    cargo test --workspace --all-features --locked
    cargo test -p spherekit-cli --locked --test it golden::

# The Python module: build it into .tools/pyvenv (the pins of python/test-requirements.txt from
# PyPI) and run its pytest suite and the examples of docs/python.md
test-python:
    MPLBACKEND=Agg bash scripts/setup-python.sh python -m pytest -q -c python/pyproject.toml --rootdir python

# The Python wheel as installed: `maturin build --release` (abi3), pip into a fresh venv, the
# pytest suite and docs/python.md run against the installed package from outside the source tree
test-wheel:
    bash scripts/setup-python.sh
    bash scripts/test-wheel.sh

# Time the Python module against scipy in one run (see BENCHMARKS.md, section 7)
bench-python:
    bash scripts/setup-python.sh python scripts/bench_python.py

# scripts/bench_fit.py's docstring says what it measures; `./run bench-fit --repeat-large 0`
# skips the timing of 10⁵ samples (about three minutes of scipy)
# Fitting benchmark: a known motion recovered from noisy samples (S3, S2), speed, key reduction
bench-fit *args:
    bash scripts/setup-python.sh python scripts/bench_fit.py {{args}}

# API docs, warnings are errors
doc:
    RUSTDOCFLAGS="-D warnings" cargo doc --workspace --all-features --no-deps --locked

# The library crates as crates.io would take them: `cargo publish --dry-run` packages spherekit,
# spherekit-scene and spherekit-render together (each against the others' packaged sources) and
# compiles each from its package; uncommitted changes are included. Cargo takes registry crates
# to be immutable: it unpacks each packaged crate once per version under $CARGO_HOME/registry/src
# and never rebuilds a compiled one, so a rerun after a change would verify against the earlier
# package. Hence a target directory of its own, emptied first, and the unpacked copies removed.
publish-check:
    rm -rf target/publish-check "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/spherekit-[0-9]* "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/spherekit-scene-[0-9]* "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/spherekit-render-[0-9]*
    cargo publish --dry-run --locked --allow-dirty --target-dir target/publish-check -p spherekit -p spherekit-scene -p spherekit-render

# Find repeated code (a tool of the development machines)
duplicates:
    duplicates --most 20

# Re-bless failing golden images (UPDATE_GOLDENS=force rewrites all); refused in CI
bless:
    UPDATE_GOLDENS=1 cargo test -p spherekit-cli --test it golden::

# Regenerate tests/golden/contact-sheet.png from the references
contact-sheet:
    cargo run --quiet -p spherekit-cli --example contact_sheet

# Render a scene to a PNG: just render SCENE OUT [SIZE]
render scene out size="512":
    cargo run --quiet --release -p spherekit-cli --bin spherekit -- render {{scene}} -o {{out}} --size {{size}}

# Criterion benches of the core and the renderer (by hand; CI only compiles them)
bench:
    cargo bench -p spherekit -p spherekit-render

# Time spherekit against scipy, numpy-quaternion and splines in one run; writes BENCHMARKS.md
bench-compare:
    test -x .venv/bin/python || python3 -m venv .venv
    .venv/bin/pip install --quiet --disable-pip-version-check scipy==1.17.1 numpy==2.4.6 numpy-quaternion==2024.0.13 splines==0.3.3
    cargo build --quiet --release -p spherekit --example bench_json
    .venv/bin/python scripts/bench_compare.py

# Fuzz scene parsing and curve construction for SECONDS per target (see ROBUSTNESS.md); crashes land in fuzz/artifacts/
fuzz seconds="600" target="all":
    #!/usr/bin/env bash
    set -euo pipefail
    command -v cargo-fuzz >/dev/null || cargo install --locked cargo-fuzz
    # Stable rustc accepts the -Z flags cargo-fuzz passes when RUSTC_BOOTSTRAP is set.
    export RUSTC_BOOTSTRAP=1
    sanitizer=address
    cargo fuzz build -O --sanitizer "$sanitizer" || { sanitizer=none; cargo fuzz build -O --sanitizer none; }
    targets="{{target}}"
    [ "$targets" = all ] && targets="scene_bytes extreme_geometry"
    for t in $targets; do
        mkdir -p "fuzz/corpus/$t"
        extra=(-len_control=0)
        if [ "$t" = scene_bytes ]; then
            cp tests/golden/*.json tests/robustness/degenerate/*.json tests/robustness/bad/*.json "fuzz/corpus/$t/"
            extra=(-dict=fuzz/scene.dict)
        fi
        cargo fuzz run -O --sanitizer "$sanitizer" "$t" "fuzz/corpus/$t" -- \
            -max_total_time={{seconds}} -max_len=4096 -timeout=20 -rss_limit_mb=3072 "${extra[@]}"
    done

# ---- web: wasm bindings, playground, docs widget -------------------------------------------

# Build the npm package `spherekit` into web/pkg (installs wasm-pack, wasm-bindgen and wasm-opt
# when missing): `wasm-pack build` compiles the crate for the browser in Cargo's `web` profile
# (the workspace Cargo.toml: the release profile at opt-level "z" with LTO, one codegen unit,
# panics abort, no debug info; the renderer at opt-level 3 for frame time) on the stable
# toolchain, and runs the pinned wasm-bindgen CLI (`--target web`, with TypeScript
# declarations); `--mode no-install --no-opt`: wasm-pack downloads nothing, and wasm-opt runs
# here for size, -Oz twice (the second pass finds more to remove after the first; BENCHMARKS.md
# section 6). scripts/npm_package.mjs adds the docs widget (crates/spherekit-wasm/js),
# the licences, the file list and the `exports` map to package.json; the project's pages load
# this package. Then web/pkg/presets.json, the playground's example menu (not in the package),
# from the golden scenes (scripts/web_presets.py). The budget is the gzipped size of the .wasm,
# what a browser downloads (`just wasm-size`).
web:
    bash scripts/setup-web.sh wasm-pack --quiet build crates/spherekit-wasm --target web --profile web --mode no-install --no-opt \
        --out-dir "$PWD/web/pkg" --out-name spherekit_wasm --no-gitignore -- --locked
    bash scripts/setup-web.sh wasm-opt web/pkg/spherekit_wasm_bg.wasm -o web/pkg/spherekit_wasm_bg.wasm -Oz -Oz --strip-debug --strip-producers \
        --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext --enable-mutable-globals --enable-reference-types --enable-multivalue
    node scripts/npm_package.mjs web/pkg
    python3 scripts/web_presets.py

# Build, then serve the playground on http://127.0.0.1:8000/ (docs widget: /docs.html)
serve port="8000": web
    @echo "spherekit playground: http://127.0.0.1:{{port}}/  (method gallery: /docs.html)"
    python3 -m http.server {{port}} --bind 127.0.0.1 --directory web

# wasm-bindgen-test tests of the wasm API, under node
test-wasm:
    bash scripts/setup-web.sh cargo test -p spherekit-wasm --target wasm32-unknown-unknown --locked

# End-to-end browser test of the playground and docs page in headless Chromium
test-e2e: web
    bash scripts/setup-web.sh --e2e node tests/e2e/run.mjs

# The npm package as installed: `npm pack` of web/pkg into a scratch directory outside the
# repository, and the code blocks of docs/web.md and the package README run there (pages in
# headless Chromium, a widget against its golden image; JavaScript under node)
test-package: web
    bash scripts/setup-web.sh --e2e node tests/e2e/package.mjs

# Size of the .wasm a browser downloads: gzip -9 against the 350 KiB budget (358 400 bytes), raw
# size beside it (a report; see BENCHMARKS.md section 6)
wasm-size: web
    @bytes=$(stat -c %s web/pkg/spherekit_wasm_bg.wasm); gz=$(gzip -9 -c web/pkg/spherekit_wasm_bg.wasm | wc -c); \
    echo "web/pkg/spherekit_wasm_bg.wasm: gzip -9 $gz bytes ($((gz / 1024)) KiB), raw $bytes bytes ($((bytes / 1024)) KiB); budget 350 KiB gzipped: $([ "$gz" -le 358400 ] && echo "within by $((358400 - gz)) bytes" || echo "over by $((gz - 358400)) bytes")"

# Frame time of the playground (?bench: 20 keys on S3, 4 000 samples, 800x800) in headless Chromium
bench-web: web
    bash scripts/setup-web.sh --e2e node tests/e2e/bench.mjs
