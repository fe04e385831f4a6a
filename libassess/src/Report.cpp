#include "libassess/Report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <stdexcept>

#include "libassess/CampaignPlan.hpp"
#include "libassess/ModelComparison.hpp"
#include "libdem/CampaignSummary.hpp"
#include "libcommon/InputError.hpp"

namespace fs = std::filesystem;

namespace sylva::assess {

namespace {

// " with --set a=1 --set b=2", or nothing.
std::string setsText(const std::vector<std::string>& sets) {
    std::string s;
    for (const auto& o : sets) s += (s.empty() ? " with `--set " : " --set ") + o;
    return s.empty() ? s : s + "`";
}

std::ofstream create(const std::string& path) {
    std::ofstream out(path, std::ios::trunc);
    if (!out) throw sylva::cannotWrite(path);
    out.precision(10);
    return out;
}

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return "–";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

// Mean of a statistic over a row's virtual forests (NaN values, an undefined index, are left out).
template <class Get>
double forestMean(const StructureAssessment& row, Get get) {
    double sum = 0;
    int n = 0;
    for (const auto& f : row.forests)
        if (std::isfinite(get(f))) {
            sum += get(f);
            ++n;
        }
    return n ? sum / n : std::nan("");
}

std::map<std::string, int> stopReasons(const std::vector<RunRecord>& runs) {
    std::map<std::string, int> counts;
    for (const auto& r : runs) ++counts[r.reason];
    return counts;
}

std::vector<RunRecord> pooled(const StructureAssessment& row) {
    std::vector<RunRecord> all;
    for (const auto& runs : row.runs) all.insert(all.end(), runs.begin(), runs.end());
    return all;
}

using Json = nlohmann::ordered_json;  // keys in the order written: the file reads like the report

// Non-finite numbers (an undefined index) are written as null, as nlohmann does for NaN.
void summaryFields(Json& j, const ForestSummary& f) {
    j["stems_per_ha"] = f.stemsPerHa;
    j["basal_area_m2_ha"] = f.basalAreaM2Ha;
    j["mean_dbh_cm"] = f.meanDbhCm;
    j["sd_dbh_cm"] = f.sdDbhCm;
    j["clark_evans"] = f.clarkEvans;
}

Json stopReasonsJson(const std::vector<RunRecord>& runs) {
    Json j = Json::object();
    for (const auto& [reason, count] : stopReasons(runs)) j[reason] = count;
    return j;
}

// An undefined value (a p-value under three stands, an index without stems) is an empty field, which
// spreadsheets and pandas read as missing; "nan" is text to some readers and a number to others.
struct Field {
    double value;
};
std::ostream& operator<<(std::ostream& out, Field f) { return std::isfinite(f.value) ? out << f.value : out; }

void writeTables(const std::string& dir, const AssessmentResults& res) {
    auto stands = create(dir + "/stands.csv");
    stands << "stand,structure,pf50,pf50_low,pf50_high,dist50_m,realisations,runs_per_realisation,rank_pf50,rank_basal_area,"
              "stems_per_ha,basal_area_m2_ha,mean_dbh_cm,sd_dbh_cm,clark_evans,virtual_basal_area_m2_ha,virtual_mean_dbh_cm,"
              "virtual_sd_dbh_cm,virtual_clark_evans\n";
    for (const auto& r : res.stands)
        stands << r.name << ',' << structureCode(r.structure) << ',' << Field{r.pf50} << ',' << Field{r.pf50Ci.low} << ',' << Field{r.pf50Ci.high} << ','
               << Field{r.dist50} << ',' << r.runs.size() << ',' << runsPerRealisation(res.design, res.model) << ',' << r.rankPf50 << ',' << r.rankBasalArea << ','
               << Field{r.inventory.stemsPerHa} << ',' << Field{r.inventory.basalAreaM2Ha} << ',' << Field{r.inventory.meanDbhCm} << ','
               << Field{r.inventory.sdDbhCm} << ',' << Field{r.inventory.clarkEvans} << ','
               << Field{forestMean(r, [](const ForestSummary& f) { return f.basalAreaM2Ha; })} << ','
               << Field{forestMean(r, [](const ForestSummary& f) { return f.meanDbhCm; })} << ','
               << Field{forestMean(r, [](const ForestSummary& f) { return f.sdDbhCm; })} << ','
               << Field{forestMean(r, [](const ForestSummary& f) { return f.clarkEvans; })} << '\n';
    auto forests = create(dir + "/forests.csv");
    forests << "stand,structure,realisation,stems,stems_per_ha,basal_area_m2_ha,mean_dbh_cm,sd_dbh_cm,clark_evans,dist50_m,pf50\n";
    for (const auto& r : res.stands)
        for (std::size_t k = 0; k < r.forests.size(); ++k) {
            const auto& f = r.forests[k];
            std::vector<double> runout;
            for (const auto& run : r.runs[k]) runout.push_back(run.runoutM);
            forests << r.name << ',' << structureCode(r.structure) << ',' << k + 1 << ',' << f.stems << ',' << Field{f.stemsPerHa} << ','
                    << Field{f.basalAreaM2Ha} << ',' << Field{f.meanDbhCm} << ',' << Field{f.sdDbhCm} << ',' << Field{f.clarkEvans} << ','
                    << Field{dem::quantile(runout, 0.5)} << ',' << Field{r.pf50PerRealisation[k]} << '\n';
        }
    auto corr = create(dir + "/correlations.csv");
    corr << "structure,stands,pearson_pf50_basal_area,pearson_pf50_mean_dbh,pearson_pf50_stems_per_ha,p_pf50_basal_area,p_pf50_mean_dbh,"
            "p_pf50_stems_per_ha\n";
    for (const auto& c : res.correlations)
        corr << structureCode(c.structure) << ',' << c.stands << ',' << Field{c.basalArea} << ',' << Field{c.meanDbh} << ',' << Field{c.stemsPerHa} << ','
             << Field{c.pBasalArea} << ',' << Field{c.pMeanDbh} << ',' << Field{c.pStemsPerHa} << '\n';
    auto runs = create(dir + "/runs.csv");
    runs << "stand,structure,realisation,run,seed,runout_m,runout_horizontal_m,stop_x_m,stop_y_m,tree_impacts,reason\n";
    const auto row = [&runs](const std::string& stand, const std::string& structure, std::size_t k, const RunRecord& r) {
        runs << stand << ',' << structure << ',' << k << ',' << r.run << ',' << r.seed << ',' << Field{r.runoutM} << ',' << Field{r.runoutHorizontalM}
             << ',' << Field{r.stopX} << ',' << Field{r.stopY} << ',' << r.treeImpacts << ',' << r.reason << '\n';
    };
    for (const auto& r : res.baseline) row("none", "", 0, r);
    for (const auto& s : res.stands)
        for (std::size_t k = 0; k < s.runs.size(); ++k)
            for (const auto& r : s.runs[k]) row(s.name, structureCode(s.structure), k + 1, r);
}

std::string modelName(dem::Model model) {
    return model == dem::Model::Dem ? "the discrete element model" : "the lumped-mass model";
}

// r and its p-value in one cell, the paper's significance level marked.
std::string correlationCell(double r, double p) {
    return fixed(r, 3) + " (p " + fixed(p, 3) + ")" + (p < 0.05 ? " *" : "");
}

void writeCorrelationTable(std::ostream& md, const std::vector<DendrometricCorrelation>& correlations) {
    md << "Pearson's correlation of PF50 with the inventories' G, Mean_D and N, with its two-sided p-value (t test, "
          "n − 2 degrees of freedom; * p < 0.05; undefined below three stands):\n\n"
          "| structure | stands | r(PF50, G) | r(PF50, Mean_D) | r(PF50, N) |\n| --- | --- | --- | --- | --- |\n";
    for (const auto& c : correlations)
        md << "| " << structureCode(c.structure) << " | " << c.stands << " | " << correlationCell(c.basalArea, c.pBasalArea) << " | "
           << correlationCell(c.meanDbh, c.pMeanDbh) << " | " << correlationCell(c.stemsPerHa, c.pStemsPerHa) << " |\n";
}

void writeMarkdown(const std::string& path, const AssessmentResults& res, const FigureSet& figures) {
    auto md = create(path);
    const auto& d = res.design;
    md << "# Protection of the stands against rockfall (sylvarock assess, " << modelName(res.model) << ")\n\n"
       << "Scene `" << d.sceneFile << "`" << setsText(d.sceneOverrides) << "; seed " << d.seed << "; per stand and structure " << d.realisations
       << " virtual forest(s) of " << runsPerRealisation(d, res.model) << " block runs each; " << baselineRuns(d, res.model)
       << " runs without forest.\n\n"
       << "PF50 = 1 − Dist50(with forest) / Dist50(without forest) (Toe et al., Eq. 26), Dist50 the median run-out "
       << "along the slope of the pooled runs. The interval is a " << confidencePercent(res.bootstrap.confidence)
       << " % percentile bootstrap (" << res.bootstrap.replicates
       << " replicates) that resamples the forest realisations, then the runs within each, and the runs without forest, "
       << "so it carries both the forest-to-forest and the block-to-block spread.\n\n"
       << "Without forest: Dist50 = " << fixed(res.baselineDist50, 1) << " m over " << res.baseline.size() << " runs.\n\n";
    if (!res.failedRuns.empty()) {
        md << "**" << res.failedRuns.size() << " run(s) stopped on a numerical error and are left out of every figure "
           << "and index below** (`sylvarock assess` printed why):";
        for (const auto& f : res.failedRuns) md << " " << f << ";";
        md << "\n\n";
    }

    for (auto structure : assessedStructures()) {
        const std::string code = structureCode(structure);
        md << "## " << (code == "A" ? "Aggregated forests (A)" : "Not aggregated forests (NA)") << "\n\n"
           << "| stand | PF50 | " << confidencePercent(res.bootstrap.confidence) << " % interval | Dist50 (m) | rank PF50 | G (m²/ha) | rank G | "
           << "Mean_D (cm) | N (/ha) |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
        for (const auto& r : res.stands)
            if (r.structure == structure)
                md << "| " << r.name << " | " << fixed(r.pf50, 3) << " | [" << fixed(r.pf50Ci.low, 3) << ", " << fixed(r.pf50Ci.high, 3)
                   << "] | " << fixed(r.dist50, 1) << " | " << r.rankPf50 << " | " << fixed(r.inventory.basalAreaM2Ha, 2) << " | "
                   << r.rankBasalArea << " | " << fixed(r.inventory.meanDbhCm, 2) << " | " << fixed(r.inventory.stemsPerHa, 0) << " |\n";
        md << "\nRank 1 is the least protective stand (as in the paper's Fig. 11); stands whose intervals overlap are not "
              "told apart by this campaign.\n\n";
    }

    md << "## PF50 and dendrometry (Fig. 12)\n\n";
    writeCorrelationTable(md, res.correlations);

    md << "\n## Inventories and virtual forests (Table 3)\n\nVirtual forests: mean over the realisations.\n\n"
       << "| forest | Mean_D (cm) | Std_D (cm) | N (/ha) | G (m²/ha) | R_Clark |\n| --- | --- | --- | --- | --- | --- |\n";
    for (const auto& r : res.stands) {
        if (r.structure == assessedStructures().front())
            md << "| " << r.name << " | " << fixed(r.inventory.meanDbhCm, 2) << " | " << fixed(r.inventory.sdDbhCm, 2) << " | "
               << fixed(r.inventory.stemsPerHa, 0) << " | " << fixed(r.inventory.basalAreaM2Ha, 2) << " | "
               << fixed(r.inventory.clarkEvans, 2) << " |\n";
        md << "| " << r.name << "_" << structureCode(r.structure) << " | "
           << fixed(forestMean(r, [](const ForestSummary& f) { return f.meanDbhCm; }), 2) << " | "
           << fixed(forestMean(r, [](const ForestSummary& f) { return f.sdDbhCm; }), 2) << " | "
           << fixed(forestMean(r, [](const ForestSummary& f) { return f.stemsPerHa; }), 0) << " | "
           << fixed(forestMean(r, [](const ForestSummary& f) { return f.basalAreaM2Ha; }), 2) << " | "
           << fixed(forestMean(r, [](const ForestSummary& f) { return f.clarkEvans; }), 2) << " |\n";
    }

    md << "\n## How the blocks stopped\n\n| campaign | rest | left the domain | time limit | tree impacts per run |\n"
          "| --- | --- | --- | --- | --- |\n";
    const auto reasons = [&md](const std::string& label, const std::vector<RunRecord>& runs) {
        auto c = stopReasons(runs);
        double impacts = 0;
        for (const auto& r : runs) impacts += r.treeImpacts;
        md << "| " << label << " | " << c["rest"] << " | " << c["left_domain"] << " | " << c["time_limit"] << " | "
           << fixed(runs.empty() ? 0.0 : impacts / runs.size(), 2) << " |\n";
    };
    reasons("no forest", res.baseline);
    for (const auto& r : res.stands) reasons(r.name + " " + structureCode(r.structure), pooled(r));
    md << "\nA block that left the domain counts with the run-out at which it left: Dist50 is then a lower bound.\n";

    md << "\n## Figures\n\n";
    const std::map<std::string, std::string> captions{
        {"runout_cdf.svg", "Cumulative run-out with and without forest, A against NA (Figs. 9–10)"},
        {"pf50.svg", "PF50 per stand with its interval (Fig. 11)"},
        {"pf50_dendrometry.svg", "PF50 against G, Mean_D and N (Fig. 12)"},
        {"stop_map.svg", "Stop positions (Fig. 8)"}};
    for (const auto& f : figures.files) md << "![" << captions.at(f) << "](" << f << ")\n\n";
    if (!figures.warning.empty()) md << "Figures missing: " << figures.warning << "\n\n";
    md << "Tables: `stands.csv`, `forests.csv` (each realisation), `correlations.csv`, `runs.csv` (every run); "
          "figure data in `data/`, the gnuplot script `figures.gp`.\n";
}

Json designJson(const AssessmentDesign& d, const BootstrapSettings& bootstrap) {
    Json design;
    design["scene"] = d.sceneFile;
    design["scene_set"] = d.sceneOverrides;
    design["seed"] = d.seed;
    const bool demRuns = usesModel(d, dem::Model::Dem);
    if (demRuns) design["runs_per_realisation"] = d.runs;  // the DEM's counts only where it ran
    design["realisations"] = d.realisations;
    if (demRuns) design["baseline_runs"] = d.baselineRuns;
    design["models"] = Json::array();
    for (auto model : d.models) design["models"].push_back(dem::toString(model));
    if (usesModel(d, dem::Model::Lumped)) {
        design["lumped_runs_per_realisation"] = d.lumpedRuns;
        design["lumped_baseline_runs"] = d.lumpedBaselineRuns;
    }
    design["bootstrap_replicates"] = bootstrap.replicates;
    design["confidence"] = bootstrap.confidence;
    design["stands"] = Json::array();
    for (const auto& s : d.stands) design["stands"].push_back(s.name);
    return design;
}

// One model's results: the top level of results.json for the first model, an object named after the
// model for the others.
Json modelJson(const AssessmentResults& res) {
    Json root;
    root["model"] = dem::toString(res.model);
    std::vector<double> baselineRunouts;
    for (const auto& r : res.baseline) baselineRunouts.push_back(r.runoutM);
    Json& baseline = root["baseline"];
    baseline["dist50_m"] = res.baselineDist50;
    baseline["runs"] = res.baseline.size();
    for (int p : {10, 25, 50, 75, 90}) baseline["runout_quantiles_m"]["p" + std::to_string(p)] = dem::quantile(baselineRunouts, p / 100.0);
    baseline["stop_reasons"] = stopReasonsJson(res.baseline);

    root["stands"] = Json::array();
    for (const auto& r : res.stands) {
        Json row;
        row["name"] = r.name;
        row["structure"] = structureCode(r.structure);
        row["pf50"] = r.pf50;
        row["pf50_ci"] = {r.pf50Ci.low, r.pf50Ci.high};
        row["dist50_m"] = r.dist50;
        summaryFields(row, r.inventory);
        row["realisations"] = r.runs.size();
        row["runs"] = runsPerRealisation(res.design, res.model);
        row["runs_pooled"] = pooled(r).size();
        row["rank_pf50"] = r.rankPf50;
        row["rank_basal_area"] = r.rankBasalArea;
        row["pf50_realisations"] = r.pf50PerRealisation;
        row["virtual_forests"] = Json::array();
        for (const auto& f : r.forests) {
            Json forest;
            forest["stems"] = f.stems;
            summaryFields(forest, f);
            row["virtual_forests"].push_back(forest);
        }
        row["stop_reasons"] = stopReasonsJson(pooled(r));
        root["stands"].push_back(row);
    }
    root["failed_runs"] = res.failedRuns;

    Json& rankings = root["rankings"];
    for (auto structure : assessedStructures()) {
        // Stand names from the least to the most protective, and from the smallest to the largest G.
        std::vector<const StructureAssessment*> rows;
        for (const auto& r : res.stands)
            if (r.structure == structure) rows.push_back(&r);
        Json& ranking = rankings[structureCode(structure)];
        for (const auto& [key, rankOf] : {std::pair<std::string, int StructureAssessment::*>{"by_pf50", &StructureAssessment::rankPf50},
                                          {"by_basal_area", &StructureAssessment::rankBasalArea}}) {
            auto sorted = rows;
            std::stable_sort(sorted.begin(), sorted.end(), [rankOf = rankOf](auto* a, auto* b) { return a->*rankOf < b->*rankOf; });
            ranking[key] = Json::array();
            for (auto* r : sorted) ranking[key].push_back(r->name);
        }
    }

    root["correlations"] = Json::array();
    for (const auto& c : res.correlations)
        root["correlations"].push_back({{"structure", structureCode(c.structure)},
                                        {"stands", c.stands},
                                        {"pearson_pf50_basal_area", c.basalArea},
                                        {"pearson_pf50_mean_dbh", c.meanDbh},
                                        {"pearson_pf50_stems_per_ha", c.stemsPerHa},
                                        {"p_pf50_basal_area", c.pBasalArea},
                                        {"p_pf50_mean_dbh", c.pMeanDbh},
                                        {"p_pf50_stems_per_ha", c.pStemsPerHa}});
    return root;
}

Json comparisonJson(const ModelComparison& c) {
    Json j;
    j["models"] = {dem::toString(c.first->model), dem::toString(c.second->model)};
    j["stands"] = Json::array();
    for (const auto& s : c.stands)
        j["stands"].push_back({{"name", s.name},
                               {"structure", structureCode(s.structure)},
                               {"pf50", {s.first->pf50, s.second->pf50}},
                               {"rank_pf50", {s.first->rankPf50, s.second->rankPf50}},
                               {"intervals_overlap", s.intervalsOverlap}});
    j["rank_agreement"] = Json::array();
    for (const auto& a : c.agreement)
        j["rank_agreement"].push_back({{"structure", structureCode(a.structure)},
                                       {"stands", a.stands},
                                       {"spearman", a.rankCorrelation},
                                       {"p", a.rankCorrelationP}});
    j["stands_na_above_a"] = {c.naAboveA[0], c.naAboveA[1]};
    j["stands_with_a_and_na"] = c.standsWithBoth;
    return j;
}

FigureSet writeModelReport(const std::string& reportDir, const AssessmentResults& results) {
    fs::create_directories(reportDir);
    writeTables(reportDir, results);
    const FigureSet figures = drawFigures(reportDir, results);
    writeMarkdown(reportDir + "/report.md", results, figures);
    return figures;
}

std::string pf50Cell(const StructureAssessment& r) {
    return fixed(r.pf50, 3) + " [" + fixed(r.pf50Ci.low, 3) + ", " + fixed(r.pf50Ci.high, 3) + "]";
}

void writeComparisonMarkdown(const std::string& path, const ModelComparison& c, const FigureSet& figures) {
    auto md = create(path);
    const AssessmentResults &a = *c.first, &b = *c.second;
    const std::string na = dem::toString(a.model), nb = dem::toString(b.model);
    const auto& d = a.design;
    md << "# Protection of the stands against rockfall: the two models side by side (sylvarock assess)\n\n"
       << "The paper's comparison (Toe et al., Sect. 3.2–3.3, Figs. 9–12): " << modelName(a.model) << " (`" << na << "`) and "
       << modelName(b.model) << " (`" << nb << "`, docs/lumped.md) through the same virtual forests (" << d.realisations
       << " per stand and structure) on scene `" << d.sceneFile << "`" << setsText(d.sceneOverrides) << ", seed " << d.seed << "; "
       << runsPerRealisation(d, a.model) << " and " << runsPerRealisation(d, b.model) << " runs per forest, "
       << baselineRuns(d, a.model) << " and " << baselineRuns(d, b.model) << " without forest. Each model's PF50 (Eqs. 26, 27) "
       << "is measured against its own run-out without forest. Each model's full report: [" << na << "/report.md](" << na
       << "/report.md), [" << nb << "/report.md](" << nb << "/report.md).\n\n"
       << "Without forest: Dist50 " << fixed(a.baselineDist50, 1) << " m (" << na << "), " << fixed(b.baselineDist50, 1) << " m ("
       << nb << ").\n\n"
       << "## PF50 per stand (Fig. 11)\n\n| stand | structure | PF50 " << na << " [" << confidencePercent(a.bootstrap.confidence)
       << " %] | PF50 " << nb << " | rank " << na << " | rank " << nb << " | intervals overlap |\n"
       << "| --- | --- | --- | --- | --- | --- | --- |\n";
    for (const auto& s : c.stands)
        md << "| " << s.name << " | " << structureCode(s.structure) << " | " << pf50Cell(*s.first) << " | " << pf50Cell(*s.second) << " | "
           << s.first->rankPf50 << " | " << s.second->rankPf50 << " | " << (s.intervalsOverlap ? "yes" : "**no**") << " |\n";
    md << "\nWhere the intervals do not overlap, this campaign tells the two models apart for that stand.\n\n"
       << "## Do the models order the stands alike?\n\nSpearman's rank correlation of the two models' PF50 over the stands "
          "(p two-sided, exact over all pairings of the ranks up to 9 stands; * p < 0.05):\n\n| structure | stands | Spearman | p |\n| --- | --- | --- | --- |\n";
    for (const auto& g : c.agreement)
        md << "| " << structureCode(g.structure) << " | " << g.stands << " | " << fixed(g.rankCorrelation, 3) << " | "
           << fixed(g.rankCorrelationP, 3) << (g.rankCorrelationP < 0.05 ? " *" : "") << " |\n";
    md << "\n## Aggregation (A against NA)\n\nStands whose random forests (NA) protect more than their aggregated ones (A): "
       << c.naAboveA[0] << " of " << c.standsWithBoth << " with " << na << ", " << c.naAboveA[1] << " of " << c.standsWithBoth
       << " with " << nb << " (the paper found NA more protective with both models).\n\n"
       << "## PF50 and dendrometry (Fig. 12)\n\nThe paper: with the DEM only G is significant; with RF3D G, N and Mean_D.\n\n### "
       << na << "\n\n";
    writeCorrelationTable(md, a.correlations);
    md << "\n### " << nb << "\n\n";
    writeCorrelationTable(md, b.correlations);
    md << "\n## Figures\n\n";
    const std::map<std::string, std::string> captions{
        {"runout_cdf_models.svg", "Cumulative run-out of both models with and without forest, A and NA (Figs. 9–10)"},
        {"pf50_models.svg", "PF50 per stand, both models, A and NA, with intervals (Fig. 11)"},
        {"pf50_dendrometry_models.svg", "PF50 of both models against G, Mean_D and N (Fig. 12)"}};
    for (const auto& f : figures.files) md << "![" << captions.at(f) << "](" << f << ")\n\n";
    if (!figures.warning.empty()) md << "Figures missing: " << figures.warning << "\n\n";
}

}  // namespace

void writeResultsJson(const std::string& path, const std::vector<AssessmentResults>& results) {
    if (results.empty()) throw std::invalid_argument("writeResultsJson: no results");
    Json root;
    root["design"] = designJson(results.front().design, results.front().bootstrap);
    root.update(modelJson(results.front()));
    for (std::size_t m = 1; m < results.size(); ++m) root[dem::toString(results[m].model)] = modelJson(results[m]);
    if (results.size() == 2) root["model_comparison"] = comparisonJson(compareModels(results[0], results[1]));
    auto out = create(path);
    out << root.dump(2) << '\n';
}

FigureSet writeReport(const std::string& reportDir, const std::vector<AssessmentResults>& results) {
    if (results.size() == 1) return writeModelReport(reportDir, results.front());
    if (results.size() != 2) throw std::invalid_argument("writeReport: one or two models");
    FigureSet all;
    for (const auto& r : results) {
        const FigureSet one = writeModelReport(reportDir + "/" + dem::toString(r.model), r);
        if (!one.warning.empty()) all.warning = one.warning;
    }
    const FigureSet figures = drawModelComparisonFigures(reportDir, results);
    writeComparisonMarkdown(reportDir + "/report.md", compareModels(results[0], results[1]), figures);
    all.files = figures.files;
    if (!figures.warning.empty()) all.warning = figures.warning;
    return all;
}

}  // namespace sylva::assess
