//! Whether the fitted model describes the data, and a slip of the position unit.
//!
//! LM stopping at a minimum says nothing about whether the minimum describes the data: the
//! residual is multimodal, and a model in the wrong unit still has a best fit. The residual of
//! a model that describes the data is the tracking noise; the test compares it with the noise
//! the data show on their own, and with itself.
//!
//! ```text
//! σ̂     = median|Δ³y| / (0.6745 √20)    Δ³y = y₃ − 3y₂ + 3y₁ − y₀ over 4 equally spaced rows
//! ρ₁    = Σ r_i r_{i+1} / Σ r_i²        lag-1 autocorrelation of the residuals
//! misfit  RMS > 1 µm  and  (ρ₁ > 0.8  or  RMS > 3 σ̂)
//! ```
//!
//! σ̂: white noise of spread σ gives Δ³ a spread √20 σ, and the median of |·| of a Gaussian is
//! 0.6745 of its spread. The third difference removes the motion up to its jerk (at 240 fps a
//! few µm for the toy), and the median ignores the few rows at each slip onset, where the
//! acceleration jumps. At fewer than ~20 frames per period the motion itself enters σ̂, which
//! then overstates the noise: the test errs towards "describes".
//!
//! ρ₁: a residual made of white noise (σ) and a systematic part S that is smooth on the scale
//! of a frame has ρ₁ ≈ S²/(S² + σ²); ρ₁ > 0.8 means S > 2σ, a misfit twice the noise. For white
//! residuals ρ₁ scatters by 1/√n about 0, so 0.8 is never reached by chance past a few dozen
//! rows. Tracking that smooths the positions (a filter in the app) correlates the noise itself
//! and can trip this test: fit the raw positions.
//!
//! RMS > 3σ̂: at the true parameters RMS ≈ σ; three times the data's own noise is a residual the
//! noise cannot make, whether or not it is smooth (a misfit at low frame rates is not).
//!
//! 1 µm: below any video tracking's resolution; noise-free synthetic data fitted to rounding
//! have smooth residuals (ρ₁ near 1) that are not a misfit.
//!
//! Unit slip: the data fall at v_data (the slope of a straight line through them), the model
//! at the given parameters at v̄. A ratio within a factor 2 of 10, 100 or 1000 (either way)
//! points at the unit; the fit is repeated in the unit that undoes it, and that unit is named
//! when the model then describes the data. A 10× slip scales the noise with the data, and the
//! model, flexible, can describe the data as read loosely (RMS 1.4 σ̂, ρ₁ 0.3): the data as read
//! are then judged not described when the other unit's residual is clearly less systematic
//! (ρ₁ lower by 3/√n, three spreads of white noise's ρ₁).

use serde::Serialize;

use super::data::Unit;
use crate::format::sig;

/// Lag-1 autocorrelation of the residuals above which the misfit is systematic (S > 2σ).
pub const MAX_AUTOCORRELATION: f64 = 0.8;
/// RMS residual over the data's own noise above which the noise cannot explain the residual.
pub const MAX_RMS_OVER_NOISE: f64 = 3.0;
/// A residual below this (m) describes the data whatever its shape.
pub const RESOLUTION: f64 = 1e-6;
/// Fewest runs of four equally spaced rows from which the noise is estimated.
const MIN_WINDOWS: usize = 8;
/// Two time steps are equal to this relative tolerance (timestamps are rounded).
const EQUAL_STEPS: f64 = 0.01;
/// Median of |X| for a standard Gaussian X.
const MEDIAN_ABS_GAUSSIAN: f64 = 0.674_489_750_196_081_7;
/// A speed ratio within this factor of a power of ten is a unit slip.
const SLIP_TOLERANCE: f64 = 2.0;

