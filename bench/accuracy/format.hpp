// SPDX-License-Identifier: MIT
// How the accuracy figures are spelled, shared by the stdout table and the
// Org document so both say the same.
#pragma once
#include <string>
#include <vector>

#include "accuracy/report.hpp"
#include "common/org_file.hpp"

namespace bench::accuracy {

using bench::sig3;  // about three significant digits (common/org_file.hpp)
std::string px(double v);    // a length: whole numbers without decimals
std::string share(double fraction);  // as a percentage
std::string repeat(const Repeat& r);
std::string where(const Run& run);  // which scene, solid and cause the deepest penetration had
std::string config_name(const Config& c);  // "swept k=4 rest on"

// The main table: its column heads and one row's cells.
const std::vector<std::string>& table_heads();
std::vector<std::string> table_cells(const Row& r);

}  // namespace bench::accuracy
