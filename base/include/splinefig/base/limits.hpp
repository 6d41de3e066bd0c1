#pragma once
// The limits a request is held to, in one place (docs/limits.md lists each with its reason).
// Naming rule: kMax<Thing> / kMin<Thing>, in the unit the name says.

namespace splinefig {

// Worker threads a request may ask for; more is clamped to this (0 asks for every core).
inline constexpr int kMaxThreads = 256;

}  // namespace splinefig
