// Hazard maps on a DTM (libassess: GeoRaster, ReleaseArea, HazardMap, HazardRun): the rasters' values
// against hand-computed cases, the readers against good and bad inputs, and a small run end to end.
#include <gtest/gtest.h>

#include <ogrsf_frmts.h>
#include <sqlite3.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "GeoTestFolder.hpp"
#include "libassess/CheckLines.hpp"
#include "libassess/GeoRaster.hpp"
#include "libassess/HazardFigure.hpp"
#include "libassess/HazardMap.hpp"
#include "libassess/HazardRun.hpp"
#include "libassess/ReleaseArea.hpp"
#include "libassess/SoilMap.hpp"
#include "libassess/StandPolygons.hpp"
#include "libassess/TreePoints.hpp"
#include "libcommon/InputError.hpp"
#include "libstand/Allometry.hpp"
#include "libstand/Inventory.hpp"
#include "libstand/StandCatalogue.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;
namespace stand = sylva::stand;

namespace {

constexpr double kTip = 0.01;  // m, the stems' tip diameter of the default parameters

class Hazard : public GeoTestFolder {
protected:
    // An ESRI ASCII DTM: `cols` x `rows` cells of `cell` m, south-west corner (x0, y0), height z(col, row)
    // with row 0 the northernmost (as the file is written).
    template <class Z>
    std::string dtm(const std::string& name, int cols, int rows, double cell, double x0, double y0, Z z, bool prj = false) const {
        std::string text = "ncols " + std::to_string(cols) + "\nnrows " + std::to_string(rows) + "\nxllcorner " + std::to_string(x0) +
                           "\nyllcorner " + std::to_string(y0) + "\ncellsize " + std::to_string(cell) + "\nNODATA_value -9999\n";
        for (int r = 0; r < rows; ++r) {
            for (int c = 0; c < cols; ++c) text += std::to_string(z(c, r)) + " ";
            text += "\n";
        }
        if (prj) write(name.substr(0, name.size() - 4) + ".prj", kLambert93Prj);
        return write(name, text);
    }
    std::string polygon(const std::string& name, double x0, double y0, double x1, double y1, const std::string& crs = "") const {
        const auto p = [](double x, double y) { return "[" + std::to_string(x) + ", " + std::to_string(y) + "]"; };
        return write(name, "{\"type\": \"FeatureCollection\"," + crs + " \"features\": [{\"type\": \"Feature\", \"properties\": {}, "
                           "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[" + p(x0, y0) + ", " + p(x1, y0) + ", " + p(x1, y1) +
                           ", " + p(x0, y1) + ", " + p(x0, y0) + "]]}}]}");
    }
    // The small slope of the end-to-end tests: 60 x 20 cells of 5 m easing from ~34 to ~20 degrees, a
    // release of 8 cells near the top, 400 stems of 25 cm in a staggered grid 60-200 m down, the lumped
    // model (fast), 25 blocks a cell, with and without the trees.
    HazardOptions smallSlope() const {
        std::string trees = "x,y,dbh_cm\n";
        for (int i = 0; i < 400; ++i)
            trees += std::to_string(60 + 7 * (i % 20) + (i / 20 % 2) * 3.5) + "," + std::to_string(5 + 4.5 * (i / 20)) + ",25\n";
        HazardOptions o;
        o.dtmPath = dtm("slope.asc", 60, 20, 5.0, 0, 0, [](int c, int) { return 300.0 - 5 * c * std::tan(0.6 - 0.004 * c); });
        o.releasePath = polygon("release.geojson", 10, 40, 20, 60);
        o.treesPath = write("trees.csv", trees);
        o.model = sylva::dem::Model::Lumped;
        o.runsPerCell = 25;
        o.seed = 4;
        o.compareBare = true;
        return o;
    }
    // The example's slope and release (data/hazard/), the DEM, one block a cell.
    static HazardOptions exampleSlope() {
        HazardOptions o;
        o.dtmPath = std::string(SYLVAROCK_DATA) + "/hazard/slope.tif";
        o.releasePath = std::string(SYLVAROCK_DATA) + "/hazard/release.geojson";
        o.runsPerCell = 1;
        o.seed = 1;
        return o;
    }
    // On it, the whole example under one soil type: its table row `type` (the CSV's columns below).
    void oneSoilType(HazardOptions& o, const std::string& type) const {
        o.soilTypesPath = write("soil-types.csv", "name,code,damping_ratio,kn_n_m,friction_deg\n" + type + "\n");
        const std::string name = type.substr(0, type.find(','));
        o.soilMapPath = write("soils.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"soil": ")" + name + R"("},
        "geometry": {"type": "Polygon", "coordinates": [[[924000, 6459000], [926000, 6459000], [926000, 6461000], [924000, 6461000], [924000, 6459000]]]}}]})");
    }
    // The same slope without trees, one pass, blocks drawn from `volumes` (parseBlockVolumes).
    HazardOptions bareSlopeWithVolumes(int runsPerCell, const std::string& volumes, const std::string& out) const {
        HazardOptions o = smallSlope();
        o.treesPath.clear();
        o.compareBare = false;
        o.runsPerCell = runsPerCell;
        o.blockVolumes = parseBlockVolumes(volumes);
        o.outDir = (dir_ / out).string();
        return o;
    }
};

TEST_F(Hazard, DtmKeepsItsGridAndItsHeightsNorthUp) {
    // Height 10 * column + row (row 0 north): the simulator's grid counts rows from the south.
    const Dtm d = readDtm(dtm("d.asc", 4, 3, 2.0, 1000, 2000, [](int c, int r) { return 10.0 * c + r; }, true));
    EXPECT_EQ(d.grid.columns, 4);
    EXPECT_EQ(d.grid.rows, 3);
    EXPECT_DOUBLE_EQ(d.grid.geoTransform[0], 1000);
    EXPECT_DOUBLE_EQ(d.grid.geoTransform[3], 2006);  // the north edge
    EXPECT_DOUBLE_EQ(d.grid.cellSize(), 2);
    EXPECT_EQ(crsName(d.grid.crsWkt), "RGF93 v1 / Lambert-93");
    const Eigen::Vector2d northWest = d.grid.centre(0, 0), southEast = d.grid.centre(3, 2);
    EXPECT_DOUBLE_EQ(d.elevation.height(northWest.x(), northWest.y()), 0);
    EXPECT_DOUBLE_EQ(d.elevation.height(southEast.x(), southEast.y()), 32);
    int c = 0, r = 0;
    ASSERT_TRUE(d.grid.cellOf(1003.9, 2005.9, c, r));
    EXPECT_EQ(c, 1);
    EXPECT_EQ(r, 0);
    EXPECT_FALSE(d.grid.cellOf(999.9, 2003, c, r));
}

TEST_F(Hazard, DtmReadingErrorsNameTheFile) {
    EXPECT_NE(errorOf([&] { readDtm((dir_ / "none.tif").string()); }).find("none.tif: cannot read it as a raster"), std::string::npos);
    const std::string rect = write("rect.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ndx 2\ndy 3\nNODATA_value -9999\n1 2 3\n4 5 6\n");
    EXPECT_NE(errorOf([&] { readDtm(rect); }).find("square cells"), std::string::npos) << errorOf([&] { readDtm(rect); });
    initGdal();
    {  // rows running south to north: said so, not "cells of 5 x -5 m"
        GDALDatasetUniquePtr up(GetGDALDriverManager()->GetDriverByName("GTiff")->Create((dir_ / "southup.tif").c_str(), 3, 2, 1, GDT_Float32, nullptr));
        double gt[6] = {600000, 5, 0, 5100000, 0, 5};
        up->SetGeoTransform(gt);
    }
    EXPECT_NE(errorOf([&] { readDtm((dir_ / "southup.tif").string()); }).find("a south-up raster (its first row the southern one): warp it north-up first (gdalwarp -tr 5 5)"),
              std::string::npos)
        << errorOf([&] { readDtm((dir_ / "southup.tif").string()); });
    // A header announcing 10^10 cells (a sparse GeoTIFF: no data written) is refused before it is read.
    initGdal();
    {
        char** options = CSLSetNameValue(nullptr, "SPARSE_OK", "TRUE");
        GDALDatasetUniquePtr huge(GetGDALDriverManager()->GetDriverByName("GTiff")->Create((dir_ / "huge.tif").c_str(), 100000, 100000, 1,
                                                                                            GDT_Byte, options));
        CSLDestroy(options);
        ASSERT_TRUE(huge);
        double gt[6] = {0, 1, 0, 100000, 0, -1};
        huge->SetGeoTransform(gt);
    }
    EXPECT_NE(errorOf([&] { readDtm((dir_ / "huge.tif").string()); }).find("100000 x 100000 cells, more than"), std::string::npos)
        << errorOf([&] { readDtm((dir_ / "huge.tif").string()); });
    // An image of three bands (a coloured hillshade) was read as heights from its red band; heights
    // with an alpha band are one band of values.
    for (const bool alpha : {false, true}) {
        const std::string tif = (dir_ / (alpha ? "alpha.tif" : "rgb.tif")).string();
        {
            GDALDatasetUniquePtr image(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(tif.c_str(), 3, 2, alpha ? 2 : 3, GDT_Byte, nullptr));
            ASSERT_TRUE(image);
            double gt[6] = {600000, 5, 0, 5100010, 0, -5};
            image->SetGeoTransform(gt);
            if (alpha) image->GetRasterBand(2)->SetColorInterpretation(GCI_AlphaBand);
        }
        if (alpha) {
            EXPECT_NO_THROW(readDtm(tif));
        } else {
            EXPECT_NE(errorOf([&] { readDtm(tif); }).find("rgb.tif: the raster has 3 bands of values"), std::string::npos) << errorOf([&] { readDtm(tif); });
        }
    }
}

