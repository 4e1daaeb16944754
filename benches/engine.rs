//! Timing of the pulled-mass pipeline on worked set B of physics.md §5 (μs 0.4, μd 0.35,
//! m 0.06 kg, k 45 N/m, F 0.10 N: one slip and one stick per period, so every period has events
//! to locate): all closed forms, the exact integration of 20 periods of each force law, the
//! steady-state analysis of such a run, and the whole evaluation behind `stickslip eval`.
//!
//! ```text
//! cargo bench --bench engine -- --warm-up-time 1 --measurement-time 3
//! ```
//!
//! Targets: closed forms < 1 µs; 20 periods of either law < 20 µs. The woodpecker (Fig. 15
//! set): all closed forms of both phases < 2 µs; 20 periods of either law < 30 µs. The whole
//! default report (rendered in memory) < 2 s.
//!
//! The engine at its floor (issue 14): 20 periods within 1.5× a lean closed-form engine in C
//! (1.1 / 8.4 / 2.1 / 21 µs for the pulled mass linear / harmonic and the woodpecker linear /
//! harmonic), i.e. ≤ 1.65 / 12.6 / 3.15 / 31.5 µs, and the harmonic woodpecker ≤ 15 µs. On a
//! shared machine the timings follow its load (quote `uptime` with them); the instruction counts
//! of benches/engine_instructions.rs do not, and compare versions of the engine:
//!
//! ```text
//! instructions per 20-period run  before issue 14  1st pass  2nd pass  3rd pass  4th pass  5th pass  6th pass  7th pass  libm calls/period
//! pulled mass, linear law                  44 430    35 534    24 058    21 995    22 918    21 491    20 575    20 355  0
//! pulled mass, harmonic law                98 625    77 755    59 804    58 312    44 100    43 792    43 435    34 915  23.1 → 11.2 | 9.35 → 0.8
//! woodpecker, linear law                   81 649    69 598    46 945    42 858    44 444    41 511    39 591    39 313  0
//! woodpecker, harmonic law                237 437   166 374   136 548   133 204   110 373   110 499   109 700    85 406  53.0 → 19.4 | 21.85 → 1.8
//! ```
//!
//! (libm calls before and after the first pass with a sin and a cos of one angle counted once;
//! after the third pass every call counted, from callgrind's call counts with
//! `callgrind_annotate --tree=caller`: pulled mass cos 5.25, sin 3.05, asin 1.05; woodpecker
//! cos 10.55, sin 7.15, acos 2.0, asin 2.15 per period. The first pass re-counted on the build
//! of the second: 35 374, 79 597, 69 274 and 168 798.) First pass, measured with the command above back to back with the engine
//! before issue 14 on the shared 2-core machine at load average 3 (2026-11-25): 3.96 → 3.37,
//! 10.09 → 8.23, 7.86 → 6.76 and 22.1 → 19.4 µs.
//!
//! Second pass: a piece's slip-onset searches are worked out once per run (the two-part root of
//! the switching function, its arccosine on a cos basis, the onset acceleration there: the same
//! in every period), the slide is compiled once for each kind of arc (`PolyArc`, `TrigArc`
//! behind `ArcMotion`) instead of carrying both kinds' branches and spills, a segment's arc is
//! copied only when segments are recorded, and the event recorder is inlined. Every event is the
//! same to the bit (the fingerprints of benches/engine_instructions.rs are unchanged). Back to
//! back with the first pass, three alternating rounds, two at load average 4–5 and one at 2
//! (2026-11-25): 3.66 / 3.69 / 3.59 → 1.90 / 1.86 / 1.83, 9.43 / 9.20 / 9.56 → 7.40 / 7.64 /
//! 6.97, 6.96 / 6.96 / 7.23 → 3.53 / 3.41 / 3.74 and 19.7 / 19.3 / 19.2 → 16.2 / 14.9 / 15.3 µs:
//! half the time on the linear laws, 0.8 of it on the harmonic ones. The harmonic laws meet
//! their 1.5× targets and the harmonic woodpecker is at about its 15 µs; the linear laws (no
//! libm: the time is the event machinery itself) are 10–20 % above theirs.
//!
//! Third pass: the prepared pieces of a law of up to 4 pieces (the models' laws) live on the
//! stack, each prepared in its place (no allocation per run, fewer copies of the few hundred
//! bytes of a prepared piece), the earlier of the two directions' slip onsets is picked without
//! iterator adapters, and the sign of s·a is read from its sign bit instead of a saturating
//! float-to-integer conversion of its signum. Fingerprints unchanged; the second pass re-counted
//! on the build of the third: 24 052, 59 687, 46 933 and 136 201 (−8.6 %, −2.3 %, −8.7 %,
//! −2.2 %). Back to back with the second pass, three alternating rounds at load average 1.1–1.3
//! (2026-11-25): 1.70 / 1.74 / 1.69 → 1.74 / 1.72 / 1.70, 6.34 / 6.40 / 6.43 → 6.19 / 6.26 /
//! 6.14, 3.33 / 3.36 / 3.33 → 3.36 / 3.37 / 3.37 and 14.5 / 14.4 / 14.8 → 14.2 / 14.2 /
//! 14.1 µs: the harmonic laws 3 % faster (the woodpecker's within its 15 µs), the linear laws
//! unchanged within the noise although they run 9 % fewer instructions, so their time is not
//! the instruction count (still 3–7 % above their 1.65 and 3.15 µs at this load).
//!
//! Fourth pass (the harmonic laws): in direction s the acceleration a = (D − s μd N_f)/M depends
//! on time only, so on a cos basis its zeros on a piece are located once per run, in two parts
//! like the slip onsets (src/engine/accel.rs), and the sign of s·a on each part of a slide is
//! read off them: no arccosine per arc. sin and cos of the half angles an arc meets in every
//! period (from the piece's start or a located onset to the piece's end and to the zeros of a)
//! are worked out once per run; a search for a slip onset takes sin and cos of its start from
//! the piece's phase or from the arc that stuck; the stick search steps by angle addition up to
//! 0.6 rad of δ/2 from the last evaluated half angle (Taylor sums to e^16; the seed does not move
//! with the additions, so their rounding does not accumulate); the kernels' series are summed
//! by Estrin's scheme (the search waits for each evaluation, and without FMA a Horner step is a
//! dependent multiply and add); a trigonometric arc keeps A1/ω and A1/ω². libm calls per period
//! (callgrind, every call counted, preparation included): pulled mass 9.35 → 0.8, woodpecker
//! 21.85 → 1.8, all of them the per-run preparation. Linear laws: every event bit for bit as
//! before (fingerprints unchanged); harmonic laws: kinds and counts of events unchanged on the
//! 8000 fingerprint sets, transition times within 5e-16 relative, the reference's worst event
//! error unchanged (2.5e-15 T); speed maxima near θ = π move by up to 2.6e-13 relative, to
//! mpmath's value (the old zero took the rounding of cos θc). The third pass re-counted on the
//! build of the fourth: 22 004, 58 430, 42 877 and 133 556 (harmonic −25 % and −17 %; linear
//! +4 %: the event loop's extra bookkeeping, not located). Back to back with the third pass,
//! three alternating rounds at load average 1.1–1.2 (2026-11-25): 1.76 / 1.79 / 1.76 → 1.81 /
//! 1.81 / 1.77, 6.55 / 6.53 / 6.42 → 4.79 / 4.83 / 5.04, 3.44 / 3.47 / 3.48 → 3.71 / 3.67 /
//! 3.72 and 14.7 / 14.9 / 14.6 → 10.7 / 10.8 / 11.0 µs: the harmonic laws 26 % faster, the
//! linear ones 1–3 % and 7 % slower (the woodpecker's 4 pieces; a standalone timing loop on
//! the core build puts its cost at about 12 ns per period and 70 ns per run).
//!
//! Fifth pass (the linear laws back): a run walks each piece with code compiled for the kind of
//! its basis (`walk_piece::<PolyArc>` or `::<TrigArc>` in src/engine/run.rs), so that on a
//! linear basis the phase bookkeeping of the fourth pass (the piece's start phase, the onsets'
//! and the sticks' phases) is known to be none and drops out; the search for a slip onset is
//! compiled per kind too, and `UpCrossings::first` is inlined into it (no 64-byte crossing
//! returned through memory). Every event bit for bit as before (all four fingerprints
//! unchanged). Back to back with the fourth pass, three alternating rounds at load average
//! 1.0 (2026-11-26): 1.76 / 1.80 / 1.75 → 1.57 / 1.53 / 1.55, 4.75 / 4.72 / 4.67 → 4.49 /
//! 4.55 / 4.49, 3.58 / 3.56 / 3.54 → 2.98 / 3.01 / 3.02 and 10.49 / 10.53 / 10.38 → 10.14 /
//! 10.22 / 10.11 µs: the linear laws 12 % and 16 % faster (within their 1.65 and 3.15 µs),
//! the harmonic ones 4 % and 3 % faster. The fourth pass re-counted on the build of the fifth:
//! 22 924, 44 219, 44 456 and 110 726.
//!
//! Sixth pass: the root finder `monotone_zero` (src/engine/roots.rs) is inlined into the slide
//! that calls it, so the bracket ends and the values at them stay in registers (the evaluations
//! of the motion are still a call each). Fingerprints unchanged; the fifth pass re-counted on the
//! build of the sixth: 21 493, 43 794, 41 513 and 110 501 (−4.3 %, −0.8 %, −4.6 %, −0.7 %).
//! Tried and dropped: the bracket update as two selects instead of a branch on the sign of f
//! (+1 % instructions, the harmonic woodpecker 3 % slower: the branch predicts well). Back to
//! back with the fifth pass, two alternating rounds of all four at load average 2.3–3.4 and two
//! of the harmonic woodpecker at 2.0–2.3 (2026-11-26): 1.59 / 1.55 → 1.61 / 1.49, 5.45 / 4.53 →
//! 4.42 / 4.39, 3.28 / 2.89 → 2.81 / 2.72 and 10.66 / 9.99 / 10.16 / 10.23 → 10.23 / 10.27 /
//! 10.01 / 10.12 µs: the linear laws 4–6 % faster, the harmonic pulled mass 3 %, the harmonic
//! woodpecker within the noise (about 1 %); the 8 µs stretch goal is not reached.
//!
//! Seventh pass (the stick search on a cos basis, src/engine/roots.rs and arc.rs): the search
//! starts from the Taylor parabola's zero improved by one Newton step on the cubic through it
//! and the speed at the other end of the bracket (the parabola alone started about 10 % of its
//! distance off); the step after a converging Halley step is predicted, |h₁|·|h₁/h₀|³, and the
//! search ends without the evaluation that would only confirm it where that is below eps/64 of
//! t; the later iterates and the stick turn from the first iterate's half angle by Taylor sums
//! to e⁴ (|e| ≤ 2.5e-3, at most two additions from evaluated sin and cos); the known angles of
//! a piece keep their whole kernels, δ − sin δ and δ²/2 − (1 − cos δ) summed once per run (the
//! same bits); the acceleration's zeros per direction without an array map. Evaluations per
//! stick search 4 → 2 (plus the stick itself, now by the short sums). A polynomial arc's search is as before (its parabola start is
//! exact). Linear fingerprints unchanged; harmonic laws: kinds and counts of events unchanged on
//! the 8000 fingerprint sets, transition times within 8e-16 relative (2.1e-16 of the run's
//! length), positions and velocities within 6e-15 and 2e-15 of their largest in the run. The
//! sixth pass re-counted before it: 20 569, 43 318, 39 579 and 109 353 (−1.0 %, −19 %, −0.7 %,
//! −22 %). Tried and dropped: the Taylor sums of every angle addition cut by |e| (the turn from
//! a known angle is 0.1–0.4 rad on the woodpecker: +2 % instructions). With the command above
//! at load average 2.1–1.8 (another build running, 2026-11-26): 1.47, 2.98, 2.80 and 6.88 µs
//! (the harmonic woodpecker within the 8.4 µs of the 16 % goal, not compared back to back).

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};

