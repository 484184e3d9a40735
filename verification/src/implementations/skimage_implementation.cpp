// scikit-image's marching cubes as an implementation: a program (adapters/skimage/
// skimage_marching_cubes.py) run confined in a folder of its own, the samples handed over as a
// MetaImage file and the surface read back as OBJ.
#include <fmt/format.h>

#include <filesystem>

#include "crossdiv/io/volume_io.h"
#include "crossdiv/verification/harness/install_paths.h"
#include "crossdiv/verification/harness/process.h"
#include "crossdiv/verification/harness/temporary_folder.h"
#include "crossdiv/verification/implementations/program_implementation.h"
#include "library_implementations.h"

namespace crossdiv::verification::detail {
namespace {

/// One run may take this long (the largest grid of the isosurface study takes about a second).
constexpr double kSkimageTimeoutSeconds = 120;

class Skimage final : public Implementation {
public:
    Skimage() : Implementation("skimage", "scikit-image (adapters/skimage)", ImplementationKind::Program, capabilities()) {}

    bool confines_itself() const override { return true; }

    TriMesh isosurface(const ScalarGrid& grid, const IsosurfaceOptions& options, const std::string& method) const override {
        if (method != "lewiner" && method != "lorensen")
            lacks("marching cubes method '" + method + "' (it has lewiner and lorensen)");
        const TemporaryFolder folder("skimage");
        const std::string volume = (folder.path() / "volume.mhd").string(), out = (folder.path() / "surface.obj").string();
        const std::string err = (folder.path() / "stderr.txt").string();
        write_metaimage(volume, grid);
        // Debian's python has scikit-image; another python3 earlier on PATH may not.
        const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
        const ProcessResult p = run_confined({python, adapters_dir() + "/skimage/skimage_marching_cubes.py", volume,
                                              fmt::format("{:.17g}", options.level),
                                              options.inside == InsideIs::Below ? "below" : "above", method, out},
                                             {folder.path().string(), kSkimageTimeoutSeconds, "", err});
        const std::string said = tail_of_file(err);
        if (!p.started) throw ImplementationFailure(RunStatus::Unavailable, p.start_error);
        if (p.timed_out)
            throw ImplementationFailure(RunStatus::Timeout, fmt::format("killed after {:.0f} s", kSkimageTimeoutSeconds));
        if (p.signal != 0) throw ImplementationFailure(RunStatus::Crashed, fmt::format("signal {}: {}", p.signal, said));
        if (p.exit_code == 3) throw ImplementationFailure(RunStatus::Unavailable, said);  // scikit-image is not installed
        if (p.exit_code != 0)
            throw ImplementationFailure(RunStatus::ExitStatus, fmt::format("exit status {}: {}", p.exit_code, said));
        const PolyMesh result = read_program_result(out, "skimage");  // throws ImplementationFailure
        try {
            return to_tri_mesh(result, "an isosurface");
        } catch (const InputError& e) {
            throw ImplementationFailure(RunStatus::NotTriangles, e.what());
        }
    }

private:
    static Capabilities capabilities() {
        Capabilities c;
        c.isosurface = true;
        c.precision = Precision::Float;  // scikit-image computes the crossings in float32
        return c;
    }
};

}  // namespace

std::unique_ptr<Implementation> make_skimage_implementation() { return std::make_unique<Skimage>(); }

}  // namespace crossdiv::verification::detail