// GDAL's ESRI ASCII reader read a word it cannot parse as 0 m (a pit in the slope) and took one value
// too many on a line from the next row, shifting every cell after it; both are refused at their line.
TEST_F(Hazard, AMalformedAsciiGridIsRefusedAtItsLine) {
    const std::string header = "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 5\nNODATA_value -9999\n";
    const auto refusal = [&](const std::string& name, const std::string& rows) { return errorOf([&] { readDtm(write(name, header + rows)); }); };
    EXPECT_NE(refusal("typo.asc", "30 20 10\n31 2x 11\n32 22 12\n").find("typo.asc:8: value 2 of the line, '2x', is not a whole number"), std::string::npos)
        << refusal("typo.asc", "30 20 10\n31 2x 11\n32 22 12\n");
    EXPECT_NE(refusal("extra.asc", "30 20 10\n31 21 11 99\n32 22\n").find("extra.asc:8: row 2 has 4 values, ncols = 3"), std::string::npos)
        << refusal("extra.asc", "30 20 10\n31 21 11 99\n32 22\n");
    EXPECT_NE(refusal("long.asc", "30 20 10\n31 21 11\n32 22 12\n33\n").find("long.asc:10: 10 values for a grid of ncols x nrows = 3 x 3"),
              std::string::npos)
        << refusal("long.asc", "30 20 10\n31 21 11\n32 22 12\n33\n");
    // A grid of whole numbers GDAL reads as integers: 'nan' there was 0 m; in a grid of decimals, a word
    // GDAL reads part of (2..5 as 2); a first row starting with a letter was taken for the header.
    EXPECT_NE(refusal("nan.asc", "30 20 10\n31 nan 11\n32 22 12\n").find("nan.asc:8: value 2 of the line, 'nan', is not a whole number"),
              std::string::npos);
    EXPECT_NE(refusal("dots.asc", "30.5 20 10\n31 2..5 11\n32 22 12\n").find("dots.asc:8: value 2 of the line, '2..5', is not a number"),
              std::string::npos);
    EXPECT_NE(refusal("letter.asc", "x30 20 10\n31 21 11\n32 22 12\n").find("letter.asc:7: value 1 of the line, 'x30', is not"), std::string::npos)
        << refusal("letter.asc", "x30 20 10\n31 21 11\n32 22 12\n");
    // Rows wrapped over lines, a decimal comma and a NODATA cell are what GDAL reads as meant; so is a
    // stream wrapped at a fixed width that happens to have nrows lines.
    const GeoRaster wrapped = readRaster(write("wrapped.asc", header + "30 20 10 31\n21 11 32 22,5 -9999\n"), "heights");
    EXPECT_DOUBLE_EQ(wrapped.values[wrapped.grid.index(0, 0)], 30);  // row 0: the north one
    EXPECT_DOUBLE_EQ(wrapped.values[wrapped.grid.index(1, 2)], 22.5);
    EXPECT_TRUE(std::isnan(wrapped.values[wrapped.grid.index(2, 2)]));
    const GeoRaster fixedWidth = readRaster(write("width4.asc", header + "30 20 10 31\n21 11 32 22\n12\n"), "heights");
    EXPECT_DOUBLE_EQ(fixedWidth.values[fixedWidth.grid.index(2, 2)], 12);
}

// The simulator works in metres: a DTM in degrees is refused, and so are absurd cells.
TEST_F(Hazard, DtmOutsideMetresIsRefused) {
    const std::string asc = dtm("deg.asc", 3, 3, 0.0001, 5.7, 45.2, [](int, int) { return 1000.0; });
    write("deg.prj", R"(GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]])");
    EXPECT_NE(errorOf([&] { readDtm(asc); }).find("in degrees: project it"), std::string::npos) << errorOf([&] { readDtm(asc); });
    const std::string tiny = dtm("tiny.asc", 3, 3, 0.001, 0, 0, [](int, int) { return 1.0; });
    EXPECT_NE(errorOf([&] { readDtm(tiny); }).find("cells of 0.01 to 1000 m"), std::string::npos);
}

// A LiDAR DTM's compound CRS: heights in US feet were read as metres (relief 3.28 times too steep);
// heights in metres are placed by their horizontal CRS alone, which a release drawn in Lambert-93 shares.
TEST_F(Hazard, ACompoundCrsIsReadByItsParts) {
    initGdal();
    const auto tif = [&](const std::string& name, const char* crs) {
        const std::string path = (dir_ / name).string();
        GDALDatasetUniquePtr ds(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(path.c_str(), 4, 4, 1, GDT_Float32, nullptr));
        double gt[6] = {600000, 5, 0, 5100020, 0, -5};
        ds->SetGeoTransform(gt);
        OGRSpatialReference srs;
        srs.SetFromUserInput(crs);
        ds->SetSpatialRef(&srs);
        return path;
    };
    const std::string feet = tif("feet.tif", "EPSG:26911+6360");  // UTM 11N + NAVD88 height (ftUS)
    EXPECT_NE(errorOf([&] { readDtm(feet); }).find("feet.tif: the DTM's heights are in US survey foot"), std::string::npos)
        << errorOf([&] { readDtm(feet); });
    const Dtm metres = readDtm(tif("metres.tif", "EPSG:2154+5720"));  // Lambert-93 + NGF-IGN69 height
    EXPECT_TRUE(sameCrs(metres.grid.crsWkt, kLambert93Prj));
    EXPECT_FALSE(sameCrs(metres.grid.crsWkt, R"(GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]])"));
}

// A Float32 NODATA of -9999.9 is not the double -9999.9: the band's mask knows the cell has no height.
TEST_F(Hazard, Float32NoDataIsRecognised) {
    const Dtm d = readDtm(dtm("d.asc", 3, 2, 5.0, 0, 0, [](int c, int) { return 10.0 * c; }));
    const std::string tif = (dir_ / "f.tif").string();
    writeGeoTiff(tif, d.grid, {1, 2, 3, -9999.9f, 5, 6}, -9999.9, "test");
    const Dtm back = readDtm(tif);
    EXPECT_EQ(back.elevation.noDataCells(), 1);
}

// A DTM stored as integer centimetres with a band scale of 0.01 and an offset (GDAL's unscaled value:
// scale x stored + offset) is read in metres; it was read raw, 100 times too high, without a word.
TEST_F(Hazard, AScaledDtmIsReadInItsUnits) {
    initGdal();
    const std::string tif = (dir_ / "cm.tif").string();
    {
        GDALDatasetUniquePtr d(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(tif.c_str(), 3, 2, 1, GDT_Int32, nullptr));
        ASSERT_TRUE(d);
        double gt[6] = {600000, 5, 0, 5100010, 0, -5};
        d->SetGeoTransform(gt);
        GDALRasterBand* band = d->GetRasterBand(1);
        band->SetScale(0.01);
        band->SetOffset(1000);
        std::vector<GInt32> cm{0, 150, 300, 1000, 1150, 1300};
        ASSERT_EQ(band->RasterIO(GF_Write, 0, 0, 3, 2, cm.data(), 3, 2, GDT_Int32, 0, 0), CE_None);
    }
    const Dtm d = readDtm(tif);
    const auto at = [&](int c, int r) { const Eigen::Vector2d p = d.grid.centre(c, r); return d.elevation.height(p.x(), p.y()); };
    EXPECT_DOUBLE_EQ(at(0, 0), 1000);
    EXPECT_DOUBLE_EQ(at(2, 0), 1003);
    EXPECT_DOUBLE_EQ(at(1, 1), 1011.5);
}

TEST_F(Hazard, GeoTiffRoundTripKeepsValuesGridAndNoData) {
    const Dtm d = readDtm(dtm("d.asc", 3, 2, 5.0, 600000, 5100000, [](int c, int r) { return c + 10.0 * r; }, true));
    const std::string tif = (dir_ / "out.tif").string();
    writeGeoTiff(tif, d.grid, {0.5f, 1, 2, 3, -9999, 5}, -9999, "test");
    const Dtm back = readDtm(tif);
    EXPECT_EQ(back.grid.geoTransform, d.grid.geoTransform);
    EXPECT_TRUE(sameCrs(back.grid.crsWkt, d.grid.crsWkt));
    const auto at = [&](int c, int r) { const Eigen::Vector2d p = back.grid.centre(c, r); return back.elevation.height(p.x(), p.y()); };
    EXPECT_DOUBLE_EQ(at(0, 0), 0.5);
    EXPECT_DOUBLE_EQ(at(2, 1), 5);
    EXPECT_THROW(at(1, 1), sylva::InputError);  // NODATA read back as no value
}

TEST_F(Hazard, ReleaseCellsAreTheCellsWhoseCentreIsInside) {
    const Dtm d = readDtm(dtm("d.asc", 6, 4, 5.0, 0, 0, [](int c, int) { return 100.0 - 3 * c; }));
    // Cell centres at 2.5, 7.5, 12.5, ... m: x in [4, 16] holds columns 1 and 2 (7.5, 12.5), y in [6, 14]
    // the centres 12.5 and 7.5, rows 1 and 2 counted from the north (the grid's top is y = 20).
    bool beyond = true;
    const auto cells = readReleaseCells(polygon("r.geojson", 4, 6, 16, 14), d, &beyond);
    ASSERT_EQ(cells.size(), 4u);
    EXPECT_EQ(cells[0].column, 1);
    EXPECT_EQ(cells[0].row, 1);
    EXPECT_EQ(cells[3].column, 2);
    EXPECT_EQ(cells[3].row, 2);
    EXPECT_FALSE(beyond);
    // Past the east edge (x = 30): the cells on the DTM release, and the caller is told.
    EXPECT_EQ(readReleaseCells(polygon("east.geojson", 24, 6, 40, 14), d, &beyond).size(), 2u);
    EXPECT_TRUE(beyond);
}

