// A share of an array: elements [begin, end).
#pragma once

namespace pivot {

struct IndexRange {
    int begin = 0;
    int end = 0;
};

}  // namespace pivot
