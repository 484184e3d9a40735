// The report's interactive pages: the curve editor's data (which records it edits, names that
// stay apart, core's runs within their tolerances, coordinates written exactly) and the levels
// page's arrays (edges once each, hand-encoded base64).
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "crossdiv/io/curve_io.h"
#include "crossdiv/verification/pages/editor_page.h"
#include "crossdiv/verification/pages/levels_page.h"
#include "crossdiv/verification/pages/page_arrays.h"

namespace crossdiv::verification {
namespace {

CurveFile swp(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    return read_swp(in, name);
}

TEST(EditorPage, EditsChainsAndWindowsAndNamesWhatItLeavesOut) {
    const CurveFile f = swp("bez2 a 8 4 [0 0] [1 2] [3 2] [4 0]\n"
                            "tcb2 t 8 4 [0 0] [1 1] [2 0] [3 1]\n"
                            "crc3 . 6 3 [0 0 0] [1 0 1] [0 1 2]\n"
                            "circ c 12 1\n",
                            "one.swp");
    const nlohmann::json d = editor_data({f}, "title", false);
    ASSERT_EQ(d["curves"].size(), 2u);
    EXPECT_EQ(d["curves"][0]["keyword"], "bez2");
    EXPECT_EQ(d["curves"][0]["name"], "a");
    EXPECT_EQ(d["curves"][0]["steps"], 8);
    EXPECT_EQ(d["curves"][1]["name"], ".");  // anonymous stays anonymous in a file of its own
    EXPECT_EQ(d["curves"][1]["points"][2], nlohmann::json::array({0.0, 1.0, 2.0}));
    EXPECT_FALSE(d["curves"][0].contains("core"));
    ASSERT_EQ(d["skipped"].size(), 2u);
    EXPECT_EQ(d["skipped"][0], "one: t (tcb2, line 2)");
    EXPECT_EQ(d["skipped"][1], "one: c (circ, line 4)");
}

TEST(EditorPage, CurvesOfSeveralFilesKeepApartNames) {
    const CurveFile a = swp("bez2 s 8 4 [0 0] [1 2] [3 2] [4 0]\n", "dir/first.swp");
    const CurveFile b = swp("bez2 s 8 4 [0 0] [1 2] [3 2] [4 0]\nbsp2 . 8 4 [0 0] [1 2] [3 2] [4 0]\n", "second.swp");
    const nlohmann::json d = editor_data({a, b}, "title", false);
    ASSERT_EQ(d["curves"].size(), 3u);
    EXPECT_EQ(d["curves"][0]["name"], "first.s");
    EXPECT_EQ(d["curves"][1]["name"], "second.s");
    EXPECT_EQ(d["curves"][2]["name"], "second.1");
}

TEST(EditorPage, CoordinatesAreWrittenExactly) {
    // 0.1 and 1/3 are not decimals in binary: JSON's 17 digits read back to the same doubles.
    const CurveFile f = swp("bsp2 x 4 4 [0.1 0.3333333333333333] [1 2] [3 2] [4 1e-300]\n", "x.swp");
    const nlohmann::json d = editor_data({f}, "title", false);
    const nlohmann::json back = nlohmann::json::parse(d.dump());
    EXPECT_EQ(back["curves"][0]["points"][0][0].get<double>(), 0.1);
    EXPECT_EQ(back["curves"][0]["points"][0][1].get<double>(), 0.3333333333333333);
    EXPECT_EQ(back["curves"][0]["points"][3][1].get<double>(), 1e-300);
}

TEST(EditorPage, CoreRunsMeetTheirToleranceAndFramesAreUnit) {
    const CurveFile f = swp("bez3 k 16 7 [0 0 0] [1 2 0] [3 2 1] [4 0 1] [5 -2 1] [7 -2 0] [8 0 0]\n", "k.swp");
    const nlohmann::json core = core_curve_views(f.curves[0]);
    int distance = 0;
    for (const auto& r : core["tessellations"]) {
        EXPECT_EQ(r["points"].size(), r["edges"].get<size_t>() + 1);
        if (r["mode"] != "distance") continue;
        ++distance;
        // The distance mode's guarantee: the measured deviation within the asked tolerance.
        EXPECT_LE(r["deviation"].get<double>(), r["tol"].get<double>()) << r["tol"];
        EXPECT_GT(r["deviation"].get<double>(), 0.0);
    }
    EXPECT_EQ(distance, 3);
    // Finer tolerances take more edges.
    EXPECT_LT(core["tessellations"][0]["edges"].get<int>(), core["tessellations"][2]["edges"].get<int>());
    for (const char* method : {"recursive", "rmf"}) {
        const auto& fr = core["frames"][method];
        ASSERT_EQ(fr["T"].size(), fr["points"].size());
        EXPECT_EQ(fr["points"].size(), 2u * 16 + 1);  // the uniform tessellation: STEPS per segment
        for (size_t i = 0; i < fr["T"].size(); ++i)
            for (const char* v : {"T", "N", "B"}) {
                const auto& x = fr[v][i];
                const double norm = std::hypot(x[0].get<double>(), x[1].get<double>(), x[2].get<double>());
                EXPECT_NEAR(norm, 1.0, 1e-12) << method << " " << v << " " << i;
            }
    }
}

TEST(LevelsPage, EdgesOnceEachAsLittleEndianBase64) {
    // Two triangles sharing an edge: five edges, each once, sorted pairs.
    PolyMesh m;
    m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
    m.add_face({0, 1, 2});
    m.add_face({2, 1, 3});
    const std::string script = levels_data_script({{"two", "loop", "rule", {m}}});
    // int32 pairs (0 1) (0 2) (1 2) (1 3) (2 3).
    EXPECT_EQ(base64(std::vector<int32_t>{0, 1, 0, 2, 1, 2, 1, 3, 2, 3}), "AAAAAAEAAAAAAAAAAgAAAAEAAAACAAAAAQAAAAMAAAACAAAAAwAAAA==");
    EXPECT_NE(script.find("\"edges\":\"AAAAAAEAAAAAAAAAAgAAAAEAAAACAAAAAQAAAAMAAAACAAAAAwAAAA==\""), std::string::npos) << script;
    EXPECT_NE(script.find("\"faces\":2"), std::string::npos);
    EXPECT_EQ(script.rfind("window.CROSSDIV_LEVELS = ", 0), 0u);
}

}  // namespace
}  // namespace crossdiv::verification
