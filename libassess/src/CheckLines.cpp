#include "libassess/CheckLines.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>

#include "GdalSupport.hpp"
#include "libcommon/InputError.hpp"
#include "libdem/CampaignSummary.hpp"

namespace sylva::assess {

namespace {

// A coordinate to the millimetre: projected coordinates are ~1e6 m, which 6 significant digits
// would write as 6.60001e+06, to ten metres.
std::string fixedMm(double v) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

// The same in a message, without trailing zeros.
std::string coordinate(double v) {
    std::string s = fixedMm(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
}

// A line as read, before it is checked: the layer's CRS is checked first, so that a file in another
// CRS is told so rather than that its lines are outside the DTM.
struct RawLine {
    CheckLine line;
    std::string where;  // "layer 'x', feature 3", for messages
};

std::string described(const RawLine& raw) { return "line '" + raw.line.name + "' (" + raw.where + ")"; }

// Whether the polyline touches the rectangle [x0, x1] x [y0, y1]: a segment clipped to it
// (Liang-Barsky) keeps some part. The vertices alone do not say it: a line may cross the DTM from
// one side to the other with both ends outside.
bool touches(const std::vector<Eigen::Vector2d>& v, double x0, double x1, double y0, double y1) {
    for (std::size_t j = 0; j + 1 < v.size(); ++j) {
        const Eigen::Vector2d d = v[j + 1] - v[j];
        double t0 = 0, t1 = 1;
        bool inside = true;
        for (const auto& [p, q] : {std::pair{-d.x(), v[j].x() - x0}, std::pair{d.x(), x1 - v[j].x()}, std::pair{-d.y(), v[j].y() - y0},
                                  std::pair{d.y(), y1 - v[j].y()}}) {
            if (p == 0) {
                inside = inside && q >= 0;  // parallel to this edge: inside its half-plane or nowhere
                continue;
            }
            const double t = q / p;
            if (p < 0)
                t0 = std::max(t0, t);
            else
                t1 = std::min(t1, t);
        }
        if (inside && t0 <= t1) return true;
    }
    return false;
}

void check(const RawLine& raw, const std::string& path, const Dtm& dtm) {
    if (raw.line.vertices.size() < 2)
        throw InputError(path, 0, described(raw) + " has fewer than 2 distinct vertices: a check line needs a length");
    const RasterGrid& g = dtm.grid;
    const double x0 = g.geoTransform[0], x1 = x0 + g.columns * g.cellSize(), y1 = g.geoTransform[3], y0 = y1 - g.rows * g.cellSize();
    if (!touches(raw.line.vertices, x0, x1, y0, y1))
        throw InputError(path, 0, described(raw) + " lies entirely outside the DTM (" + dtm.path + "), which spans x " + coordinate(x0) +
                                      " to " + coordinate(x1) + ", y " + coordinate(y0) + " to " + coordinate(y1));
}

// The vertices of a line string in plan, a vertex repeating the one before it left out (a segment of
// no length crosses nothing).
std::vector<Eigen::Vector2d> verticesOf(const OGRLineString& line) {
    std::vector<Eigen::Vector2d> v;
    for (int i = 0; i < line.getNumPoints(); ++i) {
        const Eigen::Vector2d p(line.getX(i), line.getY(i));
        if (v.empty() || p != v.back()) v.push_back(p);
    }
    return v;
}

// The lines of one layer; `count` numbers the line features of the file, for their default names.
std::vector<RawLine> layerLines(OGRLayer& layer, int& count, int& others) {
    std::vector<RawLine> lines;
    const int nameField = layer.GetLayerDefn()->GetFieldIndex("name");
    long number = 0;  // from 1 in the layer's order, as the other readers count (GeoJSON's FIDs start at 0)
    for (auto& feature : layer) {
        ++number;
        const OGRGeometry* g = feature->GetGeometryRef();
        const auto type = g ? wkbFlatten(g->getGeometryType()) : wkbNone;
        if (type != wkbLineString && type != wkbMultiLineString) {
            ++others;
            continue;
        }
        ++count;
        const bool named = nameField >= 0 && feature->IsFieldSetAndNotNull(nameField) && *feature->GetFieldAsString(nameField) != '\0';
        const std::string name = named ? feature->GetFieldAsString(nameField) : "line " + std::to_string(count);
        const std::string where = "layer '" + std::string(layer.GetName()) + "', feature " + std::to_string(number);
        if (type == wkbLineString) {
            lines.push_back({{name, verticesOf(*g->toLineString())}, where});
            continue;
        }
        int part = 0;
        for (const OGRLineString* line : *g->toMultiLineString())
            lines.push_back({{name + " part " + std::to_string(++part), verticesOf(*line)}, where});
    }
    return lines;
}

// Where, as a fraction of the step a -> b, the step crosses the segment p -> q; -1 if it does not.
// The sides are orientations (cross products) of a point against a segment or a step: a sample's
// side of a segment is computed alike for the step it ends and the one it starts, and a vertex's
// side of a step alike for the two segments sharing it, so a crossing exactly at a sample or at a
// vertex is neither lost to rounding nor counted twice.
double stepCrossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
    const Eigen::Vector2d e = q - p, r = b - a;
    const double sa = cross(e, a - p), sb = cross(e, b - p);  // the samples' sides of the segment's line
    if (sa == sb) return -1;                                   // parallel to it, or not moving in plan
    const bool across = sa == 0 || (sa < 0 && sb > 0) || (sa > 0 && sb < 0);  // first sample included, last excluded
    const double sp = cross(r, p - a), sq = cross(r, q - a);  // the segment's ends' sides of the step's line
    const bool within = (sp <= 0 && sq >= 0) || (sp >= 0 && sq <= 0);
    return across && within ? sa / (sa - sb) : -1;
}

LineCrossing crossingAt(const dem::TrajectorySample& a, const dem::TrajectorySample& b, double s, const Dtm& dtm, int line) {
    const auto between = [s](double u, double v) { return u + s * (v - u); };
    const Eigen::Vector3d p = a.position + s * (b.position - a.position);
    LineCrossing c;
    c.line = line;
    c.x = p.x();
    c.y = p.y();
    c.energyKj = static_cast<float>(between(a.translationalEnergy + a.rotationalEnergy, b.translationalEnergy + b.rotationalEnergy) / 1000);
    c.heightM = static_cast<float>(p.z() - dtm.elevation.height(p.x(), p.y()));
    c.speedMs = static_cast<float>(between(a.velocity.norm(), b.velocity.norm()));
    c.time = static_cast<float>(between(a.t, b.t));
    return c;
}

// A name written as is unless it would break the row (a comma, a quote, a line break).
std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string quoted = "\"";
    for (char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

std::ofstream create(const std::string& path) {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw sylva::cannotWrite(path);
    return out;
}

void close(std::ofstream& out, const std::string& path) {
    out.flush();
    if (!out) throw sylva::cannotWrite(path);
}

}  // namespace

std::vector<CheckLine> readCheckLines(const std::string& path, const Dtm& dtm, int* passedOver) {
    GDALDatasetUniquePtr ds = openVectorFile(path);
    std::vector<RawLine> raw;
    int count = 0, others = 0;
    for (OGRLayer* layer : ds->GetLayers()) {
        if (layer->GetGeomType() == wkbNone) continue;
        int othersHere = 0;
        std::vector<RawLine> lines = layerLines(*layer, count, othersHere);
        if (lines.empty()) continue;
        others += othersHere;
        // After the reading: the CRS check reads the layer's extent, which restarts its reading.
        requireDtmCrs(*layer, path, dtm);
        for (auto& l : lines) raw.push_back(std::move(l));
    }
    if (raw.empty()) throw InputError(path, 0, "no line in the file (" + geometriesHeld(*ds) + "): check lines are LineString or MultiLineString features");
    if (passedOver) *passedOver = others;
    std::map<std::string, const RawLine*> byName;
    std::vector<CheckLine> lines;
    for (const auto& r : raw) {
        check(r, path, dtm);
        const auto [it, fresh] = byName.emplace(r.line.name, &r);
        if (!fresh)
            throw InputError(path, 0, "two lines are named '" + r.line.name + "' (" + it->second->where + " and " + r.where +
                                          "): the rows of check_lines.csv tell the lines apart by their names");
        lines.push_back(r.line);
    }
    return lines;
}

std::vector<LineCrossing> crossCheckLines(const std::vector<dem::TrajectorySample>& samples, const Dtm& dtm,
                                          const std::vector<CheckLine>& lines) {
    std::vector<LineCrossing> crossings;
    for (std::size_t l = 0; l < lines.size(); ++l) {
        const auto& v = lines[l].vertices;
        Eigen::Vector2d lo = v.front(), hi = v.front();
        for (const auto& p : v) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        for (std::size_t i = 1; i < samples.size(); ++i) {
            const Eigen::Vector2d a = samples[i - 1].position.head<2>(), b = samples[i].position.head<2>();
            // Most steps are nowhere near the line: their boxes do not meet.
            if ((a.cwiseMax(b).array() < lo.array()).any() || (a.cwiseMin(b).array() > hi.array()).any()) continue;
            // A step may cross a bent line more than once: the crossing is the first along the step.
            double first = 2;
            for (std::size_t j = 0; j + 1 < v.size(); ++j) {
                const double s = stepCrossing(a, b, v[j], v[j + 1]);
                if (s >= 0 && s < first) first = s;
            }
            if (first <= 1) {
                crossings.push_back(crossingAt(samples[i - 1], samples[i], first, dtm, static_cast<int>(l)));
                break;
            }
        }
    }
    return crossings;
}

CheckLineTally::CheckLineTally(std::vector<CheckLine> lines) : lines_(std::move(lines)) {}

CheckLineTally::Pass& CheckLineTally::passNamed(const std::string& name) {
    const auto it = std::find_if(passes_.begin(), passes_.end(), [&](const Pass& p) { return p.name == name; });
    if (it != passes_.end()) return *it;
    passes_.push_back({name, -1, -1, std::vector<std::vector<Row>>(lines_.size())});
    return passes_.back();
}

void CheckLineTally::add(const std::string& passName, long run, const std::vector<LineCrossing>& crossings) {
    Pass& p = passNamed(passName);
    if (run <= p.lastRun)
        throw std::logic_error("CheckLineTally::add: run " + std::to_string(run) + " of pass " + passName + " after run " +
                               std::to_string(p.lastRun) + ": add each run once, in increasing order");
    p.lastRun = run;
    for (const auto& c : crossings) {
        if (c.line < 0 || static_cast<std::size_t>(c.line) >= lines_.size())
            throw std::logic_error("CheckLineTally::add: a crossing of line " + std::to_string(c.line) + ", of " +
                                   std::to_string(lines_.size()) + " lines");
        p.byLine[static_cast<std::size_t>(c.line)].push_back({run, c});
    }
}

void CheckLineTally::setBlocks(const std::string& passName, long blocks) { passNamed(passName).blocks = blocks; }

void CheckLineTally::write(const std::string& dir) const {
    for (const auto& p : passes_)
        if (p.blocks < 0) throw std::logic_error("CheckLineTally::write: pass " + p.name + " has no block count (setBlocks)");
    const std::string rowsPath = dir + "/check_lines.csv", summaryPath = dir + "/check_lines_summary.csv";
    std::ofstream rows = create(rowsPath);
    rows << "pass,line,run,x,y,time_s,energy_kj,height_m,speed_m_s\n";
    for (const auto& p : passes_)
        for (std::size_t l = 0; l < lines_.size(); ++l)
            for (const auto& r : p.byLine[l]) {
                const LineCrossing& c = r.crossing;
                rows << csvField(p.name) << ',' << csvField(lines_[l].name) << ',' << r.run << ',' << fixedMm(c.x) << ','
                     << fixedMm(c.y) << ',' << number(c.time) << ',' << number(c.energyKj) << ',' << number(c.heightM) << ','
                     << number(c.speedMs) << '\n';
            }
    close(rows, rowsPath);

    std::ofstream summary = create(summaryPath);
    summary << "pass,line,blocks,crossings,fraction,energy_kj_p50,energy_kj_p95,energy_kj_p99,height_m_p50,height_m_p95,height_m_p99,"
               "speed_m_s_p50,speed_m_s_p95,speed_m_s_p99\n";
    for (const auto& p : passes_)
        for (std::size_t l = 0; l < lines_.size(); ++l) {
            const auto& crossed = p.byLine[l];
            summary << csvField(p.name) << ',' << csvField(lines_[l].name) << ',' << p.blocks << ',' << crossed.size() << ','
                    << (p.blocks > 0 ? number(static_cast<double>(crossed.size()) / p.blocks) : "");
            std::vector<double> energy, height, speed;
            for (const auto& r : crossed) {
                energy.push_back(r.crossing.energyKj);
                height.push_back(r.crossing.heightM);
                speed.push_back(r.crossing.speedMs);
            }
            for (const auto* values : {&energy, &height, &speed})
                for (double q : {0.5, 0.95, 0.99}) summary << ',' << (values->empty() ? "" : number(dem::quantile(*values, q)));
            summary << '\n';
        }
    close(summary, summaryPath);
}

std::vector<CheckLineTally::LineSample> CheckLineTally::samples() const {
    std::vector<LineSample> all;
    for (const auto& p : passes_)
        for (std::size_t l = 0; l < lines_.size(); ++l) {
            LineSample s{p.name, lines_[l].name, std::max(0L, p.blocks), {}, {}};
            for (const auto& r : p.byLine[l]) {
                s.energyKj.push_back(r.crossing.energyKj);
                s.heightM.push_back(r.crossing.heightM);
            }
            all.push_back(std::move(s));
        }
    return all;
}

}  // namespace sylva::assess
