#include "libstand/ForestGenerator.hpp"

#include <gsl/gsl_rng.h>

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "BalancedSampler.hpp"
#include "StemGrid.hpp"
#include "libcommon/SeededRandom.hpp"
#include "libstand/Allometry.hpp"
#include "libcommon/InputError.hpp"

namespace sylva::stand {

ForestStructure parseForestStructure(const std::string& name) {
    if (name == "aggregated" || name == "A") return ForestStructure::Aggregated;
    if (name == "random" || name == "NA") return ForestStructure::Random;
    throw InputError("unknown forest structure '" + name + "' (expected 'aggregated' (A) or 'random' (NA))");
}

std::string toString(ForestStructure structure) {
    return structure == ForestStructure::Aggregated ? "aggregated" : "random";
}

namespace {

using Vec = Eigen::Vector2d;

// Positions are rounded to 1 mm (the precision of the inventories) before the clearance test, so
// the coordinates written to the CSV are exactly the ones that were checked.
Vec roundToMillimetre(const Vec& p) { return Vec(std::round(p.x() * 1e3) / 1e3, std::round(p.y() * 1e3) / 1e3); }

// Places stems one by one (or a stool's stems all or none) at random positions in the extent,
// keeping the clearance to every stem already placed, and records them as trees.
class ForestBuilder {
public:
    ForestBuilder(const StandCatalogue& stand, const Window& extent, const GenerationSettings& settings, gsl_rng* rng,
                  std::size_t stems)
        : stand_(stand),
          extent_(extent),
          settings_(settings),
          rng_(rng),
          grid_(extent.lower(), extent.upper(), stand.maxDbhCm() / 200.0, settings.clearanceM, stems) {}

    void placeSingle(const StemTemplate& stem) {
        const double radius = stem.dbhCm / 200.0;
        for (long attempt = 0; attempt < settings_.maxAttempts; ++attempt) {
            const Vec p = roundToMillimetre(uniformPoint());
            if (!extent_.contains(p) || !grid_.isFree(p, radius)) continue;
            grid_.insert(p, radius);
            addTree(p, stem, std::nullopt);
            return;
        }
        std::ostringstream what;
        what << "a stem of " << stem.dbhCm << " cm DBH";
        failPlacement(what.str());
    }

    // The first `count` stems of the stool, around a uniform centroid and rotated by a uniform angle
    // (stools have no preferred orientation). One stem left of a trimmed stool is a single tree. A
    // stool's stems keep their clearance from the stems placed before, not from one another: they
    // stand as the inventory measured them, often closer (coppice stems grow fused at the base).
    void placeStool(const StoolTemplate& stool, std::size_t count) {
        for (long attempt = 0; attempt < settings_.maxAttempts; ++attempt) {
            const Vec centroid = uniformPoint();
            const double angle = 2 * M_PI * gsl_rng_uniform(rng_);
            const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
            std::vector<Vec> positions;
            for (std::size_t i = 0; i < count; ++i) {
                const Vec p = roundToMillimetre(centroid + rotation * stool.offsets[i]);
                if (!extent_.contains(p) || !grid_.isFree(p, stool.stems[i].dbhCm / 200.0)) break;
                positions.push_back(p);
            }
            if (positions.size() < count) continue;
            for (std::size_t i = 0; i < count; ++i) grid_.insert(positions[i], stool.stems[i].dbhCm / 200.0);
            const std::optional<long> id = count >= 2 ? std::optional<long>(++result_.stools) : std::nullopt;
            for (std::size_t i = 0; i < count; ++i) addTree(positions[i], stool.stems[i], id);
            if (id) result_.stemsInStools += count;
            return;
        }
        failPlacement("a stool of " + std::to_string(count) + " stems");
    }

    void warn(std::string message) { result_.warnings.push_back(std::move(message)); }
    void tooSmall(const std::string& message) {
        result_.tooSmall = message;
        warn(message);
    }
    GeneratedForest take() { return std::move(result_); }

private:
    Vec uniformPoint() const {
        const Vec lo = extent_.lower(), hi = extent_.upper();
        return Vec(lo.x() + (hi.x() - lo.x()) * gsl_rng_uniform(rng_), lo.y() + (hi.y() - lo.y()) * gsl_rng_uniform(rng_));
    }

