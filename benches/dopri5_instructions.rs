//! Instructions per accepted step of the tool's `dopri5` against a textbook DOPRI5: a driver
//! for `valgrind --tool=callgrind` (instruction counts do not depend on the load of the
//! machine).
//!
//! The stretch: the pulled mass with F = 0.5 N > 2 μs W (μs 0.4, μd 0.35, other parameters
//! default, harmonic law) over 20 periods: it slips at t = 0 and never sticks (physics.md
//! §1.5), so `Dopri5` integrates the one smooth slip equation
//!
//! ```text
//! x' = v,   v' = (F − μd W (1 + cos ωt)) / M        (s = +1 throughout)
//! ```
//!
//! with all its machinery (stick switching function checked on every step's interpolant,
//! steps ending at the period boundaries, the breakpoints of the force law). The textbook
//! DOPRI5 below integrates the same equation: Hairer's tableau with FSAL, the same error norm
//! (RMS, atol = rtol = tol), controller (0.9 err^(−1/5) clamped to [0.2, 5], no growth after
//! a rejection), first step (Hairer's heuristic) and landing on the same period boundaries, so
//! that both take the same steps; its right-hand side is what a hand-written one would be (one
//! cosine per evaluation, no piece lookup); no events, no dense output. Measure: instructions
//! collected in `ours_repeatedly` resp. `textbook_repeatedly` divided by runs × accepted
//! steps (the driver prints the steps; the slip-onset check at t = 0 counts in `ours`).
//!
//! ```text
//! cargo bench --bench dopri5_instructions --no-run
//! valgrind --tool=callgrind --toggle-collect='*dopri5_instructions*ours_repeatedly*' \
//!     target/release/deps/dopri5_instructions-<hash> ours 1e-8 200
//! valgrind --tool=callgrind --toggle-collect='*dopri5_instructions*textbook_repeatedly*' \
//!     target/release/deps/dopri5_instructions-<hash> textbook 1e-8 200
//! valgrind --tool=callgrind --toggle-collect='*dopri5_instructions*smooth_repeatedly*' \
//!     target/release/deps/dopri5_instructions-<hash> smooth 1e-8 200
//! valgrind --tool=callgrind --toggle-collect='*dopri5_instructions*ours_repeatedly*' \
//!     target/release/deps/dopri5_instructions-<hash> set-b 1e-8 200
//! valgrind --tool=callgrind --toggle-collect='*dopri5_instructions*lean_repeatedly*' \
//!     target/release/deps/dopri5_instructions-<hash> lean-woodpecker 1e-10 200
//! target/release/deps/dopri5_instructions-<hash> fingerprint
//! callgrind_annotate --inclusive=yes callgrind.out.<pid>
//! ```
//!
//! Arguments: `ours`, `textbook`, `smooth` (the tool's plain DOPRI5, `try_solve_smooth`, with
//! the textbook's right-hand side from 0 to t_end: the integrator without the stick/slip
//! machinery; no stops, so its steps differ slightly), `set-b` (ours on the stick-slip set B,
//! harmonic law, 20 periods, 40 events: the stick checks at work), `woodpecker` (ours on the
//! woodpecker's Fig. 15 set, harmonic law, 20 periods, 80 events; `set-b` and `woodpecker`
//! print the largest event-time error against the exact engine), `lean-set-b` and
//! `lean-woodpecker` (the same two problems by a lean event-locating DOPRI5, [`Lean`]) or
//! `fingerprint` (bits of
//! dopri5's results on 6 problems × 11 tolerances, to check that a change keeps them); then
//! the tolerance (default 1e-8) and the runs (default 200).
//!
//! Measured (instructions per accepted step = collected / (200 runs × accepted steps); ours
//! and the textbook take the same steps: 216 accepted + 25 rejected at 1e-8, 44 + 0 at 1e-4,
//! 1277 + 0 at 1e-12):
//!
//! ```text
//!                                 tol 1e-4   tol 1e-8   tol 1e-12
//! textbook DOPRI5                     894        979         880
//! ours before (f6f836f)              3325       3700        3378    (3.7–3.8× the textbook)
//! ours at 18331a2                    1485       1462        1307    (1.49–1.66×)
//! ours at 5932b79                    1184       1199        1076    (1.22–1.32×)
//! ours at 58a1b64                    1168       1171        1047    (1.19–1.31×)
//!     (58a1b64 measured again with rustc 1.95: 1179, 1186, 1062)
//! ours at b638ea1                    1177       1185        1062    (1.21–1.32×, rustc 1.95)
//! ours at e009c57                    1109       1112         998    (1.13–1.24×, rustc 1.95)
//! ours at b4ec6d1                    1065       1111        1013    (1.13–1.19×, rustc 1.95)
//! ours plain integrator (smooth)        –       1072           –    (1.10×; 208 + 26 steps)
//!     (1149 at 18331a2, 1102 at 5932b79, 1097 at b638ea1)
//! set B (stick-slip), ours: 3104 (f6f836f), 1525 (18331a2), 1215 (5932b79), 1192 (58a1b64;
//!     1209 measured again with rustc 1.95), 1209 (b638ea1), 1174 (e009c57), 1184 (b4ec6d1)
//!     per accepted step (342 + 19 steps)
//! ```
//!
//! Against the exact engine (benches/engine_instructions.rs, the same problems over 20 periods),
//! ours per run (collected / 200 runs, `set-b TOL 200` resp. `woodpecker TOL 200`) and the
//! largest event-time error against the exact engine, with the engine's instructions per run at
//! c8fb77c and after the preparation work of src/engine/run.rs:
//!
//! ```text
//!                 tol      error       ours/run   steps      engine/run         ratio
//!                                                 acc.+rej.  c8fb77c → perf     c8fb77c → perf
//! set B           1e-10    3.6e-10 s   608,430    561 + 0    10,905 → 10,241    55.8× → 59.4×
//! set B           3e-11    8.1e-11 s   711,334    660 + 0    10,905 → 10,241    65.2× → 69.5×
//! woodpecker      1e-10    5.5e-11 s   971,557    782 + 20   23,433 → 19,897    41.5× → 48.8×
//! ```
//!
//! Measured again at perf2 (ours unchanged in code; the engine after src/engine/replay.rs's
//! smaller tape steps; engine/run from b33a971, the main branch it started from, to perf2):
//!
//! ```text
//!                 tol      error       ours/run   engine/run          ratio
//! set B           1e-10    3.6e-10 s   608,326    10,438 → 10,044     58.3× → 60.6×
//! set B           3e-11    8.1e-11 s   711,230    10,438 → 10,044     68.1× → 70.8×
//! woodpecker      1e-10    5.5e-11 s   971,456    20,318 → 19,798     47.8× → 49.1×
//! ```
//!
//! Measured again at engine50 (ours unchanged; the engine's replay appends the kept periods'
//! events directly where the recorder would only keep them; engine/run from e97c72c, the main
//! branch it started from, to engine50):
//!
//! ```text
//!                 tol      error       ours/run   engine/run          ratio
//! set B           3e-11    8.1e-11 s   711,334     9,867 → 8,424      72.1× → 84.4×
//! woodpecker      1e-10    5.5e-11 s   971,557    19,431 → 16,953     50.0× → 57.3×
//! ```
//!
//! With the replayed periods' positions kept as exact steps (src/engine/series.rs, for runs of
//! 10⁶ periods), the 20-period runs moved with the compiler's inlining: 8,833 (set B, 80.5×) and
//! 17,411 (woodpecker, 55.8×), ours unchanged.
//!
//! The tolerance whose event-time error is at most 1e-10 s: 3e-11 on set B (1e-10 gives 3.6e-10
//! s), 1e-10 on the woodpecker (1.5e-10 gives 1.5e-10 s). Ours takes the textbook's steps and
//! about 1.1–1.2× its instructions per step (above), so a ratio against the textbook is lower
//! by about that factor.
//!
//! That estimate was too kind to the engine. Measured against a lean event-locating DOPRI5
//! ([`Lean`]: the textbook's steps with no stops at the period boundaries, a stick checked by
//! two sign tests per step, the slip onset from rest solved by `acos` instead of sampled), at
//! the same tolerances, collected in `lean_repeatedly` / 200 runs, engine/run of main at
//! c426ece:
//!
//! ```text
//!                 tol      error       lean/run   steps      engine/run   ratio
//!                                                 acc.+rej.
//! set B           3e-11    8.1e-11 s   482,153    480 + 0     8,833       54.6×
//! woodpecker      1e-10    5.5e-11 s   677,524    601 + 20   17,411       38.9×
//! ```
//!
//! After the engine work of branch linear (src/engine/run.rs, the replay's kept periods split
//! into moves and events) and with the lean and textbook methods sharing their steps
//! ([`first_step`], [`accepted_step`]; the same results, the textbook's instructions per step
//! unchanged at 894, 979 and 880): set B 481,158 / 8,182 = **58.8×**, woodpecker 676,058 / 15,927
//! = **42.4×**. The issue's 50× held on set B; on the woodpecker it needed about 13,520
//! instructions per run. With the known half angles set up only from a run's second integrated
//! period and the kept periods' events written in place: set B 481,158 / 7,384 = **65.2×**,
//! woodpecker 676,058 / 13,482 = **50.1×** (the tool's DOPRI5: 96.3× and 72.1×).
//!
//! The lean method takes fewer steps than ours (480 against 660 on set B, 621 against 802 on the
//! woodpecker: ours ends a step at every period boundary) and no right-hand side while stuck
//! (ours samples G at 4 points per T/16 there). Nearby tolerances do not meet 1e-10 s: on set
//! B 5e-11 and 4e-11 give 1.02e-10 and 1.16e-10 s, on the woodpecker 1.2e-10 gives 1.08e-10 s.
//! Without landing on the kinks of N_f (the woodpecker's F_e = 0) the lean method stalls at
//! 5.9e-10 s (1591 steps at 3e-11 and 1683 at 1e-11, a quarter of them rejected).

