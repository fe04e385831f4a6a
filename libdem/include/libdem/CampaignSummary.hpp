#pragma once
// What a campaign of runs says: Dist50 and the run-out distribution, lateral dispersion, energy
// line, speeds and bounces (the figures of the paper's Sect. 3.2), and the files that hold them.
#include <map>
#include <string>
#include <vector>

#include "libdem/BlockRun.hpp"

namespace sylva::dem {

struct CampaignSummary {
    int runs = 0;
    double dist50 = 0;                       // median run-out along the slope, m (Eq. 26's Dist50)
    std::map<int, double> runoutQuantiles;   // percent -> m
    double horizontal50 = 0;
    double lateralSd = 0, lateralRange90 = 0;  // stop y: standard deviation, 5-95 % range, m
    double energyLine50 = 0, energyLineMin = 0, energyLineMax = 0;  // deg
    double meanSpeed50 = 0, maxSpeed50 = 0;  // medians over runs, m/s
    double maxBounce50 = 0, shareBounceBelow1m = 0;
    double cpu50 = 0;
    PhaseTimes phases;  // summed over the runs
    double worstEnergyImbalance = 0;
    int energyFlaggedRuns = 0;  // runs whose budget did not close to integration.energy_warning
    int failedRuns = 0;         // stopped on a SimulationError: counted here, left out of every statistic above
    std::map<std::string, int> stopReasons;
    ForestLedger forestEnergy;  // summed over the runs that did not fail, J
};

CampaignSummary summarise(const std::vector<RunResult>& runs);
// Linear-interpolated quantile (GSL's definition) of unsorted values; p in [0, 1].
double quantile(std::vector<double> values, double p);

void writeRunsCsv(const std::string& path, const std::vector<RunResult>& runs);
// Whether the file at path is one writeRunsCsv wrote (its header line): how an earlier simulate run's
// folder is told from a folder of someone else's files.
bool isRunsCsv(const std::string& path);
// The energy budget of a single-tree launch (a tree-mechanics check): the block's kinetic energy
// before and after the impact, each dissipation term, whether the stem broke or the root yielded.
void writeImpactEnergyJson(const std::string& path, const RunResult& run);
// One row per block/tree impact of every run.
void writeImpactsCsv(const std::string& path, const std::vector<RunResult>& runs);
// `model`: "dem" or "lumped", which wrote the runs (calibrate-lumped reads it: it fits on the DEM's).
void writeSummaryJson(const std::string& path, const CampaignSummary& s, double wallSeconds, const std::string& scene,
                      const std::string& model);
// One CSV per run (t,x,y,z,vx,vy,vz,wx,wy,wz,ek_translation_j,ek_rotation_j) and one legacy VTK
// polyline per run (ParaView), in dir, named run_NNNN.csv and run_NNNN.vtk.
void writeTrajectories(const std::string& dir, const std::vector<RunResult>& runs);
// Removes what writeTrajectories wrote in dir, and dir if nothing else is left in it; true if it removed any.
bool removeTrajectories(const std::string& dir);

}  // namespace sylva::dem
