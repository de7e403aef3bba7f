# The headers a C++ program includes (src/*.hpp, src/tilemap/*.hpp) must not
# include the core's machinery in src/detail/: that is what keeps the public
# API the table in docs/cpp.org and lets the machinery change freely.
file(GLOB public ${SRC}/*.hpp ${SRC}/tilemap/*.hpp)
set(bad "")
foreach(h ${public})
  file(STRINGS ${h} lines REGEX "#include \"(\\.\\./)?detail/")
  if(lines)
    list(APPEND bad "${h}: ${lines}")
  endif()
endforeach()
if(bad)
  string(REPLACE ";" "\n" bad "${bad}")
  message(FATAL_ERROR "public headers include src/detail/:\n${bad}")
endif()
list(LENGTH public n)
message(STATUS "${n} public headers, none includes src/detail/")
