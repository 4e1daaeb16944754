#!/usr/bin/env python3
"""SciPy peer of `stickslip bench --peer scipy`.

Runs scipy.integrate.solve_ivp (RK45, DOP853, Radau) on the benchmark problems with an
event-restart loop, the way a careful SciPy user would integrate a dry-friction oscillator:

    STUCK (v = 0)   integrate a zero right-hand side until |D| - mu_s N_f crosses 0 upward
                    -> SLIP in direction s = sgn D
    SLIP (s = +-1)  M dv/dt = D - s mu_d N_f until v crosses 0 (direction -s)
                    -> STUCK if |D| <= mu_s N_f, else SLIP in direction sgn D (a reversal)

Every phase is also restarted at the kinks of the force law (the triangle-wave corners, the zeros
of the woodpecker's spring force), so no solver steps over a corner of its right-hand side.
The force laws are built here from the model parameters (physics.md 1.1-1.2, 2, 3.1):

    pulled mass   M = 2m, D = F, N_f = W (1 + cos wt) or its triangle wave 2W|1 - 2 tau|
    woodpecker    M = m_S, D = W_S + k z(t), N_f = 2 lambda k |z(t)|, z = z0 + d0 cos wt or
                  delta0 + zeta(t) with the triangle zeta of amplitude zeta0 (counterpart)

Input (JSON, a file path or '-' for stdin): {"repeats": N, "long_run_s": 1.0,
"tolerances": [...], "methods": [...], "problems": [{"id", "model", "law", "params", "periods",
"exact": {"events": [{"t", "kind"}], "x_end_m"}}]}.
Output (JSON on stdout): versions, machine and one point per problem x method x tolerance with
the best-of-N time, rhs evaluations, event-time error against the exact events (matched in
order) and x_end with its error. Only numpy and scipy are needed.
"""

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


class Law:
    """A force law: M, mu_s, mu_d, period, D(t), N_f(t), and the kinks within one period."""

    def __init__(self, mass, mu_s, mu_d, period, drive, normal, kinks):
        self.mass, self.mu_s, self.mu_d = mass, mu_s, mu_d
        self.period, self.drive, self.normal = period, drive, normal
        self.kinks = sorted(k for k in kinks if 0.0 < k < period)


def triangle(t, period):
    """|1 - 2 tau| with tau = (t mod T)/T: 1 at t = 0, 0 at T/2."""
    tau = (t % period) / period
    return abs(1.0 - 2.0 * tau)


def pulled_mass(p, law):
    m, g, k, force = p["mass"], p["g"], p["k"], p["force"]
    w = m * g
    omega = math.sqrt(k / m)
    period = 2.0 * math.pi / omega
    if law == "harmonic":
        normal = lambda t: w * (1.0 + math.cos(omega * t))
        kinks = []
    else:
        normal = lambda t: 2.0 * w * triangle(t, period)
        kinks = [0.5 * period]
    return Law(2.0 * m, p["mu_s"], p["mu_d"], period, lambda t: force, normal, kinks)


def counterpart(z0, d0, kind):
    """(zeta0, delta0) of the linear counterpart of z0 + d0 cos wt (physics.md 3.1)."""
    if kind == "extremes":
        return d0, z0
    ratio = z0 / d0
    if abs(ratio) > 1.0:
        raise ValueError("the %s counterpart needs |z0| <= d0" % kind)
    if kind == "zeros":
        return d0, d0 * (2.0 / math.pi) * math.asin(ratio)
    zeta0 = math.sqrt(d0 * d0 - z0 * z0) / (2.0 / math.pi)
    return zeta0, zeta0 * (2.0 / math.pi) * math.asin(ratio)


def woodpecker(p, law):
    k, ms, mw, g = p["k"], p["m_sleeve"], p["m_bird"], p["g"]
    lam = p["lever"] if p.get("lever") is not None else p["l"] / p["h"]
    mode = p.get("omega", "bird")
    omega = {
        "bird": math.sqrt(k / mw),
        "reduced": math.sqrt(k * (ms + mw) / (ms * mw)),
        "total": math.sqrt(k / (ms + mw)),
    }[mode]
    period = 2.0 * math.pi / omega
    ws = ms * g
    z0, d0 = p["z0"], p["d0"]
    if law == "harmonic":
        z = lambda t: z0 + d0 * math.cos(omega * t)
        kinks = []
        if abs(z0) < d0:
            t1 = math.acos(-z0 / d0) / omega
            kinks = [t1, period - t1]
    else:
        zeta0, delta0 = counterpart(z0, d0, p.get("counterpart", "zeros"))
        tau = 0.25 * period

        def z(t):
            phase = (t % period) / tau
            zeta = zeta0 * (1.0 - phase) if phase <= 2.0 else zeta0 * (phase - 3.0)
            return delta0 + zeta

        kinks = [2.0 * tau]
        if abs(delta0) < zeta0:
            kinks += [tau * (1.0 + delta0 / zeta0), tau * (3.0 - delta0 / zeta0)]
    drive = lambda t: ws + k * z(t)
    normal = lambda t: 2.0 * lam * k * abs(z(t))
    return Law(ms, p["mu_s"], p["mu_d"], period, drive, normal, kinks)


def build_law(problem):
    builder = pulled_mass if problem["model"] == "pulled-mass" else woodpecker
    return builder(problem["params"], problem["law"])


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
