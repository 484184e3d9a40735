// libFuzzer target: the BEZ reader, then the patches tessellated and welded.
#include "crossdiv/io/patch_io.h"
#include "crossdiv/surfaces/bezier_patch.h"
#include "fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        const std::vector<BezierPatch> patches = read_bez(in, "fuzz.bez");
        (void)tessellate_patches(patches, 4, 50'000);
    });
}
