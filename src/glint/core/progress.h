#pragma once
// Progress of a long job on stderr. Workers call advance() from any thread; it costs an
// atomic add and a clock read, and at most one thread prints at a time without making
// the others wait.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace glint {

class Progress {
public:
    /// `total_work` in units of `unit` (e.g. samples); `quiet` prints nothing at all.
    /// On a terminal one line is redrawn about ten times a second; otherwise (a log file,
    /// CI) a plain line is printed about every 10 % or every 5 s, with no carriage returns.
    Progress(std::string label, uint64_t total_work, bool quiet, std::string unit = "samples");
    /// Ends a redrawn line left open by an unfinished job (e.g. one that threw).
    ~Progress();

    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Thread-safe; `work` more units are done. Throws glint::Interrupted when the cancel
    /// flag is set: every integrator advances once per tile (or chunk, or pass), so a
    /// render stops within one tile of a signal, and TBB carries the exception out.
    void advance(uint64_t work);
    /// While `*flag` is non-zero, advance() throws Interrupted(*flag). The flag is written
    /// by a signal handler, hence a lock-free atomic; null (the default) never cancels.
    void set_cancel_flag(const std::atomic<int>* flag) { m_cancel = flag; }
    /// Prints the final line with elapsed time and mean throughput. Idempotent.
    void finish();

    /// Whether this job prints nothing (a job started inside it may follow suit).
    bool quiet() const { return m_quiet; }
    uint64_t done() const { return m_done.load(std::memory_order_relaxed); }
    double elapsed_seconds() const;

private:
    using Clock = std::chrono::steady_clock;

    void print_locked(uint64_t done, bool final_line);
    int64_t now_ns() const;

    std::string m_label;
    std::string m_unit;
    uint64_t m_total;
    bool m_quiet;
    bool m_terminal;
    Clock::time_point m_start;
    std::atomic<uint64_t> m_done{0};
    const std::atomic<int>* m_cancel = nullptr;
    // Earliest time, in ns since m_start, at which a worker should try to print; lets
    // advance() skip the mutex entirely between updates.
    std::atomic<int64_t> m_next_print_ns{0};

    std::mutex m_print_mutex;  // guards everything below
    bool m_finished = false;
    bool m_line_open = false;
    int m_last_decile = 0;
    int64_t m_last_line_ns = 0;
};

}  // namespace glint
