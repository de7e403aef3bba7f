// SPDX-License-Identifier: MIT
// What every mode's command line uses: option values checked as they are
// read, and the command line as it was typed, for the reports.
#pragma once
#include <string>

namespace bench {

// An option's whole-number value of at least `least`; throws
// std::invalid_argument ("OPT: expected a count, got 'V'") otherwise.
int count_arg(const std::string& opt, const std::string& v, int least);
// argv as a shell would take it back (arguments quoted where needed).
std::string command_line(int argc, char** argv);
// An option's value as a number above 0; throws std::invalid_argument
// ("OPT: expected a positive number, got 'V'") otherwise.
double positive_arg(const std::string& opt, const std::string& v);

// The options of a mode that takes only --rounds R and --org FILE (argv[1]
// is the mode): fills what is given, leaving the defaults otherwise; false,
// with the usage printed, on anything else.
bool rounds_and_org(int argc, char** argv, const char* mode, int& rounds, std::string& org);

}  // namespace bench
