#include <glint/core/error.h>
#include <glint/core/file_access.h>

#include <fmt/format.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <random>

namespace glint {
namespace {

namespace fs = std::filesystem;

// Closes a descriptor however the function that opened it ends.
struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

std::string reason(int error) {
    return std::strerror(error);
}

}  // namespace

std::string read_regular_file(const std::string& path, const std::string& what) {
    // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer for ever.
    Descriptor file{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
    if (file.fd < 0) throw Error(fmt::format("cannot open {} '{}': {}", what, path, reason(errno)));
    struct stat info {};
    if (::fstat(file.fd, &info) != 0)
        throw Error(fmt::format("cannot read {} '{}': {}", what, path, reason(errno)));
    if (!S_ISREG(info.st_mode)) {
        throw Error(
            fmt::format("cannot open {} '{}': {}", what, path,
                        S_ISDIR(info.st_mode) ? "it is a directory" : "it is not a regular file"));
    }
    std::string bytes(static_cast<size_t>(info.st_size), '\0');
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::read(file.fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    // A file that shrank while it was read is as bad as an unreadable one.
    if (done != bytes.size())
        throw Error(fmt::format("cannot read {} '{}': read error", what, path));
    return bytes;
}

bool is_inside_folder(const std::string& folder, const std::string& path) {
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(fs::absolute(folder, ec), ec);
    if (ec) return false;
    const fs::path target = fs::weakly_canonical(fs::absolute(path, ec), ec);
    if (ec) return false;
    const fs::path inside = target.lexically_relative(base);
    return !inside.empty() && *inside.begin() != "..";
}

void write_file_atomically(const std::string& path, const std::string& bytes,
                           const std::string& what) {
    auto fail = [&](const std::string& why) {
        throw Error(fmt::format("cannot write {} '{}': {}", what, path, why));
    };
    struct stat existing {};
    if (::lstat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode))
        fail("it exists and is not a regular file");
    const fs::path target(path);
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    // A unique name beside the target (the rename stays on one file system); O_EXCL makes a
    // name someone else created, a link included, fail instead of being written through.
    std::random_device entropy;
    std::string temporary;
    Descriptor file;
    for (int attempt = 0; attempt < 100 && file.fd < 0; ++attempt) {
        temporary = (folder / fmt::format(".{}.{:08x}.tmp", target.filename().string(), entropy()))
                        .string();
        file.fd =
            ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (file.fd < 0 && errno != EEXIST) fail(reason(errno));
    }
    if (file.fd < 0) fail("no unique temporary name could be made");
    auto remove_and_fail = [&](const std::string& why) {
        ::unlink(temporary.c_str());
        fail(why);
    };
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(file.fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) remove_and_fail(n < 0 ? reason(errno) : "nothing was written");
        done += static_cast<size_t>(n);
    }
    if (::fsync(file.fd) != 0) remove_and_fail(reason(errno));
    const int closed = ::close(file.fd);
    file.fd = -1;
    if (closed != 0) remove_and_fail(reason(errno));
    if (::rename(temporary.c_str(), path.c_str()) != 0) remove_and_fail(reason(errno));
}

std::string private_cache_folder(const std::string& name) {
    const fs::path folder = fs::temp_directory_path() / fmt::format("{}-{}", name, ::getuid());
    if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        throw Error(fmt::format("cannot make the cache folder '{}': {}", folder.string(),
                                std::strerror(errno)));
    struct stat info {};
    if (::lstat(folder.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) ||
        info.st_uid != ::getuid() || (info.st_mode & 077) != 0) {
        throw Error(fmt::format("the cache folder '{}' is not a private folder of this user (a "
                                "link, another owner, or open to others); remove it",
                                folder.string()));
    }
    return folder.string();
}

}  // namespace glint
