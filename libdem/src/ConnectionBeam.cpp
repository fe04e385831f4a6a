#include "libdem/ConnectionBeam.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace sylva::dem {

namespace {

const double kInner = std::sqrt(3.0 / 7.0);

}  // namespace

// Gauss-Lobatto points xi on [-1, 1] (node a at -1, node b at +1) and weights, normalised to sum 1:
// the mean over the connection of a quantity sampled at the sections. The 3-point rule is Simpson's.
struct ConnectionBeam::Rule {
    int count;
    double xi[kMaxSections];
    double weight[kMaxSections];
};

namespace {
const ConnectionBeam::Rule kRules[] = {
    {1, {0}, {1}},
    {3, {-1, 0, 1}, {1.0 / 6, 2.0 / 3, 1.0 / 6}},
    {5, {-1, -kInner, 0, kInner, 1}, {1.0 / 20, 49.0 / 180, 16.0 / 45, 49.0 / 180, 1.0 / 20}},
};
}  // namespace

ConnectionBeam::ConnectionBeam(const BendingParams& p, double diameterA, double diameterB, double shearStiffness,
                               double length, int sections)
    : k_(bendingCoefficients(p, 0.5 * (diameterA + diameterB), length)), shearStiffness_(shearStiffness),
      length_(length), rule_(nullptr), reading_(p.reading), brittle_(!(p.fractureEnergy > 0)) {
    for (const Rule& r : kRules)
        if (r.count == sections) rule_ = &r;
    if (!rule_) throw std::invalid_argument("ConnectionBeam: " + std::to_string(sections) + " sections (1, 3 or 5)");
    for (int i = 0; i < rule_->count; ++i) {
        const double d = diameterA + (diameterB - diameterA) * 0.5 * (rule_->xi[i] + 1);
        const HingeCoefficients& k = sectionK_[i] = bendingCoefficients(p, d, length);
        // Along the plastic branch dtheta = dM / K_Unld + d(plastic) and dM = K_Plast dtheta (Eqs. 3-4).
        hardening_[i] = k.plastic > 0 ? k.plastic * k.unloading / (k.unloading - k.plastic) : 0;
        elasticCompliance_[i] = 1 / k.elastic;
        unloadingCompliance_[i] = 1 / k.unloading;
        for (Channel& ch : channels_) ch.section[i] = Section{Moment::Zero(), k.yieldMoment};
    }
    for (Channel& ch : channels_) ch.mean = ch.change = Moment::Zero();
}

// The connection's deformations are the sections' ones summed with their weights, plus the shear
// spring's: theta = sum w (c m + p), eps = sum w xi (c m + p) + 4 / (l^2 k_s) dM, where m = M + xi dM,
// c the section's compliance and p its plastic rotation (the force-based element's compatibility).
ConnectionBeam::Flexibility ConnectionBeam::flexibility(const Channel& ch) const {
    std::array<double, kMaxSections> c{};
    for (int i = 0; i < rule_->count; ++i) c[i] = compliance(i, ch.section[i]);
    return flexibility(c);
}

ConnectionBeam::Flexibility ConnectionBeam::flexibility(const std::array<double, kMaxSections>& compliance) const {
    const Rule& r = *rule_;
    Flexibility f{0, 0, 4 / (length_ * length_ * shearStiffness_), 0};
    for (int i = 0; i < r.count; ++i) {
        const double wc = r.weight[i] * compliance[i];
        f.mm += wc;
        f.mc += wc * r.xi[i];
        f.cc += wc * r.xi[i] * r.xi[i];
    }
    f.inverseDet = 1 / (f.mm * f.cc - f.mc * f.mc);
    return f;
}

Eigen::Matrix2d ConnectionBeam::elasticStiffness() const {
    const Flexibility f = flexibility(elasticCompliance_);
    Eigen::Matrix2d flex;
    flex << f.mm, f.mc, f.mc, f.cc;
    return flex.inverse();
}