//! At e009c57 the stage states, y1, the error estimate and r5 of the interpolant are formed as the
//! textbook forms them, y + h·Σ a_ij k_j: one product by h per sum instead of one per coefficient
//! (the (h·a_ij)·k_j products below), 64–73 instructions less per step; a run at 1e-4 takes 48,800.
//!
//! At b4ec6d1 the steps that land on a breakpoint and those that start from one are taken on one
//! piece without a check per evaluation, the piece's formula continued to the breakpoint (the
//! force laws are continuous there); a step landing on a period's end of the harmonic law is
//! taken on the next period (τ ∈ [−h, 0]: the cosine of an argument near 0 needs no argument
//! reduction, one near 2π the slowest), and the next piece is found without a look-up. A run at
//! 1e-4 takes 46,870 instructions (48,800 at e009c57); at 1e-12 and on set B, where few steps
//! meet a breakpoint, the step costs 15 resp. 10 more (the changed piece check and code layout,
//! not analysed further).
//!
//! Where a run's 51,800 instructions went at 1e-4 at b638ea1 (44 steps, 20 periods; textbook
//! 39,360): cos 17,200 (203 calls; the textbook's glibc cos 21,100), pow 5,600 (45 calls, the
//! same), the integrator and the machinery ≈ 28,800 (textbook 12,600): ≈ 380 per step taken on
//! the remembered piece, ≈ 470 per step whose evaluations check their piece (25 of the 44: the 20 steps that land on a period
//! boundary, whose sixth stage is on the next period's piece, and 5 that start from a boundary
//! whose τ rounded below T, still on the old piece), 65 per step for the stop and on-piece checks,
//! 92 per step for the stick bound (r5 alone 32), and per period a look-up of the next piece
//! (≈ 85 with its `fma`, 20 per run) and `next_breakpoint` (≈ 40 with its `floor`, 21 per run). Taking
//! the landing steps on the piece (the stage at the stop checked, by a compare per evaluation, a
//! separate `Field` method or an out-of-line step) gave the same bits but 11–40 more instructions
//! per ordinary step at 1e-8: the hot step's code is one inlined body whose register allocation
//! every further copy of the step degrades.
//!
//! Where ours' 1199 went at 1e-8 at 5932b79 (textbook 979; 1171 at 58a1b64: the basis of the force
//! law is matched once per step, not at each evaluation, the step's piece is not copied, and the
//! sums of r5 for the positivity bound, of the error estimate and of the error norm start from
//! their first terms): cos 447 (the `libm` crate's of src/fmath.rs, ≈ 80 per call, 5 calls per
//! attempt: the FSAL stage reuses the sixth stage's force; the textbook's glibc `cos` costs 602,
//! ≈ 108 per call, and LLVM merges its two calls at t + h as it knows `f64::cos` is pure), pow 140
//! (same), the integrator and the stick/slip machinery 600 (textbook 292): the tableau's bit-exact
//! (h·a_ij)·k_j products, the positivity bound of s·v on the interpolant (≈ 78: v's coefficients
//! only; the interpolant itself is formed only where it fails), the step's dispatch (breakpoint,
//! on-piece and stall checks, ≈ 100), the force law's piece offset per evaluation and the crossings
//! of the period boundaries. At 1e-4 nearly half the steps end on a period boundary, where the
//! force law is looked up again. Before f6f836f: 2 cosines, 4 `fmod` and 2 piece searches per
//! evaluation (1200 + 700 + 640 per step), the interpolant sampled at 8 points with its derivative
//! on every step.
//!
//! The results of f6f836f, 18331a2, 5932b79, 58a1b64 and b638ea1 are bit for bit the same
//! (`fingerprint` printed the same hashes): event times, end states and work counters on all 66
//! runs. Those of e009c57 differ from them in rounding only: on the 66 runs, the same events
//! (kinds and counts), event times within 1.1e-14 s, x_end within 8.2e-14 m, v_end within
//! 2.3e-14 m/s, the same accepted and rejected steps but at 1e-11 on the harmonic woodpecker
//! (1099 accepted instead of 1100), and right-hand-side evaluations of the stick location
//! differing by a few; ours and the textbook still take the same steps at 1e-4, 1e-8 and 1e-12.
//! Those of b4ec6d1 differ from e009c57's in rounding only: on the 66 runs, the same events (kinds
//! and counts) and the same accepted and rejected steps, event times within 2.9e-14 s, x_end
//! within 2.5e-14 m, v_end within 3.6e-15 m/s, right-hand-side evaluations of the stick location
//! differing by up to 24 (of 884); ours and the textbook still take the same steps.

