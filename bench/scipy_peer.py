#!/usr/bin/env python3
"""SciPy peer of `stickslip bench --peer scipy`.

Runs scipy.integrate.solve_ivp (RK45, DOP853, Radau) on the benchmark problems with an
event-restart loop, the way a careful SciPy user would integrate a dry-friction oscillator:

    STUCK (v = 0)   no integration: scan the static margin g(t) = |D(t)| - mu_s N_f(t) piece by
                    piece for its first upward crossing -> SLIP in direction s = sgn D there
    SLIP (s = +-1)  solve_ivp on M dv/dt = D - s mu_d N_f until v crosses 0 (direction -s)
                    -> STUCK if |D| <= mu_s N_f, else SLIP in direction sgn D (a reversal)

The stuck phase changed (issue 14): this script used to integrate y' = 0 through every stick with
solve_ivp (max step T/16) and let its event locator find the crossing of g, which spent 58-79 %
of its steps on a right-hand side that is zero. g is known in closed form from the force law, so a
careful user scans it instead:

    "linear" piece  D and N_f affine in t: split at the zero of D (where |D| has its corner); on
                    each part g is affine and its zero is solved for directly
    "cos" piece     MARGIN_SAMPLES_PER_PIECE samples of g per piece; the first sample pair with
                    g <= 0 < g is refined by scipy.optimize.brentq (xtol 1e-15 * t)

The margin evaluations are counted apart from the rhs evaluations and reported ("margin_evals");
"steps" counts solve_ivp steps, "steps_stuck" the ones taken while stuck (none, by construction).

The script knows no model. It receives each problem's force law as data, the tool's own
engine::ForceLaw and engine::Body serialized: a period tiled by pieces [start, end) on which the
driving force D and the friction-bearing normal force N_f are affine in one basis function b,

    D = drive.c0 + drive.c1 b,   N_f = normal.c0 + normal.c1 b,
    b = t_loc - t_ref ("linear")  or  cos(omega t_loc) - shift ("cos"),   t_loc = t mod period,

and evaluates D(t) and N_f(t) from them (periodic extension, piece lookup). Every phase is also
restarted at the period starts and at the piece boundaries, the kinks of the force law, so no
solver steps over a corner of its right-hand side.

A problem may instead send a surface law (the belt: a block held by a spring on a belt moving at
constant speed), "surface_law": {"drive": D0, "stiffness": c, "normal": N_f, "surface_speed": v_s},
with D = D0 + c x (c = dD/dx < 0), constant N_f, and the body sticking at the surface's speed, from
rest relative to it at x = 0, t = 0, up to "t_end" (s; "period", the cycle's, sets the window of
the missed events). Its phases, in the surface frame w = v - v_s:

    STUCK (w = 0)   no integration: x = x0 + v_s (t - t0), so D and the static margin
                    |D0 + c x| - mu_s N_f are affine in t; the end of the stick, where D reaches
                    sgn(c v_s) mu_s N_f, is solved for directly -> SLIP in direction s = sgn D
    SLIP (s = +-1)  solve_ivp on dx/dt = w + v_s, M dw/dt = D0 + c x - s mu_d N_f until w
                    crosses 0 (direction -s) -> STUCK if |D| <= mu_s N_f, else SLIP in
                    direction sgn D

Input (JSON, a file path or '-' for stdin): {"repeats": N, "long_run_s": 1.0,
"tolerances": [...], "methods": [...], "problems": [{"id", "model", "law", "periods",
"body": {"mass", "mu_s", "mu_d"},
"force_law": {"period", "pieces": [{"start", "end", "basis": {"kind": "linear", "t_ref"} or
{"kind": "cos", "omega", "shift"}, "drive": {"c0", "c1"}, "normal": {"c0", "c1"}}]},
"exact": {"events": [{"t", "kind"}], "x_end_m"}}]}. "model" and "law" are labels only.
Output (JSON on stdout): versions, machine and one point per problem x method x tolerance with
the best-of-N time, rhs evaluations, solve_ivp steps (all, and while stuck), margin evaluations,
event-time error against the exact events (matched in order), x_end with its error, and the
exact events missed (none of the same kind found within T/100; their number and the first).
Only numpy and scipy are needed.
"""

