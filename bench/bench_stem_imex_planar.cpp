// Would a stem step longer with its axial and shear springs integrated implicitly? (issue 12,
// docs/performance.md, "What would pay: a stem's own step"). A planar model of a stem, kept apart from
// libdem on purpose: a chain of nodes 0.5 m apart up a uniform 20 m beech (MOE 8.7 GPa, G = MOE / 2.6,
// 1 200 kg/m^3 as the calibrated set; no taper, crown, plasticity or damping), foot clamped, each
// connection an axial, a shear and a bending spring in the frame halfway between its nodes, the
// nodes' masses and rotational inertias lumped as Stem does. Two steppers:
//   Verlet: velocity Verlet on every spring, as libdem steps stems today;
//   IMEX:   half a kick of the bending springs, then the axial and shear springs over the whole step by
//           the trapezoidal rule linearised at its start (M + dt^2/4 K) dq = dt M v + dt^2/2 f, then
//           the other half kick. Its explicit bound is the bending springs' alone.
// A 1 350 kg block strikes the node 1 m up at 10 m/s through a penalty contact (explicit in both);
// printed: its speed when it leaves, and the largest contact force, against Verlet at 1/20 of the
// stem's Gershgorin bound. Then the stem's tip 1 s after a 2 m/s kick at 1 m, sampled every 5 ms,
// against the same reference: the wave field the implicit springs distort.
//   bench_stem_imex_planar
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using Vec = Eigen::VectorXd;
using Mat = Eigen::MatrixXd;

const double kPi = std::acos(-1.0);

// Node i (1..n) has x, z and the rotation phi at 3 (i - 1); node 0 is clamped at the origin.
struct PlanarStem {
    int n;
    double l, axial, shear, bending, mass, inertia;
    Vec m;  // per degree of freedom

    PlanarStem(double d, double height, double spacing) {
        n = static_cast<int>(std::ceil(height / spacing - 1e-9));
        l = height / n;
        const double moe = 8.7e9, g = moe / 2.6, rho = 1200, area = kPi * d * d / 4, second = kPi * std::pow(d, 4) / 64;
        axial = moe * area / l;
        shear = g * area / l;
        bending = moe * second / l;
        mass = rho * area * l;
        inertia = mass * (d * d / 16 + l * l / 12);  // as Stem
        m.resize(3 * n);
        for (int i = 0; i < n; ++i) {
            const double share = i == n - 1 ? 0.5 : 1.0;
            m[3 * i] = m[3 * i + 1] = share * mass;
            m[3 * i + 2] = share * inertia;
        }
    }
    Vec upright() const {
        Vec q = Vec::Zero(3 * n);
        for (int i = 1; i <= n; ++i) q[3 * (i - 1) + 1] = i * l;
        return q;
    }
    // Stem::stableTimeStep's Gershgorin bound at an inner node, and its bending row alone.
    double gershgorin() const {
        const double invShear = 1 / mass + 0.25 * l * l / inertia;
        return 2 / std::sqrt(4 * axial / mass + 4 * shear * invShear + 4 * bending / inertia);
    }
    double bendingBound() const { return 2 / std::sqrt(4 * bending / inertia); }

