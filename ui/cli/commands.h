// The subcommands of `accelcal`. Each lives in ui/cli/<name>.cpp with an options struct, a
// setup function that binds its flags (CLI11's subcommands-in-files pattern) and a run function
// that takes the options and calls the core, so it can be tested without parsing.
//
// Run functions report a failed job by throwing accelcal::Error (main prints one line on stderr
// and exits 1); bad usage is CLI11's (exit 2).
#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace accelcal::cli {

void SetupFitCommand(CLI::App& app);
void SetupApplyCommand(CLI::App& app);
void SetupSimulateCommand(CLI::App& app);
void SetupRecordCommand(CLI::App& app);
void SetupSessionsCommand(CLI::App& app);
void SetupExportCommand(CLI::App& app);
void SetupExportCalCommand(CLI::App& app);
void SetupHistoryCommand(CLI::App& app);
void SetupReportCommand(CLI::App& app);
void SetupRefitCommand(CLI::App& app);
void SetupWizardCommand(CLI::App& app);
void SetupAllanCommand(CLI::App& app);
void SetupNoiseCommand(CLI::App& app);
void SetupLabCommand(CLI::App& app);
void SetupDeviceInfoCommand(CLI::App& app);
void SetupBagInfoCommand(CLI::App& app);
// The hidden commands that write the manual pages and the completion from `app` (set up last,
// after every other command; help_commands.cpp). `version` goes into the pages.
void SetupHelpCommands(CLI::App& app, const std::string& version);

}  // namespace accelcal::cli
