#pragma once
// `sylvarock assess` as a library call: checks the inputs, opens (or resumes) the campaign in the
// output directory, runs what is missing and analyses the stored runs. Writing the report is
// Report.hpp's job.
#include <functional>
#include <string>

#include "libassess/ProtectionAnalysis.hpp"

namespace sylva::assess {

struct AssessmentOptions {
    AssessmentDesign design;
    std::string outDir;
    bool resume = false;
    int threads = 0;  // 0: all cores; results do not depend on it
    int bootstrapReplicates = 2000;
    double confidence = 0.95;
    std::function<void(const std::string&)> onNote;  // warnings and what is being done, one line each
    std::function<void(const std::string& campaign, int done, int total)> onRunDone;
    // Writes what the results give (results.json, the report) while the campaign's folder is still
    // locked: another process resuming it waits for none of it and must not interleave its own.
    std::function<void(const std::vector<AssessmentResults>&)> writeOutputs;
};

// One result per model of the design, in its order. InputError for unusable inputs (stands, scene,
// options, output directory, mismatched design on resume) before any run starts. Under mpirun this
// is rank 0's part (it alone writes the output directory and analyses); the other ranks call
// serveAssessment with the same options.
std::vector<AssessmentResults> runAssessment(const AssessmentOptions& options);
// An MPI rank other than 0: reads the same inputs and runs the jobs rank 0 hands out. Throws
// PeerFailed (MpiWorld.hpp) if rank 0 could not start the campaign.
void serveAssessment(const AssessmentOptions& options);

}  // namespace sylva::assess