    // Forces of the axial and shear springs (stiff) and/or the bending springs; returns their energy.
    double forces(const Vec& q, Vec& f, bool stiff, bool bend) const {
        f.setZero(3 * n);
        double energy = 0;
        const auto at = [&](int i, int k) { return i == 0 ? 0.0 : q[3 * (i - 1) + k]; };
        for (int c = 0; c < n; ++c) {
            const int a = 3 * (c - 1), b = 3 * c;  // a < 0: the clamped foot
            if (stiff) {
                // Frame halfway: axis t = (sin psi, cos psi), normal u = (cos psi, -sin psi); U = ka e^2/2 + ks s^2/2.
                const double psi = 0.5 * (at(c, 2) + at(c + 1, 2));
                const double tx = std::sin(psi), tz = std::cos(psi), ux = tz, uz = -tx;
                const double dx = at(c + 1, 0) - at(c, 0), dz = at(c + 1, 1) - at(c, 1);
                const double e = dx * tx + dz * tz - l, s = dx * ux + dz * uz;
                energy += 0.5 * (axial * e * e + shear * s * s);
                const double gx = axial * e * tx + shear * s * ux, gz = axial * e * tz + shear * s * uz;
                const double gPsi = axial * e * s - shear * s * (e + l);  // de/dpsi = s, ds/dpsi = -(e + l)
                f[b] -= gx, f[b + 1] -= gz, f[b + 2] -= 0.5 * gPsi;
                if (a >= 0) f[a] += gx, f[a + 1] += gz, f[a + 2] -= 0.5 * gPsi;
            }
            if (bend) {
                const double turn = at(c + 1, 2) - at(c, 2);
                energy += 0.5 * bending * turn * turn;
                f[b + 2] -= bending * turn;
                if (a >= 0) f[a + 2] += bending * turn;
            }
        }
        return energy;
    }
    // The axial and shear springs' stiffness, -df/dq by central differences (a prototype's shortcut).
    Mat stiffness(const Vec& q) const {
        Mat k(q.size(), q.size());
        Vec plus, minus, p = q;
        for (Eigen::Index j = 0; j < q.size(); ++j) {
            const double h = 1e-7;
            p[j] = q[j] + h;
            forces(p, plus, true, false);
            p[j] = q[j] - h;
            forces(p, minus, true, false);
            p[j] = q[j];
            k.col(j) = -(plus - minus) / (2 * h);
        }
        return 0.5 * (k + k.transpose());
    }
};

struct State {
    Vec q, v;
};

void kick(const PlanarStem& s, State& x, double dt, bool stiff, bool bend) {
    Vec f;
    s.forces(x.q, f, stiff, bend);
    x.v += dt * f.cwiseQuotient(s.m);
}

void verlet(const PlanarStem& s, State& x, double dt) {
    kick(s, x, 0.5 * dt, true, true);
    x.q += dt * x.v;
    kick(s, x, 0.5 * dt, true, true);
}

void imex(const PlanarStem& s, State& x, double dt) {
    kick(s, x, 0.5 * dt, false, true);
    Vec f;
    s.forces(x.q, f, true, false);
    Mat a = dt * dt / 4 * s.stiffness(x.q);
    a.diagonal() += s.m;
    const Vec dq = a.ldlt().solve(dt * s.m.cwiseProduct(x.v) + dt * dt / 2 * f);
    x.v = 2 * dq / dt - x.v;
    x.q += dq;
    kick(s, x, 0.5 * dt, false, true);
}

using Stepper = void (*)(const PlanarStem&, State&, double);

struct Strike {
    double exitSpeed = 0, peakForce = 0;
    bool stable = true;
};

// The block moves along x at the height of node 2; both bodies take the contact's kicks around the
// stem's own step.
Strike strike(const PlanarStem& s, Stepper step, double dt, double speed) {
    const double blockMass = 1350, contactStiffness = 2e8;
    State x{s.upright(), Vec::Zero(3 * s.n)};
    double xb = 0, vb = speed;
    Strike r;
    bool touched = false;
    const auto contact = [&] { return std::max(0.0, contactStiffness * (xb - x.q[3])); };
    for (double t = 0; t < 0.5; t += dt) {
        double fc = contact();
        vb -= 0.5 * dt * fc / blockMass;
        x.v[3] += 0.5 * dt * fc / s.m[3];
        xb += dt * vb;
        step(s, x, dt);
        fc = contact();
        vb -= 0.5 * dt * fc / blockMass;
        x.v[3] += 0.5 * dt * fc / s.m[3];
        r.peakForce = std::max(r.peakForce, fc);
        touched = touched || fc > 0;
        if (!std::isfinite(vb) || std::abs(vb) > 10 * speed) {
            r.stable = false;
            return r;
        }
        if (touched && fc == 0 && xb < x.q[3] - 0.01) break;
    }
    r.exitSpeed = vb;
    return r;
}