import bisect
import json
import math
import platform
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

# Samples of the static margin per "cos" piece before brentq refines the first upward crossing:
# 16 per piece is at least as fine as the T/16 step cap of the former zero-rhs integration, and
# the woodpecker's shortest stick is T/20 across three pieces.
MARGIN_SAMPLES_PER_PIECE = 16
# brentq's absolute tolerance relative to |t|: the crossing to about an ulp of the time.
BRENTQ_XTOL_REL = 1e-15


class Piece:
    """One piece of a force law: D and N_f affine in the basis b(t) on [start, end)."""

    def __init__(self, piece):
        self.start, self.end = piece["start"], piece["end"]
        basis = piece["basis"]
        if basis["kind"] == "linear":
            t_ref = basis["t_ref"]
            self.basis = lambda t: t - t_ref
        elif basis["kind"] == "cos":
            omega, shift = basis["omega"], basis.get("shift", 0.0)
            self.basis = lambda t: math.cos(omega * t) - shift
        else:
            raise ValueError("unknown basis kind %r" % basis["kind"])
        self.d0, self.d1 = piece["drive"]["c0"], piece["drive"]["c1"]
        self.n0, self.n1 = piece["normal"]["c0"], piece["normal"]["c1"]
        self.kind = basis["kind"]
        self.t_ref = basis.get("t_ref", 0.0)

    def drive(self, t):
        """D at time t within the period (N)."""
        return self.d0 + self.d1 * self.basis(t)

    def normal(self, t):
        """N_f at time t within the period (N)."""
        return self.n0 + self.n1 * self.basis(t)

    def margin(self, t, mu_s):
        """The static margin |D| - mu_s N_f at time t within the period (N)."""
        b = self.basis(t)
        return abs(self.d0 + self.d1 * b) - mu_s * (self.n0 + self.n1 * b)

    def first_upward(self, lo, hi, mu_s, from_stick, count):
        """First time in [lo, hi] (within the period) at which the margin crosses 0 upward, or
        None. `from_stick`: lo is the stick time itself, where the margin is <= 0 by the state
        machine (its evaluation there may round either way); else lo is the piece start, where a
        positive margin means the crossing is at the boundary. `count[0]` counts evaluations."""

        def g(t):
            count[0] += 1
            return self.margin(t, mu_s)

        if not from_stick and g(lo) > 0.0:
            return lo
        if self.kind == "linear":
            return self._first_upward_linear(lo, hi, mu_s, g)
        n = max(1, math.ceil(MARGIN_SAMPLES_PER_PIECE * (hi - lo) / (self.end - self.start)))
        a, g_a = lo, -1.0
        for k in range(1, n + 1):
            b = hi if k == n else lo + (hi - lo) * k / n
            g_b = g(b)
            if g_a <= 0.0 < g_b:
                try:
                    return brentq(g, a, b, xtol=BRENTQ_XTOL_REL * b,
                                  rtol=4.0 * np.finfo(float).eps)
                except ValueError:  # g rounded above 0 at the stick time itself: slip at once
                    return a
            a, g_a = b, g_b
        return None

    def _first_upward_linear(self, lo, hi, mu_s, g):
        """On a linear piece: D = d0 + d1 u, N_f = n0 + n1 u with u = t - t_ref. Where D keeps
        its sign s the margin s D - mu_s N_f is affine in u; its zero is solved for."""
        cuts = [lo]
        if self.d1 != 0.0:
            t_zero = self.t_ref - self.d0 / self.d1
            if lo < t_zero < hi:
                cuts.append(t_zero)
        cuts.append(hi)
        for a, b in zip(cuts, cuts[1:]):
            g_b = g(b)
            if g_b <= 0.0:
                continue
            mid = 0.5 * (a + b) - self.t_ref
            s = sign(self.d0 + self.d1 * mid)
            slope = s * self.d1 - mu_s * self.n1
            if slope <= 0.0:  # g rounded above 0 at the stick time itself: slip at once
                return a
            # g(a) <= 0 < g(b) (the margin is <= 0 at the start of the search and at every cut
            # passed), so the slope is positive and the zero lies in [a, b].
            u = (mu_s * self.n0 - s * self.d0) / slope
            return min(max(self.t_ref + u, a), b)
        return None


