#include "read_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace ds::tmx {

namespace {

struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

const char* kind_of(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a file";
}

// Reads to the end, stopping after max_bytes + 1 bytes: a file that grew
// since fstat is still bounded.
bool read_all(int fd, int64_t max_bytes, const char* limit_name, std::string& out,
              std::string& error) {
    char buf[65536];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = std::strerror(errno);
            return false;
        }
        if (n == 0) return true;
        out.append(buf, static_cast<size_t>(n));
        if (static_cast<int64_t>(out.size()) > max_bytes) {
            error = "is more than the " + std::to_string(max_bytes) + " bytes " + limit_name;
            return false;
        }
    }
}

}  // namespace

std::optional<std::string> read_regular_file(const std::string& path, int64_t max_bytes,
                                             const char* limit_name, std::string& error) {
    // Refused before opening, so no device is ever opened; the fstat below
    // still decides, as the name may be swapped in between.
    struct stat named{};
    if (::stat(path.c_str(), &named) == 0 && !S_ISREG(named.st_mode) && !S_ISDIR(named.st_mode)) {
        error = std::string("is not a regular file (") + kind_of(named.st_mode) + ")";
        return std::nullopt;
    }
    // O_NONBLOCK: opening a FIFO must not wait for a writer. It has no effect
    // on the regular files that are read.
    const Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
    if (f.fd < 0) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    // fstat of the opened file, not stat of the name: nothing can swap it between.
    struct stat st{};
    if (::fstat(f.fd, &st) != 0) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    if (S_ISDIR(st.st_mode)) {
        error = "is a directory";
        return std::nullopt;
    }
    if (!S_ISREG(st.st_mode)) {
        error = std::string("is not a regular file (") + kind_of(st.st_mode) + ")";
        return std::nullopt;
    }
    if (st.st_size > max_bytes) {
        error = "is " + std::to_string(st.st_size) + " bytes, more than the " +
                std::to_string(max_bytes) + " bytes " + limit_name;
        return std::nullopt;
    }
    std::string text;
    text.reserve(static_cast<size_t>(st.st_size));
    if (!read_all(f.fd, max_bytes, limit_name, text, error)) return std::nullopt;
    return text;
}

}  // namespace ds::tmx
