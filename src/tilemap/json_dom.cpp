// SPDX-License-Identifier: MIT
#include "json_dom.hpp"

#include <algorithm>

namespace ds::json {

namespace {

using Json = nlohmann::json;

void pack(std::vector<uint8_t>& bytes, uint32_t gid) {
    for (int b = 0; b < 4; ++b) bytes.push_back(uint8_t(gid >> (8 * b)));
}

uint32_t unpack(const std::vector<uint8_t>& bytes, size_t i) {
    return uint32_t(bytes[4 * i]) | uint32_t(bytes[4 * i + 1]) << 8 | uint32_t(bytes[4 * i + 2]) << 16 |
           uint32_t(bytes[4 * i + 3]) << 24;
}

// nlohmann's DOM, built event by event, packing the arrays of a "data" key
// while every element is a gid; the first element that is not turns what
// came so far into an ordinary array, and reading goes on as usual (so a bad
// gid is reported by the reader as it would be from any array).
class PackingDom final : public nlohmann::json_sax<Json> {
public:
    PackingDom(Json& root, DomError& error) : root_(root), error_(error) {}

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool v) override { return add(Json(v)); }
    bool number_integer(number_integer_t v) override { return add(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override {
        if (packing_ && v <= UINT32_MAX) {
            pack(bytes_, uint32_t(v));
            return true;
        }
        return add(Json(v));
    }
    bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
    bool string(string_t& v) override { return add(Json(std::move(v))); }
    bool binary(binary_t& v) override { return add(Json::binary(std::move(v))); }
    bool key(string_t& k) override {
        key_ = std::move(k);
        return true;
    }
    bool start_object(std::size_t) override {
        spill();
        open_.push_back(place(Json(Json::value_t::object)));
        return true;
    }
    bool end_object() override {
        open_.pop_back();
        return true;
    }
    bool start_array(std::size_t) override {
        spill();
        const bool gids = !open_.empty() && open_.back()->is_object() && key_ == "data";
        open_.push_back(place(Json(Json::value_t::array)));
        packing_ = gids;
        bytes_.clear();
        return true;
    }
    bool end_array() override {
        if (packing_) *open_.back() = Json::binary(std::move(bytes_));
        packing_ = false;
        bytes_.clear();
        open_.pop_back();
        return true;
    }
    bool parse_error(std::size_t byte, const std::string&, const nlohmann::detail::exception& e) override {
        error_ = {byte, e.what()};
        return false;
    }

private:
    void spill() {
        if (!packing_) return;
        packing_ = false;
        Json& array = *open_.back();
        for (size_t i = 0; i < bytes_.size() / 4; ++i) array.push_back(unpack(bytes_, i));
        bytes_.clear();
    }
    bool add(Json v) {
        spill();
        place(std::move(v));
        return true;
    }
    // Where a new value goes: the root, the end of the open array, or the
    // open object's last key (a repeated key keeps its last value, as
    // nlohmann's own DOM does). Containers on open_ never move: only the
    // innermost one grows.
    Json* place(Json v) {
        if (open_.empty()) {
            root_ = std::move(v);
            return &root_;
        }
        Json& top = *open_.back();
        if (top.is_array()) {
            top.push_back(std::move(v));
            return &top.back();
        }
        Json& slot = top[key_];
        slot = std::move(v);
        return &slot;
    }

    Json& root_;
    DomError& error_;
    std::vector<Json*> open_;
    std::string key_;
    bool packing_ = false;
    std::vector<uint8_t> bytes_;
};

}  // namespace

bool parse_dom(std::string_view text, Json& out, DomError& error) {
    PackingDom dom(out, error);
    return Json::sax_parse(text.begin(), text.end(), &dom);
}

bool is_packed_gids(const Json& v) { return v.is_binary(); }

std::vector<uint32_t> packed_gids(const Json& v, size_t max) {
    const std::vector<uint8_t>& bytes = v.get_binary();
    const size_t n = std::min(bytes.size() / 4, max);
    std::vector<uint32_t> gids(n);
    for (size_t i = 0; i < n; ++i) gids[i] = unpack(bytes, i);
    return gids;
}

void unpack_gids(Json& v) {
    if (!v.is_binary()) return;
    const std::vector<uint8_t> bytes = std::move(v.get_binary());
    v = Json::array();
    for (size_t i = 0; i < bytes.size() / 4; ++i) v.push_back(unpack(bytes, i));
}

}  // namespace ds::json
