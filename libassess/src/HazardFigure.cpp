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
       << "set title 'Reach probability (light yellow to dark red: 0 to " << topText << ") over the hillshade"
       << (forest.trees.empty() ? "" : "; trees in green") << "'\n"
       << "set xlabel 'm east of " << west << "'\nset ylabel 'm north of " << south << "'\nset size ratio -1\n"
       << "set xrange [0:" << width << "]\nset yrange [0:" << height << "]\nunset key\n"
       << "plot 'hillshade.dat' using 1:2:3:4:5 with rgbimage, 'reach.dat' using 1:2:3:4:5:6 with rgbalpha"
       // Without trees gnuplot would warn on stderr about the empty file.
       << (forest.trees.empty() ? "" : ", 'trees.dat' using 1:2 with dots lc rgb '#1e8449'") << "\n"
       // The same map as a picture for a report or a mail, where an SVG is not welcome.
       << "set terminal pngcairo size " << px << ',' << py << " noenhanced font 'sans,10'\nset output '../map.png'\nreplot\nunset output\n";
    FigureSet set = runGnuplot(dir, gp.str(), {"../map.svg", "../map.png"});
    for (auto& f : set.files) f = f.substr(3);
    return set;
}

namespace {

// A name inside a gnuplot single-quoted string, where a quote is written twice.
// A single-quoted gnuplot string: a quote doubled, and a line break (a name a GIS let through) a
// space, since a gnuplot command ends at the line's end.
std::string gnuplotQuoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("''") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
    return q + "'";
}

}  // namespace

FigureSet drawCheckLines(const std::string& outDir, const std::vector<CheckLineTally::LineSample>& samples) {
    const std::string dir = outDir + "/check_lines";
    fs::create_directories(dir);
    std::vector<std::string> lineNames;  // a colour per line, a dash per pass
    std::vector<std::string> passNames;
    for (const auto& s : samples) {
        if (std::find(lineNames.begin(), lineNames.end(), s.line) == lineNames.end()) lineNames.push_back(s.line);
        if (std::find(passNames.begin(), passNames.end(), s.pass) == passNames.end()) passNames.push_back(s.pass);
    }
    std::ofstream energy(dir + "/energy.dat"), height(dir + "/height.dat");
    energy << "# per line and pass (gnuplot index k): energy_kj, probability that a released block crosses with at least it\n";
    height << "# per line and pass (gnuplot index k): height_m, probability that a released block crosses at least that high\n";
    std::vector<std::string> plotted;  // "index k with its style and title", in the files' order
    std::string never;
    for (const auto& s : samples) {
        if (s.energyKj.empty() || s.blocks <= 0) {
            never += (never.empty() ? "" : "; ") + s.pass + ": " + s.line;
            continue;
        }
        // The k-th largest value is reached or passed by k of the pass's blocks.
        for (auto [values, out] : {std::pair{s.energyKj, &energy}, std::pair{s.heightM, &height}}) {
            std::sort(values.begin(), values.end(), std::greater<float>());
            for (std::size_t k = 0; k < values.size(); ++k) *out << values[k] << ' ' << static_cast<double>(k + 1) / s.blocks << '\n';
            *out << "\n\n";
        }
        const auto colour = std::find(lineNames.begin(), lineNames.end(), s.line) - lineNames.begin() + 1;
        const auto dash = std::find(passNames.begin(), passNames.end(), s.pass) - passNames.begin() + 1;
        plotted.push_back("index " + std::to_string(plotted.size()) + " using 1:2 with steps lw 2 lc " + std::to_string(colour) + " dt " +
                          std::to_string(dash) + " title " +
                          gnuplotQuoted(s.pass + ": " + s.line + " (" + std::to_string(s.energyKj.size()) + " of " + std::to_string(s.blocks) + ")"));
    }
    if (!energy || !height) throw InputError(dir, 0, "cannot write the check lines' data");
    energy.close();
    height.close();
    std::ostringstream gp;
    gp << "# What crossed the check lines of sylvarock hazard; run `gnuplot figures.gp` in this folder to redraw it.\n"
       << "set terminal svg size 1100,480 dynamic noenhanced font 'sans,11'\nset output '../check_lines.svg'\n";
    std::ostringstream body;
    body << "set multiplot layout 1,2 title " << gnuplotQuoted("Blocks crossing the check lines" + (never.empty() ? "" : " (never crossed: " + never + ")"))
         << "\nset logscale y\nset yrange [*:1.05]\nset grid\nset key top right\nset ylabel 'probability that a released block crosses with more'\n";
    for (const char* file : {"energy", "height"}) {
        body << "set xlabel '" << (std::string(file) == "energy" ? "kinetic energy at the crossing (kJ)" : "passing height of the centre above the ground (m)")
             << "'\n";
        if (plotted.empty()) {
            body << "set label 1 'no block crossed a check line' at graph 0.5, 0.5 center\nplot [0:1] [0.1:1] NaN notitle\n";
            continue;
        }
        body << "plot";
        for (std::size_t k = 0; k < plotted.size(); ++k) body << (k ? ", " : " ") << "'" << file << ".dat' " << plotted[k];
        body << "\n";
    }
    body << "unset multiplot\n";
    gp << body.str() << "unset output\n"
       << "set terminal pngcairo size 1100,480 noenhanced font 'sans,10'\nset output '../check_lines.png'\n"
       << body.str() << "unset output\n";
    FigureSet set = runGnuplot(dir, gp.str(), {"../check_lines.svg", "../check_lines.png"});
    for (auto& f : set.files) f = f.substr(3);
    return set;
}

