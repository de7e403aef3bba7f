// SPDX-License-Identifier: MIT
// The work-precision plot of `downstroke-bench accuracy`, drawn by gnuplot
// when it is installed: error against milliseconds per frame, one curve per
// collision mode, a point per k.
#pragma once
#include <string>
#include <vector>

#include "accuracy/report.hpp"

namespace bench::accuracy {

struct PlotResult {
    bool written = false;
    std::string note;  // what happened, for the table and the document
};
// Never throws: a missing or failing gnuplot is reported in the note.
PlotResult write_plot(const std::string& png, const std::vector<Row>& rows);

}  // namespace bench::accuracy
