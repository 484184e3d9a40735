#pragma once
/// @file
/// The core features the suite's check operations exercise, as the functions they call:
/// core's by default. A test stands a double in (ScopedFeaturesUnderTest) to show that the
/// suite fails on a seeded bug, without editing core; worker processes forked while it is in
/// place inherit it.

#include "crossdiv/verification/comparisons/edit_differential.h"
#include "crossdiv/verification/comparisons/normals_comparison.h"
#include "crossdiv/verification/properties/surface_checks.h"

namespace crossdiv::verification {

struct FeaturesUnderTest {
    OurEdits edits;                           ///< the `edits` operation's flip and split
    NormalsFunction normals = vertex_normals;  ///< the `normals` operation's vertex normals
    SweepBuilder sweep = build_sweep;          ///< the `surfaces` operation's srev and gcyl
};

/// The features in use (core's unless a ScopedFeaturesUnderTest is alive).
const FeaturesUnderTest& features_under_test();

/// Puts `features` in place for its lifetime, then restores the previous ones.
class ScopedFeaturesUnderTest {
public:
    explicit ScopedFeaturesUnderTest(FeaturesUnderTest features);
    ~ScopedFeaturesUnderTest();
    ScopedFeaturesUnderTest(const ScopedFeaturesUnderTest&) = delete;
    ScopedFeaturesUnderTest& operator=(const ScopedFeaturesUnderTest&) = delete;

private:
    FeaturesUnderTest previous_;
};

}  // namespace crossdiv::verification
