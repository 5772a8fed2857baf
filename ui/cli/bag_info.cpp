// `accelcal bag-info`: what a ROS bag holds (topics, types, counts, rates, time span, gaps).
#include <iostream>
#include <memory>

#include "accelcal/bags/bag_info.h"
#include "accelcal/report/bag_info_text.h"
#include "cli/cli_checks.h"
#include "cli/commands.h"

namespace accelcal::cli {

void SetupBagInfoCommand(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand(
      "bag-info",
      "What a ROS bag holds: each topic's type, message count, rate, time span and gaps (from\n"
      "the bag's receive times), and for each sensor_msgs/Imu topic its header stamps as\n"
      "accelcal reads them (rate, span, gaps, stamps out of order). Reads ROS 1 bags (.bag,\n"
      "format 2.0), MCAP (.mcap) and ROS 2 SQLite bags (.db3), or a ROS 2 bag folder.\n\n"
      "Example:\n"
      "  accelcal bag-info rosbag2_2024_05_01/\n"
      "  accelcal fit --recording rosbag2_2024_05_01/ --topic /imu/data -o cal.json");
  sub->add_option("bag", *path, "The bag: a file, or a ROS 2 bag folder (its metadata.yaml)")
      ->required()
      ->check(InputFileOrBag());
  sub->callback([path] { std::cout << FormatBagInfo(bags::DescribeBag(*path)); });
}

}  // namespace accelcal::cli
