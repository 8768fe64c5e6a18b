// The velocity-sweep data of the contacts the wide sweeps solve (contact_solver_wide.cpp), kept
// in tiles of kContactLanes contacts: each field of a tile is kContactLanes floats in a row, one
// per contact, so a sweep loads a field for all its lanes with one vector load, and a tile's
// fields lie next to each other in memory (one stream, however many fields). Tiles are written
// once per build (ContactSolver::prepare) and read by every sweep after.
//
// Which contacts are tiled is fixed when the solver is reset for an island: in each batch of
// independent contacts, the first kContactLanes * floor(size / kContactLanes) in runs of
// kContactLanes from the batch's start; the rest are solved one at a time. The team cuts a
// batch into blocks at multiples of kBatchAlignment from its start (islands/team.h), so a block's
// wide run always starts where a tile does, whatever the number of workers. A tile starting at
// contact k is tile k / kContactLanes: distinct tiles never overlap, so their indices differ.
//
// A tiled contact's impulses live in its tile: every sweep, wide or one contact at a time,
// reads and writes them there.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "constraints/lanes.h"
#include "core/buffer.h"
#include "core/index_range.h"

namespace pivot {

#if PIVOT_LANES_8
constexpr int kContactLanes = 8;
#else
constexpr int kContactLanes = 4;
#endif
static_assert(kBatchAlignment % kContactLanes == 0, "blocks must start where tiles do");

struct ContactTile {
    // A contact's fields, then each of its two points'.
    enum Field : int {
        kNormalX,
        kNormalY,
        kFriction,
        kMassA,
        kMassB,
        kInertiaA,
        kInertiaB,
        kKxx,  // K, the two-point normal effective mass: columns (kxx, kxy) and (kyx, kyy)
        kKxy,
        kKyx,
        kKyy,
        kMxx,  // its inverse, likewise
        kMxy,
        kMyx,
        kMyy,
        kContactFields
    };
    enum PointField : int {
        kAnchorAx,
        kAnchorAy,
        kAnchorBx,
        kAnchorBy,
        kNormalMass,
        kTangentMass,
        kNormalImpulse,
        kTangentImpulse,
        kVelocityBias,
        kSoftTarget,
        kBaseSeparation,  // soft contacts: what later substeps measure their separation from
        kPointFields
    };
    static constexpr int kFields = kContactFields + 2 * kPointFields;

    float* lanes(Field f) { return values[f]; }
    const float* lanes(Field f) const { return values[f]; }
    float* lanes(int point, PointField f) {
        return values[kContactFields + point * kPointFields + f];
    }
    const float* lanes(int point, PointField f) const {
        return values[kContactFields + point * kPointFields + f];
    }

    float values[kFields][kContactLanes];
    std::int32_t indexA[kContactLanes];  // solver slots
    std::int32_t indexB[kContactLanes];
    std::int32_t pointCount[kContactLanes];  // points the velocity sweeps solve (1 or 2)
};

class ContactTiles {
public:
    /// Lays out `count` contacts: tiles for the independent batches (those not `serial`) of
    /// `batches` (none without batches, or when `enabled` is false). Reuses the buffers.
    void layOut(int count, const std::vector<Batch>* batches, bool enabled) {
        resizeBuffer(slot_, static_cast<std::size_t>(count));
        std::fill(slot_.begin(), slot_.end(), -1);
        resizeBuffer(tiles_, static_cast<std::size_t>(count / kContactLanes + 1));
        if (!enabled || batches == nullptr) return;
        for (const Batch& batch : *batches) {
            if (batch.serial) continue;
            const int tiled = (batch.end - batch.begin) / kContactLanes * kContactLanes;
            for (int offset = 0; offset < tiled; ++offset) {
                const int start = batch.begin + offset / kContactLanes * kContactLanes;
                slot_[batch.begin + offset] =
                    start / kContactLanes * kContactLanes + offset % kContactLanes;
            }
        }
    }
    void reserve(std::size_t count) {
        slot_.reserve(count);
        tiles_.reserve(count / kContactLanes + 1);
    }

    /// Contact k's place in the tiles (tile * kContactLanes + lane), or -1 if it has none.
    int slot(int k) const { return slot_[k]; }
    /// Whether a tile starts at contact k.
    bool isTileStart(int k) const { return slot_[k] >= 0 && slot_[k] % kContactLanes == 0; }
    /// The tile that starts at contact k (a wide run's).
    ContactTile& tileAt(int k) { return tiles_[k / kContactLanes]; }
    const ContactTile& tileAt(int k) const { return tiles_[k / kContactLanes]; }
    ContactTile& tileOf(int slot) { return tiles_[slot / kContactLanes]; }
    const ContactTile& tileOf(int slot) const { return tiles_[slot / kContactLanes]; }

private:
    std::vector<std::int32_t> slot_;
    std::vector<ContactTile> tiles_;
};

}  // namespace pivot
