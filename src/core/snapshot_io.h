// The byte level of world snapshots (docs/snapshots.md): numbers written in a fixed order, little
// endian, floats as their exact bits. Each part of the world describes its fields once, as a
// template over the archive, and the writer and the reader both run that description: a field
// cannot be written and then forgotten on reading.
//
// The reader checks as it goes what could make a decoded world read out of bounds: every read
// stays inside the bytes (a short snapshot is "truncated"), booleans are 0 or 1, enums are in
// range, floats finite and counts possible. What a part means (indices that must name live
// objects, lists that must be consistent) is checked by the part that knows it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "core/validation.h"
#include "pivot/math.h"

namespace pivot {

/// The most memory restoring a snapshot may take, in bytes per byte of the snapshot (besides a
/// fixed few kilobytes). The writer and the reader count the same costs (charge: the objects a
/// count of them makes the reader allocate, with what restore sizes by them), since both run
/// the same descriptions; the reader refuses a snapshot whose counts ask for more, before it
/// allocates, and the writer pads a snapshot whose counts would (a pool of many destroyed
/// objects: each costs its slot in memory and 5 bytes in the snapshot).
constexpr std::size_t kSnapshotMemoryPerByte = 16;

/// Writes a snapshot's payload, or (Sink::Hash) only hashes the bytes it would write: World::
/// stateHash, which the tests and the fuzz take before and after every refused call, so it
/// stores nothing and folds 8 bytes at a time.
class SnapshotWriter {
public:
    static constexpr bool kReading = false;
    enum class Sink { Bytes, Hash };

    explicit SnapshotWriter(Sink sink = Sink::Bytes) : sink_(sink) {}

    template <typename T>
    void value(const T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            put(v ? 1u : 0u, 1);
        } else if constexpr (std::is_enum_v<T>) {
            value(static_cast<std::int32_t>(v));
        } else if constexpr (std::is_same_v<T, float>) {
            std::uint32_t bits;
            std::memcpy(&bits, &v, sizeof bits);
            value(bits);
        } else {
            static_assert(std::is_integral_v<T>, "a snapshot field is a number, bool or enum");
            static_assert(sizeof(T) <= 8);
            using U = std::make_unsigned_t<T>;
            put(static_cast<std::uint64_t>(static_cast<U>(v)), sizeof(T));
        }
    }
    void value(const Vec2& v) {
        value(v.x);
        value(v.y);
    }
    void value(const Rot& q) {
        value(q.s);
        value(q.c);
    }
    void value(const Transform& xf) {
        value(xf.p);
        value(xf.q);
    }
    void value(const AABB& box) {
        value(box.lower);
        value(box.upper);
    }
    /// The same as value for a writer; a reader checks the range.
    template <typename E>
    void enumValue(const E& e, int /*count*/) {
        value(static_cast<std::int32_t>(e));
    }
    /// A float that may be any value (a reader takes it as it is).
    void anyFloat(const float& v) { value(v); }
    /// The length of a sequence the caller writes next.
    void count(std::size_t n) { value(static_cast<std::uint32_t>(n)); }
    template <typename T, typename Each>
    void sequence(const std::vector<T>& items, Each&& each) {
        count(items.size());
        charge(2 * items.size() * sizeof(T));  // decoded, and copied into the world
        for (const T& item : items) each(item);
    }
    /// Bytes as they are (the header's magic, a payload inside its frame).
    void raw(const std::uint8_t* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) put(data[i], 1);
    }
    /// The memory restoring what was just written will take (kSnapshotMemoryPerByte).
    void charge(std::size_t bytes) { charged_ += bytes; }
    std::size_t charged() const { return charged_; }
    /// The payload's last field: a count and that many zero bytes, as many as it takes for the
    /// payload to be worth its charge (none, unless pools hold many destroyed objects).
    void padding() {
        const std::size_t needed = (charged_ + kSnapshotMemoryPerByte - 1) / kSnapshotMemoryPerByte;
        const std::size_t size = size_ + 4;
        const std::size_t pad = needed > size ? needed - size : 0;
        count(pad);
        for (std::size_t i = 0; i < pad; ++i) put(0, 1);
    }

    /// Sink::Bytes: what was written.
    std::size_t size() const { return size_; }
    const std::uint8_t* data() const { return bytes_.data(); }
    std::vector<std::uint8_t> bytes() const {
        return {bytes_.begin(), bytes_.begin() + static_cast<std::ptrdiff_t>(size_)};
    }
    /// Sink::Bytes: what was written, moved out (the writer is left empty).
    std::vector<std::uint8_t> take() {
        bytes_.resize(size_);
        size_ = 0;
        return std::move(bytes_);
    }
    /// Sink::Hash: the hash of every byte written, 8 at a time as little-endian words (each
    /// product of FNV-1a's constants folded down, so that a change in any bit reaches every
    /// later one), then the last few one at a time.
    std::uint64_t hash() const {
        std::uint64_t h = hash_;
        for (std::size_t i = 0; i < pendingBytes_; ++i) {
            h = (h ^ ((pending_ >> (8 * i)) & 0xFF)) * 0x100000001b3ull;
        }
        return h;
    }
    /// Empties the writer for another payload, keeping its buffer.
    void clear() {
        size_ = 0;
        charged_ = 0;
        hash_ = kHashStart;
        pending_ = 0;
        pendingBytes_ = 0;
    }

