"""What scripts/stem_matrix.py and scripts/stem_breaks.py share: the single-tree scene's command line, as
the outside checks call it, and the options that say which impacts to run."""
import argparse, os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def arguments(doc, dbh, speeds):
    """A parser with the options both take: the build, the node spacings, the stems and speeds, the
    threads and extra scene keys."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--exe", default=os.path.join(ROOT, "build/apps/sylvarock"), help="the sylvarock to run")
    ap.add_argument("--spacings", default="0.5,0.25,0.125", help="stem.node_spacing_m values, coarsest first")
    ap.add_argument("--dbh", default=dbh, help="stem diameters at breast height, cm")
    ap.add_argument("--speeds", default=speeds, help="block speeds, m/s")
    ap.add_argument("--threads", type=int, default=2, help="runs at a time")
    ap.add_argument("--set", action="append", default=[],
                    help="extra scene key=value for every run (not one the script sets itself: sylvarock refuses a key given twice)")
    return ap


def simulate_command(exe, out, dbh, speed, height, ecc, spacing, extra=()):
    """`sylvarock simulate` of one impact on the single tree, its results in `out`."""
    cmd = [exe, "simulate", "--scene", os.path.join(ROOT, "data/scenes/single-tree.ini"), "--set", f"tree.dbh_cm={dbh}",
           "--set", f"block.speed_m_s={speed}", "--set", f"block.impact_height_m={height}",
           "--set", f"block.eccentricity={ecc}", "--set", f"stem.node_spacing_m={spacing}", "--out", out]
    for kv in extra:
        cmd += ["--set", kv]
    return cmd
