// The CLI's subcommands: each file registers one on the app. No algorithm code here — only
// option parsing, library calls and file writing.
#pragma once

#include <CLI/CLI.hpp>

namespace ramus::cli {

void addLsystemCommand(CLI::App& app);
void addRenderCommand(CLI::App& app);
void addSpeciesCommand(CLI::App& app);
void addPcaCommand(CLI::App& app);
void addColonizeCommand(CLI::App& app);
void addSkeletonCommand(CLI::App& app);
void addBonesCommand(CLI::App& app);
void addServeCommand(CLI::App& app);
void addBatchCommand(CLI::App& app);

}  // namespace ramus::cli
