// Reading a file while its writer appends: only lines whose newline has been written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "crossdiv/verification/harness/appended_lines.h"

namespace crossdiv::verification {
namespace {

namespace fs = std::filesystem;

class AppendedLinesTest : public ::testing::Test {
protected:
    const fs::path path = fs::temp_directory_path() / ("crossdiv-appended-" + std::to_string(getpid()) + ".jsonl");
    void append(const std::string& text) {
        std::ofstream out(path, std::ios::app | std::ios::binary);
        out << text;
    }
    void TearDown() override { fs::remove(path); }
};

TEST_F(AppendedLinesTest, AFileNotYetWrittenHasNoLines) {
    AppendedLines lines(path.string());
    EXPECT_TRUE(lines.take_complete().empty());
}

TEST_F(AppendedLinesTest, ARecordWhoseNewlineIsNotYetWrittenWaits) {
    // The text of a record is complete JSON before its newline is flushed: a reader that took
    // it then (and asked the stream where it stood, at its end) lost every later record.
    AppendedLines lines(path.string());
    append("{\"job\":0}\n{\"job\":1}");
    EXPECT_EQ(lines.take_complete(), std::vector<std::string>{"{\"job\":0}"});
    EXPECT_TRUE(lines.take_complete().empty());
    append("\n{\"job\":2}\n{\"jo");
    EXPECT_EQ(lines.take_complete(), (std::vector<std::string>{"{\"job\":1}", "{\"job\":2}"}));
    append("b\":3}\n");
    EXPECT_EQ(lines.take_complete(), std::vector<std::string>{"{\"job\":3}"});
    EXPECT_TRUE(lines.take_complete().empty());
}

TEST_F(AppendedLinesTest, AnEmptyLineIsALine) {
    AppendedLines lines(path.string());
    append("\n\na\n");
    EXPECT_EQ(lines.take_complete(), (std::vector<std::string>{"", "", "a"}));
}

}  // namespace
}  // namespace crossdiv::verification