// A release raster (Rockyfor3D's rockdensity.asc, say) on a coarser grid than the DTM: a DTM cell
// releases when its centre falls on a raster cell holding neither 0 nor NODATA.
TEST_F(Hazard, ReleaseRasterMarksTheCellsWhoseCentreFallsOnAValue) {
    const Dtm d = readDtm(dtm("d.asc", 6, 4, 5.0, 0, 0, [](int c, int) { return 100.0 - 3 * c; }));
    // 3 x 2 cells of 10 m, row 0 north: values 0 1 0 / -9999 0 2. The DTM's 5 m cell (c, r) lies in the
    // raster's cell (c / 2, r / 2): columns 2-3 of rows 0-1 (value 1) and columns 4-5 of rows 2-3 (value 2).
    const std::string raster = write("release.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n"
                                                    "0 1 0\n-9999 0 2\n");
    const auto cells = readReleaseCells(raster, d);
    ASSERT_EQ(cells.size(), 8u);
    for (const auto& c : cells) EXPECT_TRUE((c.row <= 1 && (c.column == 2 || c.column == 3)) || (c.row >= 2 && c.column >= 4)) << c.column << "," << c.row;
    const std::string zeros = write("zeros.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\n0 0 0\n0 0 0\n");
    EXPECT_NE(errorOf([&] { readReleaseCells(zeros, d); }).find("a raster of zeros"), std::string::npos);
    EXPECT_NE(errorOf([&] { readReleaseCells(write("junk.txt", "not a raster\n"), d); }).find("cannot read it as polygons or a raster"),
              std::string::npos);
    // An image of the release area (three colour bands) was read as marks from its red band.
    const std::string rgb = (dir_ / "release_rgb.tif").string();
    {
        GDALDatasetUniquePtr image(GetGDALDriverManager()->GetDriverByName("GTiff")->Create(rgb.c_str(), 3, 2, 3, GDT_Byte, nullptr));
        ASSERT_TRUE(image);
        double gt[6] = {0, 10, 0, 20, 0, -10};
        image->SetGeoTransform(gt);
        for (int b = 1; b <= 3; ++b) image->GetRasterBand(b)->Fill(255);
    }
    const std::string image = errorOf([&] { readReleaseCells(rgb, d); });
    EXPECT_NE(image.find("release_rgb.tif: the raster has 3 bands of values (an image? a coloured hillshade?): a release raster's marks "
                         "are one band"),
              std::string::npos) << image;
}

TEST_F(Hazard, ReleaseErrorsSayWhatIsWrong) {
    const Dtm d = readDtm(dtm("d.asc", 6, 4, 5.0, 700000, 6600000, [](int c, int) { return 100.0 - 3 * c; }, true));
    EXPECT_NE(errorOf([&] { readReleaseCells(polygon("far.geojson", 800000, 6700000, 800010, 6700010), d); }).find("covers no cell centre"), std::string::npos);
    EXPECT_NE(errorOf([&] { readReleaseCells(polygon("tiny.geojson", 700001, 6600001, 700002, 6600002), d); }).find("smaller than a cell"),
              std::string::npos);
    const std::string wgs = polygon("wgs.geojson", 3, 46, 3.1, 46.1);  // degrees: GeoJSON's own CRS, not the DTM's
    EXPECT_NE(errorOf([&] { readReleaseCells(wgs, d); }).find("reproject it"), std::string::npos) << errorOf([&] { readReleaseCells(wgs, d); });
    const std::string points = write("p.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
        "geometry": {"type": "Point", "coordinates": [700010, 6600010]}}]})");
    // The refusal says what the file holds: the trees' points given as the release, say.
    EXPECT_NE(errorOf([&] { readReleaseCells(points, d); }).find("no polygon in the file (it holds 1 Point feature)"), std::string::npos)
        << errorOf([&] { readReleaseCells(points, d); });
    // Empty, it was told to reproject (an empty GeoJSON layer reads as WGS 84).
    const std::string empty = write("e.geojson", R"({"type": "FeatureCollection", "features": []})");
    EXPECT_NE(errorOf([&] { readReleaseCells(empty, d); }).find("no polygon in the file (it holds no feature with a geometry)"), std::string::npos)
        << errorOf([&] { readReleaseCells(empty, d); });
    // Polygons inside a geometry collection are not a polygon layer: the refusal says how to split it.
    const std::string collection = write("gc.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
        "geometry": {"type": "GeometryCollection", "geometries": [{"type": "Polygon", "coordinates": [[[700002, 6600002], [700028, 6600002],
        [700028, 6600018], [700002, 6600018], [700002, 6600002]]]}, {"type": "Point", "coordinates": [700010, 6600010]}]}},
        {"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [700010, 6600010]}}]})");
    const std::string parts = errorOf([&] { readReleaseCells(collection, d); });
    EXPECT_NE(parts.find("(it holds 1 Geometry Collection and 1 Point features; a geometry collection's parts become features of their "
                         "own with ogr2ogr -explodecollections)"),
              std::string::npos) << parts;
    // A bow tie (its ring crosses itself) has no defined inside: GEOS's Contains said no for every
    // cell and the error blamed the polygon's size or place.
    const std::string bowTie = write("bowtie.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
        "geometry": {"type": "Polygon", "coordinates": [[[700002, 6600002], [700028, 6600018], [700028, 6600002], [700002, 6600018], [700002, 6600002]]]}}]})");
    const std::string crossed = errorOf([&] { readReleaseCells(bowTie, d); });
    EXPECT_NE(crossed.find("layer 'bowtie', feature 1: the polygon is not valid"), std::string::npos) << crossed;
    EXPECT_NE(crossed.find("ogr2ogr -makevalid"), std::string::npos) << crossed;
    const Dtm holed = readDtm(dtm("h.asc", 6, 4, 5.0, 0, 0, [](int c, int r) { return c == 1 && r == 1 ? -9999.0 : 100.0 - 3 * c; }));
    EXPECT_NE(errorOf([&] { readReleaseCells(polygon("r.geojson", 4, 6, 16, 14), holed); }).find("NODATA hole"), std::string::npos);
}

TEST_F(Hazard, TreesFromAPointLayerGetTheirAllometryAndBadOnesAreRefused) {
    const Dtm d = readDtm(dtm("d.asc", 6, 4, 5.0, 0, 0, [](int c, int) { return 100.0 - 3 * c; }));
    const auto points = [&](const std::string& name, const std::string& properties) {
        return write(name, R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": )" + properties +
                               R"(, "geometry": {"type": "Point", "coordinates": [12.5, 7.5]}}]})");
    };
    const stand::Forest f = readTreePoints(points("t.geojson", R"({"dbh_cm": 20})"), d);
    ASSERT_EQ(f.trees.size(), 1u);
    EXPECT_DOUBLE_EQ(f.trees[0].x, 12.5);
    EXPECT_DOUBLE_EQ(f.trees[0].dbhCm, 20);
    EXPECT_DOUBLE_EQ(f.trees[0].heightM, sylva::stand::treeHeightM(20));  // Eq. 11
    EXPECT_NE(errorOf([&] { readTreePoints(points("n.geojson", R"({"dbh": 20})"), d); }).find("has points but no field dbh_cm"), std::string::npos);
    EXPECT_NE(errorOf([&] { readTreePoints(points("z.geojson", R"({"dbh_cm": 0})"), d); }).find("feature 1: dbh_cm 0 is not a DBH in (0, 200] cm"),
              std::string::npos);
    // A text that is no number was shown as the 0 GDAL reads it as.
    const std::string word = errorOf([&] { readTreePoints(points("w.geojson", R"({"dbh_cm": "abc"})"), d); });
    EXPECT_NE(word.find("feature 1: dbh_cm 'abc' is not a DBH"), std::string::npos) << word;
    const std::string csv = write("t.csv", "x,y,dbh_cm\n12.5,7.5,31\n");
    EXPECT_DOUBLE_EQ(readTreePoints(csv, d).trees.at(0).dbhCm, 31);
    // Polygons (crowns, or the stands' file) are not trees: the refusal says what the file holds.
    const std::string crowns = write("crowns.geojson", R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {"dbh_cm": 20},
        "geometry": {"type": "Polygon", "coordinates": [[[2, 2], [8, 2], [8, 8], [2, 8], [2, 2]]]}}]})");
    EXPECT_NE(errorOf([&] { readTreePoints(crowns, d); }).find("no point in the file (it holds 1 Polygon feature)"), std::string::npos)
        << errorOf([&] { readTreePoints(crowns, d); });
    // A header alone made a bare map without a word.
    EXPECT_NE(errorOf([&] { readTreePoints(write("h.csv", "x,y,dbh_cm\n"), d); }).find("no tree in the file"), std::string::npos);
}

// Two blocks by hand: passing counts, the probability, deposits, and the 95th percentile with
// GSL's linear interpolation (10 and 20 kJ: 10 + 0.95 x 10 = 19.5).
TEST_F(Hazard, MapCountsPassagesDepositsAndPercentiles) {
    RasterGrid g;
    g.columns = 3;
    g.rows = 1;
    g.geoTransform = {0, 1, 0, 1, 0, -1};
    HazardMap map(g);
    BlockTrace a, b;
    a.passages = {{0, 10, 1}, {1, 8, 0.5}};
    a.depositCell = 1;
    b.passages = {{0, 20, 3}, {1, 12, 0.4}, {2, 4, 0.2}};
    b.depositCell = 2;
    b.impactCells = {1, 1};
    map.add(a);
    map.add(b);
    EXPECT_EQ(map.passingCount(), (std::vector<float>{2, 2, 1}));
    EXPECT_EQ(map.reachProbability(), (std::vector<float>{1, 1, 0.5}));
    EXPECT_EQ(map.deposits(), (std::vector<float>{0, 1, 1}));
    EXPECT_EQ(map.treeImpacts(), (std::vector<float>{0, 2, 0}));
    EXPECT_FLOAT_EQ(map.energyP95Kj(-1)[0], 19.5f);
    EXPECT_FLOAT_EQ(map.heightP95M(-1)[0], 1 + 0.95f * 2);
    EXPECT_FLOAT_EQ(map.energyP95Kj(-1)[2], 4);
    HazardMap empty(g);
    EXPECT_EQ(empty.energyP95Kj(-1), (std::vector<float>{-1, -1, -1}));
}

// A block moving 12 m east over flat ground at z = 0, 1 m up, its energy falling from 30 to 18 kJ:
// it crosses cells 0, 1 and 2 of a 5 m grid; in each the largest energy is where it entered.
TEST_F(Hazard, TraceWalksThePathBetweenSamples) {
    const Dtm d = readDtm(dtm("flat.asc", 4, 1 + 1, 5.0, 0, 0, [](int, int) { return 0.0; }));
    sylva::dem::RunResult run;
    run.release = {1, 7.5, 1};
    run.stop = {13, 7.5, 1};
    run.reason = sylva::dem::StopReason::Rest;
    run.runoutAlongSlope = run.runoutHorizontal = 12;
    const Eigen::Vector3d still = Eigen::Vector3d::Zero();
    run.trajectory = {{0, {1, 7.5, 1}, still, still, 30000, 0}, {1, {13, 7.5, 1}, still, still, 18000, 0}};
    const BlockTrace t = traceRun(run, d, {});
    ASSERT_EQ(t.passages.size(), 3u);
    EXPECT_EQ(t.passages[0].cell, d.grid.index(0, 0));
    EXPECT_EQ(t.passages[2].cell, d.grid.index(2, 0));
    EXPECT_FLOAT_EQ(t.passages[0].energyKj, 30);
    EXPECT_NEAR(t.passages[1].energyKj, 30 - 12 * (5.0 - 1) / 12, 12 * 1.25 / 12);  // entered within a quarter cell of x = 5
    EXPECT_FLOAT_EQ(t.passages[1].heightM, 1);
    EXPECT_EQ(t.depositCell, static_cast<long>(d.grid.index(2, 0)));
    EXPECT_DOUBLE_EQ(t.pathLengthM, 12);
    EXPECT_DOUBLE_EQ(t.reachM, 12);
}

