//! The exact replay of periodic orbits (src/engine/replay.rs) gives every output bit for bit
//! as full integration does, on seeded random parameter sets of both models and both laws that
//! reach every regime, including those where no period is replayed (continuous slip,
//! orbits that do not rest at a period start, transients); and the same for the cycle of the
//! autonomous belt (src/engine/autonomous.rs), whose compact replay stays bounded in memory.

use std::collections::BTreeMap;

use stickslip::engine::autonomous::SurfaceRun;
use stickslip::engine::{
    analyse, integrate_surface_with, integrate_with, Body, ForceLaw, Replay, Run, RunOptions,
    SurfaceOptions,
};
use stickslip::models::belt::body::{body as belt_body, surface_law};
use stickslip::models::belt::formula as belt_formula;
use stickslip::models::belt::BeltParams;
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::{pulled_mass, woodpecker, LawKind};

/// A small deterministic generator (SplitMix64): the same sets on every machine.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) as f64 / u64::MAX as f64
    }

    fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// A pulled-mass set: μs, μd/μs and F/(2 μs m g) drawn uniformly from the given ranges.
fn pulled_mass_set(
    rng: &mut Rng,
    mu_s: (f64, f64),
    mu_d_share: (f64, f64),
    pull: (f64, f64),
) -> PulledMassParams {
    let mu_s = rng.between(mu_s.0, mu_s.1);
    let base = PulledMassParams::default();
    PulledMassParams {
        mu_s,
        mu_d: mu_s * rng.between(mu_d_share.0, mu_d_share.1),
        force: 2.0 * mu_s * base.mass * base.g * rng.between(pull.0, pull.1),
        ..base
    }
}

/// A woodpecker set: μs in [0.2, 1], μd/μs from `mu_d_share`, z0 in [1, 12] mm, k in [5, 60] N/m.
fn woodpecker_set(rng: &mut Rng, mu_d_share: (f64, f64)) -> WoodpeckerParams {
    let mu_s = rng.between(0.2, 1.0);
    WoodpeckerParams {
        mu_s,
        mu_d: mu_s * rng.between(mu_d_share.0, mu_d_share.1),
        z0: rng.between(0.001, 0.012),
        k: rng.between(5.0, 60.0),
        ..WoodpeckerParams::default()
    }
}

/// Every output of a run, written so that two runs compare bit for bit (`{:?}` writes −0.0
/// and every digit of an f64).
fn outputs(run: &Run, samples: &[f64]) -> String {
    let states: Vec<_> = samples
        .iter()
        .map(|&t| (run.state_at(t), run.stuck_at(t)))
        .collect();
    format!(
        "{:?} {:?} {:?} {:?} {:?} {:?} {:?} {:?}",
        run.first_slip,
        run.immediate_slip,
        run.events,
        run.x_at_period_start,
        run.v_at_period_start,
        run.dissipation,
        analyse(run),
        states,
    )
}

/// Compares full integration with both kinds of replay on one law; returns the regime and
/// whether periods were replayed.
fn compare(body: &Body, law: &ForceLaw, periods: u32, what: &str) -> (&'static str, bool) {
    let opts = RunOptions {
        periods,
        record_segments: true,
        dissipation: true,
    };
    let run = |replay| integrate_with(body, law, &opts, replay).expect("integration");
    let (full, replayed, compact) = (
        run(Replay::Off),
        run(Replay::Segments),
        run(Replay::Compact),
    );
    // Uniform times, the period starts and ends and the events' times: where the lookup of a
    // segment is most delicate.
    let end = f64::from(periods) * law.period;
    let mut samples: Vec<f64> = (0..=997).map(|i| end * f64::from(i) / 997.0).collect();
    samples.extend((0..=periods).map(|n| f64::from(n) * law.period));
    samples.extend(full.events.iter().map(|e| e.t));
    assert_eq!(
        format!("{:?}", full.segments),
        format!("{:?}", replayed.segments),
        "{what}: segments"
    );
    let reference = outputs(&full, &samples);
    assert_eq!(reference, outputs(&replayed, &samples), "{what}: replay");
    assert_eq!(
        reference,
        outputs(&compact, &samples),
        "{what}: compact replay"
    );
    (analyse(&full).regime().id(), compact.compact.is_some())
}