/// The verdict on a fit (fit.json's `verdict`).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Verdict {
    /// The residual is the tracking noise: the model describes the data.
    pub describes: bool,
    /// RMS residual (m).
    pub rms: f64,
    /// The noise the data show on their own (m); `None` with fewer than 8 runs of four equally
    /// spaced rows.
    pub noise: Option<f64>,
    /// RMS residual over `noise`.
    pub rms_over_noise: Option<f64>,
    /// Lag-1 autocorrelation of the residuals.
    pub autocorrelation: f64,
    /// Why the model does not describe the data, one sentence each (empty when it does).
    pub reasons: Vec<String>,
    /// The data fall a power of ten faster or slower than the model: a slip of the unit.
    pub scale: Option<ScaleSlip>,
}

/// The data fall `factor` times as fast as the model at the given parameters.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ScaleSlip {
    /// The power of ten nearest the speed ratio, and the ratio itself.
    pub factor: f64,
    pub ratio: f64,
    /// The unit of the positions that undoes the factor, when `--units` offers it.
    pub units: Option<Unit>,
    /// RMS residual (m) of the fit in `units`, when the model describes the data in it.
    pub rms_in_units: Option<f64>,
}

impl Verdict {
    /// The verdict on residuals `r` (m) of a fit to positions `y` (m) at times `t` (s).
    pub fn judge(t: &[f64], y: &[f64], r: &[f64]) -> Verdict {
        let n = r.len();
        let rss: f64 = r.iter().map(|x| x * x).sum();
        let rms = (rss / n as f64).sqrt();
        let lagged: f64 = r.windows(2).map(|w| w[0] * w[1]).sum();
        let autocorrelation = if rss > 0.0 { lagged / rss } else { 0.0 };
        let noise = noise(t, y);
        let rms_over_noise = noise.filter(|&s| s > 0.0).map(|s| rms / s);
        let mut reasons = Vec::new();
        if rms > RESOLUTION {
            if let Some(ratio) = rms_over_noise.filter(|&q| q > MAX_RMS_OVER_NOISE) {
                reasons.push(format!(
                    "the residual (RMS {} mm) is {}× the noise the data show on their own ({} \
                     mm; the model's residual should be that noise)",
                    sig(Some(rms * 1e3), 3),
                    sig(Some(ratio), 2),
                    sig(noise.map(|s| s * 1e3), 2)
                ));
            }
            if autocorrelation > MAX_AUTOCORRELATION {
                reasons.push(format!(
                    "the residuals are systematic, not noise: lag-1 autocorrelation {} (above \
                     {MAX_AUTOCORRELATION}: a misfit more than twice the noise)",
                    sig(Some(autocorrelation), 2)
                ));
            }
        }
        Verdict {
            describes: reasons.is_empty(),
            rms,
            noise,
            rms_over_noise,
            autocorrelation,
            reasons,
            scale: None,
        }
    }

    /// The verdict in one line (for the error message and the terminal).
    pub fn sentence(&self) -> String {
        if self.describes {
            return "the model describes these data (the residual is the noise)".to_string();
        }
        let mut s = format!(
            "the model does not describe these data: {}",
            self.reasons.join("; ")
        );
        if let Some(slip) = &self.scale {
            s.push_str("; ");
            s.push_str(&slip.sentence());
        }
        s
    }
}

impl Verdict {
    /// This residual is clearly less systematic than `other`'s, of `n` rows: its lag-1
    /// autocorrelation lower by 3/√n, three spreads of that of white noise.
    pub fn less_systematic_than(&self, other: &Verdict, n: usize) -> bool {
        self.autocorrelation < other.autocorrelation - 3.0 / (n as f64).sqrt()
    }

    /// A negative verdict in at most ~120 characters, for the one-line error: the unit that
    /// fits first, as it is what to do.
    pub fn brief(&self) -> String {
        if let Some(line) = self.scale.as_ref().and_then(ScaleSlip::fits_in_units) {
            return line;
        }
        let mut s = format!(
            "the model does not describe these data: RMS {} mm",
            sig(Some(self.rms * 1e3), 3)
        );
        if let Some(q) = self.rms_over_noise {
            s.push_str(&format!(", {}× their noise", sig(Some(q), 2)));
        }
        s.push_str(&format!(
            ", residual autocorrelation {}",
            sig(Some(self.autocorrelation), 2)
        ));
        if let Some(slip) = &self.scale {
            s.push_str(&format!(
                "; positions {} for the model: check their unit",
                ten_times(slip.factor)
            ));
        }
        s
    }
}

