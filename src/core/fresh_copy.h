// Resetting a small object to its default value with plain 16-byte moves.
//
// `object = T{}` for a joint constraint (about 200 bytes) is compiled by g++ 12 (tuned for no
// particular processor, as this library is) into `rep stos`, whose start-up is long for so few
// bytes. The joints' set-up resets one constraint per joint per substep: there the `rep stos`
// was a tenth of the set-up's time in `many_chains`. Written out below, one statement per 16
// bytes (no loop, which the compiler would turn back into the same instruction), the reset is a
// dozen stores of constants.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pivot {

namespace detail {

#if defined(__SSE2__)
template <std::size_t... I>
inline void copy16s(unsigned char* to, const unsigned char* from, std::index_sequence<I...>) {
    (_mm_storeu_si128(reinterpret_cast<__m128i*>(to + 16 * I),
                      _mm_loadu_si128(reinterpret_cast<const __m128i*>(from + 16 * I))),
     ...);
}
#endif

}  // namespace detail

/// object = T{}, the same bytes, without a string instruction where SSE2 is there to avoid one.
template <typename T>
inline void resetToDefault(T& object) {
    static_assert(std::is_trivially_copyable_v<T>, "reset by copying bytes");
#if defined(__SSE2__)
    static const T fresh{};
    constexpr std::size_t kWhole = sizeof(T) / 16;
    constexpr std::size_t kTail = sizeof(T) % 16;
    auto* to = reinterpret_cast<unsigned char*>(&object);
    const auto* from = reinterpret_cast<const unsigned char*>(&fresh);
    detail::copy16s(to, from, std::make_index_sequence<kWhole>{});
    if constexpr (kTail > 0) std::memcpy(to + 16 * kWhole, from + 16 * kWhole, kTail);
#else
    object = T{};
#endif
}

}  // namespace pivot
