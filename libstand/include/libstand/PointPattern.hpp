#pragma once
// A mapped point pattern in one observation window: a virtual forest written by `sylvarock generate`,
// or any `x,y[,dbh_cm][,stool]` file. It is read as an inventory with a single plot, so that the same
// statistics apply to inventories and patterns.
#include <string>

#include "libstand/Inventory.hpp"
#include "libstand/Window.hpp"

namespace sylva::stand {

// Columns x and y are required; dbh_cm (cm, > 0), stool and stem (ids) are used when present.
// Without dbh_cm, Inventory::hasDiameters is false. Throws InputError naming the file and line for a
// missing column, a bad number, a non-positive diameter, a duplicate stem id or a point outside the
// window. The plot is named "1" and the inventory after the file.
Inventory readPointPattern(const std::string& csv, const Window& window);

}  // namespace sylva::stand
