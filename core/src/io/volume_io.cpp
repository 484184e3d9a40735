#include "crossdiv/io/volume_io.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "crossdiv/io/output_file.h"
#include "crossdiv/error.h"

namespace crossdiv {

namespace {

enum class SampleType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

int sample_bytes(SampleType t) {
    switch (t) {
        case SampleType::Int8: case SampleType::UInt8: return 1;
        case SampleType::Int16: case SampleType::UInt16: return 2;
        case SampleType::Int32: case SampleType::UInt32: case SampleType::Float32: return 4;
        case SampleType::Float64: return 8;
    }
    return 1;
}

/// Where and how the samples are stored.
struct RawLayout {
    SampleType type = SampleType::UInt8;
    bool big_endian = false;
    std::string data_path;   ///< the file holding the samples
    int64_t skip = 0;        ///< bytes before the samples; -1: the samples are the file's last bytes
};

/// A regular file (not a folder, device or pipe, which would fail to read or never end).
std::ifstream open_regular(const std::string& path, const std::string& what) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw InputError(what + " '" + path + "' is not a readable file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(what + " '" + path + "' cannot be opened");
    return in;
}

std::string read_file(const std::string& path, const std::string& what) {
    std::ifstream in = open_regular(path, what);
    std::string text(std::istreambuf_iterator<char>(in), {});
    if (in.bad()) throw InputError(what + " '" + path + "' could not be read");
    return text;
}

std::string trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return "";
    return std::string(s.substr(first, s.find_last_not_of(" \t\r") - first + 1));
}

std::vector<std::string> words(const std::string& value) {
    std::istringstream in(value);
    return {std::istream_iterator<std::string>(in), {}};
}

int64_t parse_integer(const std::string& word, const std::string& file, int line, const std::string& key) {
    int64_t v = 0;
    const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), v);
    if (ec == std::errc::result_out_of_range) throw ParseError(file, line, key + ": '" + word + "' overflows");
    if (ec != std::errc() || end != word.data() + word.size()) throw ParseError(file, line, key + ": '" + word + "' is not an integer");
    return v;
}

double parse_real(const std::string& word, const std::string& file, int line, const std::string& key) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size()) throw ParseError(file, line, key + ": '" + word + "' is not a number");
    if (!std::isfinite(v) || errno == ERANGE) throw NonFiniteNumber(file, line, key + ": '" + word + "' is not a finite double");
    return v;
}

std::vector<double> parse_reals(const std::string& value, size_t count, const std::string& file, int line, const std::string& key) {
    const std::vector<std::string> w = words(value);
    if (w.size() != count) throw ParseError(file, line, key + " needs " + std::to_string(count) + " numbers, not " + std::to_string(w.size()));
    std::vector<double> out;
    for (const std::string& x : w) out.push_back(parse_real(x, file, line, key));
    return out;
}

std::array<int, 3> parse_sizes(const std::string& value, const std::string& file, int line, const std::string& key) {
    const std::vector<std::string> w = words(value);
    if (w.size() != 3) throw ParseError(file, line, key + " needs 3 sizes (a 3D volume), not " + std::to_string(w.size()));
    std::array<int, 3> n{};
    for (int a = 0; a < 3; ++a) {
        const int64_t v = parse_integer(w[a], file, line, key);
        if (v < 2 || v > kMaxGridSamples) throw ParseError(file, line, key + ": size " + w[a] + " must be 2 .. " + std::to_string(kMaxGridSamples));
        n[a] = static_cast<int>(v);
    }
    return n;
}

bool parse_bool(const std::string& value, const std::string& file, int line, const std::string& key) {
    if (value == "True" || value == "true" || value == "1") return true;
    if (value == "False" || value == "false" || value == "0") return false;
    throw ParseError(file, line, key + ": '" + value + "' is not True or False");
}

