#pragma once
// A DTM read from an ESRI ASCII grid (.asc): ncols, nrows, xllcorner|xllcenter,
// yllcorner|yllcenter, cellsize, optional NODATA_value, then nrows lines of ncols values, north
// first. Heights are bilinear between cell centres, so the surface is defined on the rectangle of
// the cell centres; outside it the nearest edge value is used (constant extrapolation).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace sylva::dem {

class ElevationGrid {
public:
    // Errors (bad or missing header key, non-numeric value, a row with the wrong number of values,
    // too few or too many rows, a height beyond Earth's relief or an impossible step from a neighbour:
    // an undeclared NODATA, refuseUndeclaredNoData) name the file and the line. NODATA cells are
    // accepted here and rejected only where a height is needed (see requireDefined).
    static ElevationGrid readAsc(const std::string& path);
    // A grid read by someone else (e.g. GDAL): `z` row-major with row 0 the southernmost, NaN for
    // NODATA; (x0, y0) the centre of the south-west cell. Errors about a NODATA cell then name the
    // cell (column and row counted from 1 at the north-west corner) in `source`.
    // Throws std::invalid_argument on fewer than 2 x 2 cells, a size mismatch or a cell size <= 0;
    // InputError naming the cell of a height beyond Earth's relief (an undeclared NODATA).
    static ElevationGrid fromValues(int columns, int rows, double x0, double y0, double cellSize, std::vector<double> z,
                                    std::string source);

    // Bilinear between cell centres; throws InputError naming the file and line of a NODATA cell
    // that the interpolation at (x, y) needs. Non-finite coordinates give NaN (here and below).
    double height(double x, double y) const;
    // (dz/dx, dz/dy) of the bilinear surface in the cell holding (x, y); zero across a clamped edge.
    Eigen::Vector2d gradient(double x, double y) const;
    // Length of the surface line y = const from x0 to x1 (negative if x1 < x0). Exact: along a
    // line of constant y the bilinear surface is piecewise linear with kinks at cell-centre columns.
    double lengthAlongX(double x0, double x1, double y) const;
    // Throws InputError (file, line, cell) if a cell whose value enters the interpolation anywhere
    // in [x0, x1] x [y0, y1] is NODATA; std::invalid_argument if a bound is not finite.
    void requireDefined(double x0, double x1, double y0, double y1) const;

    // Throws InputError naming the lower of two neighbouring cells whose step no terrain has
    // (impossibleStep: an undeclared NODATA within Earth's relief beside real ground). For grids read
    // from a user's file; a grid made here (micro-topography) is not the file's to blame.
    void refuseUndeclaredNoData() const;

    long noDataCells() const;  // how many cells have no height
    double xmin() const { return x0_; }
    double xmax() const { return x0_ + (ncols_ - 1) * cell_; }
    double ymin() const { return y0_; }
    double ymax() const { return y0_ + (nrows_ - 1) * cell_; }
    double cellSize() const { return cell_; }
    int columns() const { return ncols_; }
    int rows() const { return nrows_; }
    const std::string& source() const { return source_; }
    // Every cell's height, row-major with row 0 the southernmost, NaN for NODATA.
    const std::vector<double>& values() const { return z_; }

private:
    struct CellRange {
        int c0, c1, r0, r1;
    };
    CellRange cellsUnder(double x0, double x1, double y0, double y1) const;
    double at(int col, int row) const { return z_[static_cast<std::size_t>(row) * ncols_ + col]; }
    [[noreturn]] void failNoData(int col, int row) const;
    // Where a cell is named in an error: its file line and value, or its column and row.
    std::string cellPlace(int col, int row) const;

    int ncols_ = 0, nrows_ = 0;
    double x0_ = 0, y0_ = 0, cell_ = 1;  // centre of the south-west cell
    std::vector<double> z_;              // row-major, row 0 = south; NODATA stored as NaN
    bool complete_ = false;              // no NODATA cell: heights need no check (a hazard DTM is queried millions of times)
    std::string source_;                 // file name, for errors raised after reading
    std::vector<long> rowLine_;          // line of each row in the file (row 0 = south); empty: not read from text
};

}  // namespace sylva::dem
