// Value handles for the objects a World owns. A handle is a slot index, the generation of the
// slot when the object was created, and the id of the world that made it. A handle that
// outlives its object (the slot was freed or reused) or comes from another world is detected
// and rejected instead of being dereferenced. A default-constructed handle is null.
#pragma once

#include <cstdint>

namespace pivot {

namespace detail {
/// Shared representation; the tag type keeps body, shape and joint ids from mixing.
template <typename Tag>
struct Handle {
    std::int32_t index = -1;
    std::uint32_t generation = 0;
    std::uint32_t world = 0;  // 0: made by no world (null)

    constexpr bool isNull() const { return world == 0; }
    friend constexpr bool operator==(Handle a, Handle b) {
        return a.index == b.index && a.generation == b.generation && a.world == b.world;
    }
    friend constexpr bool operator!=(Handle a, Handle b) { return !(a == b); }
};
struct BodyTag {};
struct ShapeTag {};
struct JointTag {};
struct MouseJointTag {};
}  // namespace detail

using BodyId = detail::Handle<detail::BodyTag>;
using ShapeId = detail::Handle<detail::ShapeTag>;
using JointId = detail::Handle<detail::JointTag>;
using MouseJointId = detail::Handle<detail::MouseJointTag>;

}  // namespace pivot
