#include "crossdiv/io/mesh_io.h"

#include <fstream>
#include <string>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"
#include "crossdiv/io/input_file.h"

namespace crossdiv {
namespace {

std::string extension(const std::string& path) {
    const auto dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find_first_of('/', dot) != std::string::npos) return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace

std::span<const std::string_view> mesh_extensions() {
    static constexpr std::string_view kExtensions[] = {".obj", ".off", ".ply"};
    return kExtensions;
}

PolyMesh read_mesh(const std::string& path) {
    const std::string ext = extension(path);
    if (ext != "obj" && ext != "off" && ext != "ply")
        throw InputError(path + ": unknown mesh format '." + ext + "' (expected .obj, .off or .ply)");
    std::ifstream in = open_input_file(path);
    return ext == "obj" ? read_obj(in, path) : ext == "off" ? read_off(in, path) : read_ply(in, path);
}

void write_mesh(const std::string& path, const PolyMesh& mesh) {
    const std::string ext = extension(path);
    if (ext != "obj" && ext != "off" && ext != "ply")
        throw InputError(path + ": unknown mesh format '." + ext + "' (expected .obj, .off or .ply)");
    OutputFile file(path);
    std::ostream& out = file.stream();
    if (ext == "obj") write_obj(out, mesh);
    else if (ext == "off") write_off(out, mesh);
    else write_ply(out, mesh);
    file.close();
}

}  // namespace crossdiv
