// A point pattern (x, y[, dbh_cm][, stool]) in a rectangle, as `stats --points` reads it.
#include "FuzzFile.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/PointPattern.hpp"
#include "libstand/Window.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    static const stand::Window window = stand::Window::rectangle(0, 0, 100, 50);
    try {
        stand::readPointPattern(fuzz::file("points.csv", fuzz::text(data, size)), window);
    } catch (const InputError&) {
    }
    return 0;
}
