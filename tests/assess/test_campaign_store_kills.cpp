// Issue 13: a campaign killed at any moment is resumed to the results of one never interrupted. The
// kill is put at every write the campaign store makes, one campaign per write: a VFS shim around
// SQLite's own (the layer all of SQLite's file I/O goes through) counts each write, sync, truncation
// and deletion, and at the k-th writes half of it (a torn write) then SIGKILLs its process. The
// parent then resumes the campaign in the same folder and compares results.json byte for byte.
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>
#include <string>

#include "ShortCampaign.hpp"
#include "libassess/Assessment.hpp"
#include "libassess/Report.hpp"

namespace fs = std::filesystem;
using namespace sylva::assess;

namespace {

// --- the killing VFS: forwards everything to the default VFS, counting what changes the disk ---
int gKillAt = 0;  // 1-based index of the write that is cut; 0: never
int gWrites = 0;
sqlite3_vfs* gReal = nullptr;
sqlite3_vfs gKiller;
sqlite3_io_methods gMethods;

struct KillerFile {
    sqlite3_file base;
    sqlite3_file* real;  // allocated right after this struct (szOsFile covers both)
};

sqlite3_file* real(sqlite3_file* f) { return reinterpret_cast<KillerFile*>(f)->real; }

// Called before each change to the disk; `tear` writes part of it first, as a kill mid-write does.
void nextWrite(const std::function<void()>& tear = {}) {
    if (++gWrites != gKillAt) return;
    if (tear) tear();
    ::kill(::getpid(), SIGKILL);
}

int kWrite(sqlite3_file* f, const void* data, int amount, sqlite3_int64 offset) {
    nextWrite([&] { real(f)->pMethods->xWrite(real(f), data, amount / 2, offset); });
    return real(f)->pMethods->xWrite(real(f), data, amount, offset);
}
int kTruncate(sqlite3_file* f, sqlite3_int64 size) {
    nextWrite();
    return real(f)->pMethods->xTruncate(real(f), size);
}
int kSync(sqlite3_file* f, int flags) {
    nextWrite();
    return real(f)->pMethods->xSync(real(f), flags);
}
int kClose(sqlite3_file* f) { return real(f)->pMethods->xClose(real(f)); }
int kRead(sqlite3_file* f, void* data, int amount, sqlite3_int64 offset) { return real(f)->pMethods->xRead(real(f), data, amount, offset); }
int kFileSize(sqlite3_file* f, sqlite3_int64* size) { return real(f)->pMethods->xFileSize(real(f), size); }
int kLock(sqlite3_file* f, int level) { return real(f)->pMethods->xLock(real(f), level); }
int kUnlock(sqlite3_file* f, int level) { return real(f)->pMethods->xUnlock(real(f), level); }
int kCheckReservedLock(sqlite3_file* f, int* out) { return real(f)->pMethods->xCheckReservedLock(real(f), out); }
int kFileControl(sqlite3_file* f, int op, void* arg) { return real(f)->pMethods->xFileControl(real(f), op, arg); }
int kSectorSize(sqlite3_file* f) { return real(f)->pMethods->xSectorSize(real(f)); }
int kDeviceCharacteristics(sqlite3_file* f) { return real(f)->pMethods->xDeviceCharacteristics(real(f)); }
int kShmMap(sqlite3_file* f, int region, int size, int extend, void volatile** p) {
    return real(f)->pMethods->xShmMap(real(f), region, size, extend, p);
}
int kShmLock(sqlite3_file* f, int offset, int n, int flags) { return real(f)->pMethods->xShmLock(real(f), offset, n, flags); }
void kShmBarrier(sqlite3_file* f) { real(f)->pMethods->xShmBarrier(real(f)); }
int kShmUnmap(sqlite3_file* f, int deleteFlag) { return real(f)->pMethods->xShmUnmap(real(f), deleteFlag); }

int kOpen(sqlite3_vfs*, const char* name, sqlite3_file* f, int flags, int* outFlags) {
    auto* file = reinterpret_cast<KillerFile*>(f);
    file->real = reinterpret_cast<sqlite3_file*>(file + 1);
    const int rc = gReal->xOpen(gReal, name, file->real, flags, outFlags);
    f->pMethods = file->real->pMethods ? &gMethods : nullptr;
    return rc;
}
int kDelete(sqlite3_vfs*, const char* name, int syncDir) {
    nextWrite();
    return gReal->xDelete(gReal, name, syncDir);
}

// Made the default VFS of this process (a forked child's only).
void installKiller(int killAt) {
    gKillAt = killAt;
    gReal = sqlite3_vfs_find(nullptr);
    gMethods = sqlite3_io_methods{};
    gMethods.iVersion = 2;  // with the shared-memory methods WAL needs; no memory-mapped I/O
    gMethods.xClose = kClose;
    gMethods.xRead = kRead;
    gMethods.xWrite = kWrite;
    gMethods.xTruncate = kTruncate;
    gMethods.xSync = kSync;
    gMethods.xFileSize = kFileSize;
    gMethods.xLock = kLock;
    gMethods.xUnlock = kUnlock;
    gMethods.xCheckReservedLock = kCheckReservedLock;
    gMethods.xFileControl = kFileControl;
    gMethods.xSectorSize = kSectorSize;
    gMethods.xDeviceCharacteristics = kDeviceCharacteristics;
    gMethods.xShmMap = kShmMap;
    gMethods.xShmLock = kShmLock;
    gMethods.xShmBarrier = kShmBarrier;
    gMethods.xShmUnmap = kShmUnmap;
    gKiller = *gReal;
    gKiller.zName = "sylvarock-kill-at-write";
    gKiller.szOsFile = static_cast<int>(sizeof(KillerFile)) + gReal->szOsFile;
    gKiller.xOpen = kOpen;
    gKiller.xDelete = kDelete;
    gKiller.pNext = nullptr;
    if (sqlite3_vfs_register(&gKiller, 1) != SQLITE_OK) _exit(4);
}


AssessmentOptions options(const fs::path& out, bool resume) {
    AssessmentOptions o = shortCampaign(out, 2, 1, 2, 5);
    o.resume = resume;
    o.threads = 1;
    o.bootstrapReplicates = 100;
    return o;
}

}  // namespace

