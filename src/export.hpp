// SPDX-License-Identifier: MIT
// DOWNSTROKE_API marks what libdownstroke-core exports. The core is built
// with hidden visibility (src/CMakeLists.txt), so the shared library's
// symbol table is the documented API and nothing else: the machinery and
// the libraries it uses inside (nlohmann's JSON templates, tinyxml2's
// helpers) stay private and free to change without breaking a program
// linked against the .so. The same objects also go into the static
// downstroke_core, where visibility does not matter, so one spelling
// serves both.
#pragma once

#if defined(_WIN32)
#define DOWNSTROKE_API
#else
#define DOWNSTROKE_API __attribute__((visibility("default")))
#endif
