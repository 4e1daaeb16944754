//! The belt's regime map in the (μd, v_b) plane, cell by cell from the closed forms (no
//! integration: they are exact for this system, docs/belt.md): the share of the cycle the block
//! spends stuck, t_stick/T = u/(u + π − arctan u) with u = ωΔ/v_b (B12), in three bands, the
//! touching oscillation (μd = μs) and the forbidden μd > μs. The explorer page draws these cells.

use super::formula::{self, Regime};
use super::BeltParams;

/// The map's categories, in the order of [`category`]: legend label and fill.
pub const CATEGORIES: [(&str, usize); 5] = [
    ("μd > μs (not allowed)", 7),
    ("touching oscillation (the line μd = μs)", 3),
    ("stuck < 10 % of the cycle", 1),
    ("stuck 10–50 % of the cycle", 4),
    ("stuck ≥ 50 % of the cycle", 2),
];

/// The stick shares that separate the bands of [`CATEGORIES`].
pub const SHARE_BANDS: [f64; 2] = [0.1, 0.5];

/// The upper ends of the map's axes around `p` (the lower ends are 0): μd to 1.2 μs, so that
/// the line μd = μs and the forbidden side show, and v_b to 3 v_b.
pub fn top(p: &BeltParams) -> (f64, f64) {
    (1.2 * p.mu_s, 3.0 * p.v_b)
}

/// The category of the set `p` with μd = `mu_d` and v_b = `v_b` (closed forms).
pub fn category(p: &BeltParams, mu_d: f64, v_b: f64) -> u8 {
    if mu_d > p.mu_s {
        return 0;
    }
    let c = formula::evaluate(&BeltParams { mu_d, v_b, ..*p });
    if c.regime == Regime::TouchingOscillation {
        return 1;
    }
    match c.stick_share {
        s if s < SHARE_BANDS[0] => 2,
        s if s < SHARE_BANDS[1] => 3,
        _ => 4,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::belt::results::evaluate;

    #[test]
    fn each_category_is_where_the_exact_integration_puts_the_set() {
        let p = BeltParams::default();
        let (mu_top, v_top) = top(&p);
        let mut seen = [false; CATEGORIES.len()];
        for i in 0..12 {
            for j in 0..12 {
                let (mu_d, v_b) = (
                    mu_top * (f64::from(i) + 0.5) / 12.0,
                    v_top * (f64::from(j) + 0.5) / 12.0,
                );
                let cell = category(&p, mu_d, v_b);
                seen[usize::from(cell)] = true;
                let q = BeltParams { mu_d, v_b, ..p };
                let Ok(e) = evaluate(&q, 4) else {
                    assert_eq!(cell, 0, "{q:?} refused but mapped as {cell}");
                    continue;
                };
                let share = e.integration.stick_share.unwrap();
                let want = match share {
                    s if s < SHARE_BANDS[0] => 2,
                    s if s < SHARE_BANDS[1] => 3,
                    _ => 4,
                };
                assert_eq!(cell, want, "{q:?}: stuck {share} of the cycle");
            }
        }
        // The grid crosses the three bands and the forbidden side.
        assert_eq!(seen, [true, false, true, true, true]);
    }

    #[test]
    fn equal_coefficients_are_the_touching_category() {
        let p = BeltParams::default();
        assert_eq!(category(&p, p.mu_s, p.v_b), 1);
        assert_eq!(category(&p, 1.01 * p.mu_s, p.v_b), 0);
    }
}
