#include <glint/geometry/csg/interval.h>

#include <algorithm>

namespace glint {
namespace {

// Appends [enter, exit], merging with the last interval when they overlap or touch.
void append_merged(IntervalList& out, const Crossing& enter, const Crossing& exit) {
    if (!out.empty() && enter.t <= out.back().exit.t) {
        if (exit.t > out.back().exit.t) out.back().exit = exit;
        return;
    }
    out.push_back({enter, exit});
}

Crossing flipped(Crossing c) {
    c.normal = -c.normal;
    return c;
}

}  // namespace

void interval_union(const IntervalList& a, const IntervalList& b, IntervalList& out) {
    out.clear();
    size_t i = 0, j = 0;
    while (i < a.size() || j < b.size()) {
        const bool take_a = j == b.size() || (i < a.size() && a[i].enter.t <= b[j].enter.t);
        const Interval& next = take_a ? a[i++] : b[j++];
        append_merged(out, next.enter, next.exit);
    }
}

void interval_intersection(const IntervalList& a, const IntervalList& b, IntervalList& out) {
    out.clear();
    size_t i = 0, j = 0;
    while (i < a.size() && j < b.size()) {
        const Crossing& enter = a[i].enter.t >= b[j].enter.t ? a[i].enter : b[j].enter;
        const Crossing& exit = a[i].exit.t <= b[j].exit.t ? a[i].exit : b[j].exit;
        // Touching intervals share a single point: no volume, so no interval.
        if (enter.t < exit.t) out.push_back({enter, exit});
        if (a[i].exit.t <= b[j].exit.t)
            ++i;
        else
            ++j;
    }
}

void interval_difference(const IntervalList& a, const IntervalList& b, IntervalList& out) {
    out.clear();
    size_t j = 0;
    for (const Interval& span : a) {
        Crossing enter = span.enter;
        const Crossing& exit = span.exit;
        bool open = true;  // a part of `span` from `enter` is still to be emitted
        while (j < b.size() && b[j].exit.t <= enter.t) ++j;
        for (size_t k = j; k < b.size() && b[k].enter.t < exit.t; ++k) {
            // b[k] overlaps [enter, exit]: keep what lies before it, resume after it.
            if (b[k].enter.t > enter.t) out.push_back({enter, flipped(b[k].enter)});
            if (b[k].exit.t >= exit.t) {
                open = false;
                break;
            }
            enter = flipped(b[k].exit);
        }
        if (open && enter.t < exit.t) out.push_back({enter, exit});
    }
}

const Crossing* first_crossing_after(const IntervalList& list, float t_min) {
    for (const Interval& span : list) {
        if (span.enter.t > t_min) return &span.enter;
        if (span.exit.t > t_min) return &span.exit;
    }
    return nullptr;
}

}  // namespace glint
