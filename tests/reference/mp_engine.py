#!/usr/bin/env python3
"""High-precision reference for the engine (src/engine): the state machine of guide §4
integrated with mpmath at 40 significant digits or more.

Reads a JSON list of cases on stdin and writes a JSON list of results, one per case. A case is
either

* {"model": "pulled-mass" | "woodpecker", "law": "linear" | "harmonic", "params": {...},
  "periods": N}: the forces are built here from the parameters alone (guide §5.1, guide §5.2:
  W, ω, T, the triangle waves, F_e, its zeros, the linear counterparts, λ), in exact arithmetic
  on the doubles given, sharing nothing with the engine's serialized force law; the working
  precision grows with the small parameter of short slips (φ = F/W, ε = W_S/(k ζ0)) so that
  40 digits survive the cancellations of a slip 1/φ or 1/ε times shorter than the period; or
* {"law": ForceLaw, "body": Body, "periods": N} as the engine serializes them (the doubles are
  taken as exact numbers): the bench's check of the exact engine on its own force laws.

Per case: the transitions [t, kind, dir] of every period ("slip", "stick", "reversal"), the
speed maxima [t, v] of every period, the position and velocity at each period start, the
advance of each period (formed at full precision) and the friction dissipation ∫ μd N_f |v| dt
of each period. Numbers are written as decimal strings with
30 digits.

The motion on a piece is the closed form of guide §4 (a = A0 + A1 b(t), b = t − t_ref or
cos ωt) evaluated at high precision, so the cancellations that the engine must avoid in double
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
    """D = d0 + d1 b(t), N_f = n0 + n1 b(t) on [start, end); b = t − t_ref or cos ωt."""

    def __init__(self, start, end, t_ref, omega, drive, normal):
        self.start, self.end = start, end
        self.linear = omega is None
        self.t_ref, self.omega = t_ref, omega
        self.d0, self.d1 = drive
        self.n0, self.n1 = normal

    @staticmethod
    def serialized(p):
        """A piece as the engine serializes it."""
        basis = p["basis"]
        linear = basis["kind"] == "linear"
        piece = Piece(mpf(p["start"]), mpf(p["end"]),
                      mpf(basis["t_ref"]) if linear else None,
                      None if linear else mpf(basis["omega"]),
                      (mpf(p["drive"]["c0"]), mpf(p["drive"]["c1"])),
                      (mpf(p["normal"]["c0"]), mpf(p["normal"]["c1"])))
        # b = cos ωt − shift: the same affine functions of cos ωt, c0 − c1·shift + c1 cos ωt.
        shift = mpf(basis.get("shift", 0))
        piece.d0 -= piece.d1 * shift
        piece.n0 -= piece.n1 * shift
        return piece

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


def pulled_mass(law, p):
    """guide §5.1: M = 2m, W = m g, ω = √(k/m), D = F; N = W(1 + cos ωt) or the triangle
    wave 2W|1 − 2t/T| (vertex 0 at T/2). Returns (period, pieces, body, φ)."""
    mu_s, mu_d, m, k, F, g = (mpf(p[key]) for key in ("mu_s", "mu_d", "mass", "k", "force", "g"))
    W = m * g
    omega = mpmath.sqrt(k / m)
    T = 2 * mpmath.pi / omega
    if law == "harmonic":
        pieces = [Piece(mpf(0), T, None, omega, (F, mpf(0)), (W, W))]
    else:
        half = T / 2
        slope = 4 * W / T
        pieces = [Piece(mpf(0), half, half, None, (F, mpf(0)), (mpf(0), -slope)),
                  Piece(half, T, half, None, (F, mpf(0)), (mpf(0), slope))]
    return T, pieces, {"mass": 2 * m, "mu_s": mu_s, "mu_d": mu_d}, F / W


def woodpecker(law, p):
    """guide §5.2: M = m_S, D = W_S + F_e, N_f = 2λ|F_e|, F_e = k(z0 + d0 cos ωt) or
    k(δ0 + ζ(t)) with the triangle ζ of amplitude ζ0 and the counterpart's (ζ0, δ0); pieces cut
    at the zeros of F_e. Returns (period, pieces, body, ε = W_S/(k ζ0))."""
    num = lambda key: mpf(p[key])
    mu_s, mu_d, k, m_s, m_w = num("mu_s"), num("mu_d"), num("k"), num("m_sleeve"), num("m_bird")
    z0, d0, g = num("z0"), num("d0"), num("g")
    lam = num("lever") if p.get("lever") is not None else num("l") / num("h")
    omega = {"bird": mpmath.sqrt(k / m_w),
             "reduced": mpmath.sqrt(k * (m_s + m_w) / (m_s * m_w)),
             "total": mpmath.sqrt(k / (m_s + m_w))}[p["omega_mode"]]
    T = 2 * mpmath.pi / omega
    w_s = m_s * g
    pieces = []

    def add(start, end, t_ref, om, f0, f1):
        """F_e = f0 + f1 b on [start, end), its sign read at the middle."""
        mid = (start + end) / 2
        b = mid - t_ref if om is None else mpmath.cos(om * mid)
        sign = 1 if f0 + f1 * b > 0 else -1
        pieces.append(Piece(start, end, t_ref, om, (w_s + f0, f1),
                            (2 * lam * sign * f0, 2 * lam * sign * f1)))

    if law == "harmonic":
        zeta0 = d0
        cuts = [mpf(0)]
        if abs(z0) < d0:
            t1 = mpmath.acos(-z0 / d0) / omega
            cuts += [t1, T - t1]
        cuts.append(T)
        for a, b in zip(cuts, cuts[1:]):
            add(a, b, None, omega, k * z0, k * d0)
    else:
        counterpart = p["counterpart"]
        if counterpart == "extremes":
            zeta0, delta0 = d0, z0
        elif counterpart == "zeros":
            zeta0, delta0 = d0, d0 * 2 / mpmath.pi * mpmath.asin(z0 / d0)
        else:
            zeta0 = mpmath.pi / 2 * mpmath.sqrt(d0 * d0 - z0 * z0)
            delta0 = zeta0 * 2 / mpmath.pi * mpmath.asin(z0 / d0)
        tau = T / 4
        rate = k * zeta0 / tau
        # ζ = ζ0(1 − t/τ) on [0, 2τ], ζ0(t/τ − 3) on [2τ, 4τ]; F_e = k(δ0 + ζ), written about the
        # start of each half and cut at its zero.
        for start, end, f_start, r in ((mpf(0), 2 * tau, k * (delta0 + zeta0), -rate),
                                       (2 * tau, T, k * (delta0 - zeta0), rate)):
            zero = start - f_start / r
            cuts = [start] + ([zero] if start < zero < end else []) + [end]
            for a, b in zip(cuts, cuts[1:]):
                add(a, b, start, None, f_start, r)
    body = {"mass": m_s, "mu_s": mu_s, "mu_d": mu_d}
    return T, pieces, body, w_s / (k * zeta0)


def integrate(case):
    periods = case["periods"]
    if "model" in case:
        build = pulled_mass if case["model"] == "pulled-mass" else woodpecker
        # The small parameter at the working precision of the result, then the precision that
        # keeps 40 digits through the cancellations of slips that short (three factors of it
        # cancel at most, in the cubic of a position).
        mp.dps = 40
        small = build(case["law"], case["params"])[3]
        lost = max(0, int(mpmath.ceil(-mpmath.log10(small)))) if small > 0 else 0
        mp.dps = 40 + 3 * lost
        period, pieces, body, _ = build(case["law"], case["params"])
    else:
        mp.dps = 40
        law, body = case["law"], case["body"]
        body = {k: mpf(v) for k, v in body.items()}
        period = mpf(law["period"])
        pieces = [Piece.serialized(p) for p in law["pieces"]]
    result = run(period, pieces, body, periods)
    mp.dps = 40
    return result


def run(period, pieces, body, periods):
    x, v, dirn = mpf(0), mpf(0), 0
    xs, vs, diss, events, maxima = [], [], [], [], []
    tiny = period * mpf(10) ** -30
    # The sign of s·a on the last slipping stretch: a speed maximum where it turns from + to −
    # (inside a piece at a zero of a, or at a piece boundary).
    accel_sign = 0
    for n in range(periods):
        xs.append(x)
        vs.append(v)
        work = mpf(0)
        ev = []
        mx = []
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
                    accel_sign = 0
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
                    sa = s * arc.a((p + q) / 2)
                    sign = 1 if sa > 0 else (-1 if sa < 0 else 0)
                    if accel_sign > 0 and sign < 0:
                        mx.append((p, arc.v(p)))
                    if sign != 0:
                        accel_sign = sign
                    if sign < 0:
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
        maxima.append([[mpmath.nstr(n * period + e[0], 30), mpmath.nstr(e[1], 30)] for e in mx])
    xs.append(x)
    vs.append(v)
    fmt = lambda z: mpmath.nstr(z, 30)
    return {
        "period": fmt(period),
        "events": events,
        "speed_maxima": maxima,
        "x_at_period_start": [fmt(z) for z in xs],
        "advance": [fmt(b - a) for a, b in zip(xs, xs[1:])],
        "v_at_period_start": [fmt(z) for z in vs],
        "dissipation": [fmt(z) for z in diss],
    }


def main():
    cases = json.load(sys.stdin)
    json.dump([integrate(c) for c in cases], sys.stdout)


if __name__ == "__main__":
    main()
