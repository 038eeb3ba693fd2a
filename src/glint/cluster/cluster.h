#pragma once
// The processes of one job: a single process, or the ranks of an MPI job (`mpirun -np N
// glint render ...`). The rest of glint talks to the other ranks only through this
// interface; the MPI API itself stays in mpi_cluster.cpp. See docs/cluster.md.
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace glint {

class Cluster {
public:
    virtual ~Cluster() = default;
    /// This process's number, 0 .. size() - 1; rank 0 writes the outputs.
    virtual int rank() const = 0;
    virtual int size() const = 0;
    /// Collective: every rank's `text`, in rank order, on every rank.
    virtual std::vector<std::string> all_gather_text(const std::string& text) = 0;
    /// Collective: every rank's `bytes`, in rank order, on every rank (the counts may differ).
    virtual std::vector<std::vector<uint8_t>> all_gather_bytes(
        const std::vector<uint8_t>& bytes) = 0;
    /// Ends the whole job at once, after printing "glint: error: rank R: `message`": for a
    /// failure inside a collective exchange, which the other ranks would wait for forever.
    [[noreturn]] virtual void abort(const std::string& message) = 0;
    /// Collective: on rank 0, every rank's `values` in rank order (the counts may differ);
    /// empty on the other ranks.
    virtual std::vector<std::vector<float>> gather_to_root(const std::vector<float>& values) = 0;
    /// A rank's report of work done, for rank 0's progress line of the whole job.
    struct ProgressReport {
        uint64_t work = 0;   ///< units done since the rank's previous report
        bool final = false;  ///< the rank's last report
    };
    /// Sends a report to rank 0 (ranks other than 0). Called by one thread while no other
    /// thread of this process uses the cluster.
    virtual void send_progress(const ProgressReport& report) = 0;
    /// Rank 0: waits for the next report from any other rank (same thread rule).
    virtual ProgressReport receive_progress() = 0;
    /// This rank's share [first, end) of `count` items: consecutive ranges in rank order, as
    /// equal as they can be, so that the ranks' results in rank order are the items' order.
    std::pair<uint64_t, uint64_t> share(uint64_t count) const { return share_of(rank(), count); }
    /// Rank `r`'s share of `count` items (share() on that rank).
    std::pair<uint64_t, uint64_t> share_of(int r, uint64_t count) const {
        const auto boundary = [&](int b) {
            // count * b stays below 2^64 for any count a pass or an image has (< 2^40).
            return count * static_cast<uint64_t>(b) / static_cast<uint64_t>(size());
        };
        return {boundary(r), boundary(r + 1)};
    }
    /// Bytes this process has sent to and received from the others so far.
    virtual uint64_t bytes_exchanged() const = 0;
    /// Seconds this process has spent in the collectives (exchanging, and waiting for the
    /// slowest rank), for the speed-up model of docs/cluster.md.
    virtual double exchange_seconds() const = 0;
};

/// A job of one process.
std::unique_ptr<Cluster> make_single_process();

/// The MPI job this process was started in by mpirun (MPI is initialised here and finalised
/// when the Cluster is destroyed), or a single process when glint was built without MPI or
/// not started by mpirun. `argc` and `argv` are MPI_Init's.
std::unique_ptr<Cluster> make_cluster(int& argc, char**& argv);

/// Whether this glint was built with MPI.
bool cluster_has_mpi();

}  // namespace glint