use std::hint::black_box;

use stickslip::engine::{Basis, Body, Piece};
use stickslip::models::pulled_mass::{self, PulledMassParams};
use stickslip::models::woodpecker::{self, WoodpeckerParams};
use stickslip::models::LawKind;
use stickslip::solver::dopri5::tableau::*;
use stickslip::solver::dopri5::{try_solve_smooth, Dopri5};
use stickslip::solver::exact::Exact;
use stickslip::solver::{Method, MethodEvent, Problem, Setting, Solution, Stats};

/// Periods per run.
const PERIODS: f64 = 20.0;

/// The pulled mass (μs 0.4, μd 0.35, harmonic law) with drive `force` (N) over 20 periods.
fn pulled(force: f64) -> Problem {
    let p = PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.35,
        force,
        ..PulledMassParams::default()
    };
    let law = pulled_mass::force_law(&p, LawKind::Harmonic).expect("a valid force law");
    Problem {
        body: pulled_mass::body(&p),
        t_end: PERIODS * law.period,
        law,
    }
}

/// `runs` solutions by the tool's `dopri5`; the function callgrind collects in.
#[inline(never)]
fn ours_repeatedly(problem: &Problem, tol: f64, runs: u32) -> Solution {
    let mut last = None;
    for _ in 0..runs {
        last = Some(Dopri5.solve(black_box(problem), black_box(Setting::Tolerance(tol))));
    }
    last.expect("at least one run")
        .expect("the problem integrates")
}

