// SPDX-License-Identifier: MIT
// downstroke-bench query: the spatial queries' cost per frame, native and
// through Scheme, against a Scheme loop (queries.cpp says what is measured).
#pragma once
namespace bench {
// argv[1] is "query".
int query_main(int argc, char** argv);
}  // namespace bench
