// A process-wide test switch of the engine's (a reference path a test compares the fast one
// with) set for one scope, and put back on, its default, when the scope ends, whatever the
// test's assertions did in between.
#pragma once

namespace pivot {

template <void (*Set)(bool)>
class ScopedSwitch {
public:
    explicit ScopedSwitch(bool on) { Set(on); }
    ~ScopedSwitch() { Set(true); }
    ScopedSwitch(const ScopedSwitch&) = delete;
    ScopedSwitch& operator=(const ScopedSwitch&) = delete;
};

}  // namespace pivot
