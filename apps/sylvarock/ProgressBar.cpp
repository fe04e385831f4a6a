#include "ProgressBar.hpp"

#include <cstdio>

namespace sylva::cli {

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(int done, int total, const std::string& label) {
    if (!enabled_ || total <= 0) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const int width = 30, filled = width * done / total;
    std::fprintf(stderr, "\r  runs %d/%d [%s%s] %.0f s, about %.0f s left %s   ", done, total,
                 std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), s,
                 done ? s * (total - done) / done : 0.0, label.empty() ? "" : ("(" + label + ")").c_str());
    if (done == total) std::fputc('\n', stderr);
}

}  // namespace sylva::cli
