#include <glint/core/error.h>
#include <glint/core/progress.h>

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace glint {

namespace {

constexpr int64_t kTerminalInterval = 100'000'000;  // 10 redraws per second
constexpr int64_t kLogInterval = 5'000'000'000;     // plain lines: at least every 5 s
constexpr int64_t kLogPoll = 250'000'000;           // how often a log line is considered

std::string format_duration(double seconds) {
    if (seconds < 60.0) return fmt::format("{:.1f}s", seconds);
    const auto total = static_cast<int64_t>(seconds + 0.5);
    if (total < 3600) return fmt::format("{}m{:02}s", total / 60, total % 60);
    return fmt::format("{}h{:02}m{:02}s", total / 3600, (total / 60) % 60, total % 60);
}

std::string format_rate(double per_second, const std::string& unit) {
    const char* prefix = "";
    double v = per_second;
    if (v >= 1e9) {
        v /= 1e9, prefix = "G ";
    } else if (v >= 1e6) {
        v /= 1e6, prefix = "M ";
    } else if (v >= 1e3) {
        v /= 1e3, prefix = "k ";
    }
    return fmt::format("{:.2f} {}{}/s", v, prefix, unit);
}

}  // namespace

Progress::Progress(std::string label, uint64_t total_work, bool quiet, std::string unit)
    : m_label(std::move(label)),
      m_unit(std::move(unit)),
      m_total(total_work),
      m_quiet(quiet),
      m_terminal(::isatty(STDERR_FILENO) == 1),
      m_start(Clock::now()) {
    // The first redraw waits one interval so that jobs finishing at once print one line.
    m_next_print_ns.store(m_terminal ? kTerminalInterval : kLogPoll, std::memory_order_relaxed);
}

Progress::~Progress() {
    std::lock_guard lock(m_print_mutex);
    if (m_line_open) {
        std::fputc('\n', stderr);
        std::fflush(stderr);
    }
}

int64_t Progress::now_ns() const {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - m_start).count();
}

double Progress::elapsed_seconds() const {
    return static_cast<double>(now_ns()) * 1e-9;
}

void Progress::advance(uint64_t work) {
    if (m_cancel) {
        if (const int signal = m_cancel->load(std::memory_order_relaxed); signal != 0)
            throw Interrupted(signal);
    }
    const uint64_t done = m_done.fetch_add(work, std::memory_order_relaxed) + work;
    if (m_quiet) return;
    const int64_t now = now_ns();
    if (now < m_next_print_ns.load(std::memory_order_relaxed)) return;
    // A worker that finds another one printing simply carries on rendering.
    std::unique_lock lock(m_print_mutex, std::try_to_lock);
    if (!lock.owns_lock() || m_finished) return;
    if (now < m_next_print_ns.load(std::memory_order_relaxed)) return;
    m_next_print_ns.store(now + (m_terminal ? kTerminalInterval : kLogPoll),
                          std::memory_order_relaxed);
    print_locked(done, false);
}

void Progress::finish() {
    std::lock_guard lock(m_print_mutex);
    if (m_finished) return;
    m_finished = true;
    if (!m_quiet) print_locked(m_done.load(std::memory_order_relaxed), true);
}

void Progress::print_locked(uint64_t done, bool final_line) {
    const int64_t now = now_ns();
    const double elapsed = static_cast<double>(now) * 1e-9;
    const double fraction =
        m_total > 0 ? std::min(1.0, static_cast<double>(done) / static_cast<double>(m_total)) : 1.0;
    const double rate = elapsed > 0.0 ? static_cast<double>(done) / elapsed : 0.0;
    const int percent = static_cast<int>(fraction * 100.0);

    if (final_line) {
        const std::string line = fmt::format("{} done in {}, {}", m_label, format_duration(elapsed),
                                             format_rate(rate, m_unit));
        // \x1b[K clears what a longer progress line left behind.
        if (m_terminal) {
            fmt::print(stderr, "\r{}\x1b[K\n", line);
        } else {
            fmt::print(stderr, "{}\n", line);
        }
        std::fflush(stderr);
        m_line_open = false;
        return;
    }

    // Remaining time extrapolates the mean rate so far; silent until there is one.
    const std::string left =
        done > 0 && fraction < 1.0
            ? fmt::format(", {} left", format_duration(elapsed * (1.0 - fraction) / fraction))
            : std::string();
    if (m_terminal) {
        constexpr int kBarWidth = 30;
        const int filled = static_cast<int>(fraction * kBarWidth);
        const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                                std::string(static_cast<std::size_t>(kBarWidth - filled), '.');
        fmt::print(stderr, "\r{} [{}] {}% {} elapsed{}, {}\x1b[K", m_label, bar, percent,
                   format_duration(elapsed), left, format_rate(rate, m_unit));
        std::fflush(stderr);
        m_line_open = true;
        return;
    }

    const int decile = percent / 10;
    if (decile <= m_last_decile && now - m_last_line_ns < kLogInterval) return;
    m_last_decile = std::max(m_last_decile, decile);
    m_last_line_ns = now;
    fmt::print(stderr, "{}: {}% ({} elapsed{}, {})\n", m_label, percent, format_duration(elapsed),
               left, format_rate(rate, m_unit));
    std::fflush(stderr);
}

}  // namespace glint
