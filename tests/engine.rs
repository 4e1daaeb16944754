//! The engine's hard cases: each a force law built as data, with the event it must produce.

use stickslip::engine::{
    analyse, integrate, Affine, Basis, Body, EventKind, ForceLaw, IntegrationRegime, Piece, Run,
    RunOptions,
};
use stickslip::models::pulled_mass::formula as cf;
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::{pulled_mass, LawKind};

fn run(body: &Body, law: &ForceLaw, periods: u32) -> Run {
    integrate(
        body,
        law,
        &RunOptions {
            periods,
            record_segments: true,
            dissipation: true,
        },
    )
    .expect("integration")
}

fn linear_piece(start: f64, end: f64, drive: (f64, f64), normal: (f64, f64)) -> Piece {
    Piece {
        start,
        end,
        basis: Basis::Linear { t_ref: start },
        drive: Affine::new(drive.0, drive.1),
        normal: Affine::new(normal.0, normal.1),
    }
}

fn transitions(run: &Run) -> Vec<(f64, EventKind)> {
    run.events
        .iter()
        .filter(|e| e.is_transition())
        .map(|e| (e.t, e.kind))
        .collect()
}

/// Exactly representable pulled-mass numbers: W = m g = 8 N, 2W = 16 N.
fn exact_pulled_mass(force: f64) -> PulledMassParams {
    PulledMassParams {
        mu_s: 0.5,
        mu_d: 0.25,
        mass: 1.0,
        k: 4.0,
        force,
        g: 8.0,
    }
}

#[test]
fn slip_at_t_zero_is_immediate_when_the_drive_exceeds_static_friction() {
    let p = exact_pulled_mass(8.5); // F > 2 μs W = 8
    for law in [LawKind::Linear, LawKind::Harmonic] {
        let r = run(
            &pulled_mass::body(&p),
            &pulled_mass::force_law(&p, law).unwrap(),
            2,
        );
        assert!(r.immediate_slip, "{law:?}");
        assert_eq!(r.first_slip, Some(0.0), "{law:?}");
        assert_eq!(analyse(&r).regime(), IntegrationRegime::ContinuousSlip);
    }
}

#[test]
fn slip_starts_at_t_zero_but_not_immediately_when_the_drive_equals_static_friction() {
    // F = μs·2W exactly: stuck while |D| ≤ μs N_f, so the slip starts at the crossing t = 0,
    // and the start is not "immediate" (strict inequality).
    let p = exact_pulled_mass(8.0);
    for law in [LawKind::Linear, LawKind::Harmonic] {
        let r = run(
            &pulled_mass::body(&p),
            &pulled_mass::force_law(&p, law).unwrap(),
            2,
        );
        assert!(!r.immediate_slip, "{law:?}");
        assert_eq!(r.first_slip, Some(0.0), "{law:?}");
    }
}

#[test]
fn slip_restarts_exactly_where_the_drive_reaches_static_friction() {
    // Set B: after each stick the next slip starts where F = μs N, at τ_SL of (13).
    let p = PulledMassParams {
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    };
    let law = pulled_mass::force_law(&p, LawKind::Linear).unwrap();
    let r = run(&pulled_mass::body(&p), &law, 6);
    let tau_sl = cf::tau_slip(p.phi(), p.mu_s);
    let slips: Vec<f64> = transitions(&r)
        .into_iter()
        .filter(|(_, k)| matches!(k, EventKind::Slip { .. }))
        .map(|(t, _)| t / r.period)
        .collect();
    assert!(slips.len() >= 3);
    for (n, tau) in slips.iter().enumerate() {
        let expected = tau_sl + (*tau - tau_sl).round();
        assert!(
            (tau - expected).abs() < 1e-14,
            "slip {n} at {tau}, expected {expected}"
        );
        // At the onset the drive equals the static capacity.
        let t = tau * r.period;
        let margin = law.drive(t) - p.mu_s * law.normal(t);
        assert!(margin.abs() < 1e-14 * p.force, "margin {margin}");
    }
}