void ConnectionBeam::solveForces(Channel& ch, const Moment& theta, const Moment& eps) const {
    const Rule& r = *rule_;
    Moment a = theta, b = eps;
    for (int i = 0; i < r.count; ++i) {
        a -= r.weight[i] * ch.section[i].plastic;
        b -= r.weight[i] * r.xi[i] * ch.section[i].plastic;
    }
    if (ch.flexibilityStale) {
        ch.flexibility = flexibility(ch);
        ch.flexibilityStale = false;
    }
    const Flexibility f = ch.flexibility;
    ch.mean = f.inverseDet * (f.cc * a - f.mc * b);
    ch.change = f.inverseDet * (f.mm * b - f.mc * a);
}

double ConnectionBeam::channelEnergy(const Channel& ch) const {
    const Flexibility& f = ch.flexibility;
    return 0.5 * (f.mm * ch.mean.squaredNorm() + 2 * f.mc * ch.mean.dot(ch.change) + f.cc * ch.change.squaredNorm());
}

// An elastic trial from the sections' plastic state; sections beyond their elastic domain |m| <= M_y
// flow radially, dp = lambda n, and harden, M_y += H lambda, until they are back on it; the flows of
// the yielded sections are coupled through the element (one small linear system on the active set).
// With one section this is the closed-form trilinear path of BendingLaw, whatever the increment.
HingeWork ConnectionBeam::deformChannel(Channel& ch, const Moment& theta, const Moment& eps) {
    const Rule& r = *rule_;
    const int n = r.count;
    HingeWork w;
    solveForces(ch, theta, eps);
    const auto sectionMomentOf = [&](int i) -> Moment { return ch.mean + r.xi[i] * ch.change; };

    // First yield: the section's elastic stiffness drops to K_Unld (Fig. 3). Its deformation at the
    // yield moment is kept, so the energy it stores there grows: the law creates it (Eq. 4).
    bool switched = false, beyond = false;
    for (int i = 0; i < n; ++i) {
        Section& s = ch.section[i];
        const Moment m = sectionMomentOf(i);
        if (m.squaredNorm() <= s.yieldMoment * s.yieldMoment) continue;  // the common case, without a root
        beyond = true;
        if (s.yielded) continue;
        const double norm = m.norm();
        const double softening = 1 / sectionK_[i].unloading - 1 / sectionK_[i].elastic;
        s.plastic -= softening * s.yieldMoment / norm * m;
        w.created += r.weight[i] * 0.5 * s.yieldMoment * s.yieldMoment * softening;
        s.yielded = switched = true;
        ch.flexibilityStale = true;
    }
    if (!beyond) return w;  // every section elastic: the trial below would find none active
    if (switched) solveForces(ch, theta, eps);

    std::array<Moment, kMaxSections> trial, normal;
    std::array<bool, kMaxSections> active{};
    bool any = false;
    for (int i = 0; i < n; ++i) {
        trial[i] = sectionMomentOf(i);
        const double y = ch.section[i].yieldMoment;
        active[i] = trial[i].squaredNorm() > y * y;
        if (active[i]) normal[i] = trial[i].normalized();
        any = any || active[i];
    }
    if (!any) return w;

    const Flexibility f = ch.flexibility;
    const double g11 = f.cc * f.inverseDet, g12 = -f.mc * f.inverseDet, g22 = f.mm * f.inverseDet;  // the element's stiffness
    // How much a unit flow at section j lowers the moment at section i.
    const auto influence = [&](int i, int j) {
        return r.weight[j] * (g11 + g12 * (r.xi[i] + r.xi[j]) + g22 * r.xi[i] * r.xi[j]);
    };
    std::array<double, kMaxSections> lambda{};
    for (int attempt = 0; attempt < 2 * n; ++attempt) {
        int idx[kMaxSections], a = 0;
        for (int i = 0; i < n; ++i)
            if (active[i]) idx[a++] = i;
        Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSections, kMaxSections> J(a, a);
        using Column = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSections, 1>;
        Column rhs(a);
        for (int p = 0; p < a; ++p) {
            const int i = idx[p];
            rhs[p] = normal[i].dot(trial[i]) - ch.section[i].yieldMoment;
            for (int q = 0; q < a; ++q) {
                const int j = idx[q];
                J(p, q) = influence(i, j) * normal[i].dot(normal[j]) + (i == j ? hardening_[i] : 0);
            }
        }
        const Column solution = J.partialPivLu().solve(rhs);  // evaluated now: the LU is a temporary
        lambda.fill(0);
        int worst = -1;
        for (int p = 0; p < a; ++p) {
            lambda[idx[p]] = solution[p];
            if (solution[p] < 0 && (worst < 0 || solution[p] < lambda[worst])) worst = idx[p];
        }
        if (worst >= 0) {  // a section the others' flow unloads: elastic after all
            active[worst] = false;
            continue;
        }
        int violated = -1;
        for (int i = 0; i < n && violated < 0; ++i) {
            if (active[i]) continue;
            Moment m = trial[i];
            for (int j = 0; j < n; ++j)
                if (active[j]) m -= influence(i, j) * lambda[j] * normal[j];
            if (m.norm() > ch.section[i].yieldMoment * (1 + 1e-12)) {
                violated = i;
                normal[i] = m / m.norm();
            }
        }
        if (violated < 0) break;
        // Loaded past yield by the others' flow: it flows too. Its stiffness drops to K_Unld at the next
        // increment that loads it further (changing it here would move the forces without work).
        active[violated] = true;
    }

    for (int i = 0; i < n; ++i) {
        if (!active[i] || lambda[i] <= 0) continue;
        Section& s = ch.section[i];
        const double h = hardening_[i], rupture = sectionK_[i].ruptureMoment;
        double flow = lambda[i];
        if (s.yieldMoment + h * flow >= rupture) {  // Eq. 6: the section breaks, at once if brittle
            ruptureReached_ = true;
            if (brittle_) {
                flow = h > 0 ? (rupture - s.yieldMoment) / h : flow;
                broken_ = true;
            } else {
                // It flows on at M_Rupt while its owner softens what it transmits: no hardening past
                // rupture, so that the fracture's work is M_Rupt theta_f / 2 whatever the length.
                hardening_[i] = 0;
            }
        }
        // Along the plastic branch the section's moment is its growing yield moment: exact work.
        w.dissipated += r.weight[i] * flow * (s.yieldMoment + 0.5 * h * flow);
        s.plastic += flow * normal[i];
        s.yieldMoment += h * flow;
    }
    solveForces(ch, theta, eps);
    return w;
}

