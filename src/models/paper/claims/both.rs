//! Claims 3 and 7, about both models (guide §11): how well the linearized (triangle-wave)
//! law stands in for the harmonic one, and what the paper's powers measure.
//!
//! ```text
//! claim 3: v̄ and regime, harmonic vs linear (pulled mass; woodpecker with each counterpart)
//! claim 7: P_W = W_S v̄ ∝ W_S³ (m_S doubled ⇒ ×8);  P_fric = W_S v̄ + ⟨F_e v⟩;  pulled: P = F v̄
//! ```

use crate::claims::{
    mm_s, or_none, rel_diff, rel_text, steady_run, Claim, Integrated, Numbers, Verdict, BOTH_MODELS,
};
use crate::error::Result;
use crate::format::people;
use crate::models::pulled_mass::claims::PeriodicSet;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::formula::{self as cf, Counterpart};
use crate::models::woodpecker::results::linear_inputs;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind, Physics};

const PULLED_ID: &str = <PulledMassParams as Physics>::ID;
const WOOD_ID: &str = <WoodpeckerParams as Physics>::ID;

/// Mean speeds within this relative difference count as "close" for claim 3.
const CLOSE: f64 = 0.10;
/// Agreement of two exact results (guide §12).
const AGREE: f64 = 1e-9;

/// A regime and a mean speed in words.
fn motion(r: &Integrated) -> String {
    let v = r.steady.v_avg.map_or("no periodic v̄".to_string(), mm_s);
    format!("{} ({v})", r.steady.regime().words())
}

/// Claim 3: the linearization does not affect "too heavily" the numerical results.
pub(crate) fn claim_3(pulled: &PeriodicSet, w: &WoodpeckerParams) -> Result<Claim> {
    let mut n = Numbers::default();
    let (vh, vl) = (pulled.harmonic.steady.v_avg, pulled.linear.steady.v_avg);
    let pulled_same = pulled.harmonic.steady.regime() == pulled.linear.steady.regime();
    let pulled_diff = vh.zip(vl).map(|(h, l)| rel_diff(h, l));
    n.push("pulled mass v_avg, harmonic", vh, "m/s")
        .push("pulled mass v_avg, linear", vl, "m/s")
        .push(
            "pulled mass v_avg ratio harmonic/linear",
            vh.zip(vl).map(|(h, l)| h / l),
            "",
        );
    let harmonic = steady_run(w, LawKind::Harmonic)?;
    let wh = harmonic.steady.v_avg;
    n.push("woodpecker v_avg, harmonic", wh, "m/s");
    let (mut regimes_ok, mut any_ok, mut all_close) = (pulled_same, false, true);
    let (mut parts, mut wrong, mut off) = (Vec::new(), Vec::new(), Vec::new());
    for c in [
        Counterpart::Extremes,
        Counterpart::Zeros,
        Counterpart::Tangent,
    ] {
        let q = WoodpeckerParams {
            counterpart: c,
            ..*w
        };
        let name = c.id();
        if woodpecker::linear_amplitudes(&q).is_none() {
            parts.push(format!("{name}: undefined for |z0| > d0"));
            continue;
        }
        let lin = steady_run(&q, LawKind::Linear)?;
        let same = lin.steady.regime() == harmonic.steady.regime();
        let diff = (wh.filter(|&h| h > 0.0))
            .zip(lin.steady.v_avg)
            .map(|(h, l)| (l - h) / h);
        (regimes_ok, any_ok) = (regimes_ok && same, any_ok || same);
        all_close &= diff.is_some_and(|d| d.abs() <= CLOSE);
        if !same {
            wrong.push(name);
        }
        off.extend(diff.map(f64::abs));
        n.push(
            &format!("woodpecker v_avg, linear ({name})"),
            lin.steady.v_avg,
            "m/s",
        )
        .push(
            &format!("woodpecker (linear - harmonic)/harmonic v_avg ({name})"),
            diff,
            "",
        );
        let pct = diff.map_or(String::new(), |d| format!(" ({:+.0} %)", 100.0 * d));
        parts.push(format!("{name}: {}{pct}", motion(&lin)));
    }
    all_close &= pulled_diff.is_some_and(|d| d <= CLOSE);
    let verdict = match (regimes_ok && all_close, pulled_same || any_ok) {
        (true, _) => Verdict::Confirmed,
        (false, true) => Verdict::Qualified,
        (false, false) => Verdict::Refuted,
    };
    let kind = match (pulled_same, wrong.as_slice()) {
        (true, []) => "Every linearization defined here keeps the kind of motion".to_string(),
        (true, w) => format!(
            "The {} counterpart changes the kind of motion",
            w.join(" and ")
        ),
        (false, _) => "The pulled mass changes its kind of motion".to_string(),
    };
    let (lo, hi) = off.iter().fold((f64::INFINITY, 0.0_f64), |(lo, hi), &d| {
        (lo.min(d), hi.max(d))
    });
    let wood_off = match off.is_empty() {
        true => String::new(),
        false => format!(
            " off by {:.0}–{:.0} % for the woodpecker",
            100.0 * lo,
            100.0 * hi
        ),
    };
    let pulled_off = match vh.zip(vl).filter(|&(_, l)| l > 0.0) {
        Some((h, l)) => format!(" off by a factor {:.2} for the pulled mass", h / l),
        None => String::new(),
    };
    let joint = if wood_off.is_empty() || pulled_off.is_empty() {
        ""
    } else {
        " and"
    };
    let speeds = match (wood_off.is_empty(), pulled_off.is_empty()) {
        (true, true) => ".".to_string(),
        _ => format!("; the linearized mean speeds are{wood_off}{joint}{pulled_off}."),
    };
    let finding = format!(
        "Pulled mass, on {}: harmonic {}, linearized {}. Woodpecker (given set): harmonic {}; \
         linearized with the counterpart {}. {kind}{speeds}",
        pulled.name,
        motion(&pulled.harmonic),
        motion(&pulled.linear),
        motion(&harmonic),
        parts.join("; "),
    );
    Ok(Claim {
        id: 3,
        model: BOTH_MODELS,
        title: "The linearized law reproduces the harmonic one only qualitatively".to_string(),
        paper_says: "The linearization is a safe way to obtain analytical results without \
                     affecting too heavily the numerical (exact) results (Fig. 12)."
            .to_string(),
        verdict,
        finding,
        numbers: n.take(),
        sample: None,
        does_not_apply: None,
        outside: Vec::new(),
    }
    .outside(PULLED_ID, pulled.outside.clone()))
}

