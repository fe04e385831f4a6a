#pragma once
// Confidence interval of a protection index PF50 (Eq. 26) by a two-stage bootstrap, so that it carries
// both sources of uncertainty of the paper's design (Sect. 4.2): which virtual forest was generated,
// and which blocks were thrown down it. Each replicate:
//   1. draws K realisations with replacement among the K generated forests;
//   2. within each drawn realisation, draws its M run-outs with replacement;
//   3. draws the B baseline run-outs with replacement;
//   4. computes PF50* = 1 - median(pooled forest run-outs*) / median(baseline*).
// The interval is the percentile interval of the PF50* (quantiles (1 - c)/2 and (1 + c)/2, GSL's
// quantile definition). With K = 1 it is the ordinary bootstrap of the runs (the spread between
// forests cannot be seen from one forest). With K > 1 the resampling of runs inside resampled
// realisations counts the run-to-run spread about twice ((2K - 1)/K times) while the realisations'
// own spread is counted (K - 1)/K times: conservative when blocks dominate the uncertainty, a little
// narrow when forests do and K is small (Davison and Hinkley 1997, Sect. 3.8). docs: docs/assessment.md.
#include <cstdint>
#include <string>
#include <vector>

namespace sylva::assess {

struct BootstrapSettings {
    int replicates = 2000;
    double confidence = 0.95;
    std::uint64_t seed = 1;  // seeds GSL's mt19937: the same seed and data give the same interval
};

// The confidence as a percentage for people: 95, 97.5, 99.5 (to 0.01 %; never rounded up to 100).
std::string confidencePercent(double confidence);

struct Interval {
    double low = 0, high = 0;
};

// `realisations`: the run-outs of each forest realisation (none empty); `baseline`: the run-outs
// without forest. Throws std::invalid_argument on empty samples or settings out of range.
Interval bootstrapProtectionIndex(const std::vector<std::vector<double>>& realisations, const std::vector<double>& baseline,
                                  const BootstrapSettings& settings);

}  // namespace sylva::assess
