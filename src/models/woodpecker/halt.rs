//! Claim 5 (guide §8.6, guide §11): μd ≥ μd,MIN^(I) is sufficient, not necessary, for the
//! intermediate halt. (51) asks the phase-I slip to stop before T/2; the sleeve may still stop
//! after T/2, on the falling flank of the negative F_e lobe, before the phase-II slip starts.
//!
//! ```text
//! (51)  t_ST^(I) ≤ T/2  ⇔  μd ≥ μd,MIN^(I)          (for u_d^(+) ≥ 1/η)
//! guide §8.6  stop before t_SL^(II)  ⇔  μd ≥ μd,HALT^(I) = (max(x₊, 1/η) − 1)/(2λ) ≤ μd,MIN^(I)
//! ```
//! A μd between the two is integrated exactly and its first slip is followed to its stop.

use crate::claims::{or_none, steady_run, Claim, Numbers, Verdict};
use crate::error::Result;
use crate::models::woodpecker::formula::{self as cf, WoodpeckerClosedForm};
use crate::models::woodpecker::lobe::{HaltKind, OrbitRegime, Phase, PhaseLobes};
use crate::models::woodpecker::results::{domain_note, linear_inputs};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;
use crate::models::Physics;

const PAPER_SAYS: &str = "The dynamic coefficient has to exceed μd,MIN^(I) (51) for the sleeve \
     to stop in the first half period; otherwise the motion, once started, does not end.";

/// The phase-I slip of the lobe engine for a closed form (SI): (flank, halt time).
fn phase_one_halt(w: &WoodpeckerParams, c: &WoodpeckerClosedForm) -> Option<(HaltKind, f64)> {
    let lobes = PhaseLobes {
        phase: Phase::One,
        u_s: c.u_s_minus?,
        u_a: c.u_d_minus?,
        u_b: c.u_d_plus?,
        h_a: c.eta_prime?,
        h_b: c.eta?,
        t_zero: c.t0_1?,
        time_unit: cf::time_unit(c.tau_quarter?, w.sleeve_weight(), w.k, c.zeta0?)?,
        g: w.g,
    };
    lobes.orbit_slip().map(|s| (s.halt, s.t_halt))
}

fn flank_name(h: HaltKind) -> &'static str {
    match h {
        HaltKind::B => "rising flank B",
        HaltKind::BLate => "falling flank B_late",
        HaltKind::A => "next lobe A",
        HaltKind::ALate => "next lobe A_late",
    }
}

fn ms(t: f64) -> String {
    format!("{:.3} ms", 1e3 * t)
}

