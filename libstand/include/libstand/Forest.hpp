#pragma once
// A forest over a whole slope: one row per stem, with the allometry the simulator needs.
// This is what `sylvarock generate` writes and what `sylvarock simulate --forest` reads.
#include <optional>
#include <string>
#include <vector>

namespace sylva::stand {

struct Tree {
    long id = 0;
    double x = 0, y = 0;   // m
    double dbhCm = 0;
    std::string species;
    std::optional<long> stool;  // stems sharing a stool id are clamped together at the base
    double heightM = 0;         // H_T, Eq. 11
    double crownLengthM = 0;    // L_C, Eq. 12
    double crownMassKg = 0;     // m_C, Eq. 13
    long line = 0;              // its line in the file it was read from (0: generated)
};

struct Forest {
    std::vector<Tree> trees;
    std::string source;  // the file it was read from, for messages (empty: generated)
};

// Columns: stem,x,y,dbh_cm,species,stool,height_m,crown_length_m,crown_mass_kg.
void writeForestCsv(const std::string& path, const Forest& forest);
// Reads a forest written by writeForestCsv, or any tree file with at least x,y,dbh_cm (and
// optionally stem, species, stool, height_m, ...), as Rockyfor3D users have: missing allometry is
// computed from the DBH (Eqs. 11-13). Throws InputError with file and line on bad rows.
Forest readForestCsv(const std::string& path);

}  // namespace sylva::stand