/// NRRD's vectors "(a,b,c) (d,e,f)" as `count` numbers.
std::vector<double> parse_vectors(std::string value, size_t count, const std::string& file, int line, const std::string& key) {
    for (char& c : value)
        if (c == '(' || c == ')' || c == ',') c = ' ';
    return parse_reals(value, count, file, line, key);
}

/// The header's folder joined with a data file name it gives.
std::string beside(const std::string& header, const std::string& name) {
    const std::filesystem::path p(name);
    return p.is_absolute() ? name : (std::filesystem::path(header).parent_path() / p).string();
}

template <class T>
double load(const unsigned char* at, bool swap) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, at, sizeof(T));
    if (swap) std::reverse(b, b + sizeof(T));
    T v;
    std::memcpy(&v, b, sizeof(T));
    return static_cast<double>(v);
}

/// The samples of `grid` (size, origin and spacing set) from the bytes the layout names.
void read_samples(ScalarGrid& grid, const RawLayout& layout, const std::string& header_path, const std::string& bytes_if_inline) {
    check_sample_count(grid.size, header_path);
    const int64_t n = grid.num_samples(), size = sample_bytes(layout.type);
    const int64_t need = n * size;
    const std::string& where = layout.data_path.empty() ? header_path : layout.data_path;
    // A data file is read only where the samples are: it may be far larger than they are.
    std::string bytes;
    int64_t available = static_cast<int64_t>(bytes_if_inline.size());
    std::ifstream data;
    if (!layout.data_path.empty()) {
        data = open_regular(layout.data_path, "the data file of " + header_path);
        std::error_code ec;
        available = static_cast<int64_t>(std::filesystem::file_size(layout.data_path, ec));
        if (ec) throw InputError("the data file '" + layout.data_path + "' has no size: " + ec.message());
    }
    const int64_t start = layout.skip < 0 ? available - need : layout.skip;
    if (start < 0 || start > available || need > available - start)
        throw InputError(where + ": " + std::to_string(n) + " samples of " + std::to_string(size) + " bytes need " +
                         std::to_string(need) + " bytes after the first " + std::to_string(std::max<int64_t>(start, 0)) +
                         ", the file has " + std::to_string(available));
    if (layout.data_path.empty()) {
        bytes = bytes_if_inline.substr(static_cast<size_t>(start), static_cast<size_t>(need));
    } else {
        bytes.resize(static_cast<size_t>(need));
        data.seekg(start);
        data.read(bytes.data(), need);
        if (data.gcount() != need) throw InputError(where + ": could not read " + std::to_string(need) + " bytes at " + std::to_string(start));
    }
    const bool swap = layout.big_endian != (std::endian::native == std::endian::big) && size > 1;
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    grid.values.resize(n);
    for (int64_t q = 0; q < n; ++q, p += size) {
        switch (layout.type) {
            case SampleType::Int8: grid.values[q] = load<int8_t>(p, false); break;
            case SampleType::UInt8: grid.values[q] = load<uint8_t>(p, false); break;
            case SampleType::Int16: grid.values[q] = load<int16_t>(p, swap); break;
            case SampleType::UInt16: grid.values[q] = load<uint16_t>(p, swap); break;
            case SampleType::Int32: grid.values[q] = load<int32_t>(p, swap); break;
            case SampleType::UInt32: grid.values[q] = load<uint32_t>(p, swap); break;
            case SampleType::Float32: grid.values[q] = load<float>(p, swap); break;
            case SampleType::Float64: grid.values[q] = load<double>(p, swap); break;
        }
    }
    check_grid(grid, where);
}

/// A header's lines with their numbers, up to where the samples begin.
struct HeaderLine {
    int number;
    std::string text;
};

}  // namespace

