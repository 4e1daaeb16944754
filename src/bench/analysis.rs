//! Reading the sweep: the cost of reaching a given error on a work-precision curve, and the
//! fitted convergence order of the fixed-step methods.
//!
//! ```text
//! cost at error e:  Pareto front of (cost, error) by increasing cost; if its cheapest point is
//!                   already below e, that cost; else log-log interpolation between the two
//!                   front points that bracket e; else not reached.
//! fitted order p:   least-squares slope of log10 err against log10 h over the asymptotic range:
//!                   the ORDER_POINTS finest steps whose error is above the round-off floor.
//! ```

use serde::Serialize;

use super::sweep::SweepPoint;

/// Points of the asymptotic range of an order fit (two decades of h at half-decade spacing).
pub const ORDER_POINTS: usize = 5;
/// Errors below this fraction of the quantity's scale are round-off, not truncation.
pub const ROUNDOFF_REL: f64 = 1e-11;
/// The error levels at which costs are compared.
pub const LEVELS: [f64; 4] = [1e-4, 1e-6, 1e-8, 1e-10];

/// The error metrics of the sweep.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Metric {
    /// Max event-time error (s).
    EventTime,
    /// |x(t_end) − x_exact| (m).
    XEnd,
    /// |v̄ − v̄_exact| over the last period (m/s).
    VBar,
}

impl Metric {
    pub const ALL: [Metric; 3] = [Metric::EventTime, Metric::XEnd, Metric::VBar];

    /// Identifier used in JSON and CSV.
    pub fn id(self) -> &'static str {
        match self {
            Metric::EventTime => "event_time",
            Metric::XEnd => "x_end",
            Metric::VBar => "v_bar",
        }
    }

    /// Axis label of the log10 error, with its unit.
    pub fn axis_label(self) -> &'static str {
        match self {
            Metric::EventTime => "log10 max event-time error (s)",
            Metric::XEnd => "log10 error in x_end (m)",
            Metric::VBar => "log10 error in v̄ (m/s)",
        }
    }

    /// The error of a point in this metric; none for a run that found a different number of
    /// slips and sticks than the exact solution (a failure: it stays off the fronts, the costs
    /// and the order fits, and the failure table lists it).
    pub fn of(self, p: &SweepPoint) -> Option<f64> {
        if p.count_mismatch() {
            return None;
        }
        match self {
            Metric::EventTime => p.err_event_s,
            Metric::XEnd => p.err_x_m,
            Metric::VBar => p.err_vbar_m_s,
        }
    }
}

/// Cost needed to reach an error level, and whether the cheapest point already beat it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CostAt {
    pub cost: f64,
    /// The curve's cheapest point is already below the level (the cost is an upper bound).
    pub overshoot: bool,
}

/// Cost to reach `level` on the curve of (cost, error) points; `None` if never reached.
pub fn cost_at(points: &[(f64, f64)], level: f64) -> Option<CostAt> {
    let mut pts: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|(c, e)| c.is_finite() && *c > 0.0 && e.is_finite() && *e >= 0.0)
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    let mut front: Vec<(f64, f64)> = Vec::with_capacity(pts.len());
    for p in pts {
        if front.last().is_none_or(|l| p.1 < l.1) {
            front.push(p);
        }
    }
    let first = *front.first()?;
    if first.1 <= level {
        return Some(CostAt {
            cost: first.0,
            overshoot: true,
        });
    }
    let log = |x: f64| x.max(f64::MIN_POSITIVE).log10();
    front.windows(2).find_map(|w| {
        let ((c0, e0), (c1, e1)) = (w[0], w[1]);
        (e1 <= level).then(|| {
            let f = (log(level) - log(e0)) / (log(e1) - log(e0));
            CostAt {
                cost: 10f64.powf(log(c0) + f * (log(c1) - log(c0))),
                overshoot: false,
            }
        })
    })
}

/// A fitted convergence order of a fixed-step method on one problem and metric.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct OrderFit {
    pub problem: String,
    pub method: String,
    pub metric: Metric,
    /// Slope of log10 err against log10 h; `None` with fewer than 3 usable points.
    pub order: Option<f64>,
    /// The range of h fitted (s) and the number of points.
    pub h_min_s: Option<f64>,
    pub h_max_s: Option<f64>,
    pub points: usize,
}

