// libFuzzer target: the suite manifest reader, its programs checked and never run (a fuzzed
// manifest must not execute its commands), then its jobs expanded.
#include "crossdiv/verification/suite/manifest.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        const verification::Manifest m =
            verification::read_manifest(in, "fuzz.suite", "/nonexistent", verification::ProgramStatements::CheckOnly);
        (void)verification::expand_jobs(m);
    });
}