class Law:
    """The body (M, mu_s, mu_d) under its periodic force law, both as the tool sends them."""

    def __init__(self, body, force_law):
        self.mass, self.mu_s, self.mu_d = body["mass"], body["mu_s"], body["mu_d"]
        self.period = force_law["period"]
        self.pieces = [Piece(p) for p in force_law["pieces"]]
        self.ends = [p.end for p in self.pieces]
        # The piece boundaries within the period: D or N_f may have a corner there.
        self.kinks = [p.start for p in self.pieces[1:]]

    def piece_at(self, t):
        """The piece holding t (absolute, s) and the time within the period."""
        local = t % self.period
        i = bisect.bisect_right(self.ends, local)
        return self.pieces[min(i, len(self.pieces) - 1)], local

    def drive(self, t):
        """D(t) at absolute time t (N)."""
        piece, local = self.piece_at(t)
        return piece.drive(local)

    def normal(self, t):
        """N_f(t) at absolute time t (N)."""
        piece, local = self.piece_at(t)
        return piece.normal(local)

    def stick_end(self, t0, t_end, count):
        """The first upward crossing of the static margin after the stick at t0 (absolute, s),
        scanned piece by piece, or None if the body stays stuck up to t_end."""
        n = math.floor(t0 / self.period)
        first = True
        while n * self.period < t_end:
            base = n * self.period
            for piece in self.pieces:
                lo = max(piece.start, t0 - base)
                hi = min(piece.end, t_end - base)
                if hi <= lo:
                    continue
                t = piece.first_upward(lo, hi, self.mu_s, first, count)
                first = False
                if t is not None:
                    return base + t
            n += 1
        return None


class SurfaceLaw:
    """The body (M, mu_s, mu_d) under D = D0 + c x and a constant N_f on a surface moving at
    v_s, as the tool sends them (its engine::SurfaceLaw)."""

    def __init__(self, body, surface_law, period):
        self.mass, self.mu_s, self.mu_d = body["mass"], body["mu_s"], body["mu_d"]
        self.d0, self.c = surface_law["drive"], surface_law["stiffness"]
        self.n, self.v_s = surface_law["normal"], surface_law["surface_speed"]
        self.period = period

    def drive(self, x):
        """D at position x (N)."""
        return self.d0 + self.c * x

    def margin(self, x):
        """The static margin |D| - mu_s N_f at position x (N)."""
        return abs(self.drive(x)) - self.mu_s * self.n

    def stick_end(self, t0, x0, t_end):
        """The end of the stick that began at (t0, x0), or None if it outlasts t_end: carried
        at v_s, D(t) = D(x0) + c v_s (t - t0) is affine in t and reaches sgn(c v_s) mu_s N_f
        (the margin crossing 0 upward) at a time solved for directly."""
        slope = self.c * self.v_s
        if slope == 0.0:
            return None
        target = sign(slope) * self.mu_s * self.n
        te = t0 + max(0.0, (target - self.drive(x0)) / slope)
        return te if te < t_end else None


def build_law(problem):
    if "surface_law" in problem:
        return SurfaceLaw(problem["body"], problem["surface_law"], problem["period"])
    return Law(problem["body"], problem["force_law"])


def t_end_of(problem, law):
    """The final time (s): sent with a surface law, else a whole number of periods."""
    return problem.get("t_end", problem["periods"] * law.period)


def breakpoints(law, t_end):
    """Period starts and kinks in (0, t_end), then t_end."""
    out = []
    n = 0
    while n * law.period < t_end:
        for k in [0.0] + law.kinks:
            t = n * law.period + k
            if 0.0 < t < t_end:
                out.append(t)
        n += 1
    out.append(t_end)
    return out


