//! The driver: walks the force law piece by piece through the requested periods, switching
//! between STUCK and SLIP at located events, and records events, per-period positions and (when
//! asked for) friction dissipation.
//!
//! Cost, in instructions per 20-period run of the four bench problems (`valgrind
//! --tool=callgrind --toggle-collect='*engine_instructions*integrate_repeatedly*'
//! engine_instructions-<hash> PROBLEM 1000`, collected / 1000; benches/engine_instructions.rs):
//!
//! ```text
//!                          pulled mass   pulled mass   woodpecker   woodpecker
//!                          linear        harmonic      linear       harmonic
//! c8fb77c                  10,545        10,905        14,931       23,433
//! perf (its branch)         9,750        10,241        13,843       19,897
//! b33a971 (main, again)     9,780        10,438        13,913       20,318
//! f1b6f71 (perf2)           9,346        10,044        13,418       19,798
//! e97c72c (main, again)     9,328         9,867        13,392       19,431
//! engine50                  7,702         8,424        10,587       16,953
//! c426ece (main)            7,852         8,833        10,896       17,411
//! c426ece (again, linear)   7,846         8,717        10,884       17,181
//! c9e0e1a (linear)          6,829         8,182         9,371       15,927
//! lazy known angles         6,525         7,384         8,426       13,482
//! ```
//!
//! All four repeat from the first period, so a run is one integrated period, 19 replayed ones
//! ([`super::replay`]) and the preparation of the pieces, which on the harmonic woodpecker was
//! about a quarter of the run. Since c8fb77c: a piece is prepared in its place after the ones
//! before it (no copy of a few hundred bytes, two per piece before); a piece on the same cos
//! basis with the same drive and normal force as an earlier one (the woodpecker's third lobe)
//! takes that one's acceleration sign changes and slip-onset crossings (located over the
//! period, limited to the piece's end where read, [`UpCrossings::ending_at`]), one whose normal
//! force is the earlier one's negated (the middle lobe) its sign changes negated
//! ([`SignChanges::negated`]); sin and cos of ωt at a piece boundary are evaluated once for the
//! basis range of both pieces and the start phase (7 libm calls instead of 12 on the woodpecker);
//! the known half angles skip the ends outside the piece before looking at the starts; the
//! recorder's kept periods are one comparison. Every output is the same bit for bit
//! (`engine_instructions fingerprint`: the same four hashes before and after, and
//! `shared_sign_changes_and_boundary_cosines_are_located_ones` below). The rest of the
//! harmonic woodpecker's run: the replayed periods through the recorder (about 4,000: 13 of
//! the 19 replayed periods are kept or next to a kept one), the run's four allocations with
//! their frees (about 1,000), the two sign-change searches left (900), the two crossing
//! searches and the one integrated period.
//!
//! Since b33a971: a tape step (`Op` of src/engine/replay.rs) holds a recorded segment's motion by
//! index into a list of its own (empty when no segments are recorded), so a step is 40 bytes
//! instead of one sized for an arc and the tape's 16 reserved steps fit the allocator's fast
//! path (glibc's tcache, ≤ 1032 bytes); the replayed periods' start speeds and dissipations are
//! appended at once. Fingerprints unchanged.
//!
//! Since e97c72c: a replayed period no longer passes through the recorder where the recorder
//! would only keep its events (no slip onset taken back, none within the merge tolerance of a
//! stick before it, [`Recorder::apart`]): the kept periods' events are appended directly and
//! the others only move x, instead of 13 periods × 6 events of about 50 instructions each on
//! the harmonic woodpecker. Fingerprints unchanged. What is left there: the event list's
//! allocation and free (72 events of 32 bytes, beyond the fast path, about 300), the driver's
//! drop of the run it returned (about 360, in the count), the two sign-change searches (900),
//! the kept events themselves (66 appended) and the preparation and the one integrated period
//! (the rest).
//!
//! Since engine50: the per-period values are [`Series`], whose long stretch of replayed periods
//! that only move x is kept as exact steps ([`super::series`]), so that 10⁶ periods cost what 10³
//! do. The 20-period runs take no such stretch (fewer than 64 periods); their counts above moved
//! by 2–4 % with how the compiler inlines the root searches into the larger run (`UpCrossings::new`
//! and a second `cos_level_crossings_dd` are now calls). Fingerprints unchanged.
//!
//! Since c426ece (branch linear): the replayed periods of the direct path are taken from the
//! recorded period split once into its moves and its events ([`super::replay`]'s `Split`):
//! a period that is not kept adds its moves in a loop of its own, a kept one adds them and
//! pushes each event as it passes it, in one function out of line for the whole stretch
//! (before, a loop over the steps inside this large function dispatched on each step's kind,
//! about 11 instructions a step and 30 an event, with the run's state spilled); a piece's
//! known half angles (440 bytes cleared per piece, about 42 instructions) are set up only on a
//! cos basis. Fingerprints unchanged. Harmonic woodpecker 7 % less: 42.4× a lean DOPRI5's
//! instructions (`Lean`, benches/dopri5_instructions.rs; 50× needs about 13,520); the linear
//! laws' runs are 6,829 and 9,371 (341 and 469 per period). Tried and dropped:
//! appending a kept period's events with `Vec::extend` from a slice mapped to events (one
//! call out of line per kept period; better on the woodpecker by 90, worse on the pulled mass
//! by 340–410), the same split inside this function (the loop over the steps' cost again, from
//! spills), and `Option<KnownAngles>` set in the struct literal (the prepared piece was then
//! built aside and copied into place, 600 bytes twice per piece). What is left on the
//! harmonic woodpecker: the replay (about 3,200: 66 kept events at about 30 each, the 19
//! periods' moves and starts), the run's four allocations and frees (about 700, the event
//! list's beyond glibc's fast path), the searches prepared per run (sign changes 400, slip
//! onsets 500, their arccosines and divisions 550, 7 libm calls) and the one integrated period.
//! Since c9e0e1a: the known half angles (a cache of sin and cos of δ/2 at the times every
//! period meets, whose set-up and libm calls cost about 1,400 on the harmonic woodpecker) are
//! set up from a run's second integrated period on, which an orbit that repeats from the first
//! (and is replayed) never reaches: its one period evaluates the arcs from their seed (the last
//! bits of such runs changed; without the cache at all, runs integrated period by period took
//! 13 % more). A kept replayed period's events are written into the event list's reserved room
//! in place (before: a push each, then a copy and a pass over it); two-element arrays are built
//! without `array::map`, which one build left out of line. The random sets' mix of
//! `engine_instructions fingerprint` takes 123.7 M instructions (129.5 M with the cache from
//! the first period, 125.3 M without it). Harmonic woodpecker 50.1× a lean DOPRI5, set B
//! 65.2×: the woodpecker's margin is about 40 instructions, less than what the compiler's
//! layout moves a run between unrelated changes (1–2 %).

