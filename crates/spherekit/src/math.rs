// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Float backend switch and small numerically careful helpers.
//!
//! Every transcendental function of the crate goes through this module, so that the `libm`
//! feature gives bit-identical results on native and wasm targets. `+ − × ÷ sqrt` are
//! correctly rounded everywhere and need no routing.

#[cfg(feature = "libm")]
mod backend {
    #[inline]
    pub(crate) fn sin(x: f64) -> f64 {
        libm::sin(x)
    }
    #[inline]
    pub(crate) fn cos(x: f64) -> f64 {
        libm::cos(x)
    }
    #[inline]
    pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
        libm::sincos(x)
    }
    #[inline]
    pub(crate) fn atan2(y: f64, x: f64) -> f64 {
        libm::atan2(y, x)
    }
    #[inline]
    pub(crate) fn exp(x: f64) -> f64 {
        libm::exp(x)
    }
    #[inline]
    pub(crate) fn ln(x: f64) -> f64 {
        libm::log(x)
    }
    #[inline]
    pub(crate) fn powf(x: f64, y: f64) -> f64 {
        libm::pow(x, y)
    }
}

#[cfg(not(feature = "libm"))]
mod backend {
    #[inline]
    pub(crate) fn sin(x: f64) -> f64 {
        x.sin()
    }
    #[inline]
    pub(crate) fn cos(x: f64) -> f64 {
        x.cos()
    }
    #[inline]
    pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
        x.sin_cos()
    }
    #[inline]
    pub(crate) fn atan2(y: f64, x: f64) -> f64 {
        y.atan2(x)
    }
    #[inline]
    pub(crate) fn exp(x: f64) -> f64 {
        x.exp()
    }
    #[inline]
    pub(crate) fn ln(x: f64) -> f64 {
        x.ln()
    }
    #[inline]
    pub(crate) fn powf(x: f64, y: f64) -> f64 {
        x.powf(y)
    }
}

#[allow(
    unused_imports,
    reason = "not every helper is used by every feature combination"
)]
pub(crate) use backend::{atan2, cos, exp, ln, powf, sin, sin_cos};

/// Below this angle the series branches of [`sinc`] and [`inv_sinc`] are used.
const SERIES_THRESHOLD: f64 = 1e-4;

/// `sin(x)/x`, with `sinc(0) = 1`, accurate to the last bits near 0.
#[inline]
pub(crate) fn sinc(x: f64) -> f64 {
    if x.abs() < SERIES_THRESHOLD {
        let x2 = x * x;
        1.0 - x2 / 6.0 * (1.0 - x2 / 20.0)
    } else {
        sin(x) / x
    }
}

/// `x/sin(x)` for `x ∈ [0, π)`, with value 1 at 0.
#[inline]
pub(crate) fn inv_sinc(x: f64) -> f64 {
    if x.abs() < SERIES_THRESHOLD {
        let x2 = x * x;
        1.0 + x2 / 6.0 * (1.0 + 7.0 * x2 / 60.0)
    } else {
        x / sin(x)
    }
}

/// Below this argument [`sinc_deriv`] and [`kappa`] use their series (to x¹¹: the first term
/// left out is below 1e-17 relative there; the closed forms lose `~1e-16/x²` to cancellation).
const SERIES_THRESHOLD_DERIVATIVES: f64 = 0.1;

/// `σ′(x) = (x cos x − sin x)/x²`, the derivative of [`sinc`], from `(sin x, cos x)` (a series
/// below [`SERIES_THRESHOLD_DERIVATIVES`], where the closed form cancels).
pub(crate) fn sinc_deriv(x: f64, (s, c): (f64, f64)) -> f64 {
    if x.abs() < SERIES_THRESHOLD_DERIVATIVES {
        let x2 = x * x;
        x * (-1.0 / 3.0
            + x2 * (1.0 / 30.0 + x2 * (-1.0 / 840.0 + x2 * (1.0 / 45360.0 - x2 / 3_991_680.0))))
    } else {
        (x * c - s) / (x * x)
    }
}

/// `κ(x) = (x − sin x cos x)/x²`, the curvature term of the cubic's continuity equations (a
/// series below [`SERIES_THRESHOLD_DERIVATIVES`]).
pub(crate) fn kappa(x: f64) -> f64 {
    if x.abs() < SERIES_THRESHOLD_DERIVATIVES {
        let x2 = x * x;
        x * (2.0 / 3.0
            + x2 * (-2.0 / 15.0 + x2 * (4.0 / 315.0 + x2 * (-2.0 / 2835.0 + x2 * 4.0 / 155_925.0))))
    } else {
        let (s, c) = sin_cos(x);
        (x - s * c) / (x * x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn series_branches_are_continuous() {
        for f in [sinc as fn(f64) -> f64, inv_sinc] {
            let below = f(SERIES_THRESHOLD * (1.0 - 1e-12));
            let above = f(SERIES_THRESHOLD * (1.0 + 1e-12));
            assert!((below - above).abs() < 1e-15, "{below} vs {above}");
        }
    }

    #[test]
    fn closed_forms() {
        assert!((sinc(1.0) - 1f64.sin()).abs() < 1e-16, "sinc(1)");
        assert!(
            (inv_sinc(1.0) - 1.0 / 1f64.sin()).abs() < 1e-15,
            "inv_sinc(1)"
        );
        assert!(
            (sinc(1e-6) - (1.0 - 1e-12 / 6.0)).abs() < 1e-18,
            "sinc near 0"
        );
    }

    #[test]
    fn derivative_series_match_closed_forms_at_the_switch() {
        let dsinc: fn(f64) -> f64 = |x| sinc_deriv(x, sin_cos(x));
        for f in [dsinc, kappa] {
            // One ulp apart across the switch: the series below, the closed form at 0.1.
            let below = f(SERIES_THRESHOLD_DERIVATIVES - 1.5e-17);
            let above = f(SERIES_THRESHOLD_DERIVATIVES);
            assert!((below - above).abs() < 1e-15, "{below} vs {above}");
        }
        assert!(
            (kappa(1.0) - (1.0 - 1f64.sin() * 1f64.cos())).abs() < 1e-16,
            "kappa(1)"
        );
        // sinc′ against central differences of sinc.
        for x in [1e-3, 0.05, 0.3, 1.0, 2.5] {
            let h = 1e-6;
            let fd = (sinc(x + h) - sinc(x - h)) / (2.0 * h);
            assert!((dsinc(x) - fd).abs() < 1e-9, "sinc′({x})");
        }
    }
}