/// Claim 5 on the given set, or on the Fig. 15 set when the closed forms do not apply to it.
pub(crate) fn claim_5(w: &WoodpeckerParams) -> Result<Claim> {
    let given = cf::evaluate(&linear_inputs(w));
    // The claim is about a slip from rest in phase I that may halt in the negative lobe: it
    // does not apply to a set outside the closed forms' domain, one that never slips, or one
    // that slips at once.
    let outside: Option<String> = match given.regime {
        OrbitRegime::OutsideClosedFormDomain => domain_note(w, &given)
            .map(|note| format!("the claim is about the closed forms' phase-I slip, and {note}")),
        OrbitRegime::NoSlip => Some(
            "the claim is about a slip from rest in phase I, and the given sleeve never slips"
                .to_string(),
        ),
        _ if given.immediate_slip => Some(
            "the claim is about a slip from rest in phase I, and the given sleeve slips at once \
             (it never rests)"
                .to_string(),
        ),
        _ if given.mu_d_halt_1.is_none() || given.mu_d_min_1.is_none() => Some(
            "the claim compares μd,HALT^(I) with μd,MIN^(I), and the given set has no phase-I \
             lobe in which a halt could happen"
                .to_string(),
        ),
        _ => None,
    };
    let (set, c, name) = match &outside {
        None => (*w, given, "Given set"),
        _ => {
            let fig15 = WoodpeckerParams::default();
            let c = cf::evaluate(&linear_inputs(&fig15));
            (
                fig15,
                c,
                "Fig. 15 set (shown instead of the given set, to which the claim does not \
                 apply)",
            )
        }
    };
    let (halt, min) = (c.mu_d_halt_1, c.mu_d_min_1);
    let mut n = Numbers::default();
    n.push("mu_d,HALT^(I)", halt, "")
        .push("mu_d,MIN^(I)", min, "");
    let head = format!(
        "{name}: the exact least μd for a stop before the phase-II slip is μd,HALT^(I) = {}, \
         against μd,MIN^(I) = {} from (51).",
        or_none(halt, |v| format!("{v:.4}")),
        or_none(min, |v| format!("{v:.4}")),
    );
    let interval = halt
        .zip(min)
        .map(|(h, m)| (h.max(0.0), m.min(set.mu_s)))
        .filter(|(lo, hi)| lo < hi);
    let (verdict, finding) = match interval {
        Some((lo, hi)) => halt_below_min(&set, 0.5 * (lo + hi), &head, &mut n)?,
        None => (
            Verdict::Confirmed,
            format!(
                "{head} No μd below μd,MIN^(I) stops the sleeve before the phase-II slip, so for \
                 this set (51) is also necessary."
            ),
        ),
    };
    Ok(Claim {
        id: 5,
        model: <WoodpeckerParams as Physics>::ID,
        title: "μd ≥ μd,MIN^(I) is sufficient, not necessary, for the intermediate halt"
            .to_string(),
        paper_says: PAPER_SAYS.to_string(),
        verdict,
        finding,
        numbers: n.take(),
        sample: None,
        does_not_apply: None,
        outside: Vec::new(),
    }
    .outside(<WoodpeckerParams as Physics>::ID, outside))
}

/// Integrates the linear law with μd = `mu` (below μd,MIN^(I)) and reports the first stop.
fn halt_below_min(
    set: &WoodpeckerParams,
    mu: f64,
    head: &str,
    n: &mut Numbers,
) -> Result<(Verdict, String)> {
    let q = WoodpeckerParams { mu_d: mu, ..*set };
    let c = cf::evaluate(&linear_inputs(&q));
    let closed = phase_one_halt(&q, &c);
    let first = steady_run(&q, LawKind::Linear)?.first_slip_and_stick();
    let stick = first.and_then(|(_, st)| st);
    let half = 0.5 * q.period();
    n.push("mu_d tried", mu, "")
        .push("first slip, integration", first.map(|f| f.0), "s")
        .push("first stick, integration", stick, "s")
        .push("halt time, lobe engine", closed.map(|h| h.1), "s")
        .push("T/2", half, "s")
        .push("phase-II slip time t_SL^(II)", c.t_slip_2, "s");
    let before_phase_two = stick.zip(c.t_slip_2).filter(|(st, sl2)| st < sl2);
    Ok(match (c.immediate_slip, first, before_phase_two) {
        (false, Some((sl, _)), Some((st, sl2))) => (
            Verdict::Qualified,
            format!(
                "{head} With μd = {mu:.4}, below μd,MIN^(I), the exact integration of the \
                 linearized law shows the first slip (from {}) stopping at {}, {} T/2 = {} and \
                 before the phase-II slip at {} (closed form: halt on the {} at {}). So (51) \
                 decides whether the stop comes before T/2, not whether it comes.",
                ms(sl),
                ms(st),
                if st > half { "after" } else { "at or before" },
                ms(half),
                ms(sl2),
                closed.map_or("none", |h| flank_name(h.0)),
                or_none(closed.map(|h| h.1), ms),
            ),
        ),
        _ => (
            Verdict::Confirmed,
            format!(
                "{head} With μd = {mu:.4}, below μd,MIN^(I), the exact integration shows no stop \
                 before the phase-II slip."
            ),
        ),
    })
}
