#include "crossdiv/verification/suite/features_under_test.h"

#include <utility>

namespace crossdiv::verification {
namespace {

FeaturesUnderTest& current() {
    static FeaturesUnderTest features;
    return features;
}

}  // namespace

const FeaturesUnderTest& features_under_test() { return current(); }

ScopedFeaturesUnderTest::ScopedFeaturesUnderTest(FeaturesUnderTest features) : previous_(std::move(current())) {
    current() = std::move(features);
}

ScopedFeaturesUnderTest::~ScopedFeaturesUnderTest() { current() = std::move(previous_); }

}  // namespace crossdiv::verification