private:
    static constexpr std::uint64_t kHashStart = 0xcbf29ce484222325ull;

    /// The low `n` bytes (n <= 8) of `little`, lowest first; its higher bytes are zero.
    void put(std::uint64_t little, std::size_t n) {
        if (sink_ == Sink::Hash) {
            // Into the word being gathered; a filled word is folded into the hash, and what
            // did not fit starts the next one.
            pending_ |= little << (8 * pendingBytes_);
            const std::size_t room = 8 - pendingBytes_;
            if (n < room) {
                pendingBytes_ += n;
                return;
            }
            hash_ = (hash_ ^ pending_) * 0x100000001b3ull;
            hash_ ^= hash_ >> 29;
            pending_ = room < 8 ? little >> (8 * room) : 0;
            pendingBytes_ = n - room;
            return;
        }
        if (bytes_.size() - size_ < n) bytes_.resize(std::max<std::size_t>(2 * bytes_.size(), 256));
        for (std::size_t i = 0; i < n; ++i) {
            bytes_[size_ + i] = static_cast<std::uint8_t>(little >> (8 * i));
        }
        size_ += n;
    }

    Sink sink_;
    std::vector<std::uint8_t> bytes_;  // Sink::Bytes: the first size_ are written
    std::size_t size_ = 0;
    std::size_t charged_ = 0;
    std::uint64_t hash_ = kHashStart;  // Sink::Hash
    std::uint64_t pending_ = 0;        // the bytes since the last whole word
    std::size_t pendingBytes_ = 0;
};

/// Reads a payload back; every problem throws pivot::Error from `call`.
class SnapshotReader {
public:
    static constexpr bool kReading = true;

    SnapshotReader(const char* call, const std::uint8_t* data, std::size_t size)
        : call_(call), data_(data), size_(size), budget_(kSnapshotMemoryPerByte * size) {}

