//! The claims of guide §11 on the paper's default sets (Fig. 6 pulled mass, Fig. 15
//! woodpecker): the expected verdicts and numbers, determinism of the seeded sample, and the
//! harmonic regimes of Figs. 15 and 16 around the z0 threshold.

use stickslip::claims::{Claim, Claims, Sample, Verdict};
use stickslip::engine::IntegrationRegime;
use stickslip::models::paper::claims::{evaluate, halt_threshold_z0};
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::results as woodpecker;
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::Model;

/// The z0 (m) at which the Fig. 15 set loses its intermediate halt (guide §11, claim 8).
const FIG16_THRESHOLD: f64 = 7.0746e-3;

fn default_claims() -> Claims {
    evaluate(
        &PulledMassParams::default(),
        &WoodpeckerParams::default(),
        &Sample::default(),
    )
    .expect("the default sets are valid")
}

fn claim(claims: &Claims, id: u8) -> &Claim {
    claims
        .claims
        .iter()
        .find(|c| c.id == id)
        .unwrap_or_else(|| panic!("claim {id} missing"))
}

fn number(c: &Claim, label: &str) -> f64 {
    c.numbers
        .iter()
        .find(|n| n.label == label)
        .unwrap_or_else(|| panic!("claim {}: no number {label:?} in {:?}", c.id, c.numbers))
        .value
}

fn harmonic_regime(p: &WoodpeckerParams) -> IntegrationRegime {
    woodpecker::evaluate(p, 8)
        .expect("valid set")
        .harmonic
        .regime
}

#[test]
fn all_eight_claims_come_in_order_with_finite_numbers() {
    let c = default_claims();
    let ids: Vec<u8> = c.claims.iter().map(|c| c.id).collect();
    assert_eq!(ids, (1..=8).collect::<Vec<_>>());
    for claim in &c.claims {
        assert!(!claim.finding.is_empty() && !claim.paper_says.is_empty());
        assert!(claim.numbers.iter().all(|n| n.value.is_finite()));
    }
}

#[test]
fn claim_1_late_stick_below_the_22_minimum() {
    let c = default_claims();
    let c1 = claim(&c, 1);
    assert_eq!(c1.verdict, Verdict::Refuted);
    let mu = number(c1, "mu = mu_s = mu_d tried");
    let phi = number(c1, "phi = F/W (given set)");
    assert!(phi < mu && mu < number(c1, "mu_MIN of (22)"));
    // The stick comes in the next period, where the closed form of guide §7.5 puts it.
    let tau = number(c1, "stick time / T, integration (mu_s = mu_d = mu)");
    let closed = number(c1, "tau_ST,late closed form (mu_s = mu_d = mu)");
    assert!(tau > 1.0, "{tau}");
    assert!((tau - closed).abs() <= 1e-9 * closed, "{tau} vs {closed}");
    let s = c1.sample.as_ref().expect("claim 1 has a sample");
    assert_eq!((s.size, s.seed), (2000, 2017));
    assert!(s.counterexamples > 0 && s.example.is_some());
}

#[test]
fn claim_2_coefficient_one_agrees_and_two_does_not() {
    let c = default_claims();
    let c2 = claim(&c, 2);
    assert!(number(c2, "relative error, coefficient 1") <= 1e-9);
    assert!(number(c2, "relative error, coefficient 2") > 1e-2);
    assert_eq!(c2.verdict, Verdict::Confirmed);
    // Fig. 6 is continuous slip, so set B of guide §13 is used: v̄ = 5.396971 mm/s.
    let v = number(c2, "v_avg, exact integration (linear law)");
    assert!((v - 5.396_970_576e-3).abs() < 1e-11, "{v}");
}

#[test]
fn claim_3_linearization_is_only_qualitative() {
    let c = default_claims();
    let c3 = claim(&c, 3);
    assert_eq!(c3.verdict, Verdict::Qualified);
    let ratio = number(c3, "pulled mass v_avg ratio harmonic/linear");
    assert!((ratio - 11.783_111 / 5.396_971).abs() < 1e-5, "{ratio}");
    let zeros = number(c3, "woodpecker (linear - harmonic)/harmonic v_avg (zeros)");
    assert!((0.3..0.5).contains(&zeros), "{zeros}");
}

