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
//! reads back to the same `f64` ([`num`]), so the bytes are the same on every machine; every CSV
//! of the tool (these, sweep.csv, fit.csv) can be rewritten for comma-decimal spreadsheets
//! ([`CsvDialect`]).

use std::fmt::Write as _;

use crate::engine::{Event, Run};
use crate::report::OutFile;
use crate::results::summary::kind_name;

/// Uniform samples per integrated period (event times are added on top).
pub const SAMPLES_PER_PERIOD: u64 = 200;
/// Upper bound on the uniform samples of one time series: long runs are sampled more coarsely
/// (still uniformly) so that a file stays below ~100 MB.
pub const MAX_UNIFORM_SAMPLES: u64 = 1_000_000;

/// Magnitudes written without an exponent: from 10⁻⁵ (0.00001) up to 10¹⁵.
const PLAIN: std::ops::Range<f64> = 1e-5..1e15;

/// A float in the shortest form that reads back to the same `f64`: plain decimals where the
/// magnitude allows ([`PLAIN`]), scientific notation (`1.5e-9`) beyond; zero is `0` whatever
/// its sign, so that rest states read the same everywhere.
pub fn num(x: f64) -> String {
    if x == 0.0 {
        "0".to_string()
    } else if PLAIN.contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// How a CSV file separates fields and writes decimals.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum CsvDialect {
    /// `,` between fields, `.` decimals (RFC 4180; what most software reads).
    #[default]
    Standard,
    /// `;` between fields, `,` decimals: what spreadsheets set to Italian, German, French or
    /// Spanish read as numbers.
    Semicolon,
}

impl CsvDialect {
    /// `text`, a CSV file of this tool in the standard dialect (no quoted fields, no `;`), in
    /// this dialect: `;` between fields and a decimal comma in every number.
    pub fn convert(self, text: &str) -> String {
        match self {
            CsvDialect::Standard => text.to_string(),
            CsvDialect::Semicolon => text
                .split_inclusive('\n')
                .map(|line| {
                    let (body, end) = line
                        .strip_suffix('\n')
                        .map_or((line, ""), |body| (body, "\n"));
                    let fields: Vec<String> = body
                        .split(',')
                        .map(|f| {
                            if f.parse::<f64>().is_ok() {
                                f.replace('.', ",")
                            } else {
                                f.to_string()
                            }
                        })
                        .collect();
                    fields.join(";") + end
                })
                .collect(),
        }
    }

    /// `files` with every `.csv` among them in this dialect.
    pub fn apply(self, files: Vec<OutFile>) -> Vec<OutFile> {
        if self == CsvDialect::Standard {
            return files;
        }
        files
            .into_iter()
            .map(|f| {
                if f.path.extension().is_some_and(|e| e == "csv") {
                    let text = String::from_utf8_lossy(&f.bytes);
                    OutFile {
                        bytes: self.convert(&text).into_bytes(),
                        ..f
                    }
                } else {
                    f
                }
            })
            .collect()
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
        for x in [
            1.0,
            -2.5e-7,
            0.1 + 0.2,
            f64::MIN_POSITIVE,
            123456.789,
            1e-5,
            9.99e14,
            1e15,
        ] {
            assert_eq!(num(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(0.0), "0");
        // Plain decimals where the magnitude allows, an exponent beyond.
        assert_eq!(num(0.000_123), "0.000123");
        assert_eq!(num(-1234.5), "-1234.5");
        assert_eq!(num(1e-5), "0.00001");
        assert_eq!(num(2.5e-7), "2.5e-7");
        assert_eq!(num(3e15), "3e15");
    }

    #[test]
    fn the_semicolon_dialect_has_decimal_commas_and_keeps_text() {
        let text = "t_s,kind,x_m\n0.25,slip_onset,-1.5e-7\n1,stick,0\n";
        assert_eq!(
            CsvDialect::Semicolon.convert(text),
            "t_s;kind;x_m\n0,25;slip_onset;-1,5e-7\n1;stick;0\n"
        );
        assert_eq!(CsvDialect::Standard.convert(text), text);
        // A last line without a newline stays without one.
        assert_eq!(CsvDialect::Semicolon.convert("a,0.5"), "a;0,5");
    }
}
