// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Batch evaluation into rows of numbers: the parameters split over scoped threads, each part
//! evaluated in chunks that stay in cache, NaN parameters giving rows of NaN.
//!
//! One output buffer is allocated per call (numpy then takes it over without a copy); every
//! part and every chunk writes its own rows of it, so the values do not depend on the split.

/// How many parameters one batch call of the core gets: its buffers stay in cache.
const CHUNK: usize = 1024;

/// Below this many parameters a batch is evaluated on the calling thread only.
const PARALLEL_MIN: usize = 32_768;

/// The threads a large batch is split over: `SPHEREKIT_THREADS` if set (1 turns the splitting
/// off; read at every batch), else the available parallelism, at most 8.
fn threads() -> usize {
    static AVAILABLE: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    std::env::var("SPHEREKIT_THREADS")
        .ok()
        .and_then(|v| v.parse::<usize>().ok())
        .unwrap_or_else(|| {
            *AVAILABLE.get_or_init(|| {
                std::thread::available_parallelism()
                    .map_or(1, usize::from)
                    .min(8)
            })
        })
        .max(1)
}

/// Rows of `width` numbers, one per parameter of `ts`, written by `part(ts_part, rows)` for
/// contiguous parts of `ts`. A large batch is split into one part per thread (see
/// [`threads`]); the calling thread evaluates the last part itself.
pub(crate) fn split(
    ts: &[f64],
    width: usize,
    part: impl Fn(&[f64], &mut [f64]) + Sync,
) -> Vec<f64> {
    // Zeroed memory comes from the allocator as fresh pages: no pass over it here.
    let mut out = vec![0.0; ts.len() * width];
    let parts = threads().min(ts.len() / (PARALLEL_MIN / 2)).max(1);
    if parts == 1 {
        part(ts, &mut out);
        return out;
    }
    let size = ts.len().div_ceil(parts);
    let part = &part;
    std::thread::scope(|scope| {
        let mut pieces = ts.chunks(size).zip(out.chunks_mut(size * width));
        let last = pieces.next_back();
        let handles: Vec<_> = pieces
            .map(|(t, rows)| scope.spawn(move || part(t, rows)))
            .collect();
        if let Some((t, rows)) = last {
            part(t, rows);
        }
        for h in handles {
            // A panic in a part is re-raised here (pyo3 turns it into a Python exception).
            h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        }
    });
    out
}

/// Writes the rows of `ts` (`width` numbers each) into `out` by `fill(chunk, scratch, rows)`
/// for chunks of at most [`CHUNK`] parameters, with `scratch` as many copies of `slot` as the
/// chunk has parameters (the core's batch output). No parameter `fill` sees is NaN: a NaN is
/// passed as `stand_in` (a parameter where the curve is defined) and its row then set to NaN.
pub(crate) fn by_chunks<T: Clone>(
    ts: &[f64],
    out: &mut [f64],
    width: usize,
    stand_in: f64,
    slot: T,
    mut fill: impl FnMut(&[f64], &mut [T], &mut [f64]),
) {
    debug_assert_eq!(
        out.len(),
        ts.len() * width,
        "one row of `width` numbers per parameter"
    );
    let mut scratch = vec![slot; ts.len().min(CHUNK)];
    let mut clean = Vec::new();
    for (chunk, rows) in ts.chunks(CHUNK).zip(out.chunks_mut(CHUNK * width)) {
        // A fold rather than `any`: no early exit, so the check is vectorised.
        let nan = chunk.iter().fold(false, |nan, t| nan | t.is_nan());
        let params = if nan {
            clean.clear();
            clean.extend(chunk.iter().map(|&t| if t.is_nan() { stand_in } else { t }));
            clean.as_slice()
        } else {
            chunk
        };
        fill(params, &mut scratch[..chunk.len()], rows);
        if nan {
            for (t, row) in chunk.iter().zip(rows.chunks_exact_mut(width)) {
                if t.is_nan() {
                    row.fill(f64::NAN);
                }
            }
        }
    }
}
