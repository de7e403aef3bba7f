// SPDX-License-Identifier: MIT
// What the accuracy figures say, in words derived from the figures: the
// sentence of the Org document that changes with the results. Why each
// cause happens is hand-written in docs/accuracy.org.
#pragma once
#include <string>
#include <vector>

#include "accuracy/report.hpp"

namespace bench::accuracy {

// How many scene runs had a body end a frame inside a solid, the deepest
// case, and the causes of each run's deepest case, counted.
std::string penetration_summary(const std::vector<Row>& rows);

}  // namespace bench::accuracy
