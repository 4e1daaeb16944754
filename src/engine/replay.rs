//! Exact replay of a periodic orbit: once the state at two consecutive period starts is the same
//! up to the shift in x (at rest, or slipping with the same v bit for bit), every later period is
//! the recorded one.
//!
//! The forces depend on time only, and the motion relative to the start of an arc does not
//! depend on where the arc starts ([`Point::dx`](super::arc::Point)): a period is a function of
//! its start state ([`StartState`]: direction of slip, v, the sign of the acceleration for the
//! speed maxima) and of its start position x₀, the latter only through additions x ← x + Δx of
//! per-arc displacements that are themselves independent of x₀. So when period n starts in the
//! state period n − 1 started in, period n repeats period n − 1 event for event:
//!
//! ```text
//! period n − 1 (integrated, recorded):  ops = [event(t, kind, Δx?, v) | retract(t) | move(Δx) | segment(t0, t1, motion)]
//! period m ≥ n (replayed):              x ← x_m; for op in ops: the same calls with the same operands
//! ```
//!
//! The recorder ([`Recorder`]) and the segment list see the same calls with the same operands in
//! the same order as under full integration, so every output is bit-identical to it (tested in
//! tests/replay.rs against [`Replay::Off`]). Where the recorded period takes back no slip
//! onset and has no slip onset within the recorder's merge tolerance of a stick before it (it
//! grows with the period's index), the recorder would only keep the events of its kept
//! periods as they come: those are appended directly, and the other periods only move x (on
//! the harmonic woodpecker 17,000 instructions per 20-period run instead of 19,400; from the
//! period split once into its moves and its events, `Split`, 15,900 instead of 17,200; each
//! kept period's events written in place, 15,100 instead of 15,900). Orbits
//! whose start states differ (multi-period orbits, transients, a continuous slip whose v at the
//! period start still changes in its last bits) are integrated period by period as before.
//!
//! A stretch of at least [`SHORT`] replayed periods that only move x (not kept, and not next to
//! a kept one where they go through the recorder) is not walked period by period: its positions
//! are the same additions in the same order, taken as exact whole-spacing steps within each
//! binade of |x| ([`Gap::push_periods`]), and its speeds and dissipations are one repeated value
//! each ([`Stretch`]), so a run of 10⁶ periods stores and costs about what one of 10³ does.
//!
//! The autonomous belt ([`super::autonomous`]) uses the same tape for its cycle: there the
//! "period" runs from a slip onset to the next, its start state is the onset's (direction, x and
//! y = x − x_eq bit for bit), its times are local (from the onset) and its per-event extra is the
//! friction's ledger since the onset. Both engines share [`Replay`], [`Op`] and [`Tape`]
//! (recording, detection of a repeated start state, the per-period total). The loop that
//! replays differs, for two reasons of physics, not of code: the forced models' periods start
//! at n·T and move x by the recorded displacements (the motion is invariant under a shift in x,
//! so x carries on from period to period), and their events pass through the [`Recorder`],
//! which keeps only the first and last periods and merges a stick and a slip at one instant;
//! the belt's cycle starts at a time that is an output (t_k + (n − k) T) and returns to the
//! same x (the spring's force is not invariant under a shift), and every event of it is kept.
//! The belt's replay is [`super::autonomous`]'s `replay_cycles`, which places the cycle read
//! from the tape's ops (`SurfaceCycle`, the cycle the run exposes).

use super::run::{absolute_time, Event, EventKind, Motion, Recorder, Segment};
use super::series::{Gap, Series, SHORT};

/// What a run does with the periods of an orbit that repeats exactly ([`super::integrate_with`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Replay {
    /// Integrate every period (the reference the replay is tested against).
    Off,
    /// Replay the recorded period; recorded segments are kept for every period.
    Segments,
    /// Replay the recorded period; the segments of replayed periods are not stored but rebuilt
    /// on demand by [`Run::state_at`](super::Run::state_at), so that memory stays bounded for
    /// runs of 10⁶ periods (the public `segments` then stops at the recorded period).
    Compact,
}

