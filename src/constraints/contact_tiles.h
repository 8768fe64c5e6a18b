// The velocity-sweep data of the contacts the wide sweeps solve (contact_solver_wide.cpp), kept
// in tiles of kContactLanes contacts: each field of a tile is kContactLanes floats in a row, one
// per contact, so a sweep loads a field for all its lanes with one vector load, and a tile's
// fields lie next to each other in memory (one stream, however many fields). Tiles are written
// once per build (ContactSolver::prepare) and read by every sweep after.
//
// Which contacts are tiled is fixed when the solver is reset for an island: each batch of
// independent contacts, in runs of kContactLanes from the batch's start, the last run's spare
// lanes left empty (no points: every sweep leaves them and their bodies as they are, and nothing
// is written back from them). (Measured on many_pyramids, whose islands' colours hold a tile
// and a few: tiling every remainder took about 10% off the step; leaving remainders of fewer
// than 4 to the one-by-one path was no faster, within the noise.) The team cuts a batch into blocks
// at multiples of kBatchAlignment from its start (islands/team.h), so a block's tiles always start
// at its start, whatever the number of workers.
//
// A tiled contact's constraint lives only in its tile: a sweep that solves it one contact at a
// time (where a range's edge cuts its tile) reads a copy from there and writes its impulses
// back.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "collision/manifold.h"
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
    // Solver slots; an empty lane repeats lane 0's, which no other tile of the batch touches,
    // so reading them is safe while other workers solve the batch's other tiles.
    std::int32_t indexA[kContactLanes];
    std::int32_t indexB[kContactLanes];
    std::int32_t pointCount[kContactLanes];  // points the velocity sweeps solve (1 or 2; 0: empty)
    std::int32_t contactCount;               // lanes in use, from lane 0
};

// The NGS position sweeps' constants of the same contacts, in the same slots: what
// ContactPositionConstraint holds, a field of kContactLanes floats at a time. (Gathered lane by
// lane from the constraints at each of a step's three sweeps, they made the wide sweep a sixth
// slower in large_pyramid.) An empty lane has no points and lane 0's bodies, and either zeros
// and a FaceA manifold (cleared at layout) or lane 0's contact (written by prepareTile): a
// manifold type some lane already has, so that it takes no branch of its own.
struct PositionTile {
    enum Field : int {
        kMassA,
        kMassB,
        kInertiaA,
        kInertiaB,
        kRadiusA,
        kRadiusB,
        kCenterAx,  // the bodies' local centres of mass
        kCenterAy,
        kCenterBx,
        kCenterBy,
        kNormalX,  // the manifold's local normal and point
        kNormalY,
        kPointX,
        kPointY,
        kPoint0x,  // its points' local positions
        kPoint0y,
        kPoint1x,
        kPoint1y,
        kFields
    };
    float* lanes(Field f) { return values[f]; }
    const float* lanes(Field f) const { return values[f]; }
    /// Point j's x and y fields.
    float* pointX(int j) { return values[kPoint0x + 2 * j]; }
    float* pointY(int j) { return values[kPoint0y + 2 * j]; }
    const float* pointX(int j) const { return values[kPoint0x + 2 * j]; }
    const float* pointY(int j) const { return values[kPoint0y + 2 * j]; }

    float values[kFields][kContactLanes];
    std::int32_t indexA[kContactLanes];
    std::int32_t indexB[kContactLanes];
    std::int32_t pointCount[kContactLanes];  // the manifold's (0: empty)
    std::int32_t type[kContactLanes];        // its ManifoldType
};

class ContactTiles {
public:
    /// Lays out `count` contacts: tiles for the independent batches (those not `serial`) of
    /// `batches` (none without batches, or when `enabled` is false), and with `positions` a
    /// PositionTile beside each tile. Reuses the buffers.
    void layOut(int count, const std::vector<Batch>* batches, bool enabled, bool positions) {
        growBuffer(slot_, static_cast<std::size_t>(count));
        std::fill(slot_.begin(), slot_.begin() + count, -1);
        std::size_t tiles = 0;
        if (enabled && batches != nullptr) {
            for (const Batch& batch : *batches) {
                if (!batch.serial) tiles += static_cast<std::size_t>(tilesOf(batch));
            }
        }
        // Every lane of a tile is written before it is read (by prepare, or cleared below).
        growBuffer(tiles_, tiles);
        positions_ = positions;
        if (positions) growBuffer(positionTiles_, tiles);
        if (tiles == 0) return;
        int tile = 0;
        for (const Batch& batch : *batches) {
            if (batch.serial) continue;
            for (int start = batch.begin; start < batch.end; start += kContactLanes, ++tile) {
                const int contacts = std::min(kContactLanes, batch.end - start);
                for (int lane = 0; lane < contacts; ++lane) {
                    slot_[start + lane] = tile * kContactLanes + lane;
                }
                ContactTile& t = tiles_[tile];
                t.contactCount = contacts;
                for (int lane = contacts; lane < kContactLanes; ++lane) clearLane(t, lane);
                if (positions) {
                    for (int lane = contacts; lane < kContactLanes; ++lane) {
                        clearLane(positionTiles_[tile], lane);
                    }
                }
            }
        }
    }
    /// Room for `count` contacts in batches of at most `batches` colours.
    void reserve(std::size_t count, std::size_t batches) {
        slot_.reserve(count);
        tiles_.reserve(count / kContactLanes + batches);
        positionTiles_.reserve(count / kContactLanes + batches);
    }

    /// Contact k's place in the tiles (tile * kContactLanes + lane), or -1 if it has none.
    int slot(int k) const { return slot_[k]; }
    /// Whether a tile starts at contact k.
    bool isTileStart(int k) const { return slot_[k] >= 0 && slot_[k] % kContactLanes == 0; }
    /// The tile that starts at contact k (a wide run's).
    ContactTile& tileAt(int k) { return tileOf(slot_[k]); }
    const ContactTile& tileAt(int k) const { return tileOf(slot_[k]); }
    ContactTile& tileOf(int slot) { return tiles_[slot / kContactLanes]; }
    const ContactTile& tileOf(int slot) const { return tiles_[slot / kContactLanes]; }
    /// Whether the layout has position tiles.
    bool hasPositions() const { return positions_; }
    /// The position tile beside the tile of `slot` (only when hasPositions()).
    PositionTile& positionTileOf(int slot) { return positionTiles_[slot / kContactLanes]; }
    const PositionTile& positionTileOf(int slot) const {
        return positionTiles_[slot / kContactLanes];
    }

private:
    static int tilesOf(const Batch& batch) {
        return (batch.end - batch.begin + kContactLanes - 1) / kContactLanes;
    }
    /// An empty lane: no points, zeros (finite, whatever the sweeps compute from them).
    static void clearLane(ContactTile& tile, int lane) {
        for (auto& field : tile.values) field[lane] = 0.0f;
        tile.pointCount[lane] = 0;
    }
    static void clearLane(PositionTile& tile, int lane) {
        for (auto& field : tile.values) field[lane] = 0.0f;
        tile.pointCount[lane] = 0;
        tile.type[lane] = static_cast<std::int32_t>(ManifoldType::FaceA);
    }

    std::vector<std::int32_t> slot_;
    std::vector<ContactTile> tiles_;
    std::vector<PositionTile> positionTiles_;  // beside tiles_, when positions_
    bool positions_ = false;
};

}  // namespace pivot
