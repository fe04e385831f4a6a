#pragma once
// Loading the spatstat reference stands of tests/data/spatstat (see its README.md) for the tests.
#include <fstream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "libcommon/CsvTable.hpp"
#include "libstand/Window.hpp"

namespace sylva::stand::testdata {

inline std::string spatstatDir() { return std::string(SYLVAROCK_TEST_DATA) + "/spatstat/"; }

// "<name>_window.txt" holds "rectangle xmin ymin xmax ymax" or "wkt POLYGON((...), (...))".
inline Window spatstatWindow(const std::string& name) {
    std::ifstream in(spatstatDir() + name + "_window.txt");
    std::string kind;
    in >> kind;
    if (kind == "wkt") {
        std::string wkt;
        std::getline(in, wkt);
        return Window::fromWkt(wkt);
    }
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    in >> x0 >> y0 >> x1 >> y1;
    if (!in || kind != "rectangle") throw std::runtime_error("cannot read window of " + name);
    return Window::rectangle(x0, y0, x1, y1);
}

// A column of "<name>_<table>.csv" (a reference table other than the summary).
inline std::vector<double> spatstatColumn(const std::string& name, const std::string& table, const std::string& column) {
    const CsvTable t = CsvTable::read(spatstatDir() + name + "_" + table + ".csv");
    std::vector<double> values;
    for (std::size_t r = 0; r < t.rows(); ++r) values.push_back(t.number(r, t.require(column)));
    return values;
}

inline std::vector<Eigen::Vector2d> spatstatPoints(const std::string& name) {
    const CsvTable t = CsvTable::read(spatstatDir() + name + "_points.csv");
    std::vector<Eigen::Vector2d> p;
    for (std::size_t r = 0; r < t.rows(); ++r) p.emplace_back(t.number(r, t.require("x")), t.number(r, t.require("y")));
    return p;
}

// One row of summary.csv, column by name.
inline double spatstatSummary(const std::string& name, const std::string& column) {
    const CsvTable t = CsvTable::read(spatstatDir() + "summary.csv");
    for (std::size_t r = 0; r < t.rows(); ++r)
        if (t.text(r, t.require("name")) == name) return t.number(r, t.require(column));
    throw std::runtime_error("no row " + name + " in summary.csv");
}

struct ReferencePcf {
    std::vector<double> r, trans, iso;  // without the r = 0 row (Inf or NA in spatstat)
};

inline ReferencePcf spatstatPcf(const std::string& name) {
    const CsvTable t = CsvTable::read(spatstatDir() + name + "_pcf.csv");
    ReferencePcf g;
    for (std::size_t r = 0; r < t.rows(); ++r) {
        if (t.text(r, t.require("trans")) == "Inf" || t.text(r, t.require("trans")) == "NA") continue;
        g.r.push_back(t.number(r, t.require("r")));
        g.trans.push_back(t.number(r, t.require("trans")));
        g.iso.push_back(t.number(r, t.require("iso")));
    }
    return g;
}

}  // namespace sylva::stand::testdata