ScalarGrid read_metaimage(const std::string& path) {
    const std::string text = read_file(path, "volume");
    ScalarGrid grid;
    RawLayout layout;
    bool have_size = false, have_type = false, have_data = false;
    size_t pos = 0;
    int line = 0;
    while (!have_data && pos < text.size()) {
        const size_t end = std::min(text.find('\n', pos), text.size());
        const std::string raw = text.substr(pos, end - pos);
        pos = end + 1;
        ++line;
        if (trim(raw).empty()) continue;
        const size_t eq = raw.find('=');
        if (eq == std::string::npos) throw ParseError(path, line, "expected 'Key = Value'");
        const std::string key = trim(raw.substr(0, eq)), value = trim(raw.substr(eq + 1));
        if (key == "ObjectType") {
            if (value != "Image") throw ParseError(path, line, "ObjectType " + value + ": only Image is a volume");
        } else if (key == "NDims") {
            if (value != "3") throw ParseError(path, line, "NDims " + value + ": only 3D volumes are read");
        } else if (key == "DimSize") {
            grid.size = parse_sizes(value, path, line, key), have_size = true;
        } else if (key == "ElementType") {
            static const std::pair<const char*, SampleType> kTypes[] = {
                {"MET_CHAR", SampleType::Int8},    {"MET_UCHAR", SampleType::UInt8},  {"MET_SHORT", SampleType::Int16},
                {"MET_USHORT", SampleType::UInt16}, {"MET_INT", SampleType::Int32},    {"MET_UINT", SampleType::UInt32},
                {"MET_FLOAT", SampleType::Float32}, {"MET_DOUBLE", SampleType::Float64}};
            const auto* t = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& k) { return value == k.first; });
            if (t == std::end(kTypes)) throw ParseError(path, line, "ElementType " + value + " is not one crossdiv reads");
            layout.type = t->second, have_type = true;
        } else if (key == "ElementSpacing" || key == "ElementSize") {
            const std::vector<double> v = parse_reals(value, 3, path, line, key);
            if (key == "ElementSpacing" || grid.spacing == Vec3::Ones()) grid.spacing = Vec3(v[0], v[1], v[2]);
        } else if (key == "Offset" || key == "Position" || key == "Origin") {
            const std::vector<double> v = parse_reals(value, 3, path, line, key);
            grid.origin = Vec3(v[0], v[1], v[2]);
        } else if (key == "ElementByteOrderMSB" || key == "BinaryDataByteOrderMSB") {
            layout.big_endian = parse_bool(value, path, line, key);
        } else if (key == "BinaryData") {
            if (!parse_bool(value, path, line, key)) throw ParseError(path, line, "BinaryData False: text samples are not read");
        } else if (key == "CompressedData") {
            if (parse_bool(value, path, line, key)) throw ParseError(path, line, "CompressedData True: compressed samples are not read");
        } else if (key == "HeaderSize") {
            layout.skip = parse_integer(value, path, line, key);
            if (layout.skip < -1) throw ParseError(path, line, "HeaderSize must be >= -1");
        } else if (key == "ElementNumberOfChannels") {
            if (value != "1") throw ParseError(path, line, "ElementNumberOfChannels " + value + ": only scalar volumes are read");
        } else if (key == "TransformMatrix" || key == "Rotation" || key == "Orientation") {
            const std::vector<double> m = parse_reals(value, 9, path, line, key);
            if (m != std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, 1})
                throw ParseError(path, line, key + " is not the identity: rotated volumes are not read");
        } else if (key == "ElementDataFile") {
            if (value == "LIST" || value.find('%') != std::string::npos)
                throw ParseError(path, line, "ElementDataFile " + value + ": only one data file (or LOCAL) is read");
            layout.data_path = value == "LOCAL" ? "" : beside(path, value);
            have_data = true;  // the last header line: LOCAL samples start after it
        } else if (key != "Comment" && key != "AnatomicalOrientation" && key != "CenterOfRotation" && key != "ElementMin" &&
                   key != "ElementMax" && key != "Modality" && key != "Name" && key != "ID" && key != "ParentID" &&
                   key != "CompressedDataSize" && key != "Color") {
            throw ParseError(path, line, "unknown MetaImage key '" + key + "'");
        }
    }
    if (!have_size) throw ParseError(path, line, "no DimSize");
    if (!have_type) throw ParseError(path, line, "no ElementType");
    if (!have_data) throw ParseError(path, line, "no ElementDataFile");
    const std::string inline_bytes = layout.data_path.empty() ? text.substr(std::min(pos, text.size())) : std::string();
    read_samples(grid, layout, path, inline_bytes);
    return grid;
}

