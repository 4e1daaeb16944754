//! Claims 4 and 6 about the linearized woodpecker (guide §8.3 to guide §8.5, guide §11): the order of the
//! critical coefficients (51)/(65), and the independence of Γ from η.
//!
//! ```text
//! (51) μd,MIN^(I): t_ST^(I) ≤ T/2       (65) μd,MIN^(II): t_ST^(II) ≤ T
//! (71) v̄ = g τ W_S² Γ/(24 ζ0² k²),  Γ = Γ^(I) + Γ^(II) depends on λμs, λμd only
//! ```

use crate::claims::sample::{self, WOODPECKER_RANGES};
use crate::claims::{rel_diff, run_wood, spread, Claim, Numbers, Sample, Verdict};
use crate::error::Result;
use crate::models::woodpecker::formula as cf;
use crate::models::woodpecker::results::linear_inputs;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;
use crate::models::Physics;

/// Share of counterexamples above which a statement "for sensible values" is refuted.
const REFUTING_SHARE: f64 = 0.05;
/// z0 values tried for claim 6, as fractions of d0 (0, 0.025, …, 0.975), and how many are kept.
const Z0_STEPS: u32 = 40;
const Z0_KEPT: usize = 5;

/// Claim 4: "μd,MIN^(I) > μd,MIN^(II) for sensible values".
pub(crate) fn claim_4(w: &WoodpeckerParams, sample: &Sample) -> Claim {
    let c = cf::evaluate(&linear_inputs(w));
    let (one, two) = (c.mu_d_min_1, c.mu_d_min_2);
    let given_fails = one.zip(two).is_some_and(|(a, b)| a <= b);
    let result = sample::woodpecker_mu_min_order(sample, w.g, 0.25 * w.period());
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
            crate::claims::counterpart_name(w.counterpart),
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
        v_num.extend(run_wood(&q, LawKind::Linear)?.steady.v_avg);
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
        crate::claims::or_none(gammas.first().copied(), |g| format!("{g:.6}")),
        crate::claims::rel_text(s_gamma),
        crate::claims::or_none(v_num.first().copied(), crate::claims::mm_s),
        crate::claims::rel_text(s_v),
        crate::claims::rel_text(worst_closed),
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