/// Least-squares slope of y against x.
pub fn slope(points: &[(f64, f64)]) -> Option<f64> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let (sx, sy) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), p| (a + p.0, b + p.1));
    let (mx, my) = (sx / n, sy / n);
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.0 - mx) * (p.1 - my), b + (p.0 - mx).powi(2))
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// Fits the order of `method` on `problem` in `metric` from the sweep; `scale` is the size of
/// the quantity (|x_exact|, T, v̄) that sets the round-off floor.
pub fn fit_order(
    sweep: &[SweepPoint],
    problem: &str,
    method: &str,
    metric: Metric,
    scale: f64,
) -> OrderFit {
    let floor = ROUNDOFF_REL * scale.abs();
    let mut pts: Vec<(f64, f64)> = sweep
        .iter()
        .filter(|p| p.problem == problem && p.method == method)
        .filter_map(|p| Some((p.h_s?, metric.of(p)?)))
        .filter(|&(h, e)| h > 0.0 && e > floor)
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    pts.truncate(ORDER_POINTS);
    let logs: Vec<(f64, f64)> = pts.iter().map(|&(h, e)| (h.log10(), e.log10())).collect();
    OrderFit {
        problem: problem.to_string(),
        method: method.to_string(),
        metric,
        order: if logs.len() >= 3 { slope(&logs) } else { None },
        h_min_s: pts.first().map(|p| p.0),
        h_max_s: pts.last().map(|p| p.0),
        points: pts.len(),
    }
}

/// Time and work of one method to reach one error level on one problem.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CostRow {
    pub problem: String,
    pub method: String,
    pub metric: Metric,
    pub level: f64,
    pub time_s: Option<f64>,
    pub rhs_evals: Option<f64>,
    /// The method's cheapest setting already beats the level.
    pub overshoot: bool,
}

/// The (time, error) curve of a method on a problem in a metric.
pub fn time_curve(sweep: &[SweepPoint], problem: &str, method: &str, m: Metric) -> Vec<(f64, f64)> {
    curve(sweep, problem, method, m, |p| p.time_s)
}

/// The (rhs evaluations, error) curve of a method on a problem in a metric.
pub fn work_curve(sweep: &[SweepPoint], problem: &str, method: &str, m: Metric) -> Vec<(f64, f64)> {
    curve(sweep, problem, method, m, |p| p.rhs_evals.map(|r| r as f64))
}

fn curve(
    sweep: &[SweepPoint],
    problem: &str,
    method: &str,
    m: Metric,
    cost: impl Fn(&SweepPoint) -> Option<f64>,
) -> Vec<(f64, f64)> {
    sweep
        .iter()
        .filter(|p| p.problem == problem && p.method == method)
        .filter_map(|p| Some((cost(p)?, m.of(p)?)))
        .collect()
}

/// The cost of every method at every level, for the event-time and x_end metrics.
pub fn cost_rows(sweep: &[SweepPoint], problems: &[String], methods: &[String]) -> Vec<CostRow> {
    let mut rows = Vec::new();
    for problem in problems {
        for metric in [Metric::EventTime, Metric::XEnd] {
            for &level in &LEVELS {
                for method in methods {
                    let t = cost_at(&time_curve(sweep, problem, method, metric), level);
                    let w = cost_at(&work_curve(sweep, problem, method, metric), level);
                    rows.push(CostRow {
                        problem: problem.clone(),
                        method: method.clone(),
                        metric,
                        level,
                        time_s: t.map(|c| c.cost),
                        rhs_evals: w.map(|c| c.cost),
                        overshoot: t.is_some_and(|c| c.overshoot),
                    });
                }
            }
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cost_is_interpolated_log_log_on_the_pareto_front() {
        // A dominated point (3, 1e-2) is ignored.
        let curve = [(1.0, 1e-2), (3.0, 1e-2), (10.0, 1e-6), (100.0, 1e-10)];
        let c = cost_at(&curve, 1e-4).unwrap();
        assert!((c.cost - 10f64.sqrt()).abs() < 1e-12 && !c.overshoot);
        assert!(cost_at(&curve, 1e-12).is_none());
        let exact = cost_at(&[(5.0, 0.0)], 1e-8).unwrap();
        assert!(exact.overshoot && exact.cost == 5.0);
    }

    #[test]
    fn a_run_with_a_wrong_event_count_has_no_error_in_any_metric() {
        let json = serde_json::json!({
            "problem": "p", "method": "rk4", "setting_kind": "step", "tolerance": null,
            "h_s": 1e-3, "steps_per_period": 100.0, "status": "ok", "error": null,
            "time_s": 1e-6, "runs": 1, "rhs_evals": 10, "steps": 10, "accepted": null,
            "rejected": null, "n_events": 40, "n_events_exact": 80, "n_matched": 40,
            "kind_mismatches": 0, "reversals": 0, "err_event_s": 1e-12, "err_x_m": 1e-12,
            "err_vbar_m_s": 1e-12, "x_end_m": 0.1, "v_end_m_s": 0.0
        });
        let mut p: SweepPoint = serde_json::from_value(json).unwrap();
        for m in Metric::ALL {
            assert_eq!(m.of(&p), None, "{m:?}");
        }
        p.n_events = Some(80);
        for m in Metric::ALL {
            assert_eq!(m.of(&p), Some(1e-12), "{m:?}");
        }
    }

    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        let pts: Vec<(f64, f64)> = (1..6)
            .map(|i| {
                let h = 10f64.powi(-i);
                (h.log10(), (3.0 * h.powi(4)).log10())
            })
            .collect();
        assert!((slope(&pts).unwrap() - 4.0).abs() < 1e-12);
    }
}
