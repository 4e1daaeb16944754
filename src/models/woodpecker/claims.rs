//! Claims 4 and 6 about the linearized woodpecker (guide §8.3 to guide §8.5, guide §11): the order of the
//! critical coefficients (51)/(65), and the independence of Γ from η.
//!
//! ```text
//! (51) μd,MIN^(I): t_ST^(I) ≤ T/2       (65) μd,MIN^(II): t_ST^(II) ≤ T
//! (71) v̄ = g τ W_S² Γ/(24 ζ0² k²),  Γ = Γ^(I) + Γ^(II) depends on λμs, λμd only
//! sample (claim 4):  λ ∈ [1, 3], μs ∈ [0.3, 1], μd = μs·[0.05, 1], k ∈ [5, 50] N/m,
//!                    m_S ∈ [2, 20] g, ζ0 ∈ [2, 20] mm, δ0 = ζ0·[0, 0.95);
//!                    kept if in the closed-form domain without immediate slip (38);
//!                    counterexample: μd,MIN^(I) ≤ μd,MIN^(II)
//! ```
//!
//! The sample evaluates closed forms only, so thousands of sets cost milliseconds; the same
//! seed always gives the same sets ([`Draws`]).

use crate::claims::{
    mm_s, or_none, rel_diff, rel_text, spread, steady_run, Claim, Numbers, Sample, SampleResult,
    Verdict,
};
use crate::draws::Draws;
use crate::error::Result;
use crate::models::woodpecker::formula::{self as cf, LinearWoodpecker};
use crate::models::woodpecker::results::linear_inputs;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;
use crate::models::Physics;

/// Share of counterexamples above which a statement "for sensible values" is refuted.
const REFUTING_SHARE: f64 = 0.05;
/// z0 values tried for claim 6, as fractions of d0 (0, 0.025, …, 0.975), and how many are kept.
const Z0_STEPS: u32 = 40;
const Z0_KEPT: usize = 5;

/// Draws per kept set before the woodpecker sample gives up (most draws are kept).
const MAX_DRAWS_PER_SET: usize = 100;

/// The ranges of the woodpecker sample, for the finding.
const WOODPECKER_RANGES: &str = "λ in [1, 3], μs in [0.3, 1], k in [5, 50] N/m, m_S \
     in [2, 20] g, ζ0 in [2, 20] mm, δ0/ζ0 in [0, 0.95), kept when in the closed-form domain \
     and not slipping at once";

/// Claim 4: "μd,MIN^(I) > μd,MIN^(II) for sensible values".
pub(crate) fn claim_4(w: &WoodpeckerParams, sample: &Sample) -> Claim {
    let c = cf::evaluate(&linear_inputs(w));
    let (one, two) = (c.mu_d_min_1, c.mu_d_min_2);
    let given_fails = one.zip(two).is_some_and(|(a, b)| a <= b);
    let result = woodpecker_mu_min_order(sample, w.g, 0.25 * w.period());
    let verdict = if given_fails || result.share >= REFUTING_SHARE {
        Verdict::Refuted
    } else if result.counterexamples > 0 {
        Verdict::Qualified
    } else {
        Verdict::Confirmed
    };
    let given = match one.zip(two) {
        Some((a, b)) => format!(
            "Given set (`{}` counterpart, λ = {:.3}): μd,MIN^(I) = {a:.4}, μd,MIN^(II) = {b:.4}{}",
            w.counterpart.id(),
            w.lambda(),
            if a > b {
                ", in the paper's order."
            } else {
                ": the order is reversed."
            }
        ),
        None => "The given set is outside the closed-form domain.".to_string(),
    };
    let finding = format!(
        "{given} In {} random valid sets ({WOODPECKER_RANGES}), μd,MIN^(I) ≤ μd,MIN^(II) in {} \
         ({:.1} %): stopping in phase I does not imply stopping in phase II.",
        result.size,
        result.counterexamples,
        100.0 * result.share,
    );
    let mut n = Numbers::default();
    n.push("mu_d,MIN^(I) (given set)", one, "")
        .push("mu_d,MIN^(II) (given set)", two, "")
        .push(
            "share of sample with mu_d,MIN^(I) <= mu_d,MIN^(II)",
            result.share,
            "",
        );
    Claim {
        id: 4,
        model: <WoodpeckerParams as Physics>::ID,
        title: "μd,MIN^(I) > μd,MIN^(II) does not hold in general".to_string(),
        paper_says:
            "For sensible values μd,MIN^(I) (51) is always larger than μd,MIN^(II) (65), so \
                     a sleeve that sticks in the first half period also sticks in the second."
                .to_string(),
        verdict,
        finding,
        numbers: n.take(),
        sample: Some(result),
        does_not_apply: None,
        outside: Vec::new(),
    }
}

