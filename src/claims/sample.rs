//! Seeded random samples of valid parameter sets for the claims about "sensible values"
//! (claims 1 and 4). Only closed forms are evaluated here, so thousands of sets cost
//! milliseconds; the same seed always gives the same sets ([`Draws`]).
//!
//! ```text
//! pulled mass (claim 1):  μs ∈ [0.1, 1],  μd = μs·[0.05, 1],  φ uniform in (1/Θ, 2μs]
//!                         counterexample to (20): late stick, φ ≤ φ_c
//! woodpecker (claim 4):   λ ∈ [1, 3], μs ∈ [0.3, 1], μd = μs·[0.05, 1], k ∈ [5, 50] N/m,
//!                         m_S ∈ [2, 20] g, ζ0 ∈ [2, 20] mm, δ0 = ζ0·[0, 0.95);
//!                         kept if in the closed-form domain without immediate slip (38);
//!                         counterexample: μd,MIN^(I) ≤ μd,MIN^(II)
//! ```

use crate::draws::Draws;

use super::{Sample, SampleResult};
use crate::models::pulled_mass::formula as pcf;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::formula::{self as wcf, LinearWoodpecker};

/// Draws per kept set before the woodpecker sample gives up (most draws are kept).
const MAX_DRAWS_PER_SET: usize = 100;

/// The ranges of the woodpecker sample, for the finding.
pub(crate) const WOODPECKER_RANGES: &str = "λ in [1, 3], μs in [0.3, 1], k in [5, 50] N/m, m_S \
     in [2, 20] g, ζ0 in [2, 20] mm, δ0/ζ0 in [0, 0.95), kept when in the closed-form domain \
     and not slipping at once";

/// The first late-stick set of the pulled-mass sample, to integrate.
pub(crate) struct PulledExample {
    pub params: PulledMassParams,
}

/// Claim 1 on the sample: sets in the "non-stick" area of Fig. 9 (φ > 1/Θ, no immediate slip)
/// that still stick, in the next period (φ ≤ φ_c).
pub(crate) fn pulled_late_stick(sample: &Sample) -> (SampleResult, Option<PulledExample>) {
    let mut rng = Draws::new(sample.seed);
    let mut counterexamples = 0;
    let mut example = None;
    for _ in 0..sample.size {
        let mu_s = rng.between(0.1, 1.0);
        let mu_d = mu_s * rng.between(0.05, 1.0);
        let lo = pcf::phi_stick_max(mu_s, mu_d);
        // 1/Θ ≤ μd ≤ μs < 2μs, so the interval is never empty.
        let phi = lo + (2.0 * mu_s - lo) * (1.0 - rng.unit());
        if pcf::regime(phi, mu_s, mu_d) != pcf::Regime::SlipStickLate {
            continue;
        }
        counterexamples += 1;
        if example.is_none() {
            let base = PulledMassParams::default();
            let params = PulledMassParams {
                mu_s,
                mu_d,
                force: phi * base.weight(),
                ..base
            };
            let text = format!(
                "μs = {mu_s:.4}, μd = {mu_d:.4}, φ = {phi:.4}: (20) needs φ ≤ 1/Θ = {lo:.4}, \
                 but φ ≤ φ_c = {:.4}, so the mass sticks at τ = {:.6} (m 0.06 kg, k 45 N/m)",
                pcf::phi_continuous(mu_s, mu_d),
                pcf::tau_stick_late(phi, mu_s, mu_d).unwrap_or(f64::NAN),
            );
            example = Some((text, PulledExample { params }));
        }
    }
    let (text, example) = example.unzip();
    (result(sample, sample.size, counterexamples, text), example)
}

/// Claim 4 on the sample: valid sets with μd,MIN^(I) ≤ μd,MIN^(II). `g` (m/s²) and the quarter
/// period `tau` (s) do not change either critical value; they only complete the set.
pub(crate) fn woodpecker_mu_min_order(sample: &Sample, g: f64, tau: f64) -> SampleResult {
    let mut rng = Draws::new(sample.seed);
    let (mut kept, mut counterexamples) = (0, 0);
    let mut example = None;
    for _ in 0..sample.size.saturating_mul(MAX_DRAWS_PER_SET) {
        if kept == sample.size {
            break;
        }
        let p = random_woodpecker(&mut rng, g, tau);
        let Some((one, two)) = mu_d_mins(&p) else {
            continue;
        };
        kept += 1;
        if one <= two {
            counterexamples += 1;
            example.get_or_insert_with(|| describe(&p, one, two));
        }
    }
    result(sample, kept, counterexamples, example)
}

fn random_woodpecker(rng: &mut Draws, g: f64, tau: f64) -> LinearWoodpecker {
    let lambda = rng.between(1.0, 3.0);
    let mu_s = rng.between(0.3, 1.0);
    let mu_d = mu_s * rng.between(0.05, 1.0);
    let k = rng.between(5.0, 50.0);
    let m_s = rng.between(0.002, 0.02);
    let zeta0 = rng.between(0.002, 0.02);
    let delta0 = zeta0 * rng.between(0.0, 0.95);
    LinearWoodpecker {
        mu_s,
        mu_d,
        lambda,
        k,
        w_s: m_s * g,
        g,
        zeta0,
        delta0,
        tau_quarter: tau,
    }
}

/// (μd,MIN^(I), μd,MIN^(II)) of a set in the closed-form domain without immediate slip.
fn mu_d_mins(p: &LinearWoodpecker) -> Option<(f64, f64)> {
    if !wcf::in_closed_form_domain(p) {
        return None;
    }
    let c = wcf::evaluate(p);
    if c.immediate_slip {
        return None;
    }
    c.mu_d_min_1.zip(c.mu_d_min_2)
}

fn describe(p: &LinearWoodpecker, one: f64, two: f64) -> String {
    format!(
        "λ = {:.3}, μs = {:.3}, k = {:.2} N/m, m_S = {:.2} g, ζ0 = {:.2} mm, δ0 = {:.2} mm: \
         μd,MIN^(I) = {one:.4} ≤ μd,MIN^(II) = {two:.4}",
        p.lambda,
        p.mu_s,
        p.k,
        1e3 * p.w_s / p.g,
        1e3 * p.zeta0,
        1e3 * p.delta0,
    )
}

fn result(
    sample: &Sample,
    size: usize,
    counterexamples: usize,
    example: Option<String>,
) -> SampleResult {
    SampleResult {
        size,
        seed: sample.seed,
        counterexamples,
        share: if size == 0 {
            0.0
        } else {
            counterexamples as f64 / size as f64
        },
        example,
    }
}
