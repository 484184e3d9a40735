#pragma once
// What every fuzz target shares: the bytes as a stream, and the one rule of the harness. A
// clear refusal (InputError, ParseError) is a correct answer to bad input; any other
// exception escapes to libFuzzer, which reports it as a crash: the fuzzers' counterpart of
// the CLI's exit 3 ("internal error"). Memory errors and undefined behaviour are reported by
// the sanitizers the targets are built with.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "crossdiv/error.h"

namespace crossdiv::fuzz {

inline std::istringstream stream_of(const uint8_t* data, size_t size) {
    return std::istringstream(std::string(reinterpret_cast<const char*>(data), size));
}

/// Runs `f`, treating a refusal of bad input as the expected outcome.
template <class F>
int refuse_or_answer(F&& f) {
    try {
        f();
    } catch (const InputError&) {
    }
    return 0;
}

}  // namespace crossdiv::fuzz
