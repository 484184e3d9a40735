// libFuzzer target: the SWP reader, then every curve tessellated and every srev and gcyl
// record built (with a small triangle limit, so one input stays fast).
#include "crossdiv/io/curve_io.h"
#include "crossdiv/surfaces/sweep_surface.h"
#include "fuzz_curves.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    return fuzz::refuse_or_answer([&] {
        std::istringstream in = fuzz::stream_of(data, size);
        const CurveFile file = read_swp(in, "fuzz.swp");
        fuzz::tessellate_what_parses(file);
        SweepOptions o;
        o.max_triangles = 50'000;
        for (int k = 0; k < static_cast<int>(file.sweeps.size()); ++k)
            fuzz::refuse_or_answer([&] { (void)build_sweep(file, k, o); });
    });
}