/// The sleeve mass pair (m, 2m) or (m/2, m) around `w` whose sets are both in the paper's
/// standard regime, if any.
fn doubled_pair(w: &WoodpeckerParams) -> Option<(WoodpeckerParams, WoodpeckerParams)> {
    let with = |m: f64| WoodpeckerParams { m_sleeve: m, ..*w };
    let standard = |p: &WoodpeckerParams| cf::evaluate(&linear_inputs(p)).paper_regime_valid;
    let m = w.m_sleeve;
    [(with(m), with(2.0 * m)), (with(0.5 * m), with(m))]
        .into_iter()
        .find(|(a, b)| standard(a) && standard(b))
}

/// P_W = W_S v̄ of the closed form (71) and of the linear integration.
fn weight_powers(p: &WoodpeckerParams) -> Result<(Option<f64>, Option<f64>)> {
    let closed = cf::evaluate(&linear_inputs(p)).power_weight;
    let run = steady_run(p, LawKind::Linear)?;
    Ok((closed, run.steady.v_avg.map(|v| p.sleeve_weight() * v)))
}

/// P_fric/(W_S v̄) of an integration, if it reached a periodic orbit that advances.
fn friction_ratio(r: &Integrated, w_s: f64) -> Option<f64> {
    let v = r.steady.v_avg.filter(|&v| v > 0.0)?;
    r.steady.friction_power.map(|p| p / (w_s * v))
}

