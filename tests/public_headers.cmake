# SPDX-License-Identifier: MIT
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST)
# The headers a C++ program includes (cmake/public_header_list.cmake, the
# ones installed) must include only each other: nothing from src/detail/ or
# any other private header, which an installed copy lacks. That is what
# keeps the public API the table in docs/cpp.org and lets the machinery
# change freely.
include(${CMAKE_CURRENT_LIST_DIR}/../cmake/public_header_list.cmake)
set(bad "")
foreach(h ${DS_PUBLIC_HEADERS})
  get_filename_component(dir ${h} DIRECTORY)
  file(STRINGS ${SRC}/${h} lines REGEX "^#include \"")
  foreach(line ${lines})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(dir)
      set(included "${dir}/${included}")
    endif()
    get_filename_component(included ${included} ABSOLUTE BASE_DIR ${SRC})
    file(RELATIVE_PATH included ${SRC} ${included})
    if(NOT included IN_LIST DS_PUBLIC_HEADERS)
      list(APPEND bad "${h} includes ${included}")
    endif()
  endforeach()
endforeach()
if(bad)
  string(REPLACE ";" "\n" bad "${bad}")
  message(FATAL_ERROR "public headers include private ones:\n${bad}")
endif()
list(LENGTH DS_PUBLIC_HEADERS n)
message(STATUS "${n} public headers, each including only public ones")