/// "100× too large", "10× too small".
fn ten_times(factor: f64) -> String {
    if factor > 1.0 {
        format!("{}× too large", sig(Some(factor), 1))
    } else {
        format!("{}× too small", sig(Some(1.0 / factor), 1))
    }
}

impl ScaleSlip {
    /// "the model does not describe these data as read (positions 1000× too large); with
    /// --units mm it does (RMS 0.20 mm)", when the unit that undoes the slip fits.
    pub fn fits_in_units(&self) -> Option<String> {
        let (u, rms) = (self.units?, self.rms_in_units?);
        Some(format!(
            "the model does not describe these data as read (positions {}); with --units {} it \
             does (RMS {} mm)",
            ten_times(self.factor),
            u.symbol(),
            sig(Some(rms * 1e3), 2)
        ))
    }

    /// The slip in a few words, for the front of a one-line error.
    pub fn brief(&self) -> String {
        match (self.units, self.rms_in_units) {
            (Some(u), Some(_)) => format!(
                "positions {} for the model; with --units {} it fits",
                ten_times(self.factor),
                u.symbol()
            ),
            _ => format!(
                "positions {} for the model: check their unit",
                ten_times(self.factor)
            ),
        }
    }

    /// The slip in words.
    pub fn sentence(&self) -> String {
        let how = if self.factor > 1.0 {
            format!("{}× faster", sig(Some(self.factor), 1))
        } else {
            format!("{}× slower", sig(Some(1.0 / self.factor), 1))
        };
        let mut s = format!(
            "the positions fall {how} than the model at the given parameters (ratio {}): a \
             slip of the unit",
            sig(Some(self.ratio), 2)
        );
        match (self.units, self.rms_in_units) {
            (Some(u), Some(rms)) => s.push_str(&format!(
                "; with --units {} the model describes them (RMS {} mm)",
                u.symbol(),
                sig(Some(rms * 1e3), 2)
            )),
            (Some(u), None) => s.push_str(&format!(
                "; --units {} undoes it, but the model does not describe the data in it either",
                u.symbol()
            )),
            (None, _) => s.push_str("; check the unit of the positions"),
        }
        s
    }
}

/// The power of ten (≠ 1) within [`SLIP_TOLERANCE`] of `ratio` = data speed / model speed, and
/// the unit of the positions that undoes it from `unit`; `None` when the ratio is near 1 or
/// not near a power of ten up to 1000.
pub fn scale_slip(ratio: f64, unit: Unit) -> Option<(f64, Option<Unit>)> {
    if !(ratio.is_finite() && ratio > 0.0) {
        return None;
    }
    let power = ratio.log10().round();
    let factor = 10f64.powf(power);
    let close = (ratio / factor).max(factor / ratio) <= SLIP_TOLERANCE;
    if power == 0.0 || power.abs() > 3.0 || !close {
        return None;
    }
    let want = unit.metres() / factor;
    let units = [Unit::M, Unit::Cm, Unit::Mm]
        .into_iter()
        .find(|u| (u.metres() / want - 1.0).abs() < 1e-9);
    Some((factor, units))
}

