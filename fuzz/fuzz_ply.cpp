// libFuzzer target: the PLY reader, then the refinement of what it accepts.
#include "crossdiv/io/mesh_io.h"
#include "mesh_refinement.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        fuzz::refine_what_parses(read_ply(in, "fuzz.ply"));
    });
}