type State = [f64; 2];

fn norm(e: State, a: State, b: State, tol: f64) -> f64 {
    let s0 = e[0] / (tol + tol * a[0].abs().max(b[0].abs()));
    let s1 = e[1] / (tol + tol * a[1].abs().max(b[1].abs()));
    (0.5 * (s0 * s0 + s1 * s1)).sqrt()
}

/// Textbook DOPRI5 from (t0, y0) through the stop times `stops` (increasing), landing on each
/// (a step within 1 % of reaching it is stretched to it); returns y at the last stop.
fn textbook(
    f: impl Fn(f64, State) -> State,
    t0: f64,
    y0: State,
    stops: &[f64],
    tol: f64,
    stats: &mut Stats,
) -> State {
    let t_end = *stops.last().expect("a stop");
    let (mut t, mut y) = (t0, y0);
    let mut k1 = f(t, y);
    let mut h_next = first_step(&f, t, y, k1, t_end - t0, tol, stats);
    for &stop in stops {
        while stop - t > 8.0 * f64::EPSILON * t.abs().max(stop.abs()) {
            let (_, t1, y1, k) = accepted_step(&f, (t, y, k1), stop, tol, &mut h_next, stats);
            (t, y, k1) = (t1, y1, k[5]);
        }
    }
    y
}

/// The first step from (t, y) with k1 = f(t, y) over `span` (s) (Hairer, Nørsett & Wanner I,
/// II.4).
#[inline(always)]
fn first_step(
    f: &impl Fn(f64, State) -> State,
    t: f64,
    y: State,
    k1: State,
    span: f64,
    tol: f64,
    stats: &mut Stats,
) -> f64 {
    let (d0, d1) = (norm(y, [0.0; 2], y, tol), norm(k1, [0.0; 2], y, tol));
    let h0 = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6 * span
    } else {
        (0.01 * d0 / d1).min(span)
    };
    let k2 = f(t + h0, [y[0] + h0 * k1[0], y[1] + h0 * k1[1]]);
    let d2 = norm([k2[0] - k1[0], k2[1] - k1[1]], [0.0; 2], y, tol) / h0;
    let h1 = if d1.max(d2) <= 1e-15 {
        (h0 * 1e-3).max(1e-6 * span)
    } else {
        (0.01 / d1.max(d2)).powf(0.2)
    };
    stats.rhs_evals += 2;
    (100.0 * h0).min(h1).min(span)
}