// A small slope end to end with the lumped model (fast): rasters on the DTM's grid, probabilities in
// [0, 1], every block counted in its release cell, deposits adding up to the blocks at rest, a
// forest that shortens the reach, and the same rasters on 1 and 2 threads.
TEST_F(Hazard, SmallSlopeEndToEnd) {
    HazardOptions o = smallSlope();
    const std::string slope = o.dtmPath;
    o.threads = 1;
    o.outDir = (dir_ / "one").string();
    const HazardResults one = runHazard(o);
    o.threads = 2;
    o.outDir = (dir_ / "two").string();
    runHazard(o);
    EXPECT_EQ(one.releaseCells, 8);
    // The map for people, as SVG and PNG (gnuplot-nox is installed by scripts/install-deps.sh).
    EXPECT_EQ(one.figureWarning, "");
    std::ifstream png(dir_ / "one/map.png", std::ios::binary);
    std::string magic(4, '\0');
    png.read(magic.data(), 4);
    EXPECT_EQ(magic, "\x89PNG");
    EXPECT_GT(fs::file_size(dir_ / "one/map.svg"), 1000u);
    EXPECT_GT(fs::file_size(dir_ / "one/rasters.png"), 1000u);
    for (const char* f : {"map.svg", "map.png", "rasters.png"})  // summary.json's other_files
        EXPECT_NE(std::find(one.files.begin(), one.files.end(), f), one.files.end()) << f;
    ASSERT_EQ(one.passes.size(), 2u);
    EXPECT_EQ(one.passes[0].blocks, 200);
    EXPECT_GT(one.passes[0].treeImpacts, 0);
    EXPECT_LT(one.passes[0].reachP50, one.passes[1].reachP50);  // the forest holds blocks back
    const Dtm grid = readDtm(slope);
    for (const char* name : {"reach_probability.tif", "passing_count.tif", "deposits.tif", "energy_p95_kj.tif", "height_p95_m.tif",
                             "tree_impacts.tif", "protection.tif", "bare/reach_probability.tif"}) {
        const Dtm a = readDtm((dir_ / "one" / name).string()), b = readDtm((dir_ / "two" / name).string());
        EXPECT_EQ(a.grid.geoTransform, grid.grid.geoTransform) << name;
        for (int r = 0; r < a.grid.rows; ++r)
            for (int c = 0; c < a.grid.columns; ++c) {
                const Eigen::Vector2d p = a.grid.centre(c, r);
                double va = std::nan(""), vb = std::nan("");
                try { va = a.elevation.height(p.x(), p.y()); } catch (const sylva::InputError&) {}
                try { vb = b.elevation.height(p.x(), p.y()); } catch (const sylva::InputError&) {}
                ASSERT_TRUE(va == vb || (std::isnan(va) && std::isnan(vb))) << name << " cell " << c << "," << r;
            }
    }
    const Dtm reach = readDtm((dir_ / "one/reach_probability.tif").string()), deposits = readDtm((dir_ / "one/deposits.tif").string());
    double depositSum = 0;
    for (int r = 0; r < reach.grid.rows; ++r)
        for (int c = 0; c < reach.grid.columns; ++c) {
            const Eigen::Vector2d p = reach.grid.centre(c, r);
            const double v = reach.elevation.height(p.x(), p.y());
            EXPECT_GE(v, 0);
            EXPECT_LE(v, 1);
            depositSum += deposits.elevation.height(p.x(), p.y());
        }
    EXPECT_DOUBLE_EQ(depositSum, static_cast<double>(one.passes[0].rest));
    // Each release cell sends 25 of the 200 blocks: at least that share passed through it.
    const Eigen::Vector2d releaseCell = reach.grid.centre(2, 8);
    EXPECT_GE(reach.elevation.height(releaseCell.x(), releaseCell.y()), 25.0 / 200 - 1e-6);
    EXPECT_NE(errorOf([&] { o.outDir = (dir_ / "one").string(); runHazard(o); }).find("not an empty folder"), std::string::npos);

    // Release cells on the DTM's edge: points drawn in their outer half are moved onto the terrain.
    o.releasePath = polygon("edge.geojson", 0, 0, 10, 100);
    o.treesPath.clear();
    o.compareBare = false;
    o.runsPerCell = 10;
    o.outDir = (dir_ / "edge").string();
    const HazardResults edge = runHazard(o);
    EXPECT_EQ(edge.passes.at(0).blocks, 2 * 20 * 10);
    EXPECT_EQ(edge.passes.at(0).failed, 0);

    // A DTM with a hole is refused before anything is written.
    o.dtmPath = dtm("holed.asc", 60, 20, 5.0, 0, 0, [](int c, int r) { return c == 50 && r == 3 ? -9999.0 : 300.0 - 5 * c; });
    o.outDir = (dir_ / "holed").string();
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("the DTM has 1 NODATA cell(s)"), std::string::npos);
    EXPECT_FALSE(fs::exists(dir_ / "holed"));
}

// A line's name is the user's: a line break in it (a GIS lets one through) once ended a gnuplot
// command midway, and no figure came.
TEST_F(Hazard, ACheckLineNameWithALineBreakIsDrawn) {
    if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot not installed";
    CheckLineTally::LineSample sample;
    sample.pass = "forest";
    sample.line = "road\nbelow";
    sample.blocks = 3;
    sample.energyKj = {10, 20, 30};
    sample.heightM = {0.5, 1, 2};
    const FigureSet f = drawCheckLines((dir_ / "lines").string(), {sample});
    EXPECT_EQ(f.warning, "");
    EXPECT_NE(std::find(f.files.begin(), f.files.end(), "check_lines.png"), f.files.end());
}

// The outputs beside the rasters, on the small slope: a check line just below the release that every
// block crosses and one far down that fewer cross (the forest's blocks fewer than the bare ones), each
// block's path and tree impacts in the GeoPackage (as many paths as blocks, as many impacts as the
// summary counts), the VTK files; all of it the same on 1 and 2 threads.
TEST_F(Hazard, CheckLinesTrajectoriesAndVtkFollowTheBlocks) {
    const std::string lines = write("lines.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "near"}, "geometry": {"type": "LineString", "coordinates": [[25, 0], [25, 100]]}},
        {"type": "Feature", "properties": {"name": "far"}, "geometry": {"type": "LineString", "coordinates": [[150, 0], [150, 100]]}}]})");
    HazardOptions o = smallSlope();
    o.checkLinesPath = lines;
    o.writeTrajectories = true;
    o.writeVtk = true;
    o.threads = 1;
    o.outDir = (dir_ / "one").string();
    const HazardResults one = runHazard(o);
    o.threads = 2;
    o.outDir = (dir_ / "two").string();
    runHazard(o);
    const auto read = [](const fs::path& p) {
        std::ifstream in(p);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    for (const char* f : {"check_lines.csv", "check_lines_summary.csv", "vtk/paths_forest.vtk", "vtk/paths_bare.vtk", "vtk/terrain.vtk", "vtk/trees.vtk"})
        EXPECT_EQ(read(dir_ / "one" / f), read(dir_ / "two" / f)) << f;
    // pass,line,blocks,crossings,fraction,...
    std::istringstream summary(read(dir_ / "one/check_lines_summary.csv"));
    std::string header, row;
    std::getline(summary, header);
    std::map<std::string, long> crossings;
    while (std::getline(summary, row)) {
        std::stringstream cells(row);
        std::string pass, line, blocks, crossed;
        std::getline(cells, pass, ',');
        std::getline(cells, line, ',');
        std::getline(cells, blocks, ',');
        std::getline(cells, crossed, ',');
        EXPECT_EQ(blocks, "200");
        crossings[pass + " " + line] = std::stol(crossed);
    }
    // ... and drawn as exceedance curves (gnuplot-nox is installed by scripts/install-deps.sh).
    EXPECT_EQ(one.figureWarning, "");
    EXPECT_NE(std::find(one.files.begin(), one.files.end(), "check_lines.png"), one.files.end());
    EXPECT_GT(fs::file_size(dir_ / "one/check_lines.svg"), 1000u);
    EXPECT_EQ(crossings.at("forest near"), 200);
    EXPECT_EQ(crossings.at("bare near"), 200);
    EXPECT_LT(crossings.at("forest far"), crossings.at("bare far"));
    GDALDatasetUniquePtr gpkg(GDALDataset::Open((dir_ / "one/trajectories.gpkg").c_str(), GDAL_OF_VECTOR));
    ASSERT_TRUE(gpkg);
    EXPECT_EQ(gpkg->GetLayerCount(), 4);
    EXPECT_EQ(gpkg->GetLayerByName("paths_forest")->GetFeatureCount(), 200);
    EXPECT_EQ(gpkg->GetLayerByName("paths_bare")->GetFeatureCount(), 200);
    EXPECT_EQ(gpkg->GetLayerByName("impacts_forest")->GetFeatureCount(), one.passes.at(0).treeImpacts);
    EXPECT_EQ(gpkg->GetLayerByName("impacts_bare")->GetFeatureCount(), 0);
}

// An interrupted map (here: runs cut out of its store, as a kill between two batches leaves it)
// resumes with only the runs it lacks and ends with every output of the uninterrupted map.
// One writer per folder, as for assess: a resume started while the map is being made (its first run
// done) is refused instead of running the same runs and writing the same rasters beside it.
TEST_F(Hazard, AFolderBeingWrittenIsRefusedToASecondWriter) {
    HazardOptions o = smallSlope();
    o.compareBare = false;
    o.outDir = (dir_ / "busy").string();
    std::atomic<bool> tried{false};
    std::string second;
    o.onRunDone = [&](const std::string&, int, int) {
        if (tried.exchange(true)) return;
        HazardOptions resume = o;
        resume.onRunDone = nullptr;
        resume.resume = true;
        second = errorOf([&] { runHazard(resume); });
    };
    runHazard(o);
    EXPECT_NE(second.find("is being written by another sylvarock hazard"), std::string::npos) << second;
}