// The tip's x every 5 ms for 1 s after a 2 m/s sideways kick of node 2; empty if the energy blew up.
std::vector<double> sway(const PlanarStem& s, Stepper step, double dt) {
    State x{s.upright(), Vec::Zero(3 * s.n)};
    x.v[3] = 2;
    const int perSample = static_cast<int>(std::lround(0.005 / dt));
    std::vector<double> tip;
    for (int k = 0; k <= 200 * perSample; ++k) {
        if (k % perSample == 0) {
            tip.push_back(x.q[3 * (s.n - 1)]);
            if (!std::isfinite(tip.back()) || std::abs(tip.back()) > 1) return {};
        }
        step(s, x, dt);
    }
    return tip;
}

// A step of about `fraction` of the Gershgorin bound that divides 5 ms, so that samples line up.
double stepNear(double fraction, const PlanarStem& s) { return 0.005 / std::ceil(0.005 / (fraction * s.gershgorin())); }

}  // namespace

int main() {
    const double today = 0.8;  // integration.stem_safety
    const double multiples[] = {1.0, 2.5, 3.5, 4.4};
    std::printf("block 1350 kg at 10 m/s on a planar stem, 1 m up; against Verlet at 1/20 of the bound\n");
    std::printf("%-6s %-7s %-7s %10s %12s %12s\n", "DBH", "scheme", "step", "dt s", "exit energy", "peak force");
    for (const double d : {0.1, 0.2, 0.3, 0.4}) {
        const PlanarStem s(d, 20, 0.5);
        const Strike ref = strike(s, verlet, stepNear(0.05, s), 10);
        for (const auto& [name, step] : {std::pair<const char*, Stepper>{"Verlet", verlet}, {"IMEX", imex}}) {
            for (const double x : multiples) {
                if (step == verlet && x > 1) continue;
                const double dt = x * today * s.gershgorin();
                const Strike r = strike(s, step, dt, 10);
                if (!r.stable) {
                    std::printf("%4.0f cm %-7s %5.1fx %10.2e %25s\n", 100 * d, name, x, dt, "unstable");
                    continue;
                }
                // Relative to the impact energy, as the single-tree matrix reads it.
                const double gap = (r.exitSpeed * r.exitSpeed - ref.exitSpeed * ref.exitSpeed) / 100;
                std::printf("%4.0f cm %-7s %5.1fx %10.2e %+11.2f%% %+11.1f%%\n", 100 * d, name, x, dt, 100 * gap,
                            100 * (r.peakForce / ref.peakForce - 1));
            }
        }
        std::printf("       (bending bound %.2e s = %.1fx today's step; the contact's own bound %.2e s)\n", s.bendingBound(),
                    s.bendingBound() / (today * s.gershgorin()), 2 / std::sqrt(2e8 / s.m[3]));
    }
    const PlanarStem s(0.2, 20, 0.5);
    const std::vector<double> ref = sway(s, verlet, stepNear(0.05, s));
    double amplitude = 0;
    for (const double x : ref) amplitude = std::max(amplitude, std::abs(x));
    std::printf("20 cm stem's tip over 1 s after a 2 m/s kick at 1 m, largest gap to the reference (of its largest swing):\n");
    for (const auto& [name, step, fraction] : {std::tuple<const char*, Stepper, double>{"Verlet", verlet, 0.8},
                                               {"IMEX", imex, 0.8}, {"IMEX", imex, 2.0}, {"IMEX", imex, 2.8}}) {
        const double dt = stepNear(fraction, s);
        const std::vector<double> tip = sway(s, step, dt);
        if (tip.empty()) {
            std::printf("  %-7s %.2e s: unstable\n", name, dt);
            continue;
        }
        double gap = 0;
        for (std::size_t i = 0; i < std::min(tip.size(), ref.size()); ++i) gap = std::max(gap, std::abs(tip[i] - ref[i]));
        std::printf("  %-7s %.2e s (%.1fx today's): %.1f %%\n", name, dt, dt / (today * s.gershgorin()), 100 * gap / amplitude);
    }
    return 0;
}
