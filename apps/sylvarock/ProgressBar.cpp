#include "ProgressBar.hpp"

#include <cstdio>

namespace sylva::cli {

namespace {
// A campaign done within this long needs no progress in its log.
constexpr double kQuietSeconds = 5;
}  // namespace

ProgressBar::ProgressBar(bool terminal) : terminal_(terminal), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int total, const std::string& label) {
    if (total <= 0) return;
    // A count that goes back is a new pass (hazard's bare pass after its forest one): its own tenths
    // and clock. Labels may change at every run (assess names the campaign each run belongs to).
    if (done < lastDone_) lastTenth_ = 0, start_ = std::chrono::steady_clock::now();
    lastDone_ = done;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = done ? s * (total - done) / done : 0.0;
    const std::string named = label.empty() ? "" : " (" + label + ")";
    if (!terminal_) {
        const int tenth = static_cast<int>(10L * done / total);
        if (tenth == lastTenth_) return;
        lastTenth_ = tenth;
        if (s < kQuietSeconds) return;
        std::fprintf(stderr, "  runs %d/%d (%d %%), %.0f s, about %.0f s left%s\n", done, total, 10 * tenth, s, left, named.c_str());
        std::fflush(stderr);
        return;
    }
    const int width = 30, filled = static_cast<int>(static_cast<long>(width) * done / total);
    std::fprintf(stderr, "\r  runs %d/%d [%s%s] %.0f s, about %.0f s left%s   ", done, total, std::string(filled, '#').c_str(),
                 std::string(width - filled, '.').c_str(), s, left, named.c_str());
    if (done == total) std::fputc('\n', stderr);
}

}  // namespace sylva::cli
