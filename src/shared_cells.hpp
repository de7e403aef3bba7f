// SPDX-License-Identifier: MIT
// A fixed-length array of cells stored in chunks that copies share: copying
// it copies a table of chunk pointers, and writing a cell first copies its
// chunk when another copy still holds it (copy-on-write). This is what lets
// an edited map share everything but one chunk with the map it came from,
// which stays exactly as it was (scenes are values). Chunks of all zeros
// (empty cells) are one shared chunk from the start.
//
// Copies may live on other threads (Guile finalizes maps on its own thread):
// the chunks' counts are shared_ptr's atomic ones. A single SharedCells is
// no more thread-safe than a std::vector.
#pragma once
#include <algorithm>
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

#include "constants.hpp"

namespace ds {

template <typename T>
class SharedCells {
public:
    static constexpr size_t kChunk = size_t{1} << kCellChunkShift;

    SharedCells() = default;
    // From plain cells (the loaders and make_tilemap build vectors).
    SharedCells(const std::vector<T>& cells) { build(cells.data(), cells.size()); }
    SharedCells(std::initializer_list<T> cells) { build(cells.begin(), cells.size()); }
    SharedCells(size_t n, T fill) { assign(n, fill); }

    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }

    T operator[](size_t i) const { return chunks_[i >> kCellChunkShift][i & (kChunk - 1)]; }
    // A writable cell: its chunk becomes this array's own first.
    T& operator[](size_t i) { return own(i >> kCellChunkShift)[i & (kChunk - 1)]; }

    // n cells of `fill`, all in one shared chunk until written.
    void assign(size_t n, T fill) {
        auto c = std::make_shared<T[]>(std::min(n, kChunk), fill);
        chunks_.assign((n + kChunk - 1) / kChunk, c);
        size_ = n;
    }
    // Grows with empty (zero) cells, or shrinks.
    void resize(size_t n) {
        std::vector<T> all = to_vector();
        all.resize(n, T{});
        build(all.data(), all.size());
    }
    void clear() {
        chunks_.clear();
        size_ = 0;
    }

    std::vector<T> to_vector() const {
        std::vector<T> out(size_);
        for (size_t k = 0; k < chunks_.size(); ++k)
            std::copy_n(chunks_[k].get(), length(k), out.begin() + k * kChunk);
        return out;
    }

    // Same cells (chunks are compared by address first: copies share them).
    bool operator==(const SharedCells& o) const {
        if (size_ != o.size_) return false;
        for (size_t k = 0; k < chunks_.size(); ++k)
            if (chunks_[k] != o.chunks_[k] &&
                !std::equal(chunks_[k].get(), chunks_[k].get() + length(k), o.chunks_[k].get()))
                return false;
        return true;
    }
    bool operator==(const std::vector<T>& v) const { return *this == SharedCells(v); }

    // Whether cell i's chunk is also another array's (for tests of sharing).
    bool shares_chunk(const SharedCells& o, size_t i) const {
        return chunks_[i >> kCellChunkShift] == o.chunks_[i >> kCellChunkShift];
    }

private:
    // Chunk k's cells: kChunk, but fewer in the last (a small map's only)
    // chunk, so an edit of a small map copies no more than the map.
    size_t length(size_t k) const { return std::min(kChunk, size_ - k * kChunk); }

    void build(const T* cells, size_t n) {
        size_ = n;
        chunks_.clear();
        chunks_.reserve((n + kChunk - 1) / kChunk);
        std::shared_ptr<T[]> zeros;  // full-length: the last chunk never shares it
        for (size_t at = 0; at < n; at += kChunk) {
            const size_t len = std::min(kChunk, n - at);
            if (len == kChunk && std::all_of(cells + at, cells + at + len, [](T c) { return c == T{}; })) {
                if (!zeros) zeros = std::make_shared<T[]>(kChunk);
                chunks_.push_back(zeros);
                continue;
            }
            chunks_.push_back(copy_of(cells + at, len));
        }
    }

    static std::shared_ptr<T[]> copy_of(const T* cells, size_t len) {
        auto c = std::make_shared_for_overwrite<T[]>(len);
        std::copy_n(cells, len, c.get());
        return c;
    }

    T* own(size_t k) {
        std::shared_ptr<T[]>& c = chunks_[k];
        if (c.use_count() != 1) c = copy_of(c.get(), length(k));
        return c.get();
    }

    std::vector<std::shared_ptr<T[]>> chunks_;
    size_t size_ = 0;
};

}  // namespace ds
