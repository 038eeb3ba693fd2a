#include <glint/core/error.h>
#include <glint/core/progress.h>
#include <glint/film/output_batch.h>
#include <glint/integrator/tile/tile_integrator.h>
#include <glint/render/distributed_render.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <tuple>

namespace glint {

namespace {

// Relays this rank's progress while it renders: ranks other than 0 send what they did every
// quarter second, rank 0 adds what the others send to the job's line. Ends (joins) when
// every rank has finished, failed or not; only then may the main thread use the cluster.
class ProgressRelay {
public:
    ProgressRelay(Cluster& cluster, Progress& progress)
        : m_cluster(cluster), m_progress(progress), m_thread([this] { run(); }) {}
    ~ProgressRelay() { finish(); }
    ProgressRelay(const ProgressRelay&) = delete;
    ProgressRelay& operator=(const ProgressRelay&) = delete;

    void finish() {
        m_done = true;
        if (m_thread.joinable()) m_thread.join();
    }

private:
    void run() {
        if (m_cluster.rank() != 0) {
            uint64_t sent = 0;
            for (bool last = false; !last;) {
                last = m_done.load();
                if (!last) std::this_thread::sleep_for(std::chrono::milliseconds(250));
                const uint64_t done = m_progress.done();
                m_cluster.send_progress({done - sent, last});
                sent = done;
            }
            return;
        }
        for (int finished = 0; finished < m_cluster.size() - 1;) {
            const Cluster::ProgressReport report = m_cluster.receive_progress();
            finished += report.final ? 1 : 0;
            try {
                m_progress.advance(report.work);
            } catch (const Interrupted&) {
                // Rank 0's own render stops on the signal; the relay keeps listening.
            }
        }
    }

