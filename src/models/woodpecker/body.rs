//! The falling woodpecker's sleeve (guide §5.2 and guide §8): y positive downward, M = m_S,
//! D = W_S + F_e(t), N_f = 2λ|F_e(t)|, with the spring force F_e = k z(t) on the sleeve.
//!
//! ```text
//! harmonic:  z(t) = z0 + d0 cos ωt                                           guide §5.2
//! linear:    z(t) = δ0 + ζ(t),  ζ = ζ0 (1 − t/τ) on [0, 2τ], ζ0 (t/τ − 3) on [2τ, 4τ]  (37)
//! ```
//! The zero crossings of F_e, where |F_e| has a kink, are breakpoints of the force law.

use crate::engine::{Affine, Basis, Body, ForceLaw, Piece};
use crate::error::{Error, Result};
use crate::fmath;
use crate::models::woodpecker::formula::{self as formula, counterpart};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;

/// The sleeve: M = m_S, μs, μd.
pub fn body(p: &WoodpeckerParams) -> Body {
    Body {
        mass: p.m_sleeve,
        mu_s: p.mu_s,
        mu_d: p.mu_d,
    }
}

/// (ζ0, δ0) of the linear counterpart chosen in `p` (m), if it is defined for z0, d0.
pub fn linear_amplitudes(p: &WoodpeckerParams) -> Option<(f64, f64)> {
    counterpart(p.z0, p.d0, p.counterpart)
}

/// The force law of the sleeve for the chosen law, refused where the slips are too short for
/// double precision ([`WoodpeckerParams::check_resolution`]). The linear law needs a defined
/// counterpart.
pub fn force_law(p: &WoodpeckerParams, law: LawKind) -> Result<ForceLaw> {
    p.check_resolution()?;
    match law {
        LawKind::Harmonic => harmonic(p),
        LawKind::Linear => {
            let (zeta0, delta0) = linear_amplitudes(p).ok_or_else(|| {
                Error::InvalidLaw(format!(
                    "the {} counterpart needs |z0| <= d0 (z0 = {}, d0 = {})",
                    p.counterpart.id(),
                    crate::error::short(p.z0),
                    crate::error::short(p.d0)
                ))
            })?;
            linear(p, zeta0, delta0)
        }
    }
}

/// Pieces for the spring force F_e = f0 + f1 b(t) on [start, end), with N_f = 2λ|F_e|: the
/// sign of F_e is read at the middle of the piece (it does not change inside).
fn piece(p: &WoodpeckerParams, start: f64, end: f64, basis: Basis, spring: Affine) -> Piece {
    let sign = spring.at(basis.eval(0.5 * (start + end))).signum();
    let friction = 2.0 * p.lambda() * sign;
    Piece {
        start,
        end,
        basis,
        drive: Affine::new(p.sleeve_weight() + spring.c0, spring.c1),
        normal: Affine::new(friction * spring.c0, friction * spring.c1),
    }
}

fn harmonic(p: &WoodpeckerParams) -> Result<ForceLaw> {
    let (omega, period) = (p.omega(), p.period());
    let mut cuts = vec![0.0];
    let (basis, spring) = if p.z0.abs() < p.d0 {
        // F_e = 0 where cos ωt = C = −z0/d0: written about that level, F_e = k d0 (cos ωt − C),
        // so that D = W_S + F_e keeps W_S as its own coefficient. As W_S + k z0 + k d0 cos ωt,
        // W_S carried the rounding of k z0 and the zero of F_e that of both terms (eps·k d0),
        // an error of eps/ε in slips of relative length ε = W_S/(k d0).
        let level = -p.z0 / p.d0;
        let t1 = fmath::acos(level) / omega;
        cuts.extend([t1, period - t1]);
        (
            Basis::Cos {
                omega,
                shift: level,
            },
            Affine::new(0.0, p.k * p.d0),
        )
    } else {
        (
            Basis::Cos { omega, shift: 0.0 },
            Affine::new(p.k * p.z0, p.k * p.d0),
        )
    };
    cuts.push(period);
    let pieces = cuts
        .windows(2)
        .map(|w| piece(p, w[0], w[1], basis, spring))
        .collect();
    ForceLaw::new(period, pieces)
}

