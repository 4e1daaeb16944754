//! The transcendental functions of the engine and the closed forms, from the `libm` crate on
//! every target, so that the command line (x86-64, where `f64::cos` is the C library's) and the
//! explorer page (wasm32, where it is Rust's own) compute the same bits: the page's numbers are
//! those of `stickslip eval … --json` to the last digit. `sqrt` and the arithmetic are IEEE
//! correctly rounded everywhere and stay `f64` methods.

/// sin x.
pub fn sin(x: f64) -> f64 {
    libm::sin(x)
}

/// cos x.
pub fn cos(x: f64) -> f64 {
    libm::cos(x)
}

/// (sin x, cos x), each the same bits as [`sin`] and [`cos`].
pub fn sin_cos(x: f64) -> (f64, f64) {
    (libm::sin(x), libm::cos(x))
}

/// arccos x.
pub fn acos(x: f64) -> f64 {
    libm::acos(x)
}

/// arcsin x.
pub fn asin(x: f64) -> f64 {
    libm::asin(x)
}

/// arctan x.
pub fn atan(x: f64) -> f64 {
    libm::atan(x)
}

/// atan2(y, x), the angle of the point (x, y) in (−π, π].
pub fn atan2(y: f64, x: f64) -> f64 {
    libm::atan2(y, x)
}

/// log₁₀ x.
pub fn log10(x: f64) -> f64 {
    libm::log10(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agree_with_std_to_an_ulp() {
        for i in 1..1000 {
            let x = f64::from(i) * 0.0123 - 6.0;
            let ulp = |a: f64, b: f64| (a - b).abs() <= 2.0 * f64::EPSILON * a.abs().max(1e-300);
            assert!(
                ulp(sin(x), x.sin()) || (sin(x) - x.sin()).abs() < 1e-16,
                "{x}"
            );
            assert!(
                ulp(cos(x), x.cos()) || (cos(x) - x.cos()).abs() < 1e-16,
                "{x}"
            );
            assert_eq!(sin_cos(x), (sin(x), cos(x)));
            let u = x / 6.5;
            assert!(
                ulp(acos(u), u.acos()) && (asin(u) - u.asin()).abs() <= 4e-16,
                "{u}"
            );
            assert!(ulp(log10(x.abs()), x.abs().log10()), "{x}");
        }
    }
}
