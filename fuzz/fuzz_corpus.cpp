// Writes the seed corpora of the fuzz targets into DIR/<target>/: the bundled meshes, the
// edge-case catalog and the polygon meshes as OBJ, OFF and PLY; the bundled curve and
// surface files; the course files (../shared/data) when present; the suites. Generated at
// fuzzing time, so the repository holds no copy of any of them.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "crossdiv/datasets/bundled.h"
#include "crossdiv/datasets/bundled_curves.h"
#include "crossdiv/datasets/bundled_surfaces.h"
#include "crossdiv/datasets/edge_cases.h"
#include "crossdiv/io/mesh_io.h"

namespace fs = std::filesystem;
using namespace crossdiv;

namespace {

void write_text(const fs::path& p, const std::string& text) {
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

void copy_into(const std::string& file, const fs::path& dir) {
    fs::create_directories(dir);
    fs::copy_file(file, dir / fs::path(file).filename(), fs::copy_options::overwrite_existing);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: fuzz_corpus OUT_DIR SOURCE_DIR\n");
        return 2;
    }
    const fs::path out = argv[1], source = argv[2];
    std::vector<std::pair<std::string, PolyMesh>> meshes;
    for (const auto& b : datasets::bundled_meshes()) meshes.emplace_back(b.name, b.mesh);
    for (const auto& b : datasets::polygon_meshes()) meshes.emplace_back(b.name, b.mesh);
    for (const auto& c : datasets::edge_cases())
        if (c.mesh.num_vertices() <= 5000) meshes.emplace_back(c.name, c.mesh);
    for (const auto& [name, mesh] : meshes)
        for (const char* ext : {"obj", "off", "ply"}) {
            fs::create_directories(out / ext);
            write_mesh((out / ext / (name + "." + ext)).string(), mesh);
        }
    for (const auto& c : datasets::bundled_curves()) write_text(out / c.format / (c.name + "." + c.format), c.text);
    for (const auto& s : datasets::bundled_surfaces()) write_text(out / s.format / (s.name + "." + s.format), s.text);
    for (const std::string& f : datasets::course_curve_files()) copy_into(f, out / fs::path(f).extension().string().substr(1));
    for (const std::string& f : datasets::course_surface_files()) copy_into(f, out / fs::path(f).extension().string().substr(1));
    for (const std::string& f : datasets::course_mesh_files())
        if (const std::string ext = fs::path(f).extension().string(); ext == ".obj" || ext == ".off")
            if (fs::file_size(f) <= 200'000) copy_into(f, out / ext.substr(1));
    // Volumes with inline samples, behind fuzz_volume's format byte: a sphere's distance field
    // as MetaImage bytes and as NRRD floats.
    {
        std::string bytes, floats;
        for (int k = 0; k < 6; ++k)
            for (int j = 0; j < 6; ++j)
                for (int i = 0; i < 6; ++i) {
                    const float d = std::sqrt(float((i - 2.5) * (i - 2.5) + (j - 2.5) * (j - 2.5) + (k - 2.5) * (k - 2.5))) - 2;
                    bytes += static_cast<char>(std::clamp(int(128 + 40 * d), 0, 255));
                    floats += std::string(reinterpret_cast<const char*>(&d), 4);  // the fuzzers run on little-endian x86
                }
        write_text(out / "volume" / "sphere-mha", std::string(1, '\0') +
                   "ObjectType = Image\nNDims = 3\nDimSize = 6 6 6\nElementSpacing = 0.5 0.5 0.5\nOffset = -1 -1 -1\n"
                   "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + bytes);
        write_text(out / "volume" / "sphere-nrrd", std::string(1, '\1') +
                   "NRRD0004\ntype: float\ndimension: 3\nsizes: 6 6 6\nspacings: 1 1 1\nencoding: raw\nendian: little\n\n" + floats);
    }
    for (const auto& e : fs::directory_iterator(source / "verification" / "suites"))
        if (e.path().extension() == ".suite") copy_into(e.path().string(), out / "manifest");
    std::printf("seed corpora in %s\n", out.c_str());
    return 0;
}