    void addTree(const Vec& p, const StemTemplate& stem, std::optional<long> stool) {
        Tree t;
        t.id = static_cast<long>(result_.forest.trees.size()) + 1;
        t.x = p.x();
        t.y = p.y();
        t.dbhCm = stem.dbhCm;
        t.species = stem.species;
        t.stool = stool;
        t.heightM = treeHeightM(stem.dbhCm);
        t.crownLengthM = crownLengthM(t.heightM);
        t.crownMassKg = crownMassKg(stem.dbhCm);
        result_.forest.trees.push_back(std::move(t));
    }

    [[noreturn]] void failPlacement(const std::string& what) const {
        std::ostringstream msg;
        msg << "stand " << stand_.name() << ": could not place " << what << " without overlap in " << extent_.describe()
            << " after " << settings_.maxAttempts << " random positions (" << result_.forest.trees.size()
            << " stems placed): the extent is too small or too full for " << stand_.stemsPerHa() << " stems/ha";
        throw InputError(msg.str());
    }

    const StandCatalogue& stand_;
    const Window& extent_;
    const GenerationSettings& settings_;
    gsl_rng* rng_;
    StemGrid grid_;
    GeneratedForest result_;
};

void drawSingles(ForestBuilder& builder, const std::vector<StemTemplate>& pool, std::size_t count, gsl_rng* rng) {
    if (count == 0) return;
    BalancedSampler draw(pool.size(), rng);
    for (std::size_t i = 0; i < count; ++i) builder.placeSingle(pool[draw.next()]);
}

}  // namespace

GeneratedForest generateForest(const StandCatalogue& stand, const Window& extent, const GenerationSettings& settings) {
    SeededRandom random(settings.seed);
    gsl_rng* const rng = random.gsl();

    // Checked before anything is drawn: an extent typed in mm (or to 1e308) would exhaust memory.
    const double expected = stand.stemsPerHa() * extent.area() / 1e4;
    if (!(expected <= kMaxGeneratedStems)) {
        std::ostringstream what;
        what << "an extent of " << extent.area() / 1e4 << " ha at " << stand.stemsPerHa() << " stems/ha would hold "
             << expected << " stems, above the " << kMaxGeneratedStems << " a forest may have (coordinates in mm?)";
        throw InputError(what.str());
    }
    const auto stems = static_cast<std::size_t>(std::llround(expected));
    ForestBuilder builder(stand, extent, settings, rng, stems);
    if (stems == 0) {  // a sliver of a stand map: nothing to draw there, said
        std::ostringstream what;
        what << "an extent of " << extent.area() << " m2 at " << stand.stemsPerHa() << " stems/ha holds " << expected
             << " stems, not one: none drawn (at least " << 0.5e4 / stand.stemsPerHa() << " m2 holds one)";
        builder.tooSmall(what.str());
    }

    ForestStructure structure = settings.structure;
    if (structure == ForestStructure::Aggregated && stand.stools().empty()) {
        builder.warn("stand " + stand.name() +
                     " has no coppice stool: the aggregated forest is made of single trees at random (as --structure random)");
        structure = ForestStructure::Random;
    }

    if (structure == ForestStructure::Random) {
        drawSingles(builder, stand.allStems(), stems, rng);
        return builder.take();
    }

    // The inventory's share of stems in stools fixes how many stems go to stools; the last stool
    // drawn is trimmed to that budget, single trees fill the rest, so N is exact and stool stems
    // and single trees (whose diameters differ) keep their proportions.
    const auto stoolBudget = static_cast<std::size_t>(std::llround(static_cast<double>(stems) * stand.stoolStemShare()));
    BalancedSampler drawStool(stand.stools().size(), rng);
    std::size_t inStools = 0;
    while (inStools < stoolBudget) {
        const StoolTemplate& stool = stand.stools()[drawStool.next()];
        const std::size_t count = std::min(stool.stems.size(), stoolBudget - inStools);
        builder.placeStool(stool, count);
        inStools += count;
    }
    drawSingles(builder, stand.singles(), stems - stoolBudget, rng);
    return builder.take();
}

}  // namespace sylva::stand