TEST_F(Hazard, ResumedMapRunsWhatItLacksAndEqualsTheWholeMap) {
    HazardOptions o = smallSlope();
    o.checkLinesPath = write("lines.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"name": "far"}, "geometry": {"type": "LineString", "coordinates": [[150, 0], [150, 100]]}}]})");
    o.writeTrajectories = true;
    o.blockVolumes = parseBlockVolumes("0.5:2,2:1");
    o.outDir = (dir_ / "whole").string();
    runHazard(o);
    o.outDir = (dir_ / "cut").string();
    runHazard(o);
    {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open((dir_ / "cut/hazard.sqlite").c_str(), &db), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(db, "DELETE FROM runs WHERE run % 3 = 0 OR (pass = 'bare' AND run > 150)", nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(db);
    }
    long reRun = 0;
    o.onRunDone = [&](const std::string&, int, int) { ++reRun; };
    o.resume = true;
    runHazard(o);
    EXPECT_EQ(reRun, 67 + 67 + 49 - 16);  // runs 0, 3, ..., 198 of each pass, and bare runs 151-199 but the 16 multiples of 3 among them
    const auto read = [](const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    for (const char* f : {"summary.json", "check_lines.csv", "check_lines_summary.csv", "reach_probability.tif", "energy_p95_kj.tif",
                          "deposits.tif", "bare/reach_probability.tif", "protection.tif"})
        EXPECT_EQ(read(dir_ / "whole" / f), read(dir_ / "cut" / f)) << f;
    GDALDatasetUniquePtr gpkg(GDALDataset::Open((dir_ / "cut/trajectories.gpkg").c_str(), GDAL_OF_VECTOR));
    ASSERT_TRUE(gpkg);
    EXPECT_EQ(gpkg->GetLayerByName("paths_forest")->GetFeatureCount(), 200);

    // Another input is refused, naming it, and leaves the map as it was; so is a folder without a store.
    o.seed = 5;
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("started with 'seed 4', this command gives 'seed 5'"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir_ / "cut/trajectories.gpkg")) << "a refused resume deleted the map's paths";
    o.seed = 4;
    // The same stems with heights of their own (the trees file may give them) are another forest.
    const std::string sameStems = o.treesPath;
    std::ifstream in(sameStems);
    std::string line, tall;
    std::getline(in, line);
    tall = line + ",height_m\n";
    while (std::getline(in, line)) tall += line + ",30\n";
    o.treesPath = write("tall.csv", tall);
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("--resume with other inputs: the map was started with 'forest 400 stems"), std::string::npos)
        << errorOf([&] { runHazard(o); });
    o.treesPath = sameStems;
    // A file GDAL reads beside the one named is part of the input: here an .aux.xml that lifts the
    // DTM by 100 m (GDAL applies a band's offset, GeoRaster with it).
    const std::string aux = o.dtmPath + ".aux.xml";
    std::ofstream(aux) << "<PAMDataset><PAMRasterBand band=\"1\"><Offset>100</Offset><Scale>1</Scale></PAMRasterBand></PAMDataset>\n";
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("the map was started with 'dtm "), std::string::npos) << errorOf([&] { runHazard(o); });
    // Statistics there (gdalinfo -stats and QGIS write them) change no height: the map resumes.
    std::ofstream(aux) << "<PAMDataset><PAMRasterBand band=\"1\"><Metadata><MDI key=\"STATISTICS_MAXIMUM\">300</MDI>"
                          "<MDI key=\"STATISTICS_MINIMUM\">0</MDI></Metadata></PAMRasterBand></PAMDataset>\n";
    reRun = 0;
    EXPECT_NO_THROW(runHazard(o));
    EXPECT_EQ(reRun, 0);
    fs::remove(aux);
    o.outDir = (dir_ / "nothing").string();
    fs::create_directories(o.outDir);
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("holds no map to resume"), std::string::npos);
    // A file given as --out is named as one, resumed or not (it was "holds no map to resume").
    o.outDir = (dir_ / "a-file").string();
    std::ofstream(o.outDir) << "x\n";
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("is a file, not a folder"), std::string::npos) << errorOf([&] { runHazard(o); });
    o.resume = false;
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("is a file, not a folder"), std::string::npos) << errorOf([&] { runHazard(o); });
}

TEST_F(Hazard, BlockVolumesAreAListOfVolumesWithOptionalWeights) {
    const auto equal = parseBlockVolumes("0.5,1,2");
    ASSERT_EQ(equal.size(), 3u);
    EXPECT_DOUBLE_EQ(equal[2].volumeM3, 2);
    EXPECT_DOUBLE_EQ(equal[2].weight, 1);
    const auto weighted = parseBlockVolumes("0.2:6,5:1");
    EXPECT_DOUBLE_EQ(weighted[0].weight, 6);
    EXPECT_DOUBLE_EQ(weighted[1].volumeM3, 5);
    EXPECT_NE(errorOf([] { parseBlockVolumes("0.5,0"); }).find("a volume of 0 m3 is not in (0, 1000]"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes("2000"); }).find("not in (0, 1000]"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes("1:-2"); }).find("a weight of -2 is not positive"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes("1m3"); }).find("volume '1m3' is not a number"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes(""); }).find("empty list"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes("0.2:1e308,1:1e308"); }).find("the weights' sum overflows"), std::string::npos);
    // A decimal comma ("2,5:1" for 2.5 m3 of weight 1) ran as two classes, 2 and 5 m3: weights on some
    // classes only are refused; so are a trailing comma ("1," ran as "1") and a volume listed twice.
    EXPECT_NE(errorOf([] { parseBlockVolumes("2,5:1"); }).find("1 of the 2 classes have a weight: give every class one"), std::string::npos)
        << errorOf([] { parseBlockVolumes("2,5:1"); });
    EXPECT_NE(errorOf([] { parseBlockVolumes("1,"); }).find("an empty item after the last comma"), std::string::npos);
    EXPECT_NE(errorOf([] { parseBlockVolumes("0.5,0.5"); }).find("the volume 0.5 m3 is listed twice"), std::string::npos);
}

// Each block draws its volume class from its own stream: the classes' shares follow the weights
// (400 blocks at 3:1, a binomial share of 0.75 with a standard deviation of 0.022: +-0.08 is 3.7 sd),
// and the blocks of each class are counted in the summary.
TEST_F(Hazard, BlocksDrawTheirVolumeFromTheDistribution) {
    const HazardResults r = runHazard(bareSlopeWithVolumes(50, "0.2:3,4:1", "out"));
    const HazardPass& p = r.passes.at(0);
    ASSERT_EQ(p.blocksPerVolume.size(), 2u);
    EXPECT_EQ(p.blocksPerVolume[0] + p.blocksPerVolume[1], p.blocks);
    EXPECT_EQ(p.blocks, 400);
    EXPECT_NEAR(p.blocksPerVolume[0] / 400.0, 0.75, 0.08);
    std::ifstream summary(dir_ / "out/summary.json");
    const std::string text((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"block_volumes\""), std::string::npos);
    EXPECT_NE(text.find("\"volume_m3\": 4"), std::string::npos);
}

// The blocks start in the release cells: a release point set in the scene does nothing, and says so
// (the probe's release.x_m=30 changed no map and no word was said).
TEST_F(Hazard, AReleasePointInTheSceneIsSaidToBeReplaced) {
    const auto notesOf = [&](std::vector<std::string> overrides, const std::string& out) {
        HazardOptions o = bareSlopeWithVolumes(1, "1", out);
        o.sceneOverrides = std::move(overrides);
        std::vector<std::string> notes;
        o.onNote = [&notes](const std::string& n) { notes.push_back(n); };
        runHazard(o);
        return std::count_if(notes.begin(), notes.end(), [](const std::string& n) { return n.find("release point") != std::string::npos; });
    };
    EXPECT_EQ(notesOf({"release.x_m=30"}, "x"), 1);
    EXPECT_EQ(notesOf({"release.y_min_m=5", "release.y_max_m=9"}, "range"), 1);
    EXPECT_EQ(notesOf({}, "none"), 0);
}

// A lumped block larger than its fall height starts inside the ground at every release: its class's runs
// were each left out (a note apiece, exit 3) and the map drawn from the small blocks alone. Refused once,
// before the output folder is made.
TEST_F(Hazard, ALumpedBlockLargerThanItsFallHeightIsRefusedUpFront) {
    const HazardOptions o = bareSlopeWithVolumes(1, "1:9,600:1", "too_big");
    const std::string why = errorOf([&] { runHazard(o); });
    EXPECT_NE(why.find("the lumped model's block, a sphere of 5.23 m radius (its volume), would start inside the ground at every release: "
                       "release.fall_height_m (5 m) must exceed it"),
              std::string::npos) << why;
    EXPECT_FALSE(std::filesystem::exists(o.outDir));
}

// A layer naming no CRS (an ESRI ASCII release grid without its .prj, a Shapefile without its .prj)
// beside a DTM that names one is taken in the DTM's CRS, unchecked: said, as it is of a DTM without one.
TEST_F(Hazard, ALayerWithoutACrsBesideADtmWithOneIsSaidToBeUnchecked) {
    HazardOptions o = bareSlopeWithVolumes(1, "1", "crs");
    o.dtmPath = dtm("slope_l93.asc", 60, 20, 5.0, 0, 0, [](int c, int) { return 300.0 - 5 * c * std::tan(0.6 - 0.004 * c); }, true);
    const auto notesOn = [&](bool prj, const std::string& out) {
        const std::string grid = "ncols 6\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 25\n0 0 0 0 0 0\n0 0 0 0 0 0\n0 1 0 0 0 0\n0 0 0 0 0 0\n";
        const std::string name = prj ? "release_l93" : "release_bare";
        o.releasePath = write(name + ".asc", grid);
        if (prj) write(name + ".prj", kLambert93Prj);
        o.outDir = (dir_ / out).string();
        std::vector<std::string> notes;
        o.onNote = [&notes](const std::string& n) { notes.push_back(n); };
        runHazard(o);
        return std::count_if(notes.begin(), notes.end(), [&](const std::string& n) {
            return n.find(o.releasePath + " names no CRS: taken in the DTM's (RGF93 v1 / Lambert-93), unchecked") != std::string::npos;
        });
    };
    EXPECT_EQ(notesOn(false, "crs_none"), 1);
    EXPECT_EQ(notesOn(true, "crs_l93"), 0);
}

