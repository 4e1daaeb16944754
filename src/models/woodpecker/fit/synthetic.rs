//! Synthetic tracked data, made by the model itself with seeded Gaussian noise: for the tests,
//! the benchmark and `scenarios/tracked-toy-example.csv`. Not a measurement.
//!
//! ```text
//! t_i = t_0 + i / frame_rate                 t_0 ∈ [0, 1) s from the seed
//! y_i = y_off − [y_S(τ_i) − y_S(τ_1)] + σ ε_i  y up, as tracking apps; ε_i ~ N(0, 1)
//! ```
//! with τ_i as in [`super::track`] and t_shift ∈ [0, T), y_off ∈ [0.1, 0.2) m from the seed.

use std::fmt::Write as _;

use crate::draws::Draws;

use super::track;
use crate::error::Result;
use crate::fit::data::Unit;
use crate::format::people;
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

/// Where the example track is kept, relative to the repository.
pub const EXAMPLE_FILE: &str = "scenarios/tracked-toy-example.csv";

impl Synthetic {
    /// The example of `scenarios/tracked-toy-example.csv` and of the Figs. 26–27 scene: the
    /// tracked toy's set with μd, z0 and d0 a few percent off it (the paper's "a few percent"),
    /// 500 frames at 240 fps, σ = 0.2 mm, seed 2017.
    pub fn example() -> Self {
        Synthetic {
            truth: WoodpeckerParams {
                mu_d: 0.34,
                z0: 0.0069,
                d0: 0.0093,
                ..crate::models::woodpecker::lever::fig26()
            },
            points: 500,
            frame_rate: 240.0,
            noise: 2e-4,
            seed: 2017,
        }
    }

    /// What the data were made with, in words: for the example file's comment and captions.
    pub fn provenance(&self) -> String {
        let t = &self.truth;
        format!(
            "Synthetic data, NOT a measurement: made by stickslip's exact harmonic woodpecker \
             model (the sleeve position, y up as in tracking apps) with mu_d = {}, z0 = {} mm, \
             d0 = {} mm and k = {} N/m, the other values as in Fig. 15; {} frames at {} fps, \
             Gaussian noise sigma = {} mm, seed {}.",
            people(Some(t.mu_d), 4),
            people(Some(t.z0 * 1e3), 4),
            people(Some(t.d0 * 1e3), 4),
            people(Some(t.k), 4),
            self.points,
            people(Some(self.frame_rate), 4),
            people(Some(self.noise * 1e3), 4),
            self.seed
        )
    }

    /// Generates the track (the same bytes for the same seed).
    pub fn generate(&self) -> Result<SyntheticTrack> {
        let mut rng = Draws::new(self.seed);
        let time_shift = rng.unit() * self.truth.period();
        let t0 = rng.unit();
        let y_offset = rng.between(0.1, 0.2);
        let dt: Vec<f64> = (0..self.points)
            .map(|i| i as f64 / self.frame_rate)
            .collect();
        let sleeve = track(&self.truth, time_shift, &dt)?;
        let y = sleeve
            .y
            .iter()
            .map(|y_s| y_offset - y_s + self.noise * rng.gaussian())
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
