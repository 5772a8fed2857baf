// `accelcal lab ...`: the lab's store (docs/lab.md). The group and its small commands are in
// lab.cpp; publishing in lab_publish.cpp; the register's reading and the equipment in
// lab_register.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace accelcal::cli {

void SetupLabPublishCommand(CLI::App& lab);
void SetupLabHistoryCommand(CLI::App& lab);
void SetupLabDueCommand(CLI::App& lab);
void SetupLabEquipmentCommand(CLI::App& lab);

}  // namespace accelcal::cli
