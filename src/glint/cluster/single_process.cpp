// A job of one process: every collective returns this process's own data.
#include <glint/cluster/cluster.h>

#include <cstdio>
#include <cstdlib>

namespace glint {

namespace {

class SingleProcess final : public Cluster {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> all_gather_text(const std::string& text) override { return {text}; }
    std::vector<std::vector<uint8_t>> all_gather_bytes(const std::vector<uint8_t>& bytes) override {
        return {bytes};
    }
    [[noreturn]] void abort(const std::string& message) override {
        std::fprintf(stderr, "glint: error: %s\n", message.c_str());
        std::exit(1);
    }
    std::vector<std::vector<float>> gather_to_root(const std::vector<float>& values) override {
        return {values};
    }
    void send_progress(const ProgressReport&) override {}
    ProgressReport receive_progress() override { return {0, true}; }
    uint64_t bytes_exchanged() const override { return 0; }
    double exchange_seconds() const override { return 0.0; }
};

}  // namespace

std::unique_ptr<Cluster> make_single_process() {
    return std::make_unique<SingleProcess>();
}

}  // namespace glint
