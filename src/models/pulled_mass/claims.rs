//! Claims 1 and 2 about the pulled mass (guide §7, guide §11): the stick condition (20)/(22)
//! against the late stick, and the coefficient of D^{3/2} in Γ (28). Also picks the periodic
//! set that claims 3 and 7 compare the two force laws on, and draws the seeded random sample of
//! claim 1 (only closed forms are evaluated on it, so thousands of sets cost milliseconds).
//!
//! ```text
//! (20)  t_ST ≤ T  ⇔  φ ≤ 1/Θ            (22)  μs = μd = μ:  μ ≥ μ_MIN = (1+√2)φ/2
//! late stick  1/Θ < φ ≤ φ_c,  φ_c = 4μsμd/(2μs + √(2D))   (μs = μd = μ ⇒ φ_c = μ)
//! (28)  Γ = [c·D^{3/2} + μs³ + 3μs²μd − μd³]/(96 μs³ μd²),  c = 1 (derived) or 2 (misreading)
//! sample (claim 1):  μs ∈ [0.1, 1],  μd = μs·[0.05, 1],  φ uniform in (1/Θ, 2μs]
//!                    counterexample to (20): late stick, φ ≤ φ_c
//! ```

use crate::claims::{
    mm_s, or_none, rel_diff, rel_text, steady_run, Claim, Integrated, Numbers, Sample,
    SampleResult, Verdict,
};
use crate::draws::Draws;
use crate::engine::IntegrationRegime;
use crate::error::Result;
use crate::models::pulled_mass::formula as cf;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::LawKind;
use crate::models::Physics;

/// Agreement of a closed form with the exact integration (guide §12).
const AGREE: f64 = 1e-9;

/// Set B of guide §13: μs 0.4, μd 0.35, F 0.10 N, m 0.06 kg, k 45 N/m (slip-stick).
pub(crate) fn set_b() -> PulledMassParams {
    PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    }
}

/// A pulled-mass set that is periodic in both laws, with both integrations.
pub(crate) struct PeriodicSet {
    pub p: PulledMassParams,
    /// "the given set" or "set B (…)".
    pub name: String,
    /// Why the given set was replaced by set B (`None` when it is the given set).
    pub outside: Option<String>,
    pub linear: Integrated,
    pub harmonic: Integrated,
}

impl PeriodicSet {
    fn of(p: &PulledMassParams, name: String) -> Result<Self> {
        Ok(Self {
            p: *p,
            name,
            outside: None,
            linear: steady_run(p, LawKind::Linear)?,
            harmonic: steady_run(p, LawKind::Harmonic)?,
        })
    }

    fn moves_periodically(&self) -> bool {
        let advancing = |r: &Integrated| r.steady.v_avg.is_some_and(|v| v > 0.0);
        advancing(&self.linear) && advancing(&self.harmonic)
    }
}

/// The given set if both laws reach a periodic orbit that advances, else set B.
pub(crate) fn periodic_set(p: &PulledMassParams) -> Result<PeriodicSet> {
    let given = PeriodicSet::of(p, "the given set".to_string())?;
    if given.moves_periodically() {
        return Ok(given);
    }
    let mut b = PeriodicSet::of(
        &set_b(),
        "set B (μs 0.4, μd 0.35, F 0.10 N, m 0.06 kg, k 45 N/m), as the given set does not \
         reach a periodic, advancing motion in both laws"
            .to_string(),
    )?;
    b.outside = Some(format!(
        "the claim compares periodic, advancing motions; the given set has none in both laws \
         (linearized: {}; harmonic: {})",
        given.linear.steady.regime().words(),
        given.harmonic.steady.regime().words()
    ));
    Ok(b)
}

