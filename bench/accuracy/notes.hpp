// What the accuracy figures say, in words derived from the figures: the
// paragraphs of the Org document that change with the results.
#pragma once
#include <string>
#include <vector>

#include "accuracy/report.hpp"

namespace bench::accuracy {

// Where bodies ended inside solids, and why.
std::string penetration_notes(const std::vector<Row>& rows);

}  // namespace bench::accuracy
