#!/usr/bin/env python3
"""High-precision reference for the engine (src/engine): the same state machine (physics.md §0)
integrated with mpmath at 40 significant digits.

Reads a JSON list of cases on stdin, each {"law": ForceLaw, "body": Body, "periods": N} as the
engine serializes them (the doubles are taken as exact numbers), and writes a JSON list with, per
case: the transitions [t, kind, dir] of every period ("slip", "stick", "reversal"), the position
and velocity at each period start, and the friction dissipation ∫ μd N_f |v| dt of each period.
Numbers are written as decimal strings with 30 digits.

The motion on a piece is the closed form of physics.md §0 (a = A0 + A1 b(t), b = t − t_ref or
cos ωt) evaluated at 40 digits, so the cancellations that the engine must avoid in double
precision cost nothing here; events are bracketed roots on intervals where v is monotone (split
at the zeros of a), refined to 1e-36 of the period.

Usage: python3 tests/reference/mp_engine.py < cases.json > reference.json
"""
import json
import sys

try:
    import mpmath
    from mpmath import mp, mpf
except ImportError:  # the Rust test that runs this script skips on exit code 3
    sys.stderr.write("mpmath is not installed\n")
    sys.exit(3)

mp.dps = 40
MAX_TRANSITIONS_PER_PIECE = 64


class Piece:
    def __init__(self, p):
        self.start = mpf(p["start"])
        self.end = mpf(p["end"])
        basis = p["basis"]
        self.linear = basis["kind"] == "linear"
        self.t_ref = mpf(basis["t_ref"]) if self.linear else None
        self.omega = None if self.linear else mpf(basis["omega"])
        self.d0, self.d1 = mpf(p["drive"]["c0"]), mpf(p["drive"]["c1"])
        self.n0, self.n1 = mpf(p["normal"]["c0"]), mpf(p["normal"]["c1"])

    def b(self, t):
        return t - self.t_ref if self.linear else mpmath.cos(self.omega * t)

    def db(self, t):
        return mpf(1) if self.linear else -self.omega * mpmath.sin(self.omega * t)

    def drive(self, t):
        return self.d0 + self.d1 * self.b(t)

    def normal(self, t):
        return self.n0 + self.n1 * self.b(t)


class Arc:
    """Motion from (tc, xc, vc) under a = a0 + a1 b(t)."""

    def __init__(self, piece, a0, a1, tc, xc, vc):
        self.p, self.a0, self.a1, self.tc, self.xc, self.vc = piece, a0, a1, tc, xc, vc

    def a(self, t):
        return self.a0 + self.a1 * self.p.b(t)

    def v(self, t):
        p, w = self.p, t - self.tc
        if p.linear:
            return self.vc + self.a0 * w + self.a1 * ((t - p.t_ref) ** 2 - (self.tc - p.t_ref) ** 2) / 2
        om = p.omega
        return self.vc + self.a0 * w + self.a1 / om * (mpmath.sin(om * t) - mpmath.sin(om * self.tc))

    def x(self, t):
        p, w = self.p, t - self.tc
        if p.linear:
            bc = self.tc - p.t_ref
            return (self.xc + self.vc * w + self.a0 * w * w / 2
                    + self.a1 * (((t - p.t_ref) ** 3 - bc ** 3) / 6 - bc * bc * w / 2))
        om = p.omega
        sc, cc = mpmath.sin(om * self.tc), mpmath.cos(om * self.tc)
        return (self.xc + self.vc * w + self.a0 * w * w / 2
                + self.a1 / om * ((cc - mpmath.cos(om * t)) / om - w * sc))

    def normal_times_v(self, t1):
        """∫_tc^t1 N_f v dt (signed)."""
        p, t0 = self.p, self.tc
        if p.linear:
            # The integrand is a cubic in t: Gauss–Legendre with 2 nodes is exact.
            half, mid = (t1 - t0) / 2, (t1 + t0) / 2
            node = half / mpmath.sqrt(3)
            f = lambda t: p.normal(t) * self.v(t)
            return half * (f(mid - node) + f(mid + node))
        om = p.omega

        def by_parts(t):
            s, c = mpmath.sin(om * t), mpmath.cos(om * t)
            return s * self.v(t) / om + (self.a0 * c - self.a1 * s * s / 2) / om ** 2

        return p.n0 * (self.x(t1) - self.x(t0)) + p.n1 * (by_parts(t1) - by_parts(t0))

    def accel_zeros(self, lo, hi):
        p = self.p
        out = []
        if p.linear:
            if self.a1 != 0:
                out.append(p.t_ref - self.a0 / self.a1)
        elif self.a1 != 0:
            r = -self.a0 / self.a1
            if -1 < r < 1:
                th = mpmath.acos(r)
                out += [th / p.omega, (2 * mpmath.pi - th) / p.omega]
        return sorted(z for z in out if lo < z < hi)