ScalarGrid read_nrrd(const std::string& path) {
    const std::string text = read_file(path, "volume");
    if (text.rfind("NRRD000", 0) != 0) throw ParseError(path, 1, "not a NRRD file (no NRRD000n magic)");
    ScalarGrid grid;
    RawLayout layout;
    bool have_size = false, have_type = false, have_spacing = false;
    std::string encoding, endian;
    size_t pos = text.find('\n');
    pos = pos == std::string::npos ? text.size() : pos + 1;
    int line = 1;
    while (pos < text.size()) {
        const size_t end = std::min(text.find('\n', pos), text.size());
        const std::string raw = text.substr(pos, end - pos);
        pos = end + 1;
        ++line;
        if (trim(raw).empty()) break;  // the samples follow (attached data)
        if (raw[0] == '#') continue;
        if (raw.find(":=") != std::string::npos) continue;  // key/value pairs: comments to readers
        const size_t colon = raw.find(": ");
        if (colon == std::string::npos) throw ParseError(path, line, "expected 'field: value'");
        const std::string key = raw.substr(0, colon), value = trim(raw.substr(colon + 2));
        if (key == "dimension") {
            if (value != "3") throw ParseError(path, line, "dimension " + value + ": only 3D volumes are read");
        } else if (key == "sizes") {
            grid.size = parse_sizes(value, path, line, key), have_size = true;
        } else if (key == "type") {
            static const std::pair<std::vector<std::string>, SampleType> kTypes[] = {
                {{"signed char", "int8", "int8_t"}, SampleType::Int8},
                {{"uchar", "unsigned char", "uint8", "uint8_t"}, SampleType::UInt8},
                {{"short", "short int", "signed short", "signed short int", "int16", "int16_t"}, SampleType::Int16},
                {{"ushort", "unsigned short", "unsigned short int", "uint16", "uint16_t"}, SampleType::UInt16},
                {{"int", "signed int", "int32", "int32_t"}, SampleType::Int32},
                {{"uint", "unsigned int", "uint32", "uint32_t"}, SampleType::UInt32},
                {{"float"}, SampleType::Float32},
                {{"double"}, SampleType::Float64}};
            const auto* t = std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& k) {
                return std::find(k.first.begin(), k.first.end(), value) != k.first.end();
            });
            if (t == std::end(kTypes)) throw ParseError(path, line, "type " + value + " is not one crossdiv reads");
            layout.type = t->second, have_type = true;
        } else if (key == "spacings") {
            const std::vector<double> v = parse_reals(value, 3, path, line, key);
            grid.spacing = Vec3(v[0], v[1], v[2]), have_spacing = true;
        } else if (key == "space directions") {
            // Three vectors "(a,b,c)": only an axis-aligned, positive diagonal is a grid.
            const std::vector<double> m = parse_vectors(value, 9, path, line, key);
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 3; ++c)
                    if (r != c && m[3 * r + c] != 0)
                        throw ParseError(path, line, "space directions are not axis-aligned: rotated volumes are not read");
            grid.spacing = Vec3(m[0], m[4], m[8]), have_spacing = true;
        } else if (key == "space origin") {
            const std::vector<double> v = parse_vectors(value, 3, path, line, key);
            grid.origin = Vec3(v[0], v[1], v[2]);
        } else if (key == "encoding") {
            encoding = value;
            if (value != "raw") throw ParseError(path, line, "encoding " + value + ": only raw samples are read");
        } else if (key == "endian") {
            if (value != "little" && value != "big") throw ParseError(path, line, "endian must be little or big");
            layout.big_endian = value == "big";
        } else if (key == "byte skip") {
            layout.skip = parse_integer(value, path, line, key);
            if (layout.skip < -1) throw ParseError(path, line, "byte skip must be >= -1");
        } else if (key == "line skip") {
            if (parse_integer(value, path, line, key) != 0) throw ParseError(path, line, "line skip is not read (only 0)");
        } else if (key == "data file" || key == "datafile") {
            if (value == "LIST" || value.find(' ') != std::string::npos || value.find('%') != std::string::npos)
                throw ParseError(path, line, "data file " + value + ": only one data file is read");
            layout.data_path = beside(path, value);
        } else if (key != "content" && key != "kinds" && key != "labels" && key != "units" && key != "space units" &&
                   key != "centers" && key != "centerings" && key != "space" && key != "space dimension" && key != "min" &&
                   key != "max" && key != "old min" && key != "oldmin" && key != "old max" && key != "oldmax" &&
                   key != "axis mins" && key != "axismins" && key != "axis maxs" && key != "axismaxs" &&
                   key != "thicknesses" && key != "sample units" && key != "measurement frame") {
            throw ParseError(path, line, "unknown NRRD field '" + key + "'");
        }
    }
    if (!have_size) throw ParseError(path, line, "no sizes");
    if (!have_type) throw ParseError(path, line, "no type");
    if (encoding.empty()) throw ParseError(path, line, "no encoding");
    (void)have_spacing;  // without spacings the samples are a unit apart, as Teem takes them
    const std::string inline_bytes = layout.data_path.empty() ? text.substr(std::min(pos, text.size())) : std::string();
    read_samples(grid, layout, path, inline_bytes);
    return grid;
}

