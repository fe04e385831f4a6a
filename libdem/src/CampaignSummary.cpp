#include "libdem/CampaignSummary.hpp"

#include <gsl/gsl_statistics_double.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "libstand/InputError.hpp"
#include "libstand/JsonWriter.hpp"

namespace sylva::dem {

double quantile(std::vector<double> v, double p) {
    if (v.empty()) return std::nan("");
    std::sort(v.begin(), v.end());
    return gsl_stats_quantile_from_sorted_data(v.data(), 1, v.size(), p);
}

CampaignSummary summarise(const std::vector<RunResult>& runs) {
    CampaignSummary s;
    s.runs = static_cast<int>(runs.size());
    if (runs.empty()) return s;
    std::vector<double> runout, horiz, y, el, vmean, vmax, bounce, cpu;
    int low = 0;
    for (const auto& r : runs) {
        ++s.stopReasons[toString(r.reason)];
        if (r.reason == StopReason::Failed) {
            ++s.failedRuns;
            continue;
        }
        runout.push_back(r.runoutAlongSlope);
        horiz.push_back(r.runoutHorizontal);
        y.push_back(r.stop.y());
        el.push_back(r.energyLineDeg);
        vmean.push_back(r.meanSpeed);
        vmax.push_back(r.maxSpeed);
        bounce.push_back(r.maxBounce);
        cpu.push_back(r.cpuSeconds);
        s.phases += r.phases;
        low += r.maxBounce <= 1.0;
        s.worstEnergyImbalance = std::max(s.worstEnergyImbalance, r.energy.imbalance);
        s.energyFlaggedRuns += r.energy.flagged;
        s.forestEnergy.add(r.forestEnergy);
    }
    if (runout.empty()) return s;
    s.dist50 = quantile(runout, 0.5);
    for (int p : {5, 10, 25, 50, 75, 90, 95}) s.runoutQuantiles[p] = quantile(runout, p / 100.0);
    s.horizontal50 = quantile(horiz, 0.5);
    s.lateralSd = y.size() > 1 ? gsl_stats_sd(y.data(), 1, y.size()) : 0;
    s.lateralRange90 = quantile(y, 0.95) - quantile(y, 0.05);
    s.energyLine50 = quantile(el, 0.5);
    s.energyLineMin = *std::min_element(el.begin(), el.end());
    s.energyLineMax = *std::max_element(el.begin(), el.end());
    s.meanSpeed50 = quantile(vmean, 0.5);
    s.maxSpeed50 = quantile(vmax, 0.5);
    s.maxBounce50 = quantile(bounce, 0.5);
    s.shareBounceBelow1m = static_cast<double>(low) / runout.size();
    s.cpu50 = quantile(cpu, 0.5);
    return s;
}

namespace {
std::ofstream openOut(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw InputError(path, 0, "cannot write file");
    return out;
}
}  // namespace

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs) {
    auto out = openOut(path);
    out << "run,seed,release_x,release_y,release_z,stop_x,stop_y,stop_z,runout_m,runout_horizontal_m,energy_line_deg,"
           "stop_reason,max_speed_m_s,mean_speed_m_s,max_bounce_m,duration_s,cpu_s,steps,mean_dt_s,energy_imbalance,tree_impacts,energy_flag\n";
    char buf[512];
    for (const auto& r : runs) {
        std::snprintf(buf, sizeof buf,
                      "%d,%llu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%s,%.4f,%.4f,%.4f,%.4f,%.6f,%ld,%.3e,%.3e,%zu,%d\n",
                      r.run, static_cast<unsigned long long>(r.seed), r.release.x(), r.release.y(), r.release.z(),
                      r.stop.x(), r.stop.y(), r.stop.z(), r.runoutAlongSlope, r.runoutHorizontal, r.energyLineDeg,
                      toString(r.reason).c_str(), r.maxSpeed, r.meanSpeed, r.maxBounce, r.duration, r.cpuSeconds,
                      r.steps, r.meanDt, r.energy.imbalance, r.impacts.size(), r.energy.flagged ? 1 : 0);
        out << buf;
    }
}