/// One step of a recorded period, in the order the integration took it; `E` is what an event
/// carries besides its time, kind, place and speed (nothing for the forced models, the
/// friction's ledger since the cycle's onset for the belt). A segment's motion is kept apart
/// ([`Tape::recorded`]), so that a step is a few words and the tape of a run that records no
/// segments stays small (one allocation on the allocator's fast path).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Op<E = ()> {
    /// An event at local time `t`: at the current position, or `dx` (m) beyond it.
    Event {
        t: f64,
        kind: EventKind,
        dx: Option<f64>,
        v: f64,
        extra: E,
    },
    /// A slip onset at local time `t` taken back.
    Retract { t: f64 },
    /// The body moved by `dx` (m) along an arc.
    Move { dx: f64 },
    /// A recorded segment over local [t0, t1]: the motion with index `motion` in the tape's
    /// motions, started at the current position.
    Segment { t0: f64, t1: f64, motion: usize },
}

/// The segments of replayed periods, rebuilt on demand ([`Replay::Compact`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Compact {
    /// First replayed period.
    pub(super) from: u32,
    /// The recorded period's steps and its segments' motions.
    ops: Vec<Op>,
    motions: Vec<Motion>,
}

impl Compact {
    /// The first segment of the replayed periods `periods` (started at the positions
    /// `x_at_period_start`, m) that ends at or after absolute time `t` (s).
    pub(super) fn first_ending_after(
        &self,
        periods: std::ops::Range<u32>,
        x_at_period_start: &Series,
        period: f64,
        t: f64,
    ) -> Option<Segment> {
        for m in periods {
            let mut x = x_at_period_start.get(m as usize)?;
            for op in &self.ops {
                match *op {
                    Op::Move { dx } => x += dx,
                    Op::Segment { t0, t1, motion } => {
                        let seg = segment(m, period, t0, t1, self.motions[motion], x);
                        if seg.t1 >= t {
                            return Some(seg);
                        }
                    }
                    Op::Event { .. } | Op::Retract { .. } => {}
                }
            }
        }
        None
    }
}

/// The segment of period `m` over local [t0, t1] with `motion` started at position `x`, with
/// the absolute times the integration gives it.
fn segment(m: u32, period: f64, t0: f64, t1: f64, motion: Motion, x: f64) -> Segment {
    let period_start = f64::from(m) * period;
    let next_start = f64::from(m + 1) * period;
    let absolute = |t| absolute_time(period_start, next_start, period, t);
    Segment {
        t0: absolute(t0),
        t1: absolute(t1),
        period_start,
        motion: match motion {
            Motion::Rest { .. } => Motion::Rest { x },
            Motion::Slide { arc } => Motion::Slide {
                arc: arc.started_at(x),
            },
        },
    }
}

/// What a period's motion depends on besides its start position: the direction of slip (0 at
/// rest), v (m/s, as bits, so that −0 and +0 differ) and the sign of s·a on the last slipping
/// stretch (a speed maximum across the period start).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct StartState {
    pub dir: i8,
    pub v: u64,
    pub accel_sign: i8,
}

/// The steps of the current period, recorded while it may become the template: `S` is the
/// start state a repeat is detected on, `M` what a segment holds (the forced engine's motion,
/// placed at the current position; the belt's segment in local time, at its own x since its
/// cycle returns to the same x), `P` the period's total the replay hands on (the friction
/// dissipation for the forced models, the ledger for the belt).
pub(super) struct Tape<S = StartState, M = Motion, E = (), P = f64> {
    mode: Replay,
    segments: bool,
    /// Record (and detect) also with [`Replay::Off`]: the belt reads its cycle from the tape.
    always: bool,
    ops: Vec<Op<E>>,
    /// The motions of the recorded segments, in order (empty unless segments are recorded).
    motions: Vec<M>,
    /// The current period is being recorded, from this start state.
    recording: Option<S>,
    /// The last period was recorded in full and ended in its start state: the next periods
    /// repeat it.
    complete: bool,
    /// The recorded period's total: friction dissipation (J) or the belt's ledger.
    dissipation: P,
}

/// A long stretch of replayed periods that go through no recorder and only move x, kept as
/// pieces ([`Gap`]): x as exact steps, v and the dissipation as one repeated value each.
pub(super) struct Stretch {
    /// The first period of the stretch.
    at: usize,
    x: Gap,
    v: f64,
    dissipation: f64,
}