/// z0 values (m) in [0, 0.975 d0] for which the paper's standard regime holds, plus the given
/// z0 if it does.
fn standard_z0s(w: &WoodpeckerParams) -> Vec<f64> {
    let standard =
        |z0: f64| cf::evaluate(&linear_inputs(&WoodpeckerParams { z0, ..*w })).paper_regime_valid;
    let mut z0s: Vec<f64> = (0..Z0_STEPS)
        .map(|i| w.d0 * f64::from(i) / f64::from(Z0_STEPS))
        .chain(std::iter::once(w.z0))
        .filter(|&z0| standard(z0))
        .collect();
    z0s.sort_by(f64::total_cmp);
    z0s.dedup();
    if z0s.len() <= Z0_KEPT {
        return z0s;
    }
    // Evenly spread over the standard range.
    let last = z0s.len() - 1;
    (0..Z0_KEPT)
        .map(|i| z0s[(i * last + (Z0_KEPT - 1) / 2) / (Z0_KEPT - 1)])
        .collect()
}

/// Claim 6: Γ does not depend on η; in the standard regime v̄ is independent of δ0.
pub(crate) fn claim_6(w: &WoodpeckerParams) -> Result<Claim> {
    let mut set = *w;
    let mut name = "the given set";
    let mut z0s = standard_z0s(&set);
    let outside = (z0s.len() < 2).then(|| {
        format!(
            "the claim compares z0 values in the paper's standard regime; the given set has {} \
             such z0 near its own",
            if z0s.is_empty() { "no" } else { "only one" }
        )
    });
    if z0s.len() < 2 {
        set = WoodpeckerParams::default();
        name = "the Fig. 15 set (the given set has fewer than two z0 in the standard regime)";
        z0s = standard_z0s(&set);
    }
    let (mut etas, mut gammas, mut v_closed, mut v_num) = (vec![], vec![], vec![], vec![]);
    for &z0 in &z0s {
        let q = WoodpeckerParams { z0, ..set };
        let c = cf::evaluate(&linear_inputs(&q));
        etas.extend(c.eta);
        gammas.extend(c.gamma);
        v_closed.extend(c.v_avg);
        v_num.extend(steady_run(&q, LawKind::Linear)?.steady.v_avg);
    }
    let complete = v_num.len() == z0s.len() && gammas.len() == z0s.len();
    let (s_gamma, s_v) = (spread(&gammas), spread(&v_num));
    let worst_closed = v_closed
        .iter()
        .zip(&v_num)
        .fold(0.0_f64, |m, (a, b)| m.max(rel_diff(*a, *b)));
    let lo_hi = |x: &[f64]| {
        let lo = x.iter().copied().fold(f64::INFINITY, f64::min);
        (lo, x.iter().copied().fold(f64::NEG_INFINITY, f64::max))
    };
    let ((z_lo, z_hi), (e_lo, e_hi)) = (lo_hi(&z0s), lo_hi(&etas));
    let tested = complete && z0s.len() >= 2;
    let depends_on_eta = tested && (s_gamma > 1e-12 || s_v > 1e-9);
    let mut n = Numbers::default();
    n.push("z0 values tried", z0s.len() as f64, "")
        .push("smallest z0", z_lo, "m")
        .push("largest z0", z_hi, "m")
        .push("smallest eta", e_lo, "")
        .push("largest eta", e_hi, "")
        .push("Gamma", gammas.first().copied(), "")
        .push("relative spread of Gamma", s_gamma, "")
        .push(
            "v_avg, integration (first z0)",
            v_num.first().copied(),
            "m/s",
        )
        .push("relative spread of integrated v_avg", s_v, "")
        .push("largest |(71) - integration| / v_avg", worst_closed, "");
    let finding = format!(
        "On {name}, {} values of z0 from {:.2} to {:.2} mm (η from {e_lo:.3} to {e_hi:.3}) all in \
         the standard regime give Γ = {} with relative spread {}; the exact integration of the \
         linearized law gives v̄ = {} with relative spread {}, equal to (71) within {}. Γ depends \
         on λμs and λμd only.",
        z0s.len(),
        1e3 * z_lo,
        1e3 * z_hi,
        or_none(gammas.first().copied(), |g| format!("{g:.6}")),
        rel_text(s_gamma),
        or_none(v_num.first().copied(), mm_s),
        rel_text(s_v),
        rel_text(worst_closed),
    );
    Ok(Claim {
        id: 6,
        model: <WoodpeckerParams as Physics>::ID,
        title: "Γ does not depend on η: in the standard regime v̄ is independent of δ0".to_string(),
        paper_says: "v̄ = g τ W_S² Γ(η, μd, μs)/(24 ζ0² k²) (71), with Γ = Γ^(I) + Γ^(II) written \
                     as a function of η (54), (69), (70)."
            .to_string(),
        verdict: if depends_on_eta {
            Verdict::Confirmed
        } else {
            Verdict::Qualified
        },
        finding,
        numbers: n.take(),
        sample: None,
        does_not_apply: None,
        outside: Vec::new(),
    }
    .outside(<WoodpeckerParams as Physics>::ID, outside))
}

/// Claim 4 on the sample: valid sets with μd,MIN^(I) ≤ μd,MIN^(II). `g` (m/s²) and the quarter
/// period `tau` (s) do not change either critical value; they only complete the set.
fn woodpecker_mu_min_order(sample: &Sample, g: f64, tau: f64) -> SampleResult {
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
    SampleResult::counted(sample, kept, counterexamples, example)
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
    if !cf::in_closed_form_domain(p) {
        return None;
    }
    let c = cf::evaluate(p);
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
