# DOWNSTROKE_SANITIZE: every C++ file (core, bindings, host, tests) built with
# AddressSanitizer and UndefinedBehaviorSanitizer, for tools/sanitize.sh.
# Made for GCC; a build directory of its own (build-asan/), never the main one.
option(DOWNSTROKE_SANITIZE "Build with ASan+UBSan (GCC); see tools/sanitize.sh" OFF)

set(DS_SANITIZER_ENV)  # what every process loading instrumented code needs
set(DS_GUILD_PRELOAD)  # the env prefix for guild, which is not instrumented
if(NOT DOWNSTROKE_SANITIZE)
  return()
endif()

# UBSan findings stop the process (a test fails) instead of scrolling past.
add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)

# The options, each for a reason (docs/limits.org, "Fuzzing and sanitizers"):
# detect_leaks=0: Guile's collector frees by scanning, so every object still
#   reachable only from the GC heap at exit looks leaked to LeakSanitizer.
# detect_stack_use_after_return=0: call/cc and Guile's stack captures copy and
#   restore C stack frames, which a fake stack would break.
# abort_on_error=1: a report ends the test as a crash, never as a pass.
set(_asan "detect_leaks=0:detect_stack_use_after_return=0:abort_on_error=1")
set(_ubsan "print_stacktrace=1:halt_on_error=1")
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