/// The speed (m/s) of the straight line through (t, y): the data's mean fall.
pub fn descent_speed(t: &[f64], y: &[f64]) -> f64 {
    let n = t.len() as f64;
    let (tm, ym) = (t.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxx: f64 = t.iter().map(|t| (t - tm).powi(2)).sum();
    let sxy: f64 = t.iter().zip(y).map(|(t, y)| (t - tm) * (y - ym)).sum();
    (sxy / sxx).abs()
}

/// The noise σ̂ of positions `y` at times `t` (see the module doc), from runs of four rows with
/// equal time steps; `None` when there are fewer than [`MIN_WINDOWS`].
pub fn noise(t: &[f64], y: &[f64]) -> Option<f64> {
    let equal = |a: f64, b: f64| (a - b).abs() <= EQUAL_STEPS * a.abs().max(b.abs());
    let mut d3: Vec<f64> = (0..t.len().saturating_sub(3))
        .filter(|&i| {
            let h = [t[i + 1] - t[i], t[i + 2] - t[i + 1], t[i + 3] - t[i + 2]];
            equal(h[0], h[1]) && equal(h[1], h[2])
        })
        .map(|i| (y[i + 3] - 3.0 * y[i + 2] + 3.0 * y[i + 1] - y[i]).abs())
        .collect();
    if d3.len() < MIN_WINDOWS {
        return None;
    }
    let mid = d3.len() / 2;
    let (_, median, _) = d3.select_nth_unstable_by(mid, f64::total_cmp);
    Some(*median / (MEDIAN_ABS_GAUSSIAN * 20f64.sqrt()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::draws::Draws;

    #[test]
    fn the_noise_of_a_smooth_motion_is_the_noise_added() {
        let mut rng = Draws::new(7);
        let t: Vec<f64> = (0..2000).map(|i| f64::from(i) / 240.0).collect();
        // A fall with a strong periodic part (accelerations of ~5 m/s²).
        let y: Vec<f64> = t
            .iter()
            .map(|t| -0.02 * t + 1e-3 * (38.0 * t).sin() + 3e-4 * rng.gaussian())
            .collect();
        let s = noise(&t, &y).unwrap();
        assert!((s / 3e-4 - 1.0).abs() < 0.08, "{s}");
        // Gaps (skipped rows) only remove windows.
        let keep: Vec<usize> = (0..2000).filter(|i| i % 7 != 3).collect();
        let (tg, yg): (Vec<f64>, Vec<f64>) = keep.iter().map(|&i| (t[i], y[i])).unzip();
        let sg = noise(&tg, &yg).unwrap();
        assert!((sg / 3e-4 - 1.0).abs() < 0.1, "{sg}");
        assert_eq!(noise(&t[..9], &y[..9]), None);
    }

    #[test]
    fn white_residuals_describe_and_smooth_large_ones_do_not() {
        let mut rng = Draws::new(3);
        let t: Vec<f64> = (0..500).map(|i| f64::from(i) / 240.0).collect();
        let e: Vec<f64> = t.iter().map(|_| 2e-4 * rng.gaussian()).collect();
        let y: Vec<f64> = t.iter().zip(&e).map(|(t, e)| -0.02 * t + e).collect();
        let good = Verdict::judge(&t, &y, &e);
        assert!(good.describes, "{good:?}");
        assert!(good.autocorrelation.abs() < 0.15);
        let smooth: Vec<f64> = t
            .iter()
            .zip(&e)
            .map(|(t, e)| e + 1e-3 * (38.0 * t).sin())
            .collect();
        let bad = Verdict::judge(&t, &y, &smooth);
        assert!(!bad.describes && bad.reasons.len() == 2, "{bad:?}");
        assert!(bad
            .sentence()
            .starts_with("the model does not describe these data: "));
        // Noise-free residuals at rounding level are no misfit, smooth or not.
        let tiny: Vec<f64> = t.iter().map(|t| 1e-9 * (38.0 * t).sin()).collect();
        assert!(Verdict::judge(&t, &y, &tiny).describes);
    }

    #[test]
    fn a_power_of_ten_in_the_speed_is_a_unit_slip() {
        assert_eq!(scale_slip(95.0, Unit::M), Some((100.0, Some(Unit::Cm))));
        assert_eq!(scale_slip(1300.0, Unit::M), Some((1000.0, Some(Unit::Mm))));
        assert_eq!(scale_slip(0.0011, Unit::Mm), Some((0.001, Some(Unit::M))));
        assert_eq!(scale_slip(0.011, Unit::Mm), Some((0.01, None)));
        assert_eq!(scale_slip(9.0, Unit::Cm), Some((10.0, Some(Unit::Mm))));
        assert_eq!(scale_slip(12.0, Unit::M), Some((10.0, None)));
        for near_one in [1.0, 1.8, 0.6, 3.5, 30.0, 1e5, f64::NAN, 0.0] {
            assert_eq!(scale_slip(near_one, Unit::M), None, "{near_one}");
        }
    }
}