use super::accel::SignChanges;
use super::arc::{phase_from, Arc, ArcMotion, KnownAngles, Point, PolyArc, Start, TrigArc};
use super::dd::Dd;
use super::law::{Affine, Basis, Body, ForceLaw, Piece};
use super::replay::{Compact, Outputs, Replay, StartState, Stretch, Tape};
use super::roots::{monotone_zero, Crossing, UpCrossings};
use super::series::Series;
use crate::error::{Error, Result};
use crate::fmath;

/// Events of the first `KEEP_FIRST` and the last `KEEP_LAST` periods are kept; that is all the
/// checks (first cycle) and the steady-state analysis (multiplicity ≤ 4) read, and it bounds
/// memory for runs of up to 10⁶ periods.
const KEEP_FIRST: u32 = 2;
const KEEP_LAST: u32 = 10;
/// Room for this many events per kept period is reserved at the start (two slip-stick cycles
/// with their speed maxima, and two more), so that the list seldom grows during a run.
const EVENTS_RESERVED_PER_PERIOD: usize = 8;
/// A local minimum of s·v below this fraction of the speed before it is a tangential stick:
/// the attainable accuracy of the speed at the located minimum (a sum of terms as large as the
/// speed before it, each rounded, at a zero of a located from the arc's own coefficients), and
/// no more. A minimum above it is a slip that goes on: 1e-13 once declared a stick 1.2e-14
/// above φ_c, where the true minimum is 4.6e-14 of v_M.
const TOUCH_REL: f64 = 16.0 * f64::EPSILON;
/// More transitions than this inside one piece means the state machine cannot advance.
const MAX_TRANSITIONS_PER_PIECE: u32 = 64;
/// Force laws of up to this many pieces are prepared on the stack (the models' have 1 to 4).
const INLINE_PIECES: usize = 4;

/// What happened at an event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EventKind {
    /// Slip onset from rest in direction `dir` (±1).
    Slip { dir: i8 },
    /// Return to rest after slipping in direction `dir`.
    Stick { dir: i8 },
    /// v returned to 0 where |D| > μs N_f: the slip goes on in the other direction.
    Reversal { from: i8, to: i8 },
    /// A local maximum of the speed |v| while slipping.
    SpeedMax,
}

/// One located event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    /// Absolute time (s), t = 0 at the start of the first period.
    pub t: f64,
    /// Index of the period the event falls in.
    pub period: u32,
    pub kind: EventKind,
    /// Position (m) and velocity (m/s) at the event.
    pub x: f64,
    pub v: f64,
}

impl Event {
    /// True for slip, stick and reversal events (not speed maxima).
    pub fn is_transition(&self) -> bool {
        !matches!(self.kind, EventKind::SpeedMax)
    }
}

/// What the body does during a recorded segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    Rest { x: f64 },
    Slide { arc: Arc },
}

/// A piece of the trajectory, [t0, t1] in absolute time (s), for sampling x, v, a.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    pub t0: f64,
    pub t1: f64,
    /// Absolute time of the start of the period the segment lies in (arcs use local time).
    pub period_start: f64,
    pub motion: Motion,
}

/// Options of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunOptions {
    /// Number of periods to integrate.
    pub periods: u32,
    /// Keep every segment of the trajectory (for figures and time series).
    pub record_segments: bool,
    /// Integrate the friction dissipation ∫ μd N_f |v| dt of each period (for the mean friction
    /// power of the steady state); the events do not need it.
    pub dissipation: bool,
}

/// The outcome of an integration.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// Period T (s) and number of periods integrated.
    pub period: f64,
    pub periods: u32,
    /// |D(0)| > μs N_f(0): the body slips at once.
    pub immediate_slip: bool,
    /// Time of the first slip onset (s), if any.
    pub first_slip: Option<f64>,
    /// Events of the first and the last periods, in time order (see `KEEP_FIRST`, `KEEP_LAST`).
    pub events: Vec<Event>,
    /// Position (m) and velocity (m/s) at the start of each period and at the end (periods + 1).
    pub x_at_period_start: Series,
    pub v_at_period_start: Series,
    /// Friction dissipation ∫ μd N_f |v| dt in each period (J); empty unless asked for
    /// ([`RunOptions::dissipation`]).
    pub dissipation: Series,
    /// Recorded segments (empty unless asked for); with [`Replay::Compact`], only up to the
    /// first replayed period ([`Run::state_at`] covers the rest).
    pub segments: Vec<Segment>,
    /// The replayed periods' segments, rebuilt on demand ([`Replay::Compact`]).
    pub compact: Option<Compact>,
}

impl Run {
    /// (x, v, a) at absolute time t from the recorded segments, if t is covered.
    pub fn state_at(&self, t: f64) -> Option<(f64, f64, f64)> {
        let seg = self.segment_at(t)?;
        if t < seg.t0 {
            return None;
        }
        Some(match seg.motion {
            Motion::Rest { x } => (x, 0.0, 0.0),
            Motion::Slide { arc } => {
                let local = t - seg.period_start;
                (arc.x(local), arc.v(local), arc.a(local))
            }
        })
    }

    /// Whether the body is at rest at absolute time t (recorded segments only).
    pub fn stuck_at(&self, t: f64) -> Option<bool> {
        self.segment_at(t)
            .map(|s| matches!(s.motion, Motion::Rest { .. }))
    }

    /// The first recorded segment that ends at or after absolute time t, replayed ones included.
    fn segment_at(&self, t: f64) -> Option<Segment> {
        let i = self.segments.partition_point(|s| s.t1 < t);
        match (self.segments.get(i), &self.compact) {
            (Some(seg), _) => Some(*seg),
            (None, None) => None,
            (None, Some(compact)) => {
                // Segments of periods before m − 1 end before t; a window of the periods around
                // t has the segment the full list would have.
                let m = (t / self.period).floor().clamp(0.0, f64::from(u32::MAX)) as u32;
                let first = m.saturating_sub(1).max(compact.from);
                compact.first_ending_after(
                    first..self.periods.min(m.saturating_add(2)),
                    &self.x_at_period_start,
                    self.period,
                    t,
                )
            }
        }
    }
}

/// (t, x, v, a) of `run` on [t0, t1] (absolute s): `n` uniform points plus the times of the
/// run's events inside the window, in time order. Times the run does not cover are skipped.
pub fn sample(run: &Run, t0: f64, t1: f64, n: usize) -> Vec<[f64; 4]> {
    let mut times: Vec<f64> = (0..n)
        .map(|i| t0 + (t1 - t0) * i as f64 / (n.max(2) - 1) as f64)
        .collect();
    times.extend(
        run.events
            .iter()
            .map(|e: &Event| e.t)
            .filter(|&t| t > t0 && t < t1),
    );
    times.sort_by(f64::total_cmp);
    times
        .into_iter()
        .filter_map(|t| run.state_at(t).map(|(x, v, a)| [t, x, v, a]))
        .collect()
}

