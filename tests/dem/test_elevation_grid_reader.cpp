// DTMs as ESRI ASCII grids: the reader and its errors, bilinear heights and lengths along x
// against values worked out by hand from the test files.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "libdem/ElevationGrid.hpp"
#include "libcommon/InputError.hpp"

using sylva::InputError;
using sylva::dem::ElevationGrid;

namespace {

const std::string kDir = std::string(SYLVAROCK_TEST_DATA) + "/dem/";

// The error that reading `file` (from tests/data/dem) must raise.
InputError readError(const std::string& file) {
    try {
        ElevationGrid::readAsc(kDir + file);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << file << " was accepted";
    return InputError("");
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void expectError(const std::string& file, long line, const std::string& part) {
    const InputError e = readError(file);
    EXPECT_EQ(e.file(), kDir + file);
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_TRUE(contains(e.what(), part)) << e.what();
}

}  // namespace

// grid_small.asc: 3 x 2 cells of 10 m, lower-left corner (100, 200); the file lists the north row
// "7 8 9" first, then the south row "1 4 2". Cell centres: x = 105, 115, 125; y = 205, 215.
TEST(ElevationGridReader, CornerHeaderPlacesCellCentresAndNorthRowFirst) {
    const ElevationGrid g = ElevationGrid::readAsc(kDir + "grid_small.asc");
    EXPECT_EQ(g.columns(), 3);
    EXPECT_EQ(g.rows(), 2);
    EXPECT_EQ(g.cellSize(), 10.0);
    EXPECT_EQ(g.xmin(), 105.0);
    EXPECT_EQ(g.xmax(), 125.0);
    EXPECT_EQ(g.ymin(), 205.0);
    EXPECT_EQ(g.ymax(), 215.0);
    EXPECT_EQ(g.height(105, 215), 7.0);
    EXPECT_EQ(g.height(115, 215), 8.0);
    EXPECT_EQ(g.height(125, 215), 9.0);
    EXPECT_EQ(g.height(105, 205), 1.0);
    EXPECT_EQ(g.height(115, 205), 4.0);
    EXPECT_EQ(g.height(125, 205), 2.0);
}

// Same grid with centre coordinates, upper-case keys, a NODATA_value that no cell uses and a
// blank line between the rows.
TEST(ElevationGridReader, CentreHeaderGivesTheSameGrid) {
    const ElevationGrid a = ElevationGrid::readAsc(kDir + "grid_small.asc");
    const ElevationGrid b = ElevationGrid::readAsc(kDir + "grid_small_center.asc");
    EXPECT_EQ(a.xmin(), b.xmin());
    EXPECT_EQ(a.ymin(), b.ymin());
    for (double x = 100; x <= 130; x += 2.5)
        for (double y = 200; y <= 220; y += 2.5) EXPECT_EQ(a.height(x, y), b.height(x, y)) << x << "," << y;
}

// A byte-order mark before "ncols" made the reader take the header's first line for values ("the
// header ends without 'cellsize'" on a valid grid).
TEST(ElevationGridReader, AByteOrderMarkIsDropped) {
    const ElevationGrid a = ElevationGrid::readAsc(kDir + "grid_small.asc");
    const ElevationGrid b = ElevationGrid::readAsc(kDir + "grid_small_bom.asc");
    EXPECT_EQ(b.columns(), a.columns());
    EXPECT_EQ(b.xmin(), a.xmin());
    EXPECT_EQ(b.height(115, 205), a.height(115, 205));
}

TEST(ElevationGridReader, UnknownHeaderKeyNamesItsLine) { expectError("grid_unknown_key.asc", 5, "'cellsiz'"); }

TEST(ElevationGridReader, MissingHeaderKeyNamesWhereTheHeaderEnds) {
    expectError("grid_missing_cellsize.asc", 5, "cellsize");
}

TEST(ElevationGridReader, NonPositiveCellSizeIsRejected) { expectError("grid_bad_cellsize.asc", 5, "cellsize -2 is outside"); }

// Issue 13: a 100 km cell ran for ever building its soil bed; at 1e308 a cell no longer moves a
// coordinate and the row loop never ended.
TEST(ElevationGridReader, CellSizeAndCornerOutsideAMapAreRejected) {
    expectError("grid_cellsize_km.asc", 5, "cellsize 100000 is outside [0.01, 1000] m");
    expectError("grid_corner_far.asc", 3, "beyond 1e8 m");
}

TEST(ElevationGridReader, CornerAndCentreTogetherAreRejected) {
    expectError("grid_corner_and_center.asc", 4, "not both");
}

TEST(ElevationGridReader, FewerThanTwoColumnsAreRejected) { expectError("grid_one_column.asc", 1, "ncols"); }

TEST(ElevationGridReader, RowWithWrongNumberOfValuesNamesItsLine) {
    expectError("grid_short_row.asc", 7, "has 2 values, ncols = 3");
}

TEST(ElevationGridReader, TooFewRowsAreRejected) { expectError("grid_too_few_rows.asc", 7, "found 2 rows"); }

TEST(ElevationGridReader, TooManyRowsNameTheFirstExtraLine) { expectError("grid_too_many_rows.asc", 8, "nrows = 2"); }

TEST(ElevationGridReader, NonNumericValueNamesLineAndText) { expectError("grid_not_numeric.asc", 7, "'x5'"); }

TEST(ElevationGridReader, MissingFileIsAnInputError) { expectError("no_such_grid.asc", 0, "cannot open"); }

// A GeoTIFF given as terrain.dtm was "unknown header key 'II*'" and raw bytes: it is named as binary,
// with the conversion to make.
TEST(ElevationGridReader, ABinaryRasterIsNamedWithTheWayToConvertIt) {
    const std::string tif = std::string(SYLVAROCK_DATA) + "/hazard/slope.tif";
    try {
        ElevationGrid::readAsc(tif);
        ADD_FAILURE() << "a GeoTIFF was read";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "a binary file (a GeoTIFF?)")) << e.what();
        EXPECT_TRUE(contains(e.what(), "gdal_translate -of AAIGrid")) << e.what();
    }
}