use stickslip::engine::{analyse, integrate, RunOptions};
use stickslip::models::pulled_mass::formula as cf;
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker;
use stickslip::models::woodpecker::formula as wcf;
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::{pulled_mass, LawKind};
use stickslip::report::{builtin_scenes, render, Format};

/// Periods integrated per run (the targets above are stated for 20).
const PERIODS: u32 = 20;

/// Worked set B.
fn set_b() -> PulledMassParams {
    PulledMassParams {
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    }
}

fn closed_forms(c: &mut Criterion) {
    let p = set_b();
    let (g, period, phi) = (p.g, p.period(), p.phi());
    c.bench_function("closed forms, all of physics.md 1.3-1.5", |b| {
        b.iter(|| {
            cf::evaluate(
                black_box(g),
                black_box(period),
                black_box(p.force),
                black_box(phi),
                black_box(p.mu_s),
                black_box(p.mu_d),
            )
        })
    });
}

fn integration(c: &mut Criterion) {
    let p = set_b();
    let body = pulled_mass::body(&p);
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
        dissipation: false,
    };
    for (name, kind) in [("linear", LawKind::Linear), ("harmonic", LawKind::Harmonic)] {
        let law = pulled_mass::force_law(&p, kind).expect("set B gives a valid force law");
        c.bench_function(&format!("integrate {PERIODS} periods, {name} law"), |b| {
            b.iter(|| integrate(black_box(&body), black_box(&law), black_box(&opts)))
        });
    }
}

