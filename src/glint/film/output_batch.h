#pragma once
// All-or-nothing output: a render's images either all appear, complete, or none does.
#include <glint/film/image.h>
#include <glint/film/image_io.h>

#include <string>
#include <vector>

namespace glint {

/// A set of images written together. add() writes each to a temporary file beside its
/// target (same directory, so the final rename stays on one file system), flushes it to
/// the disk and decodes it again to prove it complete; commit() renames every temporary
/// over its target. Until commit() nothing is visible under a target's name, and a batch
/// destroyed without commit() (an error, an exception, an interrupted run) removes its
/// temporaries.
///
/// Temporaries are named "STEM.tmp<pid>-<n>.EXT". A rename can fail only for reasons that
/// make every rename fail (the directory went away, permissions changed under us), and
/// commit() removes the remaining temporaries when one does; files already renamed stay.
class OutputBatch {
public:
    OutputBatch() = default;
    /// Removes the temporaries of a batch that was not committed.
    ~OutputBatch();
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    /// Checks, before any work, that each path has a supported extension (.exr, .png)
    /// and names a file in an existing, writable directory, and is not itself a directory.
    /// Throws glint::Error naming the first bad path and what is wrong with it.
    static void check_targets(const std::vector<std::string>& paths);

    /// Writes `image` to a temporary beside `path`, flushed and verified. Throws
    /// glint::Error naming `path` and the reason (e.g. "No space left on device"); the
    /// failed temporary is removed, earlier ones stay until commit() or destruction.
    void add(const std::string& path, const Image& image, const WriteOptions& options = {});

    /// Renames every temporary over its target, in the order added. Throws glint::Error
    /// if a rename fails (removing the temporaries not yet renamed).
    void commit();

    /// Removes every temporary not yet renamed; safe to call more than once.
    void discard() noexcept;

    /// The temporaries written so far and not yet renamed.
    std::vector<std::string> temporaries() const;

private:
    struct Entry {
        std::string target;
        std::string temporary;
    };
    std::vector<Entry> m_entries;
};

}  // namespace glint