// GDAL's float32 NODATA marker in a file that does not declare it: a wall 3.4e38 m deep, refused
// where it stands rather than run (run-outs of 1e38 m), and likewise from a grid GDAL read.
TEST(ElevationGridReader, AHeightBeyondEarthsReliefIsAnUndeclaredNodata) {
    expectError("grid_undeclared_nodata.asc", 7, "value 3: height -3.4028235e+38 m is beyond Earth's relief");
    std::vector<double> z = {1, 2, 3, 4, 5, 1e30};  // row 0 the southernmost: the last value is the north-east cell
    try {
        ElevationGrid::fromValues(3, 2, 0.5, 0.5, 1, z, "dtm.tif");
        ADD_FAILURE() << "1e30 m was accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "dtm.tif");
        EXPECT_TRUE(contains(e.what(), "column 3, row 1")) << e.what();
    }
    z.back() = 8848.9;  // Everest, and the Dead Sea shore below, on cells of 200 m (no face steeper than 89 degrees)
    z.front() = -430;
    EXPECT_NO_THROW(ElevationGrid::fromValues(3, 2, 100, 100, 200, z, "dtm.tif"));
}

// A hole filled with -9999, inside Earth's relief, that the file does not declare NODATA: read as
// ground, it was a pit 10 km deep where every block of a hazard map stopped (paths of 344 km, no
// warning). No terrain has a step steeper than 89 degrees and higher than 2 000 m; the lower cell is
// named, even where the markers outnumber the ground (a DTM clipped to a catchment).
TEST(ElevationGridReader, AHoleOfUndeclaredNodataSteeperThanAnyTerrainIsRefused) {
    expectError("grid_undeclared_hole.asc", 7, "value 2: height -9999 m lies 10409 m below its neighbour's (410 m) over a cell of 2 m");
    // The same values from GDAL (row 0 the southernmost).
    std::vector<double> z = {409.5, 407.0, 404.5, 402.0, 411.0, -9999, 406.0, 403.5, 412.5, 410.0, 407.5, 405.0};
    try {
        ElevationGrid::fromValues(4, 3, 1, 1, 2, z, "dtm.tif").refuseUndeclaredNoData();
        ADD_FAILURE() << "-9999 m beside 410 m was accepted";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "cell (column 2, row 2, counted from 1 at the north-west corner): height -9999 m")) << e.what();
    }
    // Real cliffs, however fine the cells: 110 m over 2 m, and 1 900 m (a face higher than any on
    // Earth) over 2 m; 2 100 m over 2 m is refused.
    z[5] = 411.0 - 110;
    EXPECT_NO_THROW(ElevationGrid::fromValues(4, 3, 1, 1, 2, z, "dtm.tif").refuseUndeclaredNoData());
    z[5] = 411.0 - 1900;
    EXPECT_NO_THROW(ElevationGrid::fromValues(4, 3, 1, 1, 2, z, "dtm.tif").refuseUndeclaredNoData());
    z[5] = 411.0 - 2100;
    EXPECT_THROW(ElevationGrid::fromValues(4, 3, 1, 1, 2, z, "dtm.tif").refuseUndeclaredNoData(), InputError);
    // Mostly markers: the ground cell above them is not the one named.
    std::vector<double> clipped(12, -9999);
    clipped[10] = 380;  // north row, third column
    try {
        ElevationGrid::fromValues(4, 3, 1, 1, 2, clipped, "catchment.tif").refuseUndeclaredNoData();
        ADD_FAILURE() << "-9999 beside 380 m was accepted";
    } catch (const InputError& e) {
        EXPECT_TRUE(contains(e.what(), "row 1, counted from 1 at the north-west corner): height -9999 m lies 10379 m below")) << e.what();
    }
}

