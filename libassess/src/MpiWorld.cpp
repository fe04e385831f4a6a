#include "libassess/MpiWorld.hpp"

#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "libcommon/InputError.hpp"

#ifdef SYLVAROCK_HAVE_MPI
#include <mpi.h>
#endif

namespace sylva::assess {

namespace {

const MpiWorld* theWorld = nullptr;

// The number of processes the launcher says it started (0: not known, or not launched by one).
int launchedSize() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
        if (const char* v = std::getenv(name)) return std::atoi(v);
    return 0;
}

#ifdef SYLVAROCK_HAVE_MPI
bool launchedByMpi() { return launchedSize() > 0 || std::getenv("PMIX_RANK") != nullptr; }

MPI_Comm runners = MPI_COMM_NULL;

void check(int code, const char* call) {
    if (code == MPI_SUCCESS) return;
    char text[MPI_MAX_ERROR_STRING];
    int length = 0;
    MPI_Error_string(code, text, &length);
    throw std::runtime_error(std::string(call) + " failed: " + std::string(text, length));
}
#endif

}  // namespace

MpiWorld::MpiWorld(int* argc, char*** argv) {
#ifdef SYLVAROCK_HAVE_MPI
    if (launchedByMpi()) {
        int provided = 0;
        check(MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided), "MPI_Init_thread");
        started_ = true;
        if (provided < MPI_THREAD_SERIALIZED)
            throw std::runtime_error("the MPI library offers no MPI_THREAD_SERIALIZED: several threads per rank cannot share it");
        MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
        check(MPI_Comm_dup(MPI_COMM_WORLD, &runners), "MPI_Comm_dup");
        MPI_Comm_rank(runners, &rank_);
        MPI_Comm_size(runners, &size_);
    }
#else
    (void)argc;
    (void)argv;
    if (launchedSize() > 1)
        throw InputError("mpirun started " + std::to_string(launchedSize()) +
                         " processes of a sylvarock built without MPI: each would run the whole campaign. Install "
                         "libopenmpi-dev (scripts/install-deps.sh) and rebuild, or run without mpirun");
#endif
    theWorld = this;
}

MpiWorld::~MpiWorld() {
    if (theWorld == this) theWorld = nullptr;
#ifdef SYLVAROCK_HAVE_MPI
    if (started_) {
        MPI_Comm_free(&runners);
        MPI_Finalize();
    }
#endif
}

const MpiWorld& MpiWorld::current() {
    static const MpiWorld single;
    return theWorld ? *theWorld : single;
}

bool MpiWorld::builtWithMpi() {
#ifdef SYLVAROCK_HAVE_MPI
    return true;
#else
    return false;
#endif
}

#ifdef SYLVAROCK_HAVE_MPI

void MpiWorld::send(int to, int tag, const std::string& bytes) const {
    check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, runners), "MPI_Send");
}

namespace {
MpiWorld::Message receiveProbed(const MPI_Status& probed) {
    int count = 0;
    MPI_Get_count(&probed, MPI_BYTE, &count);
    MpiWorld::Message m;
    m.source = probed.MPI_SOURCE;
    m.tag = probed.MPI_TAG;
    m.bytes.resize(static_cast<std::size_t>(count));
    check(MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.source, m.tag, runners, MPI_STATUS_IGNORE), "MPI_Recv");
    return m;
}
}  // namespace

MpiWorld::Message MpiWorld::receive(int from) const {
    MPI_Status status;
    check(MPI_Probe(from, MPI_ANY_TAG, runners, &status), "MPI_Probe");
    return receiveProbed(status);
}

std::optional<MpiWorld::Message> MpiWorld::poll() const {
    int waiting = 0;
    MPI_Status status;
    check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, runners, &waiting, &status), "MPI_Iprobe");
    if (!waiting) return std::nullopt;
    return receiveProbed(status);
}

void MpiWorld::agree(std::exception_ptr mine) const {
    std::vector<int> failed(static_cast<std::size_t>(size_), 0);
    if (started_) {
        const int mineFailed = mine ? 1 : 0;
        check(MPI_Allgather(&mineFailed, 1, MPI_INT, failed.data(), 1, MPI_INT, runners), "MPI_Allgather");
    }
    // Bad input usually fails every rank alike: rank 0 says it once, the others leave quietly.
    if (mine && (rank_ == 0 || !failed[0])) std::rethrow_exception(mine);
    if (rank_ != 0 && failed[0]) throw PeerFailed();
    std::string ranks;
    for (int r = 1; r < size_; ++r)
        if (failed[static_cast<std::size_t>(r)]) ranks += (ranks.empty() ? "" : ", ") + std::to_string(r);
    if (ranks.empty()) return;
    if (rank_ == 0) throw std::runtime_error("MPI rank(s) " + ranks + " could not start (their messages are above)");
    throw PeerFailed();
}

#else

void MpiWorld::send(int, int, const std::string&) const { throw std::logic_error("MpiWorld::send: built without MPI"); }
MpiWorld::Message MpiWorld::receive(int) const { throw std::logic_error("MpiWorld::receive: built without MPI"); }
std::optional<MpiWorld::Message> MpiWorld::poll() const { return std::nullopt; }
void MpiWorld::agree(std::exception_ptr mine) const {
    if (mine) std::rethrow_exception(mine);
}

#endif

}  // namespace sylva::assess
