// core/fresh_copy.h: resetToDefault writes exactly the bytes of T{}, whatever T's size (whole
// 16-byte blocks, a tail, or neither) and whatever its defaults (not only zeros).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "core/fresh_copy.h"
#include "joints/revolute_constraint.h"

namespace pivot {
namespace {

template <typename T>
void expectResetsToDefault() {
    T object;
    std::memset(static_cast<void*>(&object), 0xA5, sizeof(T));  // unlike any default
    resetToDefault(object);
    static const T fresh{};  // static: its padding is zeros, as resetToDefault's source's
    EXPECT_EQ(std::memcmp(&object, &fresh, sizeof(T)), 0) << sizeof(T) << " bytes";
}

struct Tail {  // 3 * 16 + 4 bytes, defaults not zero
    float values[13] = {1.0f, 2.0f, 3.0f,  4.0f,  5.0f,  6.0f, 7.0f,
                        8.0f, 9.0f, 10.0f, 11.0f, 12.0f, 13.0f};
};
struct Blocks {  // 2 * 16 bytes
    std::int32_t values[8] = {-1, 0, 1, 2, 3, 4, 5, 6};
};
struct Small {  // under one block
    float x = 0.5f;
    std::int32_t n = 7;
};

TEST(FreshCopy, ResetGivesTheDefaultBytes) {
    expectResetsToDefault<Tail>();
    expectResetsToDefault<Blocks>();
    expectResetsToDefault<Small>();
    expectResetsToDefault<RevoluteConstraint>();
}

}  // namespace
}  // namespace pivot
