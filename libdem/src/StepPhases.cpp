#include "libdem/StepPhases.hpp"

namespace sylva::dem {

const char* name(StepPhase phase) {
    switch (phase) {
        case StepPhase::BlockSoil: return "block_soil_contacts";
        case StepPhase::Wake: return "wake";
        case StepPhase::BlockStem: return "block_stem_contacts";
        case StepPhase::StemStem: return "stem_stem_contacts";
        case StepPhase::StemSoil: return "stem_soil_contacts";
        case StepPhase::StableStep: return "stable_step";
        case StepPhase::ContactForces: return "contact_forces";
        case StepPhase::Stems: return "stems";
        case StepPhase::Audit: return "audit";
        case StepPhase::Block: return "block";
        case StepPhase::Sleep: return "sleep";
    }
    return "?";
}

double PhaseTimes::total() const {
    double t = 0;
    for (const double s : seconds) t += s;
    return t;
}

PhaseTimes& PhaseTimes::operator+=(const PhaseTimes& other) {
    for (std::size_t i = 0; i < kStepPhases; ++i) seconds[i] += other.seconds[i];
    return *this;
}

const char* name(StemAwake reason) {
    switch (reason) {
        case StemAwake::Touched: return "touched by the block";
        case StemAwake::Waiting: return "waiting (forest.sleep_after_s)";
        case StemAwake::BlockNear: return "block within reach";
        case StemAwake::PiecesFalling: return "pieces falling";
        case StemAwake::Leaning: return "touching a stem held awake";
        case StemAwake::NeighbourNear: return "a moving neighbour within reach";
    }
    return "?";
}

std::uint64_t NodeSteps::total() const {
    std::uint64_t n = 0;
    for (const std::uint64_t k : byReason) n += k;
    return n;
}

NodeSteps& NodeSteps::operator+=(const NodeSteps& other) {
    for (std::size_t i = 0; i < kStemAwakeReasons; ++i) byReason[i] += other.byReason[i];
    broken += other.broken;
    onSoilOrStem += other.onSoilOrStem;
    return *this;
}

}  // namespace sylva::dem