impl Stretch {
    /// The stretch of `periods` from position `x` (m) of the recorded period `ops`, which start
    /// at speed v and dissipate the recorded total; and x at its end. The same additions in the
    /// same order as the replay's loop, in whole steps where exact. Out of line: only runs of
    /// many periods come here, and the loop it is called from is hot in short ones.
    #[cold]
    #[inline(never)]
    fn take(
        ops: &[Op],
        x: f64,
        periods: std::ops::Range<u32>,
        (v, dissipation): (f64, f64),
    ) -> (f64, Stretch) {
        let moves = ops.iter().filter_map(|op| match *op {
            Op::Move { dx } => Some(dx),
            _ => None,
        });
        let mut x_gap = Gap::default();
        let end = x_gap.push_periods(x, moves, periods.len());
        let stretch = Stretch {
            at: periods.start as usize,
            x: x_gap,
            v,
            dissipation,
        };
        (end, stretch)
    }

    /// The series of a run whose explicit values are `x`, `v` and `dissipation` (the latter
    /// empty when not integrated), with the stretch, if any, between them.
    pub(super) fn series(
        stretch: Option<Stretch>,
        [x, v, dissipation]: [Vec<f64>; 3],
    ) -> [Series; 3] {
        let Some(Stretch {
            at,
            x: x_gap,
            v: v_value,
            dissipation: d_value,
        }) = stretch
        else {
            return [x, v, dissipation].map(Series::from);
        };
        let n = x_gap.len();
        let d_series = if dissipation.is_empty() {
            Series::from(dissipation)
        } else {
            Series::with_gap(dissipation, at, Gap::repeated(d_value, n))
        };
        [
            Series::with_gap(x, at, x_gap),
            Series::with_gap(v, at, Gap::repeated(v_value, n)),
            d_series,
        ]
    }
}

/// The outputs of a run that replayed periods extend.
pub(super) struct Outputs<'a> {
    pub x_at_period_start: &'a mut Vec<f64>,
    pub v_at_period_start: &'a mut Vec<f64>,
    pub dissipation: Option<&'a mut Vec<f64>>,
    pub segments: &'a mut Vec<Segment>,
}

/// Room for this many steps of a recorded period is reserved when a run may replay (two
/// slip-stick cycles with their speed maxima and moves, and room to spare), so that recording
/// seldom grows the list.
const OPS_RESERVED: usize = 16;

impl<S: Copy + PartialEq, M: Copy, E: Copy, P: Copy + Default> Tape<S, M, E, P> {
    /// A tape that records only where `mode` replays (the forced models).
    pub(super) fn new(mode: Replay, segments: bool) -> Self {
        Tape {
            mode,
            segments,
            always: false,
            ops: match mode {
                Replay::Off => Vec::new(),
                Replay::Segments | Replay::Compact => Vec::with_capacity(OPS_RESERVED),
            },
            motions: Vec::new(),
            recording: None,
            complete: false,
            dissipation: P::default(),
        }
    }

    /// A tape that records and detects in every mode, [`Replay::Off`] included (the belt, whose
    /// cycle is an output of every run).
    pub(super) fn detecting(mode: Replay, segments: bool) -> Self {
        Tape {
            always: true,
            ops: Vec::with_capacity(OPS_RESERVED),
            ..Self::new(mode, segments)
        }
    }

    /// At the start of a period: whether the last one repeats from here on.
    #[inline]
    pub(super) fn repeats(&self) -> bool {
        self.complete
    }

    /// Whether the run replays the periods that repeat (not with [`Replay::Off`]).
    #[inline]
    pub(super) fn replays(&self) -> bool {
        self.complete && self.mode != Replay::Off
    }

    /// The mode the tape was made for.
    pub(super) fn mode(&self) -> Replay {
        self.mode
    }

    /// A period begins in state `start`.
    #[inline]
    pub(super) fn begin(&mut self, start: S) {
        self.ops.clear();
        self.motions.clear();
        self.recording = (self.always || self.mode != Replay::Off).then_some(start);
    }

    /// The period ended with total `dissipation` (J, or the ledger) in state `end`: the next
    /// periods repeat it when that is the state it started in.
    #[inline]
    pub(super) fn end(&mut self, dissipation: P, end: S) {
        self.complete = self.recording == Some(end);
        self.dissipation = dissipation;
    }

    /// The recorded steps of the last period, the motions its segments index, its start state
    /// and its total.
    pub(super) fn recorded(&self) -> (&[Op<E>], &[M], Option<S>, P) {
        (&self.ops, &self.motions, self.recording, self.dissipation)
    }

