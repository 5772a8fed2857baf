// ParseFixture / LoadFixture: TOML -> Fixture. Every table refuses keys it does not know.
#include "accelcal/io/fixture_file.h"

#include <cmath>
#include <set>

#include <fmt/core.h>

#include "accelcal/io/detail/fixture_toml.h"
#include "accelcal/io/detail/toml_reader.h"
#include "accelcal/io/text_file.h"
#include "accelcal/base/error.h"

namespace accelcal {
namespace {

using detail::TomlTableReader;

FixtureSensor ReadFixtureSensor(TomlTableReader& r) {
  FixtureSensor s = detail::ReadFixtureSensorFields(r);
  s.source = r.String("source", std::string());
  return s;
}

}  // namespace

Fixture ParseFixture(std::string_view toml_text, const std::string& source_name) {
  const toml::table doc = detail::ParseTomlDocument(toml_text, source_name);
  Fixture f;
  TomlTableReader root(doc, "", source_name);
  f.name = root.String("name", std::string());
  f.placement_u_rad = root.Number("placement_u_deg", kNaN, detail::NumberRange::kNonNegative) * M_PI / 180.0;
  const toml::array* sensors = root.ArrayOfTables("sensor");
  if (sensors == nullptr || sensors->empty()) {
    throw InputError(source_name, 0, 0, "the fixture has no [[sensor]]");
  }
  std::set<std::string> serials;
  for (std::size_t i = 0; i < sensors->size(); ++i) {
    TomlTableReader r(*sensors->get(i)->as_table(), fmt::format("sensor {}", i + 1), source_name);
    f.sensors.push_back(ReadFixtureSensor(r));
    if (!serials.insert(f.sensors.back().serial).second) {
      r.Fail(*r.Get("serial"), "serial",
             fmt::format("'{}' is already another sensor's", f.sensors.back().serial));
    }
    r.Finish();
  }
  root.Finish();
  if (std::string why = f.Validate(); !why.empty()) throw InputError(source_name, 0, 0, why);
  return f;
}

Fixture LoadFixture(const std::string& path) {
  return ParseFixture(ReadTextFile(path), path);
}

}  // namespace accelcal
