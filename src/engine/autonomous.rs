//! Autonomous dry friction on a moving surface: a body whose driving force is affine in its
//! position, D(x) = D0 + c·x with c < 0 (a spring), under a constant friction-bearing normal
//! force N_f, on a surface that moves at a constant speed v_s (a belt). The force does not
//! depend on time, so there is no forcing period: the run goes from event to event and the
//! cycle, with its period, is found from the events ([`SurfaceCycle`]).
//!
//! ```text
//! STUCK (v = v_s)   x = x0 + v_s (t − t0);  leaves when |D(x)| > μs N_f   → SLIP, s = sgn D(x)
//! SLIP  (s = ±1)    M dv/dt = D0 + c x − s μd N_f = c (x − x_eq),  x_eq = (s μd N_f − D0)/c
//!                   leaves when s·(v − v_s) reaches 0: STUCK if |D(x)| ≤ μs N_f, else SLIP
//! ```
//!
//! s is the direction of the slip relative to the surface (the sign of v − v_s), so kinetic
//! friction −s μd N_f opposes the relative motion; with v_s = 0 this is the engine of
//! [`super::run`] for a force affine in x. On a slip the motion is a harmonic arc about x_eq
//! with ω = √(−c/M) ([`HarmonicArc`]), known in closed form: no step size. Its events are
//! located by bracketed root finding ([`super::roots::monotone_zero`]) on the intervals between
//! the zeros of the acceleration, on which v is monotone, to about 1e-15 relative. The slip
//! onset of a stick is the root of an affine function of x: exact up to one rounding.
//!
//! The friction's ledger is kept exactly too: the heat ∫ μd N_f |v − v_s| dt of each slip and
//! the work ∫ f v_s dt the surface does through the friction force f on the body (what drives
//! a belt), both from the arc's closed form.
//!
//! The cycle and its replay ([`super::replay`], the mechanism of the forced models' periods).
//! The run is integrated in local time: a cycle runs from a slip onset (τ = 0) to the next, its
//! events and segments are placed at t_n + τ, and its ledger at L_n + ℓ(τ), where (t_n, L_n)
//! is the onset's time and ledger. The motion after an onset depends only on the onset's
//! state, so an onset that repeats the state of the previous one, bit for bit, starts a cycle
//! that repeats the previous one event for event. The state compared is the direction s, x
//! and y = x − x_eq (with v = v_s at every onset): an onset reached while carried is at
//! x_on = (s μs N_f − D0)/c with y = s (μs − μd) N_f/c, both formed from the law's constants
//! alone, so every such onset has the same bits and the cycle is found at the second onset
//! (an immediate onset, where |D| exceeds μs N_f at a stick, only happens in a transient: each
//! one lowers the excess by 2 μd N_f, and after a carried onset the stick is at
//! |D| = |2 μd − μs| N_f ≤ μs N_f). From then on, with k the recorded cycle and T its length
//! in local time,
//!
//! ```text
//! t_n = t_k + (n − k)·T,   L_n = L_k + (n − k)·ΔL,   event = (t_n + τ, x, v, L_n + ℓ)
//! ```
//!
//! in every mode: with [`Replay::Off`] each cycle is integrated and placed so, and its local
//! offsets are the recorded ones bit for bit (tests/replay.rs), otherwise the recorded cycle
//! is replayed. The period, the offsets within a cycle and the ledger over it
//! ([`SurfaceCycle`]) carry their full relative precision however late the cycle starts.

use super::law::Body;
use super::replay::{Op, Replay, Tape};
use super::roots::monotone_zero;
use super::run::{Event, EventKind};
use crate::error::{Error, Result};
use crate::fmath;

/// A local extremum of s·(v − v_s) below this fraction of the arc's speed scale is a
/// tangential stick (a touch): the attainable accuracy of the relative speed, a sum of terms
/// as large as the scale, each rounded (as `TOUCH_REL` of [`super::run`]).
const TOUCH_REL: f64 = 16.0 * f64::EPSILON;
/// A zero of the acceleration this close to the start of an arc (rad) is the start itself.
const START_ANGLE: f64 = 8.0 * f64::EPSILON;
/// More events than this in one run is a run that cannot advance.
const MAX_EVENTS: usize = 1 << 20;