/// Keeps the events that are needed and merges a stick and a slip at the same instant.
pub(super) struct Recorder {
    pub(super) events: Vec<Event>,
    /// The first of the last `KEEP_LAST` periods (0 for fewer periods).
    keep_from: u32,
    period: f64,
    snap: f64,
    last_transition: Option<Event>,
    first_slip: Option<f64>,
    /// The steps of the period, recorded for a replay.
    tape: Tape,
}

impl Recorder {
    pub(super) fn keeps(&self, n: u32) -> bool {
        n < KEEP_FIRST || n >= self.keep_from
    }

    /// The periods `0..keeps_first()` are kept, and those from [`Self::keeps_from`] on.
    pub(super) fn keeps_first(&self) -> u32 {
        KEEP_FIRST
    }

    /// The first of the last kept periods.
    pub(super) fn keeps_from(&self) -> u32 {
        self.keep_from
    }

    /// Takes back a slip onset at absolute time `t` that led to no motion.
    pub(super) fn retract_slip(&mut self, t: f64) {
        if let Some(last) = self.events.last() {
            if matches!(last.kind, EventKind::Slip { .. })
                && (last.t - t).abs() <= self.snap * (1.0 + t / self.period)
            {
                self.events.pop();
            }
        }
        if self
            .first_slip
            .is_some_and(|f| (f - t).abs() <= self.snap * (1.0 + t / self.period))
        {
            self.first_slip = None;
        }
        self.last_transition = None;
    }

    /// Whether a stick and a slip onset `gap` (s) after it are two events in every period
    /// before `periods`: the merge tolerance of [`Recorder::push`] in the last of them, twice
    /// over for the rounding of the absolute times.
    pub(super) fn apart(&self, gap: f64, periods: u32) -> bool {
        gap > 2.0 * self.snap * (1.0 + f64::from(periods))
    }

    #[inline(always)]
    pub(super) fn push(&mut self, n: u32, t_local: f64, kind: EventKind, x: f64, v: f64) {
        let t = f64::from(n) * self.period + t_local;
        let mut event = Event {
            t,
            period: n,
            kind,
            x,
            v,
        };
        if let EventKind::Slip { dir } = kind {
            self.first_slip.get_or_insert(t);
            if let Some(last) = self.last_transition {
                let same_instant = (t - last.t).abs() <= self.snap * (1.0 + f64::from(n));
                if let (EventKind::Stick { dir: was }, true) = (last.kind, same_instant) {
                    // A stick and a slip at one instant are one event: a touch (v grazes 0 and
                    // the slip goes on) or a reversal.
                    if self.events.last() == Some(&last) {
                        self.events.pop();
                    }
                    if was == dir {
                        self.last_transition = None;
                        return;
                    }
                    event = Event {
                        kind: EventKind::Reversal { from: was, to: dir },
                        ..last
                    };
                }
            }
        }
        if event.is_transition() {
            self.last_transition = Some(event);
        }
        if self.keeps(event.period) {
            self.events.push(event);
        }
    }
}

/// The result of sliding through (part of) a piece.
struct Slide {
    /// Stick time (s, local), if the body came to rest.
    stick: Option<f64>,
    /// The motion at the stick, or at the end of the piece.
    end: Point,
    /// ∫ N_f |v| dt over the slide (N·m), 0 when not asked for.
    normal_work: f64,
}

/// Absolute time (s) of local time `t` in the period starting at `period_start`, with the
/// period end landing exactly on the next start.
#[inline(always)]
pub(super) fn absolute_time(period_start: f64, next_start: f64, period: f64, t: f64) -> f64 {
    if t >= period {
        next_start
    } else {
        period_start + t
    }
}

/// Integrates `body` under `law` from rest at x = 0, t = 0 for `opts.periods` periods; an orbit
/// that repeats exactly is replayed ([`Replay::Segments`]).
pub fn integrate(body: &Body, law: &ForceLaw, opts: &RunOptions) -> Result<Run> {
    integrate_with(body, law, opts, Replay::Segments)
}

/// [`integrate`], with the periods of an orbit that repeats exactly treated as `replay` says.
pub fn integrate_with(
    body: &Body,
    law: &ForceLaw,
    opts: &RunOptions,
    replay: Replay,
) -> Result<Run> {
    let period = law.period;
    let snap = 8.0 * f64::EPSILON * period;
    let periods = opts.periods;
    let first = &law.pieces[0];
    let immediate_slip = first.drive_at(0.0).abs() > body.mu_s * first.normal_at(0.0);
    let kept_periods = periods.min(KEEP_FIRST + KEEP_LAST) as usize;
    let mut rec = Recorder {
        events: Vec::with_capacity(EVENTS_RESERVED_PER_PERIOD * kept_periods),
        keep_from: periods.saturating_sub(KEEP_LAST),
        period,
        snap,
        last_transition: None,
        first_slip: None,
        tape: Tape::new(replay, opts.record_segments),
    };
    let cap = periods as usize + 1;
    let mut x_at_period_start = Vec::with_capacity(cap);
    let mut v_at_period_start = Vec::with_capacity(cap);
    let mut dissipation = Vec::with_capacity(if opts.dissipation { cap } else { 0 });
    let mut segments = Vec::new();
    let mut compact = None;
    let mut stretch = None;
    // The prepared pieces live on the stack when there are few of them (the models' laws have
    // at most `INLINE_PIECES`): a run then allocates only what it returns. Each is prepared in
    // its place (a prepared piece is a few hundred bytes), after the ones before it.
    let mut inline: [Option<PreparedPiece>; INLINE_PIECES] = [None, None, None, None];
    let mut heap = Vec::new();
    let places: &mut [Option<PreparedPiece>] = if law.pieces.len() <= INLINE_PIECES {
        &mut inline[..law.pieces.len()]
    } else {
        heap.resize_with(law.pieces.len(), || None);
        &mut heap
    };
    for (i, piece) in law.pieces.iter().enumerate() {
        let (earlier, place) = places.split_at_mut(i);
        PreparedPiece::prepare(body, piece, snap, earlier, &mut place[0]);
    }
    let mut state = State {
        x: 0.0,
        v: 0.0,
        dir: 0,
        accel_sign: 0,
        onset_start: None,
        carried: None,
        normal_work: 0.0,
    };

    // The start state of the last period, and whether the pieces know their half angles: they
    // do from the first period that starts in another state than the one before it, which an
    // orbit that repeats from the first never does (the same periods with and without replay).
    let mut last_start = None;
    let mut knows_angles = false;
    for n in 0..periods {
        if rec.tape.repeats() {
            let tape = std::mem::replace(&mut rec.tape, Tape::new(Replay::Off, false));
            let out = Outputs {
                x_at_period_start: &mut x_at_period_start,
                v_at_period_start: &mut v_at_period_start,
                dissipation: opts.dissipation.then_some(&mut dissipation),
                segments: &mut segments,
            };
            (state.x, compact, stretch) = tape.replay((n, periods, period), state.x, &mut rec, out);
            break;
        }
        let start = state.start();
        if !knows_angles && last_start.is_some_and(|last| last != start) {
            places
                .iter_mut()
                .flatten()
                .for_each(PreparedPiece::know_angles);
            knows_angles = true;
        }
        last_start = Some(start);
        let prepared: &[Option<PreparedPiece>] = places;
        rec.tape.begin(start);
        let period_start = f64::from(n) * period;
        let next_start = f64::from(n + 1) * period;
        let absolute = |t: f64| absolute_time(period_start, next_start, period, t);
        // Called only where segments are recorded (the motion, an arc, is not copied otherwise).
        let mut record = |t0: f64, t1: f64, motion: Motion| {
            if t1 > t0 {
                segments.push(Segment {
                    t0: absolute(t0),
                    t1: absolute(t1),
                    period_start,
                    motion,
                });
            }
        };
        x_at_period_start.push(state.x);
        v_at_period_start.push(state.v);
        state.normal_work = 0.0;
        state.carried = None;
        for prepared in prepared.iter().flatten() {
            // The walk compiled for each kind of basis: the phase bookkeeping of a cos basis
            // is absent from a linear one's.
            match prepared.piece.basis {
                Basis::Linear { .. } => walk_piece::<PolyArc>(
                    body,
                    opts,
                    snap,
                    (n, period_start),
                    prepared,
                    &mut state,
                    &mut rec,
                    &mut record,
                )?,
                Basis::Cos { .. } => walk_piece::<TrigArc>(
                    body,
                    opts,
                    snap,
                    (n, period_start),
                    prepared,
                    &mut state,
                    &mut rec,
                    &mut record,
                )?,
            }
        }
        if opts.dissipation {
            dissipation.push(body.mu_d * state.normal_work);
        }
        rec.tape.end(body.mu_d * state.normal_work, state.start());
    }
    let [mut x_at_period_start, mut v_at_period_start, dissipation] =
        Stretch::series(stretch, [x_at_period_start, v_at_period_start, dissipation]);
    x_at_period_start.push(state.x);
    v_at_period_start.push(state.v);
    Ok(Run {
        period,
        periods,
        immediate_slip,
        first_slip: rec.first_slip,
        events: rec.events,
        x_at_period_start,
        v_at_period_start,
        dissipation,
        segments,
        compact,
    })
}