#[test]
fn replayed_periods_are_bit_identical_to_full_integration_in_every_regime() {
    let mut rng = Rng(0x5717_c4511);
    let mut regimes: BTreeMap<(&str, bool), u32> = BTreeMap::new();
    for i in 0..320 {
        let periods = [1, 2, 3, 7, 30, 400][i % 6];
        let law = if i % 2 == 0 {
            LawKind::Harmonic
        } else {
            LawKind::Linear
        };
        if i % 4 < 2 {
            // F from below the threshold of any slip to beyond that of continuous slip.
            let p = pulled_mass_set(&mut rng, (0.05, 1.0), (0.02, 1.0), (0.3, 1.3));
            let Ok(law_data) = pulled_mass::force_law(&p, law) else {
                continue;
            };
            let what = format!("pulled mass {law:?} {p:?} over {periods}");
            *regimes
                .entry(compare(&pulled_mass::body(&p), &law_data, periods, &what))
                .or_default() += 1;
        } else {
            let p = woodpecker_set(&mut rng, (0.1, 1.0));
            let (Ok(law_data), Ok(())) = (woodpecker::force_law(&p, law), p.validate()) else {
                continue;
            };
            let what = format!("woodpecker {law:?} {p:?} over {periods}");
            *regimes
                .entry(compare(&woodpecker::body(&p), &law_data, periods, &what))
                .or_default() += 1;
        }
    }
    // The sets reach the regimes a replay treats differently: orbits replayed from the second
    // period, and ones integrated throughout (continuous slip, whose v grows every period; runs
    // too short to repeat; transients). Multi-period orbits are too rare to be drawn (none in
    // 4,000 sets); their consecutive period starts differ, as in the last two.
    eprintln!("(regime, replayed): sets {regimes:?}");
    for regime in [
        ("no_slip", true),
        ("single_slip_stick", true),
        ("double_slip_stick", true),
        ("double_slip_no_halt", true),
        ("continuous_slip", false),
        ("no_slip", false),
        ("not_periodic", false),
    ] {
        assert!(
            regimes.contains_key(&regime),
            "{regime:?} not reached: {regimes:?}"
        );
    }
}

#[test]
fn a_replay_of_1e5_periods_is_bit_identical_and_stores_a_bounded_amount() {
    // x at the start of replayed periods is kept as exact steps of whole spacings within each
    // binade of |x| (src/engine/series.rs): runs long enough to cross many binades, on sets of
    // both models and both laws, compared value by value with full integration.
    let mut rng = Rng(0x1e5_5eed);
    let periods = 100_000;
    let opts = RunOptions {
        periods,
        record_segments: false,
        dissipation: true,
    };
    let mut replayed_runs = 0;
    for i in 0..10 {
        let law = [LawKind::Harmonic, LawKind::Linear][i % 2];
        let (body, law_data) = if i < 5 {
            // Slip-stick: F well below the threshold of continuous slip.
            let p = pulled_mass_set(&mut rng, (0.2, 1.0), (0.5, 1.0), (0.1, 0.3));
            (pulled_mass::body(&p), pulled_mass::force_law(&p, law))
        } else {
            let p = woodpecker_set(&mut rng, (0.3, 1.0));
            let law_data = p.validate().and_then(|()| woodpecker::force_law(&p, law));
            (woodpecker::body(&p), law_data)
        };
        // Sets outside the models' domain (z0 > d0) are drawn again, as in the test above.
        let Ok(law_data) = law_data else {
            continue;
        };
        let run = |replay| integrate_with(&body, &law_data, &opts, replay).expect("integration");
        let (full, compact) = (run(Replay::Off), run(Replay::Compact));
        let bits = |run: &Run| {
            [
                &run.x_at_period_start,
                &run.v_at_period_start,
                &run.dissipation,
            ]
            .map(|series| series.iter().map(f64::to_bits).collect::<Vec<_>>())
        };
        assert_eq!(bits(&full), bits(&compact), "set {i}: {law:?}");
        assert_eq!(
            format!("{:?} {:?}", full.events, analyse(&full)),
            format!("{:?} {:?}", compact.events, analyse(&compact)),
            "set {i}"
        );
        // A periodic orbit that moves on is replayed: x crosses binades, and little is stored.
        let regime = analyse(&full).regime().id();
        let stored = compact.x_at_period_start.stored();
        eprintln!("set {i} {law:?}: {regime}, {stored} values stored");
        if regime.ends_with("slip_stick") || regime == "no_slip" {
            replayed_runs += 1;
            assert!(
                stored < 2_000,
                "set {i}: {stored} of {periods} values stored"
            );
        }
    }
    assert!(replayed_runs >= 5, "only {replayed_runs} periodic runs");
}

