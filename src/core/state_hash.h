// FNV-1a over the exact bits of the values fed to it: two states hash alike only if every
// float is bit-identical, which is what a determinism check needs.
#pragma once

#include <cstdint>
#include <cstring>

#include "pivot/math.h"

namespace pivot {

class StateHasher {
public:
    void add(std::int32_t value) { addBytes(&value, sizeof value); }
    void add(std::uint64_t value) { addBytes(&value, sizeof value); }
    void add(bool value) { add(static_cast<std::int32_t>(value)); }
    void add(float value) { addBytes(&value, sizeof value); }
    void add(Vec2 value) {
        add(value.x);
        add(value.y);
    }
    void add(Rot value) {
        add(value.s);
        add(value.c);
    }
    void add(Transform value) {
        add(value.p);
        add(value.q);
    }
    std::uint64_t value() const { return hash_; }

private:
    void addBytes(const void* data, std::size_t size) {
        unsigned char bytes[8];
        std::memcpy(bytes, data, size);
        for (std::size_t i = 0; i < size; ++i) {
            hash_ ^= bytes[i];
            hash_ *= 0x100000001b3ull;
        }
    }
    std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

}  // namespace pivot
