//! Synthetic tracked data, made by the model itself with seeded Gaussian noise: for the tests,
//! the benchmark and `scenarios/tracked-toy-example.csv`. Not a measurement.
//!
//! ```text
//! t_i = t_0 + i / frame_rate                 t_0 ∈ [0, 1) s from the seed
//! y_i = y_off − [y_S(τ_i) − y_S(τ_1)] + σ ε_i  y up, as tracking apps; ε_i ~ N(0, 1)
//! ```
//! with τ_i as in [`super::track`] and t_shift ∈ [0, T), y_off ∈ [0.1, 0.2) m from the seed.

use std::fmt::Write as _;

use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

use super::data::Unit;
use super::track;
use crate::error::Result;
use crate::models::woodpecker::WoodpeckerParams;

/// What to generate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Synthetic {
    /// The parameters of the model that makes the data.
    pub truth: WoodpeckerParams,
    pub points: usize,
    /// Frames per second of the imagined video.
    pub frame_rate: f64,
    /// Standard deviation σ of the tracking noise (m).
    pub noise: f64,
    pub seed: u64,
}

/// A generated track and the nuisance values it was made with.
#[derive(Clone, Debug, PartialEq)]
pub struct SyntheticTrack {
    /// Times (s) and positions (m, y up).
    pub t: Vec<f64>,
    pub y: Vec<f64>,
    /// The true t_shift (s) and y_off (m) of [`super::fit`].
    pub time_shift: f64,
    pub y_offset: f64,
}

impl Synthetic {
    /// Generates the track (the same bytes for the same seed).
    pub fn generate(&self) -> Result<SyntheticTrack> {
        let mut rng = StdRng::seed_from_u64(self.seed);
        let time_shift = rng.gen::<f64>() * self.truth.period();
        let t0: f64 = rng.gen();
        let y_offset = 0.1 + 0.1 * rng.gen::<f64>();
        let dt: Vec<f64> = (0..self.points)
            .map(|i| i as f64 / self.frame_rate)
            .collect();
        let sleeve = track(&self.truth, time_shift, &dt)?;
        let y = sleeve
            .y
            .iter()
            .map(|y_s| y_offset - y_s + self.noise * gaussian(&mut rng))
            .collect();
        Ok(SyntheticTrack {
            t: dt.iter().map(|d| t0 + d).collect(),
            y,
            time_shift,
            y_offset,
        })
    }
}

impl SyntheticTrack {
    /// The track as a tracking app would export it: `# comment` lines, a header `t,y`, a units
    /// row, times to 1 µs and positions to 0.1 µm.
    pub fn csv(&self, unit: Unit, comment: &str) -> String {
        let mut text: String = comment.lines().map(|l| format!("# {l}\n")).collect();
        let _ = writeln!(text, "t,y\ns,{}", unit.symbol());
        let decimals = match unit {
            Unit::M => 7,
            Unit::Cm => 5,
            Unit::Mm => 4,
        };
        for (t, y) in self.t.iter().zip(&self.y) {
            let _ = writeln!(text, "{t:.6},{:.decimals$}", y / unit.metres());
        }
        text
    }
}

/// A standard normal deviate (Box–Muller).
fn gaussian(rng: &mut StdRng) -> f64 {
    let u1 = 1.0 - rng.gen::<f64>();
    let u2: f64 = rng.gen();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_has_the_asked_spread_and_the_seed_fixes_the_track() {
        let s = Synthetic {
            truth: WoodpeckerParams::default(),
            points: 4000,
            frame_rate: 240.0,
            noise: 2e-4,
            seed: 5,
        };
        let noisy = s.generate().unwrap();
        let clean = Synthetic { noise: 0.0, ..s }.generate().unwrap();
        let n = noisy.y.len() as f64;
        let d: Vec<f64> = noisy.y.iter().zip(&clean.y).map(|(a, b)| a - b).collect();
        let mean = d.iter().sum::<f64>() / n;
        let sd = (d.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt();
        assert!(
            mean.abs() < 2e-5 && (sd / 2e-4 - 1.0).abs() < 0.05,
            "{mean} {sd}"
        );
        assert_eq!(noisy, s.generate().unwrap());
        // The toy falls: y (up) decreases.
        assert!(clean.y[3999] < clean.y[0] - 0.05);
    }
}