/// The forces of an autonomous system: one piece, affine in the position, on a surface moving
/// at constant speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceLaw {
    /// Driving force at x = 0, D0 (N).
    pub drive: f64,
    /// dD/dx, c (N/m): −k for a spring of constant k. Negative: the slips are harmonic arcs.
    pub stiffness: f64,
    /// Friction-bearing normal force N_f ≥ 0 (N), constant.
    pub normal: f64,
    /// Speed v_s of the surface the body sticks to (m/s).
    pub surface_speed: f64,
}

impl SurfaceLaw {
    /// Checks that the coefficients are finite, c < 0 and N_f ≥ 0.
    pub fn new(drive: f64, stiffness: f64, normal: f64, surface_speed: f64) -> Result<Self> {
        let finite = [drive, stiffness, normal, surface_speed]
            .iter()
            .all(|c| c.is_finite());
        // Finite coefficients compare as numbers (no NaN left).
        if !finite || stiffness >= 0.0 || normal < 0.0 {
            return Err(Error::InvalidLaw(format!(
                "a surface law needs finite coefficients, dD/dx = {stiffness} N/m < 0 and \
                 N_f = {normal} N >= 0"
            )));
        }
        Ok(Self {
            drive,
            stiffness,
            normal,
            surface_speed,
        })
    }

    /// D(x) = D0 + c·x (N).
    #[inline]
    pub fn force(&self, x: f64) -> f64 {
        self.drive + self.stiffness * x
    }
}

/// A harmonic arc of a slip in direction `dir` from (t_c, x_c, v_c):
///
/// ```text
/// x = x_c − y_c (1 − cos δ) + (v_c/ω) sin δ,   v = v_c − v_c (1 − cos δ) − y_c ω sin δ,
/// a = −ω² (x − x_eq),   δ = ω (t − t_c),   y_c = x_c − x_eq
/// ```
///
/// written from the start (1 − cos δ = 2 sin² δ/2), so that a short arc keeps the digits of
/// its small motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HarmonicArc {
    /// Start time (s, absolute), position (m) and velocity (m/s).
    pub t_c: f64,
    pub x_c: f64,
    pub v_c: f64,
    /// x_c − x_eq (m), formed without cancellation at a slip onset.
    pub y_c: f64,
    /// ω = √(−c/M) (rad/s).
    pub omega: f64,
    /// Speed of the surface (m/s).
    pub surface_speed: f64,
    /// Direction of the slip relative to the surface (±1).
    pub dir: i8,
}

/// The motion on an arc at one angle δ = ω (t − t_c).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcPoint {
    /// Position (m), velocity (m/s), acceleration (m/s²).
    pub x: f64,
    /// x − x_c (m): x is x_c + dx, so that a replayed event at x_c + dx has x's bits.
    pub dx: f64,
    pub v: f64,
    pub a: f64,
    /// v − v_s (m/s), formed from the start without the cancellation of v − v_s.
    pub relative: f64,
}

impl HarmonicArc {
    /// The motion at angle δ (rad).
    pub fn at_angle(&self, delta: f64) -> ArcPoint {
        let (sin, half) = (fmath::sin(delta), fmath::sin(0.5 * delta));
        let one_minus_cos = 2.0 * half * half;
        let HarmonicArc {
            x_c,
            v_c,
            y_c,
            omega,
            surface_speed,
            ..
        } = *self;
        let y = y_c - y_c * one_minus_cos + v_c / omega * sin;
        let dx = v_c / omega * sin - y_c * one_minus_cos;
        ArcPoint {
            x: x_c + dx,
            dx,
            v: v_c - v_c * one_minus_cos - y_c * omega * sin,
            a: -omega * omega * y,
            relative: (v_c - surface_speed) - v_c * one_minus_cos - y_c * omega * sin,
        }
    }

    /// The motion at absolute time t (s).
    pub fn at(&self, t: f64) -> ArcPoint {
        self.at_angle(self.omega * (t - self.t_c))
    }

    /// s·(v − v_s) at δ with its first two derivatives in δ.
    fn slip_speed(&self, delta: f64) -> (f64, f64, f64) {
        let s = f64::from(self.dir);
        let (sin, cos) = fmath::sin_cos(delta);
        let p = self.at_angle(delta);
        let w = self.y_c * self.omega;
        (
            s * p.relative,
            s * (-self.v_c * sin - w * cos),
            s * (-self.v_c * cos + w * sin),
        )
    }

