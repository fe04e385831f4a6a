#pragma once
// Everything a scene file sets. Defaults are the paper's Table 2 and Sect. 2.3.2.
#include <set>
#include <string>
#include <vector>

#include "libcommon/InputError.hpp"

#include "libdem/BlockShape.hpp"
#include "libdem/LumpedParams.hpp"
#include "libdem/MicroTopography.hpp"
#include "libdem/SoilContact.hpp"
#include "libdem/StemContact.hpp"
#include "libdem/StemParams.hpp"
#include "libdem/Terrain.hpp"

namespace sylva::dem {

struct TerrainConfig {
    std::string profile;  // slope profile CSV (x,z); paths are relative to the scene file
    std::string dtm;      // or an ESRI ASCII grid
    SoilBedParams soil;
    MicroTopographyParams micro;  // added to a DTM (its seed is soil.seed)
};

struct ReleaseConfig {
    double x = 100;             // m (Sect. 2.3.2)
    double y = 100;             // m, used when yMin == yMax
    double yMin = 100, yMax = 100;  // y drawn uniformly in [yMin, yMax] when yRangeGiven
    bool yRangeGiven = false;
    double forestYMin = 80, forestYMax = 120;  // the range used in forest runs unless one is given
    double fallHeight = 5;      // centre of the block above the surface, m
    bool randomOrientation = true;  // angles uniform in [0, 180 deg) about x, y, z (Sect. 2.3.2)
};

// A block launched at one tree (single-tree scenes): instead of a release from rest, the block
// starts `distance` before the stem, its centre `impactHeight` above the ground, offset across
// its path by eccentricity x (block radius + stem radius), moving at `speed` along +x.
struct LaunchConfig {
    bool enabled = false;
    double speed = 15;          // m/s
    double impactHeight = 1;    // m above the stem's foot
    double eccentricity = 0;    // in [-1, 1]
    double distance = 1.5;      // m between the block's centre and the stem's axis at the start
};

// One tree of a single-tree scene (replaces any forest file).
struct SingleTreeConfig {
    bool enabled = false;
    double dbhCm = 25;
    double x = 20, y = 10;      // m
    bool coppice = false;       // clamped foot (a coppice stem) instead of the root spring
};

struct IntegrationConfig {
    double safety = 0.3;        // dt = safety x stable limit of the block's springs
    double stemSafety = 0.95;   // and at most stemSafety x the awake stems' limit with their contacts (Stem::stability: within 2 % of a calibrated stem's own)
    double forcedDt = 0;        // > 0: use this step (refused if above the stable limit)
    int anticipatedContacts = 4;  // the step stays stable for this many new contacts at once
    double energyTolerance = 0.1;  // audit: relative energy growth that stops a run (SimulationError)
    double energyWarning = 0.05;   // audit: a run whose imbalance exceeds this is flagged (runs.csv energy_flag)
};

struct StopConfig {
    double restDistance = 0.05;  // m: the block rests once its centre stays this close to one point
    double restTime = 1.0;       // s it must stay so
    double maxTime = 300;       // s of simulated time
};

// When a stem is built into the simulation, when it rests and when it is put back to sleep (BlockMotion).
struct ForestActivity {
    double wakeMargin = 0.1;    // m: a stem wakes when the block's bounding sphere comes this close (plus one step's travel)
    double returnHorizon = 0.1;  // s: a moving stem the block cannot reach within this time stops where it stands
    double sleepAfter = 0.025;  // s without block contact, the block out of reach, before a stem sleeps again (docs/accuracy.md: 0.0125-1 s give one PF50)
    // A broken stem's pieces fall on: it sleeps only once every node is slower than this, m/s,
    double pieceRestSpeed = 0.2;
    // or this long after the block's last contact, s (a piece rolling downslope). 0: a broken stem
    // sleeps as a whole one does. Off by default until stems step at their own rate (issue 12): an
    // awake piece holds the whole run to the stems' step (docs/model-stems.md).
    double pieceMaxTime = 0;
    bool allAwake = false;      // reference mode: every stem awake from the start (small forests only)
};

struct SceneConfig {
    std::string sourceFile;     // the scene file, for messages
    std::string sourceText;     // its text, for the line of a key a refusal names
    std::set<std::string> setKeys;  // the keys --set gave, which a refusal names instead of the file

    // A refusal of what these keys set, found after loading (a release outside the terrain): it names
    // the first of them --set gave, or else the scene file's line of the first it holds.
    InputError refusal(const std::vector<const char*>& keys, const std::string& what) const;
    TerrainConfig terrain;
    std::string forestFile;     // forest CSV (sylvarock generate's, or x,y,dbh_cm[,stool]); empty: no forest
    std::string stemParameters = "calibrated";  // the named set the stem's defaults came from
    StemParams stem;
    StemContactParams stemContact;
    ForestActivity activity;
    SoilContactParams soilContact;
    BlockSpec block;
    ReleaseConfig release;
    LaunchConfig launch;
    SingleTreeConfig tree;
    IntegrationConfig integration;
    StopConfig stop;
    LumpedParams lumped;        // the lumped-mass model's soil and trees ([lumped])
    double gravity = 9.81;
    double trajectoryInterval = 0.05;  // s between trajectory samples
};

// Reads a scene INI file ([section] key = value) and then the overrides "section.key=value"
// (which win). Unknown keys, bad values and missing files are InputErrors naming the file.
SceneConfig loadScene(const std::string& path, const std::vector<std::string>& overrides = {});
// The same with no file (defaults + overrides), for tests and scenes built in code.
SceneConfig sceneFromOverrides(const std::vector<std::string>& overrides);
// All keys with their defaults and meaning, for `sylvarock simulate --help-scene`.
std::string describeSceneKeys();
// The keys that hold a number with a physical range (refused outside it, with the key and the range).
std::vector<std::string> sceneNumberKeys();

}  // namespace sylva::dem
