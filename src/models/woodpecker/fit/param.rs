//! The woodpecker parameters a fit can adjust, and the coordinates Levenberg–Marquardt moves
//! them in: unbounded, and valid wherever they go.
//!
//! ```text
//! μd = MU_MIN + (μs − MU_MIN) · σ(x)      MU_MIN < μd < μs
//! μs = lo + (MU_MAX − lo) · σ(x)          lo = MU_MIN, or the fixed μd when μd is not free
//! z0 = x mm                               any sign
//! d0 = eˣ,  k = eˣ                        positive
//! ```
//! with σ the logistic function. μd is set after μs, of which it is a fraction.

use serde::Serialize;

use crate::models::woodpecker::WoodpeckerParams;

use crate::models::param::{MU_MAX, MU_MIN};

/// A woodpecker parameter the fit can adjust.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, clap::ValueEnum)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub enum FitParam {
    #[value(name = "mu_d")]
    MuD,
    #[value(name = "z0")]
    Z0,
    #[value(name = "d0")]
    D0,
    #[value(name = "mu_s")]
    MuS,
    #[value(name = "k")]
    K,
}

impl FitParam {
    /// Fitted unless asked otherwise.
    pub const DEFAULT: [FitParam; 3] = [FitParam::MuD, FitParam::Z0, FitParam::D0];

    pub fn name(self) -> &'static str {
        match self {
            Self::MuD => "mu_d",
            Self::Z0 => "z0",
            Self::D0 => "d0",
            Self::MuS => "mu_s",
            Self::K => "k",
        }
    }

    /// SI unit ("" for the friction coefficients).
    pub fn unit(self) -> &'static str {
        match self {
            Self::MuD | Self::MuS => "",
            Self::Z0 | Self::D0 => "m",
            Self::K => "N/m",
        }
    }

    pub fn get(self, p: &WoodpeckerParams) -> f64 {
        match self {
            Self::MuD => p.mu_d,
            Self::Z0 => p.z0,
            Self::D0 => p.d0,
            Self::MuS => p.mu_s,
            Self::K => p.k,
        }
    }

    pub fn set(self, p: &mut WoodpeckerParams, value: f64) {
        match self {
            Self::MuD => p.mu_d = value,
            Self::Z0 => p.z0 = value,
            Self::D0 => p.d0 = value,
            Self::MuS => p.mu_s = value,
            Self::K => p.k = value,
        }
    }

    /// Typical size, for a relative difference step (z0 may be 0: d0 sets its scale).
    pub fn scale(self, p: &WoodpeckerParams) -> f64 {
        match self {
            Self::Z0 => p.z0.abs().max(p.d0),
            _ => self.get(p).abs(),
        }
    }

    fn internal(self, p: &WoodpeckerParams, free: &[FitParam]) -> f64 {
        match self {
            Self::MuD => logit((p.mu_d - MU_MIN) / (p.mu_s - MU_MIN).max(f64::MIN_POSITIVE)),
            Self::MuS => {
                let lo = mu_s_floor(p, free);
                logit((p.mu_s - lo) / (MU_MAX - lo))
            }
            Self::Z0 => p.z0 * 1e3,
            Self::D0 | Self::K => self.get(p).ln(),
        }
    }

    fn set_internal(self, p: &mut WoodpeckerParams, x: f64, free: &[FitParam]) {
        let value = match self {
            Self::MuD => MU_MIN + (p.mu_s - MU_MIN) * logistic(x),
            Self::MuS => {
                let lo = mu_s_floor(p, free);
                lo + (MU_MAX - lo) * logistic(x)
            }
            Self::Z0 => x * 1e-3,
            Self::D0 | Self::K => x.exp(),
        };
        self.set(p, value);
    }
}

/// The internal coordinates of the `free` parameters of `p`.
pub fn to_internal(p: &WoodpeckerParams, free: &[FitParam]) -> Vec<f64> {
    free.iter().map(|f| f.internal(p, free)).collect()
}

/// `base` with the `free` parameters set from their internal coordinates `x`.
pub fn from_internal(base: &WoodpeckerParams, free: &[FitParam], x: &[f64]) -> WoodpeckerParams {
    let mut p = *base;
    let pairs = || free.iter().zip(x);
    for (f, &xi) in pairs().filter(|(f, _)| **f != FitParam::MuD) {
        f.set_internal(&mut p, xi, free);
    }
    for (f, &xi) in pairs().filter(|(f, _)| **f == FitParam::MuD) {
        f.set_internal(&mut p, xi, free);
    }
    p
}

/// `base` with the `free` parameters set to `values` (physical units).
pub fn with_values(base: &WoodpeckerParams, free: &[FitParam], values: &[f64]) -> WoodpeckerParams {
    let mut p = *base;
    for (f, &v) in free.iter().zip(values) {
        f.set(&mut p, v);
    }
    p
}

/// μs must stay above a fixed μd; a free μd follows μs.
fn mu_s_floor(p: &WoodpeckerParams, free: &[FitParam]) -> f64 {
    if free.contains(&FitParam::MuD) {
        MU_MIN
    } else {
        p.mu_d
    }
}

fn logit(r: f64) -> f64 {
    let r = r.clamp(1e-9, 1.0 - 1e-9);
    (r / (1.0 - r)).ln()
}

fn logistic(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_internal_point_is_a_valid_parameter_set() {
        let base = crate::models::woodpecker::lever::fig26();
        let all = [
            FitParam::MuD,
            FitParam::Z0,
            FitParam::D0,
            FitParam::MuS,
            FitParam::K,
        ];
        for free in [&all[..], &[FitParam::MuS, FitParam::K][..]] {
            let back = from_internal(&base, free, &to_internal(&base, free));
            for f in free {
                let (a, b) = (f.get(&back), f.get(&base));
                assert!((a - b).abs() < 1e-14 * b.abs(), "{f:?} round trip: {a} {b}");
            }
            for x in [-30.0, -1.0, 0.0, 2.0, 30.0] {
                let p = from_internal(&base, free, &vec![x; free.len()]);
                p.validate()
                    .unwrap_or_else(|e| panic!("{free:?} at {x}: {e}"));
            }
        }
    }
}