/// The state of the body that a walk through a piece carries on.
#[derive(Clone, Copy)]
struct State<'a> {
    /// Position (m) and velocity (m/s).
    x: f64,
    v: f64,
    /// Direction of slip, 0 when stuck.
    dir: i8,
    /// Sign of s·a on the last slipping stretch, to find speed maxima across pieces.
    accel_sign: i8,
    /// The onset (its crossing, a, N_f) where the slip begins, for the next arc.
    onset_start: Option<(Crossing, f64, f64)>,
    /// The piece, acceleration and N_f at the end of the last arc when the slip goes on into
    /// the next piece of the same period.
    carried: Option<(&'a Piece, f64, f64)>,
    /// ∫ N_f |v| dt in the period so far (when asked for).
    normal_work: f64,
}

impl State<'_> {
    /// What the next period depends on besides x (at a period start, where nothing is carried).
    fn start(&self) -> StartState {
        StartState {
            dir: self.dir,
            v: self.v.to_bits(),
            // Read only while slipping: a slip onset resets it.
            accel_sign: if self.dir == 0 { 0 } else { self.accel_sign },
        }
    }
}

/// Walks the body through one piece of period `n` (starting at `period_start`), with the arcs
/// of kind `M` (the piece's basis).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn walk_piece<'a, M: ArcMotion>(
    body: &Body,
    opts: &RunOptions,
    snap: f64,
    (n, period_start): (u32, f64),
    prepared: &PreparedPiece<'a>,
    state: &mut State<'a>,
    rec: &mut Recorder,
    record: &mut impl FnMut(f64, f64, Motion),
) -> Result<()> {
    let period = rec.period;
    let piece = prepared.piece;
    let mut t = piece.start;
    // (sin ωt, cos ωt) at t on a cos basis where known: at the piece's start, at a stick.
    let mut phase_t = if M::TRIG { prepared.start_phase } else { None };
    let mut transitions = 0;
    let mut retries = 0u32;
    loop {
        transitions += 1;
        if transitions > MAX_TRANSITIONS_PER_PIECE {
            return Err(Error::Stalled {
                t: period_start + t,
                reason: "too many transitions within one piece of the force law",
            });
        }
        if state.dir == 0 {
            let onset = slip_onset::<M>(prepared, t, snap, phase_t);
            let t_end = onset.map_or(piece.end, |(c, _)| c.t.hi);
            if opts.record_segments {
                record(t, t_end, Motion::Rest { x: state.x });
                rec.tape.segment(t, t_end, Motion::Rest { x: state.x });
            }
            let Some((crossing, s)) = onset else { break };
            rec.push(n, crossing.t.hi, EventKind::Slip { dir: s }, state.x, 0.0);
            rec.tape
                .event(crossing.t.hi, EventKind::Slip { dir: s }, None, 0.0, ());
            state.dir = s;
            state.accel_sign = 0;
            t = crossing.t.hi;
            let (a, normal) = prepared.onset_acceleration(body, &crossing, s);
            state.onset_start = Some((crossing, a, normal));
            continue;
        }
        let s = f64::from(state.dir);
        // From an onset, or through a piece boundary (and after a reversal) where the
        // acceleration is Newton's (D − s μd N_f)/M at that instant.
        let (t_start, a_start, normal_start, phase) = match state.onset_start.take() {
            Some((crossing, a, normal)) => (
                crossing.t,
                a,
                normal,
                if M::TRIG { crossing.phase } else { None },
            ),
            None => {
                let (a, normal) = state
                    .carried
                    .take()
                    .and_then(|(prev, a, normal)| carry_over(body, prev, piece, a, normal, s))
                    .unwrap_or_else(|| {
                        let b = phase_t.map_or_else(
                            || piece.basis.eval(t),
                            |(_, cos)| cos - piece.basis.shift(),
                        );
                        let normal = piece.normal.at(b);
                        (body.slip_acceleration(piece.drive.at(b), normal, s), normal)
                    });
                (Dd::from(t), a, normal, phase_t)
            }
        };
        let start = Start {
            t: t_start,
            x: state.x,
            v: state.v,
            a: a_start,
        };
        let slope = prepared.slope[side(state.dir)];
        let arc = M::from_start(piece.basis, slope, start, phase);
        let mut on_max = |tm: f64, at_max: Point| {
            rec.push(n, tm, EventKind::SpeedMax, at_max.x, at_max.v);
            rec.tape
                .event(tm, EventKind::SpeedMax, Some(at_max.dx), at_max.v, ());
        };
        let work_normal = opts.dissipation.then_some(normal_start);
        let slide = slide(
            &arc,
            state.dir,
            prepared,
            work_normal,
            snap,
            &mut state.accel_sign,
            &mut on_max,
        );
        state.normal_work += slide.normal_work;
        let t_end = slide.stick.unwrap_or(piece.end);
        if opts.record_segments {
            record(t, t_end, Motion::Slide { arc: arc.arc() });
            rec.tape.segment(t, t_end, Motion::Slide { arc: arc.arc() });
        }
        let end = slide.end;
        state.x = end.x;
        rec.tape.moved(end.dx);
        match slide.stick {
            // A slip from rest that sticks where it started is shorter than the event
            // resolution (e.g. F ~ 1e-300 N): no motion. Stay stuck past the interval.
            Some(t_stick) if t_stick == t && state.v == 0.0 => {
                rec.retract_slip(f64::from(n) * period + t);
                rec.tape.retract(t);
                state.dir = 0;
                // Where the drive touches the threshold tangentially with μd = μs (φ = 2μs on
                // the harmonic law) a has a double zero at the onset and its sign is lost to
                // rounding for some √ε/ω: the step doubles at each retry (at most twice the
                // last step is skipped, a motion of order ε^(3/2) g/ω²).
                t = (t + snap * f64::from(1u32 << retries.min(30))).min(piece.end);
                retries += 1;
                phase_t = None;
                if t >= piece.end {
                    break;
                }
            }
            Some(t_stick) => {
                state.v = 0.0;
                rec.push(
                    n,
                    t_stick,
                    EventKind::Stick { dir: state.dir },
                    state.x,
                    0.0,
                );
                rec.tape
                    .event(t_stick, EventKind::Stick { dir: state.dir }, None, 0.0, ());
                state.dir = 0;
                t = t_stick;
                phase_t = if M::TRIG { end.phase } else { None };
            }
            None => {
                state.v = end.v;
                let normal_end = normal_start + piece.normal.c1 * end.db;
                state.carried = Some((piece, end.a, normal_end));
                break;
            }
        }
    }
    Ok(())
}