/// One accepted step from (t, y) with k1 = f(t, y) towards `stop`, landing on it when within 1 %
/// of it, trying `h_next` first and shrinking it after each rejection; sets `h_next` for the
/// next step. Returns the step's length h, its end t1 and y1 there, and the stages k1, k3 … k7
/// (for the dense output; k7 = f(t1, y1) is the next step's k1).
#[inline(always)]
fn accepted_step(
    f: &impl Fn(f64, State) -> State,
    (t, y, k1): (f64, State, State),
    stop: f64,
    tol: f64,
    h_next: &mut f64,
    stats: &mut Stats,
) -> (f64, f64, State, [State; 6]) {
    let mut h = *h_next;
    let mut rejected_last = false;
    loop {
        let last = t + 1.01 * h >= stop;
        if last {
            h = stop - t;
        }
        stats.steps += 1;
        let k2 = f(t + C2 * h, [y[0] + h * A21 * k1[0], y[1] + h * A21 * k1[1]]);
        let k3 = f(
            t + C3 * h,
            std::array::from_fn(|i| y[i] + h * (A31 * k1[i] + A32 * k2[i])),
        );
        let k4 = f(
            t + C4 * h,
            std::array::from_fn(|i| y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])),
        );
        let k5 = f(
            t + C5 * h,
            std::array::from_fn(|i| {
                y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
            }),
        );
        let t1 = if last { stop } else { t + h };
        let k6 = f(
            t1,
            std::array::from_fn(|i| {
                y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
            }),
        );
        let y1: State = std::array::from_fn(|i| {
            y[i] + h * (A71 * k1[i] + A73 * k3[i] + A74 * k4[i] + A75 * k5[i] + A76 * k6[i])
        });
        let k7 = f(t1, y1);
        stats.rhs_evals += 6;
        let e: State = std::array::from_fn(|i| {
            h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
        });
        let err = norm(e, y, y1, tol);
        let mut fac = (SAFETY * err.max(1e-300).powf(-0.2)).clamp(FAC_MIN, FAC_MAX);
        if err <= 1.0 {
            stats.accepted += 1;
            if rejected_last {
                fac = fac.min(1.0);
            }
            *h_next = if last && h < *h_next {
                h_next.max(h * fac)
            } else {
                h * fac
            };
            return (h, t1, y1, [k1, k3, k4, k5, k6, k7]);
        }
        stats.rejected += 1;
        rejected_last = true;
        h *= fac.min(1.0);
    }
}

/// The single piece of the harmonic law of `problem`, with its ω (rad/s).
fn harmonic_piece(problem: &Problem) -> (Piece, f64) {
    let piece = problem.law.pieces[0];
    match piece.basis {
        Basis::Cos { omega, .. } => (piece, omega),
        Basis::Linear { .. } => unreachable!("the harmonic law"),
    }
}

/// `runs` textbook integrations of the slip equation of `problem` (s = +1) over its period
/// boundaries; the function callgrind collects in.
#[inline(never)]
fn textbook_repeatedly(problem: &Problem, tol: f64, runs: u32) -> (State, Stats) {
    let (piece, omega) = harmonic_piece(problem);
    let body: Body = problem.body;
    let stops: Vec<f64> = (1..=PERIODS as u32)
        .map(|k| f64::from(k) * problem.law.period)
        .collect();
    let mut last = ([0.0; 2], Stats::default());
    for _ in 0..runs {
        let (piece, body) = black_box((piece, body));
        let f = move |t: f64, y: State| {
            let b = (omega * t).cos();
            [
                y[1],
                body.slip_acceleration(piece.drive.at(b), piece.normal.at(b), 1.0),
            ]
        };
        let mut stats = Stats::default();
        let y = textbook(
            f,
            0.0,
            [0.0; 2],
            black_box(&stops),
            black_box(tol),
            &mut stats,
        );
        last = (y, stats);
    }
    last
}

/// A lean event-locating DOPRI5 for the stick/slip problem of a harmonic law, what a careful
/// hand-written C program would do: D(t) = d0 + d1 cos ωt and N_f(t) = |n0 + n1 cos ωt| folded
/// once (the woodpecker's N_f = 2λ|F_e| changes its formula where F_e changes sign; the pulled
/// mass's never does); while slipping in direction s, y' = (v, (D − s μd N_f)/M), one cosine per
/// evaluation; the textbook's steps (tableau, FSAL, error norm, controller, first step by
/// Hairer's heuristic at each slip onset) with no stops at period boundaries; the stick located on v of the dense output (Hairer's
/// `contd5`, formed only where a stick is found) by Illinois regula falsi, and a dip of s·v
/// below zero inside a step looked for only where s·a goes from − to + across it (8 samples
/// of the interpolant); steps land on the kinks of N_f (where the controller alone, stepping
/// across them, stalls at event-time errors of 6e-10 s on the woodpecker: 1591 steps at 3e-11,
/// 383 of them rejected); the slip onset from rest not integrated but solved on the law by
/// `acos`. Its work per accepted step is the textbook's plus two sign tests. A few per cent
/// could still go: each slip restarted from the last step size instead of Hairer's heuristic
/// (two right-hand sides and a `powf` per slip onset, about 3 % of the woodpecker's run), sticks
/// located to a looser tolerance than 2 ulps (about 1.5 %).
struct Lean {
    omega: f64,
    period: f64,
    drive: [f64; 2],
    normal: [f64; 2],
    /// Times within the period (s) where N_f has a kink (the signed normal force's pieces change
    /// sign).
    kinks: Vec<f64>,
    inv_mass: f64,
    mu_s: f64,
    mu_d: f64,
}

