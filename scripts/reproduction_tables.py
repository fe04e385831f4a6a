#!/usr/bin/env python3
"""Markdown tables of docs/reproduction.md from an assess campaign's results.json (and its report's
wall time, if given): PF50 per stand and structure beside the paper's reading, the rankings, the
correlations of Fig. 12, and the virtual forests' Table 3.
    python3 scripts/reproduction_tables.py OUT/results.json [MODEL]
MODEL: with `assess --model both`, `lumped` reads the lumped model's results (the DEM's are the file's top level)."""
import json
import sys

res = json.load(open(sys.argv[1]))
if len(sys.argv) > 2 and sys.argv[2] != res.get("model", "dem"):
    if sys.argv[2] not in res:
        sys.exit(f"{sys.argv[1]} holds no {sys.argv[2]} results: its campaign ran the {res.get('model', 'dem')} model "
                 f"(`assess --model both` runs the two side by side)")
    res = res[sys.argv[2]]
rows = res["stands"]
names = sorted({r["name"] for r in rows})
by = {(r["name"], r["structure"]): r for r in rows}

print(f"Baseline (no forest): Dist50 {res['baseline']['dist50_m']:.1f} m over {res['baseline']['runs']} runs\n")
print("| stand | G m²/ha | N /ha | Mean_D cm | R_Clark | Dist50 A m | PF50 A [95 % CI] | Dist50 NA m | PF50 NA [95 % CI] | NA − A |")
print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
for n in names:
    a, na = by[(n, "A")], by[(n, "NA")]
    ci = lambda r: f"{r['pf50']:.3f} [{r['pf50_ci'][0]:.3f}, {r['pf50_ci'][1]:.3f}]"
    print(f"| {n} | {a['basal_area_m2_ha']:.1f} | {a['stems_per_ha']:.0f} | {a['mean_dbh_cm']:.1f} | {a['clark_evans']:.2f} | "
          f"{a['dist50_m']:.1f} | {ci(a)} | {na['dist50_m']:.1f} | {ci(na)} | {na['pf50'] - a['pf50']:+.3f} |")
pfs = [r["pf50"] for r in rows]
print(f"\nPF50 range: {min(pfs):.2f}–{max(pfs):.2f}; NA above A in "
      f"{sum(by[(n, 'NA')]['pf50'] > by[(n, 'A')]['pf50'] for n in names)} of {len(names)} stands; "
      f"mean NA − A {sum(by[(n, 'NA')]['pf50'] - by[(n, 'A')]['pf50'] for n in names) / len(names):+.3f}\n")
for s, rk in res["rankings"].items():
    print(f"- {s}, least to most protective: {', '.join(rk['by_pf50'])}; by G: {', '.join(rk['by_basal_area'])}")
print()
print("| structure | stands | r(PF50, G) | r(PF50, Mean_D) | r(PF50, N) |")
print("| --- | --- | --- | --- | --- |")
fmt = lambda v: "—" if v is None else f"{v:+.2f}"
def cell(c, key):  # r, and its p-value where the campaign wrote one
    p = c.get("p_" + key)
    return fmt(c["pearson_" + key]) + ("" if p is None else f" (p {p:.3f})")
for c in res["correlations"]:
    print(f"| {c['structure']} | {c['stands']} | {cell(c, 'pf50_basal_area')} | {cell(c, 'pf50_mean_dbh')} | {cell(c, 'pf50_stems_per_ha')} |")
if any(len(r["pf50_realisations"]) > 1 for r in rows):
    print("\nPF50 per forest realisation:\n")
    for n in names:
        for s in ("A", "NA"):
            r = by[(n, s)]
            print(f"- {n} {s}: " + ", ".join(f"{v:.2f}" for v in r["pf50_realisations"]))
print("\nVirtual forests (Table 3; the first realisation):\n")
print("| forest | N /ha | G m²/ha | Mean_D cm | Std_D cm | R_Clark |")
print("| --- | --- | --- | --- | --- | --- |")
for n in names:
    for s in ("A", "NA"):
        f = by[(n, s)]["virtual_forests"][0]
        print(f"| {n}_{s} | {f['stems_per_ha']:.0f} | {f['basal_area_m2_ha']:.2f} | {f['mean_dbh_cm']:.2f} | {f['sd_dbh_cm']:.2f} | {f['clark_evans']:.2f} |")
