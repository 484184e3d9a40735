// Volume files: MetaImage and NRRD written and read back bit-exactly, hand-written headers of
// each sample type and byte order, and the refusals, each naming the file and line or sample.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>

#include "crossdiv/error.h"
#include "crossdiv/io/volume_io.h"

using namespace crossdiv;

namespace {

std::filesystem::path temp_dir() {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("crossdiv_volume_io_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir);
    return dir;
}

void write(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

std::string error_of(const std::string& path) {
    try {
        read_volume(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

ScalarGrid small_grid() {
    ScalarGrid g;
    g.size = {3, 2, 2};
    g.origin = Vec3(-1.5, 0.25, 1e-3);
    g.spacing = Vec3(0.1, 0.2, 1.0 / 3);
    for (int q = 0; q < 12; ++q) g.values.push_back(q * 0.1 - 0.55);
    return g;
}

}  // namespace

TEST(VolumeIo, MetaImageAndNrrdReadBackExactly) {
    const auto dir = temp_dir();
    const ScalarGrid g = small_grid();
    write_metaimage((dir / "g.mhd").string(), g);
    write_nrrd((dir / "g.nrrd").string(), g);
    for (const char* name : {"g.mhd", "g.nrrd"}) {
        const ScalarGrid r = read_volume((dir / name).string());
        EXPECT_EQ(r.size, g.size) << name;
        EXPECT_EQ(r.origin, g.origin) << name;
        EXPECT_EQ(r.spacing, g.spacing) << name;
        EXPECT_EQ(r.values, g.values) << name;
    }
    EXPECT_TRUE(std::filesystem::exists(dir / "g.raw"));
}

TEST(VolumeIo, ReadsInlineAndDetachedSamplesOfEachByteOrder) {
    const auto dir = temp_dir();
    // .mha, unsigned bytes after the header.
    write(dir / "a.mha", "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementSpacing = 1 2 3\nOffset = 0 0 0\n"
                         "ElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + std::string("\x00\x01\x02\x03\x04\x05\x06\xff", 8));
    const ScalarGrid a = read_volume((dir / "a.mha").string());
    EXPECT_EQ(a.values, (std::vector<double>{0, 1, 2, 3, 4, 5, 6, 255}));
    EXPECT_EQ(a.spacing, Vec3(1, 2, 3));
    // .nhdr naming a big-endian short file whose samples are its last bytes (byte skip -1).
    std::string shorts = "junk";
    for (int v : {-2, -1, 0, 1, 2, 3, 300, -300}) shorts += {static_cast<char>((v >> 8) & 0xff), static_cast<char>(v & 0xff)};
    write(dir / "b.raw", shorts);
    write(dir / "b.nhdr", "NRRD0004\n# a comment\ntype: short\ndimension: 3\nsizes: 2 2 2\nspacings: 0.5 0.5 0.5\n"
                          "encoding: raw\nendian: big\nbyte skip: -1\ndata file: b.raw\nkinds: domain domain domain\n");
    const ScalarGrid b = read_volume((dir / "b.nhdr").string());
    EXPECT_EQ(b.values, (std::vector<double>{-2, -1, 0, 1, 2, 3, 300, -300}));
    EXPECT_EQ(b.spacing, Vec3(0.5, 0.5, 0.5));
    // MetaImage little-endian floats with a header size to skip.
    std::string floats = "XX";
    for (float v : {0.5f, -0.25f, 1.f, 2.f, 3.f, 4.f, 5.f, 6.f}) floats += std::string(reinterpret_cast<const char*>(&v), 4);
    write(dir / "c.raw", floats);
    write(dir / "c.mhd", "NDims = 3\nDimSize = 2 2 2\nElementType = MET_FLOAT\nHeaderSize = 2\nElementDataFile = c.raw\n");
    EXPECT_EQ(read_volume((dir / "c.mhd").string()).values[1], -0.25);
}

TEST(VolumeIo, RefusesWhatItCannotReadByName) {
    const auto dir = temp_dir();
    const std::string head = "NDims = 3\nDimSize = 2 2 2\n";
    write(dir / "gz.mha", head + "CompressedData = True\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n");
    EXPECT_NE(error_of((dir / "gz.mha").string()).find("gz.mha:3: CompressedData True"), std::string::npos);
    write(dir / "key.mha", head + "Frobnicate = 1\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n");
    EXPECT_NE(error_of((dir / "key.mha").string()).find("key.mha:3: unknown MetaImage key 'Frobnicate'"), std::string::npos);
    write(dir / "big.mha", "NDims = 3\nDimSize = 99999999999999999999 2 2\n");
    EXPECT_NE(error_of((dir / "big.mha").string()).find("big.mha:2: DimSize: '99999999999999999999' overflows"), std::string::npos);
    write(dir / "many.mha", "NDims = 3\nDimSize = 100000 100000 100000\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n");
    EXPECT_NE(error_of((dir / "many.mha").string()).find("more than the"), std::string::npos);
    write(dir / "short.mha", head + "ElementType = MET_SHORT\nElementDataFile = LOCAL\n1234");
    EXPECT_NE(error_of((dir / "short.mha").string()).find("need 16 bytes"), std::string::npos) << error_of((dir / "short.mha").string());
    write(dir / "missing.mhd", head + "ElementType = MET_SHORT\nElementDataFile = nowhere.raw\n");
    EXPECT_NE(error_of((dir / "missing.mhd").string()).find("nowhere.raw' is not a readable file"), std::string::npos);
    // A folder (or a device) as the data file: refused, not read until it fails or forever.
    write(dir / "folder.mhd", head + "ElementType = MET_SHORT\nElementDataFile = .\n");
    EXPECT_NE(error_of((dir / "folder.mhd").string()).find("is not a readable file"), std::string::npos);
    write(dir / "zero.mhd", head + "ElementType = MET_SHORT\nElementDataFile = /dev/zero\n");
    EXPECT_NE(error_of((dir / "zero.mhd").string()).find("/dev/zero' is not a readable file"), std::string::npos);
    EXPECT_NE(error_of(dir.string() + "/").find("unknown volume format"), std::string::npos);
    const float nan = std::numeric_limits<float>::quiet_NaN(), zero = 0;
    std::string samples;
    for (int q = 0; q < 8; ++q) samples += std::string(reinterpret_cast<const char*>(q == 3 ? &nan : &zero), 4);
    write(dir / "nan.mha", head + "ElementType = MET_FLOAT\nElementDataFile = LOCAL\n" + samples);
    EXPECT_NE(error_of((dir / "nan.mha").string()).find("sample (1, 1, 0) is not finite"), std::string::npos);
    write(dir / "rot.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nspace directions: (0,1,0) (1,0,0) (0,0,1)\n"
                            "encoding: raw\n\n12345678");
    EXPECT_NE(error_of((dir / "rot.nrrd").string()).find("rot.nrrd:5: space directions are not axis-aligned"), std::string::npos);
    write(dir / "gzip.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\n\n");
    EXPECT_NE(error_of((dir / "gzip.nrrd").string()).find("gzip.nrrd:5: encoding gzip"), std::string::npos);
    write(dir / "two.nrrd", "NRRD0004\ntype: uchar\ndimension: 2\n");
    EXPECT_NE(error_of((dir / "two.nrrd").string()).find("two.nrrd:3: dimension 2"), std::string::npos);
    write(dir / "x.vol", "");
    EXPECT_NE(error_of((dir / "x.vol").string()).find("unknown volume format"), std::string::npos);
    write(dir / "notnrrd.nrrd", "hello\n");
    EXPECT_NE(error_of((dir / "notnrrd.nrrd").string()).find("no NRRD000n magic"), std::string::npos);
}
