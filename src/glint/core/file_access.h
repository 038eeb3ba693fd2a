#pragma once
// Reading and writing files a scene names, safely: only regular files are opened (a FIFO or
// a device would block or never end), paths can be confined to a folder, and files are
// written through a temporary with a unique name that is created exclusively and never
// follows a link.
#include <string>

namespace glint {

/// The bytes of the regular file at `path`. The file is opened without blocking and checked
/// to be a regular file before anything is read, so a FIFO, a socket or a device named as
/// a file is an error, not a hang. `what` names the file in messages ("GLB file").
/// Throws glint::Error when the file is missing, not a regular file, or unreadable.
std::string read_regular_file(const std::string& path, const std::string& what);

/// Whether `path` lies inside `folder` (or is the folder), both with links followed and
/// `..` resolved; a path that does not exist yet is judged by its existing parent.
bool is_inside_folder(const std::string& folder, const std::string& path);

/// Writes `bytes` to `path`: first to `.NAME.XXXXXX` beside it (a new file, created with
/// O_EXCL and O_NOFOLLOW, mode 0644 less the umask), flushed to disk, then renamed onto
/// `path`. On any failure the temporary is removed and glint::Error says "cannot write
/// WHAT 'path': reason". An existing `path` that is not a regular file is refused.
void write_file_atomically(const std::string& path, const std::string& bytes,
                           const std::string& what);

/// A cache folder of this user's own in the temporary folder, `NAME-UID`, made private
/// (0700) when new. One that exists already is used only when it is a real folder (not a
/// link), owned by this user and closed to everyone else: another user could otherwise plant
/// files or links in it. Throws glint::Error naming the folder otherwise.
std::string private_cache_folder(const std::string& name);

}  // namespace glint