impl Lean {
    /// The lean form of `problem`: a harmonic law whose pieces share their basis and drive
    /// and whose normal forces are one affine function up to its sign.
    fn new(problem: &Problem) -> Self {
        let (piece, omega) = harmonic_piece(problem);
        let shift = piece.basis.shift();
        for other in &problem.law.pieces {
            let same_up_to_sign = other.normal == piece.normal
                || (other.normal.c0 == -piece.normal.c0 && other.normal.c1 == -piece.normal.c1);
            assert!(
                other.basis == piece.basis && other.drive == piece.drive && same_up_to_sign,
                "one harmonic formula for the whole law"
            );
        }
        let fold = |a: stickslip::engine::Affine| [a.c0 - a.c1 * shift, a.c1];
        let pieces = &problem.law.pieces;
        let kinks = (0..pieces.len())
            .filter(|&i| pieces[i].normal != pieces[(i + pieces.len() - 1) % pieces.len()].normal)
            .map(|i| pieces[i].start)
            .collect();
        Lean {
            kinks,
            omega,
            period: problem.law.period,
            drive: fold(piece.drive),
            normal: fold(piece.normal),
            inv_mass: 1.0 / problem.body.mass,
            mu_s: problem.body.mu_s,
            mu_d: problem.body.mu_d,
        }
    }

    /// (D, N_f) at cos ωt = c (N).
    fn forces(&self, c: f64) -> (f64, f64) {
        (
            self.drive[0] + self.drive[1] * c,
            (self.normal[0] + self.normal[1] * c).abs(),
        )
    }

    /// The first kink of N_f after t, or `t_end` if none comes before it.
    fn next_stop(&self, t: f64, t_end: f64) -> f64 {
        let after = t + 8.0 * f64::EPSILON * t.abs();
        self.kinks
            .iter()
            .map(|&phase| {
                let next = phase + ((after - phase) / self.period).ceil() * self.period;
                if next <= after {
                    next + self.period
                } else {
                    next
                }
            })
            .fold(t_end, f64::min)
    }

    /// True while stuck at time t (|D| ≤ μs N_f).
    fn holds(&self, t: f64) -> bool {
        let (d, n) = self.forces((self.omega * t).cos());
        d.abs() <= self.mu_s * n
    }

    /// The next time after t at which c0 + c1 cos ωt crosses 0 upwards (none where it never
    /// changes sign).
    fn up_crossing(&self, c: [f64; 2], t: f64) -> Option<f64> {
        let r = -c[0] / c[1];
        if r.is_nan() || r.abs() >= 1.0 {
            return None;
        }
        let theta = r.acos();
        let phase = if c[1] < 0.0 {
            theta
        } else {
            std::f64::consts::TAU - theta
        } / self.omega;
        let mut t_up = phase + ((t - phase) / self.period).ceil() * self.period;
        if t_up < t {
            t_up += self.period;
        }
        Some(t_up)
    }

    /// The next slip onset at or after t and its direction s: t itself where s·D > μs N_f
    /// already, else the earliest up-crossing of s·D − μs N_f = min(s·D − μs n, s·D + μs n)
    /// (n the signed normal force), an up-crossing of one of the two where the other is
    /// positive; one per period each, so the next period's are the same phases.
    fn onset(&self, t: f64) -> Option<(f64, f64)> {
        let (d, n, mu) = (self.drive, self.normal, self.mu_s);
        let mut first: Option<(f64, f64)> = None;
        for s in [1.0, -1.0] {
            let g = |sigma: f64| [s * d[0] - sigma * mu * n[0], s * d[1] - sigma * mu * n[1]];
            let at = |g: [f64; 2], t: f64| g[0] + g[1] * (self.omega * t).cos();
            if at(g(1.0), t) > 0.0 && at(g(-1.0), t) > 0.0 {
                return Some((t, s));
            }
            for sigma in [1.0, -1.0] {
                if let Some(t_up) = self.up_crossing(g(sigma), t) {
                    if at(g(-sigma), t_up) > 0.0 && first.is_none_or(|(t_first, _)| t_up < t_first)
                    {
                        first = Some((t_up, s));
                    }
                }
            }
        }
        first
    }

