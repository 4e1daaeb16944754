//! `stickslip sweep`: one parameter of a model varied on a uniform grid; at each point each of
//! the model's laws ([`Present::LAWS`]) is integrated exactly (v̄, slips and sticks per period, regime) next to the closed-form
//! regime — the paper's remark that the double slip-stick is "critically related with small
//! changes of the parameters", made visible.
//!
//! ```text
//! base params (flags / scenario) + grid (param, from, to, steps)
//!     → points in parallel (rayon), each an independent evaluation
//!     → render (sweep.csv, sweep.svg, one-line summary)  → report::write_all
//! ```
//!
//! A grid point whose parameter set is invalid (e.g. μd > μs mid-sweep) is kept as an
//! "invalid" row; only a sweep that cannot be set up (unknown parameter, bad range) is an error.

mod render;

use indicatif::ProgressBar;
use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::models::param::{invalid, num};
use crate::models::{with_capability, with_model, Capability, Model, Physics};
pub use crate::present::vocab::LawPoint;
use crate::present::vocab::{Column, LawName};
use crate::present::Present;

pub use render::{render, summary_line};

/// Fewest and most grid points.
pub const MIN_STEPS: u32 = 2;
pub const MAX_STEPS: u32 = 100_000;
/// Largest --steps × --periods: the periods one sweep integrates (10^7: ten times the longest
/// `eval`; at the slowest, about a minute of CPU).
pub const MAX_PERIODS_INTEGRATED: u64 = 10_000_000;

/// A numeric parameter that can be swept: its name, CSV unit suffix, axis label and the factor
/// from SI to the axis unit (from the model's parameter descriptor).
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    pub name: &'static str,
    /// Unit as a CSV suffix ("m", "kg", "N_m"); empty for dimensionless parameters.
    pub unit: String,
    /// Unit as written in messages ("m", "N/m"); empty for dimensionless parameters.
    pub unit_text: &'static str,
    pub axis_label: String,
    pub axis_scale: f64,
}

/// The parameters `model` can sweep: every numeric parameter.
pub fn params(model: &Model) -> Vec<Param> {
    fn of<M: Physics>(_: &M) -> Vec<Param> {
        M::PARAMS
            .iter()
            .map(|s| Param {
                name: s.key,
                unit: s.csv_unit(),
                unit_text: s.unit,
                axis_label: s.axis_label(),
                axis_scale: s.display.1,
            })
            .collect()
    }
    with_model!(model, p => of(p))
}

/// What the user asked to sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct GridSpec {
    pub param: String,
    pub from: f64,
    pub to: f64,
    pub steps: u32,
    /// Periods integrated at each point.
    pub periods: u32,
}

/// One grid point: `None` laws when the parameter set is invalid (or when a law does not
/// exist for the parameters).
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    pub value: f64,
    /// Why the point is invalid, if it is.
    pub invalid: Option<Error>,
    /// Each law of [`Sweep::laws`], in its order.
    pub laws: Vec<Option<LawPoint>>,
    pub closed_form: Option<&'static str>,
    /// The model's own quantities, in the order of [`Sweep::columns`] (empty at an invalid
    /// point).
    pub own: Vec<Option<f64>>,
}

/// A finished sweep.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub model: &'static str,
    /// The model's laws, in the order of [`Point::laws`].
    pub laws: &'static [LawName],
    /// The model's own quantities, in the order of [`Point::own`].
    pub columns: Vec<Column>,
    pub param: Param,
    pub spec: GridSpec,
    pub points: Vec<Point>,
}

/// The grid `stickslip sweep` runs for `model` when no model is named ([`Present::SWEEP`]),
/// integrating `periods` at each point; `None` for a model that cannot sweep yet.
pub fn default_spec(model: &Model, periods: u32) -> Option<GridSpec> {
    fn of<M: Present>(_: &M, periods: u32) -> GridSpec {
        GridSpec {
            param: M::SWEEP.param.to_string(),
            from: M::SWEEP.from,
            to: M::SWEEP.to,
            steps: M::SWEEP.steps,
            periods,
        }
    }
    with_capability!(model, present, p => Some(of(p, periods)), else None)
}

