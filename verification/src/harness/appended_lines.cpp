#include "crossdiv/verification/harness/appended_lines.h"

#include <fstream>
#include <iterator>

namespace crossdiv::verification {

std::vector<std::string> AppendedLines::take_complete() {
    std::ifstream in(path_, std::ios::binary);
    if (!in) return {};
    // By bytes counted here rather than tellg(), which answers -1 once a read has met the
    // end of the file.
    in.seekg(read_);
    const std::string unread{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::vector<std::string> lines;
    size_t start = 0;
    for (size_t nl; (nl = unread.find('\n', start)) != std::string::npos; start = nl + 1)
        lines.push_back(unread.substr(start, nl - start));
    read_ += static_cast<long long>(start);
    return lines;
}

}  // namespace crossdiv::verification