#[test]
fn claim_4_is_refuted_in_a_large_share_of_the_sample() {
    let c = default_claims();
    let c4 = claim(&c, 4);
    assert_eq!(c4.verdict, Verdict::Refuted);
    assert!(number(c4, "mu_d,MIN^(I) (given set)") < number(c4, "mu_d,MIN^(II) (given set)"));
    let s = c4.sample.as_ref().expect("claim 4 has a sample");
    assert_eq!(s.size, 2000);
    assert!((0.4..=0.75).contains(&s.share), "share {}", s.share);
    assert!(s.example.is_some());
}

#[test]
fn claim_5_halts_below_mu_d_min() {
    let c = default_claims();
    let c5 = claim(&c, 5);
    assert_eq!(c5.verdict, Verdict::Qualified);
    let mu = number(c5, "mu_d tried");
    assert!(number(c5, "mu_d,HALT^(I)") < mu);
    assert!(mu < number(c5, "mu_d,MIN^(I)"));
    let stick = number(c5, "first stick, integration");
    assert!(stick > number(c5, "T/2") && stick < number(c5, "phase-II slip time t_SL^(II)"));
    let closed = number(c5, "halt time, lobe engine");
    assert!((stick - closed).abs() <= 1e-9 * closed);
}

#[test]
fn claim_6_mean_speed_does_not_depend_on_z0() {
    let c = default_claims();
    let c6 = claim(&c, 6);
    assert!(number(c6, "z0 values tried") >= 3.0);
    assert!(number(c6, "largest eta") > number(c6, "smallest eta") * 1.1);
    assert!(number(c6, "relative spread of Gamma") < 1e-12);
    assert!(number(c6, "relative spread of integrated v_avg") < 1e-9);
    assert_eq!(c6.verdict, Verdict::Qualified);
}

#[test]
fn claim_7_weight_power_is_cubic_and_not_the_dissipation() {
    let c = default_claims();
    let c7 = claim(&c, 7);
    assert_eq!(c7.verdict, Verdict::Qualified);
    let ratio = number(c7, "P_W ratio for doubled m_S, integration");
    assert!((ratio - 8.0).abs() < 1e-9, "{ratio}");
    for law in ["linear", "harmonic"] {
        let r = number(c7, &format!("P_fric / (W_S v_avg), {law} (given set)"));
        assert!((2.0..3.0).contains(&r), "{law}: {r}");
        let b = number(c7, &format!("pulled mass |F v_avg - P_fric| / max, {law}"));
        assert!(b < 1e-12, "{law}: {b}");
    }
}

#[test]
fn claim_8_lever_threshold_and_fig26() {
    let c = default_claims();
    let c8 = claim(&c, 8);
    assert_eq!(c8.verdict, Verdict::Qualified);
    assert_eq!(number(c8, "sticks in 8 periods, lambda = 1"), 0.0);
    let z = number(c8, "z0 where the intermediate halt disappears");
    assert!((z - FIG16_THRESHOLD).abs() < 1e-6, "threshold {z} m");
    let v = number(c8, "Fig. 26 v_avg harmonic");
    assert!((v - 0.023_723_36).abs() < 1e-8, "{v}");
}

#[test]
fn threshold_is_found_to_a_millionth_of_a_millimetre() {
    let p = WoodpeckerParams::default();
    let z = halt_threshold_z0(&p, 7.0e-3, 7.1e-3, 1e-9).expect("7.0 and 7.1 mm bracket it");
    assert!((z - FIG16_THRESHOLD).abs() < 1e-6, "threshold {z} m");
    let at = |z0: f64| harmonic_regime(&WoodpeckerParams { z0, ..p });
    assert_eq!(at(z - 1e-9), IntegrationRegime::DoubleSlipStick);
    assert_ne!(at(z + 1e-9), IntegrationRegime::DoubleSlipStick);
    // Ends that do not bracket the change, or a bad tolerance, give no threshold.
    assert_eq!(halt_threshold_z0(&p, 7.1e-3, 7.2e-3, 1e-9), None);
    assert_eq!(halt_threshold_z0(&p, 7.0e-3, 7.1e-3, 0.0), None);
}