/// Checks the grid request against the model: a known parameter, finite distinct ends, and
/// [`MIN_STEPS`] ≤ steps ≤ [`MAX_STEPS`].
pub fn validate(base: &Model, spec: &GridSpec) -> Result<Param> {
    let known = params(base);
    let Some(param) = known.iter().find(|p| p.name == spec.param) else {
        let names: Vec<_> = known.iter().map(|p| p.name).collect();
        return Err(invalid(
            "param",
            &spec.param,
            format!("param in {{{}}} ({})", names.join(", "), base.id()),
        ));
    };
    for (name, value) in [("from", spec.from), ("to", spec.to)] {
        if !value.is_finite() {
            return Err(invalid(
                name,
                num(value),
                format!("-inf < {name} < inf ({} values)", param.name),
            ));
        }
    }
    if spec.from == spec.to {
        return Err(invalid(
            "to",
            num(spec.to),
            format!("to != from = {} (sweep of {})", num(spec.from), param.name),
        ));
    }
    if !(MIN_STEPS..=MAX_STEPS).contains(&spec.steps) {
        return Err(invalid(
            "steps",
            spec.steps,
            format!("{MIN_STEPS} <= steps <= {MAX_STEPS}"),
        ));
    }
    crate::params::validate_periods(spec.periods)?;
    for (name, value) in [("from", spec.from), ("to", spec.to)] {
        // The figure's axis is in the display unit: its value must stay a double too.
        if !(value * param.axis_scale).is_finite() {
            return Err(invalid(
                name,
                num(value),
                format!(
                    "|{name}| <= {} ({} on the figure's axis in {})",
                    num(f64::MAX / param.axis_scale),
                    param.name,
                    param.axis_label
                ),
            ));
        }
    }
    let work = u64::from(spec.steps) * u64::from(spec.periods);
    if work > MAX_PERIODS_INTEGRATED {
        return Err(invalid(
            "steps",
            spec.steps,
            format!(
                "--steps x --periods <= {MAX_PERIODS_INTEGRATED} (periods integrated by one sweep; \
                 here {} x {} = {work})",
                spec.steps, spec.periods
            ),
        ));
    }
    Ok(param.clone())
}

/// The i-th of `n` uniform grid values from `from` to `to`, both ends exact. Near the top of
/// the double range `to - from` (or its product with `i`) overflows: then the weighted mean,
/// which stays between the ends.
pub fn grid_value(from: f64, to: f64, i: u32, n: u32) -> f64 {
    if i + 1 == n {
        return to;
    }
    if i == 0 {
        return from;
    }
    let step = (to - from) / f64::from(n - 1);
    let value = from + step * f64::from(i);
    if value.is_finite() {
        return at_resolution(value, step.abs());
    }
    let t = f64::from(i) / f64::from(n - 1);
    from * (1.0 - t) + to * t
}

/// `value` rounded to a millionth of the grid's `step`, in decimal: the shortest digits that
/// tell the point from its neighbours, without the float noise of `from + step × i`
/// (0.0048, not 0.0048000000000000004). Unchanged when the step is not a positive finite number
/// or too coarse for decimals.
fn at_resolution(value: f64, step: f64) -> f64 {
    if !(step.is_finite() && step > 0.0) {
        return value;
    }
    let decimals = 6 - crate::fmath::log10(step).floor() as i32;
    if !(0..=300).contains(&decimals) {
        return value;
    }
    let decimals = decimals as usize;
    format!("{value:.decimals$}").parse().unwrap_or(value)
}