// grid_nodata.asc: 4 x 3 cells of 1 m, corner (0, 0); the NODATA cell is value 3 of line 8, the
// middle row, so its centre is (2.5, 1.5).
TEST(ElevationGridReader, NodataIsRejectedOnlyWhereAHeightNeedsIt) {
    const ElevationGrid g = ElevationGrid::readAsc(kDir + "grid_nodata.asc");
    EXPECT_EQ(g.height(0.5, 1.0), 3.5);   // between rows 3 and 4, columns 1: far from the hole
    EXPECT_EQ(g.height(1.5, 1.5), 4.0);   // on a centre next to the hole: its weight is 0
    EXPECT_EQ(g.height(3.5, 0.5), 3.0);
    for (const auto& [x, y] : {std::pair{2.5, 1.5}, {2.0, 1.0}, {3.0, 2.0}, {2.5, 0.6}}) {
        try {
            g.height(x, y);
            ADD_FAILURE() << "height(" << x << ", " << y << ") used the NODATA cell";
        } catch (const InputError& e) {
            EXPECT_EQ(e.line(), 8);
            EXPECT_TRUE(contains(e.what(), "value 3 is NODATA")) << e.what();
        }
    }
    EXPECT_NO_THROW(g.requireDefined(0.5, 1.5, 0.5, 2.5));
    EXPECT_THROW(g.requireDefined(0.5, 2.1, 0.5, 0.6), InputError);
}

TEST(ElevationGrid, BilinearBetweenCellCentres) {
    const ElevationGrid g = ElevationGrid::readAsc(kDir + "grid_small.asc");
    EXPECT_DOUBLE_EQ(g.height(110, 210), (1 + 4 + 7 + 8) / 4.0);
    // a quarter of the way across the eastern cell in x, three quarters in y
    const double south = 0.75 * 4 + 0.25 * 2, north = 0.75 * 8 + 0.25 * 9;
    EXPECT_DOUBLE_EQ(g.height(117.5, 212.5), 0.25 * south + 0.75 * north);
    // outside the centres' rectangle the nearest edge value holds
    EXPECT_EQ(g.height(0, 0), 1.0);
    EXPECT_EQ(g.height(1000, 1000), 9.0);
    EXPECT_DOUBLE_EQ(g.height(110, -50), 2.5);
    EXPECT_TRUE(std::isnan(g.height(NAN, 210)));
    EXPECT_TRUE(std::isnan(g.lengthAlongX(110, INFINITY, 210)));
}

