// pivot2d's one error mechanism: a public call given bad input throws pivot::Error, whose
// message names the call, the offending field and its value, and leaves the world exactly as
// it was before the call (every check runs before anything is changed).
#pragma once

#include <stdexcept>
#include <string>

namespace pivot {

class Error : public std::invalid_argument {
public:
    explicit Error(const std::string& message) : std::invalid_argument(message) {}
};

}  // namespace pivot