    /// The first zero of the acceleration after the start (rad), beyond [`START_ANGLE`]:
    /// x − x_eq = R cos(δ − ψ) vanishes at δ = ψ + π/2 + jπ.
    fn first_accel_zero(&self) -> f64 {
        let psi = fmath::atan2(self.v_c / self.omega, self.y_c);
        let pi = std::f64::consts::PI;
        let z = (psi + 0.5 * pi).rem_euclid(pi);
        if z <= START_ANGLE {
            z + pi
        } else {
            z
        }
    }

    /// The scale of the speeds on the arc (m/s): for the touch tolerance.
    fn speed_scale(&self) -> f64 {
        self.v_c
            .abs()
            .max(self.surface_speed.abs())
            .max((self.y_c * self.omega).abs())
    }

    /// Walks the arc to the first stick: the angles δ (rad) of the local maxima of the slip
    /// speed s·(v − v_s) passed on the way, and the angle of the stick; `None` when the slip
    /// never ends (v_s is outside the arc's range of speeds: the slip is a harmonic
    /// oscillation forever). s·(v − v_s) is monotone between zeros of a; three such intervals
    /// cover more than a full turn.
    pub fn stick(&self) -> (Vec<f64>, Option<f64>) {
        let pi = std::f64::consts::PI;
        let touch = TOUCH_REL * self.speed_scale();
        let first = self.first_accel_zero();
        let mut maxima = Vec::new();
        let (mut p, mut at_p) = (0.0, self.slip_speed(0.0).0);
        for q in [first, first + pi, first + 2.0 * pi] {
            let at_q = self.slip_speed(q);
            if at_p > 0.0 && at_q.0 <= 0.0 {
                let root = monotone_zero(|d| self.slip_speed(d), (p, at_p), (q, at_q), true);
                return (maxima, Some(root));
            }
            if at_q.0 > at_p {
                maxima.push(q);
            } else if at_q.0 <= touch {
                // A minimum of the slip speed that grazes zero: a touch at q.
                return (maxima, Some(q));
            }
            (p, at_p) = (q, at_q.0);
        }
        (maxima, None)
    }

    /// The angles δ in (0, `end`) at which the velocity vanishes (the turning points of x),
    /// each located by bracketed root finding on an interval between zeros of a, where v is
    /// monotone.
    pub fn turns(&self, end: f64) -> Vec<f64> {
        let pi = std::f64::consts::PI;
        let w = self.y_c * self.omega;
        // (v, dv/dδ, d²v/dδ²) times `sign`.
        let v = |delta: f64, sign: f64| {
            let (sin, cos) = fmath::sin_cos(delta);
            (
                sign * self.at_angle(delta).v,
                sign * (-self.v_c * sin - w * cos),
                sign * (-self.v_c * cos + w * sin),
            )
        };
        let mut turns = Vec::new();
        let mut p = 0.0;
        let mut q = self.first_accel_zero();
        while p < end {
            let q_end = q.min(end);
            let sign = if self.at_angle(p).v >= 0.0 { 1.0 } else { -1.0 };
            let (at_p, at_q) = (v(p, sign), v(q_end, sign));
            if at_p.0 > 0.0 && at_q.0 <= 0.0 {
                turns.push(monotone_zero(
                    |d| v(d, sign),
                    (p, at_p.0),
                    (q_end, at_q),
                    true,
                ));
            }
            (p, q) = (q, q + pi);
        }
        turns
    }

    /// ∫ |v − v_s| dt from the start to angle δ within the slip (m): s·(Δx − v_s τ), from the
    /// closed form of x.
    pub fn slip_distance(&self, delta: f64) -> f64 {
        let s = f64::from(self.dir);
        let (sin, half) = (fmath::sin(delta), fmath::sin(0.5 * delta));
        let one_minus_cos = 2.0 * half * half;
        let w = 1.0 / self.omega;
        let relative = (self.v_c - self.surface_speed) * delta * w
            - self.y_c * one_minus_cos
            - self.v_c * w * (delta - sin);
        s * relative
    }
}

/// What the body does during a recorded segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SurfaceMotion {
    /// Carried by the surface from x0 at t0: x = x0 + v_s (t − t0).
    Carried { t0: f64, x0: f64, speed: f64 },
    /// Slipping along a harmonic arc.
    Slip(HarmonicArc),
}

