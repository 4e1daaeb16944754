//! The built-in scenes of the belt in the default report: each a scenario file of `scenarios/`
//! compiled into the binary, what to draw, and why it matters in the model's part.

use super::present::BeltFigure;
use crate::present::vocab::Builtin;

macro_rules! scenario_file {
    ($name:literal) => {
        ($name, include_str!(concat!("../../../scenarios/", $name)))
    };
}

const TEXTBOOK: (&str, &str) = scenario_file!("belt-textbook.toml");
const TOUCHING: (&str, &str) = scenario_file!("belt-touching.toml");
const FAST: (&str, &str) = scenario_file!("belt-fast.toml");

/// The built-in scenes, in reading order.
pub fn builtins() -> Vec<Builtin> {
    vec![
        Builtin::new(
            "belt-textbook",
            (
                "The textbook oscillator: stick, then one harmonic slip",
                "The stick condition of the paper with another forcing: the spring force grows \
                 with the position while the belt carries the block.",
            ),
            TEXTBOOK,
            "The lab set-up: position and speed over three cycles with the belt's speed, and \
             the phase portrait, one harmonic arc about x_d closed by the stick at v = v_b.",
            &[
                BeltFigure::Motion { cycles: 3.0 },
                BeltFigure::PhasePortrait,
            ],
            &[],
        ),
        Builtin::new(
            "belt-touching",
            (
                "μd = μs: an oscillation that touches the belt's speed",
                "With equal coefficients the stick lasts no time: the boundary case of every \
                 closed form, where the period becomes the harmonic one.",
            ),
            TOUCHING,
            "Equal coefficients: the arc is centred on x_s, the block returns there at the \
             belt's speed and slips again at once; the phase portrait is a full ellipse.",
            &[
                BeltFigure::Motion { cycles: 3.0 },
                BeltFigure::PhasePortrait,
            ],
            &[],
        ),
        Builtin::new(
            "belt-fast",
            (
                "A fast belt: long slips, a short stick",
                "The belt's speed sets the amplitude of the slip and shortens the stick: the \
                 period is an output of the motion, not of a forcing.",
            ),
            FAST,
            "The belt ten times faster: the slip swings far past x_d and the stick is a small \
             share of the cycle.",
            &[
                BeltFigure::Motion { cycles: 3.0 },
                BeltFigure::PhasePortrait,
            ],
            &[],
        ),
    ]
}
