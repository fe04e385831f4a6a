// A WKT window (POLYGON with optional holes), then the geometry every statistic asks of it.
#include "FuzzFile.hpp"
#include "libstand/EdgeCorrection.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Window.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    try {
        const stand::Window w = stand::Window::fromWkt(fuzz::text(data, size));
        w.requirePlotSize();
        const Eigen::Vector2d centre = 0.5 * (w.lower() + w.upper());
        w.contains(centre);
        w.distanceToBoundary(centre);
        stand::circleFractionInside(w, centre, 0.1 * (w.upper() - w.lower()).norm());
        stand::TranslationCorrection(w).setCovariance(0.1 * (w.upper() - w.lower()));
    } catch (const InputError&) {
    }
    return 0;
}
