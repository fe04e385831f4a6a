#include "RunResultMessage.hpp"

#include <cstdint>
#include <type_traits>

namespace sylva::assess {

namespace {

// A field added to RunResult must travel too. This is RunResult's size (x86-64) with the fields
// below; it changes with the struct, and then this file must be looked at.
static_assert(sizeof(dem::RunResult) == 560, "dem::RunResult changed: send its new fields in RunResultMessage.cpp");
static_assert(std::is_trivially_copyable_v<dem::TreeImpact> && std::is_trivially_copyable_v<dem::StemBreak> && std::is_trivially_copyable_v<dem::EnergyBudget> &&
              std::is_trivially_copyable_v<dem::PhaseTimes> && std::is_trivially_copyable_v<dem::NodeSteps> &&
              std::is_trivially_copyable_v<dem::ForestLedger>);

void putVec(ByteWriter& w, const dem::Vec3& v) { w.put(v.x()).put(v.y()).put(v.z()); }

dem::Vec3 getVec(ByteReader& r) {
    const double x = r.get<double>(), y = r.get<double>(), z = r.get<double>();
    return {x, y, z};
}

}  // namespace

void put(ByteWriter& w, const dem::RunResult& r) {
    w.put(r.run).put(r.seed);
    putVec(w, r.release);
    putVec(w, r.stop);
    w.put(r.runoutAlongSlope).put(r.runoutHorizontal).put(r.energyLineDeg).put(r.reason);
    w.put(r.maxSpeed).put(r.meanSpeed).put(r.maxBounce).put(r.duration).put(r.cpuSeconds).put(r.steps).put(r.meanDt);
    w.put(r.phases).put(r.nodeSteps).put(r.energy).put(r.forestEnergy);
    w.put(static_cast<std::uint64_t>(r.impacts.size()));
    for (const auto& impact : r.impacts) w.put(impact);
    w.put(static_cast<std::uint64_t>(r.breaks.size()));
    for (const auto& b : r.breaks) w.put(b);
    w.put(static_cast<std::uint64_t>(r.trajectory.size()));
    for (const auto& s : r.trajectory) {
        w.put(s.t);
        putVec(w, s.position);
        putVec(w, s.velocity);
        putVec(w, s.angularVelocity);
        w.put(s.translationalEnergy).put(s.rotationalEnergy);
    }
    w.put(r.failure);
}

dem::RunResult getRunResult(ByteReader& in) {
    dem::RunResult r;
    r.run = in.get<int>();
    r.seed = in.get<std::uint64_t>();
    r.release = getVec(in);
    r.stop = getVec(in);
    r.runoutAlongSlope = in.get<double>();
    r.runoutHorizontal = in.get<double>();
    r.energyLineDeg = in.get<double>();
    r.reason = in.get<dem::StopReason>();
    r.maxSpeed = in.get<double>();
    r.meanSpeed = in.get<double>();
    r.maxBounce = in.get<double>();
    r.duration = in.get<double>();
    r.cpuSeconds = in.get<double>();
    r.steps = in.get<long>();
    r.meanDt = in.get<double>();
    r.phases = in.get<dem::PhaseTimes>();
    r.nodeSteps = in.get<dem::NodeSteps>();
    r.energy = in.get<dem::EnergyBudget>();
    r.forestEnergy = in.get<dem::ForestLedger>();
    r.impacts.resize(in.count(sizeof(dem::TreeImpact)));
    for (auto& impact : r.impacts) impact = in.get<dem::TreeImpact>();
    r.breaks.resize(in.count(sizeof(dem::StemBreak)));
    for (auto& b : r.breaks) b = in.get<dem::StemBreak>();
    r.trajectory.resize(in.count(12 * sizeof(double)));
    for (auto& s : r.trajectory) {
        s.t = in.get<double>();
        s.position = getVec(in);
        s.velocity = getVec(in);
        s.angularVelocity = getVec(in);
        s.translationalEnergy = in.get<double>();
        s.rotationalEnergy = in.get<double>();
    }
    r.failure = in.getString();
    return r;
}

}  // namespace sylva::assess