/// A piece of the trajectory on [t0, t1] (absolute s; local, from the cycle's onset, in a
/// [`SurfaceCycle`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceSegment {
    pub t0: f64,
    pub t1: f64,
    /// The segment's duration (s), from its own start rather than t1 − t0: the angle of the
    /// arc over ω, or the distance carried over v_s (an absolute time late in a run carries
    /// the rounding of the time of day).
    pub duration: f64,
    pub motion: SurfaceMotion,
}

impl SurfaceSegment {
    /// The segment of a cycle that starts at `start` (absolute s) and ends at `next`, from its
    /// local form: a slip at start + τ, a carried stretch from start + τ0 to the next onset.
    /// Integration and replay place segments through this one function.
    fn placed(&self, start: f64, next: f64) -> SurfaceSegment {
        let t0 = start + self.t0;
        let (t1, motion) = match self.motion {
            SurfaceMotion::Carried { x0, speed, .. } => {
                (next, SurfaceMotion::Carried { t0, x0, speed })
            }
            SurfaceMotion::Slip(arc) => (
                start + self.t1,
                SurfaceMotion::Slip(HarmonicArc {
                    t_c: start + arc.t_c,
                    ..arc
                }),
            ),
        };
        SurfaceSegment {
            t0,
            t1,
            duration: self.duration,
            motion,
        }
    }
}

/// Options of a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceOptions {
    /// Position (m) at t = 0, where the body starts carried by the surface (v = v_s).
    pub x0: f64,
    /// The run ends at the slip onset after this many slip onsets (so the last cycle is
    /// complete), or earlier when the body sticks or slips for ever.
    pub slips: u32,
    /// Keep every segment (for figures and time series).
    pub record_segments: bool,
}

/// The friction's ledger at an event, from t = 0 (J); within a [`SurfaceCycle`], from its
/// onset.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ledger {
    /// Heat ∫ μd N_f |v − v_s| dt.
    pub heat: f64,
    /// Work of the surface ∫ f v_s dt through the friction force f on the body.
    pub surface_work: f64,
}

impl Ledger {
    fn plus(self, other: Ledger) -> Ledger {
        Ledger {
            heat: self.heat + other.heat,
            surface_work: self.surface_work + other.surface_work,
        }
    }

    fn times(self, n: f64) -> Ledger {
        Ledger {
            heat: n * self.heat,
            surface_work: n * self.surface_work,
        }
    }
}

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// After the requested number of slip onsets.
    Slips,
    /// Carried by the surface for ever (v_s = 0, or the force never reaches μs N_f).
    Stuck,
    /// On a slip that never ends.
    Slipping,
}

/// The cycle of a run: the one from slip onset `first` to the next, which every later cycle
/// repeats (module doc). Times are local, from the cycle's onset, so that they keep their
/// relative precision however late the cycle starts.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceCycle {
    /// Index of the slip onset the recorded cycle starts at, and its time (s, absolute).
    pub first: u32,
    pub start: f64,
    /// Period T (s): the cycle's length in local time.
    pub period: f64,
    /// The friction's ledger over one cycle (J).
    pub ledger: Ledger,
    /// The cycle's events, its onset first, with `t` the offset from the onset (s) and
    /// `period` its index `first`.
    pub events: Vec<Event>,
    /// The ledger at each event since the onset (same index).
    pub event_ledger: Vec<Ledger>,
    /// The cycle's segments in local time (empty unless recorded).
    pub segments: Vec<SurfaceSegment>,
    /// The ledger at the onset (J, from t = 0).
    ledger_start: Ledger,
}

impl SurfaceCycle {
    /// The onset of cycle n ≥ `first`: time t_k + (n − k)·T (s) and ledger L_k + (n − k)·ΔL.
    fn frame(&self, n: u32) -> Frame {
        let cycles = f64::from(n - self.first);
        Frame {
            t: self.start + cycles * self.period,
            ledger: self.ledger_start.plus(self.ledger.times(cycles)),
        }
    }
}

/// A slip onset: its time (s, absolute) and the ledger there (J).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Frame {
    t: f64,
    ledger: Ledger,
}

/// What the motion after a slip onset depends on besides the law: the direction, x and
/// y = x − x_eq (as bits); v is v_s at every onset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Onset {
    dir: i8,
    x: u64,
    y: u64,
}