/// Claim 7: the powers. W_S v̄ ∝ W_S³ and is not the friction dissipation; P = F v̄ is.
pub(crate) fn claim_7(pulled: &PeriodicSet, w: &WoodpeckerParams) -> Result<Claim> {
    let mut n = Numbers::default();
    let pair = doubled_pair(w).map(|p| (p, "")).or_else(|| {
        doubled_pair(&WoodpeckerParams::default())
            .map(|p| (p, " on the Fig. 15 set (the given set has no such pair)"))
    });
    let no_pair = doubled_pair(w).is_none().then(|| {
        "the claim compares W_S v̄ of two sleeve masses m_S and 2 m_S in the paper's standard \
         regime; no such pair exists around the given m_S"
            .to_string()
    });
    let (mut cube_ok, mut cube_text) = (false, "no m_S pair in the standard regime".to_string());
    if let Some(((a, b), which)) = pair {
        let ((ca, na), (cb, nb)) = (weight_powers(&a)?, weight_powers(&b)?);
        // A ratio exists only where the first power does not vanish.
        let ratio =
            |x: Option<f64>, y: Option<f64>| x.zip(y).map(|(x, y)| y / x).filter(|r| r.is_finite());
        let (closed, numeric) = (ratio(ca, cb), ratio(na, nb));
        cube_ok = numeric.is_some_and(|r| (r / 8.0 - 1.0).abs() <= AGREE);
        n.push("P_W ratio for doubled m_S, closed form", closed, "")
            .push("P_W ratio for doubled m_S, integration", numeric, "");
        cube_text = format!(
            "doubling m_S from {:.1} to {:.1} g{which}, both sets in the paper's standard regime, \
             multiplies W_S v̄ by {} in (71) and by {} in the exact linear integration, i.e. 2³",
            1e3 * a.m_sleeve,
            1e3 * b.m_sleeve,
            or_none(closed, |r| people(Some(r), 10)),
            or_none(numeric, |r| people(Some(r), 10)),
        );
    }
    let w_s = w.sleeve_weight();
    let lin = woodpecker::linear_amplitudes(w)
        .map(|_| steady_run(w, LawKind::Linear))
        .transpose()?;
    let harm = steady_run(w, LawKind::Harmonic)?;
    let r_lin = lin.as_ref().and_then(|r| friction_ratio(r, w_s));
    let r_harm = friction_ratio(&harm, w_s);
    n.push("P_fric / (W_S v_avg), linear (given set)", r_lin, "")
        .push("P_fric / (W_S v_avg), harmonic (given set)", r_harm, "");
    let force = pulled.p.force;
    let balance = |r: &Integrated| {
        let v = r.steady.v_avg?;
        r.steady.friction_power.map(|p| rel_diff(force * v, p))
    };
    let (b_lin, b_harm) = (balance(&pulled.linear), balance(&pulled.harmonic));
    n.push("pulled mass |F v_avg - P_fric| / max, linear", b_lin, "")
        .push("pulled mass |F v_avg - P_fric| / max, harmonic", b_harm, "");
    let pulled_ok = [b_lin, b_harm]
        .iter()
        .all(|b| b.is_some_and(|b| b <= AGREE));
    let fmt = |r: Option<f64>| or_none(r, |r| format!("{r:.3} × W_S v̄"));
    let dissipation = match (r_lin, r_harm) {
        (None, None) => "The given set does not advance periodically, so its friction \
                         dissipation cannot be compared with W_S v̄."
            .to_string(),
        _ => format!(
            "For the given set the friction dissipation is {} (linear law) and {} (harmonic \
             law): the spring also does work on the sleeve.",
            fmt(r_lin),
            fmt(r_harm)
        ),
    };
    let finding = format!(
        "Woodpecker: {cube_text}, not 2². {dissipation} Pulled mass, on {}: F v̄ equals the \
         dissipated power within {} (linear) and {} (harmonic).",
        pulled.name,
        or_none(b_lin, rel_text),
        or_none(b_harm, rel_text),
    );
    Ok(Claim {
        id: 7,
        model: BOTH_MODELS,
        title: "W_S v̄ grows as W_S³ and is not the friction dissipation; F v̄ is".to_string(),
        paper_says: "The sleeve's weight dissipates energy at a constant rate depending on the \
                     second (and, later, the third) power of W_S; for the pulled mass P = F v̄ \
                     ∝ F⁴ (29)."
            .to_string(),
        verdict: if cube_ok && pulled_ok {
            Verdict::Qualified
        } else {
            Verdict::Refuted
        },
        finding,
        numbers: n.take(),
        sample: None,
        does_not_apply: None,
        outside: Vec::new(),
    }
    .outside(PULLED_ID, pulled.outside.clone())
    .outside(WOOD_ID, no_pair))
}
