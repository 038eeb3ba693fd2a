#include <glint/core/error.h>
#include <glint/core/strings.h>
#include <glint/film/output_batch.h>

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <system_error>

namespace glint {

namespace fs = std::filesystem;

namespace {

// "dir/out.exr" -> "dir/out.tmp<pid>-<n>.exr": unique per process and call, and with the
// real extension last because write_image_file chooses the format from it.
fs::path temporary_path(const fs::path& target) {
    static std::atomic<uint64_t> counter{0};
    const std::string name =
        fmt::format("{}.tmp{}-{}{}", target.stem().string(), static_cast<long>(::getpid()),
                    counter.fetch_add(1), target.extension().string());
    return target.parent_path() / name;
}

// Makes the renames themselves durable; a failure here loses nothing already written.
void sync_directory(const fs::path& directory) {
    const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

}  // namespace

OutputBatch::~OutputBatch() {
    discard();
}

void OutputBatch::check_targets(const std::vector<std::string>& paths) {
    for (const std::string& path : paths) {
        const fs::path target(path);
        const std::string ext = lower_extension(target);
        if (ext != ".exr" && ext != ".png") {
            throw Error(
                fmt::format("output '{}': unsupported format '{}' (use .exr or .png)", path, ext));
        }
        if (target.filename().empty() || target.stem().empty())
            throw Error(fmt::format("output '{}': not a file name", path));
        const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
        std::error_code ec;
        if (!fs::is_directory(directory, ec)) {
            throw Error(fmt::format("output '{}': directory '{}' does not exist", path,
                                    directory.string()));
        }
        if (::access(directory.c_str(), W_OK | X_OK) != 0) {
            throw Error(fmt::format("output '{}': directory '{}' is not writable", path,
                                    directory.string()));
        }
        if (fs::is_directory(target, ec))
            throw Error(fmt::format("output '{}': is a directory", path));
    }
}

void OutputBatch::add(const std::string& path, const Image& image, const WriteOptions& options) {
    const fs::path temp = temporary_path(fs::path(path));
    try {
        write_image_file(temp.string(), image, options);
    } catch (const std::exception& e) {
        std::error_code ignored;
        fs::remove(temp, ignored);
        throw Error(fmt::format("cannot write '{}': {}", path, e.what()));
    }
    m_entries.push_back({path, temp.string()});
}

void OutputBatch::commit() {
    for (size_t i = 0; i < m_entries.size(); ++i) {
        std::error_code ec;
        fs::rename(m_entries[i].temporary, m_entries[i].target, ec);
        if (ec) {
            m_entries.erase(m_entries.begin(), m_entries.begin() + static_cast<ptrdiff_t>(i));
            const std::string target = m_entries.front().target;
            discard();
            throw Error(fmt::format("cannot write '{}': {}", target, ec.message()));
        }
        sync_directory(fs::path(m_entries[i].target).parent_path());
    }
    m_entries.clear();
}

void OutputBatch::discard() noexcept {
    for (const Entry& entry : m_entries) {
        std::error_code ignored;
        fs::remove(entry.temporary, ignored);
    }
    m_entries.clear();
}

std::vector<std::string> OutputBatch::temporaries() const {
    std::vector<std::string> result;
    for (const Entry& entry : m_entries) result.push_back(entry.temporary);
    return result;
}

}  // namespace glint