#[test]
fn slip_onset_exactly_at_a_triangle_vertex() {
    // μs = ½, D = 1: g = D − μs N_f = t − 1 on [0, 1) (N_f = 4 − 2t), still rising after the
    // vertex (N_f = 2 − 2(t − 1) on [1, 2)). The slip starts at the vertex t = 1, once.
    let body = Body {
        mass: 1.0,
        mu_s: 0.5,
        mu_d: 0.25,
    };
    let law = ForceLaw::new(
        4.0,
        vec![
            linear_piece(0.0, 1.0, (1.0, 0.0), (4.0, -2.0)),
            linear_piece(1.0, 2.0, (1.0, 0.0), (2.0, -2.0)),
            linear_piece(2.0, 4.0, (1.0, 0.0), (0.0, 2.0)),
        ],
    )
    .unwrap();
    let r = run(&body, &law, 1);
    assert_eq!(r.first_slip, Some(1.0));
    let ev = transitions(&r);
    assert_eq!(ev[0], (1.0, EventKind::Slip { dir: 1 }));
    // A vertex where g only touches zero (falls again after it) is no slip.
    let touching = ForceLaw::new(
        2.0,
        vec![
            linear_piece(0.0, 1.0, (1.0, 0.0), (4.0, -2.0)),
            linear_piece(1.0, 2.0, (1.0, 0.0), (2.0, 2.0)),
        ],
    )
    .unwrap();
    let r = run(&body, &touching, 3);
    assert_eq!(r.first_slip, None);
    assert_eq!(analyse(&r).regime(), IntegrationRegime::NoSlip);
}

#[test]
fn tangential_stick_where_v_touches_zero_with_zero_acceleration() {
    // At φ = φ_c the late-stick speed minimum at τ = 1 + τ'_M is exactly zero (guide §7.5): the mass
    // sticks there, with a = 0, instead of sliding on.
    let (mu_s, mu_d) = (0.4, 0.35);
    let base = PulledMassParams {
        mu_s,
        mu_d,
        ..PulledMassParams::default()
    };
    let phi = cf::phi_continuous(mu_s, mu_d);
    let p = PulledMassParams {
        force: phi * base.weight(),
        ..base
    };
    let law = pulled_mass::force_law(&p, LawKind::Linear).unwrap();
    let body = pulled_mass::body(&p);
    let r = run(&body, &law, 8);
    let stick = transitions(&r)
        .into_iter()
        .find(|(_, k)| matches!(k, EventKind::Stick { .. }))
        .expect("a stick at the tangency")
        .0;
    let expected = 1.0 + cf::tau_accel_zero_falling(p.phi(), mu_d);
    assert!(
        (stick / r.period - expected).abs() < 1e-6,
        "{} vs {expected}",
        stick / r.period
    );
    let a = (law.drive(stick) - mu_d * law.normal(stick)) / body.mass;
    assert!(a.abs() < 1e-6 * p.g, "a = {a}");
    assert_eq!(analyse(&r).regime(), IntegrationRegime::SingleSlipStick);
    // Slightly above φ_c the mass never sticks again.
    let above = PulledMassParams {
        force: phi * (1.0 + 1e-6) * base.weight(),
        ..base
    };
    let law = pulled_mass::force_law(&above, LawKind::Linear).unwrap();
    let r = run(&pulled_mass::body(&above), &law, 8);
    assert_eq!(analyse(&r).regime(), IntegrationRegime::ContinuousSlip);
}

#[test]
fn reversal_where_v_returns_to_zero_with_the_drive_beyond_static_friction() {
    // D = 2 − 4t, N_f = 1, M = 1, μs = ½, μd = ¼: immediate slip forward, a = 1.75 − 4t,
    // v = 1.75 t − 2t² returns to 0 at t = 0.875 where D = −1.5, |D| > μs N_f: reversal.
    let body = Body {
        mass: 1.0,
        mu_s: 0.5,
        mu_d: 0.25,
    };
    let law = ForceLaw::new(
        2.0,
        vec![
            linear_piece(0.0, 1.0, (2.0, -4.0), (1.0, 0.0)),
            linear_piece(1.0, 2.0, (-2.0, 4.0), (1.0, 0.0)),
        ],
    )
    .unwrap();
    let r = run(&body, &law, 1);
    let ev = transitions(&r);
    assert_eq!(ev[0], (0.0, EventKind::Slip { dir: 1 }));
    assert!((ev[1].0 - 0.875).abs() < 1e-15, "{:?}", ev[1]);
    assert_eq!(ev[1].1, EventKind::Reversal { from: 1, to: -1 });
    // After the reversal the body moves backwards: v < 0 just after.
    let (_, v, _) = r.state_at(0.9).unwrap();
    assert!(v < 0.0);
}