TEST(CampaignStoreKills, AKillAtEveryWriteIsResumedToTheSameResults) {
    const fs::path root = fs::temp_directory_path() / "sylvarock-store-kills";
    fs::remove_all(root);
    writeResultsJson((root / "whole.json").string(), runAssessment(options(root / "whole", false)));
    const std::string whole = slurp(root / "whole.json");

    int kills = 0;
    for (int k = 1;; ++k) {
        const fs::path dir = root / ("killed-at-" + std::to_string(k));
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            installKiller(k);
            try {
                runAssessment(options(dir, false));
            } catch (...) {
                _exit(3);
            }
            _exit(0);
        }
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        if (WIFEXITED(status)) {  // k is past the campaign's last write: every write has been cut
            EXPECT_EQ(WEXITSTATUS(status), 0) << "the campaign failed without a kill, at k = " << k;
            break;
        }
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "k = " << k;
        ++kills;
        try {
            writeResultsJson((dir / "results.json").string(), runAssessment(options(dir, true)));
        } catch (const std::exception& e) {
            FAIL() << "killed at write " << k << ", the resume failed: " << e.what();
        }
        EXPECT_EQ(slurp(dir / "results.json"), whole) << "killed at write " << k;
        fs::remove_all(dir);
    }
    // The design, the plan, 6 runs and 2 forests' statistics, then the checkpoint at the close: a
    // count far below this would mean the shim missed SQLite's writes.
    EXPECT_GE(kills, 15);
    std::printf("killed at each of %d writes; every campaign resumed to identical results\n", kills);
    fs::remove_all(root);
}
