// How the broad phase sizes the boxes it finds pairs with (WorldDef::broadPhaseBoxes).
#pragma once

#include <cstdint>

namespace pivot {

enum class BroadPhaseBoxes : std::uint8_t {
    /// Box2D 2.4.1's: a shape that leaves its box gets the box it swept this step, fattened by
    /// kAabbMargin and stretched ahead by kAabbMotionFactor times its displacement, so pairs
    /// form steps before a fast shape arrives. Worlds that must agree with Box2D 2.4.1 bit for
    /// bit need it (it decides which contacts exist, and so their order).
    Predictive,
    /// The default.
    /// Box2D v3's: the box fattened by v3's margins only (kCompactAabbMargin, and
    /// kCompactStaticAabbMargin for static shapes), around where the shape ended the step. Fast
    /// shapes pair with far fewer shapes they never touch (Box2D v3's spinner, tumbler and
    /// smash scenes keep 27%, 47% and 38% of the contacts Predictive makes), and moving many
    /// shapes costs one partial rebuild of the tree instead of a re-insertion each. Static
    /// bodies' shapes are kept in a tree of their own, which moving shapes query beside theirs.
    /// Continuous collision finds what it did: a shape that moved further than the margin has
    /// its sweep paired once with the shapes it passed that could stop it (docs/contacts.md).
    Compact,
};

}  // namespace pivot
