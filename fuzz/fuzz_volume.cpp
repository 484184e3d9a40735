// libFuzzer target: the volume readers (the first byte picks MetaImage or NRRD, the rest is the
// file, samples inline), then marching cubes under both face rules on what they accept.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "crossdiv/io/volume_io.h"
#include "crossdiv/volume/marching_cubes.h"
#include "fuzz_input.h"

namespace {

/// The two files the inputs are written to, one pair per fuzzing process, removed when it ends
/// (libFuzzer's run ends by exit(): a run that finds a crash leaves them, with its artifact).
struct ScratchFiles {
    std::string stem =
        (std::filesystem::temp_directory_path() / ("crossdiv-fuzz-volume-" + std::to_string(getpid()))).string();
    ~ScratchFiles() {
        std::error_code ignored;
        for (const char* extension : {".nrrd", ".mha"}) std::filesystem::remove(stem + extension, ignored);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace crossdiv;
    if (size == 0) return 0;
    // The readers take a path (a detached header names its data file beside it).
    static const ScratchFiles scratch;
    const std::string path = scratch.stem + (data[0] % 2 ? ".nrrd" : ".mha");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
    return fuzz::refuse_or_answer([&] {
        const ScalarGrid grid = read_volume(path);
        for (AmbiguousFaceRule rule : {AmbiguousFaceRule::AsymptoticDecider, AmbiguousFaceRule::SeparateMinority})
            marching_cubes(grid, {grid.values[grid.values.size() / 2], InsideIs::Below, rule});
    });
}