def sign(x):
    return 1.0 if x > 0.0 else -1.0


def slip_phase(rhs, t0, t_stop, y0, direction, method, tol):
    """One slip in `direction` (+-1): solve_ivp on y = [x, speed relative to the surface] from
    t0, stopped where y[1] crosses 0 (direction -direction) or at t_stop. Returns (stopped, t,
    y, rhs evaluations, steps) with y[1] = 0 at a stop."""

    # The switching function is given the sign it is leaving at the restart time itself:
    # a zero there would be taken for a crossing (with a tiny first step, y barely moves).
    def stop(tt, y):
        return y[1] if tt > t0 else direction

    stop.terminal, stop.direction = True, -direction
    sol = solve_ivp(rhs, (t0, t_stop), y0, method=method, rtol=tol, atol=tol, events=stop)
    steps = len(sol.t) - 1
    if sol.status == 1:
        te = float(sol.t_events[0][0])
        return True, te, [float(sol.y_events[0][0][0]), 0.0], sol.nfev, steps
    if sol.status == 0:
        return False, t_stop, [float(sol.y[0, -1]), float(sol.y[1, -1])], sol.nfev, steps
    raise RuntimeError(sol.message)


def simulate(law, method, tol, t_end):
    """Event-restart integration; returns (events [(t, kind)], x_end, counts) with counts the
    rhs evaluations, solve_ivp steps (all, and while stuck) and margin evaluations."""
    mu_s, mu_d, mass = law.mu_s, law.mu_d, law.mass
    margin = lambda t: abs(law.drive(t)) - mu_s * law.normal(t)
    t, x, v, s = 0.0, 0.0, 0.0, 0.0
    events, nfev, steps = [], 0, 0
    margin_evals = [0]
    stops = breakpoints(law, t_end)
    i = 0
    while t < t_end:
        if s == 0.0:
            # Stuck: no integration (x and v do not change); the slip starts where the static
            # margin first crosses 0 upward, at once if it is already positive.
            margin_evals[0] += 1
            if margin(t) > 0.0:
                te = t
            else:
                te = law.stick_end(t, t_end, margin_evals)
                if te is None:
                    break
            margin_evals[0] += 1
            s = sign(law.drive(te))
            events.append((te, "slip"))
            t = te
            continue
        while stops[i] <= t:
            i += 1
        direction = s

        def rhs(tt, y):
            return [y[1], (law.drive(tt) - direction * mu_d * law.normal(tt)) / mass]

        stopped, t, (x, v), n, k = slip_phase(rhs, t, stops[i], [x, v], direction, method, tol)
        nfev, steps = nfev + n, steps + k
        if stopped:
            margin_evals[0] += 1
            if margin(t) <= 0.0:
                s = 0.0
                events.append((t, "stick"))
            else:
                margin_evals[0] += 1
                s = sign(law.drive(t))
    # No solve_ivp call is made while stuck: steps_stuck stays 0 and is reported as measured.
    counts = {"nfev": nfev, "steps": steps, "steps_stuck": 0, "margin_evals": margin_evals[0]}
    return events, x, counts


def simulate_surface(law, method, tol, t_end):
    """Event-restart integration of a surface law in the surface frame; returns (events
    [(t, kind)], x_end, counts) as `simulate`. Autonomous: no breakpoints."""
    mu_s, mu_d, mass, v_s, n_f = law.mu_s, law.mu_d, law.mass, law.v_s, law.n
    t, x, w, s = 0.0, 0.0, 0.0, 0.0
    events, nfev, steps, margin_evals = [], 0, 0, 0
    while t < t_end:
        if s == 0.0:
            # Stuck, carried at v_s: the slip starts where the margin, affine in t, crosses 0
            # upward (at once if it is already positive).
            margin_evals += 1
            if law.margin(x) > 0.0:
                te = t
            else:
                te = law.stick_end(t, x, t_end)
                if te is None:
                    x += v_s * (t_end - t)
                    t = t_end
                    break
                x += v_s * (te - t)
            margin_evals += 1
            s = sign(law.drive(x))
            events.append((te, "slip"))
            t = te
            continue
        direction = s

        def rhs(tt, y):
            return [y[1] + v_s, (law.d0 + law.c * y[0] - direction * mu_d * n_f) / mass]

        stopped, t, (x, w), n, k = slip_phase(rhs, t, t_end, [x, w], direction, method, tol)
        nfev, steps = nfev + n, steps + k
        if stopped:
            margin_evals += 1
            if law.margin(x) <= 0.0:
                s = 0.0
                events.append((t, "stick"))
            else:
                margin_evals += 1
                s = sign(law.drive(x))
    counts = {"nfev": nfev, "steps": steps, "steps_stuck": 0, "margin_evals": margin_evals}
    return events, x, counts


