//! The woodpecker's regime maps in the (μd, z0) plane, cell by cell: the categories (a regime of
//! the integration, an orbit regime of the closed forms, or a failed integration), the map's
//! ranges, and the regime of one cell under either law. The report's maps
//! (`scene.rs`) and the explorer page draw the same cells.

use crate::engine::{analyse, integrate, IntegrationRegime, RunOptions};
use crate::models::woodpecker::formula::{self as cf, OrbitRegime};
use crate::models::woodpecker::results::linear_inputs;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};

/// Periods integrated per cell of the harmonic regime map.
pub const MAP_PERIODS: u32 = 8;
/// Smallest μd of the regime maps; the largest is μs.
pub const MAP_MU_D_MIN: f64 = 0.05;
/// z0 range of the regime maps in units of d0.
pub const MAP_Z0: (f64, f64) = (-0.5, 0.99);

/// The ranges of the maps of `p`: μd, and z0 in m.
pub fn ranges(p: &WoodpeckerParams) -> ((f64, f64), (f64, f64)) {
    (
        (MAP_MU_D_MIN.min(0.5 * p.mu_s), p.mu_s),
        (MAP_Z0.0 * p.d0, MAP_Z0.1 * p.d0),
    )
}

/// A category of the regime maps: a regime of the integration (an orbit of the closed forms that
/// is one takes its category, so that the same regime is one category on both maps), an orbit
/// regime the integration has no name for, or a failed integration.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Category {
    Integrated(IntegrationRegime),
    Orbit(OrbitRegime),
    Failed,
}

impl Category {
    /// The category of a closed-form orbit regime.
    pub fn orbit(r: OrbitRegime) -> Self {
        r.integrated()
            .map_or(Category::Orbit(r), Category::Integrated)
    }
}

/// The categories of both maps, in legend order: legend label and fill. The same regime has the
/// same fill on both maps (and continuous motion the same fill, whichever regime names it).
pub const REGIMES: [(Category, &str, usize); 10] = [
    (
        Category::Integrated(IntegrationRegime::DoubleSlipStick),
        "2 slips, 2 sticks",
        2,
    ),
    (
        Category::Integrated(IntegrationRegime::DoubleSlipNoHalt),
        "1 slip, 2 maxima",
        4,
    ),
    (
        Category::Integrated(IntegrationRegime::SingleSlipStick),
        "1 slip, 1 maximum",
        5,
    ),
    (
        Category::Orbit(OrbitRegime::ContinuousOrMultiperiod),
        "no halt (continuous)",
        3,
    ),
    (
        Category::Integrated(IntegrationRegime::ContinuousSlip),
        "continuous slip",
        3,
    ),
    (
        Category::Integrated(IntegrationRegime::ContinuousSlipReversing),
        "continuous slip, reversing",
        3,
    ),
    (
        Category::Integrated(IntegrationRegime::Multiperiod),
        "multi-period orbit",
        1,
    ),
    (
        Category::Integrated(IntegrationRegime::NotPeriodic),
        "not periodic",
        7,
    ),
    (
        Category::Integrated(IntegrationRegime::NoSlip),
        "never slips",
        6,
    ),
    (Category::Failed, "integration failed", 0),
];

/// Index of a category in [`REGIMES`] (one not listed counts as failed).
pub fn regime_index(category: Category) -> u8 {
    let i = REGIMES
        .iter()
        .position(|r| r.0 == category)
        .unwrap_or(REGIMES.len() - 1);
    i as u8
}

/// Regime of the linear orbit from the closed forms (guide §8.6); outside their domain, from the exact
/// integration of the linear law, so that no part of the map is left without a regime.
pub fn linear_cell(p: &WoodpeckerParams, mu_d: f64, z0: f64) -> u8 {
    let q = WoodpeckerParams { mu_d, z0, ..*p };
    match cf::evaluate(&linear_inputs(&q)).regime {
        OrbitRegime::OutsideClosedFormDomain => {
            integrated_cell(p, LawKind::Linear, mu_d, z0, MAP_PERIODS)
        }
        regime => regime_index(Category::orbit(regime)),
    }
}

/// Regime of the law `kind` by exact integration over `periods` periods.
pub fn integrated_cell(
    p: &WoodpeckerParams,
    kind: LawKind,
    mu_d: f64,
    z0: f64,
    periods: u32,
) -> u8 {
    let q = WoodpeckerParams { mu_d, z0, ..*p };
    let opts = RunOptions {
        periods,
        record_segments: false,
        dissipation: false,
    };
    let run = woodpecker::force_law(&q, kind)
        .and_then(|law| integrate(&woodpecker::body(&q), &law, &opts));
    match run {
        Ok(run) => regime_index(Category::Integrated(analyse(&run).regime())),
        Err(_) => regime_index(Category::Failed),
    }
}
