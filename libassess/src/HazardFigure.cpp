#include "libassess/HazardFigure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

std::vector<float> hillshade(const Dtm& dtm) {
    const RasterGrid& g = dtm.grid;
    const double azimuth = 315 * M_PI / 180, altitude = 45 * M_PI / 180;
    const Eigen::Vector3d light(std::cos(altitude) * std::sin(azimuth), std::cos(altitude) * std::cos(azimuth), std::sin(altitude));
    std::vector<float> shade(static_cast<std::size_t>(g.columns) * g.rows, 0);
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.columns; ++c) {
            const Eigen::Vector2d p = g.centre(c, r);
            const Eigen::Vector2d dz = dtm.elevation.gradient(p.x(), p.y());
            const Eigen::Vector3d normal = Eigen::Vector3d(-dz.x(), -dz.y(), 1).normalized();
            shade[g.index(c, r)] = static_cast<float>(std::max(0.0, normal.dot(light)));
        }
    return shade;
}

FigureSet drawHazardMap(const std::string& outDir, const Dtm& dtm, const std::vector<float>& reach, const stand::Forest& forest) {
    const std::string dir = outDir + "/map";
    fs::create_directories(dir);
    const RasterGrid& g = dtm.grid;
    const double west = g.geoTransform[0], south = g.geoTransform[3] + g.rows * g.geoTransform[5];
    const std::vector<float> shade = hillshade(dtm);
    const float top = std::max(1e-6f, *std::max_element(reach.begin(), reach.end()));
    {
        std::ofstream ground(dir + "/hillshade.dat"), hazard(dir + "/reach.dat"), trees(dir + "/trees.dat");
        trees.precision(10);
        ground << "# x_m y_m (from the DTM's south-west corner) r g b\n";
        hazard << "# x_m y_m r g b alpha: reach probability from light yellow (0) to dark red (" << top << ")\n";
        for (int r = 0; r < g.rows; ++r)
            for (int c = 0; c < g.columns; ++c) {
                const Eigen::Vector2d p = g.centre(c, r);
                const double x = p.x() - west, y = p.y() - south;
                const int grey = static_cast<int>(std::lround(40 + 200 * shade[g.index(c, r)]));
                ground << x << ' ' << y << ' ' << grey << ' ' << grey << ' ' << grey << '\n';
                // Every cell, transparent where no block passed: gnuplot draws an image only from a full grid.
                const float v = std::max(0.0f, reach[g.index(c, r)]);
                const double t = std::sqrt(v / top);  // square root: the rare paths stay visible
                hazard << x << ' ' << y << ' ' << std::lround(255 - 66 * t) << ' ' << std::lround(255 - 255 * t) << ' '
                       << std::lround(178 - 140 * t) << ' ' << (v > 0 ? 215 : 0) << '\n';
            }
        trees << "# x_m y_m dbh_cm\n";
        for (const auto& t : forest.trees) trees << t.x - west << ' ' << t.y - south << ' ' << t.dbhCm << '\n';
        if (!ground || !hazard || !trees) throw InputError(dir, 0, "cannot write the map's data");
    }
    const double width = g.columns * g.cellSize(), height = g.rows * g.cellSize();
    const int px = 1000, py = std::max(250, static_cast<int>(px * height / width) + 120);
    char topText[32];
    std::snprintf(topText, sizeof topText, "%.2g", top);
    std::ostringstream gp;
    gp.precision(10);  // projected coordinates to the metre
    gp << "# The hazard map of sylvarock hazard; run `gnuplot figures.gp` in this folder to redraw it.\n"
       << "set terminal svg size " << px << ',' << py << " dynamic noenhanced font 'sans,11'\nset output '../map.svg'\n"
       << "set title 'Reach probability (light yellow to dark red: 0 to " << topText << ") over the hillshade; trees in green'\n"
       << "set xlabel 'm east of " << west << "'\nset ylabel 'm north of " << south << "'\nset size ratio -1\n"
       << "set xrange [0:" << width << "]\nset yrange [0:" << height << "]\nunset key\n"
       << "plot 'hillshade.dat' using 1:2:3:4:5 with rgbimage, 'reach.dat' using 1:2:3:4:5:6 with rgbalpha, "
       << "'trees.dat' using 1:2 with dots lc rgb '#1e8449'\n"
       // The same map as a picture for a report or a mail, where an SVG is not welcome.
       << "set terminal pngcairo size " << px << ',' << py << " noenhanced font 'sans,10'\nset output '../map.png'\nreplot\nunset output\n";
    FigureSet set = runGnuplot(dir, gp.str(), {"../map.svg", "../map.png"});
    for (auto& f : set.files) f = f.substr(3);
    return set;
}

}  // namespace sylva::assess