    #[inline]
    pub(super) fn event(&mut self, t: f64, kind: EventKind, dx: Option<f64>, v: f64, extra: E) {
        if self.recording.is_some() {
            self.ops.push(Op::Event {
                t,
                kind,
                dx,
                v,
                extra,
            });
        }
    }

    #[inline]
    pub(super) fn retract(&mut self, t: f64) {
        if self.recording.is_some() {
            self.ops.push(Op::Retract { t });
        }
    }

    #[inline]
    pub(super) fn moved(&mut self, dx: f64) {
        if self.recording.is_some() {
            self.ops.push(Op::Move { dx });
        }
    }

    #[inline]
    pub(super) fn segment(&mut self, t0: f64, t1: f64, motion: M) {
        if self.segments && self.recording.is_some() && t1 > t0 {
            self.ops.push(Op::Segment {
                t0,
                t1,
                motion: self.motions.len(),
            });
            self.motions.push(motion);
        }
    }
}

/// At most this many moves and as many events of a recorded period are replayed from a
/// [`Split`] (the models' periods have up to about ten of each).
const SPLIT_MAX: usize = 16;

/// The recorded period of the direct path (its events only kept, see
/// [`Tape::only_kept_events`]) split into its moves and its events, each event with the number
/// of moves before it: a kept period adds the moves in order, as the loop over the steps does,
/// and appends its events, each at the position the moves before it reach; any other period
/// only adds the moves.
struct Split {
    moves: [f64; SPLIT_MAX],
    n_moves: usize,
    /// The events with their local time t (s), and for x the offset (m) from the position the
    /// moves before it reach (0 for an event at that position: 0 + x is x bit for bit, x being
    /// a sum that starts from +0 and so never −0); their periods are set where placed.
    events: [Event; SPLIT_MAX],
    /// The number of moves before each event.
    after: [u8; SPLIT_MAX],
    n_events: usize,
}

impl Split {
    const EMPTY: Split = Split {
        moves: [0.0; SPLIT_MAX],
        n_moves: 0,
        events: [Event {
            t: 0.0,
            period: 0,
            // All bits zero (no copy of a constant to start from).
            kind: EventKind::Slip { dir: 0 },
            x: 0.0,
            v: 0.0,
        }; SPLIT_MAX],
        after: [0; SPLIT_MAX],
        n_events: 0,
    };

    /// Splits `ops` into this (empty) split; false when they have more than [`SPLIT_MAX`]
    /// moves or events.
    fn fill(&mut self, ops: &[Op]) -> bool {
        let (mut n_moves, mut n_events) = (0, 0);
        for op in ops {
            match *op {
                Op::Move { dx } => {
                    let Some(place) = self.moves.get_mut(n_moves) else {
                        return false;
                    };
                    *place = dx;
                    n_moves += 1;
                }
                Op::Event { t, kind, dx, v, .. } => {
                    let (Some(place), Some(after)) =
                        (self.events.get_mut(n_events), self.after.get_mut(n_events))
                    else {
                        return false;
                    };
                    *place = Event {
                        t,
                        period: 0,
                        kind,
                        x: dx.unwrap_or(0.0),
                        v,
                    };
                    *after = n_moves as u8;
                    n_events += 1;
                }
                Op::Retract { .. } | Op::Segment { .. } => {}
            }
        }
        (self.n_moves, self.n_events) = (n_moves, n_events);
        true
    }

    /// Replays `periods` (of length `period`, s) from `x` (m): their starts appended to
    /// `x_at_period_start`, the kept ones' events to the recorder's; x after them. Out of line,
    /// so that the loops are compiled for this alone.
    #[inline(never)]
    fn replay(
        &self,
        mut x: f64,
        periods: std::ops::Range<u32>,
        period: f64,
        rec: &mut Recorder,
        x_at_period_start: &mut Vec<f64>,
    ) -> f64 {
        // The positions of a kept period after each number of moves (from none).
        let mut positions = [0.0; SPLIT_MAX + 1];
        let first = x_at_period_start.len();
        x_at_period_start.resize(first + periods.len(), 0.0);
        for (x_start, m) in x_at_period_start[first..].iter_mut().zip(periods) {
            *x_start = x;
            x = if rec.keeps(m) {
                self.kept_period(x, m, period, &mut positions, &mut rec.events)
            } else {
                self.moved(x)
            };
        }
        x
    }