FigureSet drawRasterPanels(const std::string& outDir, const Dtm& dtm, const std::vector<RasterPanel>& panels) {
    const std::string dir = outDir + "/rasters";
    fs::create_directories(dir);
    const RasterGrid& g = dtm.grid;
    const double west = g.geoTransform[0], south = g.geoTransform[3] + g.rows * g.geoTransform[5];
    const double width = g.columns * g.cellSize(), height = g.rows * g.cellSize();
    const int columns = panels.size() > 1 ? 2 : 1, rows = static_cast<int>((panels.size() + 1) / 2);
    const int px = 1100, panelHeight = std::max(220, static_cast<int>(px / columns * height / width) + 90);
    std::ostringstream body;
    body.precision(10);
    body << "set multiplot layout " << rows << ',' << columns << "\nset size ratio -1\nunset key\nset tics out\n"
         << "set xrange [0:" << width << "]\nset yrange [0:" << height << "]\nset xlabel 'm east of " << west << "'\nset ylabel 'm north of "
         << south << "'\n";
    for (std::size_t k = 0; k < panels.size(); ++k) {
        const RasterPanel& panel = panels[k];
        const std::string file = "panel" + std::to_string(k + 1) + ".dat";
        std::ofstream data(dir + "/" + file);
        data << "# x_m y_m (from the DTM's south-west corner) value: " << panel.title << "\n";
        float lo = 0, hi = 0;
        for (int r = 0; r < g.rows; ++r) {
            for (int c = 0; c < g.columns; ++c) {
                const Eigen::Vector2d p = g.centre(c, r);
                const float v = panel.values[g.index(c, r)];
                const bool has = v != panel.noData && std::isfinite(v);
                if (has) {
                    lo = std::min(lo, v);
                    hi = std::max(hi, v);
                }
                data << p.x() - west << ' ' << p.y() - south << ' ';
                if (has)
                    data << v;
                else
                    data << "NaN";
                data << '\n';
            }
            data << '\n';
        }
        if (!data) throw InputError(dir + "/" + file, 0, "cannot write");
        const float extent = std::max({std::fabs(lo), std::fabs(hi), 1e-6f});
        body << "set title " << gnuplotQuoted(panel.title) << "\n";
        if (panel.signedScale)
            body << "set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\nset cbrange [" << -extent << ':' << extent << "]\n";
        else
            body << "set palette defined (0 '#ffffb2', 0.5 '#fd8d3c', 1 '#800026')\nset cbrange [0:" << std::max(hi, 1e-6f) << "]\n";
        body << "plot '" << file << "' using 1:2:3 with image\n";
    }
    body << "unset multiplot\n";
    std::ostringstream gp;
    gp << "# The rasters of sylvarock hazard side by side; run `gnuplot figures.gp` in this folder to redraw them.\n"
       << "set terminal pngcairo size " << px << ',' << rows * panelHeight << " noenhanced font 'sans,10'\nset output '../rasters.png'\n"
       << body.str() << "unset output\n";
    FigureSet set = runGnuplot(dir, gp.str(), {"../rasters.png"});
    for (auto& f : set.files) f = f.substr(3);
    return set;
}

}  // namespace sylva::assess
