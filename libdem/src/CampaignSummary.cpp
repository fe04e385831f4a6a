#include "libdem/CampaignSummary.hpp"

#include <gsl/gsl_statistics_double.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "libcommon/InputError.hpp"

namespace sylva::dem {

using Json = nlohmann::ordered_json;  // keys in the order written

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
    if (!out) throw sylva::cannotWrite(path);
    return out;
}
}  // namespace

namespace {
const char* const kRunsHeader =
    "run,seed,release_x,release_y,release_z,stop_x,stop_y,stop_z,runout_m,runout_horizontal_m,energy_line_deg,"
    "stop_reason,max_speed_m_s,mean_speed_m_s,max_bounce_m,duration_s,cpu_s,steps,mean_dt_s,energy_imbalance,tree_impacts,energy_flag";
}  // namespace

bool isRunsCsv(const std::string& path) {
    std::ifstream in(path);
    std::string first;
    return in && std::getline(in, first) && first == kRunsHeader;
}

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs) {
    auto out = openOut(path);
    out << kRunsHeader << "\n";
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
    const ForestLedger& f = r.forestEnergy;
    Json j;
    // A run stopped on a numerical error has no impact to report: said first, so that a sweep does
    // not read its zeros as a block that missed the tree.
    j["run_failed"] = r.reason == StopReason::Failed;
    if (r.reason == StopReason::Failed) j["failure"] = r.failure;
    j["impacts"] = r.impacts.size();
    if (!r.impacts.empty()) {
        const TreeImpact& i = r.impacts.front();
        j["kinetic_before_j"] = i.energyBefore;
        j["kinetic_after_j"] = i.energyAfter;
        j["speed_before_m_s"] = i.speedBefore;
        j["speed_after_m_s"] = i.speedAfter;
        j["impact_time_s"] = i.time;  // since release, at first contact
        j["impact_height_m"] = i.height;
        j["eccentricity"] = i.eccentricity;
        j["stem_broken"] = i.stemBroken;
        j["root_yielded"] = i.rootYielded;
        j["root_failed"] = i.rootFailed;
        j["break_height_m"] = i.breakHeight;  // null: not broken
        j["stem_breaks"] = i.stemBreaks;
        j["stem_height_m"] = i.stemHeight;
        // Each of its connections that broke in the run, in the order they broke: where a whipped stem
        // snapped, how thin it was there, and whether it broke under the block or when its pieces landed.
        Json breaks = Json::array();
        for (const StemBreak& b : r.breaks)
            if (b.tree == i.tree) breaks.push_back({{"time_s", b.time}, {"height_m", b.height}, {"diameter_cm", 100 * b.diameter}});
        j["breaks"] = breaks;
    } else {
        j["stem_broken"] = false;
        j["root_yielded"] = false;
        j["root_failed"] = false;
        j["stem_breaks"] = 0;
        j["breaks"] = Json::array();
    }
    j["dissipated_j"] = {{"bending_plasticity", f.bendingPlasticity}, {"bending_damping", f.bendingDamping},
                         {"axial_damping", f.axialDamping},           {"root_plasticity", f.rootPlasticity},       {"rupture", f.rupture},
                         {"contact_friction", f.contactFriction},     {"soil_damping", r.energy.contactDamping},
                         {"soil_friction", r.energy.friction},        {"stem_soil_damping", f.contactDamping},
                         {"contact_crushing", f.contactCrushing},     {"left_vibrating_in_stems", f.frozen},
                         {"left_moving_in_broken_pieces", f.frozenPieces}};
    // The tree's own terms over the impact only (first contact to the block leaving the tree).
    const StemLedger during = r.impacts.empty() ? StemLedger{} : r.impacts.front().duringImpact;
    j["impact_dissipated_j"] = {{"bending_plasticity", during.bendingPlasticity}, {"bending_damping", during.bendingDamping},
                                {"axial_damping", during.axialDamping},           {"root_plasticity", during.rootPlasticity},       {"rupture", during.rupture}};
    j["created_by_unloading_law_j"] = f.unloadingGain;
    j["energy_imbalance"] = r.energy.imbalance;
    j["energy_flag"] = r.energy.flagged;
    openOut(path) << j.dump(2) << "\n";
}

void writeSummaryJson(const std::string& path, const CampaignSummary& s, double wallSeconds, const std::string& scene,
                      const std::string& model) {
    Json j;
    j["scene"] = scene;
    j["model"] = model;
    j["runs"] = s.runs;
    j["wall_s"] = wallSeconds;
    j["dist50_m"] = s.dist50;
    for (const auto& [p, v] : s.runoutQuantiles) j["runout_quantiles_m"]["p" + std::to_string(p)] = v;
    j["runout_horizontal50_m"] = s.horizontal50;
    j["lateral_sd_m"] = s.lateralSd;
    j["lateral_range90_m"] = s.lateralRange90;
    j["energy_line_deg"] = s.energyLine50;
    j["energy_line_min_deg"] = s.energyLineMin;
    j["energy_line_max_deg"] = s.energyLineMax;
    j["mean_speed50_m_s"] = s.meanSpeed50;
    j["max_speed50_m_s"] = s.maxSpeed50;
    j["max_bounce50_m"] = s.maxBounce50;
    j["share_max_bounce_le_1m"] = s.shareBounceBelow1m;
    j["cpu_per_run50_s"] = s.cpu50;
    j["worst_energy_imbalance"] = s.worstEnergyImbalance;
    j["energy_flagged_runs"] = s.energyFlaggedRuns;
    j["failed_runs"] = s.failedRuns;
    // Where the steps' time went, summed over the runs (bench/bench_forest prints the shares).
    for (std::size_t p = 0; p < kStepPhases; ++p) j["time_by_phase_s"][name(static_cast<StepPhase>(p))] = s.phases.seconds[p];
    j["stop_reasons"] = Json::object();
    for (const auto& [k, v] : s.stopReasons) j["stop_reasons"][k] = v;
    // Where the energy the forest took went, over all runs. What was frozen when stems rested or slept
    // still moving is split: the pieces of broken or uprooted stems, and what standing stems were left
    // swaying with, which must stay small next to the trees' own terms (issue 11, point 3).
    const ForestLedger& f = s.forestEnergy;
    j["forest_energy_j"] = {{"bending_plasticity", f.bendingPlasticity}, {"bending_damping", f.bendingDamping},
                            {"axial_damping", f.axialDamping},           {"root_plasticity", f.rootPlasticity},       {"rupture", f.rupture},
                            {"contact_friction", f.contactFriction},     {"stem_soil_damping", f.contactDamping},
                            {"contact_crushing", f.contactCrushing},     {"left_vibrating_in_stems", f.frozen},
                            {"left_moving_in_broken_pieces", f.frozenPieces}};
    const double terms = f.treeTerms() > 0 ? f.treeTerms() : 1.0;  // no tree touched: every share 0
    j["left_vibrating_share_of_tree_terms"] = f.frozen / terms;
    j["left_in_standing_stems_share_of_tree_terms"] = (f.frozen - f.frozenPieces) / terms;
    openOut(path) << j.dump(2) << "\n";
}

bool removeTrajectories(const std::string& dir) {
    namespace fs = std::filesystem;
    if (!fs::is_directory(dir)) return false;
    const std::regex written(R"(run_\d{4,}\.(csv|vtk))");
    bool removed = false;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), written))
            removed = fs::remove(entry.path()) || removed;
    if (fs::is_empty(dir)) fs::remove(dir);
    return removed;
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
