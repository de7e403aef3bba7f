// SPDX-License-Identifier: MIT
// What the bench modes share when they write their Org documents: a
// generated block between BEGIN and END marker lines, with hand-written notes
// around it that a new run keeps, and numbers printed the same way.
#pragma once
#include <string>

namespace bench {

// Writes `generated` (which starts with the BEGIN line and ends after the END
// line) into `file`: in place of the old block when the file has both
// markers, keeping everything before and after; at the end of a file that
// lacks them (nothing in it is lost); and as the new document
// fresh_before + generated + fresh_after when there is no file or it is
// empty. Throws when the file cannot be written.
void write_generated(const std::string& file, const std::string& begin_marker, const std::string& end_marker,
                     const std::string& generated, const std::string& fresh_before,
                     const std::string& fresh_after = "");

// v with about three significant digits, never in exponent form.
std::string sig3(double v);

}  // namespace bench