/// A piece of the force law with what a run computes once for it: the same in every period.
struct PreparedPiece<'a> {
    piece: &'a Piece,
    /// (sin θ, cos θ) of the phase θ = ω·start of the piece's start on a cos basis, for the
    /// arcs and the searches for a slip onset that start there.
    start_phase: Option<(f64, f64)>,
    /// On a cos basis: cos(ω·end), the double ω·end as [`fmath::cos`](crate::fmath::cos) gives
    /// it; the next piece starts there.
    end_cos: Option<f64>,
    /// Per direction of slip (+1, −1, see [`side`]): the slip onsets; none where the switching
    /// function stays below zero over the piece.
    onsets: [Option<Onsets>; 2],
    /// Per direction of slip: the slope A1 of the acceleration in the basis while slipping
    /// ([`Body::slip_acceleration_affine`]).
    slope: [f64; 2],
    /// Per direction of slip, on a cos basis: where the acceleration changes sign on the piece
    /// (the same for every arc in that direction).
    accel: [SignChanges; 2],
    /// On a cos basis: the half angles δ/2 (with their sin and cos) of the arcs that start at
    /// the piece's start or at a located slip onset, at the end of the piece and at the zeros
    /// of the acceleration: the same in every period, where a slide evaluates its arc. None
    /// until the run's second integrated period ([`PreparedPiece::know_angles`]), and on a
    /// linear basis (not set up: it is a few hundred bytes).
    known: Option<KnownAngles>,
}

/// The slip onsets in one direction s on one piece: the up-crossings of the switching function
/// g = s·D − μs·N_f, and the acceleration and N_f at its located root
/// ([`onset_acceleration`]), if it has one.
type Onsets = (UpCrossings, Option<(f64, f64)>);

/// The index of direction `dir` (±1) in the per-direction arrays of [`PreparedPiece`].
#[inline]
fn side(dir: i8) -> usize {
    usize::from(dir < 0)
}