ScalarGrid read_volume(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".mhd" || ext == ".mha") return read_metaimage(path);
    if (ext == ".nrrd" || ext == ".nhdr") return read_nrrd(path);
    throw InputError(path + ": unknown volume format '" + ext + "' (MetaImage .mhd/.mha, NRRD .nrrd/.nhdr)");
}

namespace {

std::string reals(const Vec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << v.x() << ' ' << v.y() << ' ' << v.z();
    return s.str();
}

/// The samples as little-endian doubles.
void write_samples(std::ostream& out, const ScalarGrid& grid) {
    for (double v : grid.values) {
        unsigned char b[8];
        std::memcpy(b, &v, 8);
        if (std::endian::native == std::endian::big) std::reverse(b, b + 8);
        out.write(reinterpret_cast<const char*>(b), 8);
    }
}

}  // namespace

void write_metaimage(const std::string& path, const ScalarGrid& grid) {
    const std::filesystem::path raw = std::filesystem::path(path).replace_extension(".raw");
    OutputFile header_file(path);
    std::ostream& header = header_file.stream();
    header << "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
           << "DimSize = " << grid.size[0] << ' ' << grid.size[1] << ' ' << grid.size[2] << '\n'
           << "ElementSpacing = " << reals(grid.spacing) << "\nOffset = " << reals(grid.origin) << '\n'
           << "ElementType = MET_DOUBLE\nElementDataFile = " << raw.filename().string() << '\n';
    header_file.close();
    OutputFile data(raw.string());
    write_samples(data.stream(), grid);
    data.close();
}

void write_nrrd(const std::string& path, const ScalarGrid& grid) {
    OutputFile file(path);
    std::ostream& out = file.stream();
    out.precision(17);
    // A space and its directions, not "spacings": Teem takes "space origin" only with a space.
    const Vec3& h = grid.spacing;
    out << "NRRD0004\ntype: double\ndimension: 3\nspace dimension: 3\n"
        << "sizes: " << grid.size[0] << ' ' << grid.size[1] << ' ' << grid.size[2] << '\n'
        << "space directions: (" << h.x() << ",0,0) (0," << h.y() << ",0) (0,0," << h.z() << ")\n"
        << "space origin: (" << grid.origin.x() << ',' << grid.origin.y() << ',' << grid.origin.z() << ")\n"
        << "encoding: raw\nendian: little\n\n";
    write_samples(out, grid);
    file.close();
}

}  // namespace crossdiv