#[test]
fn events_are_never_repeated_nor_simultaneous() {
    // Sweep the pulled mass through all regimes on both laws, and a law with vertices at the
    // slip onset: transitions strictly increase in time and alternate correctly.
    let mut cases = Vec::new();
    for i in 0..60 {
        let phi = 0.01 + 0.9 * f64::from(i) / 60.0;
        let base = PulledMassParams {
            mu_d: 0.3,
            ..PulledMassParams::default()
        };
        cases.push(PulledMassParams {
            force: phi * base.weight(),
            ..base
        });
    }
    for p in &cases {
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let r = run(
                &pulled_mass::body(p),
                &pulled_mass::force_law(p, law).unwrap(),
                12,
            );
            let ev = transitions(&r);
            for w in ev.windows(2) {
                assert!(w[1].0 > w[0].0, "{law:?} φ = {}: {:?}", p.phi(), w);
                let alternates = matches!(
                    (w[0].1, w[1].1),
                    (EventKind::Slip { .. }, EventKind::Stick { .. })
                        | (EventKind::Stick { .. }, EventKind::Slip { .. })
                );
                // The kept windows (first and last periods) may skip the middle of the run.
                assert!(alternates || w[0].1 == w[1].1, "{law:?}: {w:?}");
            }
            // The recorded segments tile the run without gaps.
            for s in r.segments.windows(2) {
                assert_eq!(s[0].t1, s[1].t0);
            }
        }
    }
}

#[test]
fn friction_dissipation_equals_the_work_of_the_pulling_force() {
    // Steady orbit: kinetic energy repeats, so ∫ μd N |v| dt = F Δx per period (guide §4 check).
    for (mu_d, force) in [(0.35, 0.10), (0.35, 0.18)] {
        let p = PulledMassParams {
            mu_d,
            force,
            ..PulledMassParams::default()
        };
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let r = run(
                &pulled_mass::body(&p),
                &pulled_mass::force_law(&p, law).unwrap(),
                8,
            );
            let s = analyse(&r);
            let work = p.force * s.advance_per_period.unwrap() / r.period;
            let dissipated = s.friction_power.unwrap();
            assert!(
                ((work - dissipated) / work).abs() < 1e-13,
                "{law:?} {work} {dissipated}"
            );
        }
    }
}

#[test]
fn bad_force_laws_are_refused() {
    let gap = ForceLaw::new(
        2.0,
        vec![
            linear_piece(0.0, 1.0, (1.0, 0.0), (1.0, 0.0)),
            linear_piece(1.5, 2.0, (1.0, 0.0), (1.0, 0.0)),
        ],
    );
    assert!(gap.is_err());
    assert!(ForceLaw::new(f64::NAN, vec![]).is_err());
    assert!(ForceLaw::new(
        1.0,
        vec![linear_piece(0.0, 1.0, (f64::NAN, 0.0), (1.0, 0.0))]
    )
    .is_err());
}

/// A woodpecker whose spring lifts the sleeve (μs 0.148, μd 0.135, z0 −2.43 mm, d0 14.6 mm,
/// k 188 N/m) slides down and up, reversing twice a period and never sticking (issue 26): that
/// is its label, whether or not the orbit has settled within the periods integrated (it was
/// `not_periodic` after 8 periods and `double_slip_stick` after 40).
#[test]
fn a_sleeve_that_reverses_without_sticking_is_a_reversing_continuous_slip() {
    use stickslip::models::woodpecker::{results, WoodpeckerParams};
    let p = WoodpeckerParams {
        mu_s: 0.1476924386869943,
        mu_d: 0.13517198903911534,
        z0: -0.002434454589115478,
        d0: 0.014583696511394947,
        k: 187.52398366831966,
        ..WoodpeckerParams::default()
    };
    for periods in [8, 40] {
        let e = results::evaluate(&p, periods).expect("valid set");
        for s in e.linear.iter().chain([&e.harmonic]) {
            assert_eq!(
                s.regime,
                IntegrationRegime::ContinuousSlipReversing,
                "{periods}"
            );
            assert_eq!((s.slips_per_period, s.sticks_per_period), (2, 0));
            assert_eq!(s.v_avg.is_some(), periods == 40, "settled only after 40");
            // guide §14 knows no reversal regime: the JSON says what the motion is, a continuous slip.
            assert_eq!(serde_json::to_value(s.regime).unwrap(), "continuous_slip");
        }
    }
}
