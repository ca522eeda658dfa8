// What every output file records about the run that made it: driver, target, parameters, code version
// (git commit, with "-dirty" for uncommitted changes) and the UTC date.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace sph {

/// Git description of the source tree the binary was built from (generated at build time).
const char* code_version();
/// Current UTC time, ISO 8601.
std::string utc_timestamp();

struct RunInfo {
  std::string driver;
  std::string target;
  std::string description;
  std::vector<std::pair<std::string, std::string>> parameters;  // in declaration order
  /// The parameters set on the command line (the others have the driver's defaults), in declaration order:
  /// reference/check.py refuses results whose settings its reference rows do not name.
  std::vector<std::string> given;
};

/// Shortest round-trip text of a double (%.17g trimmed where %.12g already round-trips).
std::string format_number(double v);

}  // namespace sph
