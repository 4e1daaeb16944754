//! Number formatting shared by the terminal output and the reports.

use crate::fmath;

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
    let exponent = fmath::log10(x.abs()).floor() as i32;
    if (-3..6).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{:.*e}", digits.saturating_sub(1), x)
    }
}

/// `x` to at most `digits` significant digits without the zeros after the last significant one
/// (`0.5886`, `1.5e-5`, never `0.5886000000`): the terminal's numbers; "—" for a missing value.
pub fn short(x: Option<f64>, digits: usize) -> String {
    let text = sig(x, digits);
    match text.split_once('e') {
        Some((mantissa, exponent)) => format!("{}e{exponent}", trim_zeros(mantissa)),
        None => trim_zeros(&text).to_string(),
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

/// A number for people: `digits` significant figures without trailing zeros, plain for
/// 1e-3 ≤ |x| < 1e6, else `m × 10ⁿ` with a superscript exponent (never `5.4e-4`); "—" for a
/// missing value.
pub fn people(x: Option<f64>, digits: usize) -> String {
    let text = sig(x, digits);
    match text.split_once('e') {
        Some((mantissa, exponent)) => times_ten(trim_zeros(mantissa), exponent),
        None if text.contains('.') => trim_zeros(&text).to_string(),
        None => text,
    }
}

/// `x` to `digits` significant figures, zeros kept (`2.610`), plain for 1e-3 ≤ |x| < 1e6, else
/// `9.526 × 10⁻⁴` (never `9.526e-4`): an answer stated to its figures; "—" for a missing value.
pub fn figures(x: Option<f64>, digits: usize) -> String {
    let text = sig(x, digits);
    match text.split_once('e') {
        Some((mantissa, exponent)) => times_ten(mantissa, exponent),
        None => text,
    }
}

/// A relative error for people: two figures, `3.0 × 10⁻¹⁶`; "0" and "—" as they are.
pub fn people_rel(x: Option<f64>) -> String {
    let text = rel(x);
    match text.split_once('e') {
        Some((mantissa, exponent)) => times_ten(mantissa, exponent),
        None => text,
    }
}

/// A tolerance for people: `10⁻⁹`, or `2 × 10⁻⁷`.
pub fn people_tolerance(x: f64) -> String {
    let text = format!("{x:.0e}");
    match text.split_once('e') {
        Some(("1", exponent)) => format!("10{}", superscript(exponent)),
        Some((mantissa, exponent)) => times_ten(mantissa, exponent),
        None => text,
    }
}

/// `mantissa × 10^exponent`, the exponent in superscript digits; `10ⁿ` alone for mantissa 1.
fn times_ten(mantissa: &str, exponent: &str) -> String {
    format!("{mantissa} × 10{}", superscript(exponent))
}

/// Decimal digits without the zeros after the last significant one (and without a bare '.').
fn trim_zeros(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

fn superscript(exponent: &str) -> String {
    exponent
        .chars()
        .map(|c| match c {
            '-' => '⁻',
            '0' => '⁰',
            '1' => '¹',
            '2' => '²',
            '3' => '³',
            '4' => '⁴',
            '5' => '⁵',
            '6' => '⁶',
            '7' => '⁷',
            '8' => '⁸',
            '9' => '⁹',
            other => other,
        })
        .collect()
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

    #[test]
    fn numbers_for_people_have_no_trailing_zeros_and_no_e_notation() {
        assert_eq!(people(Some(0.058_86), 8), "0.05886");
        assert_eq!(people(Some(5.396_970_576e-4), 8), "5.3969706 × 10⁻⁴");
        assert_eq!(people(Some(45.0), 8), "45");
        assert_eq!(people(Some(2.285_714_285_7), 8), "2.2857143");
        assert_eq!(people(Some(1.5e7), 4), "1.5 × 10⁷");
        assert_eq!(people(Some(-0.25), 4), "-0.25");
        assert_eq!(people(Some(0.0), 4), "0");
        assert_eq!(people(None, 4), "—");
        assert_eq!(people_rel(Some(3.0e-16)), "3.0 × 10⁻¹⁶");
        assert_eq!(people_rel(Some(0.0)), "0");
        assert_eq!(people_tolerance(1e-9), "10⁻⁹");
        assert_eq!(people_tolerance(2e-7), "2 × 10⁻⁷");
    }
}
