// The tangential springs of a step's contacts, by contact key: an open-addressing hash table
// (linear probing, a power-of-two capacity at most half full) whose storage is kept from step
// to step. A granular step meets thousands of contacts; a node-based map allocated and freed
// one node per contact per step, which cost a tenth of the step (docs/performance.md).
#pragma once

#include "schemes/bodies.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rotbench {

class SpringTable {
public:
    // The spring of `key`, or zero for a contact the table does not hold.
    Vec3 find(std::uint64_t key) const {
        if (size_ == 0) return Vec3::Zero();
        for (std::size_t i = slot(key);; i = (i + 1) & mask()) {
            if (keys_[i] == key) return springs_[i];
            if (keys_[i] == empty) return Vec3::Zero();
        }
    }
    // Sets the spring of `key`, adding the contact if the table does not hold it.
    void put(std::uint64_t key, const Vec3& spring) {
        if (2 * (size_ + 1) > keys_.size()) grow();
        std::size_t i = slot(key);
        while (keys_[i] != empty && keys_[i] != key) i = (i + 1) & mask();
        if (keys_[i] == empty) keys_[i] = key, ++size_;
        springs_[i] = spring;
    }
    void clear() {
        if (size_ == 0) return;
        std::fill(keys_.begin(), keys_.end(), empty);
        size_ = 0;
    }
    std::size_t size() const { return size_; }
    void swap(SpringTable& other) noexcept {
        keys_.swap(other.keys_);
        springs_.swap(other.springs_);
        std::swap(size_, other.size_);
    }

private:
    static constexpr std::uint64_t empty = ~std::uint64_t{0};  // no contact has this key
    std::size_t mask() const { return keys_.size() - 1; }
    // splitmix64's finaliser: contact keys are two packed indices, far from uniform.
    std::size_t slot(std::uint64_t key) const {
        key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
        key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
        return static_cast<std::size_t>(key ^ (key >> 31)) & mask();
    }
    void grow() {
        std::vector<std::uint64_t> keys(std::max<std::size_t>(64, 2 * keys_.size()), empty);
        std::vector<Vec3> springs(keys.size());
        keys.swap(keys_);
        springs.swap(springs_);
        size_ = 0;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != empty) put(keys[i], springs[i]);
    }

    std::vector<std::uint64_t> keys_;
    std::vector<Vec3> springs_;
    std::size_t size_ = 0;
};

}  // namespace rotbench
