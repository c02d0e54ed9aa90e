// A preload library that makes the file system fail the way a full or read-only disk does, for
// the fault-injection tests (docs/TESTING.md "Fault injection"). Root ignores permissions and
// may not mount a small file system here, so the tests cannot make a real full disk or a real
// read-only folder; this library stands in for both by answering the same calls with the same
// errors the kernel gives. Loaded with LD_PRELOAD into airtrap-cli, it reads:
//
//   AIRTRAP_FAULT_DIR          only paths under this folder are affected (required)
//   AIRTRAP_FAULT_WRITE_LIMIT  N: after N bytes written to files opened under the folder, write()
//                              fails with ENOSPC (the last write that crosses N is cut short, as
//                              on a disk that fills up)
//   AIRTRAP_FAULT_OPEN_ERROR   EROFS, EACCES or ENOSPC: opening a file for writing, creating a
//                              folder or renaming into the folder fails with that error
//
// Reading is never affected: a read-only disk still reads.
#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace {

struct FaultPlan {
    const char* dir = nullptr;
    std::size_t dirLength = 0;
    long long writeLimit = -1; //!< -1: writes never fail
    int openError = 0;         //!< 0: opening never fails
};

int errorNamed(const char* name) {
    if (name == nullptr)
        return 0;
    if (std::strcmp(name, "EROFS") == 0)
        return EROFS;
    if (std::strcmp(name, "EACCES") == 0)
        return EACCES;
    if (std::strcmp(name, "ENOSPC") == 0)
        return ENOSPC;
    return 0;
}

const FaultPlan& plan() {
    static const FaultPlan read = [] {
        FaultPlan faults;
        faults.dir = std::getenv("AIRTRAP_FAULT_DIR");
        faults.dirLength = faults.dir != nullptr ? std::strlen(faults.dir) : 0;
        if (const char* limit = std::getenv("AIRTRAP_FAULT_WRITE_LIMIT"))
            faults.writeLimit = std::atoll(limit);
        faults.openError = errorNamed(std::getenv("AIRTRAP_FAULT_OPEN_ERROR"));
        return faults;
    }();
    return read;
}

bool underFaultDir(const char* path) {
    const FaultPlan& faults = plan();
    return faults.dirLength > 0 && path != nullptr &&
           std::strncmp(path, faults.dir, faults.dirLength) == 0 &&
           (path[faults.dirLength] == '/' || path[faults.dirLength] == '\0');
}

// File descriptors opened for writing under the folder; only their writes count.
constexpr int kTrackedDescriptors = 4096;
std::atomic<bool> watched[kTrackedDescriptors];
std::atomic<long long> bytesWritten{0};

bool opensForWriting(int flags) {
    return (flags & (O_WRONLY | O_RDWR | O_CREAT | O_TRUNC)) != 0;
}

template <class Function>
Function next(const char* name) {
    return reinterpret_cast<Function>(::dlsym(RTLD_NEXT, name));
}

//! The open family's common part: refuse or track, then call the real function.
template <class Open>
int openChecked(Open realOpen, const char* path, int flags, mode_t mode) {
    const bool faulty = underFaultDir(path) && opensForWriting(flags);
    if (faulty && plan().openError != 0) {
        errno = plan().openError;
        return -1;
    }
    const int fd = realOpen(path, flags, mode);
    if (fd >= 0 && fd < kTrackedDescriptors)
        watched[fd].store(faulty);
    return fd;
}

mode_t modeArgument(int flags, va_list arguments) {
    return (flags & (O_CREAT | O_TMPFILE)) != 0 ? mode_t(va_arg(arguments, int)) : 0;
}

//! open() and open64(): the mode argument, when the flags say there is one, then openChecked().
int openWithModeArgument(int (*real)(const char*, int, ...), const char* path, int flags,
                         va_list arguments) {
    const mode_t mode = modeArgument(flags, arguments);
    return openChecked([real](const char* p, int f, mode_t m) { return real(p, f, m); }, path,
                       flags, mode);
}

} // namespace

extern "C" {

int open(const char* path, int flags, ...) {
    static const auto real = next<int (*)(const char*, int, ...)>("open");
    va_list arguments;
    va_start(arguments, flags);
    const int fd = openWithModeArgument(real, path, flags, arguments);
    va_end(arguments);
    return fd;
}

int open64(const char* path, int flags, ...) {
    static const auto real = next<int (*)(const char*, int, ...)>("open64");
    va_list arguments;
    va_start(arguments, flags);
    const int fd = openWithModeArgument(real, path, flags, arguments);
    va_end(arguments);
    return fd;
}

int openat(int dirfd, const char* path, int flags, ...) {
    static const auto real = next<int (*)(int, const char*, int, ...)>("openat");
    va_list arguments;
    va_start(arguments, flags);
    const mode_t mode = modeArgument(flags, arguments);
    va_end(arguments);
    // Relative to another folder: not a path this library can judge.
    if (dirfd != AT_FDCWD)
        return real(dirfd, path, flags, mode);
    return openChecked([dirfd](const char* p, int f, mode_t m) { return real(dirfd, p, f, m); },
                       path, flags, mode);
}

ssize_t write(int fd, const void* data, size_t size) {
    static const auto real = next<ssize_t (*)(int, const void*, size_t)>("write");
    const long long limit = plan().writeLimit;
    if (limit < 0 || fd < 0 || fd >= kTrackedDescriptors || !watched[fd].load())
        return real(fd, data, size);
    const long long before = bytesWritten.fetch_add(static_cast<long long>(size));
    if (before >= limit) {
        errno = ENOSPC;
        return -1;
    }
    const auto room = static_cast<size_t>(limit - before);
    return real(fd, data, size < room ? size : room);
}

int close(int fd) {
    static const auto real = next<int (*)(int)>("close");
    if (fd >= 0 && fd < kTrackedDescriptors)
        watched[fd].store(false);
    return real(fd);
}

int mkdir(const char* path, mode_t mode) {
    static const auto real = next<int (*)(const char*, mode_t)>("mkdir");
    if (underFaultDir(path) && plan().openError != 0) {
        errno = plan().openError;
        return -1;
    }
    return real(path, mode);
}

int rename(const char* from, const char* to) {
    static const auto real = next<int (*)(const char*, const char*)>("rename");
    if (underFaultDir(to) && plan().openError != 0) {
        errno = plan().openError;
        return -1;
    }
    return real(from, to);
}

} // extern "C"
