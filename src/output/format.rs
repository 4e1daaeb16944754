//! Number formatting shared by the terminal output and the reports.

/// `x` to `digits` significant digits: plain decimals for 1e-3 ≤ |x| < 1e6, scientific
/// otherwise; "—" for a missing value.
pub fn sig(x: Option<f64>, digits: usize) -> String {
    let Some(x) = x else {
        return "—".to_string();
    };
    if x == 0.0 {
        return "0".to_string();
    }
    if !x.is_finite() {
        return x.to_string();
    }
    let exponent = x.abs().log10().floor() as i32;
    if (-3..6).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{:.*e}", digits.saturating_sub(1), x)
    }
}

/// A relative error in scientific notation with two digits ("—" when missing).
pub fn rel(x: Option<f64>) -> String {
    match x {
        Some(0.0) => "0".to_string(),
        Some(x) => format!("{x:.1e}"),
        None => "—".to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(sig(Some(0.229_429_488), 7), "0.2294295");
        assert_eq!(sig(Some(45.0), 4), "45.00");
        assert_eq!(sig(Some(5.396_970_576e-4), 4), "5.397e-4");
        assert_eq!(sig(None, 4), "—");
        assert_eq!(rel(Some(3.2e-14)), "3.2e-14");
    }
}
