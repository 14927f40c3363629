// SPDX-License-Identifier: MIT
// Open-addressing hash maps for the 3D generators' insertion (restricted_delaunay_3d.hpp):
// FlatKeyMap64 (base/flat_tables.hpp), per-insertion scratch of 64-bit edge keys cleared in
// O(1); TombstoneMap, a lasting map with erase, as KeyMap64 (edge keys) and Key3Map (sorted
// vertex triples: subfaces); EdgeSubfaces, the subfaces at each edge. All hash by multiplies
// and probe linearly.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/flat_tables.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"

namespace exactmesh::generators::restricted_3d {

/// Key equality by components: std::array's operator== on a face key (three 32-bit vertices)
/// compiles to a call to memcmp (2.6% of the wing's refinement instructions).
inline bool same_key(std::uint64_t a, std::uint64_t b) {
    return a == b;
}
inline bool same_key(const triangulation::Key3& a, const triangulation::Key3& b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// The scratch tables and the hash slot helpers live in base/flat_tables.hpp (the 2D
// refinement's rounds use them too); named here as this layer has always named them.
using exactmesh::FlatFlagSet32;
using exactmesh::FlatKeyMap64;
using exactmesh::hash_shift;
using exactmesh::slot_of_hash;

/// An open-addressing hash map that keeps its keys, with erase (tombstones); `Hash` gives a
/// 64-bit hash whose top bits pick the slot (slot_of_hash). Used as KeyMap64 and Key3Map below.
template <class Key, class Value, class Hash>
class TombstoneMap {
  public:
    /// Inserts `key` with `value` when missing; whether it was inserted.
    bool emplace(const Key& key, const Value& value) {
        if (2 * (size_ + tombstones_ + 1) > slots_.size()) rehash();
        std::size_t i = position(key);
        std::size_t free = kNoSlot;
        while (slots_[i].state != State::Empty) {
            if (slots_[i].state == State::Full && same_key(slots_[i].key, key)) return false;
            if (slots_[i].state == State::Erased && free == kNoSlot) free = i;
            i = (i + 1) & (slots_.size() - 1);
        }
        if (free != kNoSlot) {
            i = free;
            --tombstones_;
        }
        slots_[i].key = key;
        slots_[i].state = State::Full;
        slots_[i].value = value;
        ++size_;
        return true;
    }

    /// The value of `key`, or nullptr.
    const Value* find(const Key& key) const {
        if (slots_.empty()) return nullptr;
        std::size_t i = position(key);
        while (slots_[i].state != State::Empty) {
            if (slots_[i].state == State::Full && same_key(slots_[i].key, key))
                return &slots_[i].value;
            i = (i + 1) & (slots_.size() - 1);
        }
        return nullptr;
    }
    Value* find(const Key& key) { return const_cast<Value*>(std::as_const(*this).find(key)); }

    std::size_t count(const Key& key) const { return find(key) != nullptr ? 1 : 0; }

    const Value& at(const Key& key) const {
        const Value* value = find(key);
        if (value == nullptr) throw InternalError("TombstoneMap::at: missing key");
        return *value;
    }

    void erase(const Key& key) {
        if (slots_.empty()) return;
        std::size_t i = position(key);
        while (slots_[i].state != State::Empty) {
            if (slots_[i].state == State::Full && same_key(slots_[i].key, key)) {
                slots_[i].state = State::Erased;
                --size_;
                ++tombstones_;
                return;
            }
            i = (i + 1) & (slots_.size() - 1);
        }
    }

    std::size_t size() const { return size_; }

    /// Every entry, in no particular order.
    std::vector<std::pair<Key, Value>> entries() const {
        std::vector<std::pair<Key, Value>> out;
        out.reserve(size_);
        for (const Slot& slot : slots_)
            if (slot.state == State::Full) out.emplace_back(slot.key, slot.value);
        return out;
    }

  private:
    enum class State : std::uint8_t { Empty, Full, Erased };
    struct Slot {
        Key key{};
        State state = State::Empty;
        Value value{};
    };
    static constexpr std::size_t kNoSlot = ~std::size_t{0};
    std::vector<Slot> slots_;
    std::size_t size_ = 0;
    std::size_t tombstones_ = 0;
    unsigned shift_ = 64;  ///< 64 - log2(slots_.size())

    std::size_t position(const Key& key) const { return slot_of_hash(Hash{}(key), shift_); }

    /// Twice the live entries' room (at least 64 slots), tombstones dropped.
    void rehash() {
        std::vector<Slot> old = std::move(slots_);
        std::size_t capacity = 64;
        while (capacity < 4 * (size_ + 1)) capacity *= 2;
        slots_.assign(capacity, Slot{});
        shift_ = hash_shift(capacity);
        size_ = 0;
        tombstones_ = 0;
        for (const Slot& slot : old)
            if (slot.state == State::Full) emplace(slot.key, slot.value);
    }
};

struct EdgeKeyHash64 {
    std::uint64_t operator()(std::uint64_t key) const { return key * 0x9E3779B97F4A7C15ull; }
};
struct Key3Hash64 {
    std::uint64_t operator()(const triangulation::Key3& key) const {
        const std::uint64_t h = (std::uint64_t{key[0]} << 32 | key[1]) * 0x9E3779B97F4A7C15ull;
        return (h ^ key[2]) * 0xC2B2AE3D27D4EB4Full;
    }
};

/// 64-bit edge keys to values, with erase: the subsegments, asked for nearly every edge a
/// cavity meets (most are none: std::unordered_map's prime-modulo bucket and node chase were a
/// twentieth of refinement).
template <class Value>
using KeyMap64 = TombstoneMap<std::uint64_t, Value, EdgeKeyHash64>;

/// Sorted vertex triples (subface keys, sorted3) to values, with erase: the subfaces, asked for
/// nearly every face a cavity meets. std::unordered_map's node chase, its memcmp of keys and its
/// node allocations were a third of refinement's time on thin domains, whose insertions are
/// mostly subface splits.
template <class Value>
using Key3Map = TombstoneMap<triangulation::Key3, Value, Key3Hash64>;

/// The subfaces at each edge, as the third corners of the subfaces holding it (the subface is
/// sorted3 of the edge's ends and the third): two at an edge inside a facet, one per facet at a
/// segment. Up to kInline thirds live in the edge's slot of an open-addressing map, more (a
/// segment shared by more facets) in an overflow multimap. Thirds come back in the order they
/// were added, except that a removal moves the last one into the removed one's place.
class EdgeSubfaces {
  public:
    void add(std::uint64_t edge, triangulation::VertIdx third) {
        Thirds* thirds = map_.find(edge);
        if (thirds == nullptr) {
            map_.emplace(edge, Thirds{{third}, 1});
            return;
        }
        if (thirds->count < kInline) {
            thirds->corner[thirds->count++] = third;
        } else {
            overflow_.emplace(edge, third);
        }
    }

    void remove(std::uint64_t edge, triangulation::VertIdx third) {
        Thirds* thirds = map_.find(edge);
        if (thirds == nullptr) return;
        for (std::uint32_t i = 0; i < thirds->count; ++i) {
            if (thirds->corner[i] != third) continue;
            thirds->corner[i] = thirds->corner[--thirds->count];
            const auto extra = overflow_.find(edge);  // refill from the overflow
            if (extra != overflow_.end()) {
                thirds->corner[thirds->count++] = extra->second;
                overflow_.erase(extra);
            }
            if (thirds->count == 0) map_.erase(edge);
            return;
        }
        const auto range = overflow_.equal_range(edge);
        for (auto it = range.first; it != range.second; ++it) {
            if (it->second == third) {
                overflow_.erase(it);
                return;
            }
        }
    }

    bool contains(std::uint64_t edge) const { return map_.find(edge) != nullptr; }

    /// Calls f(third) for each subface at `edge`.
    template <class F>
    void for_each(std::uint64_t edge, F&& f) const {
        const Thirds* thirds = map_.find(edge);
        if (thirds == nullptr) return;
        for (std::uint32_t i = 0; i < thirds->count; ++i) f(thirds->corner[i]);
        if (thirds->count < kInline || overflow_.empty()) return;
        const auto range = overflow_.equal_range(edge);
        for (auto it = range.first; it != range.second; ++it) f(it->second);
    }

  private:
    static constexpr std::uint32_t kInline = 4;
    struct Thirds {
        std::array<triangulation::VertIdx, kInline> corner{};
        std::uint32_t count = 0;
    };
    KeyMap64<Thirds> map_;
    std::unordered_multimap<std::uint64_t, triangulation::VertIdx> overflow_;
};

}  // namespace exactmesh::generators::restricted_3d