impl PreparedPiece<'_> {
    /// Prepares `piece` in `place`: its start's phase and the searches for a slip onset in either direction.
    /// A direction in which g stays below zero by more than its rounding over the whole range of
    /// the basis over the piece, widened by `snap` before its start ([`Piece::basis_range`]),
    /// is not searched (the direction opposite to the drive). From the pieces prepared before
    /// it (`earlier`, in order): the sign changes of the acceleration where one has them
    /// ([`PreparedPiece::accel_of_same`]), and cos ωt at its start where the last one ends
    /// there on the same basis (sin and cos of a boundary are evaluated once per run).
    #[inline(always)]
    fn prepare<'a>(
        body: &Body,
        piece: &'a Piece,
        snap: f64,
        earlier: &[Option<PreparedPiece<'a>>],
        place: &mut Option<PreparedPiece<'a>>,
    ) {
        // On a cos basis: (sin, cos) of ω·start and cos of ω·end.
        let trig = match piece.basis {
            Basis::Linear { .. } => None,
            Basis::Cos { omega, .. } => {
                let carried = earlier.last().and_then(|last| {
                    let last = last.as_ref()?;
                    let same_basis = matches!(last.piece.basis,
                        Basis::Cos { omega: o, .. } if o.to_bits() == omega.to_bits());
                    (same_basis && last.piece.end.to_bits() == piece.start.to_bits())
                        .then_some(last.end_cos)
                        .flatten()
                });
                let theta = omega * piece.start;
                let cos_start = carried.unwrap_or_else(|| fmath::cos(theta));
                Some((
                    (fmath::sin(theta), cos_start),
                    fmath::cos(omega * piece.end),
                ))
            }
        };
        let (b_min, b_max) = piece.basis_range_from(
            snap,
            trig.map_or((0.0, 0.0), |((_, cos_start), cos_end)| (cos_start, cos_end)),
        );
        let accel = Self::accel_of_same(earlier, piece);
        let same = Self::earlier_like(earlier, piece, 1.0);
        let slope = |s: f64| {
            body.slip_acceleration_affine(piece.drive, piece.normal, s)
                .c1
        };
        // On a cos basis the zeros of a are located once, in two parts; on a linear one each
        // arc finds its own (see [`ArcMotion::sign_changes`]).
        let sign_changes = |s: f64| match piece.basis {
            Basis::Linear { .. } => SignChanges::UNKNOWN,
            Basis::Cos { omega, shift } => {
                // s·a = h/M with h = s·D − μd·N_f, formed exactly as the switching function is.
                let h = Affine::combine(s, piece.drive, -body.mu_d, piece.normal);
                let exact = || {
                    let coefficient = |d: f64, n: f64| Dd::from(s * d) + Dd::prod(-body.mu_d, n);
                    (
                        coefficient(piece.drive.c0, piece.normal.c0),
                        coefficient(piece.drive.c1, piece.normal.c1),
                    )
                };
                SignChanges::cos(omega, shift, h, exact)
            }
        };
        let accel = [
            accel[0].unwrap_or_else(|| sign_changes(1.0)),
            accel[1].unwrap_or_else(|| sign_changes(-1.0)),
        ];
        let prepared = place.insert(PreparedPiece {
            piece,
            start_phase: match (piece.basis, trig) {
                (Basis::Cos { omega, .. }, Some((start, _))) => {
                    Some(phase_from(omega, Dd::from(piece.start), start))
                }
                _ => None,
            },
            end_cos: trig.map(|(_, end)| end),
            onsets: [None, None],
            slope: [slope(1.0), slope(-1.0)],
            accel,
            known: None,
        });
        for (place, s) in prepared.onsets.iter_mut().zip([1, -1]) {
            *place = Self::onsets(body, piece, s, (b_min, b_max), snap, same);
        }
    }

    /// Sets up the known half angles of a piece on a cos basis (see [`PreparedPiece::known`]).
    /// A run does so from its second integrated period on (see [`integrate_with`]): an orbit that
    /// repeats from the first is replayed and meets each angle once, where the cache's set-up
    /// and its sin and cos cost more than the arcs' own evaluation from their seed.
    fn know_angles(&mut self) {
        let piece = self.piece;
        // The kernels are a function of the angle only: one list serves the arcs in either
        // direction. The most used first (a full list drops the rest): from the piece's start
        // and from the located onsets to the end of the piece, then to the zeros of a.
        if let Basis::Cos { omega, .. } = piece.basis {
            let known = self.known.insert(KnownAngles::new());
            let roots = self.onsets.iter().flat_map(|onsets| match onsets {
                Some((crossings, _)) => crossings.crossings(),
                None => [None, None],
            });
            let mut starts = [None; 5];
            starts[0] = Some(Dd::from(piece.start));
            for (place, root) in starts[1..].iter_mut().zip(roots) {
                *place = root.map(|c| c.t);
            }
            let zeros = self.accel.iter().flat_map(|a| a.zeros());
            let ends = std::iter::once(piece.end).chain(zeros);
            for end in ends.filter(|&end| end > piece.start && end <= piece.end) {
                for t_c in starts.into_iter().flatten() {
                    if t_c.hi < end {
                        known.push_between(omega, t_c, end);
                    }
                }
            }
        }
    }

    /// The sign changes of the acceleration per direction where an `earlier` piece has them
    /// (they are a function of the basis, drive and normal force alone, over all time, not of
    /// the piece's span): one with the same basis, drive and normal force as `piece`, bit for
    /// bit (the woodpecker's lobes before and after the middle one), has the same; one whose
    /// normal force is `piece`'s negated bit for bit (the middle lobe: N_f = 2λ|F_e| with F_e
    /// of the other sign) has h = s·D − μd·N_f in direction −s that is −h in direction s: the
    /// same zeros with the opposite signs ([`SignChanges::negated`]).
    /// On a linear basis there is nothing to share ([`SignChanges::UNKNOWN`]).
    #[inline]
    fn accel_of_same(earlier: &[Option<PreparedPiece>], piece: &Piece) -> [Option<SignChanges>; 2] {
        if let Some(same) = Self::earlier_like(earlier, piece, 1.0) {
            return same.accel.map(Some);
        }
        Self::earlier_like(earlier, piece, -1.0).map_or([None, None], |flipped| {
            [flipped.accel[1].negated(), flipped.accel[0].negated()]
        })
    }

    /// An `earlier` piece on the same cos basis as `piece` with the same drive and the normal
    /// force times `normal` (±1), bit for bit; none on a linear basis.
    #[inline]
    fn earlier_like<'e, 'a>(
        earlier: &'e [Option<PreparedPiece<'a>>],
        piece: &Piece,
        normal: f64,
    ) -> Option<&'e PreparedPiece<'a>> {
        if let Basis::Linear { .. } = piece.basis {
            return None;
        }
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        let like = |p: &Piece| match (p.basis, piece.basis) {
            (Basis::Cos { omega, shift }, Basis::Cos { omega: o, shift: h }) => {
                same(omega, o)
                    && same(shift, h)
                    && same(p.drive.c0, piece.drive.c0)
                    && same(p.drive.c1, piece.drive.c1)
                    && same(normal * p.normal.c0, piece.normal.c0)
                    && same(normal * p.normal.c1, piece.normal.c1)
            }
            _ => false,
        };
        earlier.iter().flatten().find(|p| like(p.piece))
    }

    /// The slip onsets in direction `s` on `piece`, whose basis stays within `b_range` (see
    /// [`PreparedPiece::prepare`]); inlined into the place they are stored in. Those of an
    /// earlier piece with the same basis, drive and normal force (`same`) are `piece`'s with
    /// its end ([`UpCrossings::ending_at`]), with the same acceleration at the root.
    #[inline(always)]
    fn onsets(
        body: &Body,
        piece: &Piece,
        s: i8,
        (b_min, b_max): (f64, f64),
        snap: f64,
        same: Option<&PreparedPiece>,
    ) -> Option<Onsets> {
        // g > 0 ⇔ the static friction cannot hold the body in direction s.
        let sf = f64::from(s);
        let g = Affine::combine(sf, piece.drive, -body.mu_s, piece.normal);
        let (g_lo, g_hi) = (g.at(b_min), g.at(b_max));
        let rounding =
            8.0 * f64::EPSILON * (g.c0.abs() + (g.c1 * b_min.abs().max(b_max.abs())).abs());
        if g_lo.max(g_hi) < -rounding {
            return None;
        }
        if let Some(shared) = same.and_then(|same| {
            let (crossings, at_root) = same.onsets[side(s)]?;
            Some((crossings.ending_at(piece.end, snap)?, at_root))
        }) {
            return Some(shared);
        }
        let exact = || {
            let coefficient = |d: f64, n: f64| Dd::from(sf * d) + Dd::prod(-body.mu_s, n);
            (
                coefficient(piece.drive.c0, piece.normal.c0),
                coefficient(piece.drive.c1, piece.normal.c1),
            )
        };
        let crossings = UpCrossings::new(piece.basis, g, exact, piece.end, snap);
        // Every located root of g has the same basis value, and so the same onset.
        let at_root = crossings
            .root()
            .map(|c| onset_acceleration(body, piece, &c, sf));
        Some((crossings, at_root))
    }

    /// [`onset_acceleration`] at a slip onset `c` in direction `s` on this piece.
    #[inline]
    fn onset_acceleration(&self, body: &Body, c: &Crossing, s: i8) -> (f64, f64) {
        match self.onsets[side(s)] {
            Some((_, Some(at_root))) if c.root_b.is_some() => at_root,
            _ => onset_acceleration(body, self.piece, c, f64::from(s)),
        }
    }
}

/// Earliest slip onset in [from, piece.end) from rest, with its direction. The switching
/// function g = s·D − μs·N_f is formed exactly (in two parts), so that its root is located to
/// better than its ulp (see [`PreparedPiece::prepare`]). `phase` is (sin ωt, cos ωt) at `from` on a
/// cos basis where known. `M`, the kind of arc of the piece's basis, is not used: it makes one
/// copy per kind, each inlined or not into its walk on its own (shared, it was called out of
/// line from both).
#[allow(clippy::extra_unused_type_parameters)]
#[inline]
fn slip_onset<M: ArcMotion>(
    prepared: &PreparedPiece,
    from: f64,
    snap: f64,
    phase: Option<(f64, f64)>,
) -> Option<(Crossing, i8)> {
    let first = |onset: &Option<Onsets>| {
        let (crossings, _) = onset.as_ref()?;
        crossings.first(from, snap, phase)
    };
    let [up, down] = &prepared.onsets;
    // The earlier of the two, the upward one at a tie.
    match (first(up), first(down)) {
        (Some(u), Some(d)) if d.t.value().total_cmp(&u.t.value()).is_lt() => Some((d, -1)),
        (Some(u), _) => Some((u, 1)),
        (None, d) => d.map(|d| (d, -1)),
    }
}

