//! The built-in scenes of the pulled mass in the default report: each a scenario file of `scenarios/`
//! compiled into the binary, what to draw, and why it matters in the model's part.

use super::scene::PulledFigure;
use crate::present::vocab::Builtin;

macro_rules! scenario_file {
    ($name:literal) => {
        ($name, include_str!(concat!("../../../scenarios/", $name)))
    };
}

const FIG05: (&str, &str) = scenario_file!("fig05-immediate-slip.toml");
const FIG06: (&str, &str) = scenario_file!("fig06-continuous-slip.toml");
const SET_B: (&str, &str) = scenario_file!("set-b-slip-stick.toml");
const SET_C: (&str, &str) = scenario_file!("set-c-late-stick.toml");

/// The built-in scenes, in reading order.
pub fn builtins() -> Vec<Builtin> {
    vec![
            Builtin::new(
            "fig05-immediate-slip",
            (
                "Fig. 5: immediate slip",
                "The simplest case sets the scale: a pull stronger than friction can ever hold, φ = F/W > 2μs.",
            ),
            FIG05,
            "Immediate slip: F exceeds the largest static capacity 2μsW, so the mass slips at t = 0 \
             and never sticks. Position, speed and acceleration under both laws.",
            &[PulledFigure::Motion { periods: 2.0 }],
            &[],
            ),
            Builtin::new(
            "fig06-continuous-slip",
            (
                "Fig. 6: continuous slip",
                "Friction brakes the block every period but never stops it: its speed oscillates about a steady drift.",
            ),
            FIG06,
            "Non-immediate continuous slip (the paper's Fig. 6 set): the slip starts where F = μs N, \
             the speed peaks where F = μd N, and the mass never comes back to rest.",
            &[PulledFigure::Motion { periods: 2.0 }],
            &[1],
            ),
            Builtin::new(
            "pulled-forces",
            (
                "The pull against the friction limits",
                "One picture decides the motion: where F crosses μs N the slip starts, where it crosses μd N the speed peaks.",
            ),
            SET_B,
            "The competing forces: the pull F against the static capacity μs N(t) and the dynamic \
             friction μd N(t). The slip starts where F crosses μs N (t_SL), the speed is largest \
             where F = μd N (t_M), and the mass sticks at t_ST.",
            &[PulledFigure::Forces],
            &[1],
            ),
            Builtin::new(
            "fig09-domain",
            (
                "Fig. 9: where the block sticks, in the (μd, μs) plane",
                "Which friction pairs give stick-slip, and the band where the paper's condition (20) misses a late stick.",
            ),
            FIG06,
            "The (μd, μs) plane for the Fig. 6 value of φ = F/W: where the mass sticks in the same \
             period (20), sticks late in the next period, or slips for ever, for the linear \
             closed forms and for the exact harmonic integration; the analytic boundaries are drawn \
             over the computed regimes.",
            &[PulledFigure::Domain],
            &[1],
            ),
            Builtin::new(
            "fig10-linear-slip-stick",
            (
                "Fig. 10: slip-stick within one period",
                "Textbook stick-slip: every characteristic time has a closed formula, each checked here against the integration.",
            ),
            SET_B,
            "Slip-stick within one period (set B): position, speed and acceleration with the \
             characteristic times of the closed forms.",
            &[PulledFigure::Motion { periods: 1.5 }],
            &[2],
            ),
            Builtin::new(
            "late-stick",
            (
                "Late stick: the block stops in the next period",
                "A motion the paper's Fig. 9 calls non-stick: the block halts early in the following period.",
            ),
            SET_C,
            "Late stick (set C): (20) is violated, yet the mass stops early in the next period, \
             before the next slip onset — the band the paper's Fig. 9 calls non-stick.",
            &[PulledFigure::Motion { periods: 2.0 }],
            &[1],
            ),
            Builtin::new(
            "fig11-position",
            (
                "Fig. 11: ten periods of position and the mean speed",
                "The staircase motion and its mean speed v̄, the number an experiment measures.",
            ),
            SET_B,
            "Position over ten periods and the line of slope v̄ through the slip onsets.",
            &[PulledFigure::LongRun],
            &[2, 7],
            ),
            Builtin::new(
            "fig12-harmonic-vs-linear",
            (
                "Fig. 12: the harmonic law against its linearization",
                "What the triangle-wave approximation changes in the motion: the price of closed formulas.",
            ),
            SET_B,
            "Speed and acceleration of the harmonic law against its linearization, in the settled \
             motion.",
            &[PulledFigure::Compare],
            &[3],
            ),
    ]
}