// A resumed map records the build that made its runs; a resume by another build says so (the runs it
// keeps may not be the runs this build makes), and by the same build says nothing.
TEST_F(Hazard, AResumeByAnotherBuildIsSaid) {
    HazardOptions o = bareSlopeWithVolumes(1, "1", "built");
    runHazard(o);
    const auto notesOfResume = [&] {
        std::vector<std::string> notes;
        HazardOptions again = o;
        again.resume = true;
        again.onNote = [&notes](const std::string& n) { notes.push_back(n); };
        runHazard(again);
        return std::count_if(notes.begin(), notes.end(), [](const std::string& n) {
            return n.find("its runs were made by sylvarock build 0123abcd, this is sylvarock build") != std::string::npos;
        });
    };
    EXPECT_EQ(notesOfResume(), 0);
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open((dir_ / "built/hazard.sqlite").c_str(), &db), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(db, "UPDATE inputs SET text = '# made by sylvarock build 0123abcd' WHERE text LIKE '# made by %'", nullptr,
                           nullptr, nullptr),
              SQLITE_OK);
    EXPECT_EQ(sqlite3_changes(db), 1);
    sqlite3_close(db);
    EXPECT_EQ(notesOfResume(), 1);
}

// One volume is a distribution too (it once indexed an empty count), and a pass in which no block
// could start writes no map: an all-zero one would read as ground no block reaches.
TEST_F(Hazard, OneBlockVolumeIsCountedAndAPassWithoutBlocksWritesNoMap) {
    HazardOptions o = bareSlopeWithVolumes(2, "2", "one");
    const HazardPass p = runHazard(o).passes.at(0);
    ASSERT_EQ(p.blocksPerVolume.size(), 1u);
    EXPECT_EQ(p.blocksPerVolume[0], p.blocks);
    EXPECT_GT(p.blocks, 0);

    o.blockVolumes.clear();
    o.model = sylva::dem::Model::Dem;
    o.runsPerCell = 1;
    o.sceneOverrides = {"release.fall_height_m=0.1"};  // every block starts inside the soil
    o.outDir = (dir_ / "none").string();
    std::string message = "(no error)";
    try {
        runHazard(o);
    } catch (const std::exception& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("failed (the notes above say why): no map is written"), std::string::npos) << message;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "none/reach_probability.tif"));
}

// The soil types' table: parameters not given are the scene's, a restitution becomes its damping
// ratio (Eq. 15), and each bad row is named by its line and column.
TEST_F(Hazard, SoilTypesTableFillsFromTheSceneAndNamesItsErrors) {
    sylva::dem::SoilContactParams scene;
    const auto types = readSoilTypes(write("soils.csv", "name,code,kn_n_m,restitution,friction_deg\nscree,1,,0.5,35\nmeadow,2,2e5,,\n"), scene);
    ASSERT_EQ(types.size(), 2u);
    EXPECT_EQ(types[0].params.kn, scene.kn);
    EXPECT_NEAR(types[0].params.dampingRatio, sylva::dem::dampingRatioFromRestitution(0.5), 1e-15);
    EXPECT_NEAR(sylva::dem::restitutionFromDampingRatio(types[0].params.dampingRatio), 0.5, 1e-12);
    EXPECT_EQ(types[0].params.frictionDeg, 35);
    EXPECT_EQ(types[1].params.kn, 2e5);
    EXPECT_EQ(types[1].params.dampingRatio, scene.dampingRatio);
    EXPECT_EQ(types[1].code, 2);
    const auto error = [&](const std::string& text) { return errorOf([&] { readSoilTypes(write("bad.csv", text), scene); }); };
    EXPECT_NE(error("name,code,friction_deg\nscree,1,95\n").find("bad.csv:2"), std::string::npos);
    EXPECT_NE(error("name,code,friction_deg\nscree,1,95\n").find("outside [0, 90)"), std::string::npos);
    EXPECT_NE(error("name,code\nscree,1\nscree,2\n").find("named twice"), std::string::npos);
    EXPECT_NE(error("name,code\nscree,1\nrock,1\n").find("code 1 is used by 'scree' too"), std::string::npos);
    EXPECT_NE(error("name,code\nscene,1\n").find("the scene's own soil"), std::string::npos);
    EXPECT_NE(error("name,code,damping_ratio,restitution\nscree,1,0.5,\n").find("give one"), std::string::npos);
    EXPECT_NE(error("name\nscree\n").find("code"), std::string::npos);
    // A misspelt column would leave the soil on the scene's value.
    EXPECT_NE(error("name,code,damping,kn_n_m\ndead,1,0.95,2e5\n").find("unknown column 'damping'"), std::string::npos);
}

// The map places the types on the DTM's cells (the type at each cell centre, the scene's soil
// elsewhere), from polygons or from a raster of codes.
TEST_F(Hazard, SoilMapPlacesTheTypesOnTheDtmsCells) {
    const Dtm d = readDtm(dtm("d.asc", 6, 4, 5.0, 0, 0, [](int c, int) { return 100.0 - 3 * c; }));
    sylva::dem::SoilContactParams scene;
    const auto types = readSoilTypes(write("soils.csv", "name,code,friction_deg\nscree,7,35\nrock,9,20\n"), scene);
    // Scree over x in [0, 10] (columns 0-1), rock over x in [20, 30] (columns 4-5), the scene's soil between.
    const std::string map = write("soils.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"soil": "scree"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 20], [0, 20], [0, 0]]]}},
        {"type": "Feature", "properties": {"soil": "rock"}, "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [30, 0], [30, 20], [20, 20], [20, 0]]]}}]})");
    const auto zones = readSoilZones(map, types, d, scene);
    ASSERT_EQ(zones->names, (std::vector<std::string>{"scene", "scree", "rock"}));
    for (int c = 0; c < 6; ++c) {
        const Eigen::Vector2d p = d.grid.centre(c, 1);
        EXPECT_EQ(zones->names[zones->at(p.x(), p.y())], c < 2 ? "scree" : c < 4 ? "scene" : "rock") << "column " << c;
    }
    // The same from a raster of codes on a 10 m grid: 7 | NODATA | 9.
    const std::string raster = write("soils.asc", "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n7 -9999 9\n7 -9999 9\n");
    const auto fromRaster = readSoilZones(raster, types, d, scene);
    EXPECT_EQ(fromRaster->zone, zones->zone);
    EXPECT_NE(errorOf([&] { readSoilZones(write("x.asc", "ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 40\n3\n"), types, d, scene); })
                  .find("holds 3, not the code of a soil type"),
              std::string::npos);
    const std::string unknown = write("u.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"soil": "mud"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 20], [0, 0]]]}}]})");
    EXPECT_NE(errorOf([&] { readSoilZones(unknown, types, d, scene); }).find("soil 'mud' is not in the soil types' table (scree, rock)"),
              std::string::npos);
    const std::string overlapping = write("o.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"soil": "scree"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [20, 0], [20, 20], [0, 20], [0, 0]]]}},
        {"type": "Feature", "properties": {"soil": "rock"}, "geometry": {"type": "Polygon", "coordinates": [[[10, 0], [30, 0], [30, 20], [10, 20], [10, 0]]]}}]})");
    EXPECT_NE(errorOf([&] { readSoilZones(overlapping, types, d, scene); }).find("a cell has one soil"), std::string::npos);
    // A map beside the DTM (here 1 km east) changed nothing and said nothing.
    const std::string beside = write("b.geojson", R"({"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": {"soil": "rock"}, "geometry": {"type": "Polygon", "coordinates": [[[1000, 0], [1030, 0], [1030, 20], [1000, 20], [1000, 0]]]}}]})");
    EXPECT_NE(errorOf([&] { readSoilZones(beside, types, d, scene); }).find("it places no soil type on any cell centre of the DTM"), std::string::npos)
        << errorOf([&] { readSoilZones(beside, types, d, scene); });
}

// On the example's slope (data/hazard/), the DEM's blocks, paired (the same release points and
// orientations), run shorter on a dead soil (damping ratio 0.95, K_n 2e5 N/m, friction 45 degrees)
// than on the scene's (Table 2: 0.54, 1e6 N/m, 30 degrees): every soil contact loses more. With 2
// blocks per cell the medians were 379 and 333 m, the 90th percentiles 466 and 343 m; here 1 per cell.
TEST_F(Hazard, DeadSoilStopsTheDemsBlocksSooner) {
    HazardOptions o = exampleSlope();
    o.outDir = (dir_ / "scene").string();
    const HazardResults plain = runHazard(o);
    oneSoilType(o, "dead,1,0.95,2e5,45");
    o.outDir = (dir_ / "dead").string();
    const HazardResults dead = runHazard(o);
    ASSERT_EQ(plain.passes.at(0).blocks, 48);
    ASSERT_EQ(dead.passes.at(0).blocks, 48);
    EXPECT_LT(dead.passes[0].pathP50, plain.passes[0].pathP50);
    EXPECT_LT(dead.passes[0].pathP90, plain.passes[0].pathP90);
    o.model = sylva::dem::Model::Lumped;
    o.outDir = (dir_ / "lumped").string();
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("use --model dem"), std::string::npos);
    o.model = sylva::dem::Model::Dem;
    o.soilTypesPath.clear();
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("--soils needs --soil-types"), std::string::npos);
}

// 1.2 m thick stems 3.5 m apart on the 12 release cells (5 m): a release point drawn inside one is
// drawn again in its cell. The blocks that started there were left out of the map (4 of these 24,
// `sylvarock hazard` at 9b25454).
TEST_F(Hazard, AReleasePointInsideAStemIsDrawnAgain) {
    HazardOptions o = exampleSlope();
    o.releasePath = polygon("small.geojson", 925090, 6460090, 925110, 6460105,
                            R"("crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},)");
    std::string trees = "x,y,dbh_cm\n";
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 7; ++j) trees += std::to_string(925090.5 + 3.5 * i) + "," + std::to_string(6460085.5 + 3.5 * j) + ",120\n";
    o.treesPath = write("thick.csv", trees);
    o.runsPerCell = 2;
    o.outDir = (dir_ / "redrawn").string();
    const HazardResults r = runHazard(o);
    ASSERT_EQ(r.passes.size(), 1u);
    EXPECT_EQ(r.passes[0].failed, 0);
    EXPECT_EQ(r.passes[0].blocks, 24);
}

