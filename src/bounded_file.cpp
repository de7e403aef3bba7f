// SPDX-License-Identifier: MIT
#include "bounded_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace ds {

namespace {

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// False for a regular file; else true, with `error` saying what it is.
bool refused(mode_t mode, std::string& error) {
    if (S_ISREG(mode)) return false;
    error = S_ISDIR(mode) ? std::string("is a directory") : std::string("is not a regular file (") + kind_of(mode) + ")";
    return true;
}

// Reads into `out` from `offset` until `limit` bytes are there or the file
// ends; false with `error` when the system refuses.
bool read_from(int fd, int64_t offset, size_t limit, std::string& out, std::string& error) {
    char buf[65536];
    while (out.size() < limit) {
        const size_t want = std::min(sizeof buf, limit - out.size());
        const ssize_t n = ::pread(fd, buf, want, offset + int64_t(out.size()));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::strerror(errno);
            return false;
        }
        if (n == 0) break;
        out.append(buf, size_t(n));
    }
    return true;
}

}  // namespace

std::optional<BoundedFile> BoundedFile::open(const std::string& path, std::string& error) {
    // Refused before opening, so no device is ever opened; the fstat below
    // still decides, as the name may be swapped in between.
    struct stat named{};
    if (::stat(path.c_str(), &named) == 0 && !S_ISDIR(named.st_mode) && refused(named.st_mode, error))
        return std::nullopt;
    // O_NONBLOCK: opening a FIFO must not wait for a writer. It has no effect
    // on the regular files that are read.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    BoundedFile file(fd, 0);
    // fstat of the opened file, not stat of the name: nothing can swap it between.
    struct stat st{};
    if (::fstat(fd, &st) != 0) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    if (refused(st.st_mode, error)) return std::nullopt;
    file.size_ = st.st_size;
    return file;
}

BoundedFile::~BoundedFile() {
    if (fd_ >= 0) ::close(fd_);
}

std::optional<std::string> BoundedFile::head(size_t n, std::string& error) const {
    std::string out;
    if (!read_from(fd_, 0, n, out, error)) return std::nullopt;
    return out;
}

std::optional<std::string> BoundedFile::read_all(int64_t max_bytes, const char* limit_name,
                                                 std::string& error) const {
    const auto too_big = [&](int64_t size) {
        error = "is " + std::to_string(size) + " bytes, more than the " + std::to_string(max_bytes) + " bytes " +
                limit_name;
        return std::nullopt;
    };
    if (size_ > max_bytes) return too_big(size_);
    std::string out;
    out.reserve(size_t(size_));
    // One byte past the bound tells a file that grew since it was opened.
    if (!read_from(fd_, 0, size_t(max_bytes) + 1, out, error)) return std::nullopt;
    if (int64_t(out.size()) > max_bytes) return too_big(int64_t(out.size()));
    return out;
}

std::optional<std::string> read_bounded_file(const std::string& path, int64_t max_bytes, const char* limit_name,
                                             std::string& error) {
    const auto file = BoundedFile::open(path, error);
    if (!file) return std::nullopt;
    return file->read_all(max_bytes, limit_name, error);
}

}  // namespace ds
