//! The built-in scenes of the woodpecker in the default report: each a scenario file of `scenarios/`
//! compiled into the binary, what to draw, and why it matters in the model's part.

use super::scene::WoodFigure;
use crate::present::vocab::Builtin;

macro_rules! scenario_file {
    ($name:literal) => {
        ($name, include_str!(concat!("../../../scenarios/", $name)))
    };
}

const FIG15: (&str, &str) = scenario_file!("fig15-double-slip-stick.toml");
const FIG16: (&str, &str) = scenario_file!("fig16-no-intermediate-halt.toml");
const FIG26: (&str, &str) = scenario_file!("fig26-tracked-toy.toml");
const LAMBDA1: (&str, &str) = scenario_file!("lambda1-printed-formulas.toml");

/// The built-in scenes, in reading order.
pub fn builtins() -> Vec<Builtin> {
    vec![
            Builtin::new(
            "fig15-double-slip-stick",
            (
                "Fig. 15: double slip-stick of the falling woodpecker",
                "The toy as it works: two slips and two halts per swing of the bird.",
            ),
            FIG15,
            "The falling woodpecker (Fig. 15 set): two slips and two sticks per period under both \
             laws. Sleeve position and speed with the characteristic times.",
            &[WoodFigure::Motion { periods: 2.0 }],
            &[8],
            ),
            Builtin::new(
            "fig16-no-intermediate-halt",
            (
                "Fig. 16: no intermediate halt under the harmonic law (z0 = 7.1 mm)",
                "Regime boundaries are sharp: 0.1 mm of spring set-up changes the motion.",
            ),
            FIG16,
            "A 0.1 mm larger z0 removes the intermediate halt of the harmonic law: one slip per \
             period with two speed maxima.",
            &[WoodFigure::Motion { periods: 2.0 }],
            &[8],
            ),
            Builtin::new(
            "fig17-spring-coordinate",
            (
                "Fig. 17: the spring coordinate and its linear counterparts",
                "Three ways to replace the bird's harmonic swing by a triangle wave, and how far each is off.",
            ),
            FIG15,
            "The spring coordinate of the harmonic law against its three linear counterparts \
             (same extremes, same zeros, same zeros and slopes).",
            &[WoodFigure::Spring],
            &[3],
            ),
            Builtin::new(
            "fig18-forces",
            (
                "Fig. 18: the driving force against the grip",
                "Why the sleeve slips: its weight and the spring force against the friction the lever can hold.",
            ),
            FIG15,
            "The driving force W_S + F_e against the static capacity 2λμs|F_e| (and the dynamic \
             friction 2λμd|F_e|): the slip of phase I starts where they cross.",
            &[WoodFigure::Forces],
            &[],
            ),
            Builtin::new(
            "fig19-phase-one",
            (
                "Fig. 19: phase I step by step",
                "The first slip of each period, with each of its characteristic times.",
            ),
            FIG15,
            "Phase I of the linear law: acceleration, speed and position with t_SL, t0, t_M, t_ST.",
            &[WoodFigure::Phase { phase: 1 }],
            &[5],
            ),
            Builtin::new(
            "fig20-mu-d-min-one",
            (
                "Fig. 20: the critical dynamic friction of phase I",
                "The friction μd,MIN at which the sleeve stops exactly at half a period.",
            ),
            FIG15,
            "Phase I for μd below, at and above μd,MIN^(I): at the critical value the sleeve \
             stops exactly at T/2.",
            &[WoodFigure::MuSweep { phase: 1 }],
            &[4, 5],
            ),
            Builtin::new(
            "phase-two",
            (
                "Phase II and its critical dynamic friction",
                "The second slip of the period, and the friction μd,MIN at which it ends at the period's end.",
            ),
            FIG15,
            "Phase II likewise: acceleration, speed and position, and μd below, at and above \
             μd,MIN^(II).",
            &[
                WoodFigure::Phase { phase: 2 },
                WoodFigure::MuSweep { phase: 2 },
            ],
            &[4],
            ),
            Builtin::new(
            "fig23-positions",
            (
                "Fig. 23: sleeve and bird positions",
                "The bird swings about the falling sleeve: the motion the eye follows on the real toy.",
            ),
            FIG15,
            "Sleeve and woodpecker positions and the sleeve speed (harmonic law): the bird \
             oscillates about the falling sleeve.",
            &[WoodFigure::Positions],
            &[7],
            ),
            Builtin::new(
            "fig26-tracked-toy",
            (
                "Figs. 26-27: the parameters of the tracked toy",
                "The model with the parameters of a real, video-tracked toy.",
            ),
            FIG26,
            "The tracked toy's parameters (Figs. 26–27): sleeve position and speed under both laws, \
             and a tracked track (synthetic here: the paper does not give its tracked data) with \
             the harmonic law fitted to it, as `stickslip fit` does for your own video.",
            &[WoodFigure::Motion { periods: 3.0 }, WoodFigure::Tracked],
            &[3, 8],
            ),
            Builtin::new(
            "woodpecker-regime-map",
            (
                "The woodpecker's regimes in the (μd, z0) plane",
                "Where the toy halts twice, once or never, and how well the closed-form boundaries find it.",
            ),
            FIG15,
            "Regimes in the (μd, z0) plane: the linear orbit (closed forms) and the harmonic law \
             (exact integration), with the analytic boundaries μd,MIN and μd,HALT of both phases.",
            &[WoodFigure::RegimeMap],
            &[4, 5, 6],
            ),
            Builtin::new(
            "lambda1-printed-formulas",
            (
                "The printed formulas (λ = 1): a sleeve that never halts",
                "The paper's formulas as printed leave out the lever: with them the toy would not work.",
            ),
            LAMBDA1,
            "The printed formulas (λ = 1, N = |F_e|): with the paper's friction values the sleeve \
             never sticks.",
            &[WoodFigure::Motion { periods: 2.0 }],
            &[8],
            ),
    ]
}
