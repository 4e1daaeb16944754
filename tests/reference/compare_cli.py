#!/usr/bin/env python3
"""Before/after: a stickslip binary's `eval --json` on the reference test's sets against the
40-digit truth of tests/reference/mp_engine.py (forces from the parameters alone).
Usage: python3 tests/reference/compare_cli.py BINARY SETS.json tests/reference/mp_engine.py
with SETS.json written by `STICKSLIP_REFERENCE_SETS=SETS.json cargo test --release --test
reference`: measures any built binary (an older one included) on the same sets and truth."""
import json, subprocess, sys, tempfile, os
binary, sets_path, script = sys.argv[1:4]
PERIODS = 10
sets = json.load(open(sets_path))
cases = []
for s in sets:
    for law in ("linear", "harmonic"):
        cases.append({"model": s["model"], "law": law, "params": s["params"], "periods": PERIODS})
ref = json.loads(subprocess.run(["python3", script], input=json.dumps(cases), capture_output=True, text=True, check=True).stdout)
from mpmath import mpf
rows = {}
def toml_val(v):
    if isinstance(v, str): return json.dumps(v)
    return repr(float(v))
for i, s in enumerate(sets):
    p = dict(s["params"])
    if s["model"] == "woodpecker":
        p["omega"] = p.pop("omega_mode")
    with tempfile.NamedTemporaryFile("w", suffix=".toml", delete=False) as f:
        f.write('model = "%s"\ntitle = "x"\n[params]\n' % s["model"])
        for k, v in p.items():
            if v is None: continue
            f.write("%s = %s\n" % (k, toml_val(v)))
        name = f.name
    out = subprocess.run([binary, "eval", s["model"], "--scenario", name, "--periods", str(PERIODS), "--json"], capture_output=True, text=True)
    os.unlink(name)
    for j, law in enumerate(("linear", "harmonic")):
        key = (s["region"], law)
        row = rows.setdefault(key, {"n": 0, "refused": 0, "bad": 0, "err": [0.0] * 5})
        row["n"] += 1
        if out.returncode != 0:
            row["refused"] += 1
            continue
        e = json.loads(out.stdout)[law]
        r = ref[2 * i + j]
        T = mpf(r["period"])
        adv = mpf(r["advance"][-1])
        drive = float(p["force"]) if s["model"] == "pulled-mass" else float(p["m_sleeve"]) * float(p["g"])
        truth = [adv / T, adv, drive * (adv / T), mpf(r["dissipation"][-1]) / T]
        maxima = [mpf(m[1]) for m in r["speed_maxima"][-1]]
        if e is None or e["v_avg"] is None or len(e["steady_speed_maxima"]) != len(maxima):
            row["bad"] += 1
            continue
        power_key = "power" if s["model"] == "pulled-mass" else "power_weight"
        mine = [e["v_avg"], e["advance_per_period"], e[power_key], e["power_friction"]]
        errs = [float(abs(mpf(a) - b) / abs(b)) for a, b in zip(mine, truth)]
        errs.append(max([float(abs(mpf(m["v"]) - t) / abs(t)) for m, t in zip(e["steady_speed_maxima"], maxima)] or [0.0]))
        row["err"] = [max(a, b) for a, b in zip(row["err"], errs)]
print("%-30s %-8s %3s %4s %4s %9s %9s %9s %9s %9s" % ("region", "law", "n", "ref.", "bad", "v_avg", "advance", "power", "friction", "v_max"))
for (region, law), row in rows.items():
    print("%-30s %-8s %3d %4d %4d %s" % (region, law, row["n"], row["refused"], row["bad"], " ".join("%9.1e" % x for x in row["err"])))
