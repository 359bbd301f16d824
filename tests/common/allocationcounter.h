// SPDX-License-Identifier: MIT
#pragma once

// Counts heap allocations, to prove the real-time path makes none. Linking
// allocationcounter.cpp into an executable replaces its global operator new and delete.

namespace semhap::test {

/** Starts counting from zero. */
void startCountingAllocations();
/** Stops counting and returns how many allocations were made since the start. */
long stopCountingAllocations();

} // namespace semhap::test