    /// x (m) after a period from `x` that is not kept: the moves in order.
    #[inline(always)]
    fn moved(&self, mut x: f64) -> f64 {
        for dx in &self.moves[..self.n_moves] {
            x += dx;
        }
        x
    }

    /// Period `m` (of length `period`, s) from `x` (m), kept: the positions after each move in
    /// order (into `positions`), and the events appended to `events`, each placed at the
    /// position the moves before it reach (t + t₀ and Δx + x, the recorder's sums with their
    /// operands swapped), written in place (a copy and then a pass over the copies took about
    /// 40 instructions more per period); x after it.
    #[inline(always)]
    fn kept_period(
        &self,
        x: f64,
        m: u32,
        period: f64,
        positions: &mut [f64; SPLIT_MAX + 1],
        events: &mut Vec<Event>,
    ) -> f64 {
        positions[0] = x;
        let mut at = x;
        for (place, dx) in positions[1..].iter_mut().zip(&self.moves[..self.n_moves]) {
            at += dx;
            *place = at;
        }
        let start = f64::from(m) * period;
        let n = self.n_events;
        events.reserve(n);
        let places = &mut events.spare_capacity_mut()[..n];
        for ((place, e), &after) in places.iter_mut().zip(&self.events[..n]).zip(&self.after) {
            place.write(Event {
                t: e.t + start,
                period: m,
                kind: e.kind,
                x: e.x + positions[usize::from(after)],
                v: e.v,
            });
        }
        // SAFETY: the `n` places after the events were reserved and have just been written.
        unsafe { events.set_len(events.len() + n) };
        at
    }
}

impl Tape {
    /// Whether the recorder, fed the recorded period's events in every period up to `periods`
    /// (s, of length `period`), would do no more than keep those of the kept periods: the
    /// period takes back no slip onset, and none of its slip onsets is within the recorder's
    /// merge tolerance ([`Recorder::apart`]) of a stick before it, in the same period or at the
    /// end of the one before (the last transition of the recorded period, which also precedes
    /// the first replayed one). The first slip is then known already: the recorded period set
    /// it, if it has a slip onset.
    pub(super) fn only_kept_events(&self, rec: &Recorder, period: f64, periods: u32) -> bool {
        if self.ops.iter().any(|op| matches!(op, Op::Retract { .. })) {
            return false;
        }
        let transitions = self.ops.iter().filter_map(|op| match *op {
            Op::Event { t, kind, .. } if kind != EventKind::SpeedMax => Some((t, kind)),
            _ => None,
        });
        let Some((t_last, last)) = transitions.clone().next_back() else {
            return true;
        };
        let mut before = (t_last - period, last);
        for (t, kind) in transitions {
            if let (EventKind::Slip { .. }, (t_stick, EventKind::Stick { .. })) = (kind, before) {
                if !rec.apart(t - t_stick, periods) {
                    return false;
                }
            }
            before = (t, kind);
        }
        true
    }

