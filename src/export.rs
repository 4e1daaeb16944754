//! CSV export of `stickslip eval --csv DIR`: the time series of the exact runs and their event
//! lists, one file each per law, with units in the header row.
//!
//! ```text
//! timeseries_<law>.csv   t_s,x_m,v_m_s,a_m_s2,stuck                    (pulled mass)
//!                        t_s,y_m,v_m_s,a_m_s2,stuck,y_woodpecker_m     (woodpecker, y_W = y_S + z)
//! events_<law>.csv       t_s,kind,phase,x_m,v_m_s                      (y_m for the woodpecker)
//! ```
//!
//! Rendering is pure (text in memory, [`OutFile`]s); [`crate::report::write_all`] writes them,
//! so a bad target folder leaves nothing behind. Numbers are written in the shortest form that
//! reads back to the same `f64` (`{:e}`), so the bytes are the same on every machine.

use std::fmt::Write as _;

use crate::engine::{Event, Run};
use crate::report::OutFile;
use crate::results::summary::kind_name;

/// Uniform samples per integrated period (event times are added on top).
pub const SAMPLES_PER_PERIOD: u64 = 200;
/// Upper bound on the uniform samples of one time series: long runs are sampled more coarsely
/// (still uniformly) so that a file stays below ~100 MB.
pub const MAX_UNIFORM_SAMPLES: u64 = 1_000_000;

/// A float in the shortest scientific form that round-trips; zero is written `0e0` whatever
/// its sign, so that rest states read the same everywhere.
pub fn num(x: f64) -> String {
    if x == 0.0 {
        "0e0".to_string()
    } else {
        format!("{x:e}")
    }
}

/// The time series and the event list of one law's run (`law`: "harmonic" or "linear"), with
/// the body's position in a column named `position` ("x_m", "y_m") and, where `spring` is
/// given, the spring coordinate's companion column (the woodpecker's y_W = y_S + z).
pub fn law_files(
    law: &str,
    run: &Run,
    position: &str,
    spring: Option<&dyn Fn(f64) -> Option<f64>>,
) -> [OutFile; 2] {
    [
        timeseries(law, run, position, spring),
        events(law, run, position),
    ]
}

/// Sample times: a uniform grid over the run plus the times of its kept events, sorted, with
/// exact duplicates removed.
fn sample_times(run: &Run) -> Vec<f64> {
    let periods = u64::from(run.periods);
    let per_period = (MAX_UNIFORM_SAMPLES / periods.max(1)).clamp(1, SAMPLES_PER_PERIOD);
    let n = periods * per_period;
    let end = f64::from(run.periods) * run.period;
    let mut times: Vec<f64> = (0..=n).map(|i| end * i as f64 / n as f64).collect();
    times.extend(
        run.events
            .iter()
            .map(|e| e.t)
            .filter(|&t| t > 0.0 && t < end),
    );
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
}

/// `timeseries_<law>.csv`: t, position, v, a, stuck (0/1) and, for the woodpecker, y_W.
fn timeseries(
    law: &str,
    run: &Run,
    position: &str,
    spring: Option<&dyn Fn(f64) -> Option<f64>>,
) -> OutFile {
    let mut text = format!("t_s,{position},v_m_s,a_m_s2,stuck");
    if spring.is_some() {
        text.push_str(",y_woodpecker_m");
    }
    text.push('\n');
    for t in sample_times(run) {
        let (Some((x, v, a)), Some(stuck)) = (run.state_at(t), run.stuck_at(t)) else {
            continue;
        };
        let _ = write!(
            text,
            "{},{},{},{},{}",
            num(t),
            num(x),
            num(v),
            num(a),
            u8::from(stuck)
        );
        if let Some(z) = spring {
            // The bird rides on the sleeve: y_W = y_S + z(t).
            let y_w = z(t).map(|z| num(x + z)).unwrap_or_default();
            let _ = write!(text, ",{y_w}");
        }
        text.push('\n');
    }
    OutFile {
        path: format!("timeseries_{law}.csv").into(),
        bytes: text.into_bytes(),
    }
}

/// `events_<law>.csv`: every event the run kept (first and last periods), in time order.
fn events(law: &str, run: &Run, position: &str) -> OutFile {
    let mut text = format!("t_s,kind,phase,{position},v_m_s\n");
    for e in &run.events {
        let Event { t, x, v, kind, .. } = *e;
        let phase = (t / run.period).rem_euclid(1.0);
        let _ = writeln!(
            text,
            "{},{},{},{},{}",
            num(t),
            kind_name(kind),
            num(phase),
            num(x),
            num(v)
        );
    }
    OutFile {
        path: format!("events_{law}.csv").into(),
        bytes: text.into_bytes(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_and_zero_has_one_spelling() {
        for x in [1.0, -2.5e-7, 0.1 + 0.2, f64::MIN_POSITIVE, 123456.789] {
            assert_eq!(num(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(num(-0.0), "0e0");
        assert_eq!(num(0.0), "0e0");
    }
}