/// Runs the sweep in parallel over the grid, ticking `progress` once per point.
///
/// Errors: the request fails [`validate`]; every point is invalid (the first point's error is
/// returned, so that a bad fixed parameter is named); or the engine fails at some point.
pub fn run(base: &Model, spec: &GridSpec, progress: &ProgressBar) -> Result<Sweep> {
    base.require(Capability::Present)?;
    let param = validate(base, spec)?;
    let points = (0..spec.steps)
        .into_par_iter()
        .map(|i| {
            let value = grid_value(spec.from, spec.to, i, spec.steps);
            let mut model = *base;
            model.set(param.name, value);
            let point = evaluate_point(&model, value, spec.periods);
            progress.inc(1);
            point
        })
        .collect::<Result<Vec<_>>>()?;
    progress.finish_and_clear();
    // No valid point: a fixed parameter is bad, or the whole range is; say why at the first.
    let all_invalid = points.iter().all(|p| p.invalid.is_some());
    if let Some(first) = points.first().and_then(|p| p.invalid.clone()) {
        if all_invalid {
            return Err(first);
        }
    }
    fn laws<M: Present>(_: &M) -> (&'static [LawName], Vec<Column>) {
        let columns = M::sweep_columns().into_iter().map(|c| c.head).collect();
        (M::LAWS, columns)
    }
    let (laws, columns): (&[LawName], _) =
        with_capability!(base, present, p => laws(p), else (&[], Vec::new()));
    Ok(Sweep {
        model: base.id(),
        laws,
        columns,
        param,
        spec: spec.clone(),
        points,
    })
}

/// Evaluates one grid point; an invalid parameter set is a point, not an error.
fn evaluate_point(model: &Model, value: f64, periods: u32) -> Result<Point> {
    type Laws = (Vec<Option<LawPoint>>, &'static str, Vec<Option<f64>>);
    fn laws<M: Present>(p: &M, periods: u32) -> Result<Laws> {
        let e = p.evaluate(periods)?;
        let laws = M::laws(&e);
        let own = M::sweep_columns().iter().map(|c| (c.value)(&e)).collect();
        Ok((laws.runs, laws.closed_form_regime, own))
    }
    let evaluated = with_capability!(model, present, p => laws(p, periods),
        else return Err(model.missing(Capability::Present)));
    match evaluated {
        Ok((laws, closed, own)) => Ok(Point {
            value,
            invalid: None,
            laws,
            closed_form: Some(closed),
            own,
        }),
        // A point the model refuses, or (should it ever happen) one the engine cannot
        // advance, is a gap in the sweep, not the end of it.
        Err(
            e @ (Error::InvalidParam { .. }
            | Error::InvalidLaw(_)
            | Error::OutOfRange { .. }
            | Error::Stalled { .. }),
        ) => Ok(Point {
            value,
            invalid: Some(e),
            laws: Vec::new(),
            closed_form: None,
            own: Vec::new(),
        }),
        Err(e) => Err(e),
    }
}

#[cfg(test)]
mod tests {
    use super::grid_value;

    #[test]
    fn grid_points_read_as_short_decimals_at_the_grids_resolution() {
        for n in [7_u32, 300, 1000] {
            let (from, to) = (0.0027, 0.009);
            let step = (to - from) / f64::from(n - 1);
            let mut last = f64::NEG_INFINITY;
            for i in 0..n {
                let v = grid_value(from, to, i, n);
                let exact = from + step * f64::from(i);
                assert!((v - exact).abs() <= 1e-6 * step, "{n} {i}: {v} vs {exact}");
                assert!(v > last, "{n} {i}: not increasing");
                last = v;
                // At most 6 digits beyond the step's first: no 17-digit float noise.
                let digits = format!("{v}").trim_start_matches("0.").len();
                assert!(digits <= 12, "{n} {i}: {v}");
            }
        }
        assert_eq!(grid_value(0.0027, 0.009, 2, 7), 0.0048);
        assert_eq!(grid_value(0.0027, 0.009, 3, 7), 0.00585);
    }
}
