#include "core/AtomicFile.h"

#include "core/Error.h"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>

namespace airtrap {
namespace {

constexpr const char* kTempSuffix = ".tmp";

//! A name no other writer uses: the bake thread and the editor may both write the manifest, and
//! two processes may (wrongly) bake into one folder; neither must clobber the other's temporary.
std::string uniqueTempPath(const std::string& path) {
    static std::atomic<std::uint64_t> counter{0};
    return path + "." + std::to_string(::getpid()) + "-" + std::to_string(counter.fetch_add(1)) +
           kTempSuffix;
}

std::string parentFolder(const std::string& path) {
    const auto slash = path.find_last_of('/');
    if (slash == std::string::npos)
        return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

[[noreturn]] void fail(const std::string& action, const std::string& path, int err) {
    throw Error(ErrorKind::Io, AtomicFile::errorMessage(action, path, err));
}

//! Writes everything, retrying short writes and signals; returns 0 or the errno.
int writeAll(int fd, const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
        const ssize_t written = ::write(fd, data, size);
        if (written < 0) {
            if (errno == EINTR)
                continue;
            return errno;
        }
        data += written;
        size -= static_cast<std::size_t>(written);
    }
    return 0;
}

//! Fills and closes the temporary; returns 0 or the errno of the first failure.
int fillTemporary(int fd, const void* data, std::size_t size) {
    int err = writeAll(fd, static_cast<const std::uint8_t*>(data), size);
    // fsync before rename: otherwise a crash can leave the new name pointing at empty data.
    if (err == 0 && ::fsync(fd) != 0)
        err = errno;
    // close() can report a deferred write error (NFS), so it counts as part of the write.
    if (::close(fd) != 0 && err == 0)
        err = errno;
    return err;
}

//! Makes the rename itself durable. Filesystems that cannot sync folders say EINVAL; that is
//! not a failure of ours.
void syncFolder(const std::string& path) {
    const std::string folder = parentFolder(path);
    const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0)
        fail("cannot sync folder", folder, errno);
    const int err = ::fsync(fd) == 0 ? 0 : errno;
    ::close(fd);
    if (err != 0 && err != EINVAL && err != ENOTSUP)
        fail("cannot sync folder", folder, err);
}

//! The process id in a temporary's name ("frame_0003.atf.<pid>-<n>.tmp"), or 0 when the name
//! is not one write() made.
pid_t writerOf(const std::string& name) {
    const std::string suffix = kTempSuffix;
    const std::string stem = name.substr(0, name.size() - suffix.size());
    const auto dot = stem.find_last_of('.');
    const auto dash = stem.find_last_of('-');
    if (dot == std::string::npos || dash == std::string::npos || dash < dot)
        return 0;
    pid_t pid = 0;
    const char* first = stem.data() + dot + 1;
    const char* last = stem.data() + dash;
    const auto [end, error] = std::from_chars(first, last, pid);
    return error == std::errc() && end == last && pid > 0 ? pid : 0;
}

bool isRunning(pid_t pid) {
    // EPERM: it runs, under another user.
    return ::kill(pid, 0) == 0 || errno == EPERM;
}

} // namespace

void AtomicFile::write(const std::string& path, const void* data, std::size_t size) {
    const std::string temp = uniqueTempPath(path);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0)
        fail("cannot write", path, errno);
    int err = fillTemporary(fd, data, size);
    if (err == 0 && ::rename(temp.c_str(), path.c_str()) != 0)
        err = errno;
    if (err != 0) {
        ::unlink(temp.c_str());
        fail("cannot write", path, err);
    }
    syncFolder(path);
}

void AtomicFile::write(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    write(path, bytes.data(), bytes.size());
}

void AtomicFile::write(const std::string& path, const std::string& text) {
    write(path, text.data(), text.size());
}

std::vector<std::uint8_t> AtomicFile::read(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        fail("cannot read", path, errno);
    std::vector<std::uint8_t> bytes;
    struct stat info {};
    if (::fstat(fd, &info) == 0 && info.st_size > 0)
        bytes.reserve(static_cast<std::size_t>(info.st_size));
    std::uint8_t buffer[1 << 16];
    for (;;) {
        const ssize_t got = ::read(fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            const int err = errno;
            ::close(fd);
            fail("cannot read", path, err);
        }
        if (got == 0)
            break;
        bytes.insert(bytes.end(), buffer, buffer + got);
    }
    ::close(fd);
    return bytes;
}

std::string AtomicFile::errorMessage(const std::string& action, const std::string& path, int err) {
    const std::string reason = std::generic_category().message(err);
    std::string hint;
    switch (err) {
    case ENOSPC:
    case EDQUOT:
        hint = "disk full";
        break;
    case EFBIG:
        hint = "file-size limit reached (ulimit -f)";
        break;
    case EACCES:
    case EPERM:
        hint = "permission denied";
        break;
    case EROFS:
        hint = "read-only file system";
        break;
    default:
        return action + " " + path + ": " + reason;
    }
    return action + " " + path + ": " + hint + " (" + reason + ")";
}

std::size_t AtomicFile::removeOrphanedTemporaries(const std::string& dir) {
    std::size_t removed = 0;
    std::error_code error;
    for (std::filesystem::directory_iterator it(dir, error), end; !error && it != end;
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        if (!isTemporaryName(name))
            continue;
        const pid_t writer = writerOf(name);
        if (writer == 0 || writer == ::getpid() || isRunning(writer))
            continue;
        if (::unlink(it->path().c_str()) == 0)
            ++removed;
    }
    return removed;
}

bool AtomicFile::isTemporaryName(const std::string& name) {
    const std::string suffix = kTempSuffix;
    return name.size() > suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace airtrap