def root(f, df, lo, hi, f_lo, f_hi, period):
    """Zero of a monotone f with f(lo) > 0 >= f(hi): Newton safeguarded by bisection."""
    tol = period * mpf(10) ** -36
    t = lo + (hi - lo) * f_lo / (f_lo - f_hi)
    for _ in range(400):
        if not (lo < t < hi):
            t = (lo + hi) / 2
        ft = f(t)
        if ft > 0:
            lo = t
        elif ft < 0:
            hi = t
        else:
            return t
        if hi - lo <= tol:
            return (lo + hi) / 2
        d = df(t)
        nxt = t - ft / d if d != 0 else lo - 1
        if lo < nxt < hi and abs(nxt - t) < tol / 4:
            return nxt
        t = nxt
    return (lo + hi) / 2


def first_onset(body, piece, frm):
    """Earliest slip onset in [frm, piece.end) from rest: (t, s) or None."""
    best = None
    for s in (1, -1):
        c0 = s * piece.d0 - body["mu_s"] * piece.n0
        c1 = s * piece.d1 - body["mu_s"] * piece.n1
        g = lambda t: c0 + c1 * piece.b(t)
        found = None
        gf = g(frm)
        if gf > 0:
            found = frm
        elif piece.linear:
            if c1 > 0:
                r = piece.t_ref - c0 / c1
                if frm <= r < piece.end:
                    found = r
        else:
            om = piece.omega
            slope = c1 * piece.db(frm)
            if gf == 0 and slope > 0:
                found = frm
            elif c1 != 0:
                r = -c0 / c1
                if -1 < r < 1:
                    th = mpmath.acos(r)
                    for t in sorted([th / om, (2 * mpmath.pi - th) / om]):
                        rising = c1 * (-om * mpmath.sin(om * t)) > 0
                        if frm <= t < piece.end and rising:
                            found = t
                            break
        if found is not None and (best is None or found < best[0]):
            best = (found, s)
    return best


def integrate(case):
    law, body, periods = case["law"], case["body"], case["periods"]
    body = {k: mpf(v) for k, v in body.items()}
    period = mpf(law["period"])
    pieces = [Piece(p) for p in law["pieces"]]
    x, v, dirn = mpf(0), mpf(0), 0
    xs, vs, diss, events = [], [], [], []
    tiny = period * mpf(10) ** -30
    for n in range(periods):
        xs.append(x)
        vs.append(v)
        work = mpf(0)
        ev = []
        for piece in pieces:
            t = piece.start
            transitions = 0
            while True:
                transitions += 1
                if transitions > MAX_TRANSITIONS_PER_PIECE:
                    raise RuntimeError("reference stalled at t = %s" % mpmath.nstr(n * period + t, 20))
                if dirn == 0:
                    onset = first_onset(body, piece, t)
                    if onset is None:
                        break
                    t, dirn = onset
                    if ev and ev[-1][1] == "stick" and abs(ev[-1][0] - t) <= tiny:
                        was = ev.pop()
                        if was[2] != dirn:
                            ev.append((t, "reversal", dirn))
                    else:
                        ev.append((t, "slip", dirn))
                    continue
                s = dirn
                a0 = (piece.d0 - s * body["mu_d"] * piece.n0) / body["mass"]
                a1 = (piece.d1 - s * body["mu_d"] * piece.n1) / body["mass"]
                arc = Arc(piece, a0, a1, t, x, v)
                # A zero of a within `tiny` of the start is the onset itself (μd = μs).
                bounds = arc.accel_zeros(t + tiny, piece.end) + [piece.end]
                p = t
                stick = None
                for q in bounds:
                    if s * arc.a((p + q) / 2) < 0:
                        sp, sq = s * arc.v(p), s * arc.v(q)
                        if sp <= 0:
                            stick = p
                        elif sq <= 0:
                            stick = root(lambda u: s * arc.v(u), lambda u: s * arc.a(u),
                                         p, q, sp, sq, period)
                        if stick is not None:
                            break
                    p = q
                end = piece.end if stick is None else stick
                work += abs(arc.normal_times_v(end))
                x = arc.x(end)
                if stick is None:
                    v = arc.v(end)
                    break
                v = mpf(0)
                ev.append((stick, "stick", dirn))
                dirn = 0
                t = stick
        diss.append(body["mu_d"] * work)
        events.append([[mpmath.nstr(n * period + e[0], 30), e[1], e[2]] for e in ev])
    xs.append(x)
    vs.append(v)
    fmt = lambda z: mpmath.nstr(z, 30)
    return {
        "events": events,
        "x_at_period_start": [fmt(z) for z in xs],
        "v_at_period_start": [fmt(z) for z in vs],
        "dissipation": [fmt(z) for z in diss],
    }


def main():
    cases = json.load(sys.stdin)
    json.dump([integrate(c) for c in cases], sys.stdout)


if __name__ == "__main__":
    main()
