// The byte level of snapshots as docs/snapshots.md specifies it, for tests that take snapshots
// apart: the header, the lineage, the checksum, and patching a field of a payload and sealing
// it again so that it gets past the checksum to the reader's own checks.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "pivot/pivot.h"

namespace pivot::test_support {

constexpr std::size_t kSnapshotHeader = 20;  // magic, version, payload size
constexpr std::size_t kSnapshotLineage = 4;  // the payload's first field
/// Where the state begins: the settings, then the pools (docs/snapshots.md).
constexpr std::size_t kSnapshotState = kSnapshotHeader + kSnapshotLineage;

/// 64-bit FNV-1a of the payload, little endian at the end.
inline void reseal(std::vector<std::uint8_t>& bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = kSnapshotHeader; i < bytes.size() - 8; ++i) {
        h ^= bytes[i];
        h *= 0x100000001b3ull;
    }
    for (int i = 0; i < 8; ++i)
        bytes[bytes.size() - 8 + i] = static_cast<std::uint8_t>(h >> (8 * i));
}

/// What World::restore throws for `bytes`, or "" when it takes them.
inline std::string restoreError(World& world, const std::vector<std::uint8_t>& bytes) {
    try {
        world.restore(bytes);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// The state a snapshot holds: its bytes without the header, the lineage and the checksum.
inline std::vector<std::uint8_t> stateOf(const std::vector<std::uint8_t>& bytes) {
    return {bytes.begin() + kSnapshotState, bytes.end() - 8};
}

/// The little-endian bytes of a 32-bit value (an int, or a float's bits).
template <typename T>
std::vector<std::uint8_t> bytesOf(T value) {
    static_assert(sizeof(T) == 4);
    std::uint32_t bits;
    std::memcpy(&bits, &value, 4);
    return {std::uint8_t(bits), std::uint8_t(bits >> 8), std::uint8_t(bits >> 16),
            std::uint8_t(bits >> 24)};
}

/// Overwrites 4 bytes at `at` with `value` (not resealed).
template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t at, T value) {
    const std::vector<std::uint8_t> b = bytesOf(value);
    std::copy(b.begin(), b.end(), bytes.begin() + static_cast<std::ptrdiff_t>(at));
}

/// Where `pattern` occurs in the payload, each offset from the start of the bytes.
inline std::vector<std::size_t> find(const std::vector<std::uint8_t>& bytes,
                                     const std::vector<std::uint8_t>& pattern) {
    std::vector<std::size_t> at;
    for (auto it = bytes.begin() + kSnapshotHeader;;) {
        it = std::search(it, bytes.end() - 8, pattern.begin(), pattern.end());
        if (it == bytes.end() - 8) return at;
        at.push_back(static_cast<std::size_t>(it - bytes.begin()));
        ++it;
    }
}

}  // namespace pivot::test_support
