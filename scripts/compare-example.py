#!/usr/bin/env python3
"""Compares a run of the main example (its summary.json) with the figures of the solver before issue 9
(tests/reference/example_before_issue9.json): Qz of every load point, the footprint's deflection, Qy of
every rolling state and sweep point. Prints each relative difference and the largest; exits 1 when one
exceeds the tolerance (default 1e-6).  Usage: compare-example.py SUMMARY.json [TOLERANCE]"""
import json
import pathlib
import sys

reference = json.loads((pathlib.Path(__file__).parent.parent / "tests/reference/example_before_issue9.json").read_text())
summary = json.loads(pathlib.Path(sys.argv[1]).read_text())
tolerance = float(sys.argv[2]) if len(sys.argv) > 2 else 1e-6
worst = 0.0


def compare(label, new, old, scale):
    global worst
    rel = abs(new - old) / max(abs(old), scale)
    worst = max(worst, rel)
    flag = "  <-- differs" if rel > tolerance else ""
    print(f"{label:45s} {old:14.6f} {new:14.6f} {rel:9.2e}{flag}")


for curve in summary.get("load_curves", []):
    old = dict((round(d, 9), q) for d, q in reference["load_curves"].get(curve["name"], []))
    for p in curve["points"]:
        d = round(p["deflection_mm"], 9)
        if d in old:
            compare(f"load curve {curve['name']} Qz at {d:g} mm", p["Qz_N"], old[d], 1.0)
for f in summary.get("footprints", []):
    old = reference["footprints"].get(f["name"])
    if old:
        compare(f"footprint {f['name']} deflection", f["deflection_mm"], old["deflection_mm"], 1e-3)
for r in summary.get("rolling", []):
    old = reference["rolling"].get(r["name"])
    if not old:
        continue
    qz = max(abs(s.get("Qz_N", 0.0)) for s in r["states"]) or 1.0
    for s in r["states"]:
        if s["name"] in old["states"]:
            # A near-zero Qy (free rolling) is compared relative to Qz.
            compare(f"rolling {r['name']} {s['name']} Qy", s["Qy_N"], old["states"][s["name"]], 1e-6 * qz)
    sweep = dict((round(k, 9), q) for k, q in old["sweep"])
    for p in r.get("sweep", []):
        k = round(p["slip"], 9)
        if k in sweep:
            compare(f"rolling {r['name']} sweep Qy at κ {k:g}", p["Qy_N"], sweep[k], 1e-6 * qz)
print(f"largest relative difference {worst:.2e} (tolerance {tolerance:g})")
sys.exit(0 if worst <= tolerance else 1)