// With --compare-bare, blocks whose forest run failed (released in a cell that 1.2 m thick stems
// 0.8 m apart fill, where every point drawn is inside one) are left out of the bare pass too: both
// maps count the same blocks, and where as many blocks passed with the trees as without, the
// protection is 0 (it was 1/12 - 1/10 where 10 forest blocks were set against 12 bare ones).
TEST_F(Hazard, TheBarePassLeavesOutTheBlocksWhoseForestRunFailed) {
    HazardOptions o = exampleSlope();
    o.releasePath = polygon("small.geojson", 925090, 6460090, 925110, 6460105,
                            R"("crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}},)");
    std::string trees = "x,y,dbh_cm\n";
    for (int i = 0; i < 8; ++i)  // over the release cell x 925090-925095, y 6460090-6460095 and its edges
        for (int j = 0; j < 8; ++j) trees += std::to_string(925089.9 + 0.8 * i) + "," + std::to_string(6460089.9 + 0.8 * j) + ",120\n";
    o.treesPath = write("thick.csv", trees);
    o.compareBare = true;
    o.outDir = (dir_ / "paired").string();
    const HazardResults r = runHazard(o);
    ASSERT_EQ(r.passes.size(), 2u);
    const HazardPass &forest = r.passes[0], &bare = r.passes[1];
    ASSERT_GT(forest.failed, 0) << "the test needs a forest run that cannot start";
    EXPECT_EQ(bare.leftOutForPairing, forest.failed);
    EXPECT_EQ(bare.failed, 0);
    EXPECT_EQ(bare.blocks, forest.blocks);
    const Dtm withTrees = readDtm((dir_ / "paired/passing_count.tif").string());
    const Dtm without = readDtm((dir_ / "paired/bare/passing_count.tif").string());
    const Dtm protection = readDtm((dir_ / "paired/protection.tif").string());
    int equal = 0;
    for (int row = 0; row < withTrees.grid.rows; ++row)
        for (int c = 0; c < withTrees.grid.columns; ++c) {
            const Eigen::Vector2d p = withTrees.grid.centre(c, row);
            if (withTrees.elevation.height(p.x(), p.y()) != without.elevation.height(p.x(), p.y())) continue;
            ++equal;
            EXPECT_EQ(protection.elevation.height(p.x(), p.y()), 0.0) << "cell " << c << "," << row;
        }
    EXPECT_GT(equal, 0);
}

// A soil too soft to hold the block up fails every run alike: the map says so once, as an input error
// before the first run, naming the key (it used to let each of the 48 runs fail, then stop without a
// map, and a store in the folder that the corrected command then refused). The soil map's types and
// each block volume are asked: a 4 m^3 block (2 700 kg/m^3: 10.8 t, 106 kN) would sink 0.53 m into
// a 2e5 N/m soil, under the 0.7 m spheres' radius, which holds it, and 1.06 m into a 1e5 N/m one.
TEST_F(Hazard, ASoilTooSoftForTheBlockIsRefusedBeforeAnyRun) {
    HazardOptions o = exampleSlope();
    int notes = 0;
    o.onNote = [&](const std::string&) { ++notes; };
    const auto refusal = [&](const std::string& out) {
        o.outDir = (dir_ / out).string();
        try {
            runHazard(o);
        } catch (const sylva::InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no input error)");
    };
    o.sceneOverrides = {"soil.kn_n_m=1"};
    const std::string scene = refusal("scene");
    EXPECT_NE(scene.find("soil.kn_n_m = 1 N/m"), std::string::npos) << scene;
    EXPECT_EQ(notes, 0) << "no run was tried";
    EXPECT_FALSE(std::filesystem::exists(dir_ / "scene")) << "the output folder is not touched: a rerun may use it";
    o.sceneOverrides.clear();
    oneSoilType(o, "soft,1,0.5,1e5,30");
    o.blockVolumes = parseBlockVolumes("0.5,4");
    const std::string heavy = refusal("heavy");
    EXPECT_NE(heavy.find("soil type 'soft': kn_n_m = 1e+05 N/m"), std::string::npos) << heavy;
    EXPECT_EQ(notes, 0);
    oneSoilType(o, "soft,1,0.5,2e5,30");
    EXPECT_EQ(refusal("firm"), "(no input error)");
}

// Stand polygons on a flat 300 x 200 m DTM (cell centres from 2.5 to 297.5 and 2.5 to 197.5).
class StandPolygons : public Hazard {
protected:
    static std::string ring(const std::vector<std::pair<double, double>>& points) {
        std::string s = "[";
        for (const auto& [x, y] : points) s += (s.size() > 1 ? ", [" : "[") + std::to_string(x) + ", " + std::to_string(y) + "]";
        return s + "]";
    }
    // Features: {properties JSON, rings (outer, then holes)}.
    std::string stands(const std::vector<std::pair<std::string, std::vector<std::vector<std::pair<double, double>>>>>& features) const {
        std::string text = "{\"type\": \"FeatureCollection\", \"features\": [";
        for (std::size_t i = 0; i < features.size(); ++i) {
            std::string rings;
            for (const auto& r : features[i].second) rings += (rings.empty() ? "" : ", ") + ring(r);
            text += std::string(i ? ", " : "") + "{\"type\": \"Feature\", \"properties\": " + features[i].first +
                    ", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [" + rings + "]}}";
        }
        return write("stands.geojson", text + "]}");
    }
    std::string flat() const { return dtm("flat.asc", 60, 40, 5.0, 0, 0, [](int, int) { return 100.0; }); }
    static std::string mo1() { return std::string(SYLVAROCK_DATA) + "/stands/MO1"; }
    static std::string gr1() { return std::string(SYLVAROCK_DATA) + "/stands/GR1"; }
    static double stemsPerHa(const std::string& prefix) {
        const stand::Inventory inventory = stand::readInventory(prefix + "_stems.csv", prefix + "_plots.csv");
        return stand::StandCatalogue(inventory, prefix + "_stems.csv").stemsPerHa();
    }
};

// Each polygon holds its stand's density over its area on the terrain (the generator places
// round(N/ha x area) stems: exact), nothing in a polygon's hole, nothing outside the polygons, no two
// stems overlapping across the shared border; the same seed draws the same forest, another seed another.
TEST_F(StandPolygons, EachPolygonHoldsItsStandsForest) {
    const Dtm d = readDtm(flat());
    const std::string file =
        stands({{"{\"stand\": \"" + mo1() + "\", \"structure\": \"A\"}", {{{10, 10}, {150, 10}, {150, 190}, {10, 190}, {10, 10}}}},
                {"{\"stand\": \"" + gr1() + "\", \"structure\": \"NA\"}",
                 {{{150, 10}, {290, 10}, {290, 190}, {150, 190}, {150, 10}}, {{200, 80}, {240, 80}, {240, 120}, {200, 120}, {200, 80}}}}});
    const StandForest f = readStandPolygons(file, d, 7, kTip);
    ASSERT_EQ(f.polygons.size(), 2u);
    EXPECT_EQ(f.polygons[0].structure, stand::ForestStructure::Aggregated);
    EXPECT_EQ(f.polygons[1].structure, stand::ForestStructure::Random);
    EXPECT_NEAR(f.polygons[0].areaHa, 140.0 * 180 / 1e4, 1e-9);
    EXPECT_NEAR(f.polygons[1].areaHa, (140.0 * 180 - 40 * 40) / 1e4, 1e-9);
    const long placedA = std::lround(stemsPerHa(mo1()) * f.polygons[0].areaHa);
    const long placedNA = std::lround(stemsPerHa(gr1()) * f.polygons[1].areaHa);
    EXPECT_EQ(f.polygons[0].stems, placedA);
    // Only stems of the second stand can be dropped, where they would overlap the first's at x = 150.
    EXPECT_LE(f.polygons[1].stems, placedNA);
    EXPECT_GE(f.polygons[1].stems, placedNA - 5);
    ASSERT_EQ(static_cast<long>(f.forest.trees.size()), f.polygons[0].stems + f.polygons[1].stems);
    for (std::size_t i = 0; i < f.forest.trees.size(); ++i) {
        const auto& t = f.forest.trees[i];
        EXPECT_EQ(t.id, static_cast<long>(i + 1));
        ASSERT_TRUE(t.x >= 10 && t.x <= 290 && t.y >= 10 && t.y <= 190) << t.x << "," << t.y;
        ASSERT_FALSE(t.x > 200 && t.x < 240 && t.y > 80 && t.y < 120) << "a stem in the clearing at " << t.x << "," << t.y;
        EXPECT_GT(t.heightM, 0);
    }
    for (const auto& a : f.forest.trees)
        for (const auto& b : f.forest.trees)
            if (a.id < b.id && std::abs(a.x - 150) < 1 && std::abs(b.x - 150) < 1) {
                ASSERT_GE(std::hypot(a.x - b.x, a.y - b.y), (a.dbhCm + b.dbhCm) / 200) << "stems " << a.id << " and " << b.id << " overlap";
            }
    // Stools of the aggregated stand keep their ids; the random stand has none.
    long stools = 0;
    for (const auto& t : f.forest.trees) stools += t.stool.has_value() && t.id <= f.polygons[0].stems;
    EXPECT_GT(stools, f.polygons[0].stems / 4);

    const StandForest again = readStandPolygons(file, d, 7, kTip), other = readStandPolygons(file, d, 8, kTip);
    ASSERT_EQ(again.forest.trees.size(), f.forest.trees.size());
    for (std::size_t i = 0; i < f.forest.trees.size(); ++i) ASSERT_EQ(again.forest.trees[i].x, f.forest.trees[i].x);
    EXPECT_NE(other.forest.trees.front().x, f.forest.trees.front().x);
}

