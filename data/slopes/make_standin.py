#!/usr/bin/env python3
"""Stand-in terrains for sylvarock (Python 3 standard library only, deterministic output).

The slope profile of Toe et al. (630 m of a 2 m DTM of the Vercors) is not published. This
script builds a documented stand-in (see README.md in this folder):

  make_standin.py --sigma S --seed K --out FILE   slope profile x,z: mean shape + AR(1) micro-topography
  make_standin.py --dtm --out FILE                small example DTM (.asc): tilted plane with a gully

The random numbers come from our own generator (splitmix64 seeding, xorshift64*, Box-Muller), not
from the `random` module, so that a file is the same on any Python 3.
"""
import argparse
import math
import sys

MASK64 = (1 << 64) - 1

# Mean shape: (x where the segment ends in m, angle in degrees). Release is at x = 100 m on the
# upper talus, the forest starts at x = 130 m.
SEGMENTS = [(140.0, 39.0), (300.0, 31.0), (380.0, 25.0), (630.0, 12.0)]
Z_TOP = 520.0  # m, height at x = 0 (the foot then lies near the Grenoble valley floor, ~220 m)
DX = 2.0  # m, resolution of the DTM the paper's profile came from
RELEASE_TAPER = 100.0  # m: the noise grows from 0 at x = 0 to full amplitude at the release point


class Xorshift64Star:
    """xorshift64* (Vigna 2016), seeded through splitmix64 so that any seed, 0 included, is fine."""

    def __init__(self, seed):
        z = (seed + 0x9E3779B97F4A7C15) & MASK64
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK64
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK64
        self.state = (z ^ (z >> 31)) or 1
        self.spare = None

    def uniform(self):
        """Uniform in (0, 1]: 53 random bits, never 0 (Box-Muller takes its log)."""
        x = self.state
        x ^= x >> 12
        x ^= (x << 25) & MASK64
        x ^= x >> 27
        self.state = x
        return (((x * 0x2545F4914F6CDD1D) & MASK64) >> 11) * 2.0**-53 + 2.0**-53

    def normal(self):
        """Standard normal by Box-Muller; each pair of uniforms gives two values."""
        if self.spare is not None:
            value, self.spare = self.spare, None
            return value
        r = math.sqrt(-2.0 * math.log(self.uniform()))
        phi = 2.0 * math.pi * self.uniform()
        self.spare = r * math.sin(phi)
        return r * math.cos(phi)


def mean_height(x):
    """Piecewise-linear mean shape: Z_TOP at x = 0, falling at each segment's angle."""
    z, start = Z_TOP, 0.0
    for end, angle in SEGMENTS:
        run = min(x, end) - start
        if run <= 0.0:
            break
        z -= run * math.tan(math.radians(angle))
        start = end
    return z


def release_taper(x):
    """Raised cosine from 0 at x = 0 to 1 at the release point, so no pit traps a block up there."""
    if x >= RELEASE_TAPER:
        return 1.0
    return 0.5 * (1.0 - math.cos(math.pi * x / RELEASE_TAPER))


def ar1_noise(n, sigma, corr_length, rng):
    """Stationary AR(1) series with standard deviation sigma and correlation exp(-lag / corr_length)."""
    rho = math.exp(-DX / corr_length)
    innovation = sigma * math.sqrt(1.0 - rho * rho)
    e = sigma * rng.normal()  # started in the stationary distribution: no spin-up transient
    out = [e]
    for _ in range(n - 1):
        e = rho * e + innovation * rng.normal()
        out.append(e)
    return out


def write_profile(out, sigma, seed, corr_length):
    n = int(round(SEGMENTS[-1][0] / DX)) + 1
    noise = ar1_noise(n, sigma, corr_length, Xorshift64Star(seed))
    out.write("# Stand-in slope profile, NOT the Vercors profile of Toe et al. (see data/slopes/README.md).\n")
    out.write("# make_standin.py --sigma %g --seed %d --corr-length %g\n" % (sigma, seed, corr_length))
    out.write("x,z\n")
    for k in range(n):
        x = k * DX
        out.write("%.1f,%.3f\n" % (x, mean_height(x) + release_taper(x) * noise[k]))


def write_example_dtm(out):
    """100 x 60 cells of 2 m: a 30 degree plane falling towards +x with a gully along x at y = 60 m
    (Gaussian cross-section, 3 m deep, 6 m standard width). Along any line y = const the surface is
    a straight line, so lengths along x are known exactly: dx / cos(30 deg)."""
    ncols, nrows, cell = 100, 60, 2.0
    out.write("ncols %d\nnrows %d\nxllcorner 0\nyllcorner 0\ncellsize %g\nNODATA_value -9999\n" % (ncols, nrows, cell))
    for row in range(nrows - 1, -1, -1):  # north first
        y = (row + 0.5) * cell
        gully = -3.0 * math.exp(-0.5 * ((y - 60.0) / 6.0) ** 2)
        values = ("%.3f" % (300.0 - math.tan(math.radians(30.0)) * (col + 0.5) * cell + gully) for col in range(ncols))
        out.write(" ".join(values) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sigma", type=float, default=0.0, help="standard deviation of the micro-topography, m")
    parser.add_argument("--seed", type=int, default=1, help="seed of the micro-topography (>= 0)")
    parser.add_argument("--corr-length", type=float, default=6.0, help="correlation length of the AR(1) noise, m")
    parser.add_argument("--dtm", action="store_true", help="write the example DTM instead of a profile")
    parser.add_argument("--out", required=True, help="output file")
    args = parser.parse_args()
    if not args.sigma >= 0.0 or math.isinf(args.sigma):
        parser.error("--sigma must be a finite number >= 0")
    if args.seed < 0 or args.seed > MASK64:
        parser.error("--seed must be in [0, 2^64)")
    if not args.corr_length > 0.0 or math.isinf(args.corr_length):
        parser.error("--corr-length must be a finite number > 0")
    with open(args.out, "w", newline="\n") as out:
        if args.dtm:
            write_example_dtm(out)
        else:
            write_profile(out, args.sigma, args.seed, args.corr_length)
    return 0


if __name__ == "__main__":
    sys.exit(main())