    /// Replays the recorded period for periods `from..periods` starting at position `x` (m),
    /// through the recorder and into the outputs; returns the position at the end, in
    /// [`Replay::Compact`] mode what rebuilds the replayed segments, and the long stretch of
    /// periods kept as pieces, if any (the outputs have no values for its periods).
    pub(super) fn replay(
        self,
        (from, periods, period): (u32, u32, f64),
        mut x: f64,
        rec: &mut Recorder,
        out: Outputs,
    ) -> (f64, Option<Compact>, Option<Stretch>) {
        let materialize = self.segments && self.mode == Replay::Segments;
        let Outputs {
            x_at_period_start,
            v_at_period_start,
            dissipation,
            segments,
        } = out;
        let v = self.recording.map_or(0.0, |start| f64::from_bits(start.v));
        // When the recorder would only keep the kept periods' events, as they come, they are
        // appended directly from the period split into its moves and its events (where they
        // fit: more go through the recorder), and the other periods just move x.
        let mut split = Split::EMPTY;
        let direct =
            !materialize && self.only_kept_events(rec, period, periods) && split.fill(&self.ops);
        // A period whose events are not kept leaves the recorder as it found it, except for the
        // last transition, which the next period's first slip is merged with when at the same
        // instant. When the period has a stick or a retraction (or no transition at all), the
        // last transition at its end is its own, whatever it was before: then only the periods
        // next to a kept one go through the recorder, and the others just move x. (Read off
        // the direct path only.)
        let own_last_transition = !direct
            && (self.ops.iter().any(|op| {
                matches!(
                    op,
                    Op::Event {
                        kind: EventKind::Stick { .. },
                        ..
                    } | Op::Retract { .. }
                )
            }) || !self.ops.iter().any(
                |op| matches!(op, Op::Event { kind, .. } if !matches!(kind, EventKind::SpeedMax)),
            ));
        // The periods that only move x: with the direct path every period that is not kept;
        // else those that are not the first replayed one and are not next to a kept one. When
        // many, they are taken at once as a stretch of pieces.
        let (first_kept, last_kept) = (rec.keeps_first(), rec.keeps_from());
        let only_moving = if direct {
            from.max(first_kept)..last_kept
        } else if !materialize && own_last_transition {
            from.saturating_add(1).max(first_kept + 1)..last_kept.saturating_sub(1)
        } else {
            0..0
        };
        let long = if only_moving.len() >= SHORT {
            only_moving
        } else {
            periods..periods
        };
        // Every replayed period starts at the recorded v and dissipates the recorded total.
        let explicit = periods.saturating_sub(from) as usize - long.len();
        v_at_period_start.resize(v_at_period_start.len() + explicit, v);
        if let Some(d) = dissipation {
            d.resize(d.len() + explicit, self.dissipation);
        }
        let mut stretch = None;
        let mut m = from;
        while m < periods {
            if m == long.start {
                let taken;
                (x, taken) = Stretch::take(&self.ops, x, long.clone(), (v, self.dissipation));
                stretch = Some(taken);
                m = long.end;
                continue;
            }
            if direct {
                let end = if long.start > m { long.start } else { periods };
                x = split.replay(x, m..end, period, rec, x_at_period_start);
                m = end;
                continue;
            }
            x_at_period_start.push(x);
            let through_recorder = materialize
                || !own_last_transition
                || m == from
                || rec.keeps(m)
                || rec.keeps(m - 1)
                || rec.keeps(m.saturating_add(1));
            if !through_recorder {
                for op in &self.ops {
                    if let Op::Move { dx } = *op {
                        x += dx;
                    }
                }
                m += 1;
                continue;
            }
            for op in &self.ops {
                match *op {
                    Op::Event { t, kind, dx, v, .. } => {
                        rec.push(m, t, kind, dx.map_or(x, |dx| x + dx), v);
                    }
                    Op::Retract { t } => rec.retract_slip(f64::from(m) * period + t),
                    Op::Move { dx } => x += dx,
                    Op::Segment { t0, t1, motion } => {
                        if materialize {
                            let motion = self.motions[motion];
                            segments.push(segment(m, period, t0, t1, motion, x));
                        }
                    }
                }
            }
            m += 1;
        }
        let compact =
            (self.segments && self.mode == Replay::Compact && from < periods).then_some(Compact {
                from,
                ops: self.ops,
                motions: self.motions,
            });
        (x, compact, stretch)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A split holds the moves in order and each event with the number of moves before it; a
    /// period of more steps than it holds is not split (its periods go through the recorder).
    #[test]
    fn a_split_keeps_the_order_of_the_moves_and_events() {
        let event = |t: f64, dx: Option<f64>| Op::Event {
            t,
            kind: EventKind::SpeedMax,
            dx,
            v: 1.5,
            extra: (),
        };
        let ops = [
            event(0.1, None),
            Op::Move { dx: 0.1 },
            Op::Move { dx: 0.2 },
            event(0.2, Some(0.05)),
            Op::Move { dx: 0.3 },
        ];
        let mut split = Split::EMPTY;
        assert!(split.fill(&ops));
        let x = 1.0;
        assert_eq!(
            split.moved(x).to_bits(),
            (((x + 0.1) + 0.2) + 0.3).to_bits()
        );
        let after: Vec<_> = (0..split.n_events)
            .map(|i| (split.events[i].t, split.after[i], split.events[i].x))
            .collect();
        assert_eq!(after, [(0.1, 0, 0.0), (0.2, 2, 0.05)]);
        for many in [
            vec![Op::Move { dx: 0.1 }; SPLIT_MAX + 1],
            vec![event(0.1, None); SPLIT_MAX + 1],
        ] {
            let mut split = Split::EMPTY;
            assert!(!split.fill(&many));
        }
    }
}
