#pragma once
// Where a simulation step's time goes, phase by phase, the way Box2D v3 times each stage of
// b2World_Step: a forested run's cost is read off its phases (summary.json "time_by_phase_s",
// bench/bench_forest) instead of guessed. Wall time of the running thread, from a steady clock read
// at each phase's end: 11 reads a step, which perf put at 3.4 % of a forested run when every step was
// timed. One step in kTimedStepEvery is timed, and counts for that many: a systematic sample of
// tens of thousands of steps a run (docs/performance.md, "The phase clock sampled").
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>

namespace sylva::dem {

enum class StepPhase {
    BlockSoil,      // block/soil contacts found
    Wake,           // stems woken ahead of the block and of moving stems (the forest's broad phase)
    BlockStem,      // block/stem contacts found and impacts recorded
    StemStem,       // stem/stem contacts found (pair list refreshed when stale)
    StemSoil,       // stem/soil contacts found
    StableStep,     // the step chosen from the springs acting
    ContactForces,  // forces of every contact on the block and the stems
    Stems,          // each moving stem: its connections' forces and its nodes integrated
    Audit,          // the energy budget checked
    Block,          // the block integrated
    Sleep,          // stems put to sleep, NaN and fall-through checks
};
constexpr std::size_t kStepPhases = static_cast<std::size_t>(StepPhase::Sleep) + 1;  // Sleep stays last
const char* name(StepPhase phase);  // snake_case, as written in summary.json

struct PhaseTimes {
    std::array<double, kStepPhases> seconds{};
    double& operator[](StepPhase p) { return seconds[static_cast<std::size_t>(p)]; }
    double operator[](StepPhase p) const { return seconds[static_cast<std::size_t>(p)]; }
    double total() const;
    PhaseTimes& operator+=(const PhaseTimes& other);
};

// Why an awake stem is stepped: the block touches it, or, once the block has left it and while the
// block can still reach it (or it has not come to rest: StemActivity::mayRest), what keeps it from
// sleeping (StemActivity::holds; Leaning is ForestMotion's: a stem it touches, directly or through
// others, is held). The all-awake reference, whose stems never sleep, counts them as Waiting.
enum class StemAwake { Touched, Waiting, BlockNear, PiecesFalling, Leaning, NeighbourNear };
inline constexpr std::size_t kStemAwakeReasons = static_cast<std::size_t>(StemAwake::NeighbourNear) + 1;  // the last one
const char* name(StemAwake reason);

// The stems' node-steps, the unit of a forested run's work (bench/bench_stem_step times one), by
// what kept the stem awake; and, across those reasons, how many were steps of broken stems (a
// connection broken or the root plate gone) and of stems on the soil or against a neighbour.
struct NodeSteps {
    std::array<std::uint64_t, kStemAwakeReasons> byReason{};
    std::uint64_t broken = 0, onSoilOrStem = 0;
    std::uint64_t& operator[](StemAwake r) { return byReason[static_cast<std::size_t>(r)]; }
    std::uint64_t operator[](StemAwake r) const { return byReason[static_cast<std::size_t>(r)]; }
    std::uint64_t total() const;
    NodeSteps& operator+=(const NodeSteps& other);
};

inline constexpr long kTimedStepEvery = 8;

// Laps a steady clock over a step: each lap books the time since the previous one, times
// kTimedStepEvery, to the phase that just ended. Step number `step` is timed only if it is a multiple
// of kTimedStepEvery; on the other steps lap() does nothing.
class PhaseClock {
public:
    PhaseClock(PhaseTimes& times, long step) : times_(times), timed_(step % kTimedStepEvery == 0) {
        if (timed_) last_ = std::chrono::steady_clock::now();
    }
    void lap(StepPhase ended) {
        if (!timed_) return;
        const auto now = std::chrono::steady_clock::now();
        times_[ended] += kTimedStepEvery * std::chrono::duration<double>(now - last_).count();
        last_ = now;
    }

private:
    PhaseTimes& times_;
    bool timed_;
    std::chrono::steady_clock::time_point last_;
};

}  // namespace sylva::dem