/// (x, v, a) of a belt run at `samples`, written bit for bit.
fn belt_states(run: &SurfaceRun, samples: &[f64]) -> String {
    let states: Vec<_> = samples.iter().map(|&t| run.state_at(t)).collect();
    format!("{states:?}")
}

#[test]
fn replayed_belt_cycles_are_bit_identical_to_full_integration() {
    let mut rng = Rng(0xbe17_c7c1e);
    let log = |rng: &mut Rng, lo: f64, hi: f64| (lo.ln() + (hi.ln() - lo.ln()) * rng.unit()).exp();
    let (mut transients, mut touches) = (0, 0);
    for i in 0..400 {
        let mu_s = rng.between(0.0, 2.0);
        let p = BeltParams {
            mass: log(&mut rng, 0.01, 10.0),
            k: log(&mut rng, 1.0, 1e4),
            v_b: log(&mut rng, 1e-4, 10.0),
            mu_s,
            mu_d: if i % 8 == 0 { mu_s } else { mu_s * rng.unit() },
            g: rng.between(1.0, 25.0),
        };
        // Starts beyond the threshold (a transient of immediate slips) as well as at rest.
        let x_s = belt_formula::evaluate(&p).x_s;
        let x0 = if i % 3 == 0 {
            x_s * rng.between(-6.0, 6.0)
        } else {
            0.0
        };
        let slips = [1, 2, 3, 7, 40][i % 5];
        let opts = SurfaceOptions {
            x0,
            slips,
            record_segments: true,
        };
        let law = surface_law(&p).expect("law");
        let run = |mode| integrate_surface_with(&belt_body(&p), &law, &opts, mode).expect("run");
        let (full, replayed, compact) = (
            run(Replay::Off),
            run(Replay::Segments),
            run(Replay::Compact),
        );
        let what = format!("{p:?} from x0 = {x0} over {slips}");
        assert_eq!(
            format!("{full:?}"),
            format!("{replayed:?}"),
            "{what}: replay"
        );
        // From rest the second onset repeats the first; a transient may outlast a short run.
        match &full.cycle {
            Some(cycle) => {
                transients += u32::from(cycle.first > 0);
                touches += u32::from(p.mu_d == p.mu_s);
            }
            None => assert!(x0 != 0.0 || slips < 2, "{what}: no cycle"),
        }
        // The compact run keeps the events up to the replay and rebuilds the segments.
        assert_eq!(full.cycle, compact.cycle, "{what}: compact cycle");
        assert_eq!(full.end, compact.end, "{what}: compact end");
        assert!(
            full.events.starts_with(&compact.events),
            "{what}: compact events"
        );
        let mut samples: Vec<f64> = (0..=331).map(|j| full.end * f64::from(j) / 331.0).collect();
        samples.extend(full.events.iter().map(|e| e.t));
        assert_eq!(
            belt_states(&full, &samples),
            belt_states(&compact, &samples),
            "{what}: compact states"
        );
    }
    eprintln!("belt sets with a transient: {transients}, touching: {touches}");
    assert!(transients >= 10 && touches >= 10, "{transients} {touches}");
}

#[test]
fn a_compact_belt_run_of_1e5_cycles_stores_a_bounded_amount() {
    let p = BeltParams::default();
    let opts = SurfaceOptions {
        x0: 0.0,
        slips: 100_000,
        record_segments: true,
    };
    let law = surface_law(&p).expect("law");
    let run = |mode| integrate_surface_with(&belt_body(&p), &law, &opts, mode).expect("run");
    let (full, compact) = (run(Replay::Segments), run(Replay::Compact));
    assert_eq!(full.events.len(), 3 * 100_000 + 1);
    // The first cycle is recorded, the second onset repeats it: nothing grows with the cycles.
    assert!(compact.events.len() <= 4, "{}", compact.events.len());
    assert!(compact.ledger.len() <= 4 && compact.segments.len() <= 4);
    let cycle = compact.cycle.as_ref().expect("a cycle");
    assert!(cycle.events.len() <= 4 && cycle.segments.len() <= 4);
    // The last onset at t_1 + 10⁵ T, and the late motion rebuilt bit for bit.
    assert_eq!(compact.end, full.events.last().expect("events").t);
    assert_eq!(compact.end, cycle.start + 1e5 * cycle.period);
    let late: Vec<f64> = full.events[full.events.len() - 40..]
        .iter()
        .map(|e| e.t)
        .chain((0..100).map(|j| compact.end * (1.0 - f64::from(j) * 1e-6)))
        .collect();
    assert_eq!(belt_states(&full, &late), belt_states(&compact, &late));
}