/// The acceleration (m/s²) and the normal force N_f (N) at a slip onset in direction s, formed
/// without cancellation. With g = s·D − μs·N_f ≥ 0 at the onset, Newton's a = (D − s μd N_f)/M
/// is
///
/// ```text
/// a = s [g + (μs − μd) N_f] / M
/// ```
///
/// At a located root g = 0 exactly, so a = s (μs − μd) N_f/M: exactly 0 when μd = μs (not a
/// rounding-negative difference of O(μd g) terms that would stop the slip where it starts), and
/// of the right size when the slip is short. N_f there is evaluated from the root's basis value
/// in two parts, either directly or as s·D/μs, whichever is formed with less cancellation.
/// Where the body slips at once, g > 0 is evaluated at the instant.
fn onset_acceleration(body: &Body, piece: &Piece, c: &Crossing, s: f64) -> (f64, f64) {
    let (g, normal) = match c.root_b {
        Some(b) => {
            // (value, sum of the magnitudes of its terms) of an affine function at b.
            let at = |f: Affine| {
                (
                    f.c1.mul_add(b.hi, f.c0) + f.c1 * b.lo,
                    f.c0.abs() + (f.c1 * b.hi).abs(),
                )
            };
            let (n, n_terms) = at(piece.normal);
            let (d, d_terms) = at(piece.drive);
            let from_drive = body.mu_s > 0.0 && d_terms * n.abs() < n_terms * d.abs();
            (0.0, if from_drive { s * d / body.mu_s } else { n })
        }
        None => {
            let b = c.phase.map_or_else(
                || piece.basis.eval(c.t.hi),
                |(_, cos)| cos - piece.basis.shift(),
            );
            let normal = piece.normal.at(b);
            let g = s * piece.drive.at(b) - body.mu_s * normal;
            (g.max(0.0), normal)
        }
    };
    let normal = normal.max(0.0);
    (
        s * (g + (body.mu_s - body.mu_d) * normal) / body.mass,
        normal,
    )
}

/// The acceleration and N_f at the start of `next` where the slip goes on from the end of `prev`
/// with acceleration `a` and normal force `normal` (both formed relative to the slip, see
/// [`onset_acceleration`]), when the two pieces share the basis and the drive and N_f only
/// changes the sign of its formula (N_f = 2λ|F_e| at a zero of F_e): N_f there is a tiny number
/// that the coefficients give only to eps times their size, and the arc before gives to eps of
/// the slip. Then a' = a − s μd (N_f' − N_f)/M.
fn carry_over(
    body: &Body,
    prev: &Piece,
    next: &Piece,
    a: f64,
    normal: f64,
    s: f64,
) -> Option<(f64, f64)> {
    let flipped = Affine::new(-prev.normal.c0, -prev.normal.c1);
    if prev.basis != next.basis || prev.drive != next.drive {
        None
    } else if next.normal == prev.normal {
        Some((a, normal))
    } else if next.normal == flipped {
        Some((a + 2.0 * s * body.mu_d * normal / body.mass, -normal))
    } else {
        None
    }
}