void writeImpactsCsv(const std::string& path, const std::vector<RunResult>& runs) {
    auto out = openOut(path);
    out << "run,tree,time_s,speed_before_m_s,speed_after_m_s,energy_before_j,energy_after_j,impact_height_m,"
           "eccentricity,stem_broken,root_yielded,root_failed,break_height_m,stem_height_m\n";
    char buf[256];
    for (const auto& r : runs)
        for (const auto& i : r.impacts) {
            std::snprintf(buf, sizeof buf, "%d,%ld,%.4f,%.4f,%.4f,%.1f,%.1f,%.3f,%.3f,%d,%d,%d,", r.run, i.tree, i.time,
                          i.speedBefore, i.speedAfter, i.energyBefore, i.energyAfter, i.height, i.eccentricity,
                          i.stemBroken ? 1 : 0, i.rootYielded ? 1 : 0, i.rootFailed ? 1 : 0);
            out << buf;
            if (std::isfinite(i.breakHeight)) {  // empty when the stem did not break
                std::snprintf(buf, sizeof buf, "%.2f", i.breakHeight);
                out << buf;
            }
            std::snprintf(buf, sizeof buf, ",%.2f\n", i.stemHeight);
            out << buf;
        }
}

void writeImpactEnergyJson(const std::string& path, const RunResult& r) {
    auto out = openOut(path);
    JsonWriter j(out);
    const ForestLedger& f = r.forestEnergy;
    j.beginObject();
    j.field("impacts", static_cast<int>(r.impacts.size()));
    if (!r.impacts.empty()) {
        const TreeImpact& i = r.impacts.front();
        j.field("kinetic_before_j", i.energyBefore).field("kinetic_after_j", i.energyAfter);
        j.field("speed_before_m_s", i.speedBefore).field("speed_after_m_s", i.speedAfter);
        j.field("impact_height_m", i.height).field("eccentricity", i.eccentricity);
        j.field("stem_broken", i.stemBroken).field("root_yielded", i.rootYielded).field("root_failed", i.rootFailed);
        j.field("break_height_m", i.breakHeight).field("stem_height_m", i.stemHeight);  // null: not broken
    } else {
        j.field("stem_broken", false).field("root_yielded", false).field("root_failed", false);
    }
    j.key("dissipated_j").beginObject();
    j.field("bending_plasticity", f.bendingPlasticity).field("bending_damping", f.bendingDamping);
    j.field("root_plasticity", f.rootPlasticity).field("rupture", f.rupture);
    j.field("contact_friction", f.contactFriction).field("soil_damping", r.energy.contactDamping);
    j.field("soil_friction", r.energy.friction).field("stem_soil_damping", f.contactDamping);
    j.field("contact_crushing", f.contactCrushing);
    j.field("left_vibrating_in_stems", f.frozen);
    j.endObject();
    // The tree's own terms over the impact only (first contact to the block leaving the tree).
    const StemLedger during = r.impacts.empty() ? StemLedger{} : r.impacts.front().duringImpact;
    j.key("impact_dissipated_j").beginObject();
    j.field("bending_plasticity", during.bendingPlasticity).field("bending_damping", during.bendingDamping);
    j.field("root_plasticity", during.rootPlasticity).field("rupture", during.rupture);
    j.endObject();
    j.field("created_by_unloading_law_j", f.unloadingGain);
    j.field("energy_imbalance", r.energy.imbalance).field("energy_flag", r.energy.flagged);
    j.endObject();
    out << "\n";
}