fn linear(p: &WoodpeckerParams, zeta0: f64, delta0: f64) -> Result<ForceLaw> {
    let period = p.period();
    let tau = 0.25 * period;
    let slope = p.k * zeta0 / tau;
    let halves = [(0.0, 2.0 * tau, -slope), (2.0 * tau, period, slope)];
    let mut pieces = Vec::with_capacity(4);
    for (start, end, rate) in halves {
        // Reference time: the zero of F_e in this half (t0^(I) = τ(1 + δ0/ζ0), t0^(II) =
        // τ(3 − δ0/ζ0)) when there is one, so that F_e vanishes exactly there.
        let at_start = p.k * (delta0 + if start == 0.0 { zeta0 } else { -zeta0 });
        let zero = start - at_start / rate;
        if zero > start && zero < end {
            let spring = Affine::new(0.0, rate);
            let basis = Basis::Linear { t_ref: zero };
            pieces.push(piece(p, start, zero, basis, spring));
            pieces.push(piece(p, zero, end, basis, spring));
        } else {
            let spring = Affine::new(at_start, rate);
            pieces.push(piece(p, start, end, Basis::Linear { t_ref: start }, spring));
        }
    }
    ForceLaw::new(period, pieces)
}

/// The spring coordinate z(t) (m) of the chosen law, for figures and y_W = y_S + z.
pub fn spring_coordinate(p: &WoodpeckerParams, law: LawKind, t: f64) -> Option<f64> {
    match law {
        LawKind::Harmonic => Some(p.z0 + p.d0 * fmath::cos(p.omega() * t)),
        LawKind::Linear => {
            let (zeta0, delta0) = linear_amplitudes(p)?;
            formula::spring_coordinate(t, 0.25 * p.period(), zeta0).map(|zeta| delta0 + zeta)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::woodpecker::formula::Counterpart;

    #[test]
    fn laws_follow_the_spring_coordinate_and_split_at_its_zeros() {
        let p = WoodpeckerParams::default();
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let f = force_law(&p, law).unwrap();
            assert_eq!(f.pieces.len(), if law == LawKind::Linear { 4 } else { 3 });
            for i in 0..50 {
                let t = p.period() * f64::from(i) / 50.0;
                let fe = p.k * spring_coordinate(&p, law, t).unwrap();
                let lam = p.lambda();
                assert!(
                    (f.drive(t) - (p.sleeve_weight() + fe)).abs() < 1e-15,
                    "{law:?} D at {t}"
                );
                assert!(
                    (f.normal(t) - 2.0 * lam * fe.abs()).abs() < 1e-14,
                    "{law:?} N at {t}"
                );
            }
        }
    }

    #[test]
    fn linear_zero_crossings_are_the_papers_t0() {
        let p = WoodpeckerParams {
            counterpart: Counterpart::Extremes,
            ..WoodpeckerParams::default()
        };
        let f = force_law(&p, LawKind::Linear).unwrap();
        let tau = 0.25 * p.period();
        // (40), (57): t0^(I) = τ(1 + δ0/ζ0), t0^(II) = τ(3 − δ0/ζ0) with δ0 = 7, ζ0 = 9 mm.
        assert!((f.pieces[1].start - tau * (1.0 + 7.0 / 9.0)).abs() < 1e-16);
        assert!((f.pieces[3].start - tau * (3.0 - 7.0 / 9.0)).abs() < 1e-16);
    }

    #[test]
    fn a_spring_that_never_changes_sign_gives_one_piece_per_half() {
        let p = WoodpeckerParams {
            z0: 0.012,
            counterpart: Counterpart::Extremes,
            ..WoodpeckerParams::default()
        };
        assert_eq!(force_law(&p, LawKind::Harmonic).unwrap().pieces.len(), 1);
        assert_eq!(force_law(&p, LawKind::Linear).unwrap().pieces.len(), 2);
        let zeros = WoodpeckerParams {
            counterpart: Counterpart::Zeros,
            ..p
        };
        assert!(force_law(&zeros, LawKind::Linear).is_err());
    }
}