/// Claim 1: (20) is the same-period condition; with μs = μd the least friction for a stick is φ.
pub(crate) fn claim_1(p: &PulledMassParams, sample: &Sample) -> Result<Claim> {
    let phi = p.phi();
    let (stick_max, phi_c) = (
        cf::phi_stick_max(p.mu_s, p.mu_d),
        cf::phi_continuous(p.mu_s, p.mu_d),
    );
    let regime = cf::regime(phi, p.mu_s, p.mu_d);
    // μ halfway between φ (least μ for any stick) and the (22) minimum.
    let mu_min = cf::mu_min_equal(phi);
    let mu = 0.5 * (phi + mu_min);
    let q = PulledMassParams {
        mu_s: mu,
        mu_d: mu,
        ..*p
    };
    let run = steady_run(&q, LawKind::Linear)?;
    let tau_stick = run
        .first_slip_and_stick()
        .and_then(|(_, stick)| stick)
        .map(|t| t / q.period());
    let late_closed = cf::tau_stick_late(phi, mu, mu);
    let sticks = run.steady.regime() == IntegrationRegime::SingleSlipStick && tau_stick.is_some();
    let (result, example) = pulled_late_stick(sample);
    let example_check = example.as_ref().map(check_example).transpose()?;
    let mut n = Numbers::default();
    n.push("phi = F/W (given set)", phi, "")
        .push("1/Theta, (20) bound (given set)", stick_max, "")
        .push("phi_c, any-stick bound (given set)", phi_c, "")
        .push("mu = mu_s = mu_d tried", mu, "")
        .push("mu_MIN of (22)", mu_min, "")
        .push(
            "stick time / T, integration (mu_s = mu_d = mu)",
            tau_stick,
            "",
        )
        .push(
            "tau_ST,late closed form (mu_s = mu_d = mu)",
            late_closed,
            "",
        )
        .push("share of late-stick sets in the sample", result.share, "");
    let finding = format!(
        "Given set: φ = F/W = {phi:.4}, 1/Θ = {stick_max:.4}, φ_c = {phi_c:.4} (linearized law: \
         {}). With μs = μd = μ = {mu:.4}, below the (22) minimum {mu_min:.4} but above φ, the \
         exact integration of the linearized law {}; so (20) only decides whether the stick comes \
         within the same period. Of {} random sets in the \"non-stick\" area of Fig. 9 (μs in \
         [0.1, 1], μd/μs in [0.05, 1], φ uniform between 1/Θ and 2μs), {} ({:.1} %) stick early \
         in the next period{}.",
        regime.words(),
        stick_words(tau_stick.filter(|_| sticks), late_closed),
        result.size,
        result.counterexamples,
        100.0 * result.share,
        example_check.unwrap_or_default(),
    );
    Ok(Claim {
        id: 1,
        model: <PulledMassParams as Physics>::ID,
        title: "Eq. (20) is the condition to stick within the same period, not to stick at all"
            .to_string(),
        paper_says: "The necessary condition for the stick is t_ST ≤ T, i.e. F/W ≤ 1/Θ (20); with \
                     μs = μd the least friction coefficient is μ_MIN = (1+√2)φ/2 (22)."
            .to_string(),
        verdict: if sticks {
            Verdict::Refuted
        } else {
            Verdict::Confirmed
        },
        finding,
        numbers: n.take(),
        sample: Some(result),
        does_not_apply: None,
        outside: Vec::new(),
    })
}

/// What the integration with μs = μd = μ shows, beside the late-stick closed form.
fn stick_words(tau_stick: Option<f64>, late_closed: Option<f64>) -> String {
    match tau_stick {
        Some(t) => format!(
            "shows the mass stopping at t = {t:.6} T, {} (closed form τ_ST,late = {})",
            if t > 1.0 {
                "early in the next period"
            } else {
                "within the period"
            },
            or_none(late_closed, |l| format!("{l:.6}"))
        ),
        None => "shows no stick".to_string(),
    }
}

/// Integrates the sample's first late-stick set and says where it sticks.
fn check_example(e: &PulledExample) -> Result<String> {
    let run = steady_run(&e.params, LawKind::Linear)?;
    let stick = run.first_slip_and_stick().and_then(|(_, st)| st);
    Ok(match stick {
        Some(t) => format!(
            "; the first of them, integrated exactly, stops at t = {:.6} T",
            t / e.params.period()
        ),
        None => "; the first of them shows no stick when integrated exactly".to_string(),
    })
}

/// Γ of (28) with coefficient `c` in front of D^{3/2}.
fn gamma_with(c: f64, mu_s: f64, mu_d: f64) -> f64 {
    let d = cf::big_d(mu_s, mu_d);
    (c * d * d.sqrt() + mu_s.powi(3) + 3.0 * mu_s * mu_s * mu_d - mu_d.powi(3))
        / (96.0 * mu_s.powi(3) * mu_d * mu_d)
}

