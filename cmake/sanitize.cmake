# SPDX-License-Identifier: MIT
# DOWNSTROKE_SANITIZE: every C++ file (core, bindings, host, tests) built with
# AddressSanitizer and UndefinedBehaviorSanitizer, for tools/sanitize.sh.
# Made for GCC; a build directory of its own (build-asan/), never the main one.
option(DOWNSTROKE_SANITIZE "Build with ASan+UBSan (GCC); see tools/sanitize.sh" OFF)

set(DS_SANITIZER_ENV)  # what every process loading instrumented code needs
set(DS_GUILD_PRELOAD)  # the env prefix for guild, which is not instrumented

# Called at the end of each CMakeLists.txt that adds tests: in an ASan+UBSan
# build, each of its tests runs with the options below and carries the label
# sanitize. A no-op otherwise.
function(ds_sanitize_tests)
  if(DOWNSTROKE_SANITIZE)
    get_property(tests DIRECTORY PROPERTY TESTS)
    set_property(TEST ${tests} APPEND PROPERTY ENVIRONMENT ${DS_SANITIZER_ENV})
    set_property(TEST ${tests} APPEND PROPERTY LABELS sanitize)
  endif()
endfunction()

if(NOT DOWNSTROKE_SANITIZE)
  return()
endif()

# UBSan findings stop the process (a test fails) instead of scrolling past.
# A build of its own, as tools/sanitize.sh makes it: instrumented objects must
# not mix with the main build's.
add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)

# The options, each for a reason (docs/limits.org, "Fuzzing and sanitizers"):
# detect_leaks=0: Guile's collector frees by scanning, so what its heap still
#   holds at exit (malloc'd by libguile) is reported as leaked: the tilemap
#   suite alone "leaks" 147 KB in 561 allocations.
# detect_stack_use_after_return=0: with it, instrumented frames keep their
#   locals in fake stacks on the malloc heap, which the collector does not
#   scan: an SCM held only there could be freed under the frame.
# (Not set: replace_intrin=0. A full continuation, call/cc, copies the C stack
#   with memcpy, redzones included, which ASan reports as a stack underflow;
#   no suite captures one, and turning it off would skip every memcpy check.)
set(_asan "detect_leaks=0:detect_stack_use_after_return=0")
set(_ubsan "print_stacktrace=1")
set(DS_SANITIZER_ENV "ASAN_OPTIONS=${_asan}" "UBSAN_OPTIONS=${_ubsan}")

# guild (the uninstrumented guile binary) dlopens the instrumented extension
# while compiling the Scheme modules: ASan's runtime must then be loaded first.
execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
                OUTPUT_VARIABLE _libasan OUTPUT_STRIP_TRAILING_WHITESPACE)
if(NOT EXISTS "${_libasan}")
  message(FATAL_ERROR "DOWNSTROKE_SANITIZE: ${CMAKE_CXX_COMPILER} has no libasan.so (GCC's: libasan8)")
endif()
set(DS_GUILD_PRELOAD "LD_PRELOAD=${_libasan}" ${DS_SANITIZER_ENV})
message(STATUS "Downstroke: ASan+UBSan build; guild runs with LD_PRELOAD=${_libasan}")