fn steady_analysis(c: &mut Criterion) {
    let p = set_b();
    let law = pulled_mass::force_law(&p, LawKind::Harmonic).expect("valid force law");
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
        dissipation: false,
    };
    let run = integrate(&pulled_mass::body(&p), &law, &opts).expect("set B integrates");
    c.bench_function(&format!("steady analysis of {PERIODS} periods"), |b| {
        b.iter(|| analyse(black_box(&run)))
    });
}

fn whole_evaluation(c: &mut Criterion) {
    let p = set_b();
    c.bench_function(
        "evaluate: closed forms, 8 periods of both laws, checks",
        |b| {
            b.iter(|| {
                stickslip::models::pulled_mass::results::evaluate(black_box(&p), black_box(8))
            })
        },
    );
}

fn woodpecker_closed_forms(c: &mut Criterion) {
    let inputs =
        stickslip::models::woodpecker::results::linear_inputs(&WoodpeckerParams::default());
    c.bench_function("woodpecker closed forms, both phases and the orbit", |b| {
        b.iter(|| wcf::evaluate(black_box(&inputs)))
    });
}

fn woodpecker_integration(c: &mut Criterion) {
    let p = WoodpeckerParams::default();
    let body = woodpecker::body(&p);
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
        dissipation: false,
    };
    for (name, kind) in [("linear", LawKind::Linear), ("harmonic", LawKind::Harmonic)] {
        let law = woodpecker::force_law(&p, kind).expect("Fig. 15 gives a valid force law");
        c.bench_function(
            &format!("woodpecker: integrate {PERIODS} periods, {name} law"),
            |b| b.iter(|| integrate(black_box(&body), black_box(&law), black_box(&opts))),
        );
    }
}

fn default_report(c: &mut Criterion) {
    let scenes = builtin_scenes().expect("built-in scenes");
    let mut group = c.benchmark_group("report");
    group.sample_size(10);
    group.bench_function("whole default report, html and md, in memory", |b| {
        b.iter(|| render(black_box(&scenes), &[Format::Html, Format::Md]))
    });
    group.finish();
}

criterion_group!(
    benches,
    closed_forms,
    integration,
    steady_analysis,
    whole_evaluation,
    woodpecker_closed_forms,
    woodpecker_integration,
    default_report
);
criterion_main!(benches);
