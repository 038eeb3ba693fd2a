#pragma once
// Loops whose iterations are independent, run on TBB's threads: per row of an image, or per
// index of an array. Each iteration writes only its own elements, so what they compute does
// not depend on the number of threads.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace glint {

/// body(y) for every row y in [0, height).
template <typename Body>
void parallel_for_rows(int height, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y) body(y);
    });
}

/// body(i) for every index i in [0, count), in chunks of at least `grain` (cheap bodies over
/// hundreds of thousands of pixels: the chunks keep the scheduling overhead small).
template <typename Body>
void parallel_for_indices(std::size_t count, const Body& body, std::size_t grain = 4096) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t i = range.begin(); i < range.end(); ++i) body(i);
                      });
}

}  // namespace glint
