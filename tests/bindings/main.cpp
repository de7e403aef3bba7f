// SPDX-License-Identifier: MIT
// The boundary's doctest suites run inside Guile: main boots it and runs
// every test case in guile mode.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>
#include <libguile.h>

namespace {

struct Run {
    int argc;
    char** argv;
    int status = 0;
};

void* run(void* data) {
    auto* r = static_cast<Run*>(data);
    doctest::Context context(r->argc, r->argv);
    r->status = context.run();
    return nullptr;
}

}  // namespace

int main(int argc, char** argv) {
    Run r{argc, argv};
    scm_with_guile(run, &r);
    return r.status;
}