// grid_plane.asc samples z = 50 - 0.5 x + 0.25 y exactly; bilinear interpolation reproduces a
// plane, so only floating-point rounding of values near 50 (~1e-14) separates the two.
TEST(ElevationGrid, PlaneIsReproducedWithItsGradient) {
    const ElevationGrid g = ElevationGrid::readAsc(kDir + "grid_plane.asc");
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(g.xmin(), g.xmax()), uy(g.ymin(), g.ymax());
    for (int i = 0; i < 200; ++i) {
        const double x = ux(rng), y = uy(rng);
        EXPECT_NEAR(g.height(x, y), 50 - 0.5 * x + 0.25 * y, 1e-12);
        EXPECT_NEAR(g.gradient(x, y).x(), -0.5, 1e-12);
        EXPECT_NEAR(g.gradient(x, y).y(), 0.25, 1e-12);
    }
    // beyond the western edge the height is clamped, so it no longer varies with x
    EXPECT_EQ(g.gradient(-5.0, 5.0).x(), 0.0);
    EXPECT_NEAR(g.gradient(-5.0, 5.0).y(), 0.25, 1e-12);
}

// Along y = 205 the surface of grid_small.asc is the polyline (105,1) (115,4) (125,2).
TEST(ElevationGrid, LengthAlongXFollowsTheKinks) {
    const ElevationGrid g = ElevationGrid::readAsc(kDir + "grid_small.asc");
    const double tol = 1e-12;  // sums of a few square roots of small integers
    EXPECT_NEAR(g.lengthAlongX(105, 125, 205), std::sqrt(109.0) + std::sqrt(104.0), tol);
    EXPECT_NEAR(g.lengthAlongX(110, 120, 205), std::sqrt(25 + 2.25) + std::sqrt(25 + 1.0), tol);
    EXPECT_NEAR(g.lengthAlongX(125, 105, 205), -(std::sqrt(109.0) + std::sqrt(104.0)), tol);
    EXPECT_NEAR(g.lengthAlongX(115, 115, 205), 0.0, tol);
    // beyond the edges the surface is flat (clamped)
    EXPECT_NEAR(g.lengthAlongX(95, 135, 205), 20 + std::sqrt(109.0) + std::sqrt(104.0), tol);
}

// The example DTM of data/slopes is a 30 deg plane with a gully along x: every line y = const is
// straight, of length dx / cos 30. Heights are rounded to 1 mm in the file; along a straight line
// the rounding errors telescope, leaving at most about 2 * 0.5 mm * sin 30 deg: tolerance 1e-3 m.
TEST(ElevationGrid, LengthAlongXOnTheExampleDtm) {
    const ElevationGrid g = ElevationGrid::readAsc(std::string(SYLVAROCK_DATA) + "/slopes/example-dtm.asc");
    EXPECT_EQ(g.columns(), 100);
    EXPECT_EQ(g.rows(), 60);
    const double cos30 = std::cos(std::acos(-1.0) / 6);
    for (const double y : {3.0, 45.5, 60.0, 61.0, 100.0})
        EXPECT_NEAR(g.lengthAlongX(10.0, 180.0, y), 170.0 / cos30, 1e-3) << "y = " << y;
    // across the slope: the gully -3 exp(-((y - 60) / 6)^2 / 2) m, read at the cell centres y = 21
    // and y = 61 (each height rounded to 0.5 mm: tolerance 1e-3 m)
    const auto gully = [](double y) { return -3.0 * std::exp(-0.5 * std::pow((y - 60.0) / 6.0, 2)); };
    EXPECT_NEAR(g.height(101.0, 21.0) - g.height(101.0, 61.0), gully(21.0) - gully(61.0), 1e-3);
}
