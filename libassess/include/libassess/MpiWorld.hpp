#pragma once
// The processes mpirun (or Slurm's srun) started for one command: which one this is, how many there
// are, and the point-to-point messages a campaign's coordinator and its workers exchange. Built
// without MPI, or started without mpirun, there is one rank and nothing is ever sent.
//
// MPI is process-wide state, so there is one MpiWorld per process: main() makes it, the campaign
// runners find it with MpiWorld::current().
#include <exception>
#include <optional>
#include <string>

namespace sylva::assess {

// Thrown on a rank that stops because another rank failed. That rank says why and exits non-zero,
// which makes mpirun's status; this one leaves quietly and successfully, so that mpirun does not
// end the failed rank before it has printed its message.
struct PeerFailed : std::exception {
    const char* what() const noexcept override { return "another MPI rank failed"; }
};

class MpiWorld {
public:
    struct Message {
        int source = 0, tag = 0;
        std::string bytes;
    };

    // Starts MPI when the environment says mpirun or srun started this process (OMPI_COMM_WORLD_SIZE,
    // PMIX_RANK, PMI_SIZE). Throws InputError when several ranks were started and this build has no MPI
    // (each would run the whole campaign into the same folder).
    MpiWorld(int* argc, char*** argv);
    ~MpiWorld();
    MpiWorld(const MpiWorld&) = delete;
    MpiWorld& operator=(const MpiWorld&) = delete;

    // The process's world; a single rank if main() made none (the tests).
    static const MpiWorld& current();
    static bool builtWithMpi();

    int rank() const { return rank_; }
    int size() const { return size_; }
    bool coordinator() const { return rank_ == 0; }

    // Messages of the campaign runners, on a communicator of their own. Callers serialise (the
    // threads of a rank take turns); MPI is started with MPI_THREAD_SERIALIZED for that.
    void send(int to, int tag, const std::string& bytes) const;
    Message receive(int from) const;     // blocks until a message from `from` arrives
    std::optional<Message> poll() const;  // a message from any rank, if one is waiting

    // Every rank reports how its setup went (nullptr: ready); returns if all are ready. Otherwise rank
    // 0 rethrows its own error, or one naming the ranks that failed; another rank rethrows its own
    // error if rank 0 was ready, and throws PeerFailed if not (rank 0 has said why).
    void agree(std::exception_ptr mine) const;
    // `read()` on this rank (reading options or inputs), then agree() on how it went: its value, or
    // the exception agree() throws.
    template <class Read>
    auto agreeOn(Read&& read) const -> decltype(read()) {
        decltype(read()) value{};
        std::exception_ptr failure;
        try {
            value = read();
        } catch (...) {
            failure = std::current_exception();
        }
        agree(failure);
        return value;
    }

private:
    MpiWorld() = default;  // one rank, MPI not started
    int rank_ = 0, size_ = 1;
    [[maybe_unused]] bool started_ = false;  // MPI_Init was called (read only in an MPI build)
};

}  // namespace sylva::assess
