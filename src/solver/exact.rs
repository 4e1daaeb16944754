//! The exact event-driven engine as a [`Method`]: the reference of every comparison.

use super::surface::SurfaceProblem;
use super::{Method, MethodEvent, Problem, Setting, Solution, Stats};
use crate::engine::autonomous::{Ending, SurfaceOptions, SurfaceRun};
use crate::engine::run::Motion;
use crate::engine::{integrate, integrate_surface, EventKind, RunOptions, Segment};
use crate::error::{Error, Result};

/// The exact engine ([`crate::engine::integrate`]); the setting is ignored.
pub struct Exact;

impl Method for Exact {
    fn name(&self) -> &'static str {
        "exact"
    }

    fn solve(&self, problem: &Problem, _setting: Setting) -> Result<Solution> {
        let run = integrate(&problem.body, &problem.law, &options(problem, true))?;
        // Events of every period are needed: the run keeps the first and last ones only, so
        // they are read off the recorded segments: rest → slide is a slip (also at t = 0, an
        // immediate slip), slide → rest a stick, slide → slide in the other direction a reversal.
        let direction = |seg: &Segment| match seg.motion {
            Motion::Rest { .. } => 0.0,
            Motion::Slide { arc } => arc.v(0.5 * (seg.t0 + seg.t1) - seg.period_start).signum(),
        };
        let mut events = Vec::new();
        if let Some(first) = run.segments.first().filter(|s| direction(s) != 0.0) {
            events.push(MethodEvent {
                t: first.t0,
                kind: "slip",
            });
        }
        for pair in run.segments.windows(2) {
            let (a, b) = (direction(&pair[0]), direction(&pair[1]));
            let kind = match (a == 0.0, b == 0.0) {
                (true, false) => "slip",
                (false, true) => "stick",
                (false, false) if a != b => "reversal",
                _ => continue,
            };
            if pair[1].t0 <= problem.t_end {
                events.push(MethodEvent {
                    t: pair[1].t0,
                    kind,
                });
            }
        }
        let (x_end, v_end, _) = run.state_at(problem.t_end).unwrap_or((0.0, 0.0, 0.0));
        let stats = Stats {
            rhs_evals: run.segments.len() as u64,
            steps: run.segments.len() as u64,
            accepted: run.segments.len() as u64,
            ..Stats::default()
        };
        Ok(Solution::new(events, x_end, v_end, stats))
    }

    /// [`integrate_surface`] over slip onsets until `t_end` is passed: its slips and sticks
    /// up to `t_end`, and the state there.
    fn solve_surface(&self, problem: &SurfaceProblem, _setting: Setting) -> Result<Solution> {
        let run = surface_run(problem, true)?;
        let events: Vec<MethodEvent> = run
            .events
            .iter()
            .filter(|e| e.t <= problem.t_end)
            .filter_map(|e| {
                match e.kind {
                    EventKind::Slip { .. } => Some("slip"),
                    EventKind::Stick { .. } => Some("stick"),
                    _ => None,
                }
                .map(|kind| MethodEvent { t: e.t, kind })
            })
            .collect();
        let (x_end, v_end, _) = run.state_at(problem.t_end).ok_or(Error::Stalled {
            t: problem.t_end,
            reason: "exact: the surface run does not reach t_end",
        })?;
        let n = run.segments.len() as u64;
        let stats = Stats {
            rhs_evals: n,
            steps: n,
            accepted: n,
            ..Stats::default()
        };
        Ok(Solution::new(events, x_end, v_end, stats))
    }

    /// [`integrate`] alone, as a user calls it: the same events located, without recording
    /// the segments `solve` reads every period's events from.
    fn solve_timed(&self, problem: &Problem, _setting: Setting) -> Result<()> {
        integrate(&problem.body, &problem.law, &options(problem, false)).map(drop)
    }
}

/// The surface run of `problem` past `t_end`: slip onsets doubled until the last is beyond
/// it, or the body sticks or slips for ever.
fn surface_run(problem: &SurfaceProblem, record_segments: bool) -> Result<SurfaceRun> {
    let mut slips = 8u32;
    loop {
        let opts = SurfaceOptions {
            x0: 0.0,
            slips,
            record_segments,
        };
        let run = integrate_surface(&problem.body, &problem.law, &opts)?;
        let past = run.events.last().is_some_and(|e| e.t > problem.t_end);
        if past || run.ending != Ending::Slips || slips >= 1 << 20 {
            return Ok(run);
        }
        slips *= 2;
    }
}

/// The run of `problem`: whole periods to its end, segments recorded or not.
fn options(problem: &Problem, record_segments: bool) -> RunOptions {
    let periods = (problem.t_end / problem.law.period).ceil().max(1.0) as u32;
    RunOptions {
        periods,
        record_segments,
        dissipation: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{Affine, Basis, Body, ForceLaw, Piece};

    #[test]
    fn immediate_slips_and_reversals_are_listed() {
        // D = 2 − 4t on [0, 1), −2 + 4(t − 1) on [1, 2); N_f = 1: immediate slip forward,
        // reversal at t = 0.875 (tests/engine.rs has the same case for the engine).
        let piece = |start: f64, end: f64, d: (f64, f64)| Piece {
            start,
            end,
            basis: Basis::Linear { t_ref: start },
            drive: Affine::new(d.0, d.1),
            normal: Affine::new(1.0, 0.0),
        };
        let law = ForceLaw::new(
            2.0,
            vec![piece(0.0, 1.0, (2.0, -4.0)), piece(1.0, 2.0, (-2.0, 4.0))],
        )
        .unwrap();
        let problem = Problem {
            body: Body {
                mass: 1.0,
                mu_s: 0.5,
                mu_d: 0.25,
            },
            law,
            t_end: 1.0,
        };
        let sol = Exact.solve(&problem, Setting::Tolerance(1e-9)).unwrap();
        assert_eq!(
            sol.events[0],
            MethodEvent {
                t: 0.0,
                kind: "slip"
            }
        );
        assert_eq!(sol.events[1].kind, "reversal");
        assert!((sol.events[1].t - 0.875).abs() < 1e-15);
    }
}