    /// Integrates from rest at t = 0 to `t_end`; events into `events`; returns (x, v) at t_end.
    fn solve(
        &self,
        t_end: f64,
        tol: f64,
        stats: &mut Stats,
        events: &mut Vec<MethodEvent>,
    ) -> State {
        let (mut t, mut y) = (0.0, [0.0; 2]);
        'stuck: loop {
            let Some((t_slip, s)) = self.onset(t).filter(|&(t_slip, _)| t_slip < t_end) else {
                return y;
            };
            events.push(MethodEvent {
                t: t_slip,
                kind: "slip",
            });
            let mut s = s;
            t = t_slip;
            'slip: loop {
                let friction = s * self.mu_d;
                let f = |t: f64, y: State| {
                    let (d, n) = self.forces((self.omega * t).cos());
                    [y[1], (d - friction * n) * self.inv_mass]
                };
                let mut k1 = f(t, y);
                let mut h_next = first_step(&f, t, y, k1, t_end - t, tol, stats);
                let mut stop = self.next_stop(t, t_end);
                while t_end - t > 8.0 * f64::EPSILON * t_end {
                    if stop - t <= 8.0 * f64::EPSILON * t {
                        stop = self.next_stop(t, t_end);
                    }
                    let (h, t1, y1, k) =
                        accepted_step(&f, (t, y, k1), stop, tol, &mut h_next, stats);
                    // A stick at the step's end, or a dip of s·v below zero inside it.
                    let dip = s * k[0][1] < 0.0 && s * k[5][1] > 0.0;
                    if s * y1[1] <= 0.0 || dip {
                        let dense = |i: usize| {
                            let r2 = y1[i] - y[i];
                            let r3 = h * k[0][i] - r2;
                            let r4 = r2 - h * k[5][i] - r3;
                            let r5 = h
                                * (D1 * k[0][i]
                                    + D3 * k[1][i]
                                    + D4 * k[2][i]
                                    + D5 * k[3][i]
                                    + D6 * k[4][i]
                                    + D7 * k[5][i]);
                            let y0 = y[i];
                            move |th: f64| {
                                y0 + th * (r2 + (1.0 - th) * (r3 + th * (r4 + (1.0 - th) * r5)))
                            }
                        };
                        let v = dense(1);
                        let end = if s * y1[1] <= 0.0 {
                            Some(1.0)
                        } else {
                            (1..8)
                                .map(|j| f64::from(j) / 8.0)
                                .find(|&th| s * v(th) <= 0.0)
                        };
                        if let Some(end) = end {
                            let th = illinois(|th| s * v(th), 0.0, end, h, t);
                            let t_stick = t + th * h;
                            y = [dense(0)(th), 0.0];
                            t = t_stick;
                            if self.holds(t) {
                                events.push(MethodEvent { t, kind: "stick" });
                                continue 'stuck;
                            }
                            events.push(MethodEvent {
                                t,
                                kind: "reversal",
                            });
                            s = -s;
                            continue 'slip;
                        }
                    }
                    (t, y, k1) = (t1, y1, k[5]);
                }
                return y;
            }
        }
    }
}

/// The root in (lo, hi] of g (g(lo) > 0 ≥ g(hi)) on θ ∈ [0, 1] of a step of length h from t, by
/// Illinois regula falsi to within 2 ulps of the time t + θh.
fn illinois(g: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, h: f64, t: f64) -> f64 {
    let (mut g_lo, mut g_hi) = (g(lo), g(hi));
    let width = 2.0 * f64::EPSILON * (t + h).abs() / h;
    let mut side = 0;
    for _ in 0..100 {
        if hi - lo <= width || g_hi == 0.0 {
            break;
        }
        let mid = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
        let mid = if mid > lo && mid < hi {
            mid
        } else {
            0.5 * (lo + hi)
        };
        let g_mid = g(mid);
        if g_mid > 0.0 {
            (lo, g_lo) = (mid, g_mid);
            if side == -1 {
                g_hi *= 0.5;
            }
            side = -1;
        } else {
            (hi, g_hi) = (mid, g_mid);
            if side == 1 {
                g_lo *= 0.5;
            }
            side = 1;
        }
    }
    hi
}

/// `runs` integrations of `problem` by the lean DOPRI5 ([`Lean`]); the function callgrind
/// collects in.
#[inline(never)]
fn lean_repeatedly(problem: &Problem, tol: f64, runs: u32) -> Solution {
    let lean = Lean::new(problem);
    let mut last = None;
    for _ in 0..runs {
        let mut stats = Stats::default();
        let mut events = Vec::new();
        let y = black_box(&lean).solve(
            black_box(problem.t_end),
            black_box(tol),
            &mut stats,
            &mut events,
        );
        last = Some(Solution::new(events, y[0], y[1], stats));
    }
    last.expect("at least one run")
}

/// FNV-1a over the bits of every event time, the final state and the work counters of `dopri5`
/// on both models, both laws and the tolerances 1e-2 … 1e-12, printed per problem: a change
/// meant to keep the method's results bit for bit is checked by comparing the output before
/// and after it.
fn fingerprints() {
    let mut problems = vec![
        ("slide".to_string(), pulled(0.5)),
        ("late stick".to_string(), pulled(0.185)),
    ];
    for (name, law) in [("linear", LawKind::Linear), ("harmonic", LawKind::Harmonic)] {
        let p = PulledMassParams {
            mu_s: 0.4,
            mu_d: 0.35,
            force: 0.10,
            ..PulledMassParams::default()
        };
        let law_p = pulled_mass::force_law(&p, law).expect("a valid force law");
        problems.push((
            format!("set B {name}"),
            Problem {
                body: pulled_mass::body(&p),
                t_end: PERIODS * law_p.period,
                law: law_p,
            },
        ));
        let w = WoodpeckerParams::default();
        let law_w = woodpecker::force_law(&w, law).expect("a valid force law");
        problems.push((
            format!("woodpecker {name}"),
            Problem {
                body: woodpecker::body(&w),
                t_end: PERIODS * law_w.period,
                law: law_w,
            },
        ));
    }
    for (name, problem) in &problems {
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        let mut mix = |x: u64| h = (h ^ x).wrapping_mul(0x0100_0000_01b3);
        let mut steps = Vec::new();
        for k in 2..=12 {
            let tol = 10f64.powi(-k);
            let s = Dopri5
                .solve(problem, Setting::Tolerance(tol))
                .expect("integrates");
            s.events.iter().for_each(|e| mix(e.t.to_bits()));
            mix(s.x_end.to_bits());
            mix(s.v_end.to_bits());
            let st = s.stats;
            for x in [st.rhs_evals, st.steps, st.accepted, st.rejected, st.events] {
                mix(x);
            }
            steps.push(st.accepted);
        }
        println!("{name}: {h:016x}, accepted steps at 1e-2 … 1e-12 {steps:?}");
    }
}