    Cluster& m_cluster;
    Progress& m_progress;
    std::atomic<bool> m_done{false};
    std::thread m_thread;
};

// What a rank sends with its status: its partial render's attributes, one per line.
std::string attributes_text(const Image& image) {
    std::string text;
    for (const auto& [name, value] : image.attributes) text += name + "=" + value + "\n";
    return text;
}

std::vector<std::pair<std::string, std::string>> parse_attributes(const std::string& text) {
    std::vector<std::pair<std::string, std::string>> attributes;
    size_t start = 0;
    while (start < text.size()) {
        const size_t end = text.find('\n', start);
        const std::string line = text.substr(start, end - start);
        const size_t equals = line.find('=');
        if (equals != std::string::npos)
            attributes.emplace_back(line.substr(0, equals), line.substr(equals + 1));
        start = end == std::string::npos ? text.size() : end + 1;
    }
    return attributes;
}

// "ok\n<attributes>" or "error\n<message>".
constexpr const char* kOk = "ok\n";
constexpr const char* kFailed = "error\n";

}  // namespace

SampleRange rank_share(int spp, int rank, int ranks) {
    const auto boundary = [&](int r) {
        return static_cast<int>(static_cast<int64_t>(spp) * r / ranks);
    };
    return {boundary(rank), boundary(rank + 1)};
}

namespace {

// Collective: throws, on every rank, naming each rank whose status is a failure.
std::vector<std::string> agree(Cluster& cluster, const std::string& status) {
    const std::vector<std::string> statuses = cluster.all_gather_text(status);
    std::string failures;
    size_t failed = 0;
    for (size_t r = 0; r < statuses.size(); ++r) {
        if (statuses[r].rfind(kFailed, 0) != 0) continue;
        if (!failures.empty()) failures += "; ";
        failures += fmt::format("rank {}: {}", r, statuses[r].substr(std::string(kFailed).size()));
        ++failed;
    }
    // Every rank failing the same way (a bad flag, a bad scene everywhere) is said once.
    if (failed == statuses.size() && failed > 1 &&
        std::all_of(statuses.begin(), statuses.end(),
                    [&](const std::string& s) { return s == statuses[0]; })) {
        failures = fmt::format("every rank: {}", statuses[0].substr(std::string(kFailed).size()));
    }
    if (!failures.empty()) throw Error(fmt::format("the cluster render failed: {}", failures));
    return statuses;
}

// Runs `work`; returns kOk followed by what it returns, or kFailed and the cause.
template <typename Work>
std::string status_of(Work&& work) {
    try {
        return kOk + work();
    } catch (const Interrupted& e) {
        return fmt::format("{}interrupted by signal {}", kFailed, e.signal());
    } catch (const std::exception& e) {
        return kFailed + std::string(e.what());
    }
}

// Rank 0: writes every output of the job or none.
RenderReport write_report(RenderedImage render, const RenderSettings& settings,
                          const RenderControl& control) {
    RenderReport report;
    report.render = std::move(render);
    report.targets = settings.outputs;
    const WriteOptions write_options{settings.exposure, settings.tonemap};
    std::vector<OutputFile> files;
    for (const std::string& path : settings.outputs)
        files.push_back({path, &report.render.image, write_options});
    write_outputs(files, control);
    return report;
}

}  // namespace

std::optional<RenderReport> render_distributed(Cluster& cluster, const RenderSetup& setup,
                                               const RenderControl& control) {
    const int rank = cluster.rank(), ranks = cluster.size();
    SceneDesc desc;
    RenderSettings settings;
    bool by_samples = true;
    // First every rank loads its scene (a file missing on one machine, a bad script), so that
    // no rank renders for nothing when another cannot start.
    agree(cluster, status_of([&] {
              std::tie(desc, settings) = setup();
              // Tile integrators: each rank renders a share of every pixel's samples.
              // Others share their work themselves (sppm, vcm) and every rank ends with the
              // whole image; the rest cannot be spread.
              const auto integrator = make_integrator(settings);
              by_samples = dynamic_cast<const TileIntegrator*>(integrator.get()) != nullptr;
              if (!by_samples && !integrator->share_work(cluster)) {
                  throw Error(
                      fmt::format("{}: integrator '{}' cannot be spread over MPI ranks "
                                  "(tile integrators, sppm and vcm can; docs/cluster.md)",
                                  settings.where_of("integrator"), settings.integrator));
              }
              if (by_samples && settings.spp < ranks) {
                  throw Error(fmt::format("{}: {} samples per pixel cannot be shared by {} ranks",
                                          settings.where_of("spp"), settings.spp, ranks));
              }
              // Rank 0 checks where the outputs go before anyone renders for an hour.
              if (rank == 0) OutputBatch::check_targets(settings.outputs);
              return std::string();
          }));

    const uint64_t job_samples = static_cast<uint64_t>(settings.output_width()) *
                                 settings.output_height() * settings.spp *
                                 (by_samples ? 1 : static_cast<uint64_t>(ranks));
    Progress progress(fmt::format("rendering ({} ranks)", ranks), job_samples,
                      control.quiet || rank != 0);
    RenderControl rank_control = control;
    rank_control.progress = &progress;
    // Warnings are the same on every rank: rank 0 prints them.
    if (rank != 0) rank_control.warn = [](const std::string&) {};
    RenderedImage part;
    std::string status;
    {
        ProgressRelay relay(cluster, progress);
        if (by_samples) {
            status = status_of([&] {
                part = render_image(desc, settings, rank_control,
                                    rank_share(settings.spp, rank, ranks));
                return attributes_text(part.image);
            });
        } else {
            // A rank that fails between the integrator's exchanges would leave the others
            // waiting in the next one: it ends the job instead.
            rank_control.cluster = &cluster;
            const std::string own = status_of([&] {
                part = render_image(desc, settings, rank_control);
                return std::string();
            });
            if (own.rfind(kFailed, 0) == 0) cluster.abort(own.substr(std::string(kFailed).size()));
            status = own;
        }
    }
    const std::vector<std::string> statuses = agree(cluster, status);
    if (!by_samples) {
        if (rank != 0) return std::nullopt;
        progress.finish();
        return write_report(std::move(part), settings, control);
    }

    const std::vector<std::vector<float>> pixels = cluster.gather_to_root(part.image.pixels);
    if (rank != 0) return std::nullopt;
    progress.finish();
    std::vector<Image> parts;
    std::vector<std::string> names;
    for (int r = 0; r < ranks; ++r) {
        Image image = part.image;
        image.pixels = pixels[r];
        image.attributes = parse_attributes(statuses[r].substr(std::string(kOk).size()));
        if (image.pixels.size() != part.image.pixels.size())
            throw Error(fmt::format("rank {} rendered an image of another size than rank 0's", r));
        parts.push_back(std::move(image));
        names.push_back(fmt::format("rank {}", r));
    }
    std::vector<std::string> warnings;
    RenderReport report;
    report.render = std::move(part);
    report.render.image = merge_partial_renders(parts, names, warnings);
    for (const std::string& warning : warnings) warn(control, warning);
    report.render.stats.samples =
        static_cast<uint64_t>(settings.output_width()) * settings.output_height() * settings.spp;
    return write_report(std::move(report.render), settings, control);
}

}  // namespace glint