/// The cycles a [`Replay::Compact`] run replayed without storing them: `from..to`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Replayed {
    from: u32,
    to: u32,
}

/// The outcome of a run.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceRun {
    /// Every event in time order; `period` counts the slip onsets before it (the cycle index).
    /// With [`Replay::Compact`], those up to the onset where the replay began.
    pub events: Vec<Event>,
    /// The ledger at each event (same index).
    pub ledger: Vec<Ledger>,
    /// Recorded segments (empty unless asked for; with [`Replay::Compact`], up to the onset
    /// where the replay began: [`SurfaceRun::state_at`] covers the rest).
    pub segments: Vec<SurfaceSegment>,
    pub ending: Ending,
    /// The cycle every later one repeats, once found.
    pub cycle: Option<SurfaceCycle>,
    /// Time of the run's last event (s).
    pub end: f64,
    replayed: Option<Replayed>,
}

impl SurfaceRun {
    /// (x, v, a) at absolute time t from the recorded segments, if t is covered.
    pub fn state_at(&self, t: f64) -> Option<(f64, f64, f64)> {
        let seg = self.segment_at(t)?;
        if t < seg.t0 {
            return None;
        }
        Some(match seg.motion {
            SurfaceMotion::Carried { t0, x0, speed } => (x0 + speed * (t - t0), speed, 0.0),
            SurfaceMotion::Slip(arc) => {
                let p = arc.at(t);
                (p.x, p.v, p.a)
            }
        })
    }

    /// The first segment that ends at or after t, replayed ones included.
    fn segment_at(&self, t: f64) -> Option<SurfaceSegment> {
        let i = self.segments.partition_point(|s| s.t1 < t);
        if let Some(seg) = self.segments.get(i) {
            return Some(*seg);
        }
        let (replayed, cycle) = (self.replayed?, self.cycle.as_ref()?);
        // Segments of cycles before n − 1 end before t: a window around the cycle of t.
        let n = ((t - cycle.start) / cycle.period).floor();
        let n = (f64::from(cycle.first) + n).clamp(0.0, f64::from(u32::MAX)) as u32;
        let from = n.saturating_sub(1).max(replayed.from);
        (from..replayed.to.min(n.saturating_add(2))).find_map(|m| {
            let (start, next) = (cycle.frame(m).t, cycle.frame(m + 1).t);
            cycle
                .segments
                .iter()
                .map(|s| s.placed(start, next))
                .find(|s| s.t1 >= t)
        })
    }
}

/// The acceleration's centre x_eq of a slip in direction s (m), and x − x_eq at x.
fn centre(law: &SurfaceLaw, body: &Body, s: f64) -> f64 {
    (s * body.mu_d * law.normal - law.drive) / law.stiffness
}

/// Integrates `body` under `law` from x = `opts.x0`, v = v_s at t = 0, replaying the cycle
/// once found ([`Replay::Segments`]).
pub fn integrate_surface(
    body: &Body,
    law: &SurfaceLaw,
    opts: &SurfaceOptions,
) -> Result<SurfaceRun> {
    integrate_surface_with(body, law, opts, Replay::Segments)
}

/// The recorded cycle: local segments with absolute x, events with x − x_onset, the ledger
/// since the onset.
type CycleTape = Tape<Onset, SurfaceSegment, Ledger, Ledger>;

/// The run's outputs that events and segments go to.
struct Out<'a> {
    run: &'a mut SurfaceRun,
    record_segments: bool,
}

impl Out<'_> {
    /// An event of cycle `n` at local time `tau` of the cycle starting at `frame`, with the
    /// ledger `local` since the onset (integration and replay both place events here).
    fn event(
        &mut self,
        frame: Frame,
        n: u32,
        tau: f64,
        (kind, x, v): (EventKind, f64, f64),
        local: Ledger,
    ) {
        self.run.events.push(Event {
            t: frame.t + tau,
            period: n,
            kind,
            x,
            v,
        });
        self.run.ledger.push(frame.ledger.plus(local));
    }

    fn segment(&mut self, local: &SurfaceSegment, start: f64, next: f64) {
        if self.record_segments {
            self.run.segments.push(local.placed(start, next));
        }
    }
}