/// `runs` integrations of the same slip equation by the tool's plain DOPRI5
/// ([`try_solve_smooth`]: the integrator without the stick/slip machinery, dense output still
/// formed every step) with the textbook's right-hand side, from 0 to t_end without stops; the
/// function callgrind collects in.
#[inline(never)]
fn smooth_repeatedly(problem: &Problem, tol: f64, runs: u32) -> (State, Stats) {
    let (piece, omega) = harmonic_piece(problem);
    let body: Body = problem.body;
    let mut last = ([0.0; 2], Stats::default());
    for _ in 0..runs {
        let (piece, body) = black_box((piece, body));
        let f = move |t: f64, y: State| {
            let b = (omega * t).cos();
            [
                y[1],
                body.slip_acceleration(piece.drive.at(b), piece.normal.at(b), 1.0),
            ]
        };
        last = try_solve_smooth(f, 0.0, [0.0; 2], problem.t_end, black_box(tol))
            .expect("the slip integrates");
    }
    last
}

fn main() {
    // `cargo bench` passes `--bench`; the positional arguments are the mode, tol and runs.
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let mode = args.first().map_or("both", String::as_str);
    let tol: f64 = args
        .get(1)
        .map_or(1e-8, |a| a.parse().expect("tol: a number"));
    let runs: u32 = args
        .get(2)
        .map_or(200, |a| a.parse().expect("runs: a number"));
    let slide = pulled(0.5);
    if matches!(mode, "ours" | "both") {
        let s = ours_repeatedly(&slide, tol, runs);
        println!(
            "ours: events {:?}, x_end {:e} m, v_end {:e} m/s, {:?}",
            s.events, s.x_end, s.v_end, s.stats
        );
    }
    if matches!(mode, "textbook" | "both") {
        let (y, stats) = textbook_repeatedly(&slide, tol, runs);
        println!(
            "textbook: x_end {:e} m, v_end {:e} m/s, {stats:?}",
            y[0], y[1]
        );
    }
    if mode == "smooth" {
        let (y, stats) = smooth_repeatedly(&slide, tol, runs);
        println!(
            "smooth: x_end {:e} m, v_end {:e} m/s, {stats:?}",
            y[0], y[1]
        );
    }
    if mode == "fingerprint" {
        fingerprints();
    }
    for (name, problem) in [("set-b", pulled(0.10)), ("woodpecker", woodpecker_fig_15())] {
        let (method, s) = if mode == name {
            ("ours", ours_repeatedly(&problem, tol, runs))
        } else if mode.strip_prefix("lean-") == Some(name) {
            ("lean", lean_repeatedly(&problem, tol, runs))
        } else {
            continue;
        };
        println!(
            "{method}, {name}: {} events, max event-time error {}, x_end {:e} m, {:?}",
            s.events.len(),
            event_error(&s, &problem),
            s.x_end,
            s.stats
        );
    }
}

/// The woodpecker of the paper's Fig. 15 (the default set, harmonic law) over 20 periods: two
/// slips and two sticks per period, the engine's `woodpecker-harmonic` of
/// benches/engine_instructions.rs.
fn woodpecker_fig_15() -> Problem {
    let w = WoodpeckerParams::default();
    let law = woodpecker::force_law(&w, LawKind::Harmonic).expect("a valid force law");
    Problem {
        body: woodpecker::body(&w),
        t_end: PERIODS * law.period,
        law,
    }
}

/// The largest event-time error (s) of `solution` against the exact engine on `problem`, or
/// why there is none (the events differ in kind or number).
fn event_error(solution: &Solution, problem: &Problem) -> String {
    let exact = Exact
        .solve(problem, Setting::Step(1.0))
        .expect("the exact engine integrates the problem");
    let kinds = |s: &Solution| s.events.iter().map(|e| e.kind).collect::<Vec<_>>();
    if kinds(solution) != kinds(&exact) {
        return format!(
            "undefined ({} events, the exact engine has {} of other kinds or order)",
            solution.events.len(),
            exact.events.len()
        );
    }
    let error = solution
        .events
        .iter()
        .zip(&exact.events)
        .map(|(a, b)| (a.t - b.t).abs())
        .fold(0.0, f64::max);
    format!("{error:.2e} s")
}
