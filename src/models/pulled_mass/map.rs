//! The pulled mass's domain maps in the (μd, μs) plane (Fig. 9), cell by cell: the categories of
//! each law with their legend labels and fills, the map's range, and the category of one cell.
//! The report's maps (`scene.rs`) and the explorer page draw the same cells.

use crate::engine::{analyse, integrate, IntegrationRegime, RunOptions};
use crate::models::pulled_mass::formula::{self as cf, Regime};
use crate::models::pulled_mass::PulledMassParams;
use crate::models::{pulled_mass, LawKind};

/// Periods integrated per map cell: enough to see a late stick and a settled orbit.
pub const MAP_PERIODS: u32 = 6;

/// The categories of the linearized law's map (closed forms, guide §9), in the order of
/// [`linear_category`]: legend label and fill.
pub const LINEAR_CATEGORIES: [(&str, usize); 5] = [
    ("μd > μs (not allowed)", 7),
    ("immediate continuous slip", 3),
    ("continuous slip", 1),
    ("late stick (next period)", 4),
    ("slip-stick within the period (20)", 2),
];

/// The categories of the harmonic law's map (exact integration), in the order of
/// [`harmonic_category`].
pub const HARMONIC_CATEGORIES: [(&str, usize); 5] = [
    ("μd > μs (not allowed)", 7),
    ("immediate continuous slip", 3),
    ("continuous slip", 1),
    ("sticks once per period", 2),
    ("other (not periodic)", 6),
];

/// The upper end of both axes of the maps for φ = F/W (the lower end is 0).
pub fn top(phi: f64) -> f64 {
    (2.2 * phi).max(0.1)
}

/// Category of a (μd, μs) cell for the linearized law (closed form, guide §9).
pub fn linear_category(phi: f64, mu_s: f64, mu_d: f64) -> u8 {
    if mu_d > mu_s {
        return 0;
    }
    match cf::regime(phi, mu_s, mu_d) {
        Regime::ImmediateContinuousSlip => 1,
        Regime::ContinuousSlip => 2,
        Regime::SlipStickLate => 3,
        Regime::SlipStick => 4,
    }
}

/// Category of a (μd, μs) cell for the harmonic law (exact integration).
pub fn harmonic_category(p: &PulledMassParams, mu_s: f64, mu_d: f64) -> u8 {
    if mu_d > mu_s {
        return 0;
    }
    let q = PulledMassParams { mu_s, mu_d, ..*p };
    let Ok(law) = pulled_mass::force_law(&q, LawKind::Harmonic) else {
        return 4;
    };
    let opts = RunOptions {
        periods: MAP_PERIODS,
        record_segments: false,
        dissipation: false,
    };
    match integrate(&pulled_mass::body(&q), &law, &opts) {
        Ok(run) if run.immediate_slip => 1,
        Ok(run) => match analyse(&run).regime() {
            IntegrationRegime::ContinuousSlip => 2,
            IntegrationRegime::SingleSlipStick | IntegrationRegime::DoubleSlipNoHalt => 3,
            _ => 4,
        },
        Err(_) => 4,
    }
}