/// [`integrate_surface`], with the cycles that repeat treated as `replay` says.
pub fn integrate_surface_with(
    body: &Body,
    law: &SurfaceLaw,
    opts: &SurfaceOptions,
    replay: Replay,
) -> Result<SurfaceRun> {
    let omega = (-law.stiffness / body.mass).sqrt();
    let v_s = law.surface_speed;
    let limit = body.mu_s * law.normal;
    let friction = body.mu_d * law.normal;
    let mut run = SurfaceRun {
        events: Vec::new(),
        ledger: Vec::new(),
        segments: Vec::new(),
        ending: Ending::Slips,
        cycle: None,
        end: 0.0,
        replayed: None,
    };
    let mut out = Out {
        run: &mut run,
        record_segments: opts.record_segments,
    };
    let mut tape = CycleTape::detecting(replay, opts.record_segments);
    // The current cycle's onset (before the first, t = 0), and the ledger ℓ since it.
    let mut frame = Frame {
        t: 0.0,
        ledger: Ledger::default(),
    };
    let mut local = Ledger::default();
    let mut slips = 0u32;
    // Carried from (τ, x), τ local: the next slip onset, then the arc.
    let (mut tau, mut x) = (0.0, opts.x0);
    // How far |D(x)| may exceed μs N_f by the rounding of x at a stick (N): the position at the
    // end of an arc is known to a few ulps of the arc's amplitude. A touch (μd = μs) ends at
    // the onset's position, where |D| = μs N_f: its rounding must not start a slip the other
    // way.
    let mut rounding = 0.0;
    loop {
        if out.run.events.len() > MAX_EVENTS {
            return Err(Error::Stalled {
                t: frame.t + tau,
                reason: "too many events on a surface",
            });
        }
        // STUCK at (τ, x), v = v_s: the onset, now or where the moving x brings D(x) to ±μs N_f.
        let force = law.force(x);
        let (carried, x_on, s, y_c) = if force.abs() > limit + rounding {
            let s = force.signum();
            (0.0, x, s, x - centre(law, body, s))
        } else {
            // D(x) moves at c·v_s: it reaches the limit in direction sgn(c v_s).
            let s = (law.stiffness * v_s).signum();
            if v_s == 0.0 || s == 0.0 {
                out.run.ending = Ending::Stuck;
                break;
            }
            let x_on = (s * limit - law.drive) / law.stiffness;
            // x_on − x_eq = s (μs − μd) N_f / c, without the cancellation of two positions.
            let y_c = s * (body.mu_s - body.mu_d) * law.normal / law.stiffness;
            (((x_on - x) / v_s).max(0.0), x_on, s, y_c)
        };
        let tau_on = tau + carried;
        let stretch = (tau_on > tau).then_some(SurfaceSegment {
            t0: tau,
            t1: tau_on,
            duration: carried,
            motion: SurfaceMotion::Carried {
                t0: tau,
                x0: x,
                speed: v_s,
            },
        });
        if let Some(stretch) = &stretch {
            tape.segment(tau, tau_on, *stretch);
            // f = −D(x) while carried: the surface's work −∫ D dx from x to x_on.
            local.surface_work -= (x_on - x) * (law.drive + 0.5 * law.stiffness * (x_on + x));
        }
        // The onset closes the cycle: a repeat of the last onset's state makes it the cycle.
        let dir = s as i8;
        let onset = Onset {
            dir,
            x: x_on.to_bits(),
            y: y_c.to_bits(),
        };
        tape.end(local, onset);
        if !tape.repeats() {
            out.run.cycle = None;
        } else if out.run.cycle.is_none() {
            out.run.cycle = Some(recorded(&tape, slips - 1, frame, tau_on));
        }
        let next = match &out.run.cycle {
            Some(cycle) => cycle.frame(slips),
            None => Frame {
                t: frame.t + tau_on,
                ledger: frame.ledger.plus(local),
            },
        };
        if let Some(stretch) = &stretch {
            out.segment(stretch, frame.t, next.t);
        }
        frame = next;
        local = Ledger::default();
        if tape.replays() && slips < opts.slips {
            replay_cycles(tape.mode(), slips..opts.slips, &mut out);
            break;
        }
        let cycle = slips;
        out.event(
            frame,
            cycle,
            0.0,
            (EventKind::Slip { dir }, x_on, v_s),
            local,
        );
        if slips == opts.slips {
            break;
        }
        slips += 1;
        tape.begin(onset);
        tape.event(0.0, EventKind::Slip { dir }, None, v_s, local);
        let arc = HarmonicArc {
            t_c: 0.0,
            x_c: x_on,
            v_c: v_s,
            y_c,
            omega,
            surface_speed: v_s,
            dir,
        };
        let (maxima, stick) = arc.stick();
        let at = |delta: f64| Ledger {
            heat: friction * arc.slip_distance(delta),
            surface_work: -s * friction * v_s * delta / omega,
        };
        for delta in maxima
            .iter()
            .copied()
            .filter(|&d| stick.is_none_or(|e| d < e))
        {
            let p = arc.at_angle(delta);
            let t = delta / omega;
            out.event(frame, cycle, t, (EventKind::SpeedMax, p.x, p.v), at(delta));
            tape.event(t, EventKind::SpeedMax, Some(p.dx), p.v, at(delta));
        }
        let Some(delta) = stick else {
            let slip = SurfaceSegment {
                t0: 0.0,
                t1: f64::INFINITY,
                duration: f64::INFINITY,
                motion: SurfaceMotion::Slip(arc),
            };
            out.segment(&slip, frame.t, f64::INFINITY);
            out.run.ending = Ending::Slipping;
            break;
        };
        tau = delta / omega;
        let end = arc.at_angle(delta);
        x = end.x;
        let amplitude = arc.y_c.hypot(arc.v_c / omega);
        rounding = TOUCH_REL * -law.stiffness * (amplitude + x.abs());
        local = at(delta);
        let slip = SurfaceSegment {
            t0: 0.0,
            t1: tau,
            duration: tau,
            motion: SurfaceMotion::Slip(arc),
        };
        // The next onset is not known yet; a slip ends at its own offset, not at it.
        out.segment(&slip, frame.t, f64::NAN);
        tape.segment(0.0, tau, slip);
        out.event(frame, cycle, tau, (EventKind::Stick { dir }, x, v_s), local);
        tape.event(tau, EventKind::Stick { dir }, Some(end.dx), v_s, local);
    }
    run.end = run.events.last().map_or(0.0, |e| e.t).max(run.end);
    Ok(run)
}

