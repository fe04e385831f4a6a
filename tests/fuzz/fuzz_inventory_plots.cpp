// An inventory's plots file (rectangles or WKT polygons, with holes) against valid stems.
#include "FuzzFile.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Inventory.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    const std::string stems = fuzz::file("stems.csv", "plot,stem,x,y,dbh_cm,species,stool\n1,1,2,3,12.5,beech,7\n"
                                                      "1,2,2.5,3.5,10,beech,7\n2,3,5,5,20,ash,\n");
    try {
        stand::readInventory(stems, fuzz::file("plots.csv", fuzz::text(data, size)));
    } catch (const InputError&) {
    }
    return 0;
}