HingeWork ConnectionBeam::deform(const Vec2& theta, const Vec2& stretch) {
    if (broken_) return {};
    const Vec2 eps = (2 / length_) * Vec2(stretch.y(), -stretch.x());
    HingeWork total;
    stored_ = 0;
    const int channels = reading_ == BendingReading::Isotropic ? 1 : 2;
    for (int c = 0; c < channels; ++c) {
        Channel& ch = channels_[c];
        const Moment th = channels == 1 ? theta : Moment(theta[c], 0);
        const Moment ep = channels == 1 ? eps : Moment(eps[c], 0);
        const HingeWork w = deformChannel(ch, th, ep);
        total.dissipated += w.dissipated;
        total.created += w.created;
        stored_ += channelEnergy(ch);
        if (channels == 1) {
            moment_ = ch.mean;
            change_ = ch.change;
        } else {
            moment_[c] = ch.mean[0];
            change_[c] = ch.change[0];
        }
    }
    if (broken_) {
        total.released = stored_;
        stored_ = 0;
        moment_.setZero();
        change_.setZero();
    }
    return total;
}

HingeWork ConnectionBeam::snap() {
    HingeWork w;
    if (broken_) return w;
    w.released = stored_;
    stored_ = 0;
    broken_ = true;
    moment_.setZero();
    change_.setZero();
    return w;
}

int ConnectionBeam::sectionCount() const { return rule_->count; }

Vec2 ConnectionBeam::sectionMoment(int section) const { return moment_ + rule_->xi[section] * change_; }

// Node b's balance: the moment falls from a to b by l e_z x V, so dM = (l / 2) (V_y, -V_x).
Vec2 ConnectionBeam::shearForce() const { return (2 / length_) * Vec2(-change_.y(), change_.x()); }

}  // namespace sylva::dem
