// An inventory's stems file (plot, stem, x, y, dbh_cm, species, stool) against two valid plots.
#include "FuzzFile.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    const std::string plots = fuzz::file("plots.csv", "plot,xmin,ymin,xmax,ymax\n1,0,0,20,20\n2,0,0,10,10\n");
    try {
        stand::readInventory(fuzz::file("stems.csv", fuzz::text(data, size)), plots);
    } catch (const InputError&) {
    }
    return 0;
}