// A stool's stems may stand closer than their radii (coppice stems recorded 0.15 m apart at 20 cm
// DBH): a polygon keeps all of its own stems, where they were dropped as a neighbouring stand's (a
// third of this stand), and still drops a neighbour's that would overlap them.
TEST_F(StandPolygons, AStandKeepsItsOwnStoolsStemsStandingCloserThanTheirRadii) {
    const Dtm d = readDtm(flat());
    std::string stems = "plot,stem,x,y,dbh_cm,species,stool\n";
    for (int k = 0; k < 15; ++k) {
        const double x = 1.5 + 1.2 * k, y = 2.0 + 1.1 * k;
        stems += "1," + std::to_string(2 * k + 1) + "," + std::to_string(x) + "," + std::to_string(y) + ",20,beech," + std::to_string(k + 1) + "\n";
        stems += "1," + std::to_string(2 * k + 2) + "," + std::to_string(x + 0.15) + "," + std::to_string(y) + ",20,beech," + std::to_string(k + 1) + "\n";
        stems += "1," + std::to_string(31 + k) + "," + std::to_string(18.5 - 1.2 * k) + "," + std::to_string(2.0 + 1.1 * k) + ",20,beech,\n";
    }
    write("COPPICE_stems.csv", stems);
    write("COPPICE_plots.csv", "plot,xmin,ymin,xmax,ymax\n1,0,0,20,20\n");
    const std::string coppice = (dir_ / "COPPICE").string();
    const StandForest f = readStandPolygons(
        stands({{"{\"stand\": \"" + coppice + "\", \"structure\": \"A\"}", {{{10, 10}, {150, 10}, {150, 190}, {10, 190}, {10, 10}}}},
                {"{\"stand\": \"" + coppice + "\", \"structure\": \"A\"}", {{{150, 10}, {290, 10}, {290, 190}, {150, 190}, {150, 10}}}}}),
        d, 3, kTip);
    ASSERT_EQ(f.polygons.size(), 2u);
    EXPECT_EQ(f.polygons[0].stems, std::lround(stemsPerHa(coppice) * f.polygons[0].areaHa));
    long close = 0;  // a stool's stems closer than their radii, kept
    for (std::size_t i = 1; i < f.forest.trees.size(); ++i) {
        const auto &a = f.forest.trees[i - 1], &b = f.forest.trees[i];
        close += a.stool && a.stool == b.stool && std::hypot(a.x - b.x, a.y - b.y) < 0.2;
    }
    EXPECT_GT(close, f.polygons[0].stems / 5);
    // The second stand loses at most its stems at the shared border, never its own stools' stems.
    EXPECT_LE(f.polygons[1].stems, std::lround(stemsPerHa(coppice) * f.polygons[1].areaHa));
    EXPECT_GE(f.polygons[1].stems, std::lround(stemsPerHa(coppice) * f.polygons[1].areaHa) - 10);
    for (const auto& a : f.forest.trees)
        for (const auto& b : f.forest.trees)
            if (a.id < b.id && (a.id <= f.polygons[0].stems) != (b.id <= f.polygons[0].stems)) {
                ASSERT_GE(std::hypot(a.x - b.x, a.y - b.y), (a.dbhCm + b.dbhCm) / 200) << "stems " << a.id << " and " << b.id;
            }
}

// A polygon reaching past the DTM is cut to the terrain (the rectangle of cell centres); the
// inventory is found beside the vector file; no `structure` means A, said in the notes.
TEST_F(StandPolygons, PolygonsAreCutToTheTerrainAndInventoriesFoundBesideTheFile) {
    const Dtm d = readDtm(flat());
    for (const char* tail : {"_stems.csv", "_plots.csv"}) fs::copy_file(mo1() + tail, dir_ / (std::string("MO1") + tail));
    const StandForest f = readStandPolygons(stands({{"{\"stand\": \"MO1\"}", {{{-50, -50}, {100, -50}, {100, 250}, {-50, 250}, {-50, -50}}}}}), d, 1, kTip);
    ASSERT_EQ(f.polygons.size(), 1u);
    EXPECT_NEAR(f.polygons[0].areaHa, 97.5 * 195 / 1e4, 1e-9);
    EXPECT_EQ(fs::path(f.polygons[0].inventory).filename(), "MO1");
    EXPECT_EQ(f.polygons[0].structure, stand::ForestStructure::Aggregated);
    ASSERT_FALSE(f.notes.empty());
    EXPECT_NE(f.notes.front().find("aggregated (A)"), std::string::npos);
    // What was cut is said: 150 x 300 m drawn, 100 x 200 m of it on the DTM (0..300 x 0..200).
    const auto said = [](const StandForest& forest) {
        return std::find_if(forest.notes.begin(), forest.notes.end(), [](const std::string& n) { return n.find("beyond the DTM") != std::string::npos; });
    };
    ASSERT_NE(said(f), f.notes.end());
    EXPECT_NE(said(f)->find("MO1): 25000 m2 of its 45000 m2 lie beyond the DTM (0..300 x 0..200)"), std::string::npos) << *said(f);
    // Drawn to the DTM's edge, it loses only the half-cell strip outside the cell centres, as every forest does: nothing said.
    const StandForest edge = readStandPolygons(stands({{"{\"stand\": \"MO1\"}", {{{0, 0}, {100, 0}, {100, 200}, {0, 200}, {0, 0}}}}}), d, 1, kTip);
    EXPECT_EQ(said(edge), edge.notes.end()) << *said(edge);
    for (const auto& t : f.forest.trees) ASSERT_TRUE(t.x >= 2.5 && t.x <= 100 && t.y >= 2.5 && t.y <= 197.5);
}

TEST_F(StandPolygons, BadStandsSayWhatIsWrong) {
    const Dtm d = readDtm(flat());
    const std::vector<std::vector<std::pair<double, double>>> square{{{10, 10}, {100, 10}, {100, 100}, {10, 100}, {10, 10}}};
    const auto error = [&](const std::string& properties, const std::vector<std::vector<std::pair<double, double>>>& rings) {
        return errorOf([&] { readStandPolygons(stands({{properties, rings}}), d, 1, kTip); });
    };
    EXPECT_NE(error("{\"name\": \"x\"}", square).find("no field `stand`"), std::string::npos);
    EXPECT_NE(error("{\"stand\": \"nowhere/XX\"}", square).find("stand 'nowhere/XX' has no inventory"), std::string::npos);
    EXPECT_NE(error("{\"stand\": \"" + mo1() + "\", \"structure\": \"clumped\"}", square).find("feature 1"), std::string::npos);
    EXPECT_NE(error("{\"stand\": \"" + mo1() + "\"}", {{{1000, 1000}, {1100, 1000}, {1100, 1100}, {1000, 1000}}}).find("outside the terrain"),
              std::string::npos);
    const std::string overlapping = stands({{"{\"stand\": \"" + mo1() + "\"}", square},
                                            {"{\"stand\": \"" + gr1() + "\"}", {{{90, 10}, {200, 10}, {200, 100}, {90, 100}, {90, 10}}}}});
    EXPECT_NE(errorOf([&] { readStandPolygons(overlapping, d, 1, kTip); }).find("overlaps feature 1 by 900 m2"), std::string::npos);
    EXPECT_NE(errorOf([&] { readStandPolygons(write("points.geojson", "{\"type\": \"FeatureCollection\", \"features\": []}"), d, 1, kTip); })
                  .find("no polygon"),
              std::string::npos);
    // A stem thinner than the stems' tip diameter: named by its inventory line, not as a virtual stem.
    write("THIN_stems.csv", "plot,stem,x,y,dbh_cm,species,stool\n1,1,10,10,20,beech,\n1,2,30,30,0.5,beech,\n");
    write("THIN_plots.csv", "plot,xmin,ymin,xmax,ymax\n1,0,0,50,50\n");
    EXPECT_NE(error("{\"stand\": \"" + (dir_ / "THIN").string() + "\"}", square)
                  .find("THIN_stems.csv:3: stem '2': a DBH of 0.5 cm is below the stems' tip diameter"),
              std::string::npos);
    HazardOptions o;
    o.dtmPath = flat();
    o.releasePath = polygon("release.geojson", 10, 10, 20, 20);
    o.treesPath = write("trees.csv", "x,y,dbh_cm\n50,50,20\n");
    o.standsPath = stands({{"{\"stand\": \"" + mo1() + "\"}", square}});
    o.outDir = (dir_ / "out").string();
    EXPECT_NE(errorOf([&] { runHazard(o); }).find("--trees and --stands both give the forest"), std::string::npos);
    // Polygons in longitude and latitude (GeoJSON's default CRS) over a projected DTM: the CRS is named
    // first, where every polygon was said to lie "outside the terrain".
    const Dtm projected = readDtm(dtm("projected.asc", 60, 40, 5.0, 900000, 6400000, [](int, int) { return 100.0; }, true));
    const std::string inDegrees =
        errorOf([&] { readStandPolygons(stands({{"{\"stand\": \"" + mo1() + "\"}", {{{6.10, 45.20}, {6.11, 45.20}, {6.11, 45.21}, {6.10, 45.20}}}}}), projected, 1, kTip); });
    EXPECT_NE(inDegrees.find("is in WGS 84"), std::string::npos) << inDegrees;
    EXPECT_NE(inDegrees.find("reproject it"), std::string::npos) << inDegrees;
}

// A stand's forest seed is 64 bits: as a JSON number it was read rounded by jq and JavaScript
// (9716232063330790915 as 9716232063330791000); summary.json gives it as a string, as the GeoPackage does.
TEST_F(StandPolygons, SummaryGivesEachStandsSeedAsAString) {
    HazardOptions o;
    o.dtmPath = flat();
    o.releasePath = polygon("release.geojson", 10, 10, 20, 20);
    o.standsPath = stands({{"{\"stand\": \"" + mo1() + "\"}", {{{100, 10}, {250, 10}, {250, 190}, {100, 190}, {100, 10}}}}});
    o.model = sylva::dem::Model::Lumped;
    o.runsPerCell = 1;
    o.outDir = (dir_ / "seeds").string();
    runHazard(o);
    std::ifstream in(dir_ / "seeds/summary.json");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::uint64_t seed = readStandPolygons(o.standsPath, readDtm(o.dtmPath), o.seed, kTip).polygons.at(0).seed;
    EXPECT_GT(seed, std::uint64_t(1) << 53) << "a seed a double holds exactly would not show the rounding";
    EXPECT_NE(text.find("\"seed\": \"" + std::to_string(seed) + "\""), std::string::npos) << text;
}

}  // namespace
