#pragma once
// The editor subcommand of the crossdiv CLI: writes the curve editor page (suite/editor_page.h)
// for a curve file, or for an empty start, to open in a browser from disk.

#include <CLI/CLI.hpp>

namespace crossdiv::cli {

/// Adds `editor`; when selected it stores its exit status in `status`.
void add_editor_command(CLI::App& app, int& status);

}  // namespace crossdiv::cli
