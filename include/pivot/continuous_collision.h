// How continuous collision keeps moving bodies from passing through others
// (WorldDef::continuousCollision; it runs when WorldDef::enableContinuous is on).
#pragma once

#include <cstdint>

namespace pivot {

enum class ContinuousCollision : std::uint8_t {
    /// The default. Box2D 2.4.1's: after the step, every contact that may tunnel (a dynamic
    /// body against a static or kinematic one, a bullet against any) gets a time of impact,
    /// and the earliest impact, one after another, is solved as a small island over the rest of
    /// the step. Worlds that must agree with Box2D 2.4.1 bit for bit need it. It also acts on
    /// slow bodies: a body pressed into static ground deeper than the time of impact's target
    /// (a heavy stack's bottom row) is taken back to where it touched, step after step.
    Substeps,
    /// Box2D v3's: only a body that moved more than half its smallest extent in the step
    /// (Body's shapes: a box's half width, a circle's radius) is swept, against static shapes,
    /// and a bullet against every shape but other bullets'. A hit puts the body back at the
    /// moment of impact, its velocity kept, with no solve: the next step's contacts stop it.
    /// Slow bodies cost nothing, and a fast body hitting a dynamic one (both not bullets) can
    /// pass through it, as in Box2D v3. docs/contacts.md compares the two.
    FastBodies,
};

}  // namespace pivot
