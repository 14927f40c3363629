// SPDX-License-Identifier: MIT
// Open-addressing scratch tables cleared in O(1) by an epoch, for loops that ask millions of
// small membership questions and must not allocate per key: FlatKeyMap64 (64-bit keys with a
// value: the 3D generators' per-insertion edge maps, restricted_delaunay_3d.hpp) and
// FlatFlagSet32 (32-bit keys with two flag bits: the 2D refinement's rounds), with the
// multiplicative-hash slot helpers they share. Only membership and lookup are asked, never an
// order. Header-only, no dependency.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace exactmesh {

/// 64 - log2(slots) for a power-of-two table size: the shift of slot_of_hash.
inline unsigned hash_shift(std::size_t slots) {
    unsigned shift = 64;
    for (std::size_t n = slots; n > 1; n >>= 1) --shift;
    return shift;
}

/// The slot of a multiplicative hash: its top bits (Knuth's Fibonacci hashing), where every
/// bit of the key has mixed in. Bits from the 20th up, as taken before, left the high half of
/// an edge key (the smaller vertex) out of tables below 2^12 slots (a cavity's edges: those at
/// one vertex all probed from one slot, three probes a lookup) and out of most of larger ones'
/// bits. Only the slots change: the maps are asked for membership, never an order (entries()
/// is sorted by its callers), so the meshes are the same bit for bit.
inline std::size_t slot_of_hash(std::uint64_t hash, unsigned shift) {
    return static_cast<std::size_t>(hash >> shift);
}

/// An open-addressing hash table of 64-bit keys (edge keys), cleared in O(1) by an epoch: the
/// scratch sets and maps of one insertion, reused so that no insertion allocates (node-based
/// std::unordered_set/map allocated per key: a tenth of refinement's instructions in malloc
/// and free). Only membership and lookup are asked, never an order.
template <class Value>
class FlatKeyMap64 {
  public:
    /// Forgets every key.
    void clear() {
        if (++epoch_ == 0) {
            for (Slot& slot : slots_) slot.epoch = 0;
            epoch_ = 1;
        }
        size_ = 0;
    }

    /// Forgets every key and uses the first slots only, as many as about `expected` keys need
    /// (the least power of two from 64 that is at least 4 expected): the table grows to the
    /// largest cavity met (a facet's thousands of edges), and a small cavity's keys spread over
    /// all of it missed the cache at nearly every key.
    void clear(std::size_t expected) {
        clear();
        std::size_t wanted = 64;
        while (wanted < 4 * expected) wanted *= 2;
        if (wanted > slots_.size()) slots_.assign(wanted, Slot{});  // epoch 0: no key
        used_ = wanted;
        shift_ = hash_shift(used_);
    }

    /// The value of `key`, inserted as `value` when missing; second: whether it was inserted.
    std::pair<Value*, bool> emplace(std::uint64_t key, Value value) {
        if (2 * (size_ + 1) > used_) grow();
        std::size_t i = position(key);
        while (slots_[i].epoch == epoch_) {
            if (slots_[i].key == key) return {&slots_[i].value, false};
            i = (i + 1) & (used_ - 1);
        }
        slots_[i] = {key, value, epoch_};
        ++size_;
        return {&slots_[i].value, true};
    }

    bool contains(std::uint64_t key) const {
        if (used_ == 0) return false;
        std::size_t i = position(key);
        while (slots_[i].epoch == epoch_) {
            if (slots_[i].key == key) return true;
            i = (i + 1) & (used_ - 1);
        }
        return false;
    }

  private:
    struct Slot {
        std::uint64_t key = 0;
        Value value{};
        std::uint32_t epoch = 0;
    };
    std::vector<Slot> slots_;
    std::size_t used_ = 0;  ///< the slots in use: a power of two, at most slots_.size()
    std::size_t size_ = 0;
    std::uint32_t epoch_ = 1;
    unsigned shift_ = 64;  ///< 64 - log2(used_)

