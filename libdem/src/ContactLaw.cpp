#include "libdem/ContactLaw.hpp"

#include <cmath>

namespace sylva::dem {

Vec3 updateShearForce(const ContactGeometry& g, ContactHistory& h, double kt, double normalForce, double tanPhi,
                      double dt, DissipationLedger& ledger) {
    const Vec3& n = g.normal;
    if (h.normal.squaredNorm() > 0) {
        // The contact plane moved: turn the stored force with it so the spring keeps its meaning
        // while the block rotates (minimal rotation n_prev -> n, then twist about n).
        h.shearForce = Quat::FromTwoVectors(h.normal, n) * h.shearForce;
        h.shearForce = Eigen::AngleAxisd(g.meanSpinNormal * dt, n) * h.shearForce;
    }
    h.shearForce -= n * n.dot(h.shearForce);  // exactly tangential
    h.normal = n;

    const Vec3 vt = g.relativeVelocity - n * n.dot(g.relativeVelocity);
    const Vec3 trial = h.shearForce - kt * vt * dt;  // Eq. 17: dF_t = K_t dU_t while below the limit
    const double limit = std::max(0.0, normalForce) * tanPhi;  // Eq. 18
    const double t = trial.norm();
    if (t > limit) {
        const Vec3 before = h.shearForce;
        h.shearForce = t > 0 ? Vec3(trial * (limit / t)) : Vec3::Zero();
        // Work of the slip that the return onto the Coulomb cone represents, with the force taken
        // as the mean over the step (trapezoid), as the leapfrog applies it: this closes the budget
        // to second order in dt.
        ledger.friction += 0.5 * (before + h.shearForce).dot(trial - h.shearForce) / kt;
    } else {
        h.shearForce = trial;
    }
    return h.shearForce;
}

void ContactLaw::end(const ContactGeometry& last, const Vec3& relativeVelocity, const ContactHistory& h, double dt,
                     DissipationLedger& ledger) const {
    ledger.contactDamping -= 0.5 * h.dampingForce.dot(relativeVelocity) * dt;
    const Vec3& n = last.normal;
    const Vec3 vt = relativeVelocity - n * n.dot(relativeVelocity);
    ContactGeometry open = last;
    open.overlap = 0;  // what the law stores then is its shear spring's energy alone
    ledger.friction += storedEnergy(open, h) - 0.5 * h.shearForce.dot(vt) * dt;
}

}  // namespace sylva::dem