void writeSummaryJson(const std::string& path, const CampaignSummary& s, double wallSeconds, const std::string& scene) {
    auto out = openOut(path);
    JsonWriter j(out);
    j.beginObject();
    j.field("scene", scene).field("runs", s.runs).field("wall_s", wallSeconds);
    j.field("dist50_m", s.dist50);
    j.key("runout_quantiles_m").beginObject();
    for (const auto& [p, v] : s.runoutQuantiles) j.field("p" + std::to_string(p), v);
    j.endObject();
    j.field("runout_horizontal50_m", s.horizontal50);
    j.field("lateral_sd_m", s.lateralSd).field("lateral_range90_m", s.lateralRange90);
    j.field("energy_line_deg", s.energyLine50).field("energy_line_min_deg", s.energyLineMin).field("energy_line_max_deg", s.energyLineMax);
    j.field("mean_speed50_m_s", s.meanSpeed50).field("max_speed50_m_s", s.maxSpeed50);
    j.field("max_bounce50_m", s.maxBounce50).field("share_max_bounce_le_1m", s.shareBounceBelow1m);
    j.field("cpu_per_run50_s", s.cpu50).field("worst_energy_imbalance", s.worstEnergyImbalance);
    j.field("energy_flagged_runs", s.energyFlaggedRuns);
    j.field("failed_runs", s.failedRuns);
    // Where the steps' time went, summed over the runs (bench/bench_forest prints the shares).
    j.key("time_by_phase_s").beginObject();
    for (std::size_t p = 0; p < kStepPhases; ++p) j.field(name(static_cast<StepPhase>(p)), s.phases.seconds[p]);
    j.endObject();
    j.key("stop_reasons").beginObject();
    for (const auto& [k, v] : s.stopReasons) j.field(k, v);
    j.endObject();
    // Where the energy the forest took went, over all runs; what was frozen when stems were put to
    // sleep still vibrating must stay small next to the trees' own terms (issue 11, point 3).
    const ForestLedger& f = s.forestEnergy;
    j.key("forest_energy_j").beginObject();
    j.field("bending_plasticity", f.bendingPlasticity).field("bending_damping", f.bendingDamping);
    j.field("root_plasticity", f.rootPlasticity).field("rupture", f.rupture);
    j.field("contact_friction", f.contactFriction).field("stem_soil_damping", f.contactDamping);
    j.field("contact_crushing", f.contactCrushing).field("left_vibrating_in_stems", f.frozen);
    j.endObject();
    j.field("left_vibrating_share_of_tree_terms", f.treeTerms() > 0 ? f.frozen / f.treeTerms() : 0.0);
    j.endObject();
    out << "\n";
}

void writeTrajectories(const std::string& dir, const std::vector<RunResult>& runs) {
    std::filesystem::create_directories(dir);
    char name[64], buf[512];
    for (const auto& r : runs) {
        std::snprintf(name, sizeof name, "/run_%04d", r.run);
        auto csv = openOut(dir + name + ".csv");
        csv << "t,x,y,z,vx,vy,vz,wx,wy,wz,ek_translation_j,ek_rotation_j\n";
        for (const auto& s : r.trajectory) {
            std::snprintf(buf, sizeof buf, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.2f,%.2f\n", s.t,
                          s.position.x(), s.position.y(), s.position.z(), s.velocity.x(), s.velocity.y(),
                          s.velocity.z(), s.angularVelocity.x(), s.angularVelocity.y(), s.angularVelocity.z(),
                          s.translationalEnergy, s.rotationalEnergy);
            csv << buf;
        }
        auto vtk = openOut(dir + name + ".vtk");
        const std::size_t n = r.trajectory.size();
        vtk << "# vtk DataFile Version 3.0\nsylvarock trajectory run " << r.run << "\nASCII\nDATASET POLYDATA\nPOINTS " << n
            << " double\n";
        for (const auto& s : r.trajectory) vtk << s.position.x() << ' ' << s.position.y() << ' ' << s.position.z() << '\n';
        vtk << "LINES 1 " << n + 1 << '\n' << n;
        for (std::size_t i = 0; i < n; ++i) vtk << ' ' << i;
        vtk << "\nPOINT_DATA " << n << "\nSCALARS speed_m_s double 1\nLOOKUP_TABLE default\n";
        for (const auto& s : r.trajectory) vtk << s.velocity.norm() << '\n';
        vtk << "SCALARS time_s double 1\nLOOKUP_TABLE default\n";
        for (const auto& s : r.trajectory) vtk << s.t << '\n';
    }
}

}  // namespace sylva::dem
