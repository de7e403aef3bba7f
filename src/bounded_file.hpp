// SPDX-License-Identifier: MIT
// Reading a file that came from anywhere (a map, a tileset, an image, a
// sound, music): regular files only, opened without blocking, its size
// checked against the caller's bound before anything is read, and never more
// than that bound read, so a name of /dev/zero, a FIFO or a 2 GB sparse file
// is an error with a reason rather than a read that never ends, a hang or
// memory spent. One reader for every loader, so they refuse alike.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace ds {

// An open regular file and its size when opened. Move-only; closes itself.
class BoundedFile {
public:
    // Opens `path` for reading: nullopt with `error` set to why not (the
    // system's reason, "is a directory", "is not a regular file (a FIFO)").
    static std::optional<BoundedFile> open(const std::string& path, std::string& error);

    BoundedFile(BoundedFile&& other) noexcept : fd_(other.fd_), size_(other.size_) { other.fd_ = -1; }
    BoundedFile& operator=(BoundedFile&&) = delete;
    BoundedFile(const BoundedFile&) = delete;
    ~BoundedFile();

    int64_t size() const { return size_; }

    // Up to `n` bytes from the start (fewer when the file is shorter): what
    // a format is recognised by, before its bound is known.
    std::optional<std::string> head(size_t n, std::string& error) const;

    // The whole file, which must hold at most `max_bytes`; else nullopt with
    // `error`: its size, then "more than the N bytes <limit_name>" (e.g.
    // "max-bytes allows"). Reads at most max_bytes + 1 bytes, so a file that
    // grew since it was opened is still bounded.
    std::optional<std::string> read_all(int64_t max_bytes, const char* limit_name, std::string& error) const;

private:
    BoundedFile(int fd, int64_t size) : fd_(fd), size_(size) {}
    int fd_;
    int64_t size_;
};

// open() then read_all(): the whole of the regular file at `path`.
std::optional<std::string> read_bounded_file(const std::string& path, int64_t max_bytes, const char* limit_name,
                                             std::string& error);

}  // namespace ds