/// Claim 2: coefficient 1 (not 2) in front of D^{3/2} in (28).
pub(crate) fn claim_2(p: &PulledMassParams) -> Result<Claim> {
    let given_regime = cf::regime(p.phi(), p.mu_s, p.mu_d);
    let given_sticks = given_regime == cf::Regime::SlipStick;
    let (q, name) = if given_sticks {
        (*p, "the given set")
    } else {
        (
            set_b(),
            "set B (μs 0.4, μd 0.35, F 0.10 N, m 0.06 kg, k 45 N/m), as the given set is not in \
             the slip-stick regime",
        )
    };
    let (g, period, phi) = (q.g, q.period(), q.phi());
    let v_of = |c: f64| g * period * phi.powi(3) * gamma_with(c, q.mu_s, q.mu_d);
    let (v1, v2) = (v_of(1.0), v_of(2.0));
    let v_num = steady_run(&q, LawKind::Linear)?.steady.v_avg;
    let err = |v: f64| v_num.map(|n| rel_diff(v, n));
    let (e1, e2) = (err(v1), err(v2));
    let agrees = |e: Option<f64>| e.is_some_and(|e| e <= AGREE);
    let verdict = match (agrees(e1), agrees(e2)) {
        (true, false) => Verdict::Confirmed,
        (false, true) => Verdict::Refuted,
        _ => Verdict::Qualified,
    };
    let pct = |e: Option<f64>| e.map_or("n/a".to_string(), rel_text);
    let finding = format!(
        "On {name}, the exact integration of the linearized law gives v̄ = {}. Eq. (27) with \
         coefficient 1 gives {} (relative error {}); with coefficient 2 it gives {} (relative \
         error {}).",
        v_num.map_or("no periodic orbit".to_string(), mm_s),
        mm_s(v1),
        pct(e1),
        mm_s(v2),
        pct(e2),
    );
    let mut n = Numbers::default();
    n.push("v_avg, exact integration (linear law)", v_num, "m/s")
        .push("v_avg, (27) with coefficient 1", v1, "m/s")
        .push("v_avg, (27) with coefficient 2", v2, "m/s")
        .push("relative error, coefficient 1", e1, "")
        .push("relative error, coefficient 2", e2, "");
    Ok(Claim {
        id: 2,
        model: <PulledMassParams as Physics>::ID,
        title: "Eq. (28): the coefficient of D^{3/2} in Γ is 1".to_string(),
        paper_says: "v̄ = gTφ³Γ (27) with Γ = [D^{3/2} + μs³ + 3μs²μd − μd³]/(96 μs³ μd²) (28), \
                     D = μs² + 2μsμd − μd²; the damaged print also admits 2·D^{3/2}."
            .to_string(),
        verdict,
        finding,
        numbers: n.take(),
        sample: None,
        does_not_apply: None,
        outside: Vec::new(),
    }
    .outside(
        <PulledMassParams as Physics>::ID,
        (!given_sticks).then(|| {
            format!(
                "(27) and (28) describe one slip and one stick within each period; the given set \
                 has {} (linearized law)",
                given_regime.words()
            )
        }),
    ))
}

/// The first late-stick set of the pulled-mass sample, to integrate.
struct PulledExample {
    params: PulledMassParams,
}

/// Claim 1 on the sample: sets in the "non-stick" area of Fig. 9 (φ > 1/Θ, no immediate slip)
/// that still stick, in the next period (φ ≤ φ_c).
fn pulled_late_stick(sample: &Sample) -> (SampleResult, Option<PulledExample>) {
    let mut rng = Draws::new(sample.seed);
    let mut counterexamples = 0;
    let mut example = None;
    for _ in 0..sample.size {
        let mu_s = rng.between(0.1, 1.0);
        let mu_d = mu_s * rng.between(0.05, 1.0);
        let lo = cf::phi_stick_max(mu_s, mu_d);
        // 1/Θ ≤ μd ≤ μs < 2μs, so the interval is never empty.
        let phi = lo + (2.0 * mu_s - lo) * (1.0 - rng.unit());
        if cf::regime(phi, mu_s, mu_d) != cf::Regime::SlipStickLate {
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
                cf::phi_continuous(mu_s, mu_d),
                cf::tau_stick_late(phi, mu_s, mu_d).unwrap_or(f64::NAN),
            );
            example = Some((text, PulledExample { params }));
        }
    }
    let (text, example) = example.unzip();
    (
        SampleResult::counted(sample, sample.size, counterexamples, text),
        example,
    )
}
