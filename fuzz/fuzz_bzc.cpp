// libFuzzer target: the BZC reader, then every curve tessellated.
#include "crossdiv/io/curve_io.h"
#include "fuzz_curves.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        fuzz::tessellate_what_parses(read_bzc(in, "fuzz.bzc"));
    });
}
