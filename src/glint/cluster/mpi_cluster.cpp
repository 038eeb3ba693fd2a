// The MPI job: the only file that speaks MPI. Collectives on MPI_COMM_WORLD; Open MPI's
// default error handler aborts the whole job when a rank dies, so a killed rank ends the run
// (mpirun names the rank and the signal) instead of leaving the others waiting.
#include <glint/cluster/cluster.h>
#include <glint/core/error.h>

#include <fmt/format.h>
#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace glint {

namespace {

constexpr int kProgressTag = 1;

// Adds the seconds of its scope to a total.
class Timer {
public:
    explicit Timer(double& total) : m_total(total), m_start(MPI_Wtime()) {}
    ~Timer() { m_total += MPI_Wtime() - m_start; }
    Timer(const Timer&) = delete;
    Timer& operator=(const Timer&) = delete;

private:
    double& m_total;
    double m_start;
};

class MpiCluster final : public Cluster {
public:
    MpiCluster(int& argc, char**& argv) {
        // The progress relay's thread talks to rank 0 while the render's thread exchanges
        // photons (sppm).
        int provided = 0;
        MPI_Init_thread(&argc, &argv, MPI_THREAD_MULTIPLE, &provided);
        m_threads = provided >= MPI_THREAD_MULTIPLE;
        MPI_Comm_rank(MPI_COMM_WORLD, &m_rank);
        MPI_Comm_size(MPI_COMM_WORLD, &m_size);
    }
    ~MpiCluster() override { MPI_Finalize(); }
    MpiCluster(const MpiCluster&) = delete;
    MpiCluster& operator=(const MpiCluster&) = delete;

    int rank() const override { return m_rank; }
    int size() const override { return m_size; }

    std::vector<std::string> all_gather_text(const std::string& text) override {
        const Timer timer(m_seconds);
        const int length = static_cast<int>(text.size());
        std::vector<int> lengths(m_size);
        MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
        std::vector<int> offsets(m_size, 0);
        for (int r = 1; r < m_size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
        std::string all(static_cast<size_t>(offsets.back() + lengths.back()), '\0');
        MPI_Allgatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(),
                       MPI_CHAR, MPI_COMM_WORLD);
        m_bytes += static_cast<uint64_t>(m_size - 1) * (sizeof(int) + text.size()) + all.size() -
                   text.size();
        std::vector<std::string> texts;
        for (int r = 0; r < m_size; ++r) texts.push_back(all.substr(offsets[r], lengths[r]));
        return texts;
    }

    std::vector<std::vector<uint8_t>> all_gather_bytes(const std::vector<uint8_t>& bytes) override {
        const Timer timer(m_seconds);
        if (bytes.size() > static_cast<size_t>(INT32_MAX))
            throw Error("cluster: more than 2^31 bytes in one exchange");
        const int count = static_cast<int>(bytes.size());
        std::vector<int> counts(m_size);
        MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
        std::vector<int> offsets(m_size, 0);
        int64_t total = counts[0];
        for (int r = 1; r < m_size; ++r) {
            offsets[r] = offsets[r - 1] + counts[r - 1];
            total += counts[r];
        }
        if (total > INT32_MAX) throw Error("cluster: more than 2^31 bytes in one exchange");
        std::vector<uint8_t> all(static_cast<size_t>(total));
        MPI_Allgatherv(bytes.data(), count, MPI_BYTE, all.data(), counts.data(), offsets.data(),
                       MPI_BYTE, MPI_COMM_WORLD);
        m_bytes += static_cast<uint64_t>(m_size - 1) * bytes.size() +
                   (static_cast<uint64_t>(total) - bytes.size());
        std::vector<std::vector<uint8_t>> result;
        for (int r = 0; r < m_size; ++r)
            result.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
        return result;
    }

    [[noreturn]] void abort(const std::string& message) override {
        std::fprintf(stderr, "glint: error: rank %d: %s\n", m_rank, message.c_str());
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, 1);
        std::exit(1);  // MPI_Abort does not return; this tells the compiler so
    }

    bool threads_supported() const { return m_threads; }

    std::vector<std::vector<float>> gather_to_root(const std::vector<float>& values) override {
        const Timer timer(m_seconds);
        const int count = static_cast<int>(values.size());
        if (values.size() > static_cast<size_t>(INT32_MAX))
            throw Error("cluster: an image of more than 2^31 values cannot be gathered");
        std::vector<int> counts(m_size);
        MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
        std::vector<int> offsets(m_size, 0);
        std::vector<float> all;
        if (m_rank == 0) {
            int64_t total = counts[0];
            for (int r = 1; r < m_size; ++r) {
                offsets[r] = offsets[r - 1] + counts[r - 1];
                total += counts[r];
            }
            if (total > INT32_MAX)
                throw Error("cluster: the ranks' images hold more than 2^31 values together");
            all.resize(static_cast<size_t>(total));
        }
        MPI_Gatherv(values.data(), count, MPI_FLOAT, all.data(), counts.data(), offsets.data(),
                    MPI_FLOAT, 0, MPI_COMM_WORLD);
        std::vector<std::vector<float>> result;
        if (m_rank != 0) {
            m_bytes += values.size() * sizeof(float);
            return result;
        }
        for (int r = 0; r < m_size; ++r) {
            result.emplace_back(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
            if (r > 0) m_bytes += static_cast<uint64_t>(counts[r]) * sizeof(float);
        }
        return result;
    }

    void send_progress(const ProgressReport& report) override {
        const uint64_t message[2] = {report.work, report.final ? 1u : 0u};
        MPI_Send(message, 2, MPI_UINT64_T, 0, kProgressTag, MPI_COMM_WORLD);
        m_bytes += sizeof(message);
    }

    ProgressReport receive_progress() override {
        uint64_t message[2] = {0, 0};
        MPI_Recv(message, 2, MPI_UINT64_T, MPI_ANY_SOURCE, kProgressTag, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        m_bytes += sizeof(message);
        return {message[0], message[1] != 0};
    }

    uint64_t bytes_exchanged() const override { return m_bytes; }
    double exchange_seconds() const override { return m_seconds; }

private:
    int m_rank = 0, m_size = 1;
    bool m_threads = false;
    double m_seconds = 0.0;  // in the collectives (not the progress messages)
    uint64_t m_bytes = 0;
};

// mpirun (Open MPI, MPICH, Slurm's PMI) tells its processes their number in the job.
bool started_by_mpirun() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") ||
           std::getenv("PMIX_RANK");
}

}  // namespace

std::unique_ptr<Cluster> make_cluster(int& argc, char**& argv) {
    if (!started_by_mpirun()) return make_single_process();
    auto cluster = std::make_unique<MpiCluster>(argc, argv);
    if (!cluster->threads_supported()) {
        cluster->abort(
            "this MPI library lacks MPI_THREAD_MULTIPLE, which glint's progress "
            "relay needs (Debian's Open MPI has it)");
    }
    return cluster;
}

bool cluster_has_mpi() {
    return true;
}

}  // namespace glint
