//! The pulled-pushed mass (guide §5.1): mass m pulled by F, pressed by N(t) = W(1 + cos ωt)
//! through a hanging mass m' = m on a spring; inertial mass M = 2m (eqs. 5, 14).
//!
//! ```text
//! harmonic:  D = F,  N_f = W (1 + cos ωt)                                   (8)
//! linear:    N_f = 2W (1 − 2t/T) on [0, T/2],  2W (2t/T − 1) on [T/2, T]    (Sec. 2.2)
//!            each quarter written about the vertex it touches (t = 0, T/2, T)
//! ```

use crate::engine::{Affine, Basis, Body, ForceLaw, Piece};
use crate::error::Result;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::LawKind;

/// The body: M = 2m, μs, μd.
pub fn body(p: &PulledMassParams) -> Body {
    Body {
        mass: 2.0 * p.mass,
        mu_s: p.mu_s,
        mu_d: p.mu_d,
    }
}

/// The force law of the pulled mass for the chosen law.
pub fn force_law(p: &PulledMassParams, law: LawKind) -> Result<ForceLaw> {
    let (w, period, omega) = (p.weight(), p.period(), p.omega());
    let drive = Affine::new(p.force, 0.0);
    let pieces = match law {
        LawKind::Harmonic => vec![Piece {
            start: 0.0,
            end: period,
            basis: Basis::Cos { omega, shift: 0.0 },
            drive,
            normal: Affine::new(w, w),
        }],
        LawKind::Linear => {
            // Each quarter is written about the vertex it touches, where the events that need
            // the digits happen: N = 2W ∓ (4W/T)(t − t_v) about t_v = 0 and T (the onsets of
            // φ → 2μs), N = ∓(4W/T)(t − T/2) about the zero at T/2 (the slips of a small φ).
            // Written about t = 0 across the half, 2W − (4W/T)t misplaces its zero by the
            // rounding of 4W/T (about eps·T): an error of eps·μs/φ in a slip of relative length
            // φ/μs. At T/4 and 3T/4 the two forms meet to rounding of N ≈ W.
            let half = 0.5 * period;
            let slope = 4.0 * w / period;
            let quarter = |start: f64, end: f64, t_ref: f64, normal: Affine| Piece {
                start,
                end,
                basis: Basis::Linear { t_ref },
                drive,
                normal,
            };
            vec![
                quarter(0.0, 0.25 * period, 0.0, Affine::new(2.0 * w, -slope)),
                quarter(0.25 * period, half, half, Affine::new(0.0, -slope)),
                quarter(half, 0.75 * period, half, Affine::new(0.0, slope)),
                quarter(0.75 * period, period, period, Affine::new(2.0 * w, slope)),
            ]
        }
    };
    ForceLaw::new(period, pieces)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_laws_share_the_extremes_of_the_normal_force() {
        let p = PulledMassParams::default();
        let w = p.weight();
        let t = p.period();
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let f = force_law(&p, law).unwrap();
            assert!((f.normal(0.0) - 2.0 * w).abs() < 1e-15);
            assert!(f.normal(0.5 * t).abs() < 1e-15);
            assert!((f.drive(0.3 * t) - p.force).abs() < 1e-15);
        }
        let lin = force_law(&p, LawKind::Linear).unwrap();
        assert!((lin.normal(0.25 * t) - w).abs() < 1e-15);
        assert!((lin.normal(0.75 * t) - w).abs() < 1e-15);
    }
}