#[test]
fn paper_sets_have_the_papers_harmonic_regimes() {
    let fig15 = WoodpeckerParams::default();
    assert_eq!(harmonic_regime(&fig15), IntegrationRegime::DoubleSlipStick);
    // Fig. 16: z0 just above the threshold, one stick per period and no intermediate halt.
    let fig16 = WoodpeckerParams {
        z0: FIG16_THRESHOLD + 1e-5,
        ..fig15
    };
    let e = woodpecker::evaluate(&fig16, 8).expect("valid set");
    assert_eq!(e.harmonic.regime, IntegrationRegime::DoubleSlipNoHalt);
    assert_eq!(e.harmonic.sticks_per_period, 1);
    // The printed N = |F_e| (λ = 1): the sleeve never sticks.
    let printed = WoodpeckerParams {
        lever: Some(1.0),
        ..fig15
    };
    assert_eq!(harmonic_regime(&printed), IntegrationRegime::ContinuousSlip);
}

#[test]
fn same_seed_same_json_other_seed_other_sample() {
    let (p, w) = (PulledMassParams::default(), WoodpeckerParams::default());
    let json = |seed| {
        let sample = Sample { seed, size: 500 };
        serde_json::to_string(&evaluate(&p, &w, &sample).expect("valid")).expect("serializes")
    };
    assert_eq!(json(7), json(7));
    assert_ne!(json(7), json(8));
    let text = json(7);
    assert!(text.contains("\"verdict\":\"refuted\"") && !text.contains("NaN"));
    assert!(text.contains("\"model\":\"pulled-mass\""));
}

#[test]
fn an_empty_sample_is_refused() {
    let err = evaluate(
        &PulledMassParams::default(),
        &WoodpeckerParams::default(),
        &Sample { seed: 1, size: 0 },
    )
    .unwrap_err();
    assert!(err.to_string().contains("sample size"), "{err}");
}

/// `claims woodpecker --mu-s 0.2 --mu-d 0.1` (issue 26): the given set is outside the domain of
/// claims 5 to 8, which say so with a reason; the pulled-mass claims keep the paper's set.
#[test]
fn claims_outside_their_domain_do_not_apply_and_say_why() {
    let w = WoodpeckerParams {
        mu_s: 0.2,
        mu_d: 0.1,
        ..WoodpeckerParams::default()
    };
    let sample = Sample { seed: 1, size: 200 };
    let claims = stickslip::claims::of(&Model::Woodpecker(w), &sample).expect("valid");
    for id in [5, 6, 7, 8] {
        let c = claim(&claims, id);
        assert_eq!(c.verdict, Verdict::DoesNotApply, "claim {id}");
        let why = c.does_not_apply.as_deref().unwrap_or_default();
        assert!(why.starts_with("the claim "), "claim {id}: {why}");
    }
    assert!(claim(&claims, 5)
        .does_not_apply
        .as_deref()
        .is_some_and(|w| w.contains("u_s^(-)")));
    for id in [1, 2, 3, 4] {
        let c = claim(&claims, id);
        assert_ne!(c.verdict, Verdict::DoesNotApply, "claim {id}");
        assert_eq!(c.does_not_apply, None);
    }
    // The same sets taken as the paper's: no claim is judged outside its domain.
    let paper = evaluate(&PulledMassParams::default(), &w, &sample).expect("valid");
    assert!(paper
        .claims
        .iter()
        .all(|c| c.verdict != Verdict::DoesNotApply));
    let json = serde_json::to_string(&claims).expect("serializes");
    assert!(json.contains("\"verdict\":\"does_not_apply\",\"does_not_apply\":\"the claim "));
}

/// A pulled-mass set in continuous slip is outside the domain of (28) and of claims 3 and 7.
#[test]
fn a_continuous_slip_pull_is_outside_the_domain_of_claim_2() {
    let claims = stickslip::claims::of(
        &Model::PulledMass(PulledMassParams {
            force: 0.35,
            ..PulledMassParams::default()
        }),
        &Sample { seed: 1, size: 200 },
    )
    .expect("valid");
    let c2 = claim(&claims, 2);
    assert_eq!(c2.verdict, Verdict::DoesNotApply);
    assert!(c2
        .does_not_apply
        .as_deref()
        .is_some_and(|w| w.contains("continuous slip")));
    assert_eq!(claim(&claims, 3).verdict, Verdict::DoesNotApply);
    assert_eq!(claim(&claims, 8).verdict, Verdict::Qualified);
}
