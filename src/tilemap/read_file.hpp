// Reading a map or tileset file: regular files only, bounded in size, so a
// `source` naming /dev/zero, /dev/urandom or a FIFO is an error rather than
// a read that never ends or exhausts memory.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace ds::tmx {

// The whole of the regular file at `path`, which must hold at most
// `max_bytes`; or nullopt with `error` set to why not (the system's reason,
// "is a directory", "is not a regular file (a FIFO)", or its size, then
// "more than the N bytes <limit_name>", e.g. "max-bytes allows").
std::optional<std::string> read_regular_file(const std::string& path, int64_t max_bytes,
                                             const char* limit_name, std::string& error);

}  // namespace ds::tmx
