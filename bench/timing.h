#pragma once
// Timing helpers shared by the benchmark programs.
#include <algorithm>
#include <ctime>
#include <vector>

namespace glint::bench {

/// The median of `values` (0 when there are none): robust to the odd slow run on a shared
/// machine.
inline double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

/// CPU time of the whole process (all threads), in seconds: on a machine shared with other
/// work, CPU time per frame divided by the threads is what the frame would take alone.
inline double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace glint::bench