/// The cycle recorded on `tape`, cycle `first` of the run, which started at `frame` and lasted
/// `period` (s, local).
fn recorded(tape: &CycleTape, first: u32, frame: Frame, period: f64) -> SurfaceCycle {
    let (ops, motions, start, ledger) = tape.recorded();
    let x_on = start.map_or(0.0, |s| f64::from_bits(s.x));
    let mut cycle = SurfaceCycle {
        first,
        start: frame.t,
        period,
        ledger,
        events: Vec::new(),
        event_ledger: Vec::new(),
        segments: Vec::new(),
        ledger_start: frame.ledger,
    };
    for op in ops {
        match *op {
            Op::Event {
                t,
                kind,
                dx,
                v,
                extra,
            } => {
                cycle.events.push(Event {
                    t,
                    period: first,
                    kind,
                    x: dx.map_or(x_on, |dx| x_on + dx),
                    v,
                });
                cycle.event_ledger.push(extra);
            }
            Op::Segment { motion, .. } => cycle.segments.push(motions[motion]),
            Op::Move { .. } | Op::Retract { .. } => {}
        }
    }
    cycle
}

/// Replays the run's cycle (read from the tape's ops by [`recorded`]) for cycles `cycles` and
/// the onset that ends the last: with [`Replay::Segments`] every event and segment into `out`,
/// with [`Replay::Compact`] none (the run keeps what rebuilds them).
fn replay_cycles(mode: Replay, cycles: std::ops::Range<u32>, out: &mut Out) {
    let Some(cycle) = out.run.cycle.clone() else {
        return;
    };
    out.run.end = cycle.frame(cycles.end).t;
    if mode == Replay::Compact {
        out.run.replayed = Some(Replayed {
            from: cycles.start,
            to: cycles.end,
        });
        return;
    }
    // Events and segments go to their own lists: each in its recorded order.
    let events = || cycle.events.iter().zip(&cycle.event_ledger);
    for n in cycles.clone() {
        let (frame, next) = (cycle.frame(n), cycle.frame(n + 1));
        for (e, &local) in events() {
            out.event(frame, n, e.t, (e.kind, e.x, e.v), local);
        }
        for segment in &cycle.segments {
            out.segment(segment, frame.t, next.t);
        }
    }
    // The onset that ends the run: the cycle's first event.
    if let Some((e, &local)) = events().next() {
        let frame = cycle.frame(cycles.end);
        out.event(frame, cycles.end, e.t, (e.kind, e.x, e.v), local);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The textbook belt: m 1 kg, k 100 N/m, v_b 0.1 m/s, μs 0.5, μd 0.3, g 10.
    fn belt(mu_d: f64) -> (Body, SurfaceLaw) {
        let body = Body {
            mass: 1.0,
            mu_s: 0.5,
            mu_d,
        };
        (body, SurfaceLaw::new(0.0, -100.0, 10.0, 0.1).unwrap())
    }

    #[test]
    fn a_belt_cycle_is_a_stick_and_one_harmonic_slip() {
        let (body, law) = belt(0.3);
        let opts = SurfaceOptions {
            x0: 0.0,
            slips: 4,
            record_segments: true,
        };
        let run = integrate_surface(&body, &law, &opts).unwrap();
        assert_eq!(run.ending, Ending::Slips);
        // x_s = 0.05 m, x_d = 0.03 m, Δ = 0.02 m, ω = 10 rad/s.
        let first = run.events[0];
        assert_eq!(first.kind, EventKind::Slip { dir: -1 });
        assert!((first.t - 0.5).abs() < 1e-15 && (first.x - 0.05).abs() < 1e-16);
        let cycle = run.cycle.as_ref().unwrap();
        // The second onset repeats the first: the first cycle is the cycle.
        assert_eq!(cycle.first, 0);
        let omega: f64 = 10.0;
        let period = 2.0 / omega * (std::f64::consts::PI - (omega * 0.02 / 0.1).atan()) + 0.4;
        assert!(
            (cycle.period - period).abs() <= 4e-15 * period,
            "{}",
            cycle.period
        );
        assert_eq!(cycle.events.len(), 3);
        assert_eq!(run.events.len(), 4 * 3 + 1);
        let stick = run.events[2];
        assert_eq!(stick.kind, EventKind::Stick { dir: -1 });
        assert!((stick.x - 0.01).abs() < 1e-16, "{}", stick.x);
        assert_eq!(cycle.events[2].x, stick.x);
        // Over a cycle the heat equals the belt's work: the block's energy returns.
        let (heat, work) = (cycle.ledger.heat, cycle.ledger.surface_work);
        assert!((heat - work).abs() <= 1e-14 * heat, "{heat} vs {work}");
        // Later cycles are placed at t_1 + nT.
        assert_eq!(run.events[12].t, run.events[0].t + 4.0 * cycle.period);
        // The speed maximum is the backward speed −√(v_b² + ω²Δ²) at x = x_d.
        let max = run.events[1];
        assert_eq!(max.kind, EventKind::SpeedMax);
        assert!((max.v + (0.01f64 + 0.04).sqrt()).abs() < 1e-15 && (max.x - 0.03).abs() < 1e-16);
        // The recorded trajectory agrees with the events.
        let (x, v, _) = run.state_at(stick.t).unwrap();
        assert!((x - stick.x).abs() < 1e-15 && (v - 0.1).abs() < 1e-15);
    }

    #[test]
    fn equal_coefficients_slip_a_full_turn_and_touch() {
        let (body, law) = belt(0.5);
        let opts = SurfaceOptions {
            x0: 0.0,
            slips: 3,
            record_segments: false,
        };
        let run = integrate_surface(&body, &law, &opts).unwrap();
        let cycle = run.cycle.unwrap();
        let period = std::f64::consts::TAU / 10.0;
        assert!(
            (cycle.period - period).abs() <= 4e-15 * period,
            "{}",
            cycle.period
        );
    }

    #[test]
    fn a_still_surface_holds_the_body() {
        let body = Body {
            mass: 1.0,
            mu_s: 0.5,
            mu_d: 0.3,
        };
        let law = SurfaceLaw::new(0.0, -100.0, 10.0, 0.0).unwrap();
        let opts = SurfaceOptions {
            x0: 0.01,
            slips: 3,
            record_segments: false,
        };
        let run = integrate_surface(&body, &law, &opts).unwrap();
        assert_eq!(run.ending, Ending::Stuck);
        assert!(run.events.is_empty());
        assert!(SurfaceLaw::new(0.0, 100.0, 10.0, 0.1).is_err());
    }
}