    template <typename T>
    void value(T& v) {
        if constexpr (std::is_same_v<T, bool>) {
            const std::uint8_t byte = take(1)[0];
            if (byte > 1) corrupt("a flag is " + std::to_string(byte) + ", not 0 or 1");
            v = byte == 1;
        } else if constexpr (std::is_enum_v<T>) {
            static_assert(sizeof(T) == 0, "read enums with enumValue, which checks the range");
        } else if constexpr (std::is_same_v<T, float>) {
            anyFloat(v);
            if (!std::isfinite(v)) corrupt("a number is not finite");
        } else {
            static_assert(std::is_integral_v<T>, "a snapshot field is a number, bool or enum");
            using U = std::make_unsigned_t<T>;
            const std::uint8_t* p = take(sizeof(T));
            U u = 0;
            for (std::size_t i = 0; i < sizeof(T); ++i) u |= static_cast<U>(U(p[i]) << (8 * i));
            v = static_cast<T>(u);
        }
    }
    void value(Vec2& v) {
        value(v.x);
        value(v.y);
    }
    void value(Rot& q) {
        value(q.s);
        value(q.c);
    }
    void value(Transform& xf) {
        value(xf.p);
        value(xf.q);
    }
    void value(AABB& box) {
        value(box.lower);
        value(box.upper);
    }
    template <typename E>
    void enumValue(E& e, int count) {
        std::int32_t raw = 0;
        value(raw);
        if (raw < 0 || raw >= count) corrupt("an enum value is " + std::to_string(raw));
        e = static_cast<E>(raw);
    }
    void anyFloat(float& v) {
        std::uint32_t bits = 0;
        value(bits);
        std::memcpy(&v, &bits, sizeof v);
    }
    /// A sequence's length, refused when the bytes left could not hold that many items of at
    /// least `minItemBytes` each (so a corrupt count cannot make a huge allocation).
    std::size_t count(std::size_t minItemBytes = 1) {
        std::uint32_t n = 0;
        value(n);
        if (minItemBytes > 0 && n > (size_ - offset_) / minItemBytes) {
            truncated("a list of " + std::to_string(n) + " items");
        }
        return n;
    }
    template <typename T, typename Each>
    void sequence(std::vector<T>& items, Each&& each) {
        const std::size_t n = count();
        charge(2 * n * sizeof(T));  // decoded, and copied into the world
        items.assign(n, T{});
        for (T& item : items) each(item);
    }
    /// Counts memory the snapshot makes the reader allocate against its budget
    /// (kSnapshotMemoryPerByte times its size): a snapshot asking for more is refused, before
    /// anything is allocated for it.
    void charge(std::size_t bytes) {
        if (bytes > budget_ - charged_) {
            corrupt("its counts ask for more memory than " +
                    std::to_string(kSnapshotMemoryPerByte) +
                    " bytes per byte of the snapshot, and no snapshot pivot2d writes does");
        }
        charged_ += bytes;
    }

    /// SnapshotWriter::padding's field: its zero bytes, skipped.
    void padding() {
        const std::size_t n = count();
        const std::uint8_t* bytes = take(n);
        if (std::any_of(bytes, bytes + n, [](std::uint8_t b) { return b != 0; })) {
            corrupt("its padding is not zeros");
        }
    }
    bool atEnd() const { return offset_ == size_; }
    [[noreturn]] void corrupt(const std::string& what) const {
        fail(call_, "the snapshot is corrupted: " + what + " (at byte " + std::to_string(offset_) +
                        " of the payload)");
    }
    [[noreturn]] void truncated(const std::string& what) const {
        fail(call_, "the snapshot is truncated: " + what + " goes past its end (byte " +
                        std::to_string(offset_) + " of " + std::to_string(size_) + ")");
    }
    const char* call() const { return call_; }

private:
    const std::uint8_t* take(std::size_t n) {
        if (n > size_ - offset_) truncated("a " + std::to_string(n) + "-byte field");
        const std::uint8_t* p = data_ + offset_;
        offset_ += n;
        return p;
    }

    const char* call_;
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t offset_ = 0;
    std::size_t budget_;
    std::size_t charged_ = 0;
};

/// A handle (pivot/id.h) in a snapshot: its index and generation. A restored one is stamped with
/// the world it is restored into; it may be stale (an event's), which the world's checks tell.
template <typename Io, typename Id>
void snapshotHandle(Io& io, Id& id, std::uint32_t worldId) {
    io.value(id.index);
    io.value(id.generation);
    if constexpr (Io::kReading) id.world = worldId;
}

/// 64-bit FNV-1a over the bytes: the snapshot's checksum (accidental damage, not an attacker).
inline std::uint64_t snapshotChecksum(const std::uint8_t* data, std::size_t size) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t i = 0; i < size; ++i) {
        h ^= data[i];
        h *= 0x100000001b3ull;
    }
    return h;
}

}  // namespace pivot
