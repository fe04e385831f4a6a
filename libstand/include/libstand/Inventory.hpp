#pragma once
// A stand's inventory: plots (each with its own window and frame) and the stems measured in them.
#include <optional>
#include <string>
#include <vector>

#include "libcommon/CsvTable.hpp"
#include "libstand/Window.hpp"

namespace sylva::stand {

struct Stem {
    std::string plot;
    std::string id;
    double x = 0, y = 0;   // m, in the plot's frame
    double dbhCm = 0;      // diameter at breast height (1.3 m); 0 below breast height, NaN not measured
    std::string species;   // may be empty
    std::optional<std::string> stool;  // coppice stool id; empty for a single tree
    long line = 0;         // line in the stems file, for messages
};

struct Plot {
    std::string id;
    Window window;
};

struct Inventory {
    std::string name;               // e.g. "GR1", from the file name
    std::vector<Plot> plots;
    std::vector<Stem> stems;
    std::vector<std::string> warnings;  // valid but noteworthy data (stems at identical positions, empty plots)
    bool hasDiameters = true;           // the stems have a DBH column (false: a pattern without dbh_cm)

    double areaHa() const;
};

// A stem whose DBH was measured (> 0): the only ones G and the DBH statistics use. Stems below
// breast height (DBH 0) and unmeasured ones (NA, empty) still count in N, g(r) and Clark-Evans.
inline bool measured(const Stem& s) { return s.dbhCm > 0; }

// The DBH cell of a stems file: a diameter in (0, 200] cm; "NA", "nan" or empty: not measured (NaN);
// 0: a stem below breast height. Throws InputError (file, line) for anything else.
double readDbhCell(const CsvTable& table, std::size_t row, std::size_t column);

// The stool cell of a stems, forest or point file: the stool's id, or none for a single tree: an empty
// cell, or "NA", "nan" as R and pandas write a missing value (read as an id, every single tree of a plot
// was one stool named "NA").
std::optional<std::string> readStoolCell(const CsvTable& table, std::size_t row, std::size_t column);

// For readers of one frame of x, y (a forest, a point pattern): an inventory's stems file, whose column
// `plot` names several plots each in its own frame, would stack its plots on one another. Throws
// InputError at the first stem of a plot whose stems' bounding box overlaps an earlier plot's, saying
// to give it with its plots file (`instead`); plots side by side in one frame (a georeferenced tree
// map with a plot attribute) pass.
void requireOnePlot(const CsvTable& table, std::size_t xColumn, std::size_t yColumn, const std::string& instead);

// Reads `plot,stem,x,y,dbh_cm,species,stool` stems and a plots file with either
// `plot,xmin,ymin,xmax,ymax` or `plot,wkt` (a WKT POLYGON per plot). Throws InputError naming the
// file, the line and the problem for: a missing column, a non-numeric or negative diameter, a
// stem outside its plot, duplicate stem ids, a stem whose plot has no window, a degenerate window.
Inventory readInventory(const std::string& stemsCsv, const std::string& plotsCsv);

// Valid but noteworthy data, one message each: stems at identical positions (their nearest-neighbour
// distance is 0, as in spatstat), plots without any stem, and stems without a measured DBH (counted). readInventory fills Inventory::warnings with it.
std::vector<std::string> dataWarnings(const Inventory& inv, const std::string& stemsSource,
                                      const std::string& plotsSource);

}  // namespace sylva::stand