def event_error(got, exact):
    """Max |t - t_exact| over events matched in order (None for an empty prefix)."""
    n = min(len(got), len(exact))
    if n == 0:
        return None
    return max(abs(got[i][0] - exact[i]["t"]) for i in range(n))


def missed_events(got, exact, window):
    """The exact events with no found event of the same kind within `window` (s), in order."""
    out = []
    for e in exact:
        times = [t for t, kind in got if kind == e["kind"]]
        i = bisect.bisect_left(times, e["t"] - window)
        if i == len(times) or times[i] > e["t"] + window:
            out.append(e)
    return out


def run_point(problem, law, method, tol, repeats, long_run_s):
    t_end = t_end_of(problem, law)
    run = simulate_surface if isinstance(law, SurfaceLaw) else simulate
    exact = problem["exact"]
    point = {"problem": problem["id"], "method": method, "tol": tol, "status": "ok",
             "error": None, "time_s": None, "runs": 0, "nfev": None, "steps": None,
             "steps_stuck": None, "margin_evals": None, "n_events": None,
             "n_events_exact": len(exact["events"]), "err_event_s": None, "x_end_m": None,
             "err_x_m": None, "n_missed": None, "first_missed_t": None,
             "first_missed_kind": None}
    try:
        start = time.perf_counter()
        events, x_end, counts = run(law, method, tol, t_end)
        first = time.perf_counter() - start
        n = 1 if first > long_run_s else max(1, repeats)
        best = math.inf
        for _ in range(n):
            start = time.perf_counter()
            run(law, method, tol, t_end)
            took = time.perf_counter() - start
            best = min(best, took)
            point["runs"] += 1
            if took > long_run_s:
                break
    except Exception as e:  # a solver failure is a measured result, not a crash
        point["status"], point["error"] = "error", "%s: %s" % (type(e).__name__, e)
        return point
    point.update(counts)
    # What a run with a wrong event count missed: exact events without a found one of the same
    # kind within T/100, the first of them named.
    missed = missed_events(events, exact["events"], law.period / 100.0)
    point.update(n_missed=len(missed))
    if missed:
        point.update(first_missed_t=missed[0]["t"], first_missed_kind=missed[0]["kind"])
    point.update(time_s=best, n_events=len(events),
                 err_event_s=event_error(events, exact["events"]), x_end_m=x_end,
                 err_x_m=abs(x_end - exact["x_end_m"]))
    return point


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def main(argv):
    source = argv[1] if len(argv) > 1 else "-"
    config = json.load(sys.stdin if source == "-" else open(source))
    repeats = int(config.get("repeats", 5))
    long_run_s = float(config.get("long_run_s", 1.0))
    methods = config.get("methods", ["RK45", "DOP853", "Radau"])
    points = []
    for problem in config["problems"]:
        law = build_law(problem)
        for method in methods:
            for tol in config["tolerances"]:
                points.append(run_point(problem, law, method, tol, repeats, long_run_s))
    out = {
        "python": platform.python_version(),
        "numpy": np.__version__,
        "scipy": scipy.__version__,
        "cpu": cpu_model(),
        "points": points,
    }
    json.dump(out, sys.stdout)
    sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
