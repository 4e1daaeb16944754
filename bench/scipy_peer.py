#!/usr/bin/env python3
"""SciPy peer of `stickslip bench --peer scipy`.

Runs scipy.integrate.solve_ivp (RK45, DOP853, Radau) on the benchmark problems with an
event-restart loop, the way a careful SciPy user would integrate a dry-friction oscillator:

    STUCK (v = 0)   integrate a zero right-hand side until |D| - mu_s N_f crosses 0 upward
                    -> SLIP in direction s = sgn D
    SLIP (s = +-1)  M dv/dt = D - s mu_d N_f until v crosses 0 (direction -s)
                    -> STUCK if |D| <= mu_s N_f, else SLIP in direction sgn D (a reversal)

The script knows no model. It receives each problem's force law as data, the tool's own
engine::ForceLaw and engine::Body serialized: a period tiled by pieces [start, end) on which the
driving force D and the friction-bearing normal force N_f are affine in one basis function b,

    D = drive.c0 + drive.c1 b,   N_f = normal.c0 + normal.c1 b,
    b = t_loc - t_ref ("linear")  or  cos(omega t_loc) ("cos"),   t_loc = t mod period,

and evaluates D(t) and N_f(t) from them (periodic extension, piece lookup). Every phase is also
restarted at the period starts and at the piece boundaries, the kinks of the force law, so no
solver steps over a corner of its right-hand side.

Input (JSON, a file path or '-' for stdin): {"repeats": N, "long_run_s": 1.0,
"tolerances": [...], "methods": [...], "problems": [{"id", "model", "law", "periods",
"body": {"mass", "mu_s", "mu_d"},
"force_law": {"period", "pieces": [{"start", "end", "basis": {"kind": "linear", "t_ref"} or
{"kind": "cos", "omega"}, "drive": {"c0", "c1"}, "normal": {"c0", "c1"}}]},
"exact": {"events": [{"t", "kind"}], "x_end_m"}}]}. "model" and "law" are labels only.
Output (JSON on stdout): versions, machine and one point per problem x method x tolerance with
the best-of-N time, rhs evaluations, event-time error against the exact events (matched in
order) and x_end with its error. Only numpy and scipy are needed.
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

# The stuck phase integrates a zero right-hand side, on which the step would grow without
# bound; a cap of T/16 keeps the onset window of the static margin from being stepped over.
STUCK_MAX_STEP_PER_PERIOD = 16


class Piece:
    """One piece of a force law: D and N_f affine in the basis b(t) on [start, end)."""

    def __init__(self, piece):
        self.start, self.end = piece["start"], piece["end"]
        basis = piece["basis"]
        if basis["kind"] == "linear":
            t_ref = basis["t_ref"]
            self.basis = lambda t: t - t_ref
        elif basis["kind"] == "cos":
            omega = basis["omega"]
            self.basis = lambda t: math.cos(omega * t)
        else:
            raise ValueError("unknown basis kind %r" % basis["kind"])
        self.d0, self.d1 = piece["drive"]["c0"], piece["drive"]["c1"]
        self.n0, self.n1 = piece["normal"]["c0"], piece["normal"]["c1"]

    def drive(self, t):
        """D at time t within the period (N)."""
        return self.d0 + self.d1 * self.basis(t)

    def normal(self, t):
        """N_f at time t within the period (N)."""
        return self.n0 + self.n1 * self.basis(t)


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


def build_law(problem):
    return Law(problem["body"], problem["force_law"])


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


def zero_rhs(t, y):
    return [0.0, 0.0]


def simulate(law, method, tol, t_end):
    """Event-restart integration; returns (events [(t, kind)], x_end, nfev)."""
    mu_s, mu_d, mass = law.mu_s, law.mu_d, law.mass
    margin = lambda t: abs(law.drive(t)) - mu_s * law.normal(t)
    t, x, v, s = 0.0, 0.0, 0.0, 0.0
    events, nfev = [], 0
    stops = breakpoints(law, t_end)
    i = 0
    max_step_stuck = law.period / STUCK_MAX_STEP_PER_PERIOD
    while t < t_end:
        while stops[i] <= t:
            i += 1
        t_stop = stops[i]
        if s == 0.0 and margin(t) > 0.0:
            s = sign(law.drive(t))
            events.append((t, "slip"))
        # Every switching function is given the sign it is leaving at the restart time itself:
        # a zero there would be taken for a crossing (with a tiny first step, y barely moves).
        t_start = t
        if s == 0.0:
            def onset(tt, y):
                return margin(tt) if tt > t_start else -1.0

            onset.terminal, onset.direction = True, 1.0
            sol = solve_ivp(zero_rhs, (t, t_stop), [x, 0.0], method=method, rtol=tol,
                            atol=tol, events=onset, max_step=max_step_stuck)
        else:
            direction = s

            def rhs(tt, y):
                return [y[1], (law.drive(tt) - direction * mu_d * law.normal(tt)) / mass]

            def stop(tt, y):
                return y[1] if tt > t_start else direction

            stop.terminal, stop.direction = True, -direction
            sol = solve_ivp(rhs, (t, t_stop), [x, v], method=method, rtol=tol, atol=tol,
                            events=stop)
        nfev += sol.nfev
        if sol.status == 1:
            te = float(sol.t_events[0][0])
            x = float(sol.y_events[0][0][0])
            t, v = te, 0.0
            if s == 0.0:
                s = sign(law.drive(te))
                events.append((te, "slip"))
            elif margin(te) <= 0.0:
                s = 0.0
                events.append((te, "stick"))
            else:
                s = sign(law.drive(te))
        elif sol.status == 0:
            t = t_stop
            x, v = float(sol.y[0, -1]), float(sol.y[1, -1])
        else:
            raise RuntimeError(sol.message)
    return events, x, nfev


def event_error(got, exact):
    """Max |t - t_exact| over events matched in order (None for an empty prefix)."""
    n = min(len(got), len(exact))
    if n == 0:
        return None
    return max(abs(got[i][0] - exact[i]["t"]) for i in range(n))


def run_point(problem, law, method, tol, repeats, long_run_s):
    t_end = problem["periods"] * law.period
    exact = problem["exact"]
    point = {"problem": problem["id"], "method": method, "tol": tol, "status": "ok",
             "error": None, "time_s": None, "runs": 0, "nfev": None, "n_events": None,
             "n_events_exact": len(exact["events"]), "err_event_s": None, "x_end_m": None,
             "err_x_m": None}
    try:
        start = time.perf_counter()
        events, x_end, nfev = simulate(law, method, tol, t_end)
        first = time.perf_counter() - start
        n = 1 if first > long_run_s else max(1, repeats)
        best = math.inf
        for _ in range(n):
            start = time.perf_counter()
            simulate(law, method, tol, t_end)
            took = time.perf_counter() - start
            best = min(best, took)
            point["runs"] += 1
            if took > long_run_s:
                break
    except Exception as e:  # a solver failure is a measured result, not a crash
        point["status"], point["error"] = "error", "%s: %s" % (type(e).__name__, e)
        return point
    point.update(time_s=best, nfev=int(nfev), n_events=len(events),
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