    std::size_t position(std::uint64_t key) const {
        return slot_of_hash(key * 0x9E3779B97F4A7C15ull, shift_);
    }

    /// Twice the slots in use, the keys put in again.
    void grow() {
        std::vector<Slot> live;
        for (std::size_t i = 0; i < used_; ++i)
            if (slots_[i].epoch == epoch_) live.push_back(slots_[i]);
        const std::size_t wanted = std::max<std::size_t>(64, 2 * used_);
        if (wanted > slots_.size()) slots_.resize(wanted, Slot{});
        clear();
        used_ = wanted;
        shift_ = hash_shift(used_);
        for (const Slot& slot : live) {
            std::size_t i = position(slot.key);
            while (slots_[i].epoch == epoch_) i = (i + 1) & (used_ - 1);
            slots_[i] = {slot.key, slot.value, epoch_};
            ++size_;
        }
    }
};

/// FlatKeyMap64's compact sibling for 32-bit keys (triangle slots, vertices) with two flag bits
/// each: 8 bytes a slot (a 64-bit key, a value and an epoch took 16), at most half full, cleared
/// in O(1) by an epoch. A parallel refinement's round asks it about 10^4 keys per round in
/// order on one thread; at half the bytes its table stays in the level-2 cache.
class FlatFlagSet32 {
  public:
    /// Forgets every key and uses as many slots as about `expected` keys need (the least power
    /// of two from 64 that is at least twice as many).
    void clear(std::size_t expected) {
        if (++epoch_ == kEpochs) {
            for (Slot& slot : slots_) slot.tag = 0;
            epoch_ = 1;
        }
        size_ = 0;
        std::size_t wanted = 64;
        while (wanted < 2 * expected) wanted *= 2;
        if (wanted > slots_.size()) slots_.resize(wanted, Slot{});  // tag 0: no key
        used_ = wanted;
        shift_ = hash_shift(used_);
    }

    /// The flags of `key` (0 when it is not in the set).
    unsigned flags(std::uint32_t key) const {
        if (used_ == 0) return 0;
        for (std::size_t i = position(key);; i = (i + 1) & (used_ - 1)) {
            const Slot& slot = slots_[i];
            if (slot.tag >> 2 != epoch_) return 0;
            if (slot.key == key) return slot.tag & 3u;
        }
    }

    /// Adds `key` (when missing) and ORs `flags` (1, 2 or 3) into its flags.
    void add(std::uint32_t key, unsigned flags) {
        if (2 * (size_ + 1) > used_) grow();
        std::size_t i = position(key);
        while (slots_[i].tag >> 2 == epoch_) {
            if (slots_[i].key == key) {
                slots_[i].tag |= flags;
                return;
            }
            i = (i + 1) & (used_ - 1);
        }
        slots_[i] = {key, epoch_ << 2 | flags};
        ++size_;
    }

  private:
    struct Slot {
        std::uint32_t key = 0;
        std::uint32_t tag = 0;  ///< epoch << 2 | flags; an older epoch: empty
    };
    static constexpr std::uint32_t kEpochs = 1u << 30;
    std::vector<Slot> slots_;
    std::size_t used_ = 0;  ///< the slots in use: a power of two, at most slots_.size()
    std::size_t size_ = 0;
    std::uint32_t epoch_ = 0;
    unsigned shift_ = 64;

    std::size_t position(std::uint32_t key) const {
        return slot_of_hash(std::uint64_t{key} * 0x9E3779B97F4A7C15ull, shift_);
    }

    /// Twice the slots in use, the keys put in again.
    void grow() {
        std::vector<Slot> live;
        for (std::size_t i = 0; i < used_; ++i)
            if (slots_[i].tag >> 2 == epoch_) live.push_back(slots_[i]);
        clear(used_);  // twice used_ slots: clear takes twice the expected count
        for (const Slot& slot : live) add(slot.key, slot.tag & 3u);
    }
};

}  // namespace exactmesh