/// Slides along `arc` from its start to the end of the piece or to the first stick. The
/// interval is split at the zeros of a, so that s·v is monotone on each part; a speed maximum is
/// reported where s·a changes from + to −, a stick where s·v reaches 0 (or grazes it at a zero of
/// a). `normal_start` is N_f at the start of the arc, given when the friction work is asked for.
fn slide<M: ArcMotion>(
    arc: &M,
    dir: i8,
    prepared: &PreparedPiece,
    normal_start: Option<f64>,
    snap: f64,
    accel_sign: &mut i8,
    mut on_max: impl FnMut(f64, Point),
) -> Slide {
    let (s, piece) = (f64::from(dir), prepared.piece);
    let known = prepared.known.as_ref();
    let accel = arc.sign_changes(s, &prepared.accel[side(dir)]);
    let from = arc.t_start();
    // Zeros of a strictly after `from`: a slip shorter than the event resolution still makes
    // progress instead of sticking where it started. From rest, a zero within `snap` of the
    // start is the onset itself (μd = μs: a = 0 there).
    let after = if arc.v_start() == 0.0 {
        from + snap
    } else {
        from
    };
    let mut bounds = [piece.end; 3];
    let mut count = 0;
    for zero in accel.zeros() {
        if zero > after && zero < piece.end {
            bounds[count] = zero;
            count += 1;
        }
    }
    bounds[count] = piece.end;
    let bounds = &bounds[..=count];
    let mut p = from;
    // s·v at p when known (at the start it is the arc's initial speed), to evaluate it once.
    let mut speed_p = Some(s * arc.v_start());
    let mut stick = None;
    // A located stick refined as the time since the arc's start, with the motion there.
    let mut refined = None;
    // The half angle of the last evaluation on a trigonometric arc, from which the root search
    // steps on without sin and cos.
    let mut seed = None;
    // The half angle of the stick search's first iterate on a trigonometric arc, from which the
    // later ones and the stick turn by little.
    let mut iterate = None;
    for (i, &q) in bounds.iter().enumerate() {
        // The sign of s·a on (p, q), from the zeros of a: just after `after` on the first part,
        // just after the zero p on the others.
        let sign = accel.sign_after(if i == 0 { after } else { p });
        let at_max = *accel_sign > 0 && sign < 0;
        if sign != 0 {
            *accel_sign = sign;
        }
        if sign >= 0 {
            (p, speed_p) = (q, None);
            continue;
        }
        let mut point_p = || arc.at_near(p, &mut seed, known);
        let at_p = if at_max {
            let point = arc.at_accel_zero(p).unwrap_or_else(point_p);
            on_max(p, point);
            speed_p.unwrap_or(s * point.v)
        } else {
            speed_p.unwrap_or_else(|| s * point_p().v)
        };
        let point_q = arc.at_near(q, &mut seed, known);
        let at_q = s * point_q.v;
        let at_zero_of_a = i + 1 < bounds.len();
        stick = if at_p <= 0.0 {
            Some(p)
        } else if at_q <= 0.0 {
            let f = |t: f64| {
                // The iterates are no piece's known times.
                let at = arc.at_iterate(t, &mut seed, &mut iterate);
                (s * at.v, s * at.a, s * at.jerk)
            };
            let hi = (at_q, s * point_q.a, s * point_q.jerk);
            let t = monotone_zero(f, (p, at_p), (q, hi), M::TRIG);
            refined = arc.stick_in_w(t);
            Some(t)
        } else if at_zero_of_a && at_q <= TOUCH_REL * at_p {
            Some(q)
        } else {
            None
        };
        if stick.is_some() {
            break;
        }
        (p, speed_p) = (q, Some(at_q));
    }
    // v keeps its sign over the whole slide, so the friction work is one integral.
    let end = stick.unwrap_or(piece.end);
    if let Some((w, mut point)) = refined {
        // At rest: the refined root's own speed is rounding.
        point.v = 0.0;
        return Slide {
            stick,
            end: point,
            normal_work: normal_start.map_or(0.0, |n_c| {
                arc.integrate_normal_times_speed_w(n_c, piece.normal.c1, w)
                    .unwrap_or_else(|| arc.integrate_normal_times_speed(n_c, piece.normal.c1, end))
            }),
        };
    }
    Slide {
        stick,
        end: if iterate.is_some() {
            arc.at_iterate(end, &mut seed, &mut iterate)
        } else {
            arc.at_near(end, &mut seed, known)
        },
        normal_work: normal_start.map_or(0.0, |n_c| {
            arc.integrate_normal_times_speed(n_c, piece.normal.c1, end)
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::woodpecker::{self, WoodpeckerParams};
    use crate::models::LawKind;
    use rand::{rngs::StdRng, Rng, SeedableRng};

    /// A recorded period of length 1 s with the given steps (local times).
    fn tape(steps: &[(f64, Option<EventKind>)]) -> Tape {
        let mut tape = Tape::new(Replay::Compact, false);
        tape.begin(StartState {
            dir: 0,
            v: 0,
            accel_sign: 0,
        });
        for &(t, kind) in steps {
            match kind {
                Some(kind) => tape.event(t, kind, None, 0.0, ()),
                None => tape.retract(t),
            }
        }
        tape
    }

    /// The replay appends a period's events directly only where the recorder would keep them
    /// as they come: not with a slip onset taken back, nor with a stick and a slip onset at one
    /// instant in any period (the tolerance grows with the period's index), within the period
    /// or across its end.
    #[test]
    fn replayed_events_skip_the_recorder_only_where_it_would_merge_or_retract_none() {
        let rec = Recorder {
            events: Vec::new(),
            keep_from: 990,
            period: 1.0,
            snap: 8.0 * f64::EPSILON,
            last_transition: None,
            first_slip: None,
            tape: Tape::new(Replay::Compact, false),
        };
        let (slip, stick, max) = (
            Some(EventKind::Slip { dir: 1 }),
            Some(EventKind::Stick { dir: 1 }),
            Some(EventKind::SpeedMax),
        );
        // Two slip-stick cycles: the second slip onset `gap` after the first stick, the last
        // stick at `end`.
        let cycles = |gap: f64, end: f64| {
            tape(&[
                (0.0, slip),
                (0.2, max),
                (0.4, stick),
                (0.4 + gap, slip),
                (0.6, max),
                (end, stick),
            ])
        };
        let direct = |tape: &Tape, periods| tape.only_kept_events(&rec, 1.0, periods);
        assert!(direct(&cycles(0.1, 0.8), 1000));
        assert!(direct(&tape(&[(0.3, max)]), 1000));
        // A stick and a slip onset 1e-13 s apart are one event from period 56 on (snap·57 >
        // 1e-13); the check keeps a margin of two.
        assert!(direct(&cycles(1e-13, 0.8), 20));
        assert!(!direct(&cycles(1e-13, 0.8), 60));
        assert!(!direct(&cycles(0.0, 0.8), 2));
        // The last stick at the period's end and the next period's first slip onset.
        assert!(!direct(&cycles(0.1, 1.0), 2));
        assert!(!direct(&tape(&[(0.1, slip), (0.1, None), (0.3, slip)]), 2));
    }

    /// `piece` prepared after `earlier`.
    fn prepared<'a>(
        body: &Body,
        piece: &'a Piece,
        snap: f64,
        earlier: &[Option<PreparedPiece<'a>>],
    ) -> Option<PreparedPiece<'a>> {
        let mut place = None;
        PreparedPiece::prepare(body, piece, snap, earlier, &mut place);
        place
    }

    /// Random pieces with the woodpecker's shape on a cos basis: the lobes' normal force is the
    /// middle one's negated, and their sign changes taken from the middle one negated are those
    /// located from scratch, bit for bit; so is a piece's start phase, its cos taken from the
    /// piece before.
    #[test]
    fn shared_sign_changes_and_boundary_cosines_are_located_ones() {
        let mut rng = StdRng::seed_from_u64(31);
        let mut shared = 0;
        for i in 0..2000 {
            let body = Body {
                mass: rng.gen_range(0.001..1.0),
                mu_s: rng.gen_range(0.1..1.0),
                mu_d: rng.gen_range(0.05..0.6),
            };
            let (omega, shift) = (rng.gen_range(1.0..100.0), rng.gen_range(-0.99..0.99));
            let (f1, friction) = (rng.gen_range(-1.0..1.0), rng.gen_range(0.1..5.0));
            let (w, f0) = (rng.gen_range(0.0..0.5), if i % 2 == 0 { 0.0 } else { 0.1 });
            let basis = Basis::Cos { omega, shift };
            let period = std::f64::consts::TAU / omega;
            let cut = rng.gen_range(0.1..0.9) * period;
            let piece = |start: f64, end: f64, sign: f64| Piece {
                start,
                end,
                basis,
                drive: Affine::new(w + f0, f1),
                normal: Affine::new(sign * friction * f0, sign * friction * f1),
            };
            let pieces = [piece(0.0, cut, -1.0), piece(cut, period, 1.0)];
            let snap = 8.0 * f64::EPSILON * period;
            let [first, alone] = [0, 1].map(|i| prepared(&body, &pieces[i], snap, &[]));
            let after = prepared(&body, &pieces[1], snap, &[first]);
            shared +=
                PreparedPiece::accel_of_same(&[prepared(&body, &pieces[0], snap, &[])], &pieces[1])
                    .iter()
                    .flatten()
                    .count();
            let (alone, after) = (alone.expect("prepared"), after.expect("prepared"));
            assert_eq!(format!("{:?}", alone.accel), format!("{:?}", after.accel));
            let bits = |p: Option<(f64, f64)>| p.map(|(s, c)| (s.to_bits(), c.to_bits()));
            assert_eq!(bits(alone.start_phase), bits(after.start_phase));
        }
        assert!(shared > 1000, "only {shared} directions shared");
        // The model's law: the middle lobe takes the first one's, negated.
        let p = WoodpeckerParams::default();
        let law = woodpecker::force_law(&p, LawKind::Harmonic).expect("a valid law");
        let body = woodpecker::body(&p);
        let first = prepared(&body, &law.pieces[0], 1e-16, &[]);
        let shared = PreparedPiece::accel_of_same(&[first], &law.pieces[1]);
        assert!(shared.iter().any(Option::is_some));
    }
}
